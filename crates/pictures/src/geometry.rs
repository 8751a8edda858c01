//! The mesh as a view draws it: its positions, one arrow per winged edge or
//! half-edge, and its faces, taken from the structure when it changes.

use glam::Vec3;

/// The mesh as the view draws it.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct MeshGeometry {
    pub positions: Vec<Vec3>,
    /// One per drawn arrow: a winged edge, or a half-edge (then `face` is its
    /// own face, None on the boundary, and `pair` its pair index so offsets
    /// go to opposite sides).
    pub edges: Vec<EdgeGeometry>,
    /// Each face's vertex ids in CCW (OBJ) order.
    pub faces: Vec<Vec<u32>>,
    pub half_edges: bool,
}

impl MeshGeometry {
    /// The geometry of a winged-edge or half-edge mesh: one arrow per winged
    /// edge or per half-edge, numbered like the structure's edge table.
    pub fn from_mesh(mesh: &edgewise_core::mesh::Mesh) -> Self {
        use edgewise_core::mesh::{HalfEdgeId, Mesh};
        let faces = mesh.to_polygons().faces().map(<[u32]>::to_vec).collect();
        match mesh {
            Mesh::Winged(winged) => Self {
                positions: mesh.positions(),
                edges: winged
                    .edges()
                    .iter()
                    .map(|e| EdgeGeometry {
                        start: e.start_vertex.raw(),
                        end: e.end_vertex.raw(),
                        face: None,
                        pair: None,
                    })
                    .collect(),
                faces,
                half_edges: false,
            },
            Mesh::Half(half) => Self {
                positions: mesh.positions(),
                edges: (0_u32..)
                    .zip(half.half_edges())
                    .map(|(h, edge)| EdgeGeometry {
                        start: half
                            .start_vertex(HalfEdgeId::new(h))
                            .map_or(edge.end_vertex.raw(), edgewise_core::mesh::VertexId::raw),
                        end: edge.end_vertex.raw(),
                        face: edge.face.map(edgewise_core::mesh::FaceId::raw),
                        pair: Some(edge.pair_edge.raw()),
                    })
                    .collect(),
                faces,
                half_edges: true,
            },
        }
    }
}

/// One drawn arrow.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct EdgeGeometry {
    pub start: u32,
    pub end: u32,
    pub face: Option<u32>,
    pub pair: Option<u32>,
}
