//! The page loads, the app starts, and failures are shown to the user.

use std::time::Duration;

use anyhow::ensure;
use edgewise_browser_tests::{Browser, LaunchOptions, Renderer, Screenshot};

#[tokio::test]
async fn app_starts_and_defines_its_api() -> anyhow::Result<()> {
    let browser = Browser::launch().await?;
    browser.open("").await?;

    let version = browser.eval("return window.edgewise.version;").await?;
    assert_eq!(version, env!("CARGO_PKG_VERSION"));

    let backend = browser.eval("return window.edgewise.backend;").await?;
    assert!(
        backend == "webgpu" || backend == "webgl2",
        "unexpected backend {backend}"
    );

    // state() is a plain object that survives a JSON round trip.
    let state = browser.state().await?;
    assert!(state.is_object(), "state() returned {state}");
    assert_eq!(state["version"], version);
    assert_eq!(state["backend"], backend);
    let round_trip = browser
        .eval("return JSON.parse(JSON.stringify(window.edgewise.state())).version;")
        .await?;
    assert_eq!(round_trip, version);

    // The render loop is alive: frames keep coming.
    browser
        .wait_for(
            "window.edgewise.state().frames >= 2",
            Duration::from_secs(30),
        )
        .await?;

    // The loading message is gone once the app runs.
    let loading = browser
        .eval("return document.getElementById('edgewise_loading') !== null;")
        .await?;
    assert_eq!(loading, false);

    let shot = browser.screenshot("startup").await?;
    assert!(!shot.is_blank(), "{} is blank", shot.path.display());

    browser.assert_no_console_errors().await?;
    browser.close().await
}

#[tokio::test]
async fn the_page_shows_a_loading_message_until_the_app_runs() -> anyhow::Result<()> {
    let browser = Browser::launch().await?;
    // The page as served, before any script runs.
    browser.goto("").await?;
    let html = browser
        .eval_async("fetch(location.href).then((r) => r.text())")
        .await?;
    let html = html.as_str().unwrap_or_default();
    assert!(
        html.contains("id=\"edgewise_loading\""),
        "no loading element"
    );
    assert!(html.contains("Loading Edgewise"), "no loading text");
    // Nothing is fetched from other hosts.
    assert!(!html.contains("http://") && !html.contains("https://"));
    browser.close().await
}

#[tokio::test]
async fn a_wasm_file_that_fails_to_load_gives_a_clear_message() -> anyhow::Result<()> {
    let browser = Browser::launch().await?;
    browser.block_urls(&["*.wasm"]).await?;
    browser.goto("").await?;
    let message = browser.page_error(Duration::from_secs(60)).await?;
    assert!(
        message.starts_with("Edgewise could not load"),
        "unclear message: {message}"
    );
    let loading = browser
        .eval("return document.getElementById('edgewise_loading') !== null;")
        .await?;
    assert_eq!(
        loading, false,
        "the loading message stays up beside the error"
    );
    let shot = browser.screenshot("wasm-blocked").await?;
    assert!(!shot.is_blank());
    browser.close().await
}

#[tokio::test]
async fn without_webgl_or_webgpu_the_page_explains_why() -> anyhow::Result<()> {
    let browser = Browser::launch_with(LaunchOptions {
        renderer: Renderer::None,
        ..LaunchOptions::default()
    })
    .await?;
    browser.goto("").await?;
    let message = browser.page_error(Duration::from_secs(120)).await?;
    assert!(
        message.contains("WebGPU or WebGL2"),
        "unclear message: {message}"
    );
    let shot = browser.screenshot("no-3d").await?;
    assert!(!shot.is_blank());
    browser.close().await
}

/// The suite draws on lavapipe. Chromium's own `SwiftShader` is what the
/// benchmarks measure on, and what Chromium offers a machine without a
/// GPU: the app must start there, and a traced step must look the same on
/// both.
#[tokio::test]
async fn lavapipe_and_swiftshader_draw_a_step_alike() -> anyhow::Result<()> {
    const STEP: &str = "?sample=tetrahedron&structure=winged&algorithm=vertexAdjacentEdge\
                        &args=v:1&step=6&ids=always";
    const WEBGL_RENDERER: &str = "const gl = document.createElement('canvas').getContext('webgl2');
         const info = gl.getExtension('WEBGL_debug_renderer_info');
         return gl.getParameter(info.UNMASKED_RENDERER_WEBGL);";
    let mut shots = Vec::new();
    for (renderer, name) in [
        (Renderer::Lavapipe, "llvmpipe"),
        (Renderer::SwiftShader, "SwiftShader"),
    ] {
        // Lavapipe's is the shared Chromium; SwiftShader's, one of its own.
        let browser = Browser::launch_with(LaunchOptions {
            renderer,
            ..LaunchOptions::default()
        })
        .await?;
        browser.open(STEP).await?;
        browser
            .wait_for(
                "window.edgewise.state().trace && window.edgewise.state().trace.step === 6",
                Duration::from_secs(20),
            )
            .await?;
        let drawn_by = browser.eval(WEBGL_RENDERER).await?;
        ensure!(
            drawn_by.as_str().is_some_and(|r| r.contains(name)),
            "WebGL2 draws on {name}: {drawn_by}"
        );
        browser.eval_async("window.edgewise.settled()").await?;
        shots.push(browser.screenshot(&format!("renderer-{name}")).await?);
        browser.assert_no_console_errors().await?;
        browser.close().await?;
    }
    let [lavapipe, swiftshader] = &shots[..] else {
        unreachable!("one screenshot per renderer")
    };
    // 42 of 1,024,000 pixels differed when this was written: the edges of
    // the spheres and arrows, rounded otherwise.
    let differing = differing_pixels(lavapipe, swiftshader)?;
    ensure!(
        differing * 1000 <= lavapipe.width as usize * lavapipe.height as usize,
        "{differing} pixels differ between {} and {}",
        lavapipe.path.display(),
        swiftshader.path.display()
    );
    Ok(())
}

/// Pixels that differ by more than a rasteriser's rounding (16 in a
/// channel) between two screenshots of one size.
fn differing_pixels(a: &Screenshot, b: &Screenshot) -> anyhow::Result<usize> {
    ensure!(
        (a.width, a.height) == (b.width, b.height),
        "screenshots of one size"
    );
    Ok((0..a.height)
        .flat_map(|y| (0..a.width).map(move |x| (x, y)))
        .filter(|&(x, y)| {
            let (p, q) = (a.pixel(x, y), b.pixel(x, y));
            (0..3).any(|c| p[c].abs_diff(q[c]) > 16)
        })
        .count())
}
