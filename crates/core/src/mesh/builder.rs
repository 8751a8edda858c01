//! Topology construction shared by both structures, with the refusal checks.
//!
//! [`build`] drives the same steps for both structures, all linear and
//! without hashing; an [`Assembly`] supplies what differs (the rows written,
//! where pairs go, how to turn around a vertex, the final tables):
//!
//! 1. check every face (size, index range, repeated vertices), count the
//!    corners at each vertex, and write the per-corner data;
//! 2. bucket the directed edges by their lower-numbered end (a chain per
//!    vertex, threaded through the not-yet-used pair fields), so each bucket
//!    holds every use of the edges at that vertex; sorting a bucket puts the
//!    uses of one edge side by side, which finds pairs, non-manifold edges and
//!    orientation conflicts in one scan;
//! 3. number the boundary half-edges and link them along the boundary loops;
//! 4. walk once around every vertex to find non-manifold vertices ([`build`]
//!    then splits them in the polygon list and builds again, see `repair`);
//! 5. finish the structure's tables.
//!
//! Interior half-edge `h` is corner `h` of the flat polygon list, so its start
//! vertex is `indices[h]`. The half-edge build writes its rows in the first
//! pass and pairs straight into them; besides the rows it holds only a few
//! per-vertex tables, so the peak stays near the final size.
//!
//! The browser's build optimises for size, and there LLVM leaves `Vec`
//! indexing and `push`, closures and small trait methods as calls. So the
//! hot loops index slices of tables sized up front, and the hooks called per
//! corner or per step ([`Assembly`], [`Layout`], [`Pairs`]) are
//! `#[inline(always)]`: that made the wasm32 half-edge build three times
//! faster (docs/performance.md).

use super::error::{BuildError, BuildWarning, FaceRef};
use super::ids::{FaceId, VertexId};
use super::polygons::Polygons;

mod repair;

/// "No element" in the builder's raw `u32` tables.
pub(crate) const NONE: u32 = u32::MAX;
/// An interior half-edge whose pair is not known yet. Unlike [`NONE`] it is a
/// value a typed id can hold, so half-edge rows can carry it during the build.
pub(crate) const UNPAIRED: u32 = u32::MAX - 1;
/// Marks a bucket entry whose half-edge runs from the bucket's vertex upwards.
const FORWARD: u32 = 1 << 31;
/// Ends a bucket chain (with or without the [`FORWARD`] bit, a value typed ids
/// can hold and no half-edge has).
const CHAIN_END: u32 = FORWARD - 2;
/// Buckets of [`pair_up`] up to this size are gathered on the stack.
const SMALL_BUCKET: usize = 16;
/// Half-edge numbers must stay below [`CHAIN_END`] and leave the [`FORWARD`]
/// bit free; boundary half-edges (at most one per interior one) then stay
/// below [`UNPAIRED`].
const MAX_CORNERS: usize = CHAIN_END as usize;

/// What one structure's build records and makes; [`build`] calls these hooks
/// in step order, so numbering, refusals and warnings are the same for both.
pub(crate) trait Assembly: Sized {
    /// The structure built.
    type Mesh;
    /// Where steps 2 and 3 write each interior half-edge's pair.
    type Pairs: Pairs + ?Sized;

    /// Tables for `polygons`, which are not checked yet: sizes only, with a
    /// row for every corner.
    fn new(polygons: &Polygons) -> Self;

    /// Step 1, for interior half-edge `h` ending at vertex `end` (in range)
    /// in `face`, called for `h = 0, 1, 2, ...` in turn: records it, storing
    /// `link` as its pair (see [`scan_faces`]). `#[inline(always)]`, as are
    /// the other hooks called per corner or per step (see the module notes).
    fn corner<L: Layout>(&mut self, layout: &L, h: u32, end: u32, face: u32, link: u32);

    /// The pair storage, filled by [`corner`](Self::corner).
    fn pairs(&mut self) -> &mut Self::Pairs;

    /// After step 3: records the boundary half-edges if the structure keeps
    /// rows for them.
    fn boundary(&mut self, indices: &[u32], boundary: &Boundary);

    /// The lowest-numbered half-edge ending at used vertex `v`.
    fn first_incoming(&self, v: usize) -> u32;

