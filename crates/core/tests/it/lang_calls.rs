//! Calls among algorithms and arrays: results and arguments, recursion and
//! its limit, the call stack and stepping over and out of calls in a
//! trace, arrays' items at every step, their limits, and calls that edit
//! the mesh.

use crate::lang_support::*;
use edgewise_core::lang::{
    self, Algorithm, InputError, Program, RunOptions, RuntimeErrorKind, StepKind, Trace, Value,
    execute, run,
};
use edgewise_core::mesh::{Mesh, generate};
use std::sync::Arc;

fn program(source: &str) -> Program {
    lang::compile_rendered(source, Some("test.alg")).unwrap_or_else(|e| panic!("{e}"))
}

fn algorithm(program: &Program, name: &str) -> Arc<Algorithm> {
    Arc::clone(program.algorithm(name).expect("defined"))
}

fn error_of(trace: &Trace) -> String {
    trace
        .outcome()
        .error()
        .map(ToString::to_string)
        .unwrap_or_default()
}

const TRIANGLES: &str = "
algorithm sides(f : Face) : HalfEdge returns Integer;
var h : Edge;
    n : Integer;
begin
  h := f.incidentEdge;
  n := 1;
  while h.next <> f.incidentEdge do
    h := h.next;
    n := n + 1;
  end;
  return n;
end;

algorithm isTriangle(f : Face) : HalfEdge returns Boolean;
begin
  return sides(f) = 3;
end;

algorithm countTriangles(v : Vertex) : HalfEdge;
var h : Edge;
    n : Integer;
begin
  h := v.incidentEdge;
  do
    if isTriangle(h.face) then
      n := n + 1;
    end;
    h := h.next.pair;
  while h <> v.incidentEdge;
  message v, \"touches\", n, \"triangles\";
end;
";

#[test]
fn calls_return_their_results_and_both_runs_agree() {
    let program = program(TRIANGLES);
    let count = algorithm(&program, "countTriangles");
    assert!(!count.edits());
    for (polygons, expected) in [
        (generate::tetrahedron(), 3),
        (generate::cube_zyx(), 0),
        (octahedron(), 4),
    ] {
        let mesh = half(&polygons);
        let args = [("v", Value::Vertex(0))];
        let fast = execute(&count, &mesh, &args, RunOptions::default()).expect("fits");
        let trace = run(&count, &mesh, &args, RunOptions::default()).expect("fits");
        assert_eq!(fast.outcome, *trace.outcome());
        assert_eq!(fast.variables, trace.final_variables());
        assert_eq!(fast.steps, trace.len());
        assert_eq!(fast.variable(&count, "n"), Some(Value::Integer(expected)));
        assert_eq!(
            fast.messages,
            [format!("vertex 0 touches {expected} triangles")]
        );
    }
    let sides = algorithm(&program, "sides");
    let run = execute(
        &sides,
        &half(&generate::cube_zyx()),
        &[("f", Value::Face(2))],
        RunOptions::default(),
    )
    .expect("fits");
    assert_eq!(run.result, Some(Value::Integer(4)));
}

#[test]
fn a_trace_shows_calls_and_returns_indented_by_depth() {
    let program = program(TRIANGLES);
    let count = algorithm(&program, "countTriangles");
    let mesh = half(&generate::tetrahedron());
    let trace = run(
        &count,
        &mesh,
        &[("v", Value::Vertex(0))],
        RunOptions::default(),
    )
    .expect("fits");
    let lines: Vec<String> = (0..trace.len()).map(|i| trace.render_line(i)).collect();
    let call = lines
        .iter()
        .position(|l| l.contains("call isTriangle("))
        .expect("a call");
    assert!(
        lines[call].contains("line 26  call isTriangle(f = face "),
        "{}",
        lines[call]
    );
    assert_eq!(trace.depth(call), Some(0));
    assert_eq!(trace.depth(call + 1), Some(1));
    assert!(
        lines[call + 1].contains("line 17    call sides(f = face "),
        "{}",
        lines[call + 1]
    );
    assert!(
        lines[call + 2].contains("line 6      lookup f.incidentEdge"),
        "{}",
        lines[call + 2]
    );
    let returned = lines
        .iter()
        .position(|l| l.contains("return 3"))
        .expect("sides returns");
    assert_eq!(trace.depth(returned), Some(2));
    assert!(
        lines[returned + 1].contains("    compare sides(f) = 3 (3 = 3) -> true"),
        "{}",
        lines[returned + 1]
    );
    assert!(
        lines[returned + 2].ends_with("    return true"),
        "{}",
        lines[returned + 2]
    );
    assert!(matches!(
        trace.step(returned + 2).map(|s| s.kind),
        Some(StepKind::Return {
            value: Some(Value::Boolean(true))
        })
    ));
    assert!(matches!(
        trace.step(call).map(|s| s.kind),
        Some(StepKind::Invoke {
            algorithm: "isTriangle",
            ..
        })
    ));
    assert!(lines.last().expect("steps").ends_with("  done"));
}

