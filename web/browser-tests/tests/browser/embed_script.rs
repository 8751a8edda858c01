//! The embed protocol through web/examples/embed-script.html: two views
//! placed by edgewise-embed.js size themselves from `edgewise:resize`, tell
//! the page each step, selection and answer, and answer calls, refusing bad ones
//! with a reason.

use std::time::Duration;

use edgewise_browser_tests::Browser;

/// Two apps start side by side on the CPU renderer: allow for both.
const START_TIMEOUT: Duration = Duration::from_secs(180);

/// A script calling the view in `#id` through `edgewise-embed.js`, that
/// resolves to `{ok, value}` or `{ok: false, error}`.
fn call_in(id: &str, script: &str) -> String {
    format!(
        "document.getElementById('{id}').edgewise.{script} \
           .then((value) => ({{ ok: true, value }}), (error) => ({{ ok: false, error: error.message }}))"
    )
}

#[tokio::test]
async fn views_from_the_embed_script_size_themselves_and_report_steps() -> anyhow::Result<()> {
    let browser = Browser::launch().await?;
    browser.set_script_timeout(START_TIMEOUT).await?;
    browser.goto("examples/embed-script.html").await?;

    // Each div became a titled iframe; the page hears `ready` from both.
    let titles = browser
        .eval("return [...document.querySelectorAll('iframe')].map((f) => f.title);")
        .await?;
    assert_eq!(
        titles,
        serde_json::json!([
            "Edgewise: vertexAdjacentEdge on the winged-edge tetrahedron, from vertex 1",
            "Edgewise: tetrahedron: vertexAdjacentEdge (interactive mesh view)"
        ])
    );
    browser
        .eval(
            "window.__heard = []; \
             for (const id of ['winged', 'half']) { \
               const element = document.getElementById(id); \
               for (const name of ['stepchange', 'selectionchange', 'meshchange']) \
                 element.addEventListener('edgewise:' + name, (e) => \
                   window.__heard.push([id, e.detail.type, e.detail.trace ? e.detail.trace.step : null])); \
             } return null;",
        )
        .await?;
    let ready = browser
        .eval_async(
            "Promise.all(['winged', 'half'].map((id) => document.getElementById(id).edgewise.ready)) \
             .then((messages) => messages.map((m) => m.type))",
        )
        .await?;
    assert_eq!(
        ready,
        serde_json::json!(["edgewise:ready", "edgewise:ready"])
    );

    // They asked for their height: the half-edge view shows its tables too.
    browser
        .wait_for(
            "['winged', 'half'].every((id) => \
               document.querySelector('#' + id + ' iframe').style.height !== '300px')",
            Duration::from_secs(30),
        )
        .await?;
    let heights = browser
        .eval(
            "return ['winged', 'half'].map((id) => \
               parseInt(document.querySelector('#' + id + ' iframe').style.height, 10));",
        )
        .await?;
    let (winged, half) = (
        heights[0].as_i64().unwrap_or(0),
        heights[1].as_i64().unwrap_or(0),
    );
    assert!(winged >= 240 + 48, "{heights}");
    assert!(half - winged >= 100, "the tables' share: {heights}");

    // The winged view's link carries questions: it asks the first at step
    // 0, and the page hears each answer with its verdict.
    let state = browser
        .eval_async(&call_in("winged", "call('state')"))
        .await?;
    assert_eq!(
        state["value"]["trace"]["question"]["prompt"],
        "Which edge will e be after the lookup v.incidentEdge?",
        "{state}"
    );
    let answered = browser
        .eval_async(&call_in("winged", "call('answer', 'edge', 3)"))
        .await?;
    assert_eq!(answered["ok"], true, "{answered}");
    browser
        .wait_for(
            "document.getElementById('winged-answers').textContent.startsWith('Not quite')",
            Duration::from_secs(30),
        )
        .await?;
    let told = browser
        .eval("return document.getElementById('winged-answers').textContent;")
        .await?;
    assert_eq!(
        told,
        "Not quite: Which edge will e be after the lookup v.incidentEdge? You answered Edge 3; \
         the answer is Edge 1. (0 of 1 right)"
    );
    // The question card sits under the view, with the step controls.
    browser
        .eval("document.getElementById('winged-answers').scrollIntoView({block: 'end'}); return null;")
        .await?;
    browser.screenshot("embed-script-question-answered").await?;
    let went = browser
        .eval_async(&call_in("winged", "call('goto', 4)"))
        .await?;
    assert_eq!(went["ok"], true, "{went}");
    let answered = browser
        .eval_async(&call_in("winged", "call('answer', false)"))
        .await?;
    assert_eq!(answered["ok"], true, "{answered}");
    browser
        .wait_for(
            "document.getElementById('winged-answers').textContent.endsWith('(1 of 2 right)')",
            Duration::from_secs(30),
        )
        .await?;
    let refused = browser
        .eval_async(&call_in("winged", "call('answer', 'edge', 1)"))
        .await?;
    assert_eq!(refused["ok"], false, "{refused}");
    assert_eq!(
        refused["error"], "the question at step 4 is answered already (Boolean false)",
        "{refused}"
    );
    browser
        .eval_async(&call_in("winged", "call('goto', 0)"))
        .await?;

    // The page's Step button calls into the view; the step comes back.
    browser
        .eval("document.getElementById('winged-step').click(); return null;")
        .await?;
    browser
        .wait_for(
            "document.getElementById('winged-status').textContent.startsWith('Step 1 of')",
            Duration::from_secs(60),
        )
        .await?;
    let heard = browser.eval("return window.__heard;").await?;
    assert!(
        heard
            .as_array()
            .is_some_and(|h| h.contains(&serde_json::json!(["winged", "edgewise:stepchange", 1]))),
        "{heard}"
    );

    // Calls answer with the API's value or its refusal.
    let call = |script: &str| call_in("half", script);
    let aborted = browser.eval_async(&call("call('abort')")).await?;
    assert_eq!(aborted["ok"], true, "{aborted}");
    let selected = browser
        .eval_async(&call("call('select', 'edge', 4)"))
        .await?;
    assert_eq!(selected["ok"], true, "{selected}");
    let state = browser.eval_async(&call("call('state')")).await?;
    assert_eq!(
        state["value"]["selection"],
        serde_json::json!({"kind": "edge", "id": 4})
    );
    browser
        .wait_for(
            "window.__heard.some(([id, type]) => id === 'half' && type === 'edgewise:selectionchange')",
            Duration::from_secs(30),
        )
        .await?;
    for (script, refusal) in [
        (
            "call('constructor')",
            "window.edgewise has no method \"constructor\"",
        ),
        (
            "call('__proto__')",
            "window.edgewise has no method \"__proto__\"",
        ),
        (
            "call('loadSample', 'no-such-mesh')",
            "there is no sample called 'no-such-mesh'",
        ),
    ] {
        let answer = browser.eval_async(&call(script)).await?;
        assert_eq!(answer["ok"], false, "{script}: {answer}");
        let error = answer["error"].as_str().unwrap_or_default();
        assert!(error.contains(refusal), "{script}: {error}");
    }
    browser.screenshot("embed-script-winged-view").await?;
    browser
        .eval("document.getElementById('half').scrollIntoView({block: 'start'}); return null;")
        .await?;
    browser.screenshot("embed-script-half-edge-view").await?;
    browser.assert_no_console_errors().await?;
    browser.close().await
}

