//! Meshes in the browser: every sample in both structures, linked selection,
//! and a broken OBJ that leaves the previous mesh in place.

use edgewise_browser_tests::Browser;
use edgewise_core::{formats, mesh::Structure};
use serde_json::Value;

/// The sample files, read natively to know what the app must show.
fn samples() -> Vec<(String, Vec<u8>)> {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../meshes");
    let mut samples: Vec<(String, Vec<u8>)> = std::fs::read_dir(&dir)
        .expect("meshes/ exists")
        .filter_map(Result::ok)
        .map(|entry| entry.path())
        .filter(|path| path.extension().is_some_and(|ext| ext != "md"))
        .map(|path| {
            let name = path
                .file_name()
                .expect("a directory entry has a name")
                .to_string_lossy()
                .into_owned();
            (
                name,
                std::fs::read(&path).expect("a sample file is readable"),
            )
        })
        .collect();
    samples.sort();
    samples
}

#[tokio::test]
async fn every_sample_loads_in_both_structures_and_selects() -> anyhow::Result<()> {
    let browser = Browser::launch().await?;
    browser.open("").await?;
    for (file_name, bytes) in samples() {
        let stem = file_name.split('.').next().unwrap().to_owned();
        for (structure, api_name) in [
            (Structure::WingedEdge, "winged"),
            (Structure::HalfEdge, "half"),
        ] {
            let expected = formats::load(&bytes, &file_name, structure)
                .unwrap_or_else(|err| panic!("{file_name}: {}", err.render(&file_name)))
                .mesh;
            let result = browser
                .eval_async(&format!(
                    "window.edgewise.loadSample('{stem}', {{ structure: '{api_name}' }})"
                ))
                .await?;
            assert_eq!(result, Value::Null, "{stem} as {api_name}");
            let state = browser.state().await?;
            assert_eq!(state["structure"], api_name, "{stem}");
            assert_eq!(
                state["counts"]["vertices"],
                expected.vertex_count(),
                "{stem}"
            );
            assert_eq!(state["counts"]["edges"], expected.edge_count(), "{stem}");
            assert_eq!(state["counts"]["faces"], expected.face_count(), "{stem}");
            assert_eq!(
                state["counts"]["halfedges"],
                2 * expected.edge_count(),
                "{stem}"
            );
            assert_eq!(state["error"], Value::Null);

            // Edge 0 and everything its record references.
            let result = browser
                .eval_async("window.edgewise.select('edge', 0)")
                .await?;
            assert_eq!(result, Value::Null);
            let state = browser.state().await?;
            assert_eq!(state["selection"]["kind"], "edge");
            assert_eq!(state["selection"]["id"], 0);
            let roles: Vec<&str> = state["highlights"]
                .as_array()
                .unwrap()
                .iter()
                .map(|h| h["role"].as_str().unwrap())
                .collect();
            assert_eq!(roles[0], "selected", "{stem}");
            match structure {
                Structure::WingedEdge => {
                    for role in [
                        "start vertex",
                        "end vertex",
                        "left predecessor",
                        "right successor",
                    ] {
                        assert!(roles.contains(&role), "{stem}: no {role} in {roles:?}");
                    }
                }
                Structure::HalfEdge => {
                    for role in ["end vertex", "pair edge", "successor edge", "start vertex"] {
                        assert!(roles.contains(&role), "{stem}: no {role} in {roles:?}");
                    }
                }
            }
            if matches!(stem.as_str(), "tetrahedron" | "cube" | "open-square") {
                let shot = browser
                    .screenshot(&format!("{stem}-{api_name}-edge0"))
                    .await?;
                assert!(!shot.is_blank(), "{}", shot.path.display());
            }
        }
    }
    // Selecting past the end is refused with the count.
    let message = browser
        .refusal("window.edgewise.select('face', 100000)")
        .await?;
    assert!(
        message
            .as_str()
            .is_some_and(|m| m.contains("no face 100000")),
        "{message}"
    );
    browser.assert_no_console_errors().await?;
    browser.close().await
}

#[tokio::test]
async fn a_broken_obj_is_refused_and_the_previous_mesh_stays() -> anyhow::Result<()> {
    let browser = Browser::launch().await?;
    browser.open("").await?;
    let result = browser
        .eval_async("window.edgewise.loadSample('cube')")
        .await?;
    assert_eq!(result, Value::Null);
    browser
        .eval_async("window.edgewise.select('vertex', 3)")
        .await?;

    let broken = "v 0 0 0\\nv 1 0 0\\nv 0 1 0\\nf 1 2 3\\nf 1 2 9\\n";
    let message = browser
        .refusal(&format!(
            "window.edgewise.loadMesh('{broken}', {{ format: 'obj' }})"
        ))
        .await?;
    let message = message.as_str().unwrap_or_default().to_owned();
    assert!(
        message.contains(":5:"),
        "the message names line 5: {message}"
    );
    assert!(message.contains("vertex"), "{message}");

    let state = browser.state().await?;
    assert_eq!(state["error"], Value::String(message.clone()));
    assert_eq!(state["mesh"], "cube.htb");
    assert_eq!(state["counts"]["vertices"], 8);
    assert_eq!(state["selection"]["id"], 3, "the selection survives");

    let shot = browser.screenshot("broken-obj").await?;
    assert!(!shot.is_blank());

    // A good paste then replaces the cube and clears the error.
    let good = "v 0 0 0\\nv 1 0 0\\nv 0 1 0\\nf 1 2 3\\n";
    let result = browser
        .eval_async(&format!(
            "window.edgewise.loadMesh('{good}', {{ structure: 'half' }})"
        ))
        .await?;
    assert_eq!(result, Value::Null);
    let state = browser.state().await?;
    assert_eq!(state["counts"]["faces"], 1);
    assert_eq!(state["counts"]["halfedges"], 6);
    assert_eq!(state["error"], Value::Null);
    browser.close().await
}
