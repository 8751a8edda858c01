//! Stop-and-think questions in the app: a set given to a run stops Play at
//! each question, a click or a button answers it once, the card says
//! whether it was right, `state()` and `edgewise:answer` report it, and a
//! course link carries the set.

use crate::support;

use edgewise_app::{EmbedEvent, command::Command};
use edgewise_core::lang::Value;
use edgewise_core::schema::{ElementKind, ElementRef};
use egui_kittest::kittest::Queryable as _;

const SET: &str = include_str!("../../../../algorithms/questions/vertex-adjacent-edge.txt");

fn started() -> egui_kittest::Harness<'static, edgewise_app::EdgewiseApp> {
    let mut harness = support::harness_tracing("tetrahedron", None, 1);
    harness
        .state_mut()
        .execute(Command::SetQuestions(SET.to_owned()))
        .expect("the set reads");
    harness.run();
    harness
}

fn answers(events: &[EmbedEvent]) -> Vec<(usize, String, String, bool)> {
    events
        .iter()
        .filter_map(|event| match event {
            EmbedEvent::Answer(a) => {
                Some((a.index, a.given.clone(), a.expected.clone(), a.correct))
            }
            _ => None,
        })
        .collect()
}

#[test]
fn a_question_is_asked_answered_once_and_reported() {
    let mut harness = started();
    let state = harness.state().state();
    let trace = state.trace.expect("tracing");
    let question = trace.question.expect("asked at step 0");
    assert_eq!(trace.step, 0);
    assert_eq!(
        question.prompt,
        "Which edge will e be after the lookup v.incidentEdge?"
    );
    assert_eq!((question.line, question.expects), (13, "element"));
    assert!(question.answer.is_none());
    let questions = trace.questions.expect("the run asks questions");
    assert_eq!((questions.asked, questions.answered), (6, 0));
    harness.get_by_label("Question 1 of 6 (line 13)");

    // A wrong answer, by a click on edge 3 (as the view and the tables
    // answer), then a second answer is refused.
    let app = harness.state_mut();
    app.take_embed_events();
    app.execute(Command::Answer(Value::Edge(3)))
        .expect("answers");
    let refused = app
        .execute(Command::Answer(Value::Edge(1)))
        .expect_err("answered already");
    assert_eq!(
        refused.as_str(),
        "the question at step 0 is answered already (Edge 3)"
    );
    harness.run();
    let events = harness.state_mut().take_embed_events();
    assert_eq!(
        answers(&events),
        [(0, "Edge 3".to_owned(), "Edge 1".to_owned(), false)]
    );
    harness.get_by_label("Not quite: you answered Edge 3; the answer is Edge 1.");
    harness.get_by_label("Step 1: lookup v.incidentEdge -> edge 1. Step 2: assign e := edge 1.");

    // Play stops at the next question, on line 17, before its lookup.
    harness.get_by_label("▶ Play").click();
    harness.step();
    harness.step();
    harness.get_by_label("❚❚ Pause");
    for _ in 0..400 {
        harness.step();
        if harness.query_by_label("▶ Play").is_some() {
            break;
        }
        std::thread::sleep(std::time::Duration::from_millis(10));
    }
    let trace = harness.state().state().trace.expect("tracing");
    assert_eq!(trace.step, 4, "play stops at the question");
    let question = trace.question.expect("asked at step 4");
    assert_eq!((question.line, question.expects), (17, "boolean"));

    // The False button answers it, rightly.
    harness.get_by_label("False").click();
    harness.run();
    let trace = harness.state().state().trace.expect("tracing");
    let answer = trace.question.and_then(|q| q.answer).expect("answered");
    assert!(answer.correct, "{answer:?}");
    assert_eq!(answer.expected, "Boolean false");
    let questions = trace.questions.expect("asked");
    assert_eq!((questions.answered, questions.right), (2, 1));
    harness.get_by_label("1 of 2 answered right");
}

#[test]
fn an_element_click_answers_and_wrong_kinds_are_refused() {
    let mut harness = started();
    let app = harness.state_mut();
    let refused = app
        .execute(Command::Answer(Value::Boolean(true)))
        .expect_err("an element question");
    assert_eq!(
        refused.as_str(),
        "this question is answered with a vertex, an edge, a face or null, not Boolean true"
    );
    app.trace_step(1).expect("steps");
    let refused = app
        .execute(Command::Answer(Value::Edge(1)))
        .expect_err("no question at step 1");
    assert_eq!(
        refused.as_str(),
        "no question is asked at step 1; questions are asked at steps 0, 4, 6, 8, 12 and 20"
    );
    app.trace_goto(6).expect("goes");
    harness.run();
    // A click on the edge in the 3D view, while a question waits, answers it.
    let edge = ElementRef {
        kind: ElementKind::Edge,
        id: 3,
    };
    let [x, y] = harness.state().screen_position(edge).expect("in view");
    let at = egui::pos2(x, y);
    harness.hover_at(at);
    harness.event(egui::Event::PointerButton {
        pos: at,
        button: egui::PointerButton::Primary,
        pressed: true,
        modifiers: egui::Modifiers::NONE,
    });
    harness.event(egui::Event::PointerButton {
        pos: at,
        button: egui::PointerButton::Primary,
        pressed: false,
        modifiers: egui::Modifiers::NONE,
    });
    harness.run();
    let trace = harness.state().state().trace.expect("tracing");
    let answer = trace.question.and_then(|q| q.answer).expect("answered");
    assert_eq!((answer.given.as_str(), answer.correct), ("Edge 3", true));
    assert_eq!(trace.step, 6, "answering does not step");
}

#[test]
fn a_course_link_carries_the_set_and_share_keeps_it() {
    let payload = edgewise_model::course_link::encode_payload(SET);
    let (harness, messages) = support::open_link(
        "sample=tetrahedron&algorithm=vertexAdjacentEdge&args=v:1&step=4",
        &format!("ask={payload}"),
    );
    assert!(messages.is_empty(), "{messages:?}");
    let trace = harness.state().state().trace.expect("tracing");
    assert_eq!(
        trace.question.map(|q| q.prompt),
        Some("Is v the start vertex of e?".to_owned())
    );
    let url = harness
        .state()
        .share_url("https://example.org/")
        .expect("a link");
    assert!(url.contains(&format!("ask={payload}")), "{url}");

    // A bad set names the parameter and its line and column; the rest of
    // the link still opens.
    let bad = edgewise_model::course_link::encode_payload("line 13: fine\nstep x: oops\n");
    let (harness, messages) = support::open_link(
        "sample=tetrahedron&algorithm=vertexAdjacentEdge&args=v:1",
        &format!("ask={bad}"),
    );
    assert_eq!(
        messages,
        ["#ask= question set, line 2:6: `x` is not a line or step number (1 or more)"]
    );
    let trace = harness.state().state().trace.expect("still runs");
    assert!(trace.questions.is_none());
}
