//! Practice in the app: an exercise opened by command and by link, the
//! operation done cell by cell and graded, one wrong cell named, the model
//! answer, a fresh instance, live feedback, and the events and state a page
//! and a script see.

use crate::support;

use edgewise_app::{EmbedEvent, command::Command};
use edgewise_core::mesh::Mesh;
use edgewise_core::mesh::operations::{self, Operation};
use edgewise_core::schema::{ElementKind, ElementRef};
use edgewise_model::practice::ExerciseState;
use edgewise_model::practice::progress::{Write, writes_between};

type App = support::AppHarness;

fn exercise(harness: &App) -> ExerciseState {
    harness
        .state()
        .state()
        .exercise
        .expect("an exercise is open")
}

fn run(harness: &mut App, command: Command) {
    let shown = format!("{command:?}");
    harness
        .state_mut()
        .execute(command)
        .unwrap_or_else(|err| panic!("{shown}: {err}"));
    harness.run();
}

fn start(harness: &mut App, name: &str, seed: u64) -> ExerciseState {
    run(
        harness,
        Command::StartExercise {
            exercise: name.to_owned(),
            seed: Some(seed),
            progress: None,
            name: None,
        },
    );
    exercise(harness)
}

/// The writes that turn the app's tables into `target`, as a student
/// makes them: the fewest a saved attempt replays.
fn writes_to(current: &Mesh, target: &Mesh) -> Vec<Command> {
    writes_between(current, target)
        .into_iter()
        .map(|write| match write {
            Write::AddRow(kind) => Command::AddRow(kind),
            Write::Reference {
                element,
                column,
                target,
            } => Command::SetCell {
                element,
                column: column.lookup_name().to_owned(),
                target,
            },
            Write::Position { vertex, position } => Command::SetPosition { vertex, position },
            Write::DeleteRow(row) => Command::DeleteRow(row),
        })
        .collect()
}

/// The library's result of the open exercise's task.
fn model_result(harness: &App) -> Mesh {
    let state = exercise(harness);
    let operation = Operation::parse(state.operation.expect("do-it")).expect("known");
    let mut mesh = harness.state().mesh().expect("open").clone();
    operations::apply(&mut mesh, operation, &state.ids).expect("the instance applies");
    mesh
}

fn names(events: &[EmbedEvent]) -> Vec<&'static str> {
    events.iter().map(EmbedEvent::name).collect()
}

/// Every shipped exercise in both structures, done write by write in the
/// app and checked: a pass, scored, with the events a page hears.
#[test]
fn every_shipped_exercise_done_by_hand_in_the_app_passes() {
    let mut harness = support::harness();
    for shipped in edgewise_model::practice::catalog::SHIPPED {
        if shipped.name.starts_with("walk-") || shipped.name.starts_with("predict-") {
            continue;
        }
        let state = start(&mut harness, shipped.name, 7);
        assert_eq!((state.attempt, state.step, state.passed), (1, 0, None));
        let _ = harness.state_mut().take_embed_events();
        let target = model_result(&harness);
        let current = harness.state().mesh().expect("open").clone();
        let writes = writes_to(&current, &target);
        for write in &writes {
            run(&mut harness, write.clone());
        }
        run(&mut harness, Command::SubmitExercise);
        let state = exercise(&harness);
        assert_eq!(
            state.passed,
            Some(true),
            "{}: {:?}",
            shipped.name,
            state.feedback
        );
        assert_eq!((state.score, state.max_score), (1, 1));
        assert_eq!(state.step, writes.len());
        assert!(state.finished);
        let events = harness.state_mut().take_embed_events();
        let events: Vec<_> = events
            .into_iter()
            .filter(|e| matches!(e.name(), "exercisestep" | "score"))
            .collect();
        assert_eq!(
            names(&events),
            ["exercisestep", "score"],
            "{}",
            shipped.name
        );
        let EmbedEvent::Score(score) = &events[1] else {
            unreachable!()
        };
        assert_eq!(score["passed"], true);
        assert_eq!(score["seed"], 7);
        assert_eq!(score["statement"]["verb"]["display"]["en-US"], "passed");
        assert_eq!(score["statement"]["result"]["score"]["scaled"], 1.0);
    }
}