#[test]
fn the_call_stack_holds_each_frames_variables_at_each_step() {
    let program = program(TRIANGLES);
    let count = algorithm(&program, "countTriangles");
    let mesh = half(&octahedron());
    let trace = run(
        &count,
        &mesh,
        &[("v", Value::Vertex(0))],
        RunOptions::default(),
    )
    .expect("fits");
    let inner = (0..trace.len())
        .find(|&i| trace.depth(i) == Some(2) && trace.render_line(i).contains("assign n := 2"))
        .expect("sides counts");
    let frames = trace.frames_at(inner);
    let names: Vec<&str> = frames.iter().map(|f| f.name).collect();
    assert_eq!(names, ["countTriangles", "isTriangle", "sides"]);
    assert_eq!(frames[0].call_line, None);
    assert_eq!(frames[1].call_line, Some(26));
    assert_eq!(frames[2].call_line, Some(17));
    assert_eq!(
        frames.iter().map(|f| f.depth).collect::<Vec<_>>(),
        [0, 1, 2]
    );
    let value = |frame: &lang::trace::FrameView<'_>, name: &str| {
        frame
            .variables
            .iter()
            .find(|(v, _)| v.name == name)
            .map(|&(_, value)| value)
    };
    assert_eq!(value(&frames[2], "n"), Some(Value::Integer(2)));
    assert_eq!(value(&frames[1], "f"), value(&frames[2], "f"));
    // The started algorithm's frame is what variables_at says, and a call
    // changes none of its variables.
    let root: Vec<Value> = frames[0].variables.iter().map(|&(_, v)| v).collect();
    assert_eq!(root, trace.variables_at(inner));
    let call = frames[1].call_step.expect("a call");
    assert_eq!(trace.variables_at(call), trace.variables_at(inner));
    // Every frame, at every step, is its start replayed step by step.
    for index in 0..trace.len() {
        let frames = trace.frames_at(index);
        let innermost = frames.last().expect("a frame");
        assert_eq!(innermost.depth, trace.depth(index).expect("a step"));
        assert_eq!(frames[0].variables.len(), count.variables.len());
    }
}

#[test]
fn stepping_over_and_out_of_calls() {
    let program = program(TRIANGLES);
    let count = algorithm(&program, "countTriangles");
    let mesh = half(&generate::tetrahedron());
    let trace = run(
        &count,
        &mesh,
        &[("v", Value::Vertex(0))],
        RunOptions::default(),
    )
    .expect("fits");
    let call = (0..trace.len())
        .find(|&i| matches!(trace.step(i).map(|s| s.kind), Some(StepKind::Invoke { .. })))
        .expect("a call");
    // Into: the callee's first step. Over: the caller's next step.
    assert_eq!(trace.depth(call + 1), Some(1));
    let over = trace.step_over(call).expect("the caller goes on");
    assert_eq!(trace.depth(over), Some(0));
    assert!((call + 1..over).all(|i| trace.depth(i).is_some_and(|d| d > 0)));
    assert_eq!(trace.step_back_over(over), Some(call));
    // Out of the innermost call, then out of the next.
    let deepest = (0..trace.len())
        .find(|&i| trace.depth(i) == Some(2))
        .expect("sides runs");
    let out = trace.step_out(deepest).expect("back in isTriangle");
    assert_eq!(trace.depth(out), Some(1));
    assert!(trace.render_line(out).contains("compare sides(f) = 3"));
    let out = trace.step_out(out).expect("back in countTriangles");
    assert_eq!(out, over);
    assert_eq!(trace.step_out(out), None);
    // Over a step that makes no call is the next step.
    assert_eq!(trace.step_over(over), Some(over + 1));
    assert_eq!(trace.step_over(trace.len() - 1), None);
}

