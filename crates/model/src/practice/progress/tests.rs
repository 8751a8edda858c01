//! A saved attempt comes back as it was, for every shipped exercise.

use edgewise_core::mesh::{Edit, operations};
use edgewise_core::schema::{ElementKind, ElementRef};

use super::{Body, Progress};
use crate::practice::catalog::SHIPPED;
use crate::practice::exercise::Exercise;
use crate::practice::instance::Task;
use crate::practice::session::Session;

fn shipped() -> impl Iterator<Item = Exercise> {
    SHIPPED
        .iter()
        .map(|s| Exercise::parse(s.name, s.text).unwrap_or_else(|err| panic!("{err}")))
}

/// Saves, writes out, reads back and resumes.
fn round_trip(
    session: &Session,
    tables: &edgewise_core::mesh::Mesh,
) -> (Session, edgewise_core::mesh::Mesh) {
    let progress = session.progress(tables);
    let text = progress.to_string();
    assert!(
        text.bytes()
            .all(|b| b.is_ascii_alphanumeric() || b":,.=+-@;".contains(&b)),
        "{text}"
    );
    let do_it = matches!(session.instance.task, Task::DoIt { .. });
    let read = Progress::parse(&text, do_it).unwrap_or_else(|err| panic!("{text}: {err}"));
    assert_eq!(read, progress);
    Session::resume(session.exercise.clone(), &read).unwrap_or_else(|err| panic!("{text}: {err}"))
}

#[test]
fn a_do_it_attempt_resumes_with_the_same_tables_and_grade() {
    for exercise in shipped() {
        let Ok(mut session) = Session::start(exercise.clone(), 7) else {
            panic!("{}", exercise.name)
        };
        let Task::DoIt { operation, ids } = session.instance.task.clone() else {
            continue;
        };
        // Half-way: the library's result, then a stray row and a moved vertex.
        let mut tables = session.start_mesh().clone();
        operations::apply(&mut tables, operation, &ids).expect("the instance applies");
        let mut unfinished = tables.clone();
        unfinished.push_row(ElementKind::Face).expect("a row");
        unfinished
            .set_position(
                edgewise_core::mesh::VertexId::new(0),
                glam::Vec3::new(0.5, -1.25, 3.0),
            )
            .expect("a move");
        session.writes = 50;
        let (resumed, again) = round_trip(&session, &unfinished);
        assert_eq!(again, unfinished, "{}", exercise.name);
        assert_eq!(resumed.state(), session.state(), "{}", exercise.name);

        // Checked and passed.
        session.check(&tables).expect("graded");
        assert!(session.finished, "{}", exercise.name);
        let (resumed, again) = round_trip(&session, &tables);
        assert_eq!(again, tables);
        assert_eq!(resumed.state(), session.state(), "{}", exercise.name);
    }
}

#[test]
fn a_walk_or_prediction_resumes_with_the_same_answers() {
    for exercise in shipped() {
        let mut session = Session::start(exercise.clone(), 11).expect("starts");
        let answers: Vec<Option<ElementRef>> = match &session.instance.task {
            Task::DoIt { .. } => continue,
            Task::Walk { expected, .. } => expected.iter().copied().map(Some).collect(),
            Task::Predict { lookups, .. } => lookups.iter().map(|l| l.answer).collect(),
        };
        let tables = session.start_mesh().clone();
        // A wrong answer first, then half of the right ones.
        let wrong = Some(ElementRef::new(ElementKind::Face, 9_999));
        session.answer(wrong);
        for &given in answers.iter().take(answers.len() / 2) {
            session.answer(given);
        }
        let (resumed, _) = round_trip(&session, &tables);
        assert_eq!(resumed.state(), session.state(), "{}", exercise.name);
        assert_eq!(resumed.answers, session.answers);

        // Finished early.
        session.check(&tables).expect("finished");
        let (resumed, _) = round_trip(&session, &tables);
        assert_eq!(resumed.state(), session.state(), "{}", exercise.name);
    }
}

#[test]
fn a_later_attempt_and_a_shown_model_answer_resume() {
    let exercise = shipped()
        .find(|e| e.model_answer && e.attempts != 1 && e.fresh_instance)
        .expect("an exercise with a model answer and fresh instances");
    let mut session = Session::start(exercise, 3).expect("starts");
    session.next_attempt().expect("a second attempt");
    session.model_answer().expect("shown");
    let tables = session.start_mesh().clone();
    let (resumed, _) = round_trip(&session, &tables);
    assert_eq!(resumed.state(), session.state());
    assert_eq!(resumed.attempt, 2);
}

#[test]
fn hostile_saved_text_is_refused_with_a_reason() {
    let cases = [
        ("", "version 1"),
        ("2:1:1:0::", "version 1"),
        ("1:x:1:0::", "seed"),
        ("1:1:1:0", "ends early"),
        ("1:1:1:0:z:", "`z` is not a flag"),
        ("1:1:1:0::h1.next=3", "write 1 `h1.next=3`"),
        ("1:1:1:0::e1.nope=3", "write 1"),
        ("1:1:1:0::v1@1;2", "write 1"),
        ("1:1:1:0::v1@1;2;NaN", "write 1"),
        ("1:1:1:0::e99999999999=1", "write 1"),
    ];
    for (text, says) in cases {
        let err = Progress::parse(text, true).expect_err(text).to_string();
        assert!(err.contains(says), "{text}: {err}");
    }
    let many = format!("1:1:1:0::{}", vec!["-"; super::MAX_ITEMS + 1].join(","));
    assert!(Progress::parse(&many, false).is_err());
    let err = Progress::parse("1:1:1:0::v1,x", false)
        .expect_err("x")
        .to_string();
    assert!(err.contains("answer 2 `x`"), "{err}");

    // Readable, but not of this instance: refused when resumed.
    let exercise = shipped()
        .find(|e| matches!(e.task, crate::practice::TaskSpec::DoIt(_)))
        .expect("a do-it");
    let bad = Progress {
        seed: 1,
        attempt: 1,
        writes: 1,
        graded: false,
        finished: false,
        model_answer_shown: false,
        body: Body::Writes(vec![super::Write::DeleteRow(ElementRef::new(
            ElementKind::Face,
            5_000,
        ))]),
    };
    let err = Session::resume(exercise.clone(), &bad)
        .expect_err("no such row")
        .to_string();
    assert!(err.contains("write 1 (-f5000)"), "{err}");
    let walk = Progress {
        body: Body::Answers(Vec::new()),
        ..bad.clone()
    };
    assert!(Session::resume(exercise.clone(), &walk).is_err());
    let later = Progress { attempt: 0, ..bad };
    assert!(Session::resume(exercise, &later).is_err());
}