/// A flip with one wrong cell fails naming the difference; fixed, it
/// passes. The library's operations wait while the exercise is open.
#[test]
fn one_wrong_cell_is_named_and_fixing_it_passes() {
    let mut harness = support::harness();
    start(&mut harness, "flip-edge-half-edge", 3);
    let refused = harness.state_mut().execute(Command::Edit {
        operation: Operation::FlipEdge,
        ids: vec![16],
    });
    assert!(
        refused.is_err_and(|e| e.contains("do the edit by hand")),
        "the native flip is refused during the exercise"
    );
    let target = model_result(&harness);
    let current = harness.state().mesh().expect("open").clone();
    let mut writes = writes_to(&current, &target);
    let last = writes.pop().expect("a flip writes cells");
    for write in writes {
        run(&mut harness, write);
    }
    run(&mut harness, Command::SubmitExercise);
    let state = exercise(&harness);
    assert_eq!(state.passed, Some(false));
    let feedback = state.feedback.expect("feedback");
    assert!(
        feedback.contains("flip-edge 16") || feedback.contains("do not hold"),
        "{feedback}"
    );
    assert!(!state.finished, "no attempt limit: the student may go on");
    run(&mut harness, last);
    run(&mut harness, Command::SubmitExercise);
    assert_eq!(exercise(&harness).passed, Some(true));
}

/// The model answer scores 0 and ends the attempt; a new instance is the
/// second attempt, on another instance.
#[test]
fn the_model_answer_scores_zero_and_a_new_instance_follows() {
    let mut harness = support::harness();
    let first = start(&mut harness, "split-edge-winged-edge", 11);
    let _ = harness.state_mut().take_embed_events();
    // A write of the student's, which the model answer puts aside.
    run(&mut harness, Command::AddRow(ElementKind::Vertex));
    run(&mut harness, Command::ShowModelAnswer);
    let state = exercise(&harness);
    assert!(state.model_answer_shown && state.finished);
    assert_eq!((state.score, state.passed), (0, Some(false)));
    // The library's traced split, from the instance, stepped to its end.
    let trace = harness.state().state().trace.expect("the traced operation");
    assert_eq!(trace.algorithm, "splitEdge");
    run(&mut harness, Command::Goto(usize::MAX));
    assert_eq!(
        harness.state().mesh(),
        Some(&model_result_of(&first, &harness))
    );
    let events = harness.state_mut().take_embed_events();
    assert!(names(&events).contains(&"score"), "{events:?}");
    assert!(
        harness
            .state_mut()
            .execute(Command::SubmitExercise)
            .is_err()
    );

    run(&mut harness, Command::NewInstance);
    let second = exercise(&harness);
    assert_eq!(second.attempt, 2);
    assert_ne!(second.seed, first.seed);
    assert_eq!(
        (second.passed, second.finished, second.step),
        (None, false, 0)
    );
    run(&mut harness, Command::EndExercise);
    assert!(harness.state().state().exercise.is_none());
}

fn model_result_of(state: &ExerciseState, harness: &App) -> Mesh {
    let mut start = edgewise_model::practice::catalog::find(&state.name)
        .expect("shipped")
        .expect("reads")
        .instance(state.seed)
        .expect("draws")
        .mesh;
    let operation = Operation::parse(state.operation.expect("do-it")).expect("known");
    operations::apply(&mut start, operation, &state.ids).expect("applies");
    let _ = harness;
    start
}

/// An exercise written in a page with live feedback grades every write.
#[test]
fn live_feedback_grades_every_write() {
    let mut harness = support::harness();
    let text = edgewise_model::practice::catalog::find("kef-half-edge")
        .expect("shipped")
        .expect("reads")
        .text
        .replace("feedback = \"on-check\"", "feedback = \"live\"");
    run(
        &mut harness,
        Command::StartExercise {
            exercise: text,
            seed: Some(2),
            progress: None,
            name: None,
        },
    );
    let _ = harness.state_mut().take_embed_events();
    let target = model_result(&harness);
    let current = harness.state().mesh().expect("open").clone();
    let writes = writes_to(&current, &target);
    let count = writes.len();
    for write in writes {
        run(&mut harness, write);
    }
    let events = harness.state_mut().take_embed_events();
    let steps = names(&events)
        .iter()
        .filter(|&&n| n == "exercisestep")
        .count();
    assert_eq!(steps, count, "one graded step per write");
    assert_eq!(exercise(&harness).passed, Some(true));
}

