//! Editing by hand in the browser: the edit menu on a right-clicked edge,
//! applied with Enter; undo and redo from the keyboard and the API; and a
//! hand-written table with one wrong wing, diagnosed and fixed cell by cell.

use std::time::Duration;

use edgewise_browser_tests::{Browser, LaunchOptions};
use serde_json::Value;

const WAIT: Duration = Duration::from_secs(20);

#[tokio::test]
async fn the_edit_menu_undo_redo_and_a_diagnosed_wing() -> anyhow::Result<()> {
    // A projector-sized window: the README shows these screenshots.
    let browser = Browser::launch_with(LaunchOptions {
        window_size: (1600, 1000),
        ..LaunchOptions::default()
    })
    .await?;
    browser.open("").await?;
    browser
        .eval_async("window.edgewise.loadSample('hexagon', { structure: 'half' })")
        .await?;
    browser
        .wait_for("window.edgewise.screenPosition('edge', 2)", WAIT)
        .await?;

    // Right-click half-edge 2 in the 3D view: the menu opens on it.
    let (x, y) = browser
        .element_at("edge", 2)
        .await?
        .expect("half-edge 2 is in view");
    browser.click_at(x, y, "right").await?;
    browser
        .wait_for("window.edgewise.state().editMenu", WAIT)
        .await?;
    let state = browser.state().await?;
    let menu = &state["editMenu"];
    assert_eq!(menu["element"]["kind"], "edge", "{menu}");
    assert_eq!(menu["element"]["id"], 2, "{menu}");
    let entries = menu["entries"].as_array().cloned().unwrap_or_default();
    let flip = entries
        .iter()
        .find(|e| e["operation"] == "flip-edge")
        .expect("flip is offered");
    assert_eq!(flip["refused"], Value::Null, "an inner edge flips: {flip}");
    let kemr = entries
        .iter()
        .find(|e| e["operation"] == "kemr")
        .expect("kemr is offered");
    assert!(kemr["refused"].as_str().is_some(), "{kemr}");
    assert_eq!(state["selection"]["id"], 2);
    let shot = browser.screenshot("edit-menu").await?;
    assert!(shot.distinct_colours(64) > 8, "the view is drawn");

    // Enter applies the first entry that applies: the flip.
    browser.press_key("Enter", 0).await?;
    browser
        .wait_for("!window.edgewise.state().editMenu", WAIT)
        .await?;
    let state = browser.state().await?;
    assert_eq!(state["history"]["undo"][1], "flip-edge 2", "{state}");
    assert_eq!(state["error"], Value::Null);
    // What the flip wrote stays marked, old values struck through.
    let roles: Vec<&str> = state["highlights"]
        .as_array()
        .map(|h| h.iter().filter_map(|h| h["role"].as_str()).collect())
        .unwrap_or_default();
    assert!(roles.contains(&"written"), "{roles:?}");
    browser.screenshot("edit-applied").await?;

    // Ctrl+Z takes it back; redo() makes it again; undo() again.
    browser.press_key("z", 2).await?;
    browser
        .wait_for("window.edgewise.state().history.redo.length === 1", WAIT)
        .await?;
    browser.eval_async("window.edgewise.redo()").await?;
    let state = browser.state().await?;
    assert_eq!(state["history"]["redo"], serde_json::json!([]));
    let refused = browser.refusal("window.edgewise.redo()").await?;
    assert_eq!(refused, "nothing to redo");
    browser.eval_async("window.edgewise.undo()").await?;

    // A hand-written Table 2 with one wrong wing: refused as a plain load,
    // opened for diagnosis on request.
    let wtb = include_str!("../../../../tests/bad-inputs/wtb-bad-wing.wtb");
    let text = serde_json::to_string(wtb)?;
    let refused = browser
        .refusal(&format!(
            "window.edgewise.loadMesh({text}, {{ format: 'wtb' }})"
        ))
        .await?;
    assert!(
        refused
            .as_str()
            .is_some_and(|m| m.contains("edge 2 left_predecessor")),
        "{refused}"
    );
    browser
        .eval_async(&format!(
            "window.edgewise.loadMesh({text}, {{ format: 'wtb', diagnose: true }})"
        ))
        .await?;
    let state = browser.state().await?;
    assert_eq!(state["diagnosis"], true, "{state}");
    let broken = state["broken"].as_array().cloned().unwrap_or_default();
    assert!(
        broken
            .iter()
            .any(|b| b["kind"] == "edge" && b["id"] == 2 && b["column"] == "leftPredecessor"),
        "{broken:?}"
    );
    browser.screenshot("diagnosis-wrong-wing").await?;

    // Setting the cell right ends diagnosis: the journal's Table 2.
    let refused = browser
        .refusal("window.edgewise.setCell('edge', 2, 'leftPredecesor', 0)")
        .await?;
    assert!(
        refused
            .as_str()
            .is_some_and(|m| m.contains("there is no column `leftPredecesor`")),
        "{refused}"
    );
    browser
        .eval_async("window.edgewise.setCell('edge', 2, 'leftPredecessor', 0)")
        .await?;
    let state = browser.state().await?;
    assert_eq!(state["diagnosis"], false, "{state}");
    assert_eq!(state["broken"], serde_json::json!([]));
    assert_eq!(state["stats"]["faces"], 4);
    browser.screenshot("diagnosis-fixed").await?;
    browser.assert_no_console_errors().await?;
    browser.close().await
}
