//! The shipped question sets, posed on the runs they were written for:
//! every question is asked, at the step before its line, and its expected
//! answer is what the run then does.

use edgewise_core::formats;
use edgewise_core::lang::question::{self, Posed, QuestionAt};
use edgewise_core::lang::{self, RunOptions, Trace, Value};
use edgewise_core::mesh::Structure;
use std::path::Path;
use std::sync::Arc;

fn workspace(path: &str) -> Vec<u8> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    std::fs::read(root.join(path)).unwrap_or_else(|err| panic!("{path}: {err}"))
}

fn traced(file: &str, name: &str, mesh: &str, structure: Structure, input: (&str, Value)) -> Trace {
    let program = lang::library::program(file)
        .expect("in the library")
        .expect("compiles");
    let algorithm = Arc::clone(program.algorithm(name).expect("in the file"));
    let mut mesh = formats::load(&workspace(mesh), mesh, structure)
        .expect("the sample loads")
        .mesh;
    lang::run_editing(&algorithm, &mut mesh, &[input], RunOptions::default()).expect("runs")
}

fn posed(trace: &Trace, set: &str) -> Vec<Posed> {
    let text = String::from_utf8(workspace(set)).expect("UTF-8");
    let questions = question::parse_set(&text).expect("the set reads");
    let (posed, problems) = question::pose(trace, &questions);
    assert!(problems.is_empty(), "{set}: {problems:?}");
    assert_eq!(
        posed.len(),
        questions.len(),
        "{set}: every question is asked"
    );
    posed
}

/// (asked at step, line, expected)
fn summary(trace: &Trace, posed: &[Posed]) -> Vec<(usize, u32, Value)> {
    posed
        .iter()
        .map(|p| (p.ask_at, p.line(trace), p.expected))
        .collect()
}

/// vertexAdjacentEdge on the journal's Table 2, from vertex 1.
fn table_2_from_vertex_1() -> Trace {
    traced(
        "winged-edge.alg",
        "vertexAdjacentEdge",
        "meshes/tetrahedron.wtb",
        Structure::WingedEdge,
        ("v", Value::Vertex(1)),
    )
}

#[test]
fn vertex_adjacent_edge_on_table_2() {
    let trace = table_2_from_vertex_1();
    let posed = posed(&trace, "algorithms/questions/vertex-adjacent-edge.txt");
    assert_eq!(
        summary(&trace, &posed),
        vec![
            (0, 13, Value::Edge(1)),
            (4, 17, Value::Boolean(false)),
            (6, 20, Value::Edge(3)),
            (8, 22, Value::Boolean(true)),
            (12, 18, Value::Edge(2)),
            (20, 22, Value::Boolean(false)),
        ]
    );
    assert_eq!(
        posed[0].explanation(&trace),
        "Step 1: lookup v.incidentEdge -> edge 1. Step 2: assign e := edge 1."
    );
    assert!(posed[0].accepts(Value::Edge(1)));
    assert!(!posed[0].accepts(Value::Edge(3)));
    assert!(!posed[0].accepts(Value::Vertex(1)));
}

#[test]
fn flip_edge_on_the_octahedron() {
    let trace = traced(
        "half-edge-edits.alg",
        "flipEdge",
        "meshes/octahedron.obj",
        Structure::HalfEdge,
        ("h", Value::Edge(0)),
    );
    assert!(trace.outcome().error().is_none(), "the flip is allowed");
    let posed = posed(&trace, "algorithms/questions/flip-edge.txt");
    let expected: Vec<(u32, Value)> = summary(&trace, &posed)
        .into_iter()
        .map(|(_, line, value)| (line, value))
        .collect();
    assert_eq!(
        expected,
        vec![
            (37, Value::Edge(5)),
            (40, Value::Boolean(false)),
            (52, Value::Vertex(4)),
            (53, Value::Vertex(5)),
            (58, Value::Boolean(false)),
            (63, Value::Vertex(4)),
            (67, Value::Edge(0)),
            (88, Value::Edge(0)),
        ]
    );
    // The call on line 58 belongs to its line: the question waits for
    // `joined` to return.
    let joined = &posed[4];
    assert!(joined.answered_by.len() > 10, "{:?}", joined.answered_by);
}

#[test]
fn comments_attach_to_the_next_line_with_code() {
    let source = "algorithm walk(v : Vertex) : HalfEdge;\nvar e : Edge;\nbegin\n  //? Which half-edge ends at v?\n\n  // (an ordinary comment)\n  e := v.incidentEdge;\n  //?   Does it end at v?  \n  if e.vertex = v then\n    mark e;\n  end;\n  //? dangling\nend;\n";
    let program = lang::compile(source).expect("compiles");
    let algorithm = &program.algorithms[0];
    let questions = question::from_comments(algorithm);
    let found: Vec<(QuestionAt, &str)> = questions
        .iter()
        .map(|q| (q.at, q.prompt.as_str()))
        .collect();
    assert_eq!(
        found,
        vec![
            (QuestionAt::Line(7), "Which half-edge ends at v?"),
            (QuestionAt::Line(9), "Does it end at v?"),
            // `end;` is code: the last question asks about the end.
            (QuestionAt::Line(13), "dangling"),
        ]
    );
}

#[test]
fn questions_the_run_cannot_ask_are_explained() {
    let trace = table_2_from_vertex_1();
    let questions =
        question::parse_set("line 40: Never here?\nstep 99: Too late?\nline 23: The end?\n")
            .expect("reads");
    let (posed, problems) = question::pose(&trace, &questions);
    assert!(posed.is_empty());
    assert_eq!(
        problems,
        vec![
            "line 40: the run never reaches it, so \"Never here?\" is not asked",
            "step 99: the run has 22 steps, so \"Too late?\" is not asked",
            "line 23: it gives no value to answer with; ask about a lookup, an assignment, a comparison or a mark",
        ]
    );
}
