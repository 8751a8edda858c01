//! `edgewise practice`: listing, showing an instance and grading an answer
//! offline, as a course's auto-grader calls it.

use crate::common::{code, run, scratch, stderr, stdout};

fn shown_ids(exercise: &str, seed: &str) -> (String, Vec<String>) {
    let output = run(&["practice", "show", exercise, "--seed", seed, "--json"]);
    assert_eq!(code(&output), 0, "{}", stderr(&output));
    let object: serde_json::Value = serde_json::from_str(&stdout(&output)).expect("JSON");
    let operation = object["operation"].as_str().expect("operation").to_owned();
    let ids = object["ids"]
        .as_array()
        .expect("ids")
        .iter()
        .map(|id| id.as_u64().expect("an id").to_string())
        .collect();
    (operation, ids)
}

#[test]
fn list_names_every_shipped_exercise_with_its_kind_and_structure() {
    let text = stdout(&run(&["practice", "list"]));
    assert!(text.lines().count() >= 16, "{text}");
    assert!(text.contains("flip-edge-half-edge"), "{text}");
    let json: serde_json::Value =
        serde_json::from_str(&stdout(&run(&["practice", "list", "--json"]))).expect("JSON");
    let rows = json.as_array().expect("an array");
    assert_eq!(rows.len(), text.lines().count());
    for row in rows {
        assert!(["do-it", "walk", "predict"].contains(&row["kind"].as_str().expect("str")));
        assert!(["half-edge", "winged-edge"].contains(&row["structure"].as_str().expect("str")));
    }
}

/// The instance's mesh written, the operation done by `edgewise edit`, and
/// the result graded: a pass exits 0; the untouched mesh fails with the
/// first difference and exits 1.
#[test]
fn check_passes_the_operations_result_and_fails_the_untouched_mesh() {
    let dir = scratch("practice-check");
    for (exercise, extension) in [("flip-edge-half-edge", "htb"), ("kef-winged-edge", "wtb")] {
        let (operation, ids) = shown_ids(exercise, "5");
        let start = dir.join(format!("{exercise}.{extension}"));
        let answer = dir.join(format!("{exercise}-answer.{extension}"));
        let (start_path, answer_path) = (start.to_string_lossy(), answer.to_string_lossy());
        let shown = run(&[
            "practice",
            "show",
            exercise,
            "--seed",
            "5",
            "--mesh",
            &start_path,
        ]);
        assert_eq!(code(&shown), 0, "{}", stderr(&shown));
        assert!(stdout(&shown).contains("Task: "), "{}", stdout(&shown));
        let mut edit = vec!["edit", &start_path, &answer_path, operation.as_str()];
        edit.extend(ids.iter().map(String::as_str));
        assert_eq!(code(&run(&edit)), 0);

        let pass = run(&["practice", "check", exercise, &answer_path, "--seed", "5"]);
        assert_eq!(code(&pass), 0, "{}{}", stdout(&pass), stderr(&pass));
        assert!(
            stdout(&pass).contains(": pass (1 of 1 points)"),
            "{}",
            stdout(&pass)
        );

        let fail = run(&[
            "practice",
            "check",
            exercise,
            &start_path,
            "--seed",
            "5",
            "--json",
        ]);
        assert_eq!(code(&fail), 1);
        let graded: serde_json::Value = serde_json::from_str(&stdout(&fail)).expect("JSON");
        assert_eq!(graded["passed"], false);
        assert_eq!(graded["score"], 0);
        assert_eq!(graded["seed"], 5);
        assert!(
            graded["feedback"]
                .as_str()
                .is_some_and(|f| f.contains(&operation)),
            "{graded}"
        );

        // Another seed's instance: the same answer is for another task.
        let other = run(&["practice", "check", exercise, &answer_path, "--seed", "6"]);
        assert_eq!(code(&other), 1, "{}", stdout(&other));
    }
}

