//! How each structure steps around a vertex and around a face, and what a
//! step touches: all [`Navigation`] needs to walk it.
//!
//! A step leaves the ring when its row is missing or no longer touches the
//! element, so walks on broken tables end early instead of wandering off;
//! budgets are one lap of the largest possible ring.

use super::circulator::Circulator;
use super::half_edge::HalfEdgeMesh;
use super::ids::{EdgeId, FaceId, HalfEdgeId, VertexId};
use super::navigation::{AroundFace, Navigation};
use super::winged_edge::{Side, WingedEdgeMesh};

/// Around a vertex: the half-edges ending there, by the paper's loop
/// (successor, then pair). Around a face: its half-edges, by successors.
impl Navigation for HalfEdgeMesh {
    type VertexStep = HalfEdgeId;
    type FaceStep = HalfEdgeId;

    fn step_budget(&self) -> usize {
        self.half_edges.len()
    }

    fn vertex_first(&self, v: VertexId) -> Option<HalfEdgeId> {
        let h = self.vertex(v)?.incident_edge?;
        self.half_edge(h).map(|_| h)
    }

    fn vertex_after(&self, v: VertexId, h: HalfEdgeId) -> Option<HalfEdgeId> {
        let successor = self.half_edge(h)?.successor_edge;
        let following = self.half_edge(successor)?.pair_edge;
        (self.half_edge(following)?.end_vertex == v).then_some(following)
    }

    fn face_first(&self, f: FaceId) -> Option<HalfEdgeId> {
        let h = self.face(f)?.incident_edge;
        self.half_edge(h).map(|_| h)
    }

    fn face_after(&self, f: FaceId, h: HalfEdgeId) -> Option<HalfEdgeId> {
        let following = self.half_edge(h)?.successor_edge;
        (self.half_edge(following)?.face == Some(f)).then_some(following)
    }

    /// The half-edge's own face.
    fn vertex_step_face(&self, _: VertexId, h: HalfEdgeId) -> Option<FaceId> {
        self.half_edge(h)?.face
    }

    /// The half-edge's start vertex.
    fn vertex_step_neighbour(&self, _: VertexId, h: HalfEdgeId) -> Option<VertexId> {
        self.start_vertex(h)
    }

    fn face_step_vertex(&self, h: HalfEdgeId) -> Option<VertexId> {
        self.start_vertex(h)
    }

    /// The pair's face.
    fn face_step_across(&self, h: HalfEdgeId) -> Option<FaceId> {
        let pair = self.half_edge(h)?.pair_edge;
        self.half_edge(pair)?.face
    }
}

/// Around a vertex: its edges, turning as the half-edge loop does (from an
/// edge ending there its left predecessor, from one starting there its right
/// predecessor). Around a face: its edges with the side it is on, by
/// predecessor wings (counter-clockwise, as wings follow the clockwise
/// traversal).
impl Navigation for WingedEdgeMesh {
    type VertexStep = EdgeId;
    type FaceStep = (EdgeId, Side);

    /// Each edge can come up once per side.
    fn step_budget(&self) -> usize {
        self.edges.len() * 2
    }

    fn vertex_first(&self, v: VertexId) -> Option<EdgeId> {
        let e = self.vertex(v)?.incident_edge?;
        self.touches(e, v).then_some(e)
    }

    fn vertex_after(&self, v: VertexId, e: EdgeId) -> Option<EdgeId> {
        let following = self.next_around(e, v)?;
        self.touches(following, v).then_some(following)
    }

    fn face_first(&self, f: FaceId) -> Option<(EdgeId, Side)> {
        self.side_bordering(self.face(f)?.incident_edge, f)
    }

    /// The predecessor wing, on the side entered where this edge is left
    /// (which tells the sides of an edge with `f` on both apart).
    fn face_after(&self, f: FaceId, (e, side): (EdgeId, Side)) -> Option<(EdgeId, Side)> {
        let edge = self.edge(e)?;
        let next = edge.predecessor(side);
        let side = self
            .edge(next)?
            .side_entered_at(Some(f), edge.ccw_end(side))?;
        Some((next, side))
    }

    /// The face whose counter-clockwise traversal enters `v` along the edge:
    /// the left face if the edge ends at `v`, else the right face.
    fn vertex_step_face(&self, v: VertexId, e: EdgeId) -> Option<FaceId> {
        let edge = self.edge(e)?;
        if edge.end_vertex == v {
            edge.left_face
        } else {
            edge.right_face
        }
    }

    /// The edge's other end.
    fn vertex_step_neighbour(&self, v: VertexId, e: EdgeId) -> Option<VertexId> {
        self.edge(e)?.other_vertex(v)
    }

    /// Where the face's counter-clockwise traversal enters the edge.
    fn face_step_vertex(&self, (e, side): (EdgeId, Side)) -> Option<VertexId> {
        Some(self.edge(e)?.ccw_start(side))
    }

    /// The face on the edge's other side.
    fn face_step_across(&self, (e, side): (EdgeId, Side)) -> Option<FaceId> {
        self.edge(e)?.face(side.opposite())
    }
}

impl WingedEdgeMesh {
    /// [`around_face`](Navigation::around_face) from `start` instead of the
    /// incident edge, for the polygon export. `start` must border `f` on the
    /// side given (it is yielded unchecked).
    pub(crate) fn face_sides_from(
        &self,
        f: FaceId,
        start: Option<(EdgeId, Side)>,
    ) -> Circulator<AroundFace<'_, Self>> {
        Circulator::starting_at(
            AroundFace {
                mesh: self,
                face: f,
            },
            start,
        )
    }

    /// Whether edge `e` exists and starts or ends at `v`.
    fn touches(&self, e: EdgeId, v: VertexId) -> bool {
        self.edge(e)
            .is_some_and(|edge| edge.other_vertex(v).is_some())
    }

    /// Edge `e` with the side `f` is on, if it exists and borders `f`.
    fn side_bordering(&self, e: EdgeId, f: FaceId) -> Option<(EdgeId, Side)> {
        Some((e, self.edge(e)?.side_of(Some(f))?))
    }
}
