//! Navigation: ordered walks around a vertex and around a face, for both
//! structures.
//!
//! Around a vertex both structures follow the half-edge paper's loop
//! (`e := e.successorEdge; e := e.pairEdge`), which turns clockwise seen from
//! outside and passes through boundary gaps; around a face they go
//! counter-clockwise, the order faces are listed in. Every walk starts at the
//! element's incident edge and stops after at most one lap, so it terminates
//! (without panicking) even on broken tables from
//! [`from_raw_parts`](HalfEdgeMesh::from_raw_parts).

use super::half_edge::HalfEdgeMesh;
use super::ids::{EdgeId, FaceId, HalfEdgeId, VertexId};
use super::winged_edge::{Side, WingedEdgeMesh};

/// Half-edges ending at a vertex, in loop order. See
/// [`HalfEdgeMesh::vertex_half_edges`].
#[derive(Clone, Debug)]
pub struct VertexHalfEdges<'a> {
    mesh: &'a HalfEdgeMesh,
    vertex: VertexId,
    start: Option<HalfEdgeId>,
    next: Option<HalfEdgeId>,
    budget: usize,
}

impl Iterator for VertexHalfEdges<'_> {
    type Item = HalfEdgeId;

    fn next(&mut self) -> Option<HalfEdgeId> {
        let current = self.next?;
        self.budget = self.budget.checked_sub(1)?;
        let mesh = self.mesh;
        self.next = mesh
            .half_edge(current)
            .and_then(|h| mesh.half_edge(h.successor_edge))
            .map(|s| s.pair_edge)
            .filter(|&following| {
                Some(following) != self.start
                    && mesh
                        .half_edge(following)
                        .is_some_and(|h| h.end_vertex == self.vertex)
            });
        Some(current)
    }
}

/// Half-edges of a face, counter-clockwise. See [`HalfEdgeMesh::face_half_edges`].
#[derive(Clone, Debug)]
pub struct FaceHalfEdges<'a> {
    mesh: &'a HalfEdgeMesh,
    face: FaceId,
    start: Option<HalfEdgeId>,
    next: Option<HalfEdgeId>,
    budget: usize,
}

impl Iterator for FaceHalfEdges<'_> {
    type Item = HalfEdgeId;

    fn next(&mut self) -> Option<HalfEdgeId> {
        let current = self.next?;
        self.budget = self.budget.checked_sub(1)?;
        let mesh = self.mesh;
        self.next = mesh
            .half_edge(current)
            .map(|h| h.successor_edge)
            .filter(|&following| {
                Some(following) != self.start
                    && mesh
                        .half_edge(following)
                        .is_some_and(|h| h.face == Some(self.face))
            });
        Some(current)
    }
}

