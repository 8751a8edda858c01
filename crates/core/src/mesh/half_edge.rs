//! The half-edge structure (Neperud, section 2.2): every edge is a pair of
//! half-edges, each storing its end vertex, adjacent face, pair edge and
//! successor edge (the next half-edge counter-clockwise around its face).

use std::sync::OnceLock;

use glam::Vec3;

use super::builder::{self, Boundary, Layout, NONE, Pairs};
use super::deleted::Deleted;
use super::error::{BuildError, BuildWarning};
use super::ids::{FaceId, HalfEdgeId, VertexId};
use super::polygons::Polygons;
use super::tables::tables;

/// A row of the half-edge vertex table.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Vertex {
    /// Where the vertex is.
    pub position: Vec3,
    /// A half-edge that ENDS at this vertex, so the paper's loop
    /// (`e := e.successorEdge; e := e.pairEdge`) circles it. `None` for an
    /// isolated vertex.
    pub incident_edge: Option<HalfEdgeId>,
}

/// A row of the half-edge face table.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Face {
    /// One of the face's half-edges.
    pub incident_edge: HalfEdgeId,
}

/// A row of the half-edge table.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct HalfEdge {
    /// The vertex this half-edge points to.
    pub end_vertex: VertexId,
    /// The face on its left (`None` for a boundary half-edge).
    pub face: Option<FaceId>,
    /// The other half of the same edge, running the opposite way.
    pub pair_edge: HalfEdgeId,
    /// The next half-edge counter-clockwise around the face (along the
    /// boundary loop for a boundary half-edge).
    pub successor_edge: HalfEdgeId,
}

/// A half-edge mesh.
///
/// Besides the three tables it keeps each half-edge's predecessor (the
/// inverse of `successor_edge`), so [`Self::predecessor_edge`] is O(1) for the
/// algorithm VM. That table is built on the first call (one pass over the
/// half-edges) and then kept: 4 bytes per half-edge, a quarter on top of the
/// 16-byte rows, paid only by code that asks for predecessors.
#[derive(Clone, Debug, Default)]
pub struct HalfEdgeMesh {
    pub(crate) vertices: Vec<Vertex>,
    pub(crate) faces: Vec<Face>,
    pub(crate) half_edges: Vec<HalfEdge>,
    /// Inverse of the successor links, built on first use; [`NONE`] where no
    /// half-edge has this one as successor (only in broken tables).
    predecessors: OnceLock<Vec<u32>>,
    /// Rows an edit deleted, kept as gaps until the ids are compacted.
    pub(crate) deleted: Deleted,
}

impl PartialEq for HalfEdgeMesh {
    fn eq(&self, other: &Self) -> bool {
        self.vertices == other.vertices
            && self.faces == other.faces
            && self.half_edges == other.half_edges
            && self.deleted == other.deleted
    }
}

impl Pairs for [HalfEdge] {
    #[inline(always)]
    fn pair(&self, h: u32) -> u32 {
        self[h as usize].pair_edge.raw()
    }
    #[inline(always)]
    fn set_pair(&mut self, h: u32, pair: u32) {
        self[h as usize].pair_edge = HalfEdgeId::new(pair);
    }
    #[inline(always)]
    fn end_or_start<L: Layout>(&self, layout: &L, _: &[u32], h: u32, forward: bool) -> u32 {
        // Both rows lie in the same face, usually in the same cache line.
        self[if forward { h } else { layout.prev(h) } as usize]
            .end_vertex
            .raw()
    }
}

/// The half-edge build assembles the mesh itself: the scan writes the final
/// rows and the pairing step writes into them, so the peak stays near the
/// final size. Faces are added last.
impl builder::Assembly for HalfEdgeMesh {
    type Mesh = Self;
    type Pairs = [HalfEdge];

    fn new(polygons: &Polygons) -> Self {
        let vertices = polygons
            .positions()
            .iter()
            .map(|&position| Vertex {
                position,
                incident_edge: None,
            })
            .collect();
        Self {
            vertices,
            faces: Vec::new(),
            half_edges: vec![HalfEdge::default(); polygons.corner_count()],
            predecessors: OnceLock::new(),
            deleted: Deleted::default(),
        }
    }

    /// Writes the row, with the bucket link as pair for now; the first
    /// half-edge to end at a vertex is its lowest-numbered one.
    #[inline(always)]
    fn corner<L: Layout>(&mut self, layout: &L, h: u32, end: u32, face: u32, link: u32) {
        let rows: &mut [HalfEdge] = &mut self.half_edges;
        rows[h as usize] = HalfEdge {
            end_vertex: VertexId::new(end),
            face: Some(FaceId::new(face)),
            pair_edge: HalfEdgeId::new(link),
            successor_edge: HalfEdgeId::new(layout.next(h)),
        };
        let vertices: &mut [Vertex] = &mut self.vertices;
        let vertex = &mut vertices[end as usize];
        if vertex.incident_edge.is_none() {
            vertex.incident_edge = Some(HalfEdgeId::new(h));
        }
    }

    fn pairs(&mut self) -> &mut [HalfEdge] {
        &mut self.half_edges
    }

    fn boundary(&mut self, indices: &[u32], boundary: &Boundary) {
        self.half_edges.reserve_exact(boundary.twin.len());
        for (&twin, &next) in boundary.twin.iter().zip(&boundary.next) {
            self.half_edges.push(HalfEdge {
                end_vertex: VertexId::new(indices[twin as usize]),
                face: None,
                pair_edge: HalfEdgeId::new(twin),
                successor_edge: HalfEdgeId::new(next),
            });
        }
    }