#[test]
fn breakpoints_stop_inside_calls() {
    let program = program(TRIANGLES);
    let count = algorithm(&program, "countTriangles");
    let mesh = half(&generate::tetrahedron());
    let trace = run(
        &count,
        &mesh,
        &[("v", Value::Vertex(0))],
        RunOptions::default(),
    )
    .expect("fits");
    // Line 12 is `return n` in sides.
    let first = trace.next_on_line(0, 12).expect("sides returns");
    assert_eq!(trace.line(first), Some(12));
    assert_eq!(trace.depth(first), Some(2));
    let second = trace.next_on_line(first, 12).expect("again");
    assert_eq!(trace.previous_on_line(second, 12), Some(first));
}

const RECURSION: &str = "
algorithm factorial(n : Integer) : HalfEdge returns Integer;
begin
  if n <= 1 then
    return 1;
  end;
  return n * factorial(n - 1);
end;

algorithm half(x : Float) : HalfEdge returns Float;
begin
  return x / 2;
end;

algorithm forever(n : Integer) : HalfEdge;
begin
  forever(n + 1);
end;
";

#[test]
fn recursion_runs_until_the_frame_limit() {
    let program = program(RECURSION);
    let mesh = half(&generate::tetrahedron());
    let factorial = algorithm(&program, "factorial");
    let run_of = |n| {
        execute(
            &factorial,
            &mesh,
            &[("n", Value::Integer(n))],
            RunOptions::default(),
        )
        .expect("fits")
    };
    assert_eq!(run_of(5).result, Some(Value::Integer(120)));
    assert_eq!(run_of(12).result, Some(Value::Integer(479_001_600)));
    let overflow = run_of(13);
    assert!(
        overflow
            .outcome
            .error()
            .is_some_and(|e| e.message.starts_with("integer overflow")),
        "{:?}",
        overflow.outcome
    );
    let half = algorithm(&program, "half");
    let halved = execute(
        &half,
        &mesh,
        &[("x", Value::Integer(3))],
        RunOptions::default(),
    )
    .expect("an Integer widens");
    assert_eq!(halved.result, Some(Value::Float(1.5)));

    // Frames live on the heap: the limit stops the run with a message at
    // the call, even on a thread with a small stack.
    let forever = algorithm(&program, "forever");
    let trace = std::thread::Builder::new()
        .stack_size(256 * 1024)
        .spawn(move || {
            let mesh = half_mesh();
            run(
                &forever,
                &mesh,
                &[("n", Value::Integer(0))],
                RunOptions::default(),
            )
            .expect("fits")
        })
        .expect("thread starts")
        .join()
        .expect("no stack overflow");
    let error = trace.outcome().error().expect("stopped");
    assert_eq!(error.kind, RuntimeErrorKind::Fault);
    assert_eq!(
        error.to_string(),
        "line 17: calls nest too deep: 256 algorithms are running at once, the most there may \
         be; does `forever` call itself without end?"
    );
    assert_eq!(trace.depth(trace.len() - 1), Some(255));
    assert_eq!(trace.frames_at(trace.len() - 1).len(), 256);
    assert_eq!(trace.variables_at(trace.len()), [Value::Integer(0)]);
}

fn half_mesh() -> edgewise_core::mesh::HalfEdgeMesh {
    half(&generate::tetrahedron())
}

const ARRAYS: &str = "
algorithm ring(v : Vertex) : HalfEdge returns Array of Vertex;
var around : Array of Vertex;
    h : Edge;
begin
  h := v.incidentEdge;
  do
    append(around, h.pair.vertex);
    h := h.next.pair;
  while h <> v.incidentEdge;
  return around;
end;

algorithm addValences(vs : Array of Vertex; into : Array of Integer) : HalfEdge;
var i : Integer;
begin
  i := 0;
  while i < length(vs) do
    append(into, length(ring(vs[i])));
    i := i + 1;
  end;
end;

algorithm neighbours(v : Vertex) : HalfEdge;
var near : Array of Vertex;
    valences : Array of Integer;
    weights : Array of Float;
    i : Integer;
begin
  near := ring(v);
  addValences(near, valences);
  near[0] := v;
  append(weights, 1);
  weights[0] := weights[0] + 0.5;
  message \"valences\", valences, \"of\", near;
  i := length(near) - 1;
  mark near[i];
end;
";

