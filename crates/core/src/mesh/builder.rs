//! Topology construction shared by both structures, with the refusal checks.
//!
//! Both builds follow the same steps, all linear and without hashing:
//!
//! 1. check every face (size, index range, repeated vertices) and count the
//!    corners at each vertex;
//! 2. counting-sort the directed edges by their lower-numbered end, so each
//!    bucket holds every use of the edges at that vertex; sorting a bucket puts
//!    the uses of one edge side by side, which finds pairs, non-manifold edges
//!    and orientation conflicts in one scan;
//! 3. number the boundary half-edges and link them along the boundary loops;
//! 4. walk once around every vertex to refuse non-manifold vertices.
//!
//! Interior half-edge `h` is corner `h` of the flat polygon list, so its start
//! vertex is `indices[h]` and no per-half-edge table is needed until the final
//! structure is written.

use super::error::{BuildError, BuildWarning, FaceRef};
use super::ids::{FaceId, VertexId};
use super::polygons::Polygons;

/// "No element" in the builder's raw `u32` tables.
pub(crate) const NONE: u32 = u32::MAX;
/// Marks a bucket entry whose half-edge runs from the bucket's vertex upwards.
const FORWARD: u32 = 1 << 31;
/// Half-edge numbers must leave the [`FORWARD`] bit free, and boundary
/// half-edges (at most one per interior one) must stay below [`NONE`].
const MAX_CORNERS: usize = (1 << 31) - 1;

/// How corners are grouped into faces: tells the successor, predecessor and
/// face of an interior half-edge.
pub(crate) trait Layout {
    fn next(&self, h: u32) -> u32;
    fn prev(&self, h: u32) -> u32;
    fn face(&self, h: u32) -> u32;
}

/// Every face is a triangle: the links are arithmetic, with no table.
pub(crate) struct Triangles;

impl Layout for Triangles {
    #[inline]
    fn next(&self, h: u32) -> u32 {
        if h % 3 == 2 { h - 2 } else { h + 1 }
    }
    #[inline]
    fn prev(&self, h: u32) -> u32 {
        if h.is_multiple_of(3) { h + 2 } else { h - 1 }
    }
    #[inline]
    fn face(&self, h: u32) -> u32 {
        h / 3
    }
}

/// Faces of any size: a corner-to-face table plus the face offsets.
pub(crate) struct General<'a> {
    face_of: Vec<u32>,
    offsets: &'a [usize],
}

impl<'a> General<'a> {
    pub(crate) fn new(polygons: &'a Polygons) -> Self {
        let offsets = polygons.offsets();
        let mut face_of = Vec::with_capacity(polygons.corner_count());
        for (face, window) in offsets.windows(2).enumerate() {
            if let &[start, end] = window {
                face_of.extend(std::iter::repeat_n(face as u32, end - start));
            }
        }
        Self { face_of, offsets }
    }

    #[inline]
    fn bounds(&self, h: u32) -> (u32, u32) {
        let face = self.face_of[h as usize] as usize;
        (self.offsets[face] as u32, self.offsets[face + 1] as u32)
    }
}

impl Layout for General<'_> {
    #[inline]
    fn next(&self, h: u32) -> u32 {
        let (start, end) = self.bounds(h);
        if h + 1 == end { start } else { h + 1 }
    }
    #[inline]
    fn prev(&self, h: u32) -> u32 {
        let (start, end) = self.bounds(h);
        if h == start { end - 1 } else { h - 1 }
    }
    #[inline]
    fn face(&self, h: u32) -> u32 {
        self.face_of[h as usize]
    }
}

/// The result of the per-face checks.
pub(crate) struct CheckedFaces {
    /// Corners at each vertex (= interior half-edges leaving it).
    pub valence: Vec<u32>,
    /// Every face has exactly three corners.
    pub triangles: bool,
    /// Unused vertices.
    pub warnings: Vec<BuildWarning>,
}

fn face_ref(polygons: &Polygons, face: usize) -> FaceRef {
    FaceRef {
        face: FaceId::new(face as u32),
        line: polygons.line(face),
    }
}

