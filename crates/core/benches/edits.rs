//! What an edit costs, on the 200k-face benchmark torus (half-edge):
//!
//! - a native flip and split (`operations::apply`, which clones nothing:
//!   the mesh is edited in place and each op is undone to keep it fixed);
//! - the traced `flipEdge` of the library (`run_editing`, every step and
//!   change recorded), against the native flip on the same edge;
//! - what the app does at every step of an editing trace: moving the mesh
//!   one change (`Trace::seek`) and checking every rule (`validate`) and
//!   the statistics (`live_stats`) of the whole mesh;
//! - a whole-mesh edit: the library's `loopSubdivide` on the 24×12 torus
//!   (576 triangles, about 270k steps), traced, then stepped back.
//!
//! Run: `cargo bench -p edgewise-core --bench edits`.

use std::hint::black_box;
use std::sync::Arc;

use criterion::{Criterion, criterion_group, criterion_main};
use edgewise_core::lang::{self, Algorithm, RunOptions, Value};
use edgewise_core::mesh::operations::{self, Operation};
use edgewise_core::mesh::{HalfEdgeMesh, Mesh, generate};

fn flip_edge() -> Arc<Algorithm> {
    let program = lang::library::program("half-edge-edits.alg")
        .expect("shipped")
        .expect("the library compiles");
    Arc::clone(program.algorithm("flipEdge").expect("shipped"))
}

/// Runs an editing algorithm, recording its trace, then steps the mesh back
/// to where it was; gives the number of steps.
fn traced_then_back(algorithm: &Arc<Algorithm>, mesh: &mut Mesh, input: (&str, Value)) -> usize {
    let trace =
        lang::run_editing(algorithm, mesh, &[input], RunOptions::default()).expect("inputs fit");
    trace.seek(mesh, trace.changes().len(), 0).expect("reverts");
    black_box(trace.len())
}

fn edits(c: &mut Criterion) {
    let (torus, _) = HalfEdgeMesh::build(&generate::torus(316, 316)).expect("the torus builds");
    let mut mesh = Mesh::Half(torus);
    let edge = 1000;
    let mut group = c.benchmark_group("edits/torus-200k");
    group.sample_size(20);

    for (label, operation) in [
        ("native flip", Operation::FlipEdge),
        ("native split", Operation::SplitEdge),
    ] {
        group.bench_function(label, |b| {
            b.iter(|| {
                let applied = operations::apply(&mut mesh, operation, &[edge]).expect("it applies");
                for change in applied.journal.iter().rev() {
                    change.revert(&mut mesh).expect("reverts");
                }
                black_box(applied.journal.len())
            });
        });
    }

    let algorithm = flip_edge();
    group.bench_function("traced flipEdge (run_editing)", |b| {
        b.iter(|| traced_then_back(&algorithm, &mut mesh, ("h", Value::Edge(edge))));
    });

    let trace = lang::run_editing(
        &algorithm,
        &mut mesh,
        &[("h", Value::Edge(edge))],
        RunOptions::default(),
    )
    .expect("inputs fit");
    let changes = trace.changes().len();
    group.bench_function("one step of the trace: seek one change", |b| {
        b.iter(|| {
            trace.seek(&mut mesh, changes, changes - 1).expect("seeks");
            trace.seek(&mut mesh, changes - 1, changes).expect("seeks");
        });
    });
    group.bench_function("one step of the trace: validate the mesh", |b| {
        b.iter(|| black_box(mesh.validate().len()));
    });
    group.bench_function("one step of the trace: live statistics", |b| {
        b.iter(|| black_box(mesh.live_stats().vertices));
    });
    group.finish();
}

fn subdivision(c: &mut Criterion) {
    let program = lang::library::program("half-edge-subdivision.alg")
        .expect("shipped")
        .expect("the library compiles");
    let algorithm = Arc::clone(program.algorithm("loopSubdivide").expect("shipped"));
    let (torus, _) = HalfEdgeMesh::build(&generate::torus(24, 12)).expect("the torus builds");
    let mut mesh = Mesh::Half(torus);
    let mut group = c.benchmark_group("edits/torus-576");
    group.sample_size(10);
    group.bench_function("traced loopSubdivide, then stepped back", |b| {
        b.iter(|| traced_then_back(&algorithm, &mut mesh, ("f", Value::Face(0))));
    });
    group.finish();
}

criterion_group!(benches, edits, subdivision);
criterion_main!(benches);
