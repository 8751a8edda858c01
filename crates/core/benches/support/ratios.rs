//! The builders against the floor, in one run: the three builds take turns,
//! round after round, so whatever else the machine does falls on all three
//! alike, and the table gives their medians and ratios. The native bench and
//! the wasm32 benchmark print the same table.

use edgewise_core::mesh::{
    FaceId, HalfEdgeId, HalfEdgeMesh, Polygons, VertexId, WingedEdgeMesh, generate,
};

use crate::floor;

/// Torus grids of 10k, ~100k and 1M triangles, as in `benches/mesh_build.rs`.
pub const SIZES: [(u32, u32); 3] = [(100, 50), (316, 158), (1000, 500)];

/// Medians, in milliseconds, for one mesh.
pub struct Row {
    pub label: String,
    pub triangles: usize,
    pub floor: f64,
    pub half_edge: f64,
    pub winged_edge: f64,
    /// The first half-edge build of the run, before any other build of
    /// this size: a page builds a mesh once, and a wasm engine may still be
    /// running its baseline code then.
    pub first_half_edge: f64,
}

/// Measures every size with the clock `now` (milliseconds). Each round
/// builds with all three, and drops the result outside the timing. The
/// half-edge builder goes first in the first round, so that its first time
/// is a first call.
pub fn measure(now: &dyn Fn() -> f64) -> Vec<Row> {
    SIZES
        .into_iter()
        .map(|(nu, nv)| {
            let polygons = generate::torus(nu, nv);
            let indices: Vec<u32> = polygons.faces().flatten().copied().collect();
            // Enough rounds for a steady median: 401 at 10k triangles, 41 at
            // 100k, 21 at 1M.
            let rounds = (4_000_000 / polygons.face_count()).clamp(21, 401) | 1;
            let [mut floors, mut half_edges, mut winged_edges] = [const { Vec::new() }; 3];
            for _ in 0..rounds {
                half_edges.push(time(now, || HalfEdgeMesh::build(&polygons)));
                floors.push(time(now, || {
                    floor::half_edge(&indices, polygons.positions())
                }));
                winged_edges.push(time(now, || WingedEdgeMesh::build(&polygons)));
            }
            check_floor(&polygons, &indices);
            Row {
                label: format!("{nu}x{nv}"),
                triangles: polygons.face_count(),
                first_half_edge: half_edges[0],
                floor: median(floors),
                half_edge: median(half_edges),
                winged_edge: median(winged_edges),
            }
        })
        .collect()
}

/// The table, in Markdown; `goal` is the half-edge build's goal against the
/// floor where it runs.
pub fn table(rows: &[Row], goal: &str) -> String {
    let mut out = format!(
        "| torus | triangles | floor | half-edge | half-edge / floor (goal {goal}) \
         | winged-edge | winged / half (goal ≤ 1.1×) | first half-edge build |\n\
         | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n"
    );
    for row in rows {
        out.push_str(&format!(
            "| {} | {} | {} | {} | {:.2}× | {} | {:.2}× | {} |\n",
            row.label,
            row.triangles,
            millis(row.floor),
            millis(row.half_edge),
            row.half_edge / row.floor,
            millis(row.winged_edge),
            row.winged_edge / row.half_edge,
            millis(row.first_half_edge),
        ));
    }
    out
}

fn millis(ms: f64) -> String {
    if ms < 10.0 {
        format!("{ms:.3} ms")
    } else {
        format!("{ms:.1} ms")
    }
}

/// How long `build` takes; its result is dropped after the clock stops.
fn time<T>(now: &dyn Fn() -> f64, build: impl FnOnce() -> T) -> f64 {
    let start = now();
    let built = build();
    let elapsed = now() - start;
    drop(built);
    elapsed
}

fn median(mut times: Vec<f64>) -> f64 {
    times.sort_by(f64::total_cmp);
    times.get(times.len() / 2).copied().unwrap_or(f64::NAN)
}

/// The floor must make the builder's tables, or the ratio compares unequal
/// work: every half-edge's end, face, pair and successor, each face's and
/// each vertex's half-edge.
fn check_floor(polygons: &Polygons, indices: &[u32]) {
    let floor = floor::half_edge(indices, polygons.positions());
    let (mesh, _) = HalfEdgeMesh::build(polygons).expect("the torus is a valid mesh");
    assert_eq!(mesh.half_edge_count(), floor.rows.len(), "a closed torus");
    for (h, &[end, face, pair, successor]) in (0u32..).zip(&floor.rows) {
        let built = mesh.half_edge(HalfEdgeId::new(h)).expect("a half-edge row");
        assert_eq!(
            (
                built.end_vertex.raw(),
                built.face.map(FaceId::raw),
                built.pair_edge.raw(),
                built.successor_edge.raw()
            ),
            (end, Some(face), pair, successor),
            "half-edge {h}"
        );
    }
    for (f, &incident) in (0u32..).zip(&floor.faces) {
        let built = mesh.face(FaceId::new(f)).expect("a face row");
        assert_eq!(built.incident_edge.raw(), incident, "face {f}");
    }
    for (v, &(position, incident)) in (0u32..).zip(&floor.vertices) {
        let built = mesh.vertex(VertexId::new(v)).expect("a vertex row");
        assert_eq!(
            (built.position, built.incident_edge.map(HalfEdgeId::raw)),
            (position, Some(incident)),
            "vertex {v}"
        );
    }
}
