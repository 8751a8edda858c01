//! The VM and traces: both dialects, stepping state, breakpoints, the step
//! limit, runtime errors, inputs, and a million-step trace.

use crate::lang_support::*;
use edgewise_core::lang::{
    self, Algorithm, InputError, Outcome, RunOptions, RuntimeErrorKind, StepKind, Topology, Trace,
    Value, execute, run,
};
use edgewise_core::mesh::generate;
use edgewise_core::schema::{Column, ElementKind, ElementRef, LookupError, Structure};
use std::sync::Arc;

fn compile_one(source: &str) -> Arc<Algorithm> {
    let program =
        lang::compile_rendered(source, Some("test.alg")).unwrap_or_else(|e| panic!("{e}"));
    Arc::clone(&program.algorithms[0])
}

fn trace(source: &str, topology: &dyn Topology, args: &[(&str, Value)]) -> Trace {
    run(&compile_one(source), &topology, args, RunOptions::default()).expect("inputs fit")
}

fn error_of(trace: &Trace) -> String {
    trace
        .outcome()
        .error()
        .map(ToString::to_string)
        .unwrap_or_default()
}

const JOURNAL_FIG_6: &str = "algorithm vertexAdjacentEdge(v : Vertex);
structuretype WingedEdge
description \"Mark the adjacent edges of a vertex.\"
var e, se : Edge;
begin
e := v.incidentEdge;
se := e;
do
mark e;
if e.startVertex = v then
e := e.leftSuccessor;
else
e := e.rightSuccessor;
end;
while e <> se;
end;
";

/// The same algorithm in the half-edge paper's dialect: the structure in
/// the header, `==`, `e.mark`, `do begin … end while (…)`, an `if (…)`
/// without `then`, upper-case keywords and no `;` before `end`.
const NEPERUD_STYLE_WINGED: &str = "ALGORITHM vertexAdjacentEdge( v : Vertex ) : WingedEdge;
// Marks the adjacent edges of a vertex
VAR e, se : Edge;
BEGIN
  v.highlight;
  e := v.incidentEdge;
  se := e;
  DO
  BEGIN
    e.mark;
    IF( e.startVertex == v ) e := e.leftSuccessor
    ELSE e := e.rightSuccessor
  END WHILE( e <> se )
END;
";

const NEPERUD_FIG_5B: &str = "algorithm vertexAdjacentEdge( v : Vertex ) : HalfEdge;
// Marks the adjacent edges of a vertex
var e, se : Edge;
begin
  v.highlight;
  e := v.incidentEdge;
  se := e;
  do
  begin
    e.mark;
    e := e.successorEdge;
    e := e.pairEdge
  end while( e <> se )
end;
";

const JOURNAL_STYLE_HALF: &str = "algorithm vertexAdjacentEdge(v : Vertex);
structuretype HalfEdge
var e, se : Edge;
begin
  highlight v;
  e := v.incidentEdge;
  se := e;
  do
    mark e;
    e := e.successor;
    e := e.twin;
  while (e <> se);
end;
";

#[test]
fn both_dialects_mean_the_same() {
    for polygons in [generate::cube_zyx(), icosahedron(), quad_torus(5, 4)] {
        let we = winged(&polygons);
        let he = half(&polygons);
        for v in 0..polygons.vertex_count() as u32 {
            let args = [("v", Value::Vertex(v))];
            let a = trace(JOURNAL_FIG_6, &we, &args);
            let b = trace(NEPERUD_STYLE_WINGED, &we, &args);
            assert_eq!(
                a.marked().collect::<Vec<_>>(),
                b.marked().collect::<Vec<_>>()
            );
            let c = trace(NEPERUD_FIG_5B, &he, &args);
            let d = trace(JOURNAL_STYLE_HALF, &he, &args);
            assert_eq!(
                c.marked().collect::<Vec<_>>(),
                d.marked().collect::<Vec<_>>()
            );
            assert_eq!(a.marked().count(), c.marked().count());
        }
    }
}

