//! The keyboard path to the elements: `/` puts the cursor in the message
//! line's box, and typing an element with Enter does what a click on it
//! does: select it, give it to a waiting algorithm, answer a question.

use crate::support;

use edgewise_core::mesh::{Structure, operations::Operation};
use edgewise_core::schema::{ElementKind, ElementRef, Records as _};
use egui_kittest::kittest::Queryable as _;

/// Presses `/` (with its text, as a browser sends it: in the same frame,
/// or with `late_slash` in the next), types `text` and Enter.
fn type_element_with(
    harness: &mut egui_kittest::Harness<'static, edgewise_app::EdgewiseApp>,
    text: &str,
    late_slash: bool,
) {
    harness.key_press(egui::Key::Slash);
    if late_slash {
        harness.step();
    }
    harness.event(egui::Event::Text("/".to_owned()));
    harness.run();
    harness.event(egui::Event::Text(text.to_owned()));
    harness.run();
    harness.key_press(egui::Key::Enter);
    harness.run();
}

fn type_element(
    harness: &mut egui_kittest::Harness<'static, edgewise_app::EdgewiseApp>,
    text: &str,
) {
    type_element_with(harness, text, false);
}

#[test]
fn a_typed_element_is_selected_picked_and_answers() {
    let mut harness = support::harness_with("tetrahedron", None);
    harness.run();
    type_element(&mut harness, "e 2");
    assert_eq!(
        harness.state().state().selection,
        Some(ElementRef::new(ElementKind::Edge, 2))
    );
    // The `/` that focuses the box is never typed into it.
    type_element_with(&mut harness, "v 1", true);
    assert_eq!(
        harness.state().state().selection,
        Some(ElementRef::new(ElementKind::Vertex, 1))
    );
    assert_eq!(harness.state().state().error, None);

    // An algorithm waiting for its input takes the typed vertex.
    harness
        .state_mut()
        .run_algorithm("vertexAdjacentEdge", &[])
        .expect("waits for v");
    harness.run();
    type_element(&mut harness, "vertex 1");
    let trace = harness.state().state().trace.expect("started");
    assert_eq!(
        trace.variables.get("v").map(String::as_str),
        Some("Vertex 1")
    );

    // A question waiting for an element takes it as the answer.
    support::ask(
        &mut harness,
        "line 13: Which edge will e be?
",
    );
    type_element(&mut harness, "e1");
    let answer = harness
        .state()
        .state()
        .trace
        .and_then(|t| t.question)
        .and_then(|q| q.answer)
        .expect("answered");
    assert!(answer.correct, "{answer:?}");
}

#[test]
fn a_mistyped_element_says_what_was_expected() {
    let mut harness = support::harness_with("tetrahedron", None);
    harness.run();
    type_element(&mut harness, "vertex 99");
    assert_eq!(
        harness.state().state().error.as_deref(),
        Some("there is no vertex 99 (the table has 4 rows)")
    );
    type_element(&mut harness, "q 1");
    assert_eq!(
        harness.state().state().error.as_deref(),
        Some("`q 1`: type an element as vertex, edge or face and its id, such as e 3 or vertex 1")
    );
    assert_eq!(harness.state().state().selection, None);
    harness.get_by_label("Dismiss");
}

#[test]
fn the_camera_turns_zooms_and_frames_from_the_keyboard() {
    let mut harness = support::harness_tracing("tetrahedron", None, 1);
    let camera = |harness: &egui_kittest::Harness<'static, edgewise_app::EdgewiseApp>| {
        harness.state().course_link().camera.expect("a camera")
    };
    let start = camera(&harness);
    harness.key_press_modifiers(egui::Modifiers::SHIFT, egui::Key::ArrowLeft);
    harness.run();
    let turned = camera(&harness);
    assert!(
        (turned.yaw - start.yaw).abs() > 0.2,
        "Shift+← turns the view: {start:?} -> {turned:?}"
    );
    let trace = harness.state().state().trace.expect("tracing");
    assert_eq!(trace.step, 0, "and does not step the trace");
    harness.key_press_modifiers(egui::Modifiers::SHIFT, egui::Key::Home);
    harness.run();
    let framed = camera(&harness);
    harness.key_press(egui::Key::Plus);
    harness.run();
    assert!(camera(&harness).distance < framed.distance, "+ zooms in");
    harness.key_press_modifiers(egui::Modifiers::SHIFT, egui::Key::Home);
    harness.run();
    let again = camera(&harness);
    assert!(
        (again.distance - framed.distance).abs() < 1e-3 * framed.distance,
        "Shift+Home frames the mesh again: {framed:?} -> {again:?}"
    );
    harness.key_press(egui::Key::ArrowRight);
    harness.run();
    assert_eq!(
        harness.state().state().trace.expect("tracing").step,
        1,
        "→ steps"
    );
}

