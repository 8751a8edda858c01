//! The level of detail in the browser: icosphere-20k seen whole, its edges
//! a few pixels long, is drawn coarse (edges as lines, no vertex spheres,
//! the selection in full); the cube in full; torus-200k, new, draws its
//! base image a part a frame behind its motion proxy, and turns with it.
//! (Zooming across the switch is covered by the render test
//! `a_dense_mesh_far_away_is_drawn_coarse_…`.)

use std::time::Duration;

use edgewise_browser_tests::{Browser, DRAG_IN_VIEW, FIRE_MOUSE};

/// Waits a few animation frames, for the view to draw what changed.
async fn settle(browser: &Browser) -> anyhow::Result<()> {
    browser
        .eval_async(
            "new Promise((r) => { let n = 0; \
             const f = () => (++n > 10 ? r(null) : requestAnimationFrame(f)); f(); })",
        )
        .await?;
    Ok(())
}

#[tokio::test]
async fn a_dense_mesh_seen_whole_is_drawn_coarse_and_the_cube_in_full() -> anyhow::Result<()> {
    let browser = Browser::launch_on_sample("icosphere-20k").await?;
    browser
        .eval_async("window.edgewise.select('vertex', 0)")
        .await?;
    settle(&browser).await?;
    let state = browser.state().await?;
    assert_eq!(state["coarseView"], true, "seen whole");
    assert_eq!(state["selection"]["id"], 0, "{}", state["selection"]);
    let shot = browser.screenshot("detail-icosphere-coarse").await?;
    assert!(shot.distinct_colours(64) > 4, "the sphere is drawn");
    assert!(
        browser.element_at("vertex", 0).await?.is_some(),
        "the selected vertex is in view"
    );

    // A new selection is drawn over the kept base image: WebGL2 copies it
    // rather than drawing the 20k faces again.
    let [drawn, copied] = browser.drawn_and_copied("baseImage").await?;
    assert!(drawn >= 1 && copied >= 1, "drawn {drawn}, copied {copied}");
    browser
        .eval_async("window.edgewise.select('vertex', 5)")
        .await?;
    settle(&browser).await?;
    let [drawn_after, copied_after] = browser.drawn_and_copied("baseImage").await?;
    assert_eq!(drawn_after, drawn, "the selection keeps the image");
    assert!(copied_after > copied, "and copies it");
    let selected = browser.screenshot("detail-icosphere-selected").await?;
    assert!(
        selected.distinct_colours(64) > 4,
        "the copied image is not blank"
    );
    assert_eq!(
        selected.pixel(5, 300),
        shot.pixel(5, 300),
        "the backdrop beside the view is unchanged"
    );

    browser
        .eval_async("window.edgewise.loadSample('cube', { structure: 'half' })")
        .await?;
    settle(&browser).await?;
    assert_eq!(
        browser.state().await?["coarseView"],
        false,
        "the cube in full"
    );
    browser.screenshot("detail-cube-full").await?;
    browser.assert_no_console_errors().await?;
    browser.close().await
}

/// A large new mesh draws its base image a part a frame, from the frame
/// after the one that shows it, behind its motion proxy: the page paints
/// between the parts, the proxy shows the whole torus meanwhile, and the
/// finished image then takes its place and is kept.
#[tokio::test]
async fn a_large_new_mesh_draws_its_base_image_over_several_frames_behind_its_proxy()
-> anyhow::Result<()> {
    let browser = Browser::launch_on_sample("cube").await?;
    settle(&browser).await?;
    let [drawn, _] = browser.drawn_and_copied("baseImage").await?;
    let proxied = proxy_frames(&browser).await?;
    let in_parts = browser
        .canvas_when(
            "window.edgewise.loadSample('torus-200k', { structure: 'half' });",
            &format!(
                "(() => {{ const s = window.edgewise.state(); \
                 return s.mesh === 'torus-200k' && s.baseImage[0] === {drawn} \
                 && s.motionProxy >= {proxied} + 2; }})()"
            ),
            "detail-torus-in-parts",
        )
        .await?;
    until_base_image_drawn(&browser, drawn + 1).await?;
    let proxied_while_drawn = proxy_frames(&browser).await? - proxied;
    assert!(
        proxied_while_drawn >= 4,
        "the proxy showed in {proxied_while_drawn} frames while the image was drawn"
    );
    settle(&browser).await?;
    let whole = canvas_on_selection(&browser, "detail-torus-whole").await?;
    let (partly, wholly) = (drawn_in_middle(&in_parts), drawn_in_middle(&whole));
    assert!(
        wholly > 10_000 && partly.abs_diff(wholly) * 5 < wholly,
        "while drawn, the proxy covers {partly} pixels, the torus {wholly}"
    );
    let [drawn_after, _] = browser.drawn_and_copied("baseImage").await?;
    assert_eq!(drawn_after, drawn + 1, "then kept");
    assert_eq!(
        proxy_frames(&browser).await?,
        proxied + proxied_while_drawn,
        "and copied, not the proxy"
    );
    browser.assert_no_console_errors().await?;
    browser.close().await
}

