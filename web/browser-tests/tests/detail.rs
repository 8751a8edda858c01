//! The level of detail in the browser: icosphere-20k seen whole is drawn in
//! full; zoomed out with the wheel until its edges are a few pixels long,
//! it is drawn coarse (edges as lines, no vertex spheres, the selection in
//! full); zoomed back in, in full again.

use std::time::Duration;

use edgewise_browser_tests::Browser;
use serde_json::json;

/// Turns the wheel over the middle of the canvas, `notches` times (out if
/// positive), and waits for the app to draw the result.
async fn wheel(browser: &Browser, notches: i32) -> anyhow::Result<()> {
    let at = browser
        .eval(
            "const r = document.querySelector('canvas').getBoundingClientRect();
             return [r.left + r.width * 0.4, r.top + r.height * 0.4];",
        )
        .await?;
    let (x, y) = (
        at[0].as_f64().unwrap_or(300.0),
        at[1].as_f64().unwrap_or(300.0),
    );
    for _ in 0..notches.abs() {
        browser
            .cdp(
                "Input.dispatchMouseEvent",
                json!({ "type": "mouseWheel", "x": x, "y": y, "deltaX": 0,
                        "deltaY": 120 * notches.signum() }),
            )
            .await?;
    }
    let frames = browser.state().await?["frames"].as_u64().unwrap_or(0);
    browser
        .wait_for(
            &format!("window.edgewise.state().frames > {}", frames + 2),
            Duration::from_secs(120),
        )
        .await
}

#[tokio::test]
async fn zooming_out_draws_a_dense_mesh_coarse_and_zooming_in_in_full() -> anyhow::Result<()> {
    let browser = Browser::launch().await?;
    browser.set_script_timeout(Duration::from_secs(180)).await?;
    browser.open("").await?;
    browser
        .eval_async("window.edgewise.loadSample('icosphere-20k', { structure: 'half' })")
        .await?;
    browser
        .eval_async("window.edgewise.select('vertex', 0)")
        .await?;
    wheel(&browser, 0).await?;
    assert_eq!(browser.state().await?["coarseView"], false, "seen whole");
    browser.screenshot("detail-icosphere-full").await?;

    let mut notches = 0;
    while browser.state().await?["coarseView"] != true {
        notches += 1;
        assert!(
            notches <= 12,
            "still drawn in full after {notches} notches out"
        );
        wheel(&browser, 1).await?;
    }
    let shot = browser.screenshot("detail-icosphere-coarse").await?;
    assert!(shot.distinct_colours(64) > 4, "the sphere is drawn");
    // The selected vertex keeps its full form, and is still picked there.
    let state = browser.state().await?;
    assert_eq!(state["selection"]["id"], 0, "{}", state["selection"]);
    let at = browser.element_at("vertex", 0).await?;
    assert!(at.is_some(), "vertex 0 is in view");

    wheel(&browser, -notches).await?;
    assert_eq!(
        browser.state().await?["coarseView"],
        false,
        "zoomed back in"
    );
    browser.assert_no_console_errors().await?;
    browser.close().await
}
