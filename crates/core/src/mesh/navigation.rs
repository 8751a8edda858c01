//! Navigation: ordered walks around a vertex and around a face, written once
//! for both structures.
//!
//! Around a vertex both structures follow the half-edge paper's loop
//! (`e := e.successorEdge; e := e.pairEdge`), which turns clockwise seen from
//! outside and passes through boundary gaps; around a face they go
//! counter-clockwise, the order faces are listed in. Every walk starts at the
//! element's incident edge and stops after at most one lap, so it terminates
//! (without panicking) even on broken tables from
//! [`from_raw_parts`](super::HalfEdgeMesh::from_raw_parts).
//!
//! A structure implements [`Navigation`] by saying what one step is (a
//! half-edge; an edge, with a side around a face), where a walk starts, how it
//! takes the next step and what a step touches. Everything else is written
//! here once: [`AroundVertex`] and [`AroundFace`] are the [`Ring`]s one
//! [`Circulator`] walks, and the walks people call
//! ([`vertex_faces`](Navigation::vertex_faces) and the rest) read off them.

use super::circulator::{Circulator, Ring};
use super::ids::{FaceId, VertexId};

/// The ring around a vertex, clockwise seen from outside: the [`Ring`] that
/// [`Navigation::around_vertex`] walks.
#[derive(Clone, Debug)]
pub struct AroundVertex<'a, M> {
    pub(crate) mesh: &'a M,
    pub(crate) vertex: VertexId,
}

impl<M: Navigation> Ring for AroundVertex<'_, M> {
    type Step = M::VertexStep;

    fn first(&self) -> Option<M::VertexStep> {
        self.mesh.vertex_first(self.vertex)
    }

    fn after(&self, step: M::VertexStep) -> Option<M::VertexStep> {
        self.mesh.vertex_after(self.vertex, step)
    }

    fn budget(&self) -> usize {
        self.mesh.step_budget()
    }
}

/// The ring around a face, counter-clockwise: the [`Ring`] that
/// [`Navigation::around_face`] walks.
#[derive(Clone, Debug)]
pub struct AroundFace<'a, M> {
    pub(crate) mesh: &'a M,
    pub(crate) face: FaceId,
}

impl<M: Navigation> Ring for AroundFace<'_, M> {
    type Step = M::FaceStep;

    fn first(&self) -> Option<M::FaceStep> {
        self.mesh.face_first(self.face)
    }

    fn after(&self, step: M::FaceStep) -> Option<M::FaceStep> {
        self.mesh.face_after(self.face, step)
    }

    fn budget(&self) -> usize {
        self.mesh.step_budget()
    }
}

/// Walks around vertices and faces, for either structure. Import it to call
/// the walks on a mesh.
///
/// On a tetrahedron, faces counter-clockwise seen from outside, both
/// structures turn the same way, each from its own incident edge:
///
/// ```
/// use edgewise_core::mesh::{FaceId, HalfEdgeMesh, Navigation, Polygons, VertexId, WingedEdgeMesh};
/// use glam::Vec3;
///
/// let positions = vec![Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::Z];
/// let faces = [[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]];
/// let polygons = Polygons::from_triangles(positions, &faces);
/// let (he, _) = HalfEdgeMesh::build(&polygons)?;
/// let (we, _) = WingedEdgeMesh::build(&polygons)?;
/// // The numbers of the ids a walk yields.
/// fn raw<I: Into<usize>>(ids: impl Iterator<Item = I>) -> Vec<usize> {
///     ids.map(Into::into).collect()
/// }
/// let (v0, f0, f1) = (VertexId::new(0), FaceId::new(0), FaceId::new(1));
///
/// // Around vertex 0: the half-edges ending there, or the edges at it.
/// let around = raw(he.around_vertex(v0));
/// assert_eq!(around, [2, 11, 5]);
/// assert!(around.iter().all(|&h| he.half_edges()[h].end_vertex == v0));
/// assert_eq!(raw(we.around_vertex(v0)), [0, 4, 2]);
/// assert_eq!(raw(he.vertex_faces(v0)), [0, 3, 1]);
/// assert_eq!(raw(we.vertex_faces(v0)), [3, 1, 0]); // the same turn, from edge 0
/// assert_eq!(raw(he.vertex_neighbours(v0)), [1, 2, 3]);
/// assert_eq!(raw(we.vertex_neighbours(v0)), [2, 3, 1]);
///
/// // Around a face: its half-edges, or its edges with the side it is on.
/// assert_eq!(raw(he.around_face(f1)), [3, 4, 5]);
/// assert_eq!(raw(we.around_face(f1).map(|(e, _side)| e)), [2, 3, 4]);
/// assert_eq!(raw(he.face_vertices(FaceId::new(2))), [1, 2, 3]);
/// assert_eq!(raw(we.face_vertices(f1)), [0, 1, 3]);
/// assert_eq!(raw(he.face_neighbours(f0)), [3, 2, 1]);
/// assert_eq!(raw(we.face_neighbours(f0)), [3, 2, 1]);
/// # Ok::<(), edgewise_core::mesh::BuildError>(())
/// ```
pub trait Navigation: Sized {
    /// One step around a vertex: a half-edge ending there, or an edge at it.
    type VertexStep: Copy + PartialEq;
    /// One step around a face: a half-edge of it, or an edge with the side
    /// the face is on.
    type FaceStep: Copy + PartialEq;