/// `?exercise=NAME&seed=N` opens the instance; bad parameters are named.
#[test]
fn a_link_opens_an_exercise_at_its_seed() {
    let (harness, messages) = support::open_link("exercise=mef-winged-edge&seed=4", "");
    assert!(messages.is_empty(), "{messages:?}");
    let state = exercise(&harness);
    assert_eq!((state.name.as_str(), state.seed), ("mef-winged-edge", 4));
    let link = harness
        .state()
        .share_url("https://example.edu/edgewise/")
        .expect("a link");
    assert!(
        link.contains("exercise=mef-winged-edge") && link.contains("seed=4"),
        "{link}"
    );

    let (harness, messages) = support::open_link("exercise=teapot&seed=x", "");
    assert!(harness.state().state().exercise.is_none());
    assert!(
        messages
            .iter()
            .any(|m| m.starts_with("exercise=teapot: no exercise has that name")),
        "{messages:?}"
    );
    assert!(
        messages.iter().any(|m| m.starts_with("seed=")),
        "{messages:?}"
    );
}

/// A walk clicked through selections, as a click in the 3D view or a
/// table makes them: each click graded at once, a score at the end.
#[test]
fn a_walk_is_clicked_through_selections() {
    let mut harness = support::harness();
    let state = start(&mut harness, "walk-vertex-edges-winged-edge", 0);
    assert_eq!(state.kind, "walk");
    assert!(state.task.contains("vertex 1"), "{}", state.task);
    let _ = harness.state_mut().take_embed_events();
    // Table 2: the edges around vertex 1 (B), as vertexAdjacentEdge marks them.
    for id in [1, 3, 2] {
        run(
            &mut harness,
            Command::Select(Some(ElementRef::new(ElementKind::Edge, id))),
        );
    }
    let state = exercise(&harness);
    assert_eq!((state.correct, state.total, state.step), (3, 3, 3));
    assert_eq!(state.passed, Some(true), "{:?}", state.feedback);
    assert!(state.finished);
    let events = harness.state_mut().take_embed_events();
    let graded: Vec<_> = names(&events)
        .into_iter()
        .filter(|n| matches!(*n, "exercisestep" | "score"))
        .collect();
    assert_eq!(
        graded,
        ["exercisestep", "exercisestep", "exercisestep", "score"]
    );

    // A wrong click is named and corrected; the score counts the rest.
    start(&mut harness, "walk-vertex-edges-winged-edge", 0);
    run(
        &mut harness,
        Command::Select(Some(ElementRef::new(ElementKind::Edge, 2))),
    );
    let state = exercise(&harness);
    assert_eq!(state.passed, Some(false));
    let feedback = state.feedback.expect("feedback");
    assert!(
        feedback.contains("Not edge 2: the walk marks edge 1 next"),
        "{feedback}"
    );

    // The model answer is the run itself, traced from the same vertex, to
    // step through.
    run(&mut harness, Command::ShowModelAnswer);
    assert!(exercise(&harness).model_answer_shown);
    let trace = harness.state().state().trace.expect("the walk's run");
    assert_eq!(trace.algorithm, "vertexAdjacentEdge");
    run(&mut harness, Command::Goto(usize::MAX));
    let marked = harness.state().state().trace.expect("still running").marked;
    assert_eq!(marked.len(), 3, "{marked:?}");
}

/// A prediction answered through the card's commands and selections: the
/// question moves on with the run, null is an answer, a wrong one is named.
#[test]
fn a_prediction_is_answered_lookup_by_lookup() {
    let mut harness = support::harness();
    let state = start(&mut harness, "predict-vertex-edges-winged-edge", 0);
    assert_eq!(state.kind, "predict");
    assert_eq!(
        state.question.as_deref(),
        Some("line 13: vertex 1.incidentEdge")
    );
    let instance = edgewise_model::practice::catalog::find("predict-vertex-edges-winged-edge")
        .expect("shipped")
        .expect("reads")
        .instance(0)
        .expect("draws");
    let edgewise_model::practice::Task::Predict { lookups, .. } = &instance.task else {
        panic!("a prediction");
    };
    // The first right by selection, the second wrong (null), the rest right.
    let first = lookups[0].answer.expect("an element");
    run(&mut harness, Command::Select(Some(first)));
    run(&mut harness, Command::AnswerExercise(None));
    let state = exercise(&harness);
    assert!(
        state
            .feedback
            .as_deref()
            .is_some_and(|f| f.starts_with("Not null: edge 1.startVertex is vertex")),
        "{:?}",
        state.feedback
    );
    for lookup in &lookups[2..] {
        run(&mut harness, Command::AnswerExercise(lookup.answer));
    }
    let state = exercise(&harness);
    assert!(state.finished);
    assert_eq!(
        (state.correct, state.total),
        (lookups.len() - 1, lookups.len())
    );
    assert_eq!(state.passed, Some(false));
    assert!(state.question.is_none());
    assert!(
        harness
            .state_mut()
            .execute(Command::AnswerExercise(None))
            .is_err()
    );
}