#[test]
fn bad_exercises_and_answers_are_refused_with_their_place() {
    let dir = scratch("practice-bad");
    let unknown = run(&["practice", "show", "flop"]);
    assert_eq!(code(&unknown), 2);
    assert!(
        stderr(&unknown).contains("no exercise is named `flop`"),
        "{}",
        stderr(&unknown)
    );

    let file = dir.join("mine.toml");
    std::fs::write(
        &file,
        "title = \"Mine\"\nkind = \"do-it\"\nstructure = \"half-edge\"\n[mesh]\nsample = \"cube\"\n\
         [do-it]\noperation = \"flip\"\n",
    )
    .expect("writes");
    let path = file.to_string_lossy();
    let bad = run(&["practice", "show", &path]);
    assert_eq!(code(&bad), 1);
    assert!(
        stderr(&bad).contains("mine.toml:7:13: no operation is named `flip`"),
        "{}",
        stderr(&bad)
    );

    // An OBJ is not tables; a winged-edge file is not a half-edge answer.
    let obj = run(&[
        "practice",
        "check",
        "flip-edge-half-edge",
        "meshes/octahedron.obj",
    ]);
    assert_eq!(code(&obj), 1);
    assert!(
        stderr(&obj).contains("a .wtb or .htb file, not OBJ"),
        "{}",
        stderr(&obj)
    );
    let winged = run(&[
        "practice",
        "check",
        "flip-edge-half-edge",
        "meshes/tetrahedron.wtb",
    ]);
    assert_eq!(code(&winged), 1);
    assert!(
        stdout(&winged).contains(
            "the answer is a winged-edge mesh; the exercise is in the half-edge structure"
        ),
        "{}",
        stdout(&winged)
    );
    let wrong_format = run(&["practice", "show", "flip-edge-half-edge", "--mesh", "x.wtb"]);
    assert_eq!(code(&wrong_format), 2);
}

/// A walk's answer is the elements clicked, one a line.
#[test]
fn check_grades_a_walk_from_the_elements_clicked() {
    let dir = scratch("practice-walk");
    let shown = run(&[
        "practice",
        "show",
        "walk-vertex-edges-winged-edge",
        "--json",
    ]);
    let object: serde_json::Value = serde_json::from_str(&stdout(&shown)).expect("JSON");
    assert_eq!(object["algorithm"], "vertexAdjacentEdge");
    assert_eq!(object["args"]["v"], 1);
    // Table 2: the edges around vertex 1 (B), from its incident edge.
    let answer = dir.join("walk.txt");
    std::fs::write(&answer, "# around vertex 1\nedge 1\nedge 3\nedge 2\n").expect("writes");
    let path = answer.to_string_lossy();
    let pass = run(&["practice", "check", "walk-vertex-edges-winged-edge", &path]);
    assert_eq!(code(&pass), 0, "{}{}", stdout(&pass), stderr(&pass));
    assert!(
        stdout(&pass).contains("pass (3 of 3 steps right)"),
        "{}",
        stdout(&pass)
    );
    std::fs::write(&answer, "edge 1\nedge 2\nedge 3\n").expect("writes");
    let fail = run(&["practice", "check", "walk-vertex-edges-winged-edge", &path]);
    assert_eq!(code(&fail), 1);
    assert!(
        stdout(&fail).contains("answer 2: Not edge 2: the walk marks edge 3 next"),
        "{}",
        stdout(&fail)
    );
    std::fs::write(&answer, "edge 1\ncorner 3\n").expect("writes");
    let bad = run(&["practice", "check", "walk-vertex-edges-winged-edge", &path]);
    assert_eq!(code(&bad), 1);
    assert!(
        stderr(&bad).contains("walk.txt:2: `corner 3`"),
        "{}",
        stderr(&bad)
    );
}

/// A prediction's answer is what each lookup gives, one a line, `null`
/// where it gives none.
#[test]
fn check_grades_a_prediction_from_its_answers() {
    let dir = scratch("practice-predict");
    let shown = run(&[
        "practice",
        "show",
        "predict-vertex-edges-winged-edge",
        "--json",
    ]);
    let object: serde_json::Value = serde_json::from_str(&stdout(&shown)).expect("JSON");
    assert_eq!(object["kind"], "predict");
    assert_eq!(object["lookups"], 7);
    assert!(
        object.get("questions").is_none(),
        "later questions would give answers away"
    );
    let answer = dir.join("predict.txt");
    std::fs::write(&answer, "edge 1\nnull\n").expect("writes");
    let path = answer.to_string_lossy();
    let graded = run(&[
        "practice",
        "check",
        "predict-vertex-edges-winged-edge",
        &path,
    ]);
    assert_eq!(code(&graded), 1);
    let text = stdout(&graded);
    assert!(text.contains("fail (1 of 7 steps right)"), "{text}");
    assert!(
        text.contains("answer 2: Not null: edge 1.startVertex is vertex 0"),
        "{text}"
    );
}