/// Step 1: refuses faces that are too small, out of range or repeat a
/// vertex, and counts the corners at each vertex.
pub(crate) fn check_faces(polygons: &Polygons) -> Result<CheckedFaces, BuildError> {
    let vertex_count = polygons.vertex_count();
    if vertex_count >= NONE as usize {
        return Err(BuildError::TooLarge {
            element: "vertices",
            count: vertex_count,
            limit: NONE as usize - 1,
        });
    }
    let corners = polygons.corner_count();
    if corners > MAX_CORNERS {
        return Err(BuildError::TooLarge {
            element: "face corners (half-edges)",
            count: corners,
            limit: MAX_CORNERS,
        });
    }
    let indices = polygons.indices();
    let offsets = polygons.offsets();
    let mut valence = vec![0u32; vertex_count];
    // Only faces with many corners use this (last face that used each vertex).
    let mut last_face: Vec<u32> = Vec::new();
    let mut triangles = true;
    for (face, window) in offsets.windows(2).enumerate() {
        let &[start, end] = window else { continue };
        let corners = indices.get(start..end).unwrap_or(&[]);
        triangles &= corners.len() == 3;
        if corners.len() < 3 {
            return Err(BuildError::TooFewVertices {
                face: face_ref(polygons, face),
                count: corners.len(),
            });
        }
        for &v in corners {
            if v as usize >= vertex_count {
                return Err(BuildError::IndexOutOfRange {
                    face: face_ref(polygons, face),
                    index: v,
                    vertex_count,
                });
            }
        }
        let repeated = if corners.len() <= 16 {
            corners
                .iter()
                .enumerate()
                .find_map(|(i, &v)| corners[..i].contains(&v).then_some(v))
        } else {
            if last_face.is_empty() {
                last_face = vec![NONE; vertex_count];
            }
            let mut repeated = None;
            for &v in corners {
                let slot = &mut last_face[v as usize];
                if *slot == face as u32 {
                    repeated = Some(v);
                    break;
                }
                *slot = face as u32;
            }
            repeated
        };
        if let Some(v) = repeated {
            return Err(BuildError::RepeatedVertex {
                face: face_ref(polygons, face),
                vertex: VertexId::new(v),
            });
        }
        for &v in corners {
            valence[v as usize] += 1;
        }
    }
    let warnings = valence
        .iter()
        .enumerate()
        .filter(|&(_, &count)| count == 0)
        .map(|(v, _)| BuildWarning::UnusedVertex {
            vertex: VertexId::new(v as u32),
        })
        .collect();
    Ok(CheckedFaces {
        valence,
        triangles,
        warnings,
    })
}

/// The connectivity both structures are written from.
pub(crate) struct Topology {
    /// Number of interior half-edges (= face corners).
    pub interior: u32,
    /// Pair of each interior half-edge; `interior + i` is boundary half-edge `i`.
    pub pair: Vec<u32>,
    /// The interior pair of each boundary half-edge.
    pub boundary_twin: Vec<u32>,
    /// The successor of each boundary half-edge (a boundary half-edge number).
    pub boundary_next: Vec<u32>,
    /// The lowest-numbered half-edge ending at each vertex, or [`NONE`].
    pub first_incoming: Vec<u32>,
}