impl HalfEdgeMesh {
    /// The half-edges ending at `v`, starting with its incident edge and
    /// following the paper's loop (successor, then pair): clockwise seen from
    /// outside, including boundary half-edges.
    ///
    /// ```
    /// use edgewise_core::mesh::{HalfEdgeId, HalfEdgeMesh, Polygons, VertexId};
    /// use glam::Vec3;
    ///
    /// // A tetrahedron, faces counter-clockwise seen from outside.
    /// let positions = vec![Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::Z];
    /// let faces = [[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]];
    /// let (mesh, _) = HalfEdgeMesh::build(&Polygons::from_triangles(positions, &faces))?;
    /// let around: Vec<u32> = mesh.vertex_half_edges(VertexId::new(0)).map(|h| h.raw()).collect();
    /// assert_eq!(around, [2, 11, 5]);
    /// assert!(around.iter().all(|&h| mesh.half_edges()[h as usize].end_vertex == VertexId::new(0)));
    /// # Ok::<(), edgewise_core::mesh::BuildError>(())
    /// ```
    pub fn vertex_half_edges(&self, v: VertexId) -> VertexHalfEdges<'_> {
        let start = self
            .vertex(v)
            .and_then(|vertex| vertex.incident_edge)
            .filter(|&h| self.half_edge(h).is_some());
        VertexHalfEdges {
            mesh: self,
            vertex: v,
            start,
            next: start,
            budget: self.half_edges.len(),
        }
    }

    /// The faces around `v` in the same order as
    /// [`vertex_half_edges`](Self::vertex_half_edges) (each half-edge's face;
    /// boundary gaps are skipped).
    ///
    /// ```
    /// # use edgewise_core::mesh::{FaceId, HalfEdgeMesh, Polygons, VertexId};
    /// # use glam::Vec3;
    /// # let positions = vec![Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::Z];
    /// # let faces = [[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]];
    /// # let (mesh, _) = HalfEdgeMesh::build(&Polygons::from_triangles(positions, &faces))?;
    /// let faces: Vec<u32> = mesh.vertex_faces(VertexId::new(0)).map(|f| f.raw()).collect();
    /// assert_eq!(faces, [0, 3, 1]);
    /// # Ok::<(), edgewise_core::mesh::BuildError>(())
    /// ```
    pub fn vertex_faces(&self, v: VertexId) -> impl Iterator<Item = FaceId> + '_ {
        self.vertex_half_edges(v)
            .filter_map(|h| self.half_edge(h).and_then(|h| h.face))
    }

    /// The vertices joined to `v` by an edge, in loop order (the start vertex
    /// of each half-edge ending at `v`).
    ///
    /// ```
    /// # use edgewise_core::mesh::{HalfEdgeMesh, Polygons, VertexId};
    /// # use glam::Vec3;
    /// # let positions = vec![Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::Z];
    /// # let faces = [[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]];
    /// # let (mesh, _) = HalfEdgeMesh::build(&Polygons::from_triangles(positions, &faces))?;
    /// let neighbours: Vec<u32> = mesh.vertex_neighbours(VertexId::new(0)).map(|v| v.raw()).collect();
    /// assert_eq!(neighbours, [1, 2, 3]);
    /// # Ok::<(), edgewise_core::mesh::BuildError>(())
    /// ```
    pub fn vertex_neighbours(&self, v: VertexId) -> impl Iterator<Item = VertexId> + '_ {
        self.vertex_half_edges(v)
            .filter_map(|h| self.start_vertex(h))
    }

    /// The half-edges of face `f`, counter-clockwise from its incident edge.
    ///
    /// ```
    /// # use edgewise_core::mesh::{FaceId, HalfEdgeMesh, Polygons};
    /// # use glam::Vec3;
    /// # let positions = vec![Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::Z];
    /// # let faces = [[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]];
    /// # let (mesh, _) = HalfEdgeMesh::build(&Polygons::from_triangles(positions, &faces))?;
    /// let edges: Vec<u32> = mesh.face_half_edges(FaceId::new(1)).map(|h| h.raw()).collect();
    /// assert_eq!(edges, [3, 4, 5]);
    /// # Ok::<(), edgewise_core::mesh::BuildError>(())
    /// ```
    pub fn face_half_edges(&self, f: FaceId) -> FaceHalfEdges<'_> {
        let start = self
            .face(f)
            .map(|face| face.incident_edge)
            .filter(|&h| self.half_edge(h).is_some());
        FaceHalfEdges {
            mesh: self,
            face: f,
            start,
            next: start,
            budget: self.half_edges.len(),
        }
    }

    /// The vertices of face `f`, counter-clockwise, starting with the start
    /// vertex of its incident edge (for a built mesh: the face as listed).
    ///
    /// ```
    /// # use edgewise_core::mesh::{FaceId, HalfEdgeMesh, Polygons};
    /// # use glam::Vec3;
    /// # let positions = vec![Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::Z];
    /// # let faces = [[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]];
    /// # let (mesh, _) = HalfEdgeMesh::build(&Polygons::from_triangles(positions, &faces))?;
    /// let vertices: Vec<u32> = mesh.face_vertices(FaceId::new(2)).map(|v| v.raw()).collect();
    /// assert_eq!(vertices, [1, 2, 3]);
    /// # Ok::<(), edgewise_core::mesh::BuildError>(())
    /// ```
    pub fn face_vertices(&self, f: FaceId) -> impl Iterator<Item = VertexId> + '_ {
        self.face_half_edges(f).filter_map(|h| self.start_vertex(h))
    }

    /// The faces across each edge of `f`, counter-clockwise (boundary edges
    /// are skipped).
    ///
    /// ```
    /// # use edgewise_core::mesh::{FaceId, HalfEdgeMesh, Polygons};
    /// # use glam::Vec3;
    /// # let positions = vec![Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::Z];
    /// # let faces = [[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]];
    /// # let (mesh, _) = HalfEdgeMesh::build(&Polygons::from_triangles(positions, &faces))?;
    /// let neighbours: Vec<u32> = mesh.face_neighbours(FaceId::new(0)).map(|f| f.raw()).collect();
    /// assert_eq!(neighbours, [3, 2, 1]);
    /// # Ok::<(), edgewise_core::mesh::BuildError>(())
    /// ```
    pub fn face_neighbours(&self, f: FaceId) -> impl Iterator<Item = FaceId> + '_ {
        self.face_half_edges(f).filter_map(|h| {
            let pair = self.half_edge(h)?.pair_edge;
            self.half_edge(pair)?.face
        })
    }
}

