//! The winged-edge structure (Neperud and Shene, section 2, Tables 1 and 2).
//!
//! Faces are traversed clockwise seen from outside: the right face traverses
//! an edge from start to end, the left face from end to start, and each wing
//! (predecessor, successor) is relative to that clockwise traversal. So a face
//! listed counter-clockwise with consecutive vertices `a, b` is the LEFT face
//! of edge `a→b`; its left predecessor is the edge after `b` in the listing
//! and its left successor the edge before `a`.

use glam::Vec3;

use super::builder::{self, Boundary, Layout, NONE};
use super::deleted::Deleted;
use super::error::{BuildError, BuildWarning};
use super::ids::{EdgeId, FaceId, VertexId};
use super::polygons::Polygons;
use super::tables::tables;

/// A row of the winged-edge vertex table.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Vertex {
    /// Where the vertex is.
    pub position: Vec3,
    /// An edge that starts or ends here (`None` for an isolated vertex).
    pub incident_edge: Option<EdgeId>,
}

impl Vertex {
    /// The vertex table from each vertex's position and incident edge
    /// (`NONE` for an isolated vertex), as the build and the conversion from
    /// half-edges find them. Written into rows sized up front, as in the
    /// builder (see its module notes).
    pub(crate) fn rows(positions: impl IntoIterator<Item = Vec3>, incident: &[u32]) -> Vec<Self> {
        let mut rows = vec![Self::default(); incident.len()];
        for ((row, position), &e) in rows.iter_mut().zip(positions).zip(incident) {
            row.position = position;
            row.incident_edge = (e != NONE).then_some(EdgeId::new(e));
        }
        rows
    }
}

/// A row of the winged-edge face table.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Face {
    /// One of the face's edges.
    pub incident_edge: EdgeId,
}

/// A row of the winged-edge edge table: the nine pieces of Table 1 (the name
/// is the row number).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct WingedEdge {
    /// Where the edge starts (the direction of its first appearance).
    pub start_vertex: VertexId,
    /// Where it ends.
    pub end_vertex: VertexId,
    /// The face that traverses it from end to start clockwise (`None` on the
    /// boundary).
    pub left_face: Option<FaceId>,
    /// The face that traverses it from start to end clockwise (`None` on the
    /// boundary).
    pub right_face: Option<FaceId>,
    /// The edge before this one in the clockwise traversal of the left face.
    pub left_predecessor: EdgeId,
    /// The edge after this one in the clockwise traversal of the left face.
    pub left_successor: EdgeId,
    /// The edge before this one in the clockwise traversal of the right face.
    pub right_predecessor: EdgeId,
    /// The edge after this one in the clockwise traversal of the right face.
    pub right_successor: EdgeId,
}

/// A winged-edge mesh: the vertex, edge and face tables.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct WingedEdgeMesh {
    pub(crate) vertices: Vec<Vertex>,
    pub(crate) faces: Vec<Face>,
    pub(crate) edges: Vec<WingedEdge>,
    /// Rows an edit deleted, kept as gaps until the ids are compacted.
    pub(crate) deleted: Deleted,
}

/// The winged-edge build's tables until the edges are numbered: the pair of
/// each interior half-edge, and the lowest-numbered one ending at each vertex.
struct WingedEdgeAssembly {
    pair: Vec<u32>,
    first_incoming: Vec<u32>,
}

impl builder::Assembly for WingedEdgeAssembly {
    type Mesh = WingedEdgeMesh;
    type Pairs = [u32];

    fn new(polygons: &Polygons) -> Self {
        Self {
            pair: vec![0; polygons.corner_count()],
            first_incoming: vec![NONE; polygons.vertex_count()],
        }
    }

    #[inline(always)]
    fn corner<L: Layout>(&mut self, _: &L, h: u32, end: u32, _: u32, link: u32) {
        let pair: &mut [u32] = &mut self.pair;
        pair[h as usize] = link;
        let first_incoming: &mut [u32] = &mut self.first_incoming;
        let slot = &mut first_incoming[end as usize];
        if *slot == NONE {
            *slot = h;
        }
    }

    fn pairs(&mut self) -> &mut [u32] {
        &mut self.pair
    }

    /// Boundary half-edges get no rows: their links stay in `boundary`.
    fn boundary(&mut self, _: &[u32], _: &Boundary) {}

    #[inline(always)]
    fn first_incoming(&self, v: usize) -> u32 {
        let first_incoming: &[u32] = &self.first_incoming;
        first_incoming[v]
    }

    /// Half-edge `h` is interior below `n`, the number of corners (one pair
    /// entry each), and boundary half-edge `h - n` from there on.
    #[inline(always)]
    fn around<L: Layout>(&self, layout: &L, boundary: &Boundary, h: u32) -> u32 {
        let pair: &[u32] = &self.pair;
        let n = pair.len() as u32;
        let s = if h < n {
            layout.next(h)
        } else {
            let next: &[u32] = &boundary.next;
            next[(h - n) as usize]
        };
        if s < n {
            pair[s as usize]
        } else {
            let twin: &[u32] = &boundary.twin;
            twin[(s - n) as usize]
        }
    }