/// Steps 2 to 4. `valence` comes from [`check_faces`], which also guarantees
/// every index is in range (so the indexing below cannot fail).
pub(crate) fn topology<L: Layout>(
    polygons: &Polygons,
    layout: &L,
    valence: &[u32],
) -> Result<Topology, BuildError> {
    let indices = polygons.indices();
    let n = indices.len() as u32;
    let vertex_count = valence.len();
    let ends = |h: u32| (indices[h as usize], indices[layout.next(h) as usize]);

    // Step 2: bucket every directed edge under its lower-numbered end.
    let mut cursor = vec![0u32; vertex_count + 1];
    for h in 0..n {
        let (a, b) = ends(h);
        cursor[a.min(b) as usize + 1] += 1;
    }
    for i in 1..cursor.len() {
        cursor[i] += cursor[i - 1];
    }
    // Entry: the upper end in the high half (so sorting groups an edge's uses),
    // the half-edge and its direction in the low half.
    let mut entries = vec![0u64; n as usize];
    for h in 0..n {
        let (a, b) = ends(h);
        let (low, high, tag) = if a < b {
            (a, b, h | FORWARD)
        } else {
            (b, a, h)
        };
        let slot = &mut cursor[low as usize];
        entries[*slot as usize] = (u64::from(high) << 32) | u64::from(tag);
        *slot += 1;
    }
    // Now cursor[v] is the end of bucket v.
    let mut pair = vec![NONE; n as usize];
    let mut start = 0;
    for (low, &end) in cursor.iter().take(vertex_count).enumerate() {
        let bucket = &mut entries[start..end as usize];
        start = end as usize;
        if bucket.len() > 1 {
            bucket.sort_unstable();
        }
        let mut i = 0;
        while i < bucket.len() {
            let high = (bucket[i] >> 32) as u32;
            let mut j = i + 1;
            while j < bucket.len() && (bucket[j] >> 32) as u32 == high {
                j += 1;
            }
            match j - i {
                1 => {}
                2 => {
                    let (x, y) = (bucket[i] as u32, bucket[i + 1] as u32);
                    let (hx, hy) = (x & !FORWARD, y & !FORWARD);
                    if (x ^ y) & FORWARD == 0 {
                        let (from, to) = if x & FORWARD != 0 {
                            (low as u32, high)
                        } else {
                            (high, low as u32)
                        };
                        let (fx, fy) = (layout.face(hx) as usize, layout.face(hy) as usize);
                        return Err(BuildError::InconsistentOrientation {
                            start: VertexId::new(from),
                            end: VertexId::new(to),
                            first: face_ref(polygons, fx.min(fy)),
                            second: face_ref(polygons, fx.max(fy)),
                        });
                    }
                    pair[hx as usize] = hy;
                    pair[hy as usize] = hx;
                }
                _ => {
                    let mut faces: Vec<usize> = bucket[i..j]
                        .iter()
                        .map(|&e| layout.face(e as u32 & !FORWARD) as usize)
                        .collect();
                    faces.sort_unstable();
                    return Err(BuildError::NonManifoldEdge {
                        start: VertexId::new(low as u32),
                        end: VertexId::new(high),
                        faces: faces.into_iter().map(|f| face_ref(polygons, f)).collect(),
                    });
                }
            }
            i = j;
        }
    }
    drop(entries);
    drop(cursor);

    // Step 3: boundary half-edges come after the interior ones, in the order of
    // their interior pair.
    let mut boundary_twin = Vec::new();
    for h in 0..n {
        if pair[h as usize] == NONE {
            pair[h as usize] = n + boundary_twin.len() as u32;
            boundary_twin.push(h);
        }
    }
    // The boundary half-edge paired with h = a→b runs b→a; its successor is the
    // boundary half-edge leaving a, found by turning around a through the fan
    // of h until an unpaired edge. The turn never repeats (h has no pair to come
    // back through), so it ends within valence(a) steps.
    let mut boundary_next = Vec::with_capacity(boundary_twin.len());
    for &h in &boundary_twin {
        let a = indices[h as usize];
        let mut k = layout.prev(h);
        let mut next = NONE;
        for _ in 0..=valence[a as usize] {
            let p = pair[k as usize];
            if p >= n {
                next = p;
                break;
            }
            k = layout.prev(p);
        }
        if next == NONE {
            let face = face_ref(polygons, layout.face(h) as usize);
            return Err(BuildError::NonManifoldVertex {
                vertex: VertexId::new(a),
                first: face,
                second: face,
            });
        }
        boundary_next.push(next);
    }

    let mut first_incoming = vec![NONE; vertex_count];
    for h in 0..n {
        let slot = &mut first_incoming[indices[layout.next(h) as usize] as usize];
        if *slot == NONE {
            *slot = h;
        }
    }

    // Step 4: the paper's loop (successor, then pair) from the first incoming
    // half-edge must meet every corner at the vertex, or the vertex joins
    // several fans.
    let rotate = |h: u32| {
        let s = if h < n {
            layout.next(h)
        } else {
            boundary_next[(h - n) as usize]
        };
        if s < n {
            pair[s as usize]
        } else {
            boundary_twin[(s - n) as usize]
        }
    };
    for (v, (&count, &first)) in valence.iter().zip(&first_incoming).enumerate() {
        if count == 0 {
            continue;
        }
        let mut h = first;
        let mut seen = 0;
        let mut closed = false;
        for _ in 0..=2 * u64::from(count) {
            seen += u32::from(h < n);
            h = rotate(h);
            if h == first {
                closed = true;
                break;
            }
        }
        if !closed || seen != count {
            return Err(fan_error(polygons, layout, v as u32, first, count, &rotate));
        }
    }

    Ok(Topology {
        interior: n,
        pair,
        boundary_twin,
        boundary_next,
        first_incoming,
    })
}

/// Names a face of the fan reached from `first` and a face of another fan.
fn fan_error<L: Layout>(
    polygons: &Polygons,
    layout: &L,
    v: u32,
    first: u32,
    count: u32,
    rotate: &impl Fn(u32) -> u32,
) -> BuildError {
    let n = polygons.corner_count() as u32;
    let mut fan = Vec::new();
    let mut h = first;
    for _ in 0..=2 * u64::from(count) {
        if h < n {
            fan.push(layout.face(h));
        }
        h = rotate(h);
        if h == first {
            break;
        }
    }
    let indices = polygons.indices();
    let other = (0..n)
        .filter(|&h| indices[h as usize] == v)
        .map(|h| layout.face(h))
        .find(|face| !fan.contains(face));
    let first_face = layout.face(first);
    BuildError::NonManifoldVertex {
        vertex: VertexId::new(v),
        first: face_ref(polygons, first_face as usize),
        second: face_ref(polygons, other.unwrap_or(first_face) as usize),
    }
}
