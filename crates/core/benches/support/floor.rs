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
    // sum turns it into where lo's bucket ends. Slices, not vectors, are
    // indexed throughout and no table grows by `push`: the browser's
    // size-optimised build makes both calls, where a slice's indexing is
    // inline.
    let mut start_table = vec![0u32; vertex_count + 1];
    let start = &mut start_table[..];
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
    let mut cursor_table = start[..vertex_count].to_vec();
    let mut entries_table = vec![0u64; indices.len()];
    let mut rows_table = vec![[0; 4]; indices.len()];
    let mut incoming_table = vec![NONE; vertex_count];
    let mut pass = Pass {
        cursor: &mut cursor_table,
        entries: &mut entries_table,
        rows: &mut rows_table,
        incoming: &mut incoming_table,
    };
    for (face, &[a, b, c]) in (0u32..).zip(triangles) {
        let h = 3 * face;
        pass.half_edge(h, a, b, face, h + 1);
        pass.half_edge(h + 1, b, c, face, h + 2);
        pass.half_edge(h + 2, c, a, face, h);
    }

    let (entries, rows) = (&entries_table[..], &mut rows_table[..]);
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
        rows: rows_table,
        faces: (0..triangles.len() as u32).map(|f| 3 * f).collect(),
        vertices: positions.iter().copied().zip(incoming_table).collect(),
    }
}

/// The placing pass's tables.
struct Pass<'a> {
    cursor: &'a mut [u32],
    entries: &'a mut [u64],
    rows: &'a mut [Row],
    incoming: &'a mut [u32],
}

impl Pass<'_> {
    /// Writes half-edge `h = from→to`: its row, its bucket entry, and the
    /// vertex's incoming half-edge if it is the first to end there.
    #[inline(always)]
    fn half_edge(&mut self, h: u32, from: u32, to: u32, face: u32, successor: u32) {
        let slot = &mut self.cursor[from.min(to) as usize];
        self.entries[*slot as usize] = (u64::from(from.max(to)) << 32) | u64::from(h);
        *slot += 1;
        self.rows[h as usize] = [to, face, NONE, successor];
        let first = &mut self.incoming[to as usize];
        if *first == NONE {
            *first = h;
        }
    }
}
