//! The shipped exercises and the exercise format's errors.

use std::collections::HashSet;

use edgewise_core::mesh::operations;

use super::catalog::{self, SHIPPED};
use super::exercise::Exercise;
use super::instance::Task;

#[test]
fn every_exercise_file_is_shipped_and_there_are_at_least_sixteen() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../algorithms/exercises");
    let mut files: Vec<String> = std::fs::read_dir(dir)
        .expect("algorithms/exercises")
        .filter_map(|entry| {
            let name = entry
                .expect("entry")
                .file_name()
                .to_string_lossy()
                .into_owned();
            name.strip_suffix(".toml").map(str::to_owned)
        })
        .collect();
    files.sort();
    let mut shipped = catalog::names();
    shipped.sort_unstable();
    assert_eq!(files, shipped);
    assert!(shipped.len() >= 16);
}

/// Every shipped exercise reads, and draws instances that apply, that the
/// library's own result passes and the untouched mesh fails, and that vary
/// with the seed.
#[test]
fn every_shipped_exercise_draws_gradable_instances() {
    for shipped in SHIPPED {
        let exercise =
            Exercise::parse(shipped.name, shipped.text).unwrap_or_else(|err| panic!("{err}"));
        let mut seen = HashSet::new();
        for seed in 0..12 {
            let instance = exercise
                .instance(seed)
                .unwrap_or_else(|err| panic!("{}: seed {seed}: {err}", shipped.name));
            let chosen = match &instance.task {
                Task::DoIt { operation, ids } => {
                    let mut answer = instance.mesh.clone();
                    operations::apply(&mut answer, *operation, ids)
                        .expect("a drawn instance applies");
                    let outcome = exercise.grade(&instance, &answer).expect("grades");
                    assert!(
                        outcome.passed,
                        "{}: seed {seed}: {}",
                        shipped.name, outcome.feedback
                    );
                    assert_eq!(outcome.score, exercise.points);
                    let untouched = exercise.grade(&instance, &instance.mesh).expect("grades");
                    assert!(
                        !untouched.passed && untouched.score == 0,
                        "{}",
                        shipped.name
                    );
                    format!("{ids:?}")
                }
                Task::Walk { args, expected, .. } => {
                    assert!(
                        expected.len() >= 3 || seed == 0,
                        "{}: {expected:?}",
                        shipped.name
                    );
                    let clicks: Vec<_> = expected.iter().copied().map(Some).collect();
                    let outcome = exercise.grade_clicks(&instance, &clicks).expect("grades");
                    assert!(
                        outcome.passed,
                        "{}: seed {seed}: {}",
                        shipped.name, outcome.feedback
                    );
                    assert_eq!(outcome.score as usize, expected.len());
                    let mut reversed = clicks.clone();
                    reversed.reverse();
                    let backwards = exercise.grade_clicks(&instance, &reversed).expect("grades");
                    let set = matches!(
                        &exercise.task,
                        super::exercise::TaskSpec::Walk(w)
                            if w.judged == super::walk::Judged::Marks(super::walk::Order::Set)
                    );
                    assert_eq!(
                        backwards.passed, set,
                        "{}: {}",
                        shipped.name, backwards.feedback
                    );
                    format!("{args:?}")
                }
                Task::Predict { args, lookups, .. } => {
                    assert!(lookups.len() >= 3, "{}: {lookups:?}", shipped.name);
                    let answers: Vec<_> = lookups.iter().map(|l| l.answer).collect();
                    let outcome = exercise.grade_clicks(&instance, &answers).expect("grades");
                    assert!(outcome.passed, "{}: {}", shipped.name, outcome.feedback);
                    let mut wrong = answers.clone();
                    wrong[1] = if wrong[1].is_some() { None } else { wrong[0] };
                    let failed = exercise.grade_clicks(&instance, &wrong).expect("grades");
                    assert!(!failed.passed && failed.feedback.starts_with("answer 2: Not "));
                    format!("{args:?}")
                }
            };
            assert_eq!(
                exercise.instance(seed).expect("draws").task,
                instance.task,
                "{}: one seed, one instance",
                shipped.name
            );
            seen.insert(chosen);
        }
        assert!(
            seen.len() >= 3,
            "{}: only {} instances",
            shipped.name,
            seen.len()
        );
    }
}

const GOOD: &str = r#"title = "Flip"
kind = "do-it"
structure = "half-edge"

[mesh]
sample = "octahedron"

[do-it]
operation = "flip-edge"
"#;

