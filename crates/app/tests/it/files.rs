//! Opening files (dropped on the window, with the structure dialog), saving
//! in every format, and the OBJ editor's inline error marks, driven natively
//! through `egui_kittest`.

use crate::support;

use std::path::Path;

use edgewise_app::{EdgewiseApp, code_editor::Diagnostic, save_format::SaveFormat};
use edgewise_core::{formats, mesh::Structure};
use egui_kittest::{Harness, kittest::Queryable as _};

const QUAD: &str = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n";

fn harness() -> Harness<'static, EdgewiseApp> {
    support::harness_sized(1280.0, 800.0)
}

fn drop_file(harness: &mut Harness<'static, EdgewiseApp>, name: &str, bytes: &[u8]) {
    support::drop_file(harness, name, bytes.to_vec());
    harness.run();
}

#[test]
fn a_dropped_obj_asks_for_a_structure_and_opens_as_half_edge() {
    let mut harness = harness();
    harness.state_mut().load_sample("cube", None).expect("cube");
    harness.run();
    drop_file(&mut harness, "quad.obj", QUAD.as_bytes());

    let state = harness.state().state();
    let dialog = state.dialog.expect("the structure dialog is open");
    assert_eq!(
        (dialog.kind, dialog.file.as_str()),
        ("structure", "quad.obj")
    );
    // It offers the current structure first: the cube sample is half-edge.
    assert_eq!(dialog.structure, "half");
    assert_eq!(state.mesh.as_deref(), Some("cube.htb"), "nothing opens yet");

    harness
        .get_by_label("Winged-edge: one record per edge, with its two faces and four wings")
        .click();
    harness.run();
    harness
        .get_by_label("Half-edge: two records per edge, one for each side")
        .click();
    harness.run();
    harness.get_by_label("Open").click();
    harness.run();

    let state = harness.state().state();
    assert!(state.dialog.is_none());
    assert_eq!(state.mesh.as_deref(), Some("quad.obj"));
    assert_eq!(state.structure, Some("half"));
    assert_eq!((state.counts.faces, state.counts.halfedges), (1, 8));
    assert!(state.error.is_none());
}

#[test]
fn cancelling_the_dialog_keeps_the_mesh() {
    let mut harness = harness();
    harness
        .state_mut()
        .load_sample("tetrahedron", None)
        .expect("tetrahedron");
    drop_file(&mut harness, "quad.obj", QUAD.as_bytes());
    assert_eq!(
        harness.state().state().dialog.map(|d| d.structure),
        Some("winged")
    );
    harness.get_by_label("Cancel").click();
    harness.run();
    let state = harness.state().state();
    assert!(state.dialog.is_none());
    assert_eq!(state.mesh.as_deref(), Some("tetrahedron.wtb"));
    // Answering with nothing to answer is refused.
    assert!(harness.state_mut().answer_structure_dialog(None).is_err());
}

#[test]
fn table_files_open_as_what_they_store_and_bad_files_keep_the_mesh() {
    let mut harness = harness();
    let cube = std::fs::read(Path::new(env!("CARGO_MANIFEST_DIR")).join("../../meshes/cube.htb"))
        .expect("the cube sample");
    drop_file(&mut harness, "cube.htb", &cube);
    let state = harness.state().state();
    assert!(state.dialog.is_none(), "a table file needs no question");
    assert_eq!(state.structure, Some("half"));

    drop_file(&mut harness, "notes.txt", b"hello");
    let state = harness.state().state();
    assert_eq!(state.mesh.as_deref(), Some("cube.htb"));
    let error = state.error.expect("an unknown extension is refused");
    assert!(
        error.contains("notes.txt") && error.contains(".obj"),
        "{error}"
    );

    // A broken PLY chosen as winged-edge: the loader's place is in the message.
    drop_file(
        &mut harness,
        "bad.ply",
        b"ply\nformat ascii 1.0\nelement vertex x\n",
    );
    harness
        .state_mut()
        .answer_structure_dialog(Some(Structure::WingedEdge))
        .unwrap_err();
    harness.run();
    let state = harness.state().state();
    assert_eq!(state.mesh.as_deref(), Some("cube.htb"));
    assert!(
        state
            .error
            .as_deref()
            .is_some_and(|e| e.starts_with("bad.ply:3")),
        "{:?}",
        state.error
    );
}

