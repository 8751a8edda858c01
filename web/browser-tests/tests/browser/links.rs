//! Course links in the browser: crafted URLs reproduce a view (a sample
//! with an algorithm at a step; inline OBJ built the way docs/embedding.md
//! shows), a broken fragment falls back with a message, and the Share link
//! of a view opens the same view.

use std::time::Duration;

use edgewise_browser_tests::Browser;
use serde_json::Value;

const APPLY_TIMEOUT: Duration = Duration::from_secs(20);

#[tokio::test]
async fn a_sample_an_algorithm_and_a_step() -> anyhow::Result<()> {
    let browser = Browser::launch().await?;
    browser
        .open("?sample=tetrahedron&structure=winged&algorithm=vertexAdjacentEdge&args=v:1&step=6&ids=always")
        .await?;
    browser
        .wait_for(
            "window.edgewise.state().trace && window.edgewise.state().trace.step === 6",
            APPLY_TIMEOUT,
        )
        .await?;
    let state = browser.state().await?;
    assert_eq!(state["mesh"], "tetrahedron.wtb");
    assert_eq!(state["structure"], "winged");
    assert_eq!(state["trace"]["algorithm"], "vertexAdjacentEdge");
    assert_eq!(state["trace"]["variables"]["v"], "Vertex 1");
    assert_eq!(state["error"], Value::Null);
    let shot = browser.screenshot("link-tetrahedron-step6").await?;
    assert!(!shot.is_blank(), "{}", shot.path.display());
    browser.assert_no_console_errors().await?;
    browser.close().await
}

#[tokio::test]
async fn inline_obj_compressed_in_the_page_opens() -> anyhow::Result<()> {
    let browser = Browser::launch().await?;
    browser.open("").await?;
    // Build the fragment as a page author would: deflate-raw, then base64url.
    let payload = browser
        .payload("'v 0 0 0\\nv 1 0 0\\nv 1 1 0\\nv 0 1 0\\nv 0.5 0.5 1\\nf 1 2 5\\nf 2 3 5\\nf 3 4 5\\nf 4 1 5\\n'")
        .await?;
    let fragment = format!("mesh={payload}&format=obj");
    browser
        .open(&format!("?structure=half&select=face:2#{fragment}"))
        .await?;
    browser
        .wait_for("window.edgewise.state().counts.faces === 4", APPLY_TIMEOUT)
        .await?;
    let state = browser.state().await?;
    assert_eq!(state["structure"], "half");
    assert_eq!(state["counts"]["vertices"], 5);
    assert_eq!(state["selection"]["kind"], "face");
    assert_eq!(state["selection"]["id"], 2);
    assert_eq!(state["error"], Value::Null);
    browser.assert_no_console_errors().await?;
    browser.close().await
}

#[tokio::test]
async fn a_broken_fragment_falls_back_with_a_message() -> anyhow::Result<()> {
    let browser = Browser::launch().await?;
    browser
        .open("?sample=cube&step=abc#mesh=%%%not-a-payload&alg=@@@")
        .await?;
    browser
        .wait_for("window.edgewise.state().error !== null", APPLY_TIMEOUT)
        .await?;
    let state = browser.state().await?;
    let error = state["error"].as_str().unwrap_or_default();
    assert!(
        error.starts_with("Some of this link could not be followed"),
        "{error}"
    );
    for part in ["step=abc", "#mesh", "#alg"] {
        assert!(error.contains(part), "no message about {part}: {error}");
    }
    // Never a blank page: the cube is on screen.
    assert_eq!(state["mesh"], "cube.htb");
    let shot = browser.screenshot("link-broken-fragment").await?;
    assert!(!shot.is_blank(), "{}", shot.path.display());
    browser.close().await
}

#[tokio::test]
async fn the_share_link_opens_the_same_view() -> anyhow::Result<()> {
    let browser = Browser::launch().await?;
    browser.open("").await?;
    for command in [
        "window.edgewise.loadSample('octahedron', {structure: 'half'})",
        "window.edgewise.run('vertexAdjacentFace', {v: 2})",
        "window.edgewise.step(9)",
    ] {
        assert_eq!(browser.eval_async(command).await?, Value::Null, "{command}");
    }
    let before = browser.state().await?;
    let url = browser.eval("return window.edgewise.shareUrl()").await?;
    let url = url.as_str().expect("a URL").to_owned();
    assert!(url.starts_with(browser.base_url()), "{url}");
    let suffix = &url[browser.base_url().len()..];
    browser.open(suffix).await?;
    browser
        .wait_for(
            "window.edgewise.state().trace && window.edgewise.state().trace.step === 9",
            APPLY_TIMEOUT,
        )
        .await?;
    let after = browser.state().await?;
    assert_eq!(after["trace"], before["trace"]);
    assert_eq!(after["highlights"], before["highlights"]);
    assert_eq!(after["mesh"], before["mesh"]);
    browser.assert_no_console_errors().await?;
    browser.close().await
}