    /// Numbers the edges and writes the three tables.
    fn finish<L: Layout>(
        self,
        polygons: &Polygons,
        layout: &L,
        boundary: Boundary,
    ) -> WingedEdgeMesh {
        let Self {
            pair,
            first_incoming,
        } = self;
        let indices = polygons.indices();
        let n = indices.len() as u32;
        let Boundary {
            twin: boundary_twin,
            next: boundary_next,
        } = boundary;
        // Number the edges in place: an interior half-edge whose pair comes later
        // (or is a boundary half-edge) is the first appearance of its edge.
        // Slices of tables sized up front in the loops over half-edges and
        // edges, as in the builder (see its module notes).
        let mut edge_of_table = pair;
        let edge_of = &mut edge_of_table[..];
        let mut edge_count = 0u32;
        for h in 0..edge_of.len() {
            let p = edge_of[h];
            edge_of[h] = if p as usize > h {
                edge_count += 1;
                edge_count - 1
            } else {
                edge_of[p as usize]
            };
        }
        // A vertex's lowest-numbered edge is that of its lowest-numbered
        // half-edge, which is in the first face to use it: the one ending
        // there, or the one leaving. Written over the first incoming
        // half-edges before the rows are allocated, so the peak stays that of
        // the rows and the edge numbers.
        let mut incident_table = first_incoming;
        for h in &mut incident_table[..] {
            if *h != NONE {
                *h = edge_of[*h as usize].min(edge_of[layout.next(*h) as usize]);
            }
        }
        let mut edges_table = vec![WingedEdge::default(); edge_count as usize];
        let edges = &mut edges_table[..];
        // Edges are numbered in order of first appearance.
        let mut new_edge = 0;
        for (h, &e) in (0..n).zip(&*edge_of) {
            let next = layout.next(h);
            let face = Some(FaceId::new(layout.face(h)));
            // Counter-clockwise next is the clockwise predecessor, and back.
            let predecessor = EdgeId::new(edge_of[next as usize]);
            let successor = EdgeId::new(edge_of[layout.prev(h) as usize]);
            let edge = &mut edges[e as usize];
            if e == new_edge {
                new_edge += 1;
                *edge = WingedEdge {
                    start_vertex: VertexId::new(indices[h as usize]),
                    end_vertex: VertexId::new(indices[next as usize]),
                    left_face: face,
                    right_face: None,
                    left_predecessor: predecessor,
                    left_successor: successor,
                    right_predecessor: EdgeId::new(e),
                    right_successor: EdgeId::new(e),
                };
            } else {
                edge.right_face = face;
                edge.right_predecessor = predecessor;
                edge.right_successor = successor;
            }
        }
        // Boundary edges: their right side is the boundary loop.
        for (&twin, &next) in boundary_twin.iter().zip(&boundary_next) {
            let e = edge_of[twin as usize];
            let next_twin = boundary_twin
                .get((next - n) as usize)
                .copied()
                .unwrap_or(twin);
            let next_edge = edge_of[next_twin as usize];
            if let Some(edge) = edges.get_mut(e as usize) {
                edge.right_predecessor = EdgeId::new(next_edge);
            }
            if let Some(edge) = edges.get_mut(next_edge as usize) {
                edge.right_successor = EdgeId::new(e);
            }
        }
        // Each face's lowest-numbered edge, in a plain loop: the
        // size-optimised build called `Iterator::min` once per face.
        let offsets = polygons.offsets();
        let mut faces = vec![Face::default(); polygons.face_count()];
        for (face, row) in faces.iter_mut().enumerate() {
            let (start, end) = (offsets[face], offsets[face + 1]);
            let mut lowest = edge_of[start];
            for &e in &edge_of[start + 1..end] {
                lowest = lowest.min(e);
            }
            row.incident_edge = EdgeId::new(lowest);
        }
        drop(edge_of_table);
        let vertices = Vertex::rows(polygons.positions().iter().copied(), &incident_table);
        WingedEdgeMesh::from_raw_parts(vertices, faces, edges_table)
    }
}

impl WingedEdgeMesh {
    /// Builds the structure from counter-clockwise polygons, with the same
    /// refusals, vertex splits and warnings as
    /// [`HalfEdgeMesh::build`](super::HalfEdgeMesh::build): one driver builds
    /// both.
    ///
    /// Vertices and faces keep their numbers; edges are numbered in order of
    /// first appearance walking the faces in order and point the way they
    /// first appear (so their first face is their left face). Incident edges
    /// are the lowest-numbered candidates. Missing faces on the boundary are
    /// `None`, and the wings on that side link along the boundary loop.
    ///
    /// ```
    /// use edgewise_core::mesh::{EdgeId, FaceId, Polygons, VertexId, WingedEdgeMesh};
    /// use glam::Vec3;
    ///
    /// let positions = vec![Vec3::ZERO, Vec3::X, Vec3::Y];
    /// let (mesh, _) = WingedEdgeMesh::build(&Polygons::from_triangles(positions, &[[0, 1, 2]]))?;
    /// let edge = mesh.edge(EdgeId::new(0)).expect("three edges");
    /// assert_eq!((edge.start_vertex, edge.end_vertex), (VertexId::new(0), VertexId::new(1)));
    /// assert_eq!((edge.left_face, edge.right_face), (Some(FaceId::new(0)), None));
    /// assert_eq!(edge.left_predecessor, EdgeId::new(1)); // 1→2 comes before 0→1 clockwise
    /// # Ok::<(), edgewise_core::mesh::BuildError>(())
    /// ```
    pub fn build(polygons: &Polygons) -> Result<(Self, Vec<BuildWarning>), BuildError> {
        builder::build::<WingedEdgeAssembly>(polygons)
    }

