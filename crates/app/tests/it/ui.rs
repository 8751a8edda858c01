//! The app's UI logic, driven natively through `egui_kittest`: opening samples,
//! linked selection through table cells, and switching structure.

use crate::support;

use edgewise_app::EdgewiseApp;
use edgewise_core::mesh::{EdgeId, Mesh, Structure};
use edgewise_core::schema::{ElementKind, ElementRef};
use egui_kittest::{Harness, kittest::Queryable as _};

fn harness() -> Harness<'static, EdgewiseApp> {
    support::harness_sized(1280.0, 800.0)
}

/// A harness with `sample` open as `structure` and one element selected.
fn harness_with_selection(
    sample: &str,
    structure: Option<Structure>,
    kind: ElementKind,
    id: u32,
) -> Harness<'static, EdgewiseApp> {
    let mut harness = harness();
    let app = harness.state_mut();
    app.load_sample(sample, structure)
        .expect("the sample opens");
    app.select(Some(ElementRef { kind, id }))
        .expect("the element exists");
    harness.run();
    harness
}

#[test]
fn opening_a_sample_from_the_menu_shows_its_tables() {
    let mut harness = harness();
    harness.get_by_label("Samples").click();
    harness.run();
    harness.get_by_label("octahedron").click();
    harness.run();
    let state = harness.state().state();
    assert_eq!(state.mesh.as_deref(), Some("octahedron.obj"));
    assert_eq!(state.structure, Some("winged"));
    assert_eq!(
        (
            state.counts.vertices,
            state.counts.edges,
            state.counts.faces
        ),
        (6, 12, 8)
    );
    assert!(state.error.is_none());
    // The edge table is on screen with its winged-edge columns.
    harness.get_by_label("left pred");
    harness.get_by_label("right succ");
}

#[test]
fn a_reference_cell_selects_what_it_refers_to() {
    let mut harness = harness_with_selection("tetrahedron", None, ElementKind::Edge, 0);

    let state = harness.state().state();
    let roles: Vec<&str> = state.highlights.iter().map(|h| h.role.as_str()).collect();
    assert_eq!(
        roles,
        [
            "selected",
            "start vertex",
            "end vertex",
            "left face",
            "right face",
            "left predecessor",
            "left successor",
            "right predecessor",
            "right successor"
        ]
    );

    // Walk to edge 0's left predecessor by clicking its cell in the table.
    let mesh = support::sample_mesh("tetrahedron.wtb", Structure::WingedEdge);
    let Mesh::Winged(m) = &mesh else {
        unreachable!()
    };
    let pred = m.edge(EdgeId::new(0)).unwrap().left_predecessor.index();
    let label = format!("left pred of edge 0: edge {pred}");
    let link = harness.get_by_label(&label);
    // The tables keep their default share of the window: the link is on screen.
    assert!(
        link.rect().bottom() < 800.0 && link.rect().top() > 500.0,
        "{:?}",
        link.rect()
    );
    link.click();
    harness.run();
    let state = harness.state().state();
    let selection = state.selection.expect("a selection");
    assert_eq!(selection.id as usize, pred);
    assert_eq!(state.highlights[0].role, "selected");
    assert_eq!(state.highlights[0].id as usize, pred);
}

#[test]
fn switching_structure_converts_and_keeps_the_selection() {
    let mut harness =
        harness_with_selection("cube", Some(Structure::WingedEdge), ElementKind::Face, 4);
    harness.get_by_label("Half-edge").click();
    harness.run();
    let state = harness.state().state();
    assert_eq!(state.structure, Some("half"));
    assert_eq!(state.counts.halfedges, 24);
    let selection = state.selection.expect("the face stays selected");
    assert_eq!(selection.id, 4);
    assert_eq!(state.highlights[1].role, "incident edge");
    // The half-edge table shows its derived columns.
    harness.get_by_label("predecessor");
}

#[test]
fn a_broken_file_keeps_the_previous_mesh() {
    let mut harness = harness();
    harness.state_mut().load_sample("cube", None).unwrap();
    let err = harness
        .state_mut()
        .load_mesh(b"v 0 0 0\nf 1 2 3\n", "broken.obj", None)
        .unwrap_err();
    assert!(err.starts_with("broken.obj:2:"), "{err}");
    harness.run();
    let state = harness.state().state();
    assert_eq!(state.mesh.as_deref(), Some("cube.htb"));
    assert_eq!(state.error.as_deref(), Some(err.as_str()));
    // The message is on screen, and Dismiss clears it.
    harness.get_by_label_contains("broken.obj:2:");
    harness.get_by_label("Dismiss").click();
    harness.run();
    assert!(harness.state().state().error.is_none());
}