#[test]
fn steps_carry_the_papers_operations_and_their_spans() {
    let mesh = winged(&generate::regular_tetrahedron());
    let algorithm = compile_one(JOURNAL_FIG_6);
    let trace = run(
        &algorithm,
        &&mesh,
        &[("v", Value::Vertex(1))],
        RunOptions::default(),
    )
    .expect("fits");
    let source = &algorithm.source;
    let first = trace.step(0).expect("a first step");
    assert!(matches!(
        first.kind,
        StepKind::Lookup {
            base: Value::Vertex(1),
            field: Column::IncidentEdge,
            result: Value::Edge(_)
        }
    ));
    assert_eq!(first.span.text(source), "v.incidentEdge");
    assert_eq!(first.line, 6);
    assert!(matches!(
        trace.step(1).expect("step").kind,
        StepKind::Assign {
            variable: 1,
            value: Value::Edge(_)
        }
    ));
    assert_eq!(
        trace.step(1).expect("step").span.text(source),
        "e := v.incidentEdge"
    );
    // The comparison of line 10 highlights just `e.startVertex = v` (Fig. 7).
    let compare = (0..trace.len())
        .find_map(|i| trace.step(i))
        .filter(|_| true);
    assert!(compare.is_some());
    let compare = (0..trace.len())
        .filter_map(|i| trace.step(i))
        .find(|s| matches!(s.kind, StepKind::Compare { .. }))
        .expect("a comparison");
    assert_eq!(compare.span.text(source), "e.startVertex = v");
    assert!(matches!(
        trace.step(trace.len() - 1).expect("last").kind,
        StepKind::Done
    ));
    assert_eq!(*trace.outcome(), Outcome::Finished);
    assert!(trace.step(trace.len()).is_none());
}

const SPIN: &str = "algorithm spin(v : Vertex) : HalfEdge;
var e : Edge;
    n : Integer;
    even : Boolean;
begin
  e := v.incidentEdge;
  n := 0;
  while n < LIMIT do
    e := e.successorEdge.pairEdge;
    n := n + 1;
    even := n mod 2 = 0;
    if even then
      mark e.startVertex;
    end;
  end;
  message \"spun\", n, \"times\";
end;
";

/// The state after each step, recomputed the slow way: from the initial
/// variables, applying every assignment step in order.
fn replayed_states(trace: &Trace) -> Vec<Vec<Value>> {
    let mut state = trace.initial_variables().to_vec();
    let mut states = Vec::with_capacity(trace.len());
    for i in 0..trace.len() {
        if let StepKind::Assign { variable, value } = trace.step(i).expect("step").kind {
            state[variable] = value;
        }
        states.push(state.clone());
    }
    states
}

#[test]
fn any_step_can_be_visited_in_any_order() {
    let mesh = half(&quad_torus(6, 5));
    let trace = trace(
        &SPIN.replace("LIMIT", "700"),
        &mesh,
        &[("v", Value::Vertex(7))],
    );
    assert!(trace.len() > 5 * lang::trace::SNAPSHOT_INTERVAL);
    let states = replayed_states(&trace);
    // Visit steps back to front and scattered, not just forward.
    for i in (0..trace.len()).rev().chain((0..trace.len()).step_by(97)) {
        assert_eq!(trace.variables_at(i), states[i], "variables after step {i}");
        let marks_so_far = (0..=i)
            .filter(|&j| matches!(trace.step(j).expect("step").kind, StepKind::Mark { .. }))
            .count();
        assert_eq!(
            trace.marked_at(i).count(),
            marks_so_far,
            "marks after step {i}"
        );
    }
    assert_eq!(trace.variables_at(trace.len() - 1), trace.final_variables());
    assert_eq!(trace.final_variables()[2], Value::Integer(700));
    assert_eq!(trace.marked().count(), 350);
    assert_eq!(trace.message_at(trace.len() - 1), Some("spun 700 times"));
    assert_eq!(trace.message_at(3), None);
}

#[test]
fn breakpoints_find_the_next_and_previous_step_on_a_line() {
    let mesh = half(&quad_torus(6, 5));
    let trace = trace(
        &SPIN.replace("LIMIT", "20"),
        &mesh,
        &[("v", Value::Vertex(0))],
    );
    // Line 13 is `mark e.startVertex;`.
    let first = trace.next_on_line(0, 13).expect("line 13 runs");
    assert_eq!(trace.line(first), Some(13));
    let second = trace.next_on_line(first, 13).expect("it runs again");
    assert!(second > first);
    assert!((first + 1..second).all(|i| trace.line(i) != Some(13)));
    assert_eq!(trace.previous_on_line(second, 13), Some(first));
    assert_eq!(trace.next_on_line(0, 2), None);
    let last = (0..trace.len())
        .rev()
        .find(|&i| trace.line(i) == Some(13))
        .expect("a last one");
    assert_eq!(trace.next_on_line(last, 13), None);
}