/// Edges at a vertex, in loop order. See [`WingedEdgeMesh::vertex_edges`].
#[derive(Clone, Debug)]
pub struct VertexEdges<'a> {
    mesh: &'a WingedEdgeMesh,
    vertex: VertexId,
    start: Option<EdgeId>,
    next: Option<EdgeId>,
    budget: usize,
}

impl Iterator for VertexEdges<'_> {
    type Item = EdgeId;

    fn next(&mut self) -> Option<EdgeId> {
        let current = self.next?;
        self.budget = self.budget.checked_sub(1)?;
        let mesh = self.mesh;
        self.next = mesh.next_around(current, self.vertex).filter(|&following| {
            Some(following) != self.start
                && mesh
                    .edge(following)
                    .is_some_and(|e| e.other_vertex(self.vertex).is_some())
        });
        Some(current)
    }
}

/// Edges of a face with the side the face is on, counter-clockwise. See
/// [`WingedEdgeMesh::face_sides`].
#[derive(Clone, Debug)]
pub struct FaceSides<'a> {
    mesh: &'a WingedEdgeMesh,
    face: FaceId,
    start: Option<(EdgeId, Side)>,
    next: Option<(EdgeId, Side)>,
    budget: usize,
}

impl Iterator for FaceSides<'_> {
    type Item = (EdgeId, Side);

    fn next(&mut self) -> Option<(EdgeId, Side)> {
        let current = self.next?;
        self.budget = self.budget.checked_sub(1)?;
        let mesh = self.mesh;
        let (e, side) = current;
        self.next = mesh
            .edge(e)
            .map(|edge| edge.predecessor(side))
            .and_then(|following| {
                Some((following, mesh.edge(following)?.side_of(Some(self.face))?))
            })
            .filter(|&following| Some(following) != self.start);
        Some(current)
    }
}