    #[inline(always)]
    fn first_incoming(&self, v: usize) -> u32 {
        let vertices: &[Vertex] = &self.vertices;
        vertices[v].incident_edge.map_or(NONE, HalfEdgeId::raw)
    }

    /// Every row is written by now, boundary ones included. An interior
    /// successor is arithmetic, which saves the loop a dependent read.
    #[inline(always)]
    fn around<L: Layout>(&self, layout: &L, boundary: &Boundary, h: u32) -> u32 {
        let rows: &[HalfEdge] = &self.half_edges;
        let interior = (rows.len() - boundary.twin.len()) as u32;
        let successor = if h < interior {
            layout.next(h)
        } else {
            rows[h as usize].successor_edge.raw()
        };
        rows[successor as usize].pair_edge.raw()
    }

    /// Each face's incident edge is its first half-edge.
    fn finish<L: Layout>(mut self, polygons: &Polygons, _: &L, _: Boundary) -> Self {
        self.faces = polygons
            .offsets()
            .split_last()
            .map_or(&[][..], |(_, starts)| starts)
            .iter()
            .map(|&start| Face {
                incident_edge: HalfEdgeId::new(start as u32),
            })
            .collect();
        self
    }
}

impl HalfEdgeMesh {
    /// Builds the structure from counter-clockwise polygons, refusing
    /// non-manifold edges and inconsistently oriented input. A vertex where
    /// separate fans of faces meet is split into one vertex per fan (new ids
    /// after the input's), so the result is manifold. Returns the mesh and
    /// warnings about what it kept or split (unused and split vertices).
    ///
    /// Vertices and faces keep their numbers. Interior half-edges are numbered
    /// face by face along each face's vertex order (face `[a, b, c]` gives
    /// `a→b`, `b→c`, `c→a`), then boundary half-edges in the order of their
    /// interior pair. Each face's incident edge is its first half-edge; each
    /// vertex's is the lowest-numbered half-edge ending at it.
    ///
    /// ```
    /// use edgewise_core::mesh::{HalfEdgeMesh, HalfEdgeId, Polygons, VertexId};
    /// use glam::Vec3;
    ///
    /// let positions = vec![Vec3::ZERO, Vec3::X, Vec3::Y];
    /// let (mesh, warnings) = HalfEdgeMesh::build(&Polygons::from_triangles(positions, &[[0, 1, 2]]))?;
    /// assert!(warnings.is_empty());
    /// assert_eq!(mesh.half_edge_count(), 6); // 3 interior + 3 boundary
    /// assert_eq!(mesh.start_vertex(HalfEdgeId::new(0)), Some(VertexId::new(0)));
    /// assert_eq!(mesh.half_edge(HalfEdgeId::new(3)).and_then(|h| h.face), None);
    /// # Ok::<(), edgewise_core::mesh::BuildError>(())
    /// ```
    pub fn build(polygons: &Polygons) -> Result<(Self, Vec<BuildWarning>), BuildError> {
        builder::build::<Self>(polygons)
    }

    /// Takes the three tables as written (for example from a `.htb` file)
    /// without checking them; call [`Self::validate`] to find what is wrong.
    /// Every accessor and iterator stays panic-free and terminates on broken
    /// tables.
    pub fn from_raw_parts(
        vertices: Vec<Vertex>,
        faces: Vec<Face>,
        half_edges: Vec<HalfEdge>,
    ) -> Self {
        Self {
            vertices,
            faces,
            half_edges,
            predecessors: OnceLock::new(),
            deleted: Deleted::default(),
        }
    }

    /// Drops the predecessor table after a successor changed; the next
    /// question rebuilds it.
    pub(crate) fn forget_predecessors(&mut self) {
        self.predecessors = OnceLock::new();
    }

    /// The predecessor table, built on first use: the first live half-edge
    /// (in number order) naming each half-edge as its successor.
    fn predecessors(&self) -> &[u32] {
        self.predecessors.get_or_init(|| {
            let mut predecessors = vec![NONE; self.half_edges.len()];
            for (h, half_edge) in (0u32..).zip(&self.half_edges) {
                // A deleted row keeps its contents but is no one's predecessor.
                if self.deleted.contains(HalfEdgeId::new(h).into()) {
                    continue;
                }
                if let Some(slot) = predecessors.get_mut(half_edge.successor_edge.index())
                    && *slot == NONE
                {
                    *slot = h;
                }
            }
            predecessors
        })
    }

    tables!(Vertex, Face, half_edges: HalfEdge, "half-edge", half_edge(HalfEdgeId), half_edge_count);

    /// Number of edges (half-edge pairs).
    pub fn edge_count(&self) -> usize {
        self.half_edges.len() / 2
    }

    /// The start vertex of a half-edge: its pair's end vertex (derived).
    #[inline]
    pub fn start_vertex(&self, h: HalfEdgeId) -> Option<VertexId> {
        let pair = self.half_edge(h)?.pair_edge;
        // An unset end vertex (a new half-edge) gives no start vertex.
        Some(self.half_edge(pair)?.end_vertex).filter(|v| !v.is_unset())
    }

    /// The half-edge whose successor is `h` (derived; O(1) from a table built
    /// on the first call).
    #[inline]
    pub fn predecessor_edge(&self, h: HalfEdgeId) -> Option<HalfEdgeId> {
        self.predecessors()
            .get(h.index())
            .filter(|&&p| p != NONE)
            .map(|&p| HalfEdgeId::new(p))
    }

    /// Whether a half-edge lies on the boundary (has no face).
    #[inline]
    pub fn is_boundary(&self, h: HalfEdgeId) -> bool {
        self.half_edge(h)
            .is_some_and(|half_edge| half_edge.face.is_none())
    }
}
