//! What a screen reader finds: Chromium's accessibility tree (through the
//! DevTools protocol) holds the three tables with their captions and
//! headers, the selected row's role in words, and the step's message in a
//! live region that changes as the trace moves.

use std::time::Duration;

use edgewise_browser_tests::Browser;
use serde_json::Value;

/// Every (role, name) pair in the page's full accessibility tree.
async fn ax_nodes(browser: &Browser) -> anyhow::Result<Vec<(String, String)>> {
    let tree = browser
        .cdp("Accessibility.getFullAXTree", serde_json::json!({}))
        .await?;
    let text = |node: &Value, key: &str| node[key]["value"].as_str().unwrap_or_default().to_owned();
    Ok(tree["nodes"]
        .as_array()
        .map(|nodes| {
            nodes
                .iter()
                .map(|node| (text(node, "role"), text(node, "name")))
                .collect()
        })
        .unwrap_or_default())
}

fn has(nodes: &[(String, String)], role: &str, name: &str) -> bool {
    nodes.iter().any(|(r, n)| r == role && n.contains(name))
}

/// The tree once it has a node of `role` named with `name`: Chromium
/// updates it a moment after the page changes.
async fn ax_nodes_with(
    browser: &Browser,
    role: &str,
    name: &str,
) -> anyhow::Result<Vec<(String, String)>> {
    for _ in 0..50 {
        let nodes = ax_nodes(browser).await?;
        if has(&nodes, role, name) {
            return Ok(nodes);
        }
        tokio::time::sleep(Duration::from_millis(200)).await;
    }
    anyhow::bail!("no {role} node named with {name:?} in the accessibility tree")
}

#[tokio::test]
async fn the_accessibility_tree_holds_the_tables_and_announces_steps() -> anyhow::Result<()> {
    let browser = Browser::launch().await?;
    browser
        .open("?sample=tetrahedron&structure=half&select=edge:3")
        .await?;
    browser
        .wait_for(
            "document.getElementById('edgewise_a11y_tables').querySelectorAll('table').length === 3 \
             && document.getElementById('edgewise_a11y_live').textContent.startsWith('Half-edge 3 selected')",
            Duration::from_secs(30),
        )
        .await?;
    let nodes = ax_nodes_with(&browser, "StaticText", "Half-edge 3 selected").await?;
    for caption in ["Faces: 4 rows", "Half-edges: 12 rows", "Vertices: 4 rows"] {
        assert!(has(&nodes, "table", caption), "a table named {caption}");
    }
    for header in ["end vertex", "pair", "successor", "incident edge"] {
        assert!(
            has(&nodes, "columnheader", header),
            "a column header {header}"
        );
    }
    assert!(has(&nodes, "rowheader", "half-edge 3"));
    assert!(
        has(&nodes, "cell", "selected"),
        "the selected row says so in words"
    );
    // The live region (role status) reads out the message line.
    assert!(has(&nodes, "status", ""), "a live region");

    // Another selection changes only the role cells that change (half-edge
    // 3 is now the successor): the tables stay the same nodes (rebuilt, 900
    // rows cost Chromium about 0.1 s).
    let moved = browser
        .eval_async(
            "(async () => { \
               const tables = document.getElementById('edgewise_a11y_tables'); \
               tables.querySelector('table').__kept = true; \
               await window.edgewise.select('edge', 5); \
               await new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))); \
               const role = (id) => document.getElementById('edgewise_a11y_role_' + id).textContent; \
               return [tables.querySelector('table').__kept === true, role('e3'), role('e5')]; \
             })()",
        )
        .await?;
    assert_eq!(
        moved,
        serde_json::json!([true, "successor edge", "selected"]),
        "{moved}"
    );
    let nodes = ax_nodes_with(&browser, "StaticText", "Half-edge 5 selected").await?;
    assert!(has(&nodes, "cell", "selected"), "the new row says so");

    // A trace: each step's message replaces the live region's text.
    browser
        .eval_async("window.edgewise.run('vertexAdjacentEdge', { v: 1 }).then(() => window.edgewise.step(1))")
        .await?;
    browser
        .wait_for(
            "document.getElementById('edgewise_a11y_live').textContent.startsWith('Step 1 of')",
            Duration::from_secs(30),
        )
        .await?;
    let nodes = ax_nodes_with(&browser, "StaticText", "Step 1 of").await?;
    let live = nodes
        .iter()
        .find(|(role, name)| role == "StaticText" && name.starts_with("Step 1 of"))
        .map(|(_, name)| name.clone())
        .unwrap_or_default();
    assert!(live.contains("Highlight vertex 1"), "{live}");
    browser.eval_async("window.edgewise.step(1)").await?;
    browser
        .wait_for(
            "document.getElementById('edgewise_a11y_live').textContent.startsWith('Step 2 of')",
            Duration::from_secs(30),
        )
        .await?;
    let live = browser
        .eval("return document.getElementById('edgewise_a11y_live').getAttribute('aria-live');")
        .await?;
    assert_eq!(live, "polite");
    browser.assert_no_console_errors().await?;
    browser.close().await
}

/// The focus ring's colour in the light theme (the hover blue).
const RING: [u8; 3] = [0, 108, 204];

#[tokio::test]
async fn the_keyboard_alone_moves_focus_visibly_and_walks_a_table() -> anyhow::Result<()> {
    let browser = Browser::launch().await?;
    browser.open("?sample=tetrahedron&structure=winged").await?;
    browser
        .wait_for(
            "window.edgewise.state().mesh === 'tetrahedron.wtb'",
            Duration::from_secs(30),
        )
        .await?;
    let before = browser.screenshot("keyboard-before").await?.count(RING, 24);
    for _ in 0..3 {
        browser.press_key("Tab", 0).await?;
    }
    tokio::time::sleep(Duration::from_millis(500)).await;
    let ringed = browser
        .screenshot("keyboard-focus-ring")
        .await?
        .count(RING, 24);
    assert!(
        ringed > before + 100,
        "Tab draws a focus ring: {before} ring-blue pixels before, {ringed} after"
    );

    // Escape gives the keys back to the app: ↓ walks the edge table.
    browser.press_key("Escape", 0).await?;
    for id in [0, 1] {
        browser.press_key("ArrowDown", 0).await?;
        browser
            .wait_for(
                &format!(
                    "JSON.stringify(window.edgewise.state().selection) === \
                     '{{\"kind\":\"edge\",\"id\":{id}}}'"
                ),
                Duration::from_secs(10),
            )
            .await?;
    }
    let cleared = browser.screenshot("keyboard-walked").await?.count(RING, 24);
    assert!(
        cleared < ringed,
        "Escape hides the ring: {cleared} vs {ringed}"
    );
    browser.assert_no_console_errors().await?;
    browser.close().await
}
