//! The UI cache in the browser: while the camera turns, the tables, the
//! menus, the welcome card and the algorithm panel stay the same, so each
//! frame copies them from their textures instead of drawing them again.
//! (That a copy shows what drawing directly does is the render test
//! `a_part_unchanged_since_the_frame_before_is_copied_as_drawn`.)

use edgewise_browser_tests::{Browser, DRAG_IN_VIEW, FIRE_MOUSE, Screenshot};

/// A frame at rest and one after twenty frames of turning the camera,
/// and how many parts were drawn into textures and copied meanwhile.
async fn turn(browser: &Browser, name: &str) -> anyhow::Result<(Screenshot, Screenshot, [u64; 2])> {
    // A repaint that changes nothing, so that the canvas holds a frame.
    let still = browser
        .canvas_when(
            "const first = window.edgewise.state().frames; window.edgewise.clearSelection();",
            "window.edgewise.state().frames > first",
            &format!("ui-cache-{name}-still"),
        )
        .await?;
    let [drawn, copied] = browser.drawn_and_copied("uiCache").await?;
    let turning = browser
        .canvas_when(
            &format!("{FIRE_MOUSE}{DRAG_IN_VIEW} const first = window.edgewise.state().frames;"),
            "window.edgewise.state().frames >= first + 20",
            &format!("ui-cache-{name}-turning"),
        )
        .await?;
    browser
        .eval("window.__release = true; return null;")
        .await?;
    let [drawn_after, copied_after] = browser.drawn_and_copied("uiCache").await?;
    Ok((still, turning, [drawn_after - drawn, copied_after - copied]))
}

/// How many pixels of `columns` × `rows` differ between two frames by more
/// than 8 levels in a channel: a part drawn directly and its copy differ
/// by egui's dithering, which the texture offsets (a level or two, a few
/// more where shapes overlap), and a panel drawn wrong differs by
/// thousands of pixels.
fn differing(
    a: &Screenshot,
    b: &Screenshot,
    columns: std::ops::Range<u32>,
    rows: std::ops::Range<u32>,
) -> usize {
    rows.flat_map(|y| columns.clone().map(move |x| (x, y)))
        .filter(|&(x, y)| {
            let (a, b) = (a.pixel(x, y), b.pixel(x, y));
            a.iter().zip(b).any(|(a, b)| a.abs_diff(b) > 8)
        })
        .count()
}

#[tokio::test]
async fn unchanged_panels_are_copied_while_the_camera_turns() -> anyhow::Result<()> {
    let browser = Browser::launch().await?;
    browser.open("").await?;
    assert!(
        browser.state().await?["welcome"].is_array(),
        "a first visit shows the welcome card"
    );
    // Each part is drawn into its texture at most once (at the first frame
    // after it last changed) and copied at every other frame: the menus,
    // the tables and the welcome card.
    let (still, turning, [drawn, copied]) = turn(&browser, "first-visit").await?;
    assert!(drawn <= 3, "the panels drawn again {drawn} times");
    assert!(
        copied >= 19 * 3,
        "the panels copied {copied} times in 20 frames"
    );
    // The copies show the panels as they were: the tables' rows, below the
    // view, are the same pixels.
    let (width, height) = (still.width, still.height);
    let tables = differing(&still, &turning, 0..width, height * 3 / 4..height);
    assert_eq!(tables, 0, "the tables changed while the camera turned");
    assert!(still.distinct_colours(64) > 8, "the page is drawn");

    // With a trace open, its panel on the right is copied as well.
    browser
        .eval_async("window.edgewise.run('vertexAdjacentEdge', { v: 1 }).then(() => window.edgewise.step(2))")
        .await?;
    let (still, turning, [drawn, copied]) = turn(&browser, "trace").await?;
    assert!(drawn <= 4, "the panels drawn again {drawn} times");
    assert!(
        copied >= 19 * 3,
        "the panels copied {copied} times in 20 frames"
    );
    let panel = differing(&still, &turning, width - 300..width, 0..height);
    assert_eq!(
        panel, 0,
        "the algorithm panel changed while the camera turned"
    );
    browser.assert_no_console_errors().await?;
    browser.close().await
}
