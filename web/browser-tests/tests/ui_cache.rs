//! The UI cache in the browser: while the camera turns, the tables, the
//! menus and the welcome card stay the same, so each frame copies them
//! from their textures instead of drawing them again. (That a copy shows
//! what drawing directly does is the render test
//! `a_part_unchanged_since_the_frame_before_is_copied_as_drawn`.)

use edgewise_browser_tests::{Browser, DRAG_IN_VIEW, FIRE_MOUSE};

#[tokio::test]
async fn unchanged_panels_are_copied_while_the_camera_turns() -> anyhow::Result<()> {
    let browser = Browser::launch().await?;
    browser.open("").await?;
    assert!(
        browser.state().await?["welcome"].is_array(),
        "a first visit shows the welcome card"
    );
    // A repaint that changes nothing, so that the canvas holds a frame.
    let still = browser
        .canvas_when(
            "const first = window.edgewise.state().frames; window.edgewise.clearSelection();",
            "window.edgewise.state().frames > first",
            "ui-cache-still",
        )
        .await?;
    let [drawn, copied] = browser.drawn_and_copied("uiCache").await?;

    // Twenty frames of turning: the view changes, the panels do not.
    let turning = browser
        .canvas_when(
            &format!("{FIRE_MOUSE}{DRAG_IN_VIEW} const first = window.edgewise.state().frames;"),
            "window.edgewise.state().frames >= first + 20",
            "ui-cache-turning",
        )
        .await?;
    browser
        .eval("window.__release = true; return null;")
        .await?;
    let [drawn_after, copied_after] = browser.drawn_and_copied("uiCache").await?;
    // Each part is drawn into its texture at most once (at the first frame
    // after it last changed) and copied at every other frame.
    assert!(
        drawn_after <= drawn + 3,
        "the panels drawn again: {drawn} then {drawn_after}"
    );
    assert!(
        copied_after >= copied + 19 * 3,
        "the tables, menus and card copied each frame: {copied} then {copied_after}"
    );

    // The copies show the panels as they were: the tables' rows, below the
    // view, are the same pixels, and full of text.
    let tables_top = still.height * 3 / 4;
    let differing = (tables_top..still.height)
        .flat_map(|y| (0..still.width).map(move |x| (x, y)))
        .filter(|&(x, y)| still.pixel(x, y) != turning.pixel(x, y))
        .count();
    assert_eq!(differing, 0, "the tables changed while the camera turned");
    assert!(still.distinct_colours(64) > 8, "the page is drawn");
    browser.assert_no_console_errors().await?;
    browser.close().await
}