/// Each fault in a file, with the place it is at.
#[test]
fn a_bad_exercise_file_is_refused_with_its_place() {
    assert!(Exercise::parse("good.toml", GOOD).is_ok());
    let cases = [
        (
            GOOD.replace("title", "titel"),
            "bad.toml:1:1: unknown field `titel`",
        ),
        (
            GOOD.replace("\"half-edge\"", "\"quad-edge\""),
            "bad.toml:3:13: structure `quad-edge` is not one of half-edge, winged-edge",
        ),
        (
            GOOD.replace("flip-edge", "flop"),
            "bad.toml:9:13: no operation is named `flop`; the operations are flip-edge, \
             split-edge, split-face, collapse-edge, remove-vertex, mev, kev, mef, kef, kemr, mekr",
        ),
        (
            GOOD.replace("octahedron", "teapot"),
            "bad.toml:6:10: there is no sample called",
        ),
        (
            format!("{GOOD}ids = [1, 2]\n"),
            "bad.toml:10:7: flip-edge takes 1 (edge); `ids` gives 2",
        ),
        (
            format!("{}ids = [0]\n", GOOD.replace("octahedron", "open-square")),
            "bad.toml: [do-it] ids: flip-edge 0 is refused on this mesh",
        ),
        (
            GOOD.replace(
                "sample = \"octahedron\"",
                "generator = \"torus\"\nsize = [400, 400]",
            ),
            "bad.toml:7:8: that makes 320000 faces; an exercise mesh may have 20000",
        ),
        (
            GOOD.replace(
                "sample = \"octahedron\"",
                "sample = \"cube\"\ngenerator = \"cube\"",
            ),
            "bad.toml:5:1: [mesh] needs exactly one of `sample`, `text` or `generator`",
        ),
        (
            GOOD.replace("kind = \"do-it\"", "kind = \"do-it"),
            "bad.toml:2:14: invalid basic string",
        ),
        (
            GOOD.replace("kind = \"do-it\"", "kind = \"walk\"").replace(
                "[do-it]\noperation = \"flip-edge\"",
                "[walk]\nalgorithm = \"faceAdjacentVertex\"\nvisit = \"variable q\"",
            ),
            "bad.toml:10:9: visit `variable q` is not `marks` or `variable NAME` naming one of \
             `faceAdjacentVertex`'s element variables",
        ),
        (
            GOOD.replace("[do-it]\noperation = \"flip-edge\"\n", ""),
            "bad.toml: a do-it exercise needs a [do-it] table",
        ),
    ];
    for (text, expected) in cases {
        let message = match Exercise::parse("bad.toml", &text) {
            Ok(exercise) => exercise
                .instance(0)
                .map(|_| ())
                .expect_err("refused")
                .to_string(),
            Err(err) => err.to_string(),
        };
        assert!(
            message.starts_with(expected),
            "expected {expected:?}\n     got {message:?}"
        );
    }
}

/// A walk clicked one element at a time: right steps, a wrong click named
/// and corrected, the score as right steps out of all.
#[test]
fn a_walk_is_graded_click_by_click() {
    let exercise = catalog::find("walk-vertex-edges-winged-edge")
        .expect("shipped")
        .expect("reads");
    let instance = exercise.instance(0).expect("the lecturer's instance");
    let Task::Walk { expected, args, .. } = &instance.task else {
        panic!("a walk");
    };
    assert_eq!(args[0].1.id, 1, "Table 2's walk from vertex 1");
    let mut session = super::Session::start(exercise.clone(), 0).expect("starts");
    let first = session.click(expected[0]).expect("graded");
    assert!(first.right, "{}", first.feedback);
    let wrong = expected[0];
    let second = session.click(wrong).expect("graded");
    assert!(!second.right);
    assert!(
        second.feedback.starts_with("Not edge"),
        "{}",
        second.feedback
    );
    for &element in &expected[2..] {
        assert!(session.click(element).expect("graded").right);
    }
    assert!(session.click(expected[0]).is_none(), "the walk is over");
    let state = session.state();
    assert!(state.finished);
    assert_eq!(
        (state.correct, state.total),
        (expected.len() - 1, expected.len())
    );
    assert_eq!(state.passed, Some(false));
    assert_eq!(state.score as usize, expected.len() - 1);
}

/// Feedback at the end: a walk's clicks say nothing until the last, and
/// a do-it exercise's one Check ends it.
#[test]
fn feedback_at_the_end_waits_for_the_end() {
    let walk = catalog::find("walk-vertex-edges-winged-edge")
        .expect("shipped")
        .expect("reads");
    let text = walk
        .text
        .replace("feedback = \"live\"", "feedback = \"at-end\"");
    let exercise = Exercise::parse("at-end.toml", &text).expect("reads");
    let mut session = super::Session::start(exercise, 0).expect("starts");
    let Task::Walk { expected, .. } = session.instance.task.clone() else {
        panic!("a walk");
    };
    session.click(expected[0]);
    let state = session.state();
    assert_eq!((state.passed, state.feedback.as_deref()), (None, None));
    for &element in &expected[1..] {
        session.click(element);
    }
    assert_eq!(session.state().passed, Some(true));

    let flip = catalog::find("flip-edge-half-edge")
        .expect("shipped")
        .expect("reads");
    let text = flip
        .text
        .replace("feedback = \"on-check\"", "feedback = \"at-end\"");
    let exercise = Exercise::parse("at-end.toml", &text).expect("reads");
    let mut session = super::Session::start(exercise, 0).expect("starts");
    let start = session.start_mesh().clone();
    session.check(&start).expect("grades");
    let state = session.state();
    assert!(state.finished, "one Check ends it");
    assert_eq!(state.passed, Some(false));
}