#[test]
fn arrays_are_filled_read_and_passed_to_and_from_calls() {
    let program = program(ARRAYS);
    let neighbours = algorithm(&program, "neighbours");
    let mesh = half(&octahedron());
    let args = [("v", Value::Vertex(0))];
    let fast = execute(&neighbours, &mesh, &args, RunOptions::default()).expect("fits");
    assert_eq!(fast.outcome, lang::Outcome::Finished);
    let near = fast.variable(&neighbours, "near").expect("a variable");
    let items = fast.items(near).expect("an array");
    assert_eq!(items.len(), 4);
    assert_eq!(items[0], Value::Vertex(0));
    let valences = fast.variable(&neighbours, "valences").expect("a variable");
    assert_eq!(
        fast.items(valences),
        Some(&[Value::Integer(4); 4][..]),
        "the callee appended to the caller's array"
    );
    let weights = fast.variable(&neighbours, "weights").expect("a variable");
    assert_eq!(fast.items(weights), Some(&[Value::Float(1.5)][..]));
    assert_eq!(fast.marked, [items[3].element().expect("a vertex")]);
    assert!(
        fast.messages[0].starts_with("valences [4, 4, 4, 4] of [vertex 0, vertex "),
        "{:?}",
        fast.messages
    );

    let trace = run(&neighbours, &mesh, &args, RunOptions::default()).expect("fits");
    assert_eq!(trace.final_variables(), fast.variables);
    assert_eq!(trace.items_at(near, trace.len()), Some(items.to_vec()));
    let rendered = trace.render();
    assert!(rendered.contains("  append vertex "), "{rendered}");
    assert!(rendered.contains("return [vertex "), "{rendered}");
    assert!(
        rendered.contains("call addValences(vs = [vertex "),
        "{rendered}"
    );
    assert!(
        rendered.contains("store near[0] := vertex 0 (was vertex "),
        "{rendered}"
    );
    assert!(rendered.contains("call length(vs) -> 4"), "{rendered}");
}

/// Replays the array steps forward and checks each array's items at each
/// step, then visits the steps backwards: both agree with `items_at`.
#[test]
fn array_items_at_any_step_are_exact_back_and_forth() {
    let program = program(ARRAYS);
    let neighbours = algorithm(&program, "neighbours");
    let mesh = half(&octahedron());
    let trace = run(
        &neighbours,
        &mesh,
        &[("v", Value::Vertex(0))],
        RunOptions::default(),
    )
    .expect("fits");
    let mut arrays: std::collections::BTreeMap<u32, Vec<Value>> = Default::default();
    let mut states = Vec::new();
    for index in 0..trace.len() {
        match trace.step(index).expect("a step").kind {
            StepKind::Append {
                array: Value::Array(a),
                value,
                length,
            } => {
                let items = arrays.entry(a).or_default();
                items.push(value);
                assert_eq!(items.len() as i32, length);
            }
            StepKind::Store {
                array: Value::Array(a),
                index: i,
                old,
                new,
            } => {
                let slot = &mut arrays.entry(a).or_default()[i as usize];
                assert_eq!(*slot, old);
                *slot = new;
            }
            _ => {}
        }
        states.push(arrays.clone());
    }
    assert!(arrays.len() >= 3, "{arrays:?}");
    for index in (0..trace.len()).rev() {
        for (&a, items) in &states[index] {
            assert_eq!(
                trace.items_at(Value::Array(a), index).as_ref(),
                Some(items),
                "array {a} after step {index}"
            );
        }
    }
}

#[test]
fn array_errors_name_the_index_and_the_length() {
    let source = "
algorithm third(f : Face) : HalfEdge;
var edges : Array of Edge;
    i : Integer;
begin
  append(edges, f.incidentEdge);
  append(edges, f.incidentEdge.next);
  i := 2;
  mark edges[i];
end;

algorithm hoard(v : Vertex) : HalfEdge;
var all : Array of Vertex;
begin
  do
    append(all, v);
  end;
end;
";
    let program = program(source);
    let mesh = half(&generate::tetrahedron());
    let third = algorithm(&program, "third");
    let trace = run(
        &third,
        &mesh,
        &[("f", Value::Face(0))],
        RunOptions::default(),
    )
    .expect("fits");
    assert_eq!(
        error_of(&trace),
        "line 9: index 2 is out of range in edges[i] (the array has 2 items, indices 0 to 1)"
    );
    let hoard = algorithm(&program, "hoard");
    let options = RunOptions {
        step_limit: 2_000_000,
        ..RunOptions::default()
    };
    let fast = execute(&hoard, &mesh, &[("v", Value::Vertex(0))], options).expect("fits");
    let error = fast.outcome.error().expect("stopped");
    assert_eq!(
        error.to_string(),
        "line 16: the arrays of this run reached 1048576 items, the most one run may make \
         (each new array counts as one)"
    );
    // The array itself counts as one.
    assert_eq!(fast.steps, lang::vm::MAX_ARRAY_ITEMS - 1);
}

