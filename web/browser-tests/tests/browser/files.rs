//! Files in the browser: a file dropped on the canvas asks which structure
//! to build, and `exportMesh` gives what Save as… would download, which
//! loads back.

use std::time::Duration;

use edgewise_browser_tests::Browser;
use edgewise_core::{formats, mesh::Structure};
use serde_json::Value;

/// Drops a file called `name` holding `text` on the canvas, as a user's drag
/// from the desktop would: dragenter, dragover, then drop.
fn drop_script(name: &str, text: &str) -> String {
    format!(
        "const canvas = document.getElementById('edgewise_canvas');\n\
         const dt = new DataTransfer();\n\
         dt.items.add(new File([{text}], {name}, {{ type: 'text/plain' }}));\n\
         const at = {{ bubbles: true, cancelable: true, dataTransfer: dt, clientX: 600, clientY: 400 }};\n\
         for (const type of ['dragenter', 'dragover', 'drop']) {{\n\
           canvas.dispatchEvent(new DragEvent(type, at));\n\
         }}\n\
         return null;",
        text = serde_json::to_string(text).unwrap_or_default(),
        name = serde_json::to_string(name).unwrap_or_default(),
    )
}

#[tokio::test]
async fn a_dropped_obj_asks_for_a_structure_and_exports_round_trip() -> anyhow::Result<()> {
    let browser = Browser::launch().await?;
    browser.open("").await?;
    let result = browser
        .eval_async("window.edgewise.loadSample('tetrahedron')")
        .await?;
    assert_eq!(result, Value::Null);

    let quad = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n";
    browser.eval(&drop_script("quad.obj", quad)).await?;
    // The browser reads the file asynchronously; the dialog follows.
    browser
        .wait_for(
            "window.edgewise.state().dialog !== null",
            Duration::from_secs(20),
        )
        .await?;
    let state = browser.state().await?;
    assert_eq!(state["dialog"]["kind"], "structure");
    assert_eq!(state["dialog"]["file"], "quad.obj");
    assert_eq!(
        state["dialog"]["structure"], "winged",
        "the current structure"
    );
    assert_eq!(
        state["mesh"], "tetrahedron.wtb",
        "nothing opens before the answer"
    );
    // egui sizes a new window in the frame after it appears, unasked.
    browser.frames(3).await?;
    let shot = browser.screenshot("structure-dialog").await?;
    assert!(!shot.is_blank());

    let result = browser
        .eval_async("window.edgewise.chooseStructure('half')")
        .await?;
    assert_eq!(result, Value::Null);
    let state = browser.state().await?;
    assert_eq!(state["dialog"], Value::Null);
    assert_eq!(state["mesh"], "quad.obj");
    assert_eq!(state["structure"], "half");
    assert_eq!(state["counts"]["faces"], 1);
    assert_eq!(state["counts"]["halfedges"], 8);
    assert_eq!(state["error"], Value::Null);

    // A second answer has nothing to answer.
    let message = browser
        .refusal("window.edgewise.chooseStructure('winged')")
        .await?;
    assert!(message.is_string(), "{message}");

    // Save as .htb: the text loads back natively with the same counts.
    let exported = browser
        .eval_async("window.edgewise.exportMesh('htb')")
        .await?;
    assert_eq!(exported["name"], "quad.htb");
    let text = exported["text"].as_str().unwrap_or_default();
    let mesh = formats::load(text.as_bytes(), "quad.htb", Structure::HalfEdge)
        .map_err(|err| anyhow::anyhow!(err.render("quad.htb")))?
        .mesh;
    assert_eq!(
        (mesh.vertex_count(), mesh.edge_count(), mesh.face_count()),
        (4, 4, 1)
    );
    // ...and back into the app through loadMesh.
    let result = browser
        .eval_async(&format!(
            "window.edgewise.loadMesh({}, {{ format: 'htb' }})",
            serde_json::to_string(text)?
        ))
        .await?;
    assert_eq!(result, Value::Null);
    assert_eq!(browser.state().await?["counts"]["halfedges"], 8);

    // Binary PLY comes as base64, named after the reloaded (pasted) mesh.
    let exported = browser
        .eval_async("window.edgewise.exportMesh('ply-binary')")
        .await?;
    assert_eq!(exported["name"], "pasted.ply");
    let header = browser
        .eval_async(&format!(
            "atob({}).slice(0, 36)",
            serde_json::to_string(&exported["base64"])?
        ))
        .await?;
    assert_eq!(header, "ply\nformat binary_little_endian 1.0\n");

    // An unknown format is refused.
    let refused = browser
        .eval_async("window.edgewise.exportMesh('stl')")
        .await;
    assert!(refused.is_err(), "{refused:?}");

    browser.assert_no_console_errors().await?;
    browser.close().await
}

#[tokio::test]
async fn a_broken_dropped_table_file_keeps_the_mesh() -> anyhow::Result<()> {
    let browser = Browser::launch().await?;
    browser.open("").await?;
    browser
        .eval_async("window.edgewise.loadSample('cube')")
        .await?;

    // A table file opens without a question; this one is broken at line 2.
    browser
        .eval(&drop_script("broken.wtb", "wtb 1\nvertices lots\n"))
        .await?;
    browser
        .wait_for(
            "window.edgewise.state().error !== null",
            Duration::from_secs(20),
        )
        .await?;
    let state = browser.state().await?;
    let error = state["error"].as_str().unwrap_or_default();
    assert!(error.starts_with("broken.wtb:2"), "{error}");
    assert_eq!(state["mesh"], "cube.htb");
    assert_eq!(state["dialog"], Value::Null);
    let shot = browser.screenshot("dropped-broken-file").await?;
    assert!(!shot.is_blank());
    browser.close().await
}
