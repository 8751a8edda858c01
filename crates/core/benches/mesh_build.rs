//! Building both structures from the benchmark torus, and validating them.
//!
//! Torus grids of 100×50 (10k triangles), 316×158 (~100k) and 1000×500 (1M),
//! exactly as `mesh::generate::torus` documents, so figures compare with other
//! libraries. Every builder check is on, each build allocates fresh tables,
//! and dropping the result is not timed.
//!
//! `bare_counting_sort` is a reference measured alongside: the plainest
//! half-edge build (counting sort of half-edges by start vertex, pairs found
//! by scanning, no checks, no boundary), so figures taken on a busy machine
//! can still be compared with figures taken on a quiet one.
//!
//! Run: `cargo bench -p edgewise-core --bench mesh_build`.

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use edgewise_core::mesh::{HalfEdgeMesh, Polygons, WingedEdgeMesh, generate};
use glam::Vec3;

const SIZES: [(u32, u32); 3] = [(100, 50), (316, 158), (1000, 500)];

/// One row of the reference build: end vertex, face, pair, successor.
type BareRow = [u32; 4];

/// The reference build: triangles only, no checks. Returns the half-edge rows,
/// the face table and the vertex table.
fn bare_counting_sort(polygons: &Polygons) -> (Vec<BareRow>, Vec<u32>, Vec<(Vec3, u32)>) {
    let indices: Vec<u32> = polygons.faces().flatten().copied().collect();
    let n = indices.len();
    let vertex_count = polygons.vertex_count();
    let next = |h: usize| if h % 3 == 2 { h - 2 } else { h + 1 };
    let mut start = vec![0u32; vertex_count + 1];
    for &a in &indices {
        start[a as usize + 1] += 1;
    }
    for v in 1..=vertex_count {
        start[v] += start[v - 1];
    }
    let mut cursor = start.clone();
    let mut outgoing = vec![0u32; n];
    for (h, &a) in indices.iter().enumerate() {
        outgoing[cursor[a as usize] as usize] = h as u32;
        cursor[a as usize] += 1;
    }
    let mut rows = Vec::with_capacity(n);
    let mut incident = vec![u32::MAX; vertex_count];
    for h in 0..n {
        let (a, b) = (indices[h], indices[next(h)]);
        let around_b = &outgoing[start[b as usize] as usize..start[b as usize + 1] as usize];
        let pair = around_b
            .iter()
            .copied()
            .find(|&g| indices[next(g as usize)] == a)
            .unwrap_or(u32::MAX);
        rows.push([b, (h / 3) as u32, pair, next(h) as u32]);
        if incident[b as usize] == u32::MAX {
            incident[b as usize] = h as u32;
        }
    }
    let faces = (0..n as u32 / 3).map(|f| 3 * f).collect();
    let vertices = polygons.positions().iter().copied().zip(incident).collect();
    (rows, faces, vertices)
}

fn mesh_build(c: &mut Criterion) {
    let mut group = c.benchmark_group("mesh_build");
    for (nu, nv) in SIZES {
        let polygons = generate::torus(nu, nv);
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
            BenchmarkId::new("bare_counting_sort", &label),
            &polygons,
            |b, polygons| {
                b.iter_with_large_drop(|| bare_counting_sort(black_box(polygons)));
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

criterion_group!(benches, mesh_build);
criterion_main!(benches);