    /// One step of the paper's loop (successor, then pair) from half-edge
    /// `h`, interior or boundary, once every pair and boundary link is known.
    fn around<L: Layout>(&self, layout: &L, boundary: &Boundary, h: u32) -> u32;

    /// Step 5: the structure's tables, once every check has passed.
    fn finish<L: Layout>(self, polygons: &Polygons, layout: &L, boundary: Boundary) -> Self::Mesh;
}

/// Builds structure `A` from counter-clockwise polygons: refuses what the
/// steps refuse and, if only a vertex joining separate fans stands in the
/// way, splits it and builds again (see `repair`).
pub(crate) fn build<A: Assembly>(
    polygons: &Polygons,
) -> Result<(A::Mesh, Vec<BuildWarning>), BuildError> {
    repair::build_splitting_fans(polygons, |polygons| {
        if all_triangles(polygons) {
            assemble::<A, _>(polygons, &Triangles, true)
        } else {
            assemble::<A, _>(polygons, &General::new(polygons), false)
        }
    })
}

/// Steps 1 to 5 on the polygons as given; `triangles` must say whether
/// `layout` is [`Triangles`].
fn assemble<A: Assembly, L: Layout>(
    polygons: &Polygons,
    layout: &L,
    triangles: bool,
) -> Result<(A::Mesh, Vec<BuildWarning>), BuildError> {
    let mut assembly = A::new(polygons);
    let Scanned {
        valence,
        heads,
        warnings,
    } = scan_faces(polygons, layout, triangles, &mut assembly)?;
    let unpaired = pair_up(polygons, layout, &heads, assembly.pairs())?;
    drop(heads);
    let boundary = link_boundary(polygons, layout, &valence, unpaired, assembly.pairs())?;
    assembly.boundary(polygons.indices(), &boundary);
    check_fans(polygons, layout, &valence, &boundary, &assembly)?;
    drop(valence);
    Ok((assembly.finish(polygons, layout, boundary), warnings))
}

/// How corners are grouped into faces: tells the successor, predecessor and
/// face of an interior half-edge.
pub(crate) trait Layout {
    fn next(&self, h: u32) -> u32;
    fn prev(&self, h: u32) -> u32;
    fn face(&self, h: u32) -> u32;
}

/// Every face is a triangle: the links are arithmetic, with no table.
struct Triangles;

impl Layout for Triangles {
    #[inline(always)]
    fn next(&self, h: u32) -> u32 {
        if h % 3 == 2 { h - 2 } else { h + 1 }
    }
    #[inline(always)]
    fn prev(&self, h: u32) -> u32 {
        if h.is_multiple_of(3) { h + 2 } else { h - 1 }
    }
    #[inline(always)]
    fn face(&self, h: u32) -> u32 {
        h / 3
    }
}

/// Faces of any size: a corner-to-face table plus the face offsets.
pub(crate) struct General<'a> {
    /// A boxed slice, whose indexing is inline where a `Vec`'s is a call
    /// (see the module notes).
    face_of: Box<[u32]>,
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
        Self {
            face_of: face_of.into_boxed_slice(),
            offsets,
        }
    }

    #[inline(always)]
    fn bounds(&self, h: u32) -> (u32, u32) {
        let face = self.face_of[h as usize] as usize;
        (self.offsets[face] as u32, self.offsets[face + 1] as u32)
    }
}

impl Layout for General<'_> {
    #[inline(always)]
    fn next(&self, h: u32) -> u32 {
        let (start, end) = self.bounds(h);
        if h + 1 == end { start } else { h + 1 }
    }
    #[inline(always)]
    fn prev(&self, h: u32) -> u32 {
        let (start, end) = self.bounds(h);
        if h == start { end - 1 } else { h - 1 }
    }
    #[inline(always)]
    fn face(&self, h: u32) -> u32 {
        self.face_of[h as usize]
    }
}

/// Where the pairing step writes pairs: the half-edge rows themselves for a
/// half-edge build, a plain table for a winged-edge build.
pub(crate) trait Pairs {
    fn pair(&self, h: u32) -> u32;
    fn set_pair(&mut self, h: u32, pair: u32);
    /// The end vertex (`forward`) or start vertex of interior half-edge `h`,
    /// read from wherever is cheapest.
    fn end_or_start<L: Layout>(&self, layout: &L, indices: &[u32], h: u32, forward: bool) -> u32;
}

