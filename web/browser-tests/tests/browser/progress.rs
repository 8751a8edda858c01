//! A large mesh opens in slices across frames: the page keeps painting, shows a
//! progress bar with Cancel, and the old mesh stays until the new one is
//! ready (or for good, after Cancel, from the API or the Esc key).

use edgewise_browser_tests::Browser;

/// Starts loading torus-200k without waiting for it: `window.__load` settles
/// to 'shown' or to the refusal's message.
const START_LOAD: &str = "window.__load = window.edgewise \
    .loadSample('torus-200k', { structure: 'half' }) \
    .then(() => 'shown', (e) => String(e.message)); \
    return window.edgewise.state().job;";

#[tokio::test]
async fn a_large_mesh_shows_progress_and_cancel_keeps_the_old_one() -> anyhow::Result<()> {
    let browser = Browser::launch_on_sample("cube").await?;

    // Cancelled from the API, before any frame: the promise says why.
    let job = browser
        .eval(&format!(
            "const job = (() => {{ {START_LOAD} }})(); window.edgewise.cancel(); return job;"
        ))
        .await?;
    assert_eq!(job["label"], "Opening torus-200k", "{job}");
    let outcome = browser.eval_async("window.__load").await?;
    assert_eq!(outcome, "Opening torus-200k was cancelled");
    let state = browser.state().await?;
    assert_eq!(state["mesh"], "cube.htb");
    assert!(state["job"].is_null());

    // Waited for: the promise settles once the torus is shown, and the page
    // painted frames meanwhile.
    let frames_before = browser.state().await?["frames"].as_u64().unwrap_or(0);
    browser
        .eval_async("window.edgewise.loadSample('torus-200k', { structure: 'half' })")
        .await?;
    let state = browser.state().await?;
    assert_eq!(state["mesh"], "torus-200k");
    assert_eq!(state["counts"]["faces"], 316 * 316 * 2);
    assert!(state["job"].is_null());
    let frames = state["frames"].as_u64().unwrap_or(0) - frames_before;
    assert!(
        frames >= 2,
        "the page painted while the torus loaded: {frames}"
    );

    // Opening it again: the progress bar shows while it is prepared, and
    // Esc cancels it.
    let shot = browser
        .canvas_when(
            &format!(
                "(() => {{ {} }})();",
                START_LOAD.replace("'half'", "'winged'")
            ),
            // The first frame after: what it showed is kept.
            "(window.__jobSeen = window.edgewise.state().job, true)",
            "progress-opening-torus",
        )
        .await?;
    assert!(shot.distinct_colours(64) > 4, "the app is drawn");
    let seen = browser.eval("return window.__jobSeen;").await?;
    // A fast machine may prepare the whole mesh within the first frame's
    // time budget; otherwise that frame shows the bar part way.
    if !seen.is_null() {
        let progress = seen["progress"].as_f64().unwrap_or(0.0);
        assert!(progress > 0.0 && progress < 1.0, "{seen}");
    }
    browser.press_key("Escape", 0).await?;
    // The key is handled in the app's next animation frame: wait two, so
    // that a late Esc cannot cancel the switch below instead.
    browser
        .eval_async(
            "new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(() => r(true))))",
        )
        .await?;
    let outcome = browser.eval_async("window.__load").await?;
    let state = browser.state().await?;
    if outcome == "shown" {
        // The rest of the load fitted before Esc: nothing was left to cancel.
        assert_eq!(state["structure"], "winged");
        browser
            .eval_async("window.edgewise.setStructure('half')")
            .await?;
    } else {
        assert_eq!(outcome, "Opening torus-200k was cancelled");
        assert_eq!(state["structure"], "half", "the half-edge torus stays");
    }

    // A structure switch is sliced the same way.
    let job = browser
        .eval(
            "window.__convert = window.edgewise.setStructure('winged'); \
             return window.edgewise.state().job;",
        )
        .await?;
    assert_eq!(
        job["label"], "Converting torus-200k to winged-edge",
        "{job}"
    );
    browser.eval_async("window.__convert").await?;
    assert_eq!(browser.state().await?["structure"], "winged");
    browser.screenshot("progress-torus-shown").await?;
    browser.assert_no_console_errors().await?;
    browser.close().await
}
