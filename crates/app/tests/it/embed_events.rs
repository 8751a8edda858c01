//! The events an embedding page hears (docs/embedding.md, "The embed
//! protocol"): one per change of mesh, selection or trace step, and the
//! height the content wants, each once.

use crate::support;

use edgewise_app::{EmbedEvent, preferred_height};
use edgewise_core::schema::{ElementKind, ElementRef};

fn names(events: &[EmbedEvent]) -> Vec<&'static str> {
    events.iter().map(EmbedEvent::name).collect()
}

#[test]
fn each_change_is_told_once() {
    let mut harness = support::harness_sized(800.0, 600.0);
    harness.run();
    let first = harness.state_mut().take_embed_events();
    assert_eq!(names(&first), ["resize"], "{first:?}");
    let EmbedEvent::Resize { height: wide } = first[0] else {
        unreachable!()
    };
    // The view at 5:3 of the width, plus the top bar and the tables.
    assert!(wide > preferred_height(800.0, 100.0), "{wide}");

    harness
        .state_mut()
        .load_sample("tetrahedron", None)
        .expect("opens");
    harness.run();
    let events = harness.state_mut().take_embed_events();
    assert_eq!(names(&events), ["meshchange"], "{events:?}");
    let EmbedEvent::MeshChange { mesh, counts, .. } = &events[0] else {
        unreachable!()
    };
    assert_eq!(mesh.as_deref(), Some("tetrahedron.wtb"));
    assert_eq!((counts.vertices, counts.edges, counts.faces), (4, 6, 4));

    let edge = ElementRef {
        kind: ElementKind::Edge,
        id: 2,
    };
    harness.state_mut().select(Some(edge)).expect("selects");
    harness.run();
    assert_eq!(
        harness.state_mut().take_embed_events(),
        [EmbedEvent::SelectionChange {
            selection: Some(edge)
        }]
    );

    support::run_vertex_adjacent_edge(&mut harness, 1);
    harness.state_mut().trace_step(2).expect("steps");
    harness.run();
    let events = harness.state_mut().take_embed_events();
    let steps: Vec<usize> = events
        .iter()
        .filter_map(|event| match event {
            EmbedEvent::StepChange { trace: Some(trace) } => Some(trace.step),
            _ => None,
        })
        .collect();
    // Starting the run cleared the selection and stood at step 0.
    assert_eq!(steps, [0, 2], "{events:?}");
    let EmbedEvent::StepChange { trace: Some(trace) } = &events[events.len() - 1] else {
        unreachable!()
    };
    assert_eq!(trace.algorithm, "vertexAdjacentEdge");

    // Nothing changed: nothing is told.
    harness.run();
    assert_eq!(harness.state_mut().take_embed_events(), []);

    harness.state_mut().abort_algorithm().expect("aborts");
    harness.run();
    let events = harness.state_mut().take_embed_events();
    assert!(
        events.contains(&EmbedEvent::StepChange { trace: None }),
        "{events:?}"
    );

    // A narrower window asks for less height, by the view's 5:3 (above
    // the small-screen layout's width).
    harness.set_size(egui::vec2(720.0, 600.0));
    harness.run();
    let events = harness.state_mut().take_embed_events();
    let [EmbedEvent::Resize { height: narrow }] = events[..] else {
        panic!("{events:?}")
    };
    assert_eq!(
        wide - narrow,
        preferred_height(800.0, 0.0) - preferred_height(720.0, 0.0)
    );
}

/// An embed's height holds while its questions are asked, answered and
/// skipped: the card keeps one height for the run, so the text of the page
/// around the frame does not move.
#[test]
fn an_embeds_height_holds_while_questions_come_and_go() {
    use edgewise_app::command::Command;
    use edgewise_core::lang::Value;
    let mut harness = support::harness_sized(720.0, 600.0);
    harness
        .state_mut()
        .set_embed(Some(edgewise_app::Embed { tables: false }));
    harness
        .state_mut()
        .load_sample("tetrahedron", None)
        .expect("opens");
    support::run_vertex_adjacent_edge(&mut harness, 1);
    harness
        .state_mut()
        .execute(Command::SetQuestions(
            include_str!("../../../../algorithms/questions/vertex-adjacent-edge.txt").to_owned(),
        ))
        .expect("the set reads");
    harness.run();
    harness.state_mut().take_embed_events();
    let mut asked = 0;
    loop {
        let trace = harness.state().state().trace.expect("tracing");
        if trace.done {
            break;
        }
        if let Some(question) = trace.question {
            asked += 1;
            // Answers of each kind, some right and some wrong, so that
            // both verdicts show.
            let given = match question.expects {
                "boolean" => Value::Boolean(asked % 2 == 0),
                "number" => Value::Integer(asked),
                _ if asked % 2 == 0 => Value::Edge(5),
                _ => Value::Null,
            };
            harness
                .state_mut()
                .execute(Command::Answer(given))
                .unwrap_or_else(|e| panic!("{}: {e}", question.prompt));
            harness.run();
        }
        harness.state_mut().trace_step(1).expect("steps");
        harness.run();
        let events = harness.state_mut().take_embed_events();
        assert!(
            !names(&events).contains(&"resize"),
            "at step {}: {events:?}",
            trace.step
        );
    }
    assert!(asked >= 4, "{asked} questions asked");
}

/// The Share dialog's embed code is sized for what the embed shows: in a
/// frame of that size, with the tables, the step controls and a question
/// card, the 3D view keeps its 5:3 (the fixed 720×480 had left it 100 px).
/// Its title names the mesh, the algorithm and the step.
#[test]
fn the_embed_code_is_sized_and_titled_for_what_it_shows() {
    use edgewise_app::command::Command;
    let mut harness = support::harness_tracing("tetrahedron", None, 1);
    harness
        .state_mut()
        .execute(Command::SetQuestions(
            include_str!("../../../../algorithms/questions/vertex-adjacent-edge.txt").to_owned(),
        ))
        .expect("the set reads");
    harness.state_mut().trace_step(2).expect("steps");
    harness.run();
    let app = harness.state();
    assert_eq!(
        app.embed_title(),
        "Edgewise: vertexAdjacentEdge on tetrahedron.wtb, step 2 of 22"
    );
    let (width, height) = app.embed_size(true);
    assert_eq!(width, 720);
    let bare = harness.state().embed_size(false).1;
    assert!(height > bare, "the tables add height: {height} vs {bare}");

    harness
        .state_mut()
        .set_embed(Some(edgewise_app::Embed { tables: true }));
    harness.set_size(egui::vec2(width as f32, height as f32));
    harness.run();
    harness.run();
    let view = harness.state().state().layout.view.expect("the view shows");
    assert!(
        view.h >= 0.6 * view.w * 0.9,
        "the view keeps about 5:3 in a {width}×{height} frame: {view:?}"
    );
}