#[test]
fn the_step_limit_stops_runaway_loops() {
    let mesh = half(&generate::cube_zyx());
    let runaway = "algorithm forever(v : Vertex) : HalfEdge;
var n : Integer;
begin
  do
    n := n + 1;
  while true;
end;";
    let algorithm = compile_one(runaway);
    let limited = run(
        &algorithm,
        &&mesh,
        &[("v", Value::Vertex(0))],
        RunOptions {
            step_limit: 1000,
            ..RunOptions::default()
        },
    )
    .expect("fits");
    assert_eq!(limited.len(), 1000);
    let error = limited.outcome().error().expect("stopped");
    assert_eq!(error.kind, RuntimeErrorKind::StepLimit);
    assert_eq!(
        error.to_string(),
        "line 5: stopped after 1000 operations: the step limit was reached (the loop may never end; raise the limit to run longer)"
    );
    let default = run(
        &algorithm,
        &&mesh,
        &[("v", Value::Vertex(0))],
        RunOptions::default(),
    )
    .expect("fits");
    assert_eq!(default.len(), lang::DEFAULT_STEP_LIMIT);
    assert_eq!(lang::DEFAULT_STEP_LIMIT, 1_000_000);

    // A loop that performs no operation at all is stopped too.
    let idle = compile_one("algorithm idle(v : Vertex) : HalfEdge; begin while true do end end");
    let stopped = execute(
        &idle,
        &&mesh,
        &[("v", Value::Vertex(0))],
        RunOptions {
            step_limit: 50,
            ..RunOptions::default()
        },
    )
    .expect("fits");
    assert_eq!(
        stopped.outcome.error().map(|e| e.kind),
        Some(RuntimeErrorKind::StepLimit)
    );
}

#[test]
fn runtime_errors_name_the_line_and_the_values() {
    let grid = generate::grid(2, 2);
    let we = winged(&grid);
    // Edge 0 runs along the bottom of the grid: one of its faces is missing.
    let missing_side = if we
        .lookup(ElementRef::new(ElementKind::Edge, 0), Column::LeftFace)
        .expect("lookup")
        .is_none()
    {
        "leftFace"
    } else {
        "rightFace"
    };
    let direct = format!(
        "algorithm a(e : Edge);\nstructuretype WingedEdge\nvar g : Edge;\nbegin\n  g := e.{missing_side}.incidentEdge;\nend;"
    );
    let t = trace(&direct, &we, &[("e", Value::Edge(0))]);
    assert_eq!(
        error_of(&t),
        format!("line 5: e.{missing_side} is null (edge 0 is on the boundary)")
    );

    let via_variable = format!(
        "algorithm a(e : Edge);\nstructuretype WingedEdge\nvar f : Face;\n    g : Edge;\nbegin\n  f := e.{missing_side};\n  g := f.incidentEdge;\nend;"
    );
    let t = trace(&via_variable, &we, &[("e", Value::Edge(0))]);
    assert_eq!(
        error_of(&t),
        format!(
            "line 7: f is null (set from e.{missing_side} on line 6: edge 0 is on the boundary)"
        )
    );
    assert_eq!(t.len(), 2, "the trace keeps the steps before the error");

    let unassigned =
        "algorithm a(v : Vertex) : WingedEdge;\nvar e : Edge;\nbegin\n  mark e.startVertex;\nend;";
    assert_eq!(
        error_of(&trace(unassigned, &we, &[("v", Value::Vertex(0))])),
        "line 4: e is null (it has not been assigned yet)"
    );

    let null_mark = "algorithm a(v : Vertex) : WingedEdge;\nvar e : Edge;\nbegin\n  e := null;\n  mark e;\nend;";
    assert_eq!(
        error_of(&trace(null_mark, &we, &[("v", Value::Vertex(0))])),
        "line 5: cannot mark null: e is null (assigned on line 4)"
    );

    let division = "algorithm a(n : Integer) : HalfEdge;\nvar m : Integer;\nbegin\n  m := 7 div (n - 2);\nend;";
    let he = half(&grid);
    assert_eq!(
        error_of(&trace(division, &he, &[("n", Value::Integer(2))])),
        "line 4: division by zero (7 div 0) in 7 div (n - 2)"
    );
    let overflow = "algorithm a(n : Integer) : HalfEdge;\nbegin\n  n := n * n;\nend;";
    assert_eq!(
        error_of(&trace(overflow, &he, &[("n", Value::Integer(100_000))])),
        "line 3: integer overflow (100000 * 100000) in n * n"
    );
}

