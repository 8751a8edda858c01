//! Building both structures from the benchmark torus, and validating them.
//!
//! Torus grids of 100×50 (10k triangles), 316×158 (~100k) and 1000×500 (1M),
//! exactly as `mesh::generate::torus` documents, so figures compare with other
//! libraries. Every builder check is on, each build allocates fresh tables,
//! and dropping the result is not timed.
//!
//! `floor` is the floor measured alongside (`support/floor.rs`): the plainest
//! half-edge build from triangles, no checks and no boundary. After the
//! criterion groups, `cargo bench` prints the builders' medians against it,
//! measured in turns in the same run (`support/ratios.rs`), the table that
//! `cargo xtask bench-wasm` prints for wasm32.
//!
//! Run: `cargo bench -p edgewise-core --bench mesh_build`.

use std::{hint::black_box, time::Instant};

use criterion::{BenchmarkId, Criterion, Throughput};
use edgewise_core::mesh::{HalfEdgeMesh, WingedEdgeMesh, generate};

#[path = "support/floor.rs"]
mod floor;
#[path = "support/ratios.rs"]
mod ratios;

fn mesh_build(c: &mut Criterion) {
    let mut group = c.benchmark_group("mesh_build");
    for (nu, nv) in ratios::SIZES {
        let polygons = generate::torus(nu, nv);
        let indices: Vec<u32> = polygons.faces().flatten().copied().collect();
        let label = format!("{nu}x{nv}");
        group.throughput(Throughput::Elements(polygons.face_count() as u64));
        group.sample_size(if polygons.face_count() > 500_000 {
            20
        } else {
            50
        });

        group.bench_with_input(
            BenchmarkId::new("half_edge", &label),
            &polygons,
            |b, polygons| {
                b.iter_with_large_drop(|| HalfEdgeMesh::build(black_box(polygons)));
            },
        );
        group.bench_with_input(
            BenchmarkId::new("winged_edge", &label),
            &polygons,
            |b, polygons| {
                b.iter_with_large_drop(|| WingedEdgeMesh::build(black_box(polygons)));
            },
        );
        group.bench_with_input(
            BenchmarkId::new("floor", &label),
            &polygons,
            |b, polygons| {
                b.iter_with_large_drop(|| {
                    floor::half_edge(black_box(&indices), black_box(polygons.positions()))
                });
            },
        );

        let (half, _) = HalfEdgeMesh::build(&polygons).expect("the torus is a valid mesh");
        let (winged, _) = WingedEdgeMesh::build(&polygons).expect("the torus is a valid mesh");
        group.bench_with_input(
            BenchmarkId::new("validate_half_edge", &label),
            &half,
            |b, mesh| {
                b.iter(|| black_box(mesh).validate());
            },
        );
        group.bench_with_input(
            BenchmarkId::new("validate_winged_edge", &label),
            &winged,
            |b, mesh| {
                b.iter(|| black_box(mesh).validate());
            },
        );
    }
    group.finish();
}

fn main() {
    let mut criterion = Criterion::default().configure_from_args();
    mesh_build(&mut criterion);
    criterion.final_summary();
    // `cargo bench` passes --bench; `cargo test --benches` runs each
    // benchmark once, unoptimised, where the ratios would take minutes.
    if std::env::args().any(|arg| arg == "--bench") {
        let start = Instant::now();
        let rows = ratios::measure(&|| start.elapsed().as_secs_f64() * 1e3);
        println!(
            "\nThe builders against the floor, natively:\n\n{}",
            ratios::table(&rows, "≤ 1.2×")
        );
    }
}
