//! `exportImage`: the view as PNG (a data URL of the next frame) and as
//! SVG (vector shapes and the tables), each opening as an image in the
//! browser; `exportHandout`: a run as a PDF with a page per step;
//! `recordRun`: the run as a WebM video. All are written to screenshots/ to
//! be looked at.

use base64::Engine as _;
use edgewise_browser_tests::{Browser, Screenshot, screenshots_dir};

/// Loads `src` into an `<img>` and resolves to its natural size.
fn image_size(src_js: &str) -> String {
    format!(
        "new Promise((resolve, reject) => {{ \
           const image = new Image(); \
           image.onload = () => resolve([image.naturalWidth, image.naturalHeight]); \
           image.onerror = () => reject(new Error('the image did not open')); \
           image.src = {src_js}; \
         }})"
    )
}

/// The bytes of an exported `{name, base64}` file.
fn decoded(file: &serde_json::Value) -> anyhow::Result<Vec<u8>> {
    Ok(base64::engine::general_purpose::STANDARD
        .decode(file["base64"].as_str().unwrap_or_default())?)
}

#[tokio::test]
async fn the_view_exports_as_png_and_svg_that_open_as_images() -> anyhow::Result<()> {
    let browser = Browser::launch().await?;
    browser
        .open("?sample=tetrahedron&structure=winged&select=edge:0")
        .await?;

    let svg = browser
        .eval_async("window.edgewise.exportImage('svg')")
        .await?;
    let svg = svg.as_str().unwrap_or_default().to_owned();
    std::fs::write(
        screenshots_dir()?.join("export-tetrahedron-edge-0.svg"),
        &svg,
    )?;
    assert!(
        svg.starts_with("<svg xmlns=\"http://www.w3.org/2000/svg\""),
        "{svg}"
    );
    assert!(svg.contains(">left predecessor</text>"), "{svg}");
    assert!(svg.contains(">Edges: 6 rows</text>"), "{svg}");
    let size = browser
        .eval_async(&image_size(&format!(
            "URL.createObjectURL(new Blob([{}], {{type: 'image/svg+xml'}}))",
            serde_json::to_string(&svg)?
        )))
        .await?;
    let [width, height] = [size[0].as_u64().unwrap_or(0), size[1].as_u64().unwrap_or(0)];
    assert!(
        width > 600 && height > 200,
        "the SVG opens as an image: {size}"
    );

    let png = browser
        .eval_async("window.edgewise.exportImage('png')")
        .await?;
    let png = png.as_str().unwrap_or_default().to_owned();
    let data = png
        .strip_prefix("data:image/png;base64,")
        .ok_or_else(|| anyhow::anyhow!("a PNG data URL: {}", &png[..png.len().min(60)]))?;
    let bytes = base64::engine::general_purpose::STANDARD.decode(data)?;
    let picture = Screenshot::keep("export-tetrahedron-edge-0", &bytes)?;
    assert!(!picture.is_blank(), "the PNG shows the app");
    let size = browser
        .eval_async(&image_size(&serde_json::to_string(&png)?))
        .await?;
    assert_eq!(
        size,
        serde_json::json!([picture.width, picture.height]),
        "the PNG opens as an image"
    );

    // A handout of a run: a PDF with a page per step.
    browser
        .eval_async("window.edgewise.run('vertexAdjacentEdge', {v: 1})")
        .await?;
    let handout = browser
        .eval_async("window.edgewise.exportHandout()")
        .await?;
    assert_eq!(handout["name"], "tetrahedron-vertexAdjacentEdge.pdf");
    let pdf = decoded(&handout)?;
    std::fs::write(
        screenshots_dir()?.join("handout-vertexAdjacentEdge.pdf"),
        &pdf,
    )?;
    assert!(pdf.starts_with(b"%PDF-1.4\n") && pdf.ends_with(b"%%EOF\n"));
    assert!(
        String::from_utf8_lossy(&pdf).contains("/Count 23"),
        "a page for the start and each of the 22 steps"
    );

    // The run as a video, a step every 60 ms, recorded from the canvas.
    let video = browser
        .eval_async("window.edgewise.recordRun({delay: 60})")
        .await?;
    assert_eq!(video["name"], "tetrahedron-vertexAdjacentEdge.webm");
    assert_eq!(video["type"], "video/webm");
    let webm = decoded(&video)?;
    std::fs::write(
        screenshots_dir()?.join("run-vertexAdjacentEdge.webm"),
        &webm,
    )?;
    assert!(
        webm.starts_with(&[0x1a, 0x45, 0xdf, 0xa3]),
        "a WebM (EBML) file of {} bytes",
        webm.len()
    );
    assert_eq!(
        browser.state().await?["trace"]["step"],
        0,
        "the trace is back where it was"
    );
    assert_eq!(
        browser
            .refusal("window.edgewise.recordRun({delay: 1})")
            .await?,
        "recordRun(options): options.delay must be milliseconds from 50 to 5000, not 1"
    );

    let refusal = browser
        .refusal("window.edgewise.exportImage('gif')")
        .await?;
    assert_eq!(
        refusal,
        "exportImage(format): format must be 'png' or 'svg', not the string 'gif'"
    );
    browser.assert_no_console_errors().await?;
    browser.close().await
}
