//! Hover previews the element under the pointer in the other view: a vertex
//! under the mouse in 3D outlines its row in the Vertices table and names
//! it on the message line, without selecting it.

use std::time::Duration;

use edgewise_browser_tests::Browser;

#[tokio::test]
async fn the_vertex_under_the_pointer_is_previewed_in_the_tables() -> anyhow::Result<()> {
    let browser = Browser::launch().await?;
    browser.open("?sample=tetrahedron&structure=winged").await?;
    let (x, y) = browser
        .element_at("vertex", 3)
        .await?
        .ok_or_else(|| anyhow::anyhow!("vertex 3 is in view"))?;
    browser
        .cdp(
            "Input.dispatchMouseEvent",
            serde_json::json!({ "type": "mouseMoved", "x": x, "y": y }),
        )
        .await?;
    browser
        .wait_for(
            "(window.edgewise.state().hovered || {}).id === 3",
            Duration::from_secs(30),
        )
        .await?;
    let state = browser.state().await?;
    assert_eq!(
        state["hovered"],
        serde_json::json!({"kind": "vertex", "id": 3})
    );
    assert!(state["selection"].is_null(), "a preview, not a selection");
    let shot = browser.screenshot("hover-vertex-3-previewed").await?;
    assert!(shot.distinct_colours(64) > 4);
    browser.assert_no_console_errors().await?;
    browser.close().await
}