impl Pairs for [u32] {
    #[inline(always)]
    fn pair(&self, h: u32) -> u32 {
        self[h as usize]
    }
    #[inline(always)]
    fn set_pair(&mut self, h: u32, pair: u32) {
        self[h as usize] = pair;
    }
    #[inline(always)]
    fn end_or_start<L: Layout>(&self, layout: &L, indices: &[u32], h: u32, forward: bool) -> u32 {
        indices[if forward { layout.next(h) } else { h } as usize]
    }
}

/// The result of the face scan.
struct Scanned {
    /// Corners at each vertex (= interior half-edges leaving it).
    valence: Vec<u32>,
    /// The head of each vertex's bucket chain (see [`scan_faces`]).
    heads: Vec<u32>,
    /// Unused vertices.
    warnings: Vec<BuildWarning>,
}

fn face_ref(polygons: &Polygons, face: usize) -> FaceRef {
    FaceRef {
        face: FaceId::new(face as u32),
        line: polygons.line(face),
    }
}

/// Whether every face has exactly three corners (then [`Triangles`] applies).
fn all_triangles(polygons: &Polygons) -> bool {
    polygons.corner_count() == 3 * polygons.face_count()
        && polygons
            .offsets()
            .iter()
            .enumerate()
            .all(|(face, &start)| start == 3 * face)
}

