//! Runaway algorithms as course links, in the browser: each of
//! tests/hostile/run-*.alg opens on the cube, goes to its last step and
//! stops for the reason `edgewise trace` gives (tests/hostile/*.expected); the
//! page stays alive, and afterwards `state()` answers and a selection and
//! a step work.

use std::time::Duration;

use edgewise_browser_tests::Browser;
use serde_json::Value;

/// A run of a million steps, then its last step laid out, drawn in software.
const RUN_TIMEOUT: Duration = Duration::from_secs(120);

/// The committed cases: the file and its expected message.
const CASES: [(&str, &str); 3] = [
    (
        include_str!("../../../../tests/hostile/run-calls-300-variables.alg"),
        include_str!("../../../../tests/hostile/run-calls-300-variables.expected"),
    ),
    (
        include_str!("../../../../tests/hostile/run-long-messages.alg"),
        include_str!("../../../../tests/hostile/run-long-messages.expected"),
    ),
    (
        include_str!("../../../../tests/hostile/run-new-edges-forever.alg"),
        include_str!("../../../../tests/hostile/run-new-edges-forever.expected"),
    ),
];

/// The algorithm's name and the link's `args` from the `// run: NAME MESH
/// ARG…` line.
fn run_line(source: &str) -> (String, String) {
    let line = source
        .lines()
        .next()
        .and_then(|l| l.strip_prefix("// run: "))
        .expect("a run line");
    let mut words = line.split_whitespace();
    let name = words.next().expect("a name").to_owned();
    let _mesh = words.next();
    let args: Vec<String> = words.map(|w| w.replacen('=', ":", 1)).collect();
    (name, args.join(","))
}

#[tokio::test]
async fn runaway_runs_stop_with_their_message_and_the_page_works() -> anyhow::Result<()> {
    let browser = Browser::launch().await?;
    browser.set_script_timeout(RUN_TIMEOUT).await?;
    // The links first, made in one page; each case's link then loads the
    // page anew, as its query (the algorithm's name) differs from the last.
    browser.open("").await?;
    let mut payloads = Vec::new();
    for (source, _) in CASES {
        payloads.push(browser.payload(&serde_json::to_string(source)?).await?);
    }
    for ((source, expected), payload) in CASES.into_iter().zip(payloads) {
        let (name, args) = run_line(source);
        let message = expected
            .split_once(": error: ")
            .map(|(_, m)| m.trim())
            .expect("an error line");
        browser
            .open(&format!(
                "?sample=cube&structure=half&algorithm={name}&args={args}&step=2000000#alg={payload}"
            ))
            .await?;
        browser
            .wait_for(
                "(() => { const t = window.edgewise.state().trace; \
                 return t !== null && t.error !== null; })()",
                RUN_TIMEOUT,
            )
            .await?;
        let state = browser.state().await?;
        let trace = &state["trace"];
        // The reason, as the CLI gives it. Where a memory budget stops the
        // run the step differs a little: wasm32's values are smaller.
        let error = trace["error"].as_str().unwrap_or_default();
        let reason = |text: &str| text.split_once(" operations: ").map(|(_, r)| r.to_owned());
        assert!(error.contains("stopped after "), "{name}: {error}");
        assert_eq!(reason(error), reason(message), "{name}: {error}");
        assert!(
            state["broken"].as_array().map_or(0, Vec::len) <= 1_000,
            "{name}: {} broken records listed",
            state["broken"].as_array().map_or(0, Vec::len)
        );
        assert!(
            trace["output"].as_array().map_or(0, Vec::len) <= 200,
            "{name}"
        );
        let page_error = browser
            .eval("return document.getElementById('edgewise_error').dataset.visible === 'true'")
            .await?;
        assert_eq!(page_error, Value::Bool(false), "{name}");
        // Afterwards: a step back, a selection, and the state answers.
        let last = trace["step"].as_u64().unwrap_or(0);
        browser.eval_async("window.edgewise.back()").await?;
        assert_eq!(
            browser.state().await?["trace"]["step"].as_u64(),
            Some(last - 1),
            "{name}"
        );
        browser
            .eval_async("window.edgewise.select('vertex', 3)")
            .await?;
        let state = browser.state().await?;
        assert_eq!(state["selection"]["id"], 3, "{name}");
        let shot = browser.screenshot(&format!("hostile-run-{name}")).await?;
        assert!(!shot.is_blank(), "{}", shot.path.display());
    }
    browser.assert_no_console_errors().await?;
    browser.close().await
}

/// A trap in the wasm (what running out of memory ends in) shows the error
/// box with a way back that drops the link.
#[tokio::test]
async fn a_trap_offers_a_reload_without_the_link() -> anyhow::Result<()> {
    let browser = Browser::launch().await?;
    browser
        .open("?sample=cube&structure=half&algorithm=vertexAdjacentEdge&args=v:0&step=3")
        .await?;
    let shown = browser
        .eval(
            "window.dispatchEvent(new ErrorEvent('error', \
               {error: new WebAssembly.RuntimeError('unreachable'), message: 'unreachable'})); \
             const box = document.getElementById('edgewise_error'); \
             return {visible: box.dataset.visible, text: box.textContent, \
                     buttons: [...box.querySelectorAll('button')].map(b => b.textContent)};",
        )
        .await?;
    assert_eq!(shown["visible"], "true", "{shown}");
    assert!(
        shown["text"]
            .as_str()
            .unwrap_or_default()
            .contains("Edgewise stopped: unreachable"),
        "{shown}"
    );
    assert_eq!(
        shown["buttons"],
        serde_json::json!(["Reload without the link", "Reload"])
    );
    browser
        .eval("document.querySelector('#edgewise_error button').click(); return null;")
        .await?;
    browser
        .wait_for(
            "location.search === '' && location.hash === ''",
            Duration::from_secs(20),
        )
        .await?;
    browser.wait_until_ready().await?;
    let state = browser.state().await?;
    assert!(state["trace"].is_null(), "{state}");
    browser.close().await
}
