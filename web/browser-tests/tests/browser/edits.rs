//! Editing in the browser: a traced edge flip on the half-edge explainer's
//! example mesh, whose records break at the first write and mend by the
//! end, and a native operation refused with its reason.

use anyhow::Context as _;
use edgewise_browser_tests::{Browser, LaunchOptions};
use edgewise_core::lang::{StepKind, Value as Input};
use edgewise_core::schema::Structure;
use edgewise_model::algorithm::{library::AlgorithmLibrary, session::PendingRun};
use edgewise_model::samples;
use serde_json::Value;

/// The step, as the page numbers them, that makes `flipEdge`'s first write
/// on the hexagon's half-edge 2: the step after that operation.
fn first_write_step() -> anyhow::Result<usize> {
    let document = samples::open("hexagon", Some(Structure::HalfEdge), Structure::HalfEdge)
        .map_err(anyhow::Error::msg)?;
    let flip = AlgorithmLibrary::shipped()
        .find("flipEdge", Structure::HalfEdge)
        .context("flipEdge is shipped")?
        .clone();
    // As the page's run('flipEdge', { h: 2 }) starts it.
    let mut run = PendingRun::new(flip);
    run.set("h", Input::Edge(2));
    let trace = run
        .start(document.mesh())
        .map_err(anyhow::Error::msg)?
        .trace;
    (0..trace.len())
        .find(|&i| {
            matches!(
                trace.step(i).map(|step| step.kind),
                Some(StepKind::Write { .. })
            )
        })
        .map(|i| i + 1)
        .context("the flip writes")
}

#[tokio::test]
async fn a_traced_flip_breaks_the_records_then_mends_them() -> anyhow::Result<()> {
    // A projector-sized window: the README shows these screenshots.
    let browser = Browser::launch_with(LaunchOptions {
        window_size: (1600, 1000),
        ..LaunchOptions::default()
    })
    .await?;
    browser.open("").await?;
    let loaded = browser
        .eval_async("window.edgewise.loadSample('hexagon', { structure: 'half' })")
        .await?;
    assert_eq!(loaded, Value::Null);
    browser
        .eval_async("window.edgewise.run('flipEdge', { h: 2 })")
        .await?;

    // The tables are sound until the first write. The app's own test walks
    // every step to it (crates/app/tests/it/edits.rs); the page, where each
    // step is a software-rendered frame, goes to the step before it, found in
    // the same trace run here, then takes the write.
    let first_write = first_write_step()?;
    browser
        .eval_async(&format!("window.edgewise.goto({})", first_write - 1))
        .await?;
    let state = browser.state().await?;
    assert_eq!(state["broken"], serde_json::json!([]), "{state}");
    assert_ne!(state["trace"]["operation"], "write", "{state}");
    browser.eval_async("window.edgewise.step(1)").await?;
    // The layout is the last frame's: let the step's frame be drawn.
    browser.frames(2).await?;
    let state = browser.state().await?;
    assert_eq!(state["trace"]["step"], first_write, "{state}");
    assert_eq!(state["trace"]["operation"], "write", "{state}");
    let broken = state["broken"].as_array().cloned().unwrap_or_default();
    assert!(
        !broken.is_empty(),
        "the first write breaks records: {state}"
    );
    assert!(
        broken
            .iter()
            .any(|b| b["kind"] == "edge" && b["id"] == 2 && b["rule"].as_str().is_some()),
        "{broken:?}"
    );
    assert!(
        state["highlights"]
            .as_array()
            .is_some_and(|h| h.iter().any(|h| h["role"] == "broken")),
        "{state}"
    );
    // The write's line is in sight in the code, beside the ten variables.
    let line = state["trace"]["line"].as_u64().context("a line")?;
    let lines = &state["layout"]["sourceLines"];
    let (first, last) = (lines[0].as_u64(), lines[1].as_u64());
    assert!(
        first
            .zip(last)
            .is_some_and(|(first, last)| (first..=last).contains(&line)),
        "line {line} is out of sight: {lines}"
    );
    let shot = browser.screenshot("edit-flip-first-write").await?;
    assert!(shot.distinct_colours(64) > 8, "the view is drawn");

    // At the end every record follows the rules again.
    browser.eval_async("window.edgewise.goto(100000)").await?;
    let state = browser.state().await?;
    assert_eq!(state["trace"]["done"], true, "{state}");
    assert_eq!(state["broken"], serde_json::json!([]));
    assert_eq!(state["stats"]["vertices"], 7);
    assert_eq!(state["stats"]["edges"], 12);
    assert_eq!(state["stats"]["faces"], 6);
    browser.screenshot("edit-flip-done").await?;

    // A finished flip is kept; a native flip of a boundary edge is refused.
    browser.eval_async("window.edgewise.abort()").await?;
    let refusal = browser
        .refusal("window.edgewise.edit('flip-edge', [0])")
        .await?;
    let message = refusal.as_str().unwrap_or_default();
    assert!(message.contains("on the boundary"), "{message}");
    let state = browser.state().await?;
    assert_eq!(state["error"].as_str(), Some(message));
    browser
        .eval_async("window.edgewise.restoreBeforeEdit()")
        .await?;
    browser.assert_no_console_errors().await?;
    browser.close().await
}