#[test]
fn arrows_walk_the_selection_along_its_table_over_deleted_rows() {
    let mut harness = support::harness_with("octahedron", Some(Structure::WingedEdge));
    let selection = |harness: &support::AppHarness| harness.state().state().selection;
    let press = |harness: &mut support::AppHarness, key| {
        harness.key_press(key);
        harness.run();
    };
    press(&mut harness, egui::Key::ArrowDown);
    assert_eq!(selection(&harness), Some(edge(0)), "↓ starts at edge 0");
    press(&mut harness, egui::Key::ArrowDown);
    assert_eq!(selection(&harness), Some(edge(1)));
    press(&mut harness, egui::Key::ArrowUp);
    press(&mut harness, egui::Key::ArrowUp);
    assert_eq!(selection(&harness), Some(edge(0)), "the first row stays");
    // A slow frame gathers a held key's presses: each counts.
    for _ in 0..3 {
        harness.key_press(egui::Key::ArrowDown);
    }
    harness.run();
    assert_eq!(
        selection(&harness),
        Some(edge(3)),
        "three presses, three rows"
    );
    harness.state_mut().select(Some(edge(0))).expect("selects");
    harness.run();

    let last = ElementRef::new(ElementKind::Vertex, 5);
    harness.state_mut().select(Some(last)).expect("selects");
    harness.run();
    press(&mut harness, egui::Key::ArrowDown);
    assert_eq!(selection(&harness), Some(last), "the last row stays");
    press(&mut harness, egui::Key::ArrowUp);
    assert_eq!(
        selection(&harness),
        Some(ElementRef::new(ElementKind::Vertex, 4))
    );

    // Collapsing an edge deletes rows but keeps their ids until compacted.
    harness
        .state_mut()
        .edit(Operation::CollapseEdge, &[0])
        .expect("collapses");
    harness.run();
    let mesh = harness.state().mesh().expect("a mesh").clone();
    let live: Vec<u32> = (0..mesh.count(ElementKind::Edge) as u32)
        .filter(|&e| mesh.contains(edge(e)))
        .collect();
    assert!(
        live.len() < mesh.count(ElementKind::Edge),
        "some edge rows are deleted"
    );
    harness.state_mut().select(None).expect("clears");
    harness.run();
    let mut walked = Vec::new();
    for _ in 0..live.len() + 2 {
        press(&mut harness, egui::Key::ArrowDown);
        walked.push(selection(&harness).expect("selected").id);
    }
    walked.dedup();
    assert_eq!(walked, live, "↓ visits every live edge, in order, once");

    // During a run, → steps and ↓ leaves the selection alone.
    support::run_vertex_adjacent_edge(&mut harness, 1);
    let before = selection(&harness);
    press(&mut harness, egui::Key::ArrowDown);
    assert_eq!(selection(&harness), before);
}

#[test]
fn tab_shows_a_focus_ring_until_the_pointer_is_used() {
    let mut harness = support::harness_with("tetrahedron", None);
    assert_eq!(harness.state().focus_ring(), None, "no ring at first");
    harness.key_press(egui::Key::Tab);
    harness.run();
    let ring = harness.state().focus_ring().expect("Tab shows a ring");
    assert!(ring.width() > 4.0 && ring.height() > 4.0, "{ring:?}");
    harness.key_press(egui::Key::Tab);
    harness.run();
    let next = harness.state().focus_ring().expect("Tab moves it");
    assert_ne!(next, ring, "round the next widget");

    // Escape gives focus back to the app's own keys.
    harness.key_press(egui::Key::Escape);
    harness.run();
    assert_eq!(harness.state().focus_ring(), None);
    harness.key_press(egui::Key::ArrowDown);
    harness.run();
    assert_eq!(harness.state().state().selection, Some(edge(0)));

    harness.key_press(egui::Key::Tab);
    harness.run();
    assert!(harness.state().focus_ring().is_some());
    let corner = egui::pos2(700.0, 400.0);
    harness.hover_at(corner);
    harness.event(egui::Event::PointerButton {
        pos: corner,
        button: egui::PointerButton::Primary,
        pressed: true,
        modifiers: egui::Modifiers::NONE,
    });
    harness.run();
    assert_eq!(harness.state().focus_ring(), None, "a press hides it");
}

fn edge(id: u32) -> ElementRef {
    ElementRef::new(ElementKind::Edge, id)
}

#[test]
fn tab_reaches_the_tables_and_enter_follows_a_reference() {
    let mut harness = support::harness_with("tetrahedron", Some(Structure::WingedEdge));
    harness.state_mut().select(Some(edge(0))).expect("selects");
    harness.run();
    // The tables fill the lower part of the window.
    let mut in_tables = false;
    for _ in 0..80 {
        harness.key_press(egui::Key::Tab);
        harness.run();
        if harness
            .state()
            .focus_ring()
            .is_some_and(|ring| ring.top() > 600.0)
        {
            in_tables = true;
            break;
        }
    }
    assert!(in_tables, "Tab reaches a table cell");
    harness.key_press(egui::Key::Enter);
    harness.run();
    let selection = harness.state().state().selection;
    assert!(
        selection.is_some() && selection != Some(edge(0)),
        "Enter on a cell selects its row or follows its reference: {selection:?}"
    );
}

/// Help lists the keys the app answers, the go-to box, the edit menu,
/// stepping over and out, and undo among them.
#[test]
fn help_lists_every_key() {
    let mut harness = support::harness_with("tetrahedron", None);
    harness.get_by_label("Help").click();
    harness.run();
    for keys in ["/", "E", "O  U", "Ctrl+Z  Ctrl+Y", "↑  ↓", "Space  →", "P"] {
        harness.get_by_label(keys);
    }
}