    /// The most steps one walk may take: at least one lap of any valid ring
    /// (every half-edge, or every edge on both sides), so walks on broken
    /// tables end.
    fn step_budget(&self) -> usize;

    /// Where a walk around `v` starts: its incident edge, if that exists and
    /// touches `v`.
    fn vertex_first(&self, v: VertexId) -> Option<Self::VertexStep>;

    /// The step after `step` around `v`, or `None` when the tables lead
    /// away from `v` (a missing row, or one that does not touch `v`).
    fn vertex_after(&self, v: VertexId, step: Self::VertexStep) -> Option<Self::VertexStep>;

    /// Where a walk around `f` starts: its incident edge, if that exists and
    /// borders `f`.
    fn face_first(&self, f: FaceId) -> Option<Self::FaceStep>;

    /// The step after `step` around `f`, or `None` when the tables lead
    /// away from `f`.
    fn face_after(&self, f: FaceId, step: Self::FaceStep) -> Option<Self::FaceStep>;

    /// The face a step around `v` lies in, turning the way the walk turns
    /// (`None` at a boundary gap or on a broken row).
    fn vertex_step_face(&self, v: VertexId, step: Self::VertexStep) -> Option<FaceId>;

    /// The vertex a step around `v` joins it to (`None` on a broken row).
    fn vertex_step_neighbour(&self, v: VertexId, step: Self::VertexStep) -> Option<VertexId>;

    /// Where a step around a face starts, counter-clockwise (`None` on a
    /// broken row).
    fn face_step_vertex(&self, step: Self::FaceStep) -> Option<VertexId>;

    /// The face across a step around a face (`None` on the boundary or on a
    /// broken row).
    fn face_step_across(&self, step: Self::FaceStep) -> Option<FaceId>;

    /// The steps around `v`, from its incident edge, clockwise seen from
    /// outside (the half-edge loop: successor, then pair), boundary steps
    /// included. Empty for an isolated or nonexistent vertex.
    fn around_vertex(&self, v: VertexId) -> Circulator<AroundVertex<'_, Self>> {
        Circulator::new(AroundVertex {
            mesh: self,
            vertex: v,
        })
    }

    /// The steps around `f`, counter-clockwise from its incident edge. Empty
    /// for a nonexistent face.
    fn around_face(&self, f: FaceId) -> Circulator<AroundFace<'_, Self>> {
        Circulator::new(AroundFace {
            mesh: self,
            face: f,
        })
    }

    /// The faces around `v` in [`around_vertex`](Self::around_vertex) order,
    /// boundary gaps skipped.
    fn vertex_faces(&self, v: VertexId) -> impl Iterator<Item = FaceId> + '_ {
        self.around_vertex(v)
            .filter_map(move |step| self.vertex_step_face(v, step))
    }

    /// The vertices joined to `v` by an edge, in
    /// [`around_vertex`](Self::around_vertex) order.
    fn vertex_neighbours(&self, v: VertexId) -> impl Iterator<Item = VertexId> + '_ {
        self.around_vertex(v)
            .filter_map(move |step| self.vertex_step_neighbour(v, step))
    }

    /// The vertices of `f`, counter-clockwise, starting where its incident
    /// edge is entered (for a built half-edge mesh: the face as listed).
    fn face_vertices(&self, f: FaceId) -> impl Iterator<Item = VertexId> + '_ {
        self.around_face(f)
            .filter_map(|step| self.face_step_vertex(step))
    }

    /// The faces across each edge of `f`, counter-clockwise, boundary edges
    /// skipped.
    fn face_neighbours(&self, f: FaceId) -> impl Iterator<Item = FaceId> + '_ {
        self.around_face(f)
            .filter_map(|step| self.face_step_across(step))
    }
}
