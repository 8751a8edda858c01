//! Input limits in the app: a large file says it is being opened before it
//! is read, and the editors refuse a paste past their size before laying it
//! out, keeping their text.

use crate::support;

use edgewise_app::{EdgewiseApp, files::ANNOUNCE_BYTES, obj_editor::MAX_EDITOR_BYTES};
use edgewise_core::formats::{self, Format, SaveOptions};
use edgewise_core::mesh::{Mesh, Structure, generate};
use egui_kittest::{Harness, kittest::Queryable as _};

#[test]
fn a_large_dropped_file_shows_it_is_opening_before_it_is_read() {
    let mut harness = support::harness_with("cube", None);
    let (torus, _) = Mesh::build(&generate::torus(200, 100), Structure::HalfEdge).expect("builds");
    let bytes = formats::save(&torus, Format::Htb, &SaveOptions::default()).expect("saves");
    assert!(bytes.len() > ANNOUNCE_BYTES, "{} bytes", bytes.len());
    support::drop_file(&mut harness, "torus.htb", bytes);
    // The frames after the drop show what is being opened (an egui area is
    // measured unseen on its first frame), and have not read it yet.
    harness.step();
    harness.step();
    harness.get_by_label_contains("Opening torus.htb (");
    assert_eq!(harness.state().state().mesh.as_deref(), Some("cube.htb"));
    // The next frames open it, and the notice goes.
    harness.run();
    assert_eq!(harness.state().state().mesh.as_deref(), Some("torus.htb"));
    assert!(
        harness
            .query_by_label_contains("Opening torus.htb")
            .is_none()
    );
}

fn focused_editor(harness: &mut Harness<'static, EdgewiseApp>) {
    let editor = harness.get_by_role(egui::accesskit::Role::MultilineTextInput);
    editor.focus();
    harness.run();
}

#[test]
fn the_obj_editor_refuses_a_paste_past_its_size_and_keeps_its_text() {
    let mut harness = support::harness();
    harness.get_by_label("OBJ editor").click();
    harness.run();
    focused_editor(&mut harness);
    let editor = harness.get_by_role(egui::accesskit::Role::MultilineTextInput);
    editor.type_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    harness.run_steps(60);
    assert_eq!(harness.state().state().counts.faces, 1);

    let paste = "v 0 0 0\n".repeat(MAX_EDITOR_BYTES / 8 + 1);
    harness.event(egui::Event::Paste(paste.clone()));
    harness.run_steps(60);
    harness.get_by_label_contains(&format!(
        "{} bytes were not added: this editor holds at most {MAX_EDITOR_BYTES} bytes",
        paste.len()
    ));
    assert_eq!(harness.state().state().counts.faces, 1, "the mesh stays");

    // A small paste still goes in, and the notice goes with the edit.
    harness.event(egui::Event::Paste("v 1 1 0\nf 2 4 3\n".to_owned()));
    harness.run_steps(60);
    assert_eq!(harness.state().state().counts.faces, 2);
    assert!(
        harness
            .query_by_label_contains("bytes were not added")
            .is_none()
    );
}

#[test]
fn the_algorithm_editor_refuses_a_paste_past_its_size() {
    let mut harness = support::harness();
    support::drop_file(&mut harness, "mine.alg", b"// mine\n".to_vec());
    harness.run();
    focused_editor(&mut harness);
    let paste = "x".repeat(edgewise_core::lang::MAX_SOURCE_BYTES + 1);
    harness.event(egui::Event::Paste(paste));
    harness.run_steps(10);
    harness.get_by_label_contains("bytes were not added: this editor holds at most 1048576 bytes");
}