#[test]
fn the_obj_editor_rebuilds_as_you_type_and_keeps_the_last_good_mesh() {
    let mut harness = harness();
    support::type_in_obj_editor(&mut harness, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    let state = harness.state().state();
    assert_eq!(state.mesh.as_deref(), Some("editor.obj"));
    assert_eq!(state.counts.faces, 1);

    // A face naming a missing vertex: the message names the line, the mesh stays.
    let editor = harness.get_by_role(egui::accesskit::Role::MultilineTextInput);
    editor.type_text("f 1 2 7\n");
    harness.run_steps(60);
    let state = harness.state().state();
    assert_eq!(state.counts.faces, 1, "the last good mesh stays");
    assert_eq!(state.diagnostics.first().map(|d| d.line), Some(5));
}

#[test]
fn keys_walk_a_half_edge_mesh() {
    let mut harness =
        harness_with_selection("cube", Some(Structure::HalfEdge), ElementKind::Edge, 0);
    let mesh = support::sample_mesh("cube.htb", Structure::HalfEdge);
    let Mesh::Half(m) = &mesh else { unreachable!() };
    let h0 = m.half_edges()[0];

    harness.key_press(egui::Key::N);
    harness.run();
    let selected = harness.state().state().selection.unwrap();
    assert_eq!(selected.id as usize, h0.successor_edge.index());

    harness.key_press(egui::Key::T);
    harness.run();
    let selected = harness.state().state().selection.unwrap();
    assert_eq!(
        selected.id as usize,
        m.half_edges()[h0.successor_edge.index()].pair_edge.index()
    );

    harness.key_press(egui::Key::V);
    harness.run();
    let selected = harness.state().state().selection.unwrap();
    assert_eq!(selected.kind, ElementKind::Vertex);
}

#[test]
fn the_tables_scroll_to_what_is_selected() {
    let mut harness = harness();
    harness
        .state_mut()
        .load_sample("icosphere-20k", None)
        .expect("opens");
    harness.run();
    assert!(
        harness.query_all_by_label("9000").next().is_none(),
        "row 9000 starts out of view"
    );
    harness
        .state_mut()
        .select(Some(ElementRef {
            kind: ElementKind::Vertex,
            id: 9000,
        }))
        .expect("selects");
    // One frame: the table jumps before it lays its rows out, so the row
    // shows in the frame that shows the selection.
    harness.step();
    assert!(
        harness.query_all_by_label("9000").next().is_some(),
        "the vertex table brought row 9000 into view"
    );
    // A row already in view is selected where it is.
    harness
        .state_mut()
        .select(Some(ElementRef {
            kind: ElementKind::Vertex,
            id: 9003,
        }))
        .expect("selects");
    harness.step();
    assert!(
        harness.query_all_by_label("9000").next().is_some(),
        "the table stays"
    );
}

#[test]
fn the_statistics_window_shows_euler_s_formula_and_the_build_s_warnings() {
    let mut harness = harness();
    harness
        .state_mut()
        .load_sample("torus", None)
        .expect("the sample opens");
    harness.run();
    // The summary in the top bar opens it.
    harness
        .get_by_label_contains("torus.obj: 288 vertices")
        .click();
    harness.run();
    for text in [
        "Vertices (V)",
        "V − E + F",
        "Boundary loops",
        "The build gave no warnings.",
    ] {
        harness.get_by_label(text);
    }
    // V − E + F = 288 − 576 + 288 = 0: one closed component of genus 1.
    harness.get_by_label("V 288 E 576 F 288, χ 0, genus 1");

    // A vertex no face uses: the build's warning is listed, and the open
    // triangle is one component with a boundary plus the isolated vertex.
    let obj = b"v 0 0 0\nv 1 0 0\nv 0 1 0\nv 5 5 5\nf 1 2 3\n";
    harness
        .state_mut()
        .load_mesh(obj, "stray.obj", Some(Structure::HalfEdge))
        .expect("loads");
    harness.run();
    harness.get_by_label("1 warning from the build:");
    // Listed in the window, as in the load's own warning line.
    assert_eq!(harness.get_all_by_label_contains("vertex 3").count(), 2);
    harness.get_by_label("V 3 E 3 F 1, χ 1, open (has a boundary)");
    harness.get_by_label("V 1 E 0 F 0, χ 1, open (has a boundary)");
}

#[test]
fn a_reference_under_the_pointer_is_previewed_in_the_view_and_the_message_line() {
    let mut harness = harness();
    harness
        .state_mut()
        .load_sample("tetrahedron", None)
        .expect("opens");
    harness.run();
    harness
        .get_by_label("incident edge of face 1: edge 2")
        .hover();
    harness.run();
    let state = harness.state().state();
    assert_eq!(
        state.hovered,
        Some(ElementRef {
            kind: ElementKind::Edge,
            id: 2
        })
    );
    assert!(state.selection.is_none(), "a preview, not a selection");
    harness.get_by_label("Edge 2: click to select");
}