#[test]
fn an_array_parameter_of_the_started_algorithm_starts_empty() {
    let program = program(ARRAYS);
    let add = algorithm(&program, "addValences");
    let mesh = half(&generate::tetrahedron());
    let fast = execute(&add, &mesh, &[], RunOptions::default()).expect("arrays need no input");
    assert_eq!(fast.outcome, lang::Outcome::Finished);
    assert_eq!(fast.arrays, [Vec::<Value>::new(), Vec::new()]);
    assert_eq!(
        execute(
            &add,
            &mesh,
            &[("vs", Value::Integer(3))],
            RunOptions::default()
        ),
        Err(InputError::WrongType {
            name: "vs".to_owned(),
            expected: lang::Type::Array(lang::types::Item::Vertex),
            found: "3".to_owned(),
        })
    );
}

#[test]
fn the_started_algorithms_return_goes_on_to_done() {
    let program = program(TRIANGLES);
    let is_triangle = algorithm(&program, "isTriangle");
    let mesh = half(&generate::cube_zyx());
    let trace = run(
        &is_triangle,
        &mesh,
        &[("f", Value::Face(0))],
        RunOptions::default(),
    )
    .expect("fits");
    assert_eq!(trace.result(), Some(Value::Boolean(false)));
    let last = trace.len() - 1;
    assert_eq!(trace.step(last).map(|s| s.kind), Some(StepKind::Done));
    assert!(matches!(
        trace.step(last - 1).map(|s| s.kind),
        Some(StepKind::Return {
            value: Some(Value::Boolean(false))
        })
    ));
}

/// A call that edits: the changes are journaled at the callee's steps, and
/// the trace seeks the mesh to any step.
#[test]
fn edits_inside_calls_are_journaled_at_the_callees_steps() {
    let program = lang::library::program("winged-edge-edits.alg")
        .expect("shipped")
        .unwrap_or_else(|e| panic!("{e}"));
    let split = algorithm(&program, "splitEdge");
    assert!(split.edits());
    assert!(algorithm(&program, "cutCorner").edits());
    assert!(!algorithm(&program, "isTriangle").edits());
    let mut mesh = Mesh::Winged(winged(&generate::tetrahedron()));
    let original = mesh.clone();
    let trace = lang::run_editing(
        &split,
        &mut mesh,
        &[("e", Value::Edge(0))],
        RunOptions::default(),
    )
    .expect("fits");
    assert_eq!(
        trace.outcome(),
        &lang::Outcome::Finished,
        "{}",
        trace.render()
    );
    assert!(mesh.validate().is_empty());
    let deep: Vec<usize> = (0..trace.len())
        .filter(|&i| trace.changes_at(i).next().is_some())
        .map(|i| trace.depth(i).expect("a step"))
        .collect();
    assert!(
        deep.contains(&0) && deep.contains(&1) && deep.contains(&2),
        "{deep:?}"
    );
    let after = mesh.clone();
    // Step back to before each step and forwards again.
    for index in (0..trace.len()).rev() {
        let to = trace.changes_through(index.checked_sub(1));
        trace
            .seek(&mut mesh, trace.changes().len(), to)
            .expect("reverts");
        trace
            .seek(&mut mesh, to, trace.changes().len())
            .expect("replays");
        assert_eq!(mesh, after);
    }
    trace
        .seek(&mut mesh, trace.changes().len(), 0)
        .expect("reverts");
    assert_eq!(mesh, original);
}

