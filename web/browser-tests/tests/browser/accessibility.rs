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
    browser.frames(2).await?;
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

/// The DOM node behind the accessibility tree's first node of `role` whose
/// name is exactly `name`, as a remote object id: what a screen reader
/// acts on.
async fn ax_object(browser: &Browser, role: &str, name: &str) -> anyhow::Result<String> {
    for _ in 0..50 {
        let tree = browser
            .cdp("Accessibility.getFullAXTree", serde_json::json!({}))
            .await?;
        let found = tree["nodes"].as_array().and_then(|nodes| {
            nodes.iter().find(|node| {
                node["role"]["value"] == role
                    && node["name"]["value"] == name
                    && node["ignored"] != true
            })
        });
        if let Some(id) = found.and_then(|node| node["backendDOMNodeId"].as_u64()) {
            let resolved = browser
                .cdp("DOM.resolveNode", serde_json::json!({"backendNodeId": id}))
                .await?;
            if let Some(object) = resolved["object"]["objectId"].as_str() {
                return Ok(object.to_owned());
            }
        }
        tokio::time::sleep(Duration::from_millis(200)).await;
    }
    anyhow::bail!("no {role} named {name:?} in the accessibility tree")
}

/// Activates the button named `name` as a screen reader does (a click on
/// its node), found through the accessibility tree alone.
async fn activate(browser: &Browser, name: &str) -> anyhow::Result<()> {
    let object = ax_object(browser, "button", name).await?;
    browser
        .cdp(
            "Runtime.callFunctionOn",
            serde_json::json!({"objectId": object, "functionDeclaration": "function () { this.click(); }"}),
        )
        .await?;
    Ok(())
}

/// The live region's text once it starts with `start`.
async fn announced(browser: &Browser, start: &str) -> anyhow::Result<String> {
    let waited = browser
        .wait_for(
            &format!(
                "document.getElementById('edgewise_a11y_live').textContent.startsWith({start:?})"
            ),
            Duration::from_secs(30),
        )
        .await;
    let text = browser
        .eval("return document.getElementById('edgewise_a11y_live').textContent;")
        .await?;
    let text = text.as_str().unwrap_or_default().to_owned();
    waited.map_err(|error| error.context(format!("the live region says {text:?}")))?;
    Ok(text)
}

/// A screen reader starts a run and steps it from the page's copy alone:
/// the algorithm's form and the step buttons are real controls in the
/// accessibility tree, each step's sentence comes from the live region, and
/// the copy holds the current line and the variables with their values.
#[tokio::test]
async fn a_screen_reader_steps_a_run_from_the_page_copy_alone() -> anyhow::Result<()> {
    let browser = Browser::launch().await?;
    browser.open("?sample=tetrahedron&structure=winged").await?;
    browser
        .wait_for(
            "window.edgewise && window.edgewise.state().mesh === 'tetrahedron.wtb'",
            Duration::from_secs(60),
        )
        .await?;

    // The input as its label names it, then the form's Run button.
    let field = ax_object(&browser, "spinbutton", "v, a Vertex id").await?;
    let vertex_adjacent = "function () { \
         const form = this.closest('form'); \
         return form.dataset.algorithm; }";
    let form = browser
        .cdp(
            "Runtime.callFunctionOn",
            serde_json::json!({"objectId": field, "functionDeclaration": vertex_adjacent, "returnByValue": true}),
        )
        .await?;
    assert!(
        form["result"]["value"].is_string(),
        "the field is in a form: {form}"
    );
    browser
        .eval(
            "document.querySelector('form[data-algorithm=\"vertexAdjacentEdge\"] input[name=\"v\"]').value = '1'; \
             return null;",
        )
        .await?;
    activate(&browser, "Run vertexAdjacentEdge").await?;
    let ready = announced(&browser, "Step 0 of 22: vertexAdjacentEdge is ready").await?;
    assert!(ready.ends_with("with v = vertex 1"), "{ready}");

    let copy = |id: &'static str| {
        let browser = &browser;
        async move {
            let text = browser
                .eval(&format!(
                    "return document.getElementById('{id}').textContent;"
                ))
                .await?;
            anyhow::Ok(text.as_str().unwrap_or_default().to_owned())
        }
    };
    activate(&browser, "Step").await?;
    let first = announced(&browser, "Step 1 of 22").await?;
    assert!(first.contains("vertex 1"), "{first}");
    assert_eq!(
        copy("edgewise_a11y_status").await?,
        "vertexAdjacentEdge, step 1 of 22"
    );
    assert_eq!(
        copy("edgewise_a11y_line").await?,
        "Line 13: e := v.incidentEdge;"
    );
    activate(&browser, "Step").await?;
    announced(&browser, "Step 2 of 22").await?;
    let variables = browser
        .eval(
            "return [...document.querySelectorAll('#edgewise_a11y_variables dt')] \
             .map((dt) => dt.textContent + ' = ' + dt.nextElementSibling.textContent);",
        )
        .await?;
    assert_eq!(
        variables,
        serde_json::json!([
            "v, Vertex = Vertex 1",
            "e, Edge = Edge 1",
            "se, Edge = null"
        ]),
        "each variable with its value"
    );
    // The role cell names the variable, as the view's label does.
    let roles = browser
        .eval(
            "return [...document.querySelectorAll('[id^=edgewise_a11y_role_]')] \
             .map((cell) => cell.textContent).filter((text) => text);",
        )
        .await?;
    assert!(
        roles.as_array().is_some_and(|r| r
            .iter()
            .any(|w| w.as_str().is_some_and(|w| w.contains("variable e")))),
        "a role cell says which variable: {roles}"
    );

    activate(&browser, "Back").await?;
    announced(&browser, "Step 1 of 22").await?;
    activate(&browser, "To end").await?;
    announced(&browser, "Step 22 of 22").await?;
    assert_eq!(
        copy("edgewise_a11y_status").await?,
        "vertexAdjacentEdge, step 22 of 22, done"
    );
    activate(&browser, "To start").await?;
    browser
        .wait_for(
            "document.getElementById('edgewise_a11y_status').textContent === 'vertexAdjacentEdge, step 0 of 22'",
            Duration::from_secs(30),
        )
        .await?;
    activate(&browser, "Play").await?;
    browser
        .wait_for(
            "document.getElementById('edgewise_a11y_status').textContent.endsWith(', playing') \
             && window.edgewise.state().trace.step >= 2",
            Duration::from_secs(60),
        )
        .await?;
    activate(&browser, "Pause").await?;
    browser
        .wait_for(
            "!document.getElementById('edgewise_a11y_status').textContent.endsWith(', playing')",
            Duration::from_secs(30),
        )
        .await?;
    // A keyboard user who tabs into the copy sees it, over the app.
    browser
        .eval("document.querySelector('[data-edgewise-call=step]').focus(); return null;")
        .await?;
    let shown = browser
        .eval("return document.getElementById('edgewise_a11y').getBoundingClientRect().width;")
        .await?;
    assert!(
        shown.as_f64().unwrap_or_default() > 200.0,
        "the focused copy shows: {shown}"
    );
    browser.screenshot("reader-copy-focused").await?;
    activate(&browser, "Abort").await?;
    browser
        .wait_for(
            "document.getElementById('edgewise_a11y_controls').hidden",
            Duration::from_secs(30),
        )
        .await?;
    browser.assert_no_console_errors().await?;
    browser.close().await
}