#[test]
fn integers_and_booleans_compute_as_documented() {
    let mesh = half(&generate::cube_zyx());
    let source = "algorithm a(v : Vertex) : HalfEdge;
var q, r, s : Integer;
    b, c : Boolean;
    e : Edge;
begin
  q := -7 div 2;
  r := -7 mod 3;
  s := 2 + 3 * 4 - -1;
  b := not (r < q) or false;
  e := v.incidentEdge;
  // `and` short-circuits: the lookup on the right never runs on null.
  c := e.face = null and e.face.incidentEdge = e;
end;";
    let t = trace(source, &mesh, &[("v", Value::Vertex(0))]);
    assert_eq!(*t.outcome(), Outcome::Finished);
    let vars = t.final_variables();
    assert_eq!(
        &vars[1..6],
        &[
            Value::Integer(-3),
            Value::Integer(-1),
            Value::Integer(15),
            Value::Boolean(true),
            Value::Boolean(false)
        ]
    );
}

#[test]
fn inputs_are_checked_against_parameters_and_mesh() {
    let algorithm = compile_one(NEPERUD_FIG_5B);
    let cube = generate::cube_zyx();
    let (we, he) = (winged(&cube), half(&cube));
    let err = |topology: &dyn Topology, args: &[(&str, Value)]| {
        run(&algorithm, &topology, args, RunOptions::default())
            .err()
            .map(|e| e.to_string())
    };
    assert_eq!(
        err(&we, &[("v", Value::Vertex(0))]).as_deref(),
        Some(
            "algorithm `vertexAdjacentEdge` walks a HalfEdge structure, but the mesh is a WingedEdge structure"
        )
    );
    assert_eq!(
        err(&he, &[]).as_deref(),
        Some("no value given for parameter `v` (Vertex)")
    );
    assert_eq!(
        err(&he, &[("v", Value::Vertex(0)), ("w", Value::Vertex(1))]).as_deref(),
        Some("algorithm `vertexAdjacentEdge` has no parameter `w` (its parameters: v : Vertex)")
    );
    assert_eq!(
        err(&he, &[("v", Value::Face(0))]).as_deref(),
        Some("parameter `v` is a Vertex, but was given face 0")
    );
    assert_eq!(
        err(&he, &[("v", Value::Vertex(8))]).as_deref(),
        Some("parameter `v`: vertex 8 does not exist (the mesh has 8 vertices)")
    );
    assert_eq!(
        algorithm.parse_argument("v=3"),
        Ok(("v".to_owned(), Value::Vertex(3)))
    );
    assert_eq!(
        algorithm.parse_argument(" v = 3 "),
        Ok(("v".to_owned(), Value::Vertex(3)))
    );
    assert!(matches!(
        algorithm.parse_argument("v=x"),
        Err(InputError::WrongType { .. })
    ));
    assert!(matches!(
        algorithm.parse_argument("v3"),
        Err(InputError::Malformed { .. })
    ));
    assert!(matches!(
        algorithm.parse_argument("f=3"),
        Err(InputError::UnknownParameter { .. })
    ));
}

/// A topology with a broken table, to show lookup failures are reported,
/// not panicked on.
struct Broken;

impl Topology for Broken {
    fn structure(&self) -> Structure {
        Structure::HalfEdge
    }

    fn count(&self, _kind: ElementKind) -> usize {
        1
    }

    fn lookup(
        &self,
        element: ElementRef,
        field: Column,
    ) -> Result<Option<ElementRef>, LookupError> {
        match field {
            Column::IncidentEdge => Ok(Some(ElementRef::new(ElementKind::Edge, 0))),
            _ => Err(LookupError::NoSuchElement(element)),
        }
    }
}

#[test]
fn a_broken_table_stops_the_trace_with_a_message() {
    let t = trace(NEPERUD_FIG_5B, &Broken, &[("v", Value::Vertex(0))]);
    assert_eq!(
        error_of(&t),
        "line 11: lookup failed: edge 0 does not exist in this mesh"
    );
    assert_eq!(t.render_marked(), "marked: edge 0");
}

#[test]
fn fast_execution_and_full_traces_agree() {
    let programs = lang::library::load().expect("library compiles");
    let polygons = icosahedron();
    let (we, he) = (winged(&polygons), half(&polygons));
    for (program, topology) in [
        (&programs[0], &we as &dyn Topology),
        (&programs[1], &he as &dyn Topology),
    ] {
        for algorithm in &program.algorithms {
            let kind = algorithm
                .params()
                .next()
                .and_then(|p| p.ty.element_kind())
                .expect("element parameter");
            let args = [(
                algorithm
                    .params()
                    .next()
                    .expect("a parameter")
                    .name
                    .as_str(),
                Value::from(ElementRef::new(kind, 3)),
            )];
            let fast = execute(algorithm, &topology, &args, RunOptions::default()).expect("fits");
            let full = run(algorithm, &topology, &args, RunOptions::default()).expect("fits");
            assert_eq!(
                fast.marked,
                full.marked().collect::<Vec<_>>(),
                "{}",
                algorithm.name
            );
            assert_eq!(fast.steps, full.len(), "{}", algorithm.name);
            assert_eq!(fast.variables, full.final_variables(), "{}", algorithm.name);
            assert_eq!(&fast.outcome, full.outcome(), "{}", algorithm.name);
        }
    }
}