impl WingedEdgeMesh {
    /// The edges at `v`, starting with its incident edge and turning the same
    /// way as the half-edge loop: from an edge ending at `v` take its left
    /// predecessor, from an edge starting at `v` its right predecessor.
    ///
    /// ```
    /// use edgewise_core::mesh::{Polygons, VertexId, WingedEdgeMesh};
    /// use glam::Vec3;
    ///
    /// // A tetrahedron, faces counter-clockwise seen from outside.
    /// let positions = vec![Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::Z];
    /// let faces = [[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]];
    /// let (mesh, _) = WingedEdgeMesh::build(&Polygons::from_triangles(positions, &faces))?;
    /// let edges: Vec<u32> = mesh.vertex_edges(VertexId::new(0)).map(|e| e.raw()).collect();
    /// assert_eq!(edges, [0, 4, 2]);
    /// # Ok::<(), edgewise_core::mesh::BuildError>(())
    /// ```
    pub fn vertex_edges(&self, v: VertexId) -> VertexEdges<'_> {
        let start = self
            .vertex(v)
            .and_then(|vertex| vertex.incident_edge)
            .filter(|&e| {
                self.edge(e)
                    .is_some_and(|edge| edge.other_vertex(v).is_some())
            });
        VertexEdges {
            mesh: self,
            vertex: v,
            start,
            next: start,
            budget: self.edges.len() * 2,
        }
    }

    /// The faces around `v` in [`vertex_edges`](Self::vertex_edges) order:
    /// for each edge, the face whose counter-clockwise traversal enters `v`
    /// along it (boundary gaps are skipped).
    ///
    /// ```
    /// # use edgewise_core::mesh::{Polygons, VertexId, WingedEdgeMesh};
    /// # use glam::Vec3;
    /// # let positions = vec![Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::Z];
    /// # let faces = [[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]];
    /// # let (mesh, _) = WingedEdgeMesh::build(&Polygons::from_triangles(positions, &faces))?;
    /// let faces: Vec<u32> = mesh.vertex_faces(VertexId::new(0)).map(|f| f.raw()).collect();
    /// assert_eq!(faces, [3, 1, 0]); // the half-edge order, from edge 0
    /// # Ok::<(), edgewise_core::mesh::BuildError>(())
    /// ```
    pub fn vertex_faces(&self, v: VertexId) -> impl Iterator<Item = FaceId> + '_ {
        self.vertex_edges(v).filter_map(move |e| {
            let edge = self.edge(e)?;
            if edge.end_vertex == v {
                edge.left_face
            } else {
                edge.right_face
            }
        })
    }

    /// The vertices joined to `v`, in [`vertex_edges`](Self::vertex_edges) order.
    ///
    /// ```
    /// # use edgewise_core::mesh::{Polygons, VertexId, WingedEdgeMesh};
    /// # use glam::Vec3;
    /// # let positions = vec![Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::Z];
    /// # let faces = [[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]];
    /// # let (mesh, _) = WingedEdgeMesh::build(&Polygons::from_triangles(positions, &faces))?;
    /// let neighbours: Vec<u32> = mesh.vertex_neighbours(VertexId::new(0)).map(|v| v.raw()).collect();
    /// assert_eq!(neighbours, [2, 3, 1]);
    /// # Ok::<(), edgewise_core::mesh::BuildError>(())
    /// ```
    pub fn vertex_neighbours(&self, v: VertexId) -> impl Iterator<Item = VertexId> + '_ {
        self.vertex_edges(v)
            .filter_map(move |e| self.edge(e)?.other_vertex(v))
    }

    /// The edges of face `f` with the side `f` is on, counter-clockwise
    /// (following predecessor wings) from its incident edge.
    pub fn face_sides(&self, f: FaceId) -> FaceSides<'_> {
        let start = self
            .face(f)
            .map(|face| face.incident_edge)
            .and_then(|e| Some((e, self.edge(e)?.side_of(Some(f))?)));
        self.face_sides_from(f, start)
    }

    pub(crate) fn face_sides_from(
        &self,
        f: FaceId,
        start: Option<(EdgeId, Side)>,
    ) -> FaceSides<'_> {
        FaceSides {
            mesh: self,
            face: f,
            start,
            next: start,
            budget: self.edges.len() * 2,
        }
    }

    /// The edges of face `f`, counter-clockwise from its incident edge.
    ///
    /// ```
    /// # use edgewise_core::mesh::{FaceId, Polygons, WingedEdgeMesh};
    /// # use glam::Vec3;
    /// # let positions = vec![Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::Z];
    /// # let faces = [[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]];
    /// # let (mesh, _) = WingedEdgeMesh::build(&Polygons::from_triangles(positions, &faces))?;
    /// let edges: Vec<u32> = mesh.face_edges(FaceId::new(1)).map(|e| e.raw()).collect();
    /// assert_eq!(edges, [2, 3, 4]);
    /// # Ok::<(), edgewise_core::mesh::BuildError>(())
    /// ```
    pub fn face_edges(&self, f: FaceId) -> impl Iterator<Item = EdgeId> + '_ {
        self.face_sides(f).map(|(e, _)| e)
    }

    /// The vertices of face `f`, counter-clockwise from where its incident
    /// edge is entered.
    ///
    /// ```
    /// # use edgewise_core::mesh::{FaceId, Polygons, WingedEdgeMesh};
    /// # use glam::Vec3;
    /// # let positions = vec![Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::Z];
    /// # let faces = [[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]];
    /// # let (mesh, _) = WingedEdgeMesh::build(&Polygons::from_triangles(positions, &faces))?;
    /// let vertices: Vec<u32> = mesh.face_vertices(FaceId::new(1)).map(|v| v.raw()).collect();
    /// assert_eq!(vertices, [0, 1, 3]);
    /// # Ok::<(), edgewise_core::mesh::BuildError>(())
    /// ```
    pub fn face_vertices(&self, f: FaceId) -> impl Iterator<Item = VertexId> + '_ {
        self.face_sides(f)
            .filter_map(|(e, side)| Some(self.edge(e)?.ccw_start(side)))
    }

    /// The faces across each edge of `f`, counter-clockwise (boundary edges
    /// are skipped).
    ///
    /// ```
    /// # use edgewise_core::mesh::{FaceId, Polygons, WingedEdgeMesh};
    /// # use glam::Vec3;
    /// # let positions = vec![Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::Z];
    /// # let faces = [[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]];
    /// # let (mesh, _) = WingedEdgeMesh::build(&Polygons::from_triangles(positions, &faces))?;
    /// let neighbours: Vec<u32> = mesh.face_neighbours(FaceId::new(0)).map(|f| f.raw()).collect();
    /// assert_eq!(neighbours, [3, 2, 1]);
    /// # Ok::<(), edgewise_core::mesh::BuildError>(())
    /// ```
    pub fn face_neighbours(&self, f: FaceId) -> impl Iterator<Item = FaceId> + '_ {
        self.face_sides(f)
            .filter_map(|(e, side)| self.edge(e)?.face(side.opposite()))
    }
}
