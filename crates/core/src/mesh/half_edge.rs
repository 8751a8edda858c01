//! The half-edge structure (Neperud, section 2.2): every edge is a pair of
//! half-edges, each storing its end vertex, adjacent face, pair edge and
//! successor edge (the next half-edge counter-clockwise around its face).

use glam::Vec3;

use super::builder::{self, General, Layout, NONE, Topology, Triangles};
use super::error::{BuildError, BuildWarning};
use super::ids::{FaceId, HalfEdgeId, VertexId};
use super::polygons::Polygons;

/// A row of the half-edge vertex table.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Vertex {
    /// Where the vertex is.
    pub position: Vec3,
    /// A half-edge that ENDS at this vertex, so the paper's loop
    /// (`e := e.successorEdge; e := e.pairEdge`) circles it. `None` for an
    /// isolated vertex.
    pub incident_edge: Option<HalfEdgeId>,
}

/// A row of the half-edge face table.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Face {
    /// One of the face's half-edges.
    pub incident_edge: HalfEdgeId,
}

/// A row of the half-edge table.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
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
/// algorithm VM; that costs 4 bytes per half-edge (20% on top of the 20-byte
/// half-edge rows) and is recomputed by [`Self::from_raw_parts`].
#[derive(Clone, Debug, Default, PartialEq)]
pub struct HalfEdgeMesh {
    pub(crate) vertices: Vec<Vertex>,
    pub(crate) faces: Vec<Face>,
    pub(crate) half_edges: Vec<HalfEdge>,
    /// Inverse of the successor links; [`NONE`] where no half-edge has this
    /// one as successor (only in broken tables).
    pub(crate) predecessors: Vec<u32>,
}

impl HalfEdgeMesh {
    /// Builds the structure from counter-clockwise polygons, refusing
    /// non-manifold or inconsistently oriented input. Returns the mesh and
    /// warnings about what it kept (unused vertices).
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
        let checked = builder::check_faces(polygons)?;
        let mesh = if checked.triangles {
            let topology = builder::topology(polygons, &Triangles, &checked.valence)?;
            drop(checked.valence);
            Self::assemble(polygons, &Triangles, topology)
        } else {
            let layout = General::new(polygons);
            let topology = builder::topology(polygons, &layout, &checked.valence)?;
            drop(checked.valence);
            Self::assemble(polygons, &layout, topology)
        };
        Ok((mesh, checked.warnings))
    }

    fn assemble<L: Layout>(polygons: &Polygons, layout: &L, topology: Topology) -> Self {
        let Topology {
            interior: n,
            pair,
            boundary_twin,
            boundary_next,
            first_incoming,
        } = topology;
        let indices = polygons.indices();
        let total = n as usize + boundary_twin.len();
        let mut half_edges = Vec::with_capacity(total);
        let mut predecessors = Vec::with_capacity(total);
        for (h, &pair) in (0..n).zip(&pair) {
            let next = layout.next(h);
            half_edges.push(HalfEdge {
                end_vertex: VertexId::new(indices[next as usize]),
                face: Some(FaceId::new(layout.face(h))),
                pair_edge: HalfEdgeId::new(pair),
                successor_edge: HalfEdgeId::new(next),
            });
            predecessors.push(layout.prev(h));
        }
        drop(pair);
        for (&twin, &next) in boundary_twin.iter().zip(&boundary_next) {
            half_edges.push(HalfEdge {
                end_vertex: VertexId::new(indices[twin as usize]),
                face: None,
                pair_edge: HalfEdgeId::new(twin),
                successor_edge: HalfEdgeId::new(next),
            });
            predecessors.push(NONE);
        }
        for (b, &next) in (n..).zip(&boundary_next) {
            if let Some(slot) = predecessors.get_mut(next as usize) {
                *slot = b;
            }
        }
        let vertices = polygons
            .positions()
            .iter()
            .zip(&first_incoming)
            .map(|(&position, &first)| Vertex {
                position,
                incident_edge: (first != NONE).then_some(HalfEdgeId::new(first)),
            })
            .collect();
        let faces = polygons
            .offsets()
            .split_last()
            .map_or(&[][..], |(_, starts)| starts)
            .iter()
            .map(|&start| Face {
                incident_edge: HalfEdgeId::new(start as u32),
            })
            .collect();
        Self {
            vertices,
            faces,
            half_edges,
            predecessors,
        }
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
        let mut predecessors = vec![NONE; half_edges.len()];
        for (h, half_edge) in (0u32..).zip(&half_edges) {
            if let Some(slot) = predecessors.get_mut(half_edge.successor_edge.index())
                && *slot == NONE
            {
                *slot = h;
            }
        }
        Self {
            vertices,
            faces,
            half_edges,
            predecessors,
        }
    }

    /// Gives the tables back, for editing.
    pub fn into_raw_parts(self) -> (Vec<Vertex>, Vec<Face>, Vec<HalfEdge>) {
        (self.vertices, self.faces, self.half_edges)
    }

    /// The vertex table.
    pub fn vertices(&self) -> &[Vertex] {
        &self.vertices
    }

    /// The face table.
    pub fn faces(&self) -> &[Face] {
        &self.faces
    }

    /// The half-edge table.
    pub fn half_edges(&self) -> &[HalfEdge] {
        &self.half_edges
    }

    /// Number of vertices.
    pub fn vertex_count(&self) -> usize {
        self.vertices.len()
    }

    /// Number of faces.
    pub fn face_count(&self) -> usize {
        self.faces.len()
    }

    /// Number of half-edges, interior and boundary.
    pub fn half_edge_count(&self) -> usize {
        self.half_edges.len()
    }

    /// Number of edges (half-edge pairs).
    pub fn edge_count(&self) -> usize {
        self.half_edges.len() / 2
    }

    /// A vertex row.
    #[inline]
    pub fn vertex(&self, v: VertexId) -> Option<&Vertex> {
        self.vertices.get(v.index())
    }

    /// A face row.
    #[inline]
    pub fn face(&self, f: FaceId) -> Option<&Face> {
        self.faces.get(f.index())
    }

    /// A half-edge row.
    #[inline]
    pub fn half_edge(&self, h: HalfEdgeId) -> Option<&HalfEdge> {
        self.half_edges.get(h.index())
    }

    /// The position of a vertex.
    #[inline]
    pub fn position(&self, v: VertexId) -> Option<Vec3> {
        self.vertex(v).map(|vertex| vertex.position)
    }

    /// The start vertex of a half-edge: its pair's end vertex (derived).
    #[inline]
    pub fn start_vertex(&self, h: HalfEdgeId) -> Option<VertexId> {
        let pair = self.half_edge(h)?.pair_edge;
        Some(self.half_edge(pair)?.end_vertex)
    }

    /// The half-edge whose successor is `h` (derived, O(1) from a stored
    /// inverse table).
    #[inline]
    pub fn predecessor_edge(&self, h: HalfEdgeId) -> Option<HalfEdgeId> {
        self.predecessors
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