#[test]
fn a_file_holds_several_algorithms_found_by_name() {
    let source = format!(
        "{JOURNAL_FIG_6}\n{}",
        NEPERUD_FIG_5B.replace("vertexAdjacentEdge", "aroundVertex")
    );
    let program = lang::compile(&source).expect("compiles");
    assert_eq!(
        program.names().collect::<Vec<_>>(),
        ["vertexAdjacentEdge", "aroundVertex"]
    );
    assert_eq!(
        program.algorithm("AROUNDVERTEX").map(|a| a.structure),
        Some(Structure::HalfEdge)
    );
    assert!(lang::check(&source).is_empty());
}

#[test]
fn a_million_steps_stay_compact_and_reachable() {
    let mesh = half(&quad_torus(6, 5));
    let algorithm = compile_one(&SPIN.replace("LIMIT", "120000"));
    let trace = run(
        &algorithm,
        &&mesh,
        &[("v", Value::Vertex(0))],
        RunOptions {
            step_limit: 2_000_000,
            ..RunOptions::default()
        },
    )
    .expect("fits");
    assert!(trace.len() > 1_000_000, "{}", trace.len());
    let per_step = trace.memory_bytes() as f64 / trace.len() as f64;
    eprintln!(
        "{} steps, {} bytes, {per_step:.2} bytes per step",
        trace.len(),
        trace.memory_bytes()
    );
    assert!(per_step < 17.5, "{per_step} bytes per step");
    // Jumping far into the trace is a snapshot plus a short replay.
    let i = 777_777;
    let state = trace.variables_at(i);
    let start = i - i % lang::trace::SNAPSHOT_INTERVAL;
    let mut expected = trace.variables_at(start - 1);
    for j in start..=i {
        if let StepKind::Assign { variable, value } = trace.step(j).expect("step").kind {
            expected[variable] = value;
        }
    }
    assert_eq!(state, expected);
    assert_eq!(trace.final_variables()[2], Value::Integer(120_000));
}

#[test]
fn deep_nesting_is_refused_not_overflowing_the_stack() {
    let deep_parens = format!(
        "algorithm a(n : Integer) : HalfEdge; begin n := {}1{}; end",
        "(".repeat(100_000),
        ")".repeat(100_000)
    );
    let deep_blocks = format!(
        "algorithm a(n : Integer) : HalfEdge; begin {} n := 1 {} end",
        "begin ".repeat(100_000),
        "end ".repeat(100_000)
    );
    let deep_nots = format!(
        "algorithm a(b : Boolean) : HalfEdge; begin b := {} b; end",
        "not ".repeat(100_000)
    );
    for source in [deep_parens, deep_blocks, deep_nots] {
        let diagnostics = lang::check(&source);
        assert!(
            diagnostics
                .iter()
                .any(|d| d.message.contains("nested too deeply")),
            "{diagnostics:?}"
        );
    }
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(300))]

    /// Whatever a student types, compiling it reports errors or succeeds;
    /// it never panics. Inputs: the library with a random slice cut out
    /// and random text spliced in.
    #[test]
    fn compiling_never_panics(cut in 0usize..20_000, len in 0usize..40, insert in "[ -~\\n]{0,12}") {
        let library = lang::library::SOURCES[(cut / 7) % 2].1;
        let start = cut % library.len();
        let end = (start + len).min(library.len());
        let (start, end) = (floor_char(library, start), floor_char(library, end));
        let source = format!("{}{insert}{}", &library[..start], &library[end..]);
        match lang::compile(&source) {
            Ok(program) => {
                for algorithm in &program.algorithms {
                    let _ = lang::disassemble(algorithm);
                }
            }
            Err(diagnostics) => {
                proptest::prop_assert!(!diagnostics.is_empty());
                let rendered = lang::render_all(&diagnostics, &source, Some("x.alg"));
                proptest::prop_assert!(rendered.contains("error"));
            }
        }
    }
}

fn floor_char(text: &str, mut index: usize) -> usize {
    while !text.is_char_boundary(index) {
        index -= 1;
    }
    index
}
