//! The floor the builders are measured against: the plainest half-edge build
//! from triangles that makes the same tables as `HalfEdgeMesh::build` (end
//! vertex, face, pair and successor of each half-edge; a half-edge per face;
//! a position and its lowest-numbered incoming half-edge per vertex), and nothing else. It
//! trusts its input: closed, manifold, consistently oriented triangles with
//! every index in range. It checks nothing, so it cannot refuse a file, name
//! a line or find a boundary: the builder's cost above it is what those take.
//!
//! Shared by `benches/mesh_build.rs` (native) and the wasm32 benchmark
//! (`cargo xtask bench-wasm`), so both measure the same code.

use glam::Vec3;

/// "No half-edge", as the builder writes it.
const NONE: u32 = u32::MAX;

/// One half-edge: end vertex, face, pair, successor.
pub type Row = [u32; 4];

/// The floor's tables.
pub struct Tables {
    pub rows: Vec<Row>,
    pub faces: Vec<u32>,
    pub vertices: Vec<(Vec3, u32)>,
}

/// Builds from `indices`, three per triangle, over `positions`.
///
/// Half-edge `h` is corner `h`. The edges are bucketed by their lower end
/// with a counting sort (one pass counts, one places), and each bucket, a
/// handful of entries, pairs its two uses of every edge by their upper end.
pub fn half_edge(indices: &[u32], positions: &[Vec3]) -> Tables {
    let vertex_count = positions.len();
    let triangles = indices.as_chunks::<3>().0;

    // start[lo + 1] counts the edges whose lower end is lo, then the prefix
    // sum turns it into where lo's bucket ends.
    let mut start = vec![0u32; vertex_count + 1];
    for &[a, b, c] in triangles {
        start[a.min(b) as usize + 1] += 1;
        start[b.min(c) as usize + 1] += 1;
        start[c.min(a) as usize + 1] += 1;
    }
    for v in 1..=vertex_count {
        start[v] += start[v - 1];
    }

    // One pass over the triangles writes each half-edge's row, its bucket
    // entry (upper end above, half-edge below) and an incoming half-edge.
    let mut cursor = start[..vertex_count].to_vec();
    let mut entries = vec![0u64; indices.len()];
    let mut rows = Vec::with_capacity(indices.len());
    let mut incoming = vec![NONE; vertex_count];
    for (face, &[a, b, c]) in (0u32..).zip(triangles) {
        let h = 3 * face;
        for (k, (from, to)) in (0u32..).zip([(a, b), (b, c), (c, a)]) {
            let slot = &mut cursor[from.min(to) as usize];
            entries[*slot as usize] = (u64::from(from.max(to)) << 32) | u64::from(h + k);
            *slot += 1;
            rows.push([to, face, NONE, h + (k + 1) % 3]);
            // The lowest-numbered half-edge ending at each vertex.
            let first = &mut incoming[to as usize];
            if *first == NONE {
                *first = h + k;
            }
        }
    }

    for bucket in start.windows(2) {
        let bucket = &entries[bucket[0] as usize..bucket[1] as usize];
        for (i, &x) in bucket.iter().enumerate() {
            if let Some(&y) = bucket[i + 1..].iter().find(|&&y| (x ^ y) >> 32 == 0) {
                rows[x as u32 as usize][2] = y as u32;
                rows[y as u32 as usize][2] = x as u32;
            }
        }
    }

    Tables {
        rows,
        faces: (0..triangles.len() as u32).map(|f| 3 * f).collect(),
        vertices: positions.iter().copied().zip(incoming).collect(),
    }
}