/// Step 1, in one pass over the faces: refuses faces that are too small, out
/// of range or repeat a vertex, counts the corners at each vertex, and hands
/// every interior half-edge `h = a→b` of face `f` to
/// [`Assembly::corner`]`(h, b, f, link)`.
///
/// `link` threads the half-edges into one chain per bucket (the edges whose
/// lower-numbered end is the same vertex): the caller stores it as the
/// half-edge's pair until [`pair_up`] replaces it, so the buckets need no
/// table of their own. It is the next half-edge of the chain (or
/// [`CHAIN_END`]) plus the [`FORWARD`] bit when `a < b`.
fn scan_faces<A: Assembly, L: Layout>(
    polygons: &Polygons,
    layout: &L,
    triangles: bool,
    assembly: &mut A,
) -> Result<Scanned, BuildError> {
    let vertex_count = polygons.vertex_count();
    if vertex_count >= UNPAIRED as usize {
        return Err(BuildError::TooLarge {
            element: "vertices",
            count: vertex_count,
            limit: UNPAIRED as usize - 1,
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
    let mut valence_table = vec![0u32; vertex_count];
    let mut heads_table = vec![CHAIN_END; vertex_count];
    // Slices in the hot loop (see the module notes).
    let (valence, heads) = (&mut valence_table[..], &mut heads_table[..]);
    if triangles {
        for (face, corners) in (0u32..).zip(indices.chunks_exact(3)) {
            let &[a, b, c] = corners else { continue };
            if a.max(b).max(c) as usize >= vertex_count {
                let index = [a, b, c]
                    .into_iter()
                    .find(|&v| v as usize >= vertex_count)
                    .unwrap_or(a);
                return Err(BuildError::IndexOutOfRange {
                    face: face_ref(polygons, face as usize),
                    index,
                    vertex_count,
                });
            }
            if a == b || a == c || b == c {
                let vertex = VertexId::new(if a == b || a == c { a } else { b });
                return Err(BuildError::RepeatedVertex {
                    face: face_ref(polygons, face as usize),
                    vertex,
                });
            }
            valence[a as usize] += 1;
            valence[b as usize] += 1;
            valence[c as usize] += 1;
            let h = 3 * face;
            assembly.corner(layout, h, b, face, chain(heads, h, a, b));
            assembly.corner(layout, h + 1, c, face, chain(heads, h + 1, b, c));
            assembly.corner(layout, h + 2, a, face, chain(heads, h + 2, c, a));
        }
    } else {
        // Only faces with many corners use this (last face that used each vertex).
        let mut last_face: Vec<u32> = Vec::new();
        for (face, window) in polygons.offsets().windows(2).enumerate() {
            let &[start, end] = window else { continue };
            let corners = indices.get(start..end).unwrap_or(&[]);
            if corners.len() < 3 {
                return Err(BuildError::TooFewVertices {
                    face: face_ref(polygons, face),
                    count: corners.len(),
                });
            }
            if let Some(&index) = corners.iter().find(|&&v| v as usize >= vertex_count) {
                return Err(BuildError::IndexOutOfRange {
                    face: face_ref(polygons, face),
                    index,
                    vertex_count,
                });
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
                corners.iter().copied().find(|&v| {
                    let slot = &mut last_face[v as usize];
                    let seen = *slot == face as u32;
                    *slot = face as u32;
                    seen
                })
            };
            if let Some(v) = repeated {
                return Err(BuildError::RepeatedVertex {
                    face: face_ref(polygons, face),
                    vertex: VertexId::new(v),
                });
            }
            for (k, &a) in corners.iter().enumerate() {
                valence[a as usize] += 1;
                let b = corners.get(k + 1).copied().unwrap_or(corners[0]);
                let h = (start + k) as u32;
                assembly.corner(layout, h, b, face as u32, chain(heads, h, a, b));
            }
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
    Ok(Scanned {
        valence: valence_table,
        heads: heads_table,
        warnings,
    })
}

/// Threads half-edge `h = a→b` onto the bucket chain of `min(a, b)`, and
/// returns its link (see [`scan_faces`]).
#[inline(always)]
fn chain(heads: &mut [u32], h: u32, a: u32, b: u32) -> u32 {
    let head = &mut heads[a.min(b) as usize];
    let link = *head | if a < b { FORWARD } else { 0 };
    *head = h;
    link
}

/// Step 2: pairs every interior half-edge, refusing edges with more than two
/// faces or two faces running the same way. Each bucket chain (see
/// [`scan_faces`]) is gathered and sorted by upper end, which puts the uses of
/// one edge side by side. Replaces every link with the pair, or [`UNPAIRED`];
/// returns the unpaired half-edges in increasing order.
fn pair_up<L: Layout>(
    polygons: &Polygons,
    layout: &L,
    heads: &[u32],
    pairs: &mut (impl Pairs + ?Sized),
) -> Result<Vec<u32>, BuildError> {
    let indices = polygons.indices();
    let mut unpaired = Vec::new();
    // Entry: the upper end in the high half, the half-edge and its direction
    // in the low half. A bucket is gathered on the stack while it is small
    // (most hold about three entries), so no `push` is called per entry.
    let mut small = [0u64; SMALL_BUCKET];
    let mut large: Vec<u64> = Vec::new();
    for (low, &head) in (0u32..).zip(heads) {
        let mut len = 0;
        let mut h = head;
        while h != CHAIN_END {
            let link = pairs.pair(h);
            let forward = link & FORWARD;
            let high = pairs.end_or_start(layout, indices, h, forward != 0);
            let entry = (u64::from(high) << 32) | u64::from(h | forward);
            if len < SMALL_BUCKET {
                small[len] = entry;
            } else {
                if len == SMALL_BUCKET {
                    large.clear();
                    large.extend_from_slice(&small);
                }
                large.push(entry);
            }
            len += 1;
            h = link & !FORWARD;
        }
        let bucket = if len <= SMALL_BUCKET {
            &mut small[..len]
        } else {
            &mut large[..]
        };
        if len <= SMALL_BUCKET {
            insertion_sort(bucket);
        } else {
            bucket.sort_unstable();
        }
        let bucket = &*bucket;
        let mut i = 0;
        while i < bucket.len() {
            let high = (bucket[i] >> 32) as u32;
            let mut j = i + 1;
            while j < bucket.len() && (bucket[j] >> 32) as u32 == high {
                j += 1;
            }
            match j - i {
                1 => {
                    let h = bucket[i] as u32 & !FORWARD;
                    pairs.set_pair(h, UNPAIRED);
                    unpaired.push(h);
                }
                2 => {
                    let (x, y) = (bucket[i] as u32, bucket[i + 1] as u32);
                    let (hx, hy) = (x & !FORWARD, y & !FORWARD);
                    if (x ^ y) & FORWARD == 0 {
                        let (from, to) = if x & FORWARD != 0 {
                            (low, high)
                        } else {
                            (high, low)
                        };
                        let (fx, fy) = (layout.face(hx) as usize, layout.face(hy) as usize);
                        return Err(BuildError::InconsistentOrientation {
                            start: VertexId::new(from),
                            end: VertexId::new(to),
                            first: face_ref(polygons, fx.min(fy)),
                            second: face_ref(polygons, fx.max(fy)),
                        });
                    }
                    pairs.set_pair(hx, hy);
                    pairs.set_pair(hy, hx);
                }
                _ => {
                    let mut faces: Vec<usize> = bucket[i..j]
                        .iter()
                        .map(|&e| layout.face(e as u32 & !FORWARD) as usize)
                        .collect();
                    faces.sort_unstable();
                    return Err(BuildError::NonManifoldEdge {
                        start: VertexId::new(low),
                        end: VertexId::new(high),
                        faces: faces.into_iter().map(|f| face_ref(polygons, f)).collect(),
                    });
                }
            }
            i = j;
        }
    }
    unpaired.sort_unstable();
    Ok(unpaired)
}

/// Sorts a small bucket in place, with no call (see [`SMALL_BUCKET`]).
#[inline(always)]
fn insertion_sort(bucket: &mut [u64]) {
    for i in 1..bucket.len() {
        let entry = bucket[i];
        let mut j = i;
        while j > 0 && bucket[j - 1] > entry {
            bucket[j] = bucket[j - 1];
            j -= 1;
        }
        bucket[j] = entry;
    }
}

/// The boundary half-edges: boundary half-edge `i` is number `n + i`.
pub(crate) struct Boundary {
    /// The interior pair of each boundary half-edge.
    pub twin: Vec<u32>,
    /// The successor of each boundary half-edge (a boundary half-edge number).
    pub next: Vec<u32>,
}

/// Step 3: numbers the boundary half-edges after the interior ones, in the
/// order of their interior pair, records them as those pairs' pairs, and
/// links them along the boundary loops.
fn link_boundary<L: Layout>(
    polygons: &Polygons,
    layout: &L,
    valence: &[u32],
    twin: Vec<u32>,
    pairs: &mut (impl Pairs + ?Sized),
) -> Result<Boundary, BuildError> {
    let indices = polygons.indices();
    let n = indices.len() as u32;
    for (b, &h) in (n..).zip(&twin) {
        pairs.set_pair(h, b);
    }
    // The boundary half-edge paired with h = a→b runs b→a; its successor is the
    // boundary half-edge leaving a, found by turning around a through the fan
    // of h until an unpaired edge. The turn never repeats (h has no pair to come
    // back through), so it ends within valence(a) steps.
    let mut next = Vec::with_capacity(twin.len());
    for &h in &twin {
        let a = indices[h as usize];
        let mut k = layout.prev(h);
        let mut found = NONE;
        for _ in 0..=valence[a as usize] {
            let p = pairs.pair(k);
            if p >= n {
                found = p;
                break;
            }
            k = layout.prev(p);
        }
        if found == NONE {
            let face = face_ref(polygons, layout.face(h) as usize);
            return Err(BuildError::NonManifoldVertex {
                vertex: VertexId::new(a),
                first: face,
                second: face,
            });
        }
        next.push(found);
    }
    Ok(Boundary { twin, next })
}

/// Step 4: the paper's loop (successor, then pair) from the first half-edge
/// ending at each vertex must meet every corner at the vertex, or the vertex
/// joins several fans.
fn check_fans<A: Assembly, L: Layout>(
    polygons: &Polygons,
    layout: &L,
    valence: &[u32],
    boundary: &Boundary,
    assembly: &A,
) -> Result<(), BuildError> {
    let n = polygons.corner_count() as u32;
    for (v, &count) in valence.iter().enumerate() {
        if count == 0 {
            continue;
        }
        let first = assembly.first_incoming(v);
        let mut h = first;
        let mut seen = 0;
        let mut closed = false;
        // At most 2 × count + 1 steps: a fan meets each corner once, and
        // a boundary half-edge between corners.
        let mut steps = 2 * u64::from(count) + 1;
        while steps > 0 {
            seen += u32::from(h < n);
            h = assembly.around(layout, boundary, h);
            if h == first {
                closed = true;
                break;
            }
            steps -= 1;
        }
        if !closed || seen != count {
            let rotate = |h| assembly.around(layout, boundary, h);
            return Err(fan_error(polygons, layout, v as u32, first, count, &rotate));
        }
    }
    Ok(())
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
    let first_face = if first < n { layout.face(first) } else { 0 };
    BuildError::NonManifoldVertex {
        vertex: VertexId::new(v),
        first: face_ref(polygons, first_face as usize),
        second: face_ref(polygons, other.unwrap_or(first_face) as usize),
    }
}