/// Waits until the base image has been drawn whole `count` times in all.
async fn until_base_image_drawn(browser: &Browser, count: u64) -> anyhow::Result<()> {
    browser
        .wait_for(
            &format!("window.edgewise.state().baseImage[0] >= {count}"),
            Duration::from_secs(60),
        )
        .await
}

/// Selects vertex 0 and reads the canvas in the frame that shows it (the
/// canvas keeps no picture between frames), saved as `name`.
async fn canvas_on_selection(
    browser: &Browser,
    name: &str,
) -> anyhow::Result<edgewise_browser_tests::Screenshot> {
    browser
        .canvas_when(
            "window.edgewise.select('vertex', 0);",
            "window.edgewise.state().selection !== null",
            name,
        )
        .await
}

/// How many pixels of the view's middle, where the torus lies left of the
/// welcome card, differ from the backdrop beside the view.
fn drawn_in_middle(shot: &edgewise_browser_tests::Screenshot) -> usize {
    let backdrop = shot.pixel(5, 300);
    (60..320)
        .flat_map(|y| (450..850).map(move |x| (x, y)))
        .filter(|&(x, y)| {
            let pixel = shot.pixel(x, y);
            (0..3).any(|c| pixel[c].abs_diff(backdrop[c]) > 2)
        })
        .count()
}

/// `state().motionProxy`: how many frames drew the motion proxy.
async fn proxy_frames(browser: &Browser) -> anyhow::Result<u64> {
    Ok(browser.state().await?["motionProxy"].as_u64().unwrap_or(0))
}

/// A drag on torus-200k turns the camera with the torus drawn from its
/// motion proxy, each frame; released, the view rests, draws the torus's
/// base image behind the proxy, and then shows the torus itself again.
#[tokio::test]
async fn a_large_mesh_turns_with_its_motion_proxy_and_rests_on_the_mesh_itself()
-> anyhow::Result<()> {
    let browser = Browser::launch_on_sample("torus-200k").await?;
    until_base_image_drawn(&browser, 1).await?;
    settle(&browser).await?;
    let [drawn, _] = browser.drawn_and_copied("baseImage").await?;
    let at_rest = proxy_frames(&browser).await?;
    settle(&browser).await?;
    assert_eq!(proxy_frames(&browser).await?, at_rest, "not moved yet");

    let moving = browser
        .canvas_when(
            &format!("{FIRE_MOUSE}{DRAG_IN_VIEW}"),
            &format!("window.edgewise.state().motionProxy >= {at_rest} + 3"),
            "detail-torus-moving",
        )
        .await?;
    let [drawn_moving, _] = browser.drawn_and_copied("baseImage").await?;
    assert_eq!(drawn_moving, drawn, "no base image while the camera moves");
    browser
        .eval("window.__release = true; return null;")
        .await?;
    until_base_image_drawn(&browser, drawn + 1).await?;
    settle(&browser).await?;
    let proxied = proxy_frames(&browser).await?;
    settle(&browser).await?;
    assert_eq!(proxy_frames(&browser).await?, proxied, "at rest, no proxy");
    let rested = canvas_on_selection(&browser, "detail-torus-rested").await?;
    assert_eq!(
        proxy_frames(&browser).await?,
        proxied,
        "a selection copies the image"
    );

    // Both pictures show the torus over about the same pixels.
    let (proxy_pixels, mesh_pixels) = (drawn_in_middle(&moving), drawn_in_middle(&rested));
    assert!(
        mesh_pixels > 10_000 && proxy_pixels.abs_diff(mesh_pixels) * 5 < mesh_pixels,
        "the proxy covers {proxy_pixels} pixels, the mesh {mesh_pixels}"
    );
    browser.assert_no_console_errors().await?;
    browser.close().await
}