#[test]
fn every_save_format_loads_back_with_the_same_counts() {
    let mut harness = harness();
    let app = harness.state_mut();
    app.load_sample("cube", Some(Structure::WingedEdge))
        .expect("cube");
    let expected = app.state().counts;
    for format in SaveFormat::ALL {
        let saved = app.export(format).expect("the cube saves");
        assert_eq!(
            saved.name,
            format!("cube.{}", format.format().extension()),
            "{format:?}"
        );
        // Each file loads as the structure it stores (winged for PLY and OBJ).
        let loaded = formats::load(&saved.bytes, &saved.name, Structure::WingedEdge)
            .unwrap_or_else(|err| panic!("{format:?}: {}", err.render(&saved.name)));
        assert_eq!(
            (
                loaded.mesh.vertex_count(),
                loaded.mesh.edge_count(),
                loaded.mesh.face_count()
            ),
            (expected.vertices, expected.edges, expected.faces),
            "{format:?}"
        );
        if format == SaveFormat::Htb {
            assert!(loaded.converted_from.is_some(), "htb stores half-edges");
        }
    }
    let binary = app.export(SaveFormat::PlyBinary).expect("binary PLY");
    assert!(
        binary
            .bytes
            .starts_with(b"ply\nformat binary_little_endian 1.0\n")
    );

    // The menu offers every format.
    harness.run();
    harness.get_by_label("Save as…").click();
    harness.run();
    for format in SaveFormat::ALL {
        harness.get_by_label(format.label());
    }
}

#[test]
fn a_broken_edit_is_marked_at_its_line_and_the_mesh_stays() {
    let mut harness = harness();
    support::type_in_obj_editor(&mut harness, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    assert_eq!(harness.state().state().counts.faces, 1);
    let editor = harness.get_by_role(egui::accesskit::Role::MultilineTextInput);
    editor.type_text("f 1 2 7\n");
    harness.run_steps(60);

    let state = harness.state().state();
    assert_eq!(state.counts.faces, 1, "the last good mesh stays");
    assert!(
        state.error.is_none(),
        "the editor shows the problem, not the panel"
    );
    let [
        Diagnostic {
            line,
            column,
            message,
        },
    ] = state.diagnostics.as_slice()
    else {
        panic!("one diagnostic: {:?}", state.diagnostics);
    };
    assert_eq!((*line, *column), (5, Some(7)), "{message}");
    // The message is on screen, in the editor panel, without hovering.
    let label = harness.get_by_label_contains(message.as_str());
    assert!(label.rect().left() > 900.0, "{:?}", label.rect());

    // Deleting the line clears the mark.
    for _ in "f 1 2 7\n".chars() {
        harness.key_press(egui::Key::Backspace);
    }
    harness.run_steps(60);
    let state = harness.state().state();
    assert!(state.diagnostics.is_empty(), "{:?}", state.diagnostics);
}

/// A line still being typed waits for a longer pause before it replaces
/// the last good mesh (`f 1 2 3` on the way to `f 1 2 3 4` is a valid
/// triangle); Enter builds at once. A pasted mesh is framed by the camera.
#[test]
fn a_half_typed_line_waits_and_a_paste_is_framed() {
    let mut harness = harness();
    support::type_in_obj_editor(
        &mut harness,
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 4\n",
    );
    assert_eq!(harness.state().state().counts.faces, 1);
    let editor = harness.get_by_role(egui::accesskit::Role::MultilineTextInput);
    editor.type_text("f 2 3 4");
    // The harness's frames are a quarter of a second apart.
    harness.run_steps(2);
    assert_eq!(
        harness.state().state().counts.faces,
        1,
        "half a second into typing a line, the mesh changed"
    );
    harness.run_steps(4);
    assert_eq!(harness.state().state().counts.faces, 2, "a pause builds it");

    // A paste of a mesh far away: the camera frames it.
    let far = "v 100 100 100\nv 101 100 100\nv 100 101 100\nf 1 2 3\n";
    let editor = harness.get_by_role(egui::accesskit::Role::MultilineTextInput);
    editor.focus();
    harness.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::A);
    harness.event(egui::Event::Paste(far.to_owned()));
    harness.run_steps(40);
    let state = harness.state().state();
    assert_eq!(state.counts.vertices, 3, "the paste replaced the text");
    let camera = harness.state().course_link().camera.expect("a camera");
    assert!(
        camera.target.iter().all(|&c| (99.0..=102.0).contains(&c)),
        "the camera did not frame the pasted mesh: {camera:?}"
    );
}
