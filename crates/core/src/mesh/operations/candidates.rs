//! Every id list an operation could take on a mesh, before its
//! preconditions are checked: each edge row, each vertex, each face with
//! two of its corners, each vertex with edges around it, each face with a
//! boundary vertex. Tests walk them all; practice draws instances from them.

use super::Operation;
use crate::mesh::navigation::Navigation;
use crate::mesh::structure::Mesh;
use crate::mesh::{EdgeId, FaceId, HalfEdgeId, VertexId};
use crate::schema::{Column, ElementKind, ElementRef, Records, Structure};

/// The id lists `op` takes that fit together on `mesh`, in order; the
/// operation may still refuse any of them.
pub fn candidates(mesh: &Mesh, op: Operation) -> Vec<Vec<u32>> {
    let live = |kind| {
        (0..mesh.count(kind) as u32).filter(move |&id| mesh.contains(ElementRef::new(kind, id)))
    };
    let mut all: Vec<Vec<u32>> = Vec::new();
    match op {
        Operation::FlipEdge
        | Operation::SplitEdge
        | Operation::CollapseEdge
        | Operation::Kev
        | Operation::Kef
        | Operation::Kemr => all.extend(live(ElementKind::Edge).map(|e| vec![e])),
        Operation::RemoveVertex => all.extend(live(ElementKind::Vertex).map(|v| vec![v])),
        Operation::SplitFace | Operation::Mef => {
            for f in live(ElementKind::Face) {
                let corners = face_vertices(mesh, FaceId::new(f));
                for &u in &corners {
                    for &w in &corners {
                        all.push(vec![f, u, w]);
                    }
                }
            }
        }
        Operation::Mev => {
            for v in live(ElementKind::Vertex) {
                let around = edges_at(mesh, VertexId::new(v));
                all.push(vec![v, around.first().copied().unwrap_or(0)]);
                for &x in &around {
                    for &y in &around {
                        all.push(vec![v, x, y]);
                    }
                }
            }
        }
        Operation::Mekr => {
            let boundary = boundary_vertices(mesh);
            for f in live(ElementKind::Face) {
                for u in face_vertices(mesh, FaceId::new(f)) {
                    for &b in &boundary {
                        all.push(vec![f, u, b]);
                    }
                }
            }
        }
    }
    all
}

/// A face's corners, counter-clockwise from its incident edge.
pub fn face_vertices(mesh: &Mesh, f: FaceId) -> Vec<u32> {
    match mesh {
        Mesh::Winged(m) => m.face_vertices(f).map(VertexId::raw).collect(),
        Mesh::Half(m) => m.face_vertices(f).map(VertexId::raw).collect(),
    }
}

/// The edge rows at a vertex, in turn around it.
pub fn edges_at(mesh: &Mesh, v: VertexId) -> Vec<u32> {
    match mesh {
        Mesh::Winged(m) => m.around_vertex(v).map(EdgeId::raw).collect(),
        Mesh::Half(m) => m.around_vertex(v).map(HalfEdgeId::raw).collect(),
    }
}

/// Vertices on a boundary loop, each once.
pub fn boundary_vertices(mesh: &Mesh) -> Vec<u32> {
    let on_boundary = |v: VertexId| match mesh {
        Mesh::Winged(m) => m.around_vertex(v).any(|e| {
            m.edge(e)
                .is_some_and(|row| row.left_face.is_none() || row.right_face.is_none())
        }),
        Mesh::Half(m) => m
            .around_vertex(v)
            .any(|h| m.half_edge(h).is_some_and(|row| row.face.is_none())),
    };
    (0..mesh.count(ElementKind::Vertex) as u32)
        .filter(|&v| mesh.contains(ElementRef::new(ElementKind::Vertex, v)))
        .filter(|&v| on_boundary(VertexId::new(v)))
        .collect()
}

/// Whether an edge row has a face on both sides (in a half-edge mesh: the
/// half-edge and its pair each have one).
pub fn interior(mesh: &Mesh, edge: ElementRef) -> bool {
    let columns: &[Column] = match mesh.structure() {
        Structure::WingedEdge => &[Column::LeftFace, Column::RightFace],
        Structure::HalfEdge => &[Column::Face],
    };
    let faced = |row: ElementRef| {
        columns
            .iter()
            .all(|&c| mesh.reference(row, c).ok().flatten().is_some())
    };
    let pair = match mesh.structure() {
        Structure::HalfEdge => mesh.reference(edge, Column::PairEdge).ok().flatten(),
        Structure::WingedEdge => Some(edge),
    };
    faced(edge) && pair.is_some_and(faced)
}