/// Adds a view of the tetrahedron with `origins=` to an emptied page and
/// gives the messages the page heard from it once it runs, and whether a
/// call was answered: once the view has settled after the call, a message
/// the page posts to itself reaches it after every message the view posted
/// (one window's posted messages arrive in order).
async fn embedded_with_origins(
    browser: &Browser,
    origins: &str,
) -> anyhow::Result<serde_json::Value> {
    browser.goto("examples/embed-script.html").await?;
    browser
        .eval(&format!(
            "document.body.innerHTML = ''; window.heard = []; \
             window.addEventListener('message', (e) => {{ \
               if (e.data !== 'edgewise-test:after') window.heard.push(e.data.type || e.data.subject || e.data.context); \
             }}); \
             const frame = document.createElement('iframe'); frame.id = 'view'; \
             frame.width = 640; frame.height = 480; \
             frame.src = '../index.html?embed=1&sample=tetrahedron&origins={origins}'; \
             document.body.append(frame); return null;"
        ))
        .await?;
    browser
        .wait_for(
            "document.getElementById('view').contentWindow.edgewise?.state().frames >= 2",
            START_TIMEOUT,
        )
        .await?;
    browser
        .eval_async(
            "new Promise((resolve, reject) => { \
               const view = document.getElementById('view').contentWindow; \
               view.postMessage( \
                 {type: 'edgewise:call', id: 7, method: 'select', args: ['edge', 1]}, '*'); \
               view.edgewise.settled().then(() => { \
                 const after = (e) => { \
                   if (e.data !== 'edgewise-test:after') return; \
                   window.removeEventListener('message', after); \
                   resolve(null); \
                 }; \
                 window.addEventListener('message', after); \
                 window.postMessage('edgewise-test:after', '*'); \
               }, reject); })",
        )
        .await?;
    let heard = browser.eval("return window.heard;").await?;
    let selected = browser
        .eval("return document.getElementById('view').contentWindow.edgewise.state().selection;")
        .await?;
    Ok(serde_json::json!({ "heard": heard, "selected": selected }))
}

#[tokio::test]
async fn origins_limit_who_commands_a_view_and_hears_it() -> anyhow::Result<()> {
    let browser = Browser::launch().await?;
    browser.set_script_timeout(START_TIMEOUT).await?;
    // Another origin is named: this page hears nothing and commands nothing.
    let other = embedded_with_origins(&browser, "https://notes.example.edu").await?;
    assert_eq!(other["heard"], serde_json::json!([]), "{other}");
    assert_eq!(other["selected"], serde_json::Value::Null, "{other}");
    // This page's own origin is named: it hears the view and is answered.
    let origin = browser.eval("return location.origin;").await?;
    let origin = origin.as_str().unwrap_or_default().to_owned();
    let own =
        embedded_with_origins(&browser, &format!("https://elsewhere.example,{origin}")).await?;
    let heard = own["heard"].as_array().cloned().unwrap_or_default();
    for expected in [
        "edgewise:ready",
        "edgewise:reply",
        "edgewise:selectionchange",
    ] {
        assert!(heard.iter().any(|h| h == expected), "{expected}: {own}");
    }
    assert_eq!(own["selected"]["id"], 1, "{own}");
    browser.close().await
}
