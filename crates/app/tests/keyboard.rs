//! The keyboard path to the elements: `/` puts the cursor in the message
//! line's box, and typing an element with Enter does what a click on it
//! does: select it, give it to a waiting algorithm, answer a question.

mod support;

use edgewise_app::command::Command;
use edgewise_core::schema::{ElementKind, ElementRef};
use egui_kittest::kittest::Queryable as _;

/// Presses `/`, types `text` and Enter.
fn type_element(
    harness: &mut egui_kittest::Harness<'static, edgewise_app::EdgewiseApp>,
    text: &str,
) {
    harness.key_press(egui::Key::Slash);
    harness.run();
    harness.event(egui::Event::Text(text.to_owned()));
    harness.run();
    harness.key_press(egui::Key::Enter);
    harness.run();
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
    harness
        .state_mut()
        .execute(Command::SetQuestions(
            "line 13: Which edge will e be?\n".to_owned(),
        ))
        .expect("asks");
    harness.run();
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
