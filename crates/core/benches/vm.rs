//! The algorithm VM's speed: the library's `vertexAdjacentEdge` from every
//! vertex of a ~200k-face mesh (the benchmark torus at 316×316 vertices,
//! 199,712 triangles), on both structures, counting operations (trace steps)
//! per second.
//!
//! `execute` keeps only the output (the fast path for queries); `run` records
//! the full trace for stepping, as the app does.
//!
//! Run: `cargo bench -p edgewise-core --bench vm`.

use std::hint::black_box;

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use edgewise_core::lang::{self, Algorithm, RunOptions, Topology, Value};
use edgewise_core::mesh::{HalfEdgeMesh, WingedEdgeMesh, generate};

fn library_algorithm(file: usize, name: &str) -> std::sync::Arc<Algorithm> {
    let programs = lang::library::load().expect("the library compiles");
    let algorithm = programs[file].algorithm(name).expect("the library has it");
    std::sync::Arc::clone(algorithm)
}

/// Operations performed by one pass over every vertex.
fn operations<T: Topology>(algorithm: &Algorithm, mesh: &T) -> u64 {
    let vertices = mesh.count(edgewise_core::schema::ElementKind::Vertex) as u32;
    (0..vertices)
        .map(|v| {
            let run = lang::execute(
                algorithm,
                mesh,
                &[("v", Value::Vertex(v))],
                RunOptions::default(),
            );
            run.expect("inputs fit").steps as u64
        })
        .sum()
}

fn every_vertex<T: Topology>(
    c: &mut Criterion,
    label: &str,
    algorithm: &std::sync::Arc<Algorithm>,
    mesh: &T,
) {
    let vertices = mesh.count(edgewise_core::schema::ElementKind::Vertex) as u32;
    let mut group = c.benchmark_group(format!("vm/{label}"));
    group.sample_size(10);
    group.throughput(Throughput::Elements(operations(algorithm, mesh)));
    group.bench_function("execute", |b| {
        b.iter(|| {
            for v in 0..vertices {
                let args = [("v", Value::Vertex(v))];
                black_box(
                    lang::execute(algorithm, mesh, black_box(&args), RunOptions::default()).ok(),
                );
            }
        });
    });
    group.bench_function("trace", |b| {
        b.iter(|| {
            for v in 0..vertices {
                let args = [("v", Value::Vertex(v))];
                black_box(lang::run(algorithm, mesh, black_box(&args), RunOptions::default()).ok());
            }
        });
    });
    group.finish();
}

fn vm(c: &mut Criterion) {
    let polygons = generate::torus(316, 316);
    let (winged, _) = WingedEdgeMesh::build(&polygons).expect("the torus is a valid mesh");
    let (half, _) = HalfEdgeMesh::build(&polygons).expect("the torus is a valid mesh");
    every_vertex(
        c,
        "winged_edge/vertexAdjacentEdge",
        &library_algorithm(0, "vertexAdjacentEdge"),
        &winged,
    );
    every_vertex(
        c,
        "half_edge/vertexAdjacentEdge",
        &library_algorithm(1, "vertexAdjacentEdge"),
        &half,
    );
}

criterion_group!(benches, vm);
criterion_main!(benches);
