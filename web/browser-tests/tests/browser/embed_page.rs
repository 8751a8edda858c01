//! The example page web/examples/embed.html: lecture notes with two live
//! views in iframes, and buttons that drive the second through its
//! `window.edgewise`.

use std::time::Duration;

use anyhow::Context as _;
use edgewise_browser_tests::Browser;

/// Two apps start side by side on the CPU renderer: allow for both.
const START_TIMEOUT: Duration = Duration::from_secs(180);

/// A key's effect on a started view, two frames of the CPU renderer.
const WAIT: Duration = Duration::from_secs(30);

#[tokio::test]
async fn the_example_page_starts_both_views() -> anyhow::Result<()> {
    let browser = Browser::launch().await?;
    browser.goto("examples/embed.html").await?;

    let heading = browser
        .eval("return document.querySelector('h1').textContent;")
        .await?;
    assert_eq!(heading, "Two ways to store a mesh");
    let frames = browser
        .eval("return [...document.querySelectorAll('iframe')].map((f) => f.id);")
        .await?;
    assert_eq!(frames, serde_json::json!(["winged", "half"]));

    for id in ["winged", "half"] {
        // The views load lazily: bring each one near the viewport.
        browser
            .eval(&format!(
                "document.getElementById('{id}').scrollIntoView({{block: 'center'}}); return null;"
            ))
            .await?;
        let api = format!("document.getElementById('{id}').contentWindow.edgewise");
        browser
            .wait_for(
                &format!(
                    "{api} || document.getElementById('{id}').contentDocument\
                     ?.getElementById('edgewise_error')?.dataset.visible === 'true'"
                ),
                START_TIMEOUT,
            )
            .await?;
        let error = browser
            .eval(&format!(
                "const box = document.getElementById('{id}').contentDocument.getElementById('edgewise_error'); \
                 return box.dataset.visible === 'true' ? box.textContent : null;"
            ))
            .await?;
        assert_eq!(error, serde_json::Value::Null, "the {id} view failed");
        browser
            .wait_for(
                &format!("{api}.state().frames >= 2"),
                Duration::from_secs(30),
            )
            .await?;
    }

    // Each frame follows its link: embedded, the first at step 3 of its
    // trace, the second with half-edge 3 selected.
    browser
        .wait_for(
            "document.getElementById('winged').contentWindow.edgewise.state().trace?.step === 3 \
             && document.getElementById('half').contentWindow.edgewise.state().selection",
            Duration::from_secs(30),
        )
        .await?;
    let winged = browser
        .eval("return document.getElementById('winged').contentWindow.edgewise.state();")
        .await?;
    assert_eq!(winged["embed"], true);
    assert_eq!(winged["structure"], "winged");
    assert_eq!(winged["trace"]["algorithm"], "vertexAdjacentEdge");
    assert_eq!(winged["trace"]["step"], 3);
    assert_eq!(winged["error"], serde_json::Value::Null);
    let half = browser
        .eval("return document.getElementById('half').contentWindow.edgewise.state();")
        .await?;
    assert_eq!(half["embed"], true);
    assert_eq!(half["structure"], "half");
    assert_eq!(
        half["selection"],
        serde_json::json!({"kind": "edge", "id": 3})
    );

    // The button row finds the second view's API and reports what it did.
    browser
        .wait_for(
            "!document.getElementById('half-step').disabled",
            Duration::from_secs(10),
        )
        .await?;
    let before = browser
        .eval("return document.getElementById('half-status').textContent;")
        .await?;
    assert_ne!(before, "Waiting for the view to start…");
    // Run, then two steps, from the page's own buttons.
    browser
        .eval("document.getElementById('half-run').click(); return null;")
        .await?;
    let ran = browser
        .wait_for(
            "document.getElementById('half-status').textContent.startsWith('Step 0 of')",
            Duration::from_secs(10),
        )
        .await;
    if let Err(err) = ran {
        let status = browser
            .eval("return document.getElementById('half-status').textContent;")
            .await?;
        anyhow::bail!("{err}; the page says: {status}");
    }
    for _ in 0..2 {
        browser
            .eval("document.getElementById('half-step').click(); return null;")
            .await?;
    }
    browser
        .wait_for(
            "document.getElementById('half').contentWindow.edgewise.state().trace.step === 2 \
             && document.getElementById('half-status').textContent.startsWith('Step 2 of')",
            Duration::from_secs(10),
        )
        .await?;

    let shot = browser.screenshot("embed-page-half").await?;
    assert!(!shot.is_blank(), "{} is blank", shot.path.display());
    browser.eval("window.scrollTo(0, 0); return null;").await?;
    let shot = browser.screenshot("embed-page").await?;
    assert!(!shot.is_blank(), "{} is blank", shot.path.display());

    browser.assert_no_console_errors().await?;
    browser.close().await
}

/// A view in a page never takes the keyboard on its own: the page keeps its
/// arrow keys until the reader clicks the view; then → steps the view, and
/// Escape hands the keys back to the page.
#[tokio::test]
async fn an_embedded_view_takes_the_keys_only_when_asked() -> anyhow::Result<()> {
    let browser = Browser::launch().await?;
    browser.goto("examples/embed.html").await?;
    browser
        .eval("document.getElementById('winged').scrollIntoView({block: 'center'}); return null;")
        .await?;
    let view = "document.getElementById('winged').contentWindow.edgewise";
    browser
        .wait_for(
            &format!("{view} && {view}.state().frames >= 3 && {view}.state().trace?.step === 3"),
            START_TIMEOUT,
        )
        .await?;
    let active = "return document.activeElement.tagName + (document.activeElement.id ? '#' + document.activeElement.id : '');";
    assert_eq!(
        browser.eval(active).await?,
        "BODY",
        "the view took the focus"
    );
    browser.press_key("ArrowRight", 0).await?;
    browser
        .wait_for(
            &format!("{view}.state().trace.step === 3"),
            Duration::from_secs(10),
        )
        .await
        .context("the page's → did not reach the view")?;

    // A click on the view gives it the keys, and shows a ring.
    let centre = browser
        .eval(
            "const r = document.getElementById('winged').getBoundingClientRect(); \
             return [r.left + r.width / 2, r.top + r.height / 2];",
        )
        .await?;
    let (x, y) = (
        centre[0].as_f64().unwrap_or_default(),
        centre[1].as_f64().unwrap_or_default(),
    );
    // An empty corner of the view: a click there selects nothing.
    browser.click_at(x, y - 100.0, "left").await?;
    assert_eq!(browser.eval(active).await?, "IFRAME#winged");
    let ring = browser
        .eval(
            "return getComputedStyle(document.getElementById('winged').contentDocument\
             .getElementById('edgewise_keys')).display;",
        )
        .await?;
    assert_eq!(ring, "block", "no ring shows that the view has the keys");
    browser.press_key("ArrowRight", 0).await?;
    browser
        .wait_for(
            &format!("{view}.state().trace.step === 4"),
            Duration::from_secs(10),
        )
        .await?;
    let shot = browser.screenshot("embed-page-keys").await?;
    assert!(!shot.is_blank());

    // Escape hands the keys back to the page.
    browser.press_key("Escape", 0).await?;
    assert_eq!(browser.eval(active).await?, "BODY", "Escape kept the keys");
    browser.press_key("ArrowRight", 0).await?;
    browser
        .wait_for(&format!("{view}.state().trace.step === 4"), WAIT)
        .await
        .context("→ no longer reached the view after Escape")?;
    browser.assert_no_console_errors().await?;
    browser.close().await
}