/// Share while an exercise is open offers it as an exercise: at its seed,
/// or, ticked, with none, so that each student draws a fresh instance.
#[test]
fn share_offers_the_exercise_with_or_without_its_seed() {
    use egui_kittest::kittest::Queryable as _;
    let mut harness = support::harness();
    start(&mut harness, "kef-half-edge", 12);
    harness.get_by_label("Share…").click();
    harness.run();
    let shown = |harness: &App| {
        harness
            .get_by_role(egui::accesskit::Role::MultilineTextInput)
            .value()
            .unwrap_or_default()
    };
    let link = shown(&harness);
    assert!(
        link.contains("exercise=kef-half-edge") && link.contains("seed=12"),
        "{link}"
    );
    harness
        .get_by_label("a fresh instance for each student")
        .click();
    harness.run();
    let link = shown(&harness);
    assert!(
        link.contains("exercise=kef-half-edge") && !link.contains("seed="),
        "{link}"
    );
}

/// A saved attempt (`exerciseProgress()`) brings the same instance and the
/// student's writes back, graded as before; a damaged one is refused with
/// the reason, and the exercise on screen stays.
#[test]
fn a_saved_attempt_resumes_where_it_stopped() {
    let mut harness = support::harness();
    let first = start(&mut harness, "split-face-half-edge", 5);
    let target = model_result(&harness);
    let current = harness.state().mesh().expect("open").clone();
    let writes = writes_to(&current, &target);
    let half = writes.len() / 2;
    for write in &writes[..half] {
        run(&mut harness, write.clone());
    }
    let tables = harness.state().mesh().expect("open").clone();
    let saved = harness
        .state()
        .exercise_progress()
        .expect("an exercise is open");

    // Another exercise in between, as a package's other items are.
    start(&mut harness, "flip-edge-winged-edge", 1);
    run(
        &mut harness,
        Command::StartExercise {
            exercise: "split-face-half-edge".to_owned(),
            seed: None,
            progress: Some(saved.clone()),
            name: None,
        },
    );
    let resumed = exercise(&harness);
    assert_eq!((resumed.seed, resumed.step), (first.seed, half));
    assert_eq!(harness.state().mesh(), Some(&tables));
    for write in &writes[half..] {
        run(&mut harness, write.clone());
    }
    run(&mut harness, Command::SubmitExercise);
    assert_eq!(exercise(&harness).passed, Some(true));

    let damaged = saved.replacen("1:", "1:x", 1);
    let err = harness
        .state_mut()
        .execute(Command::StartExercise {
            exercise: "split-face-half-edge".to_owned(),
            seed: None,
            progress: Some(damaged),
            name: None,
        })
        .expect_err("damaged");
    assert!(
        err.contains("options.progress") && err.contains("seed"),
        "{err}"
    );
    assert_eq!(exercise(&harness).passed, Some(true));
}

/// Share's *Download as a SCORM package*: the exercise on screen, or else
/// the view, as a one-item package named for it.
#[test]
fn share_packages_the_exercise_or_else_the_view() {
    use edgewise_model::package::{Item, Scorm};
    let mut harness = support::harness();
    start(&mut harness, "kev-half-edge", 2);
    let (name, package) = harness
        .state()
        .scorm_package(Scorm::V2004)
        .expect("a package");
    assert_eq!(name, "kev-half-edge-scorm-2004.zip");
    assert_eq!(package.pass_mark, 80);
    assert!(
        matches!(&package.items[..], [Item::Exercise(e)] if e.name == "kev-half-edge"),
        "{:?}",
        package.items
    );
    run(&mut harness, Command::EndExercise);
    let (name, package) = harness.state().scorm_package(Scorm::V1_2).expect("a view");
    assert_eq!(name, "edgewise-view-scorm-1.2.zip");
    assert!(
        matches!(&package.items[..], [Item::View { href, .. }] if href.starts_with("index.html?") && href.contains("embed=1")),
        "{:?}",
        package.items
    );
}