    /// Takes the three tables as written (for example from a `.wtb` file)
    /// without checking them; call [`Self::validate`] to find what is wrong.
    /// Every accessor and iterator stays panic-free and terminates on broken
    /// tables.
    pub fn from_raw_parts(vertices: Vec<Vertex>, faces: Vec<Face>, edges: Vec<WingedEdge>) -> Self {
        Self {
            vertices,
            faces,
            edges,
            deleted: Deleted::default(),
        }
    }

    tables!(Vertex, Face, edges: WingedEdge, "edge", edge(EdgeId), edge_count);
}

/// One side of a winged edge: the left face's or the right face's.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Side {
    /// The left face traverses the edge from end to start (clockwise).
    Left,
    /// The right face traverses the edge from start to end (clockwise).
    Right,
}

impl Side {
    /// The other side.
    pub fn opposite(self) -> Self {
        match self {
            Self::Left => Self::Right,
            Self::Right => Self::Left,
        }
    }
}

impl WingedEdge {
    /// The face on `side` (`None` on the boundary).
    #[inline]
    pub fn face(&self, side: Side) -> Option<FaceId> {
        match side {
            Side::Left => self.left_face,
            Side::Right => self.right_face,
        }
    }

    /// The predecessor wing on `side`: the next edge counter-clockwise around
    /// that face.
    #[inline]
    pub fn predecessor(&self, side: Side) -> EdgeId {
        match side {
            Side::Left => self.left_predecessor,
            Side::Right => self.right_predecessor,
        }
    }

    /// The successor wing on `side`: the previous edge counter-clockwise.
    #[inline]
    pub fn successor(&self, side: Side) -> EdgeId {
        match side {
            Side::Left => self.left_successor,
            Side::Right => self.right_successor,
        }
    }

    /// Which side `face` is on (`None` asks for the boundary side); the left
    /// side wins if both match.
    #[inline]
    pub fn side_of(&self, face: Option<FaceId>) -> Option<Side> {
        if self.left_face == face {
            Some(Side::Left)
        } else if self.right_face == face {
            Some(Side::Right)
        } else {
            None
        }
    }

    /// The side bordering `face` whose counter-clockwise traversal enters
    /// this edge at `vertex`. An edge with the same face on both sides (a
    /// dangling edge, or a bridge to an inner cycle) is walked once each way
    /// by that face, so the face alone cannot say which side a walk is on;
    /// the vertex it arrives at can. When only one side borders `face` that
    /// side is returned whatever the vertex, so a broken wing is still
    /// followed and reported.
    #[inline]
    pub fn side_entered_at(&self, face: Option<FaceId>, vertex: VertexId) -> Option<Side> {
        self.side_where(face, |side| self.ccw_start(side) == vertex)
    }

    /// The side bordering `face` whose counter-clockwise traversal leaves
    /// this edge at `vertex`: [`Self::side_entered_at`] walking backwards.
    #[inline]
    pub fn side_left_at(&self, face: Option<FaceId>, vertex: VertexId) -> Option<Side> {
        self.side_where(face, |side| self.ccw_end(side) == vertex)
    }

    fn side_where(&self, face: Option<FaceId>, matches: impl Fn(Side) -> bool) -> Option<Side> {
        if self.left_face == face && self.right_face == face && matches(Side::Right) {
            Some(Side::Right)
        } else {
            self.side_of(face)
        }
    }

    /// Where the counter-clockwise traversal of the face on `side` enters
    /// this edge (the start for the left face, the end for the right face).
    #[inline]
    pub fn ccw_start(&self, side: Side) -> VertexId {
        match side {
            Side::Left => self.start_vertex,
            Side::Right => self.end_vertex,
        }
    }

    /// Where the counter-clockwise traversal of the face on `side` leaves
    /// this edge.
    #[inline]
    pub fn ccw_end(&self, side: Side) -> VertexId {
        self.ccw_start(side.opposite())
    }

    /// The other end of the edge from `v` (`None` if `v` is not an end).
    #[inline]
    pub fn other_vertex(&self, v: VertexId) -> Option<VertexId> {
        if self.start_vertex == v {
            Some(self.end_vertex)
        } else if self.end_vertex == v {
            Some(self.start_vertex)
        } else {
            None
        }
    }
}