#[test]
fn a_read_only_run_stops_at_an_edit_inside_a_call() {
    let source = "
algorithm forget(v : Vertex) : HalfEdge;
begin
  v.incidentEdge := null;
end;

algorithm outer(v : Vertex) : HalfEdge;
begin
  forget(v);
end;
";
    let program = program(source);
    let outer = algorithm(&program, "outer");
    assert!(outer.edits());
    let mesh = half(&generate::tetrahedron());
    let trace = run(
        &outer,
        &mesh,
        &[("v", Value::Vertex(0))],
        RunOptions::default(),
    )
    .expect("fits");
    assert_eq!(
        error_of(&trace),
        "line 4: this run can only read the mesh; algorithms that change it run as edits"
    );
    // The call made no step before it stopped; the stack at the end has it.
    assert_eq!(trace.frames_at(trace.len() - 1).len(), 1);
    let frames = trace.frames_at(trace.len());
    assert_eq!(
        frames.iter().map(|f| f.name).collect::<Vec<_>>(),
        ["outer", "forget"]
    );
}

#[test]
fn traces_with_many_calls_stay_compact() {
    let source = "
algorithm next(h : Edge) : HalfEdge returns Edge;
begin
  return h.next;
end;

algorithm spin(v : Vertex; laps : Integer) : HalfEdge;
var h : Edge;
    n : Integer;
begin
  h := v.incidentEdge;
  while n < laps do
    h := next(h);
    n := n + 1;
  end;
end;
";
    let program = program(source);
    let spin = algorithm(&program, "spin");
    let mesh = half(&generate::tetrahedron());
    let trace = run(
        &spin,
        &mesh,
        &[("v", Value::Vertex(0)), ("laps", Value::Integer(50_000))],
        RunOptions {
            step_limit: 1_000_000,
            ..RunOptions::default()
        },
    )
    .expect("fits");
    assert_eq!(trace.outcome(), &lang::Outcome::Finished);
    // Per lap: the compare, the call, its lookup and return, two assigns
    // and the addition: 7 steps, one frame.
    let per_step = trace.memory_bytes() as f64 / trace.len() as f64;
    eprintln!(
        "{} steps, {} bytes, {per_step:.2} bytes per step",
        trace.len(),
        trace.memory_bytes()
    );
    assert!(per_step < 36.0, "{per_step} bytes per step");
    let i = trace.len() / 2 + 3;
    let frames = trace.frames_at(i);
    assert!(!frames.is_empty());
    assert_eq!(trace.variables_at(trace.len() - 1), trace.final_variables());
}

/// The strips showcase: on closed triangle meshes every face is in exactly
/// one strip, and each strip's faces follow one another across edges.
#[test]
fn triangle_strips_cover_every_face_once() {
    let program = lang::library::program("half-edge-strips.alg")
        .expect("shipped")
        .unwrap_or_else(|e| panic!("{e}"));
    let strips = algorithm(&program, "triangleStrips");
    for (name, polygons) in [
        ("octahedron", octahedron()),
        ("icosahedron", icosahedron()),
        ("tetrahedron", generate::tetrahedron()),
    ] {
        let mesh = half(&polygons);
        let run = execute(
            &strips,
            &mesh,
            &[("f", Value::Face(0))],
            RunOptions::default(),
        )
        .expect("fits");
        assert_eq!(run.outcome, lang::Outcome::Finished, "{name}");
        let mut faces: Vec<u32> = run.marked.iter().map(|f| f.id).collect();
        assert_eq!(faces.len(), polygons.face_count(), "{name}: {faces:?}");
        faces.sort_unstable();
        faces.dedup();
        assert_eq!(faces.len(), polygons.face_count(), "{name}: a face twice");
        let lengths = run
            .items(run.variable(&strips, "lengths").expect("a variable"))
            .expect("an array")
            .to_vec();
        let mut marked = run.marked.iter();
        for length in &lengths {
            let Value::Integer(length) = *length else {
                panic!("{length}")
            };
            let strip: Vec<u32> = marked
                .by_ref()
                .take(length as usize)
                .map(|f| f.id)
                .collect();
            for pair in strip.windows(2) {
                let shared = polygons
                    .face(pair[0] as usize)
                    .expect("a face")
                    .iter()
                    .filter(|v| polygons.face(pair[1] as usize).expect("a face").contains(v))
                    .count();
                assert_eq!(shared, 2, "{name}: {pair:?} share no edge");
            }
        }
        assert!(marked.next().is_none());
        eprintln!("{name}: {}", run.messages.last().expect("a summary"));
    }
    let cube = half(&generate::cube_zyx());
    let run = execute(
        &strips,
        &cube,
        &[("f", Value::Face(0))],
        RunOptions::default(),
    )
    .expect("fits");
    assert_eq!(
        run.outcome.error().map(|e| e.kind),
        Some(RuntimeErrorKind::Refused)
    );
}
