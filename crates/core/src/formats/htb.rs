//! `.htb`: the half-edge tables as written, one row per vertex, face and
//! half-edge (format in `docs/formats.md`).

use glam::Vec3;

use super::rows::Section;
use super::tables::TableFile;
use crate::mesh::half_edge::Vertex;
use crate::mesh::{Element, HalfEdgeMesh, Issue, Mesh};
use crate::schema::{ElementKind, Structure};

impl TableFile for HalfEdgeMesh {
    const MAGIC: &'static str = "htb";
    const OTHER: &'static str = "wtb";
    const PREAMBLE: &'static str = "# Half-edge tables (Edgewise .htb, see docs/formats.md). Ids count from 0;\n\
         # successors go counter-clockwise around their face; a vertex's incident\n\
         # half-edge ends at it; - is the boundary.\n";
    const EDGES: Section = Section {
        name: "halfedges",
        element: "half-edge",
        table: (Structure::HalfEdge, ElementKind::Edge),
    };

    fn from_tables(
        vertices: Vec<(Vec3, Vertex)>,
        faces: Vec<Self::Face>,
        edges: Vec<Self::Edge>,
    ) -> Self {
        let vertices = vertices
            .into_iter()
            .map(|(position, vertex)| Vertex { position, ..vertex })
            .collect();
        Self::from_raw_parts(vertices, faces, edges)
    }

    fn is_edge_row(element: Element) -> bool {
        matches!(element, Element::HalfEdge(_))
    }

    fn into_mesh(self) -> Mesh {
        Mesh::Half(self)
    }

    fn validate(&self) -> Vec<Issue> {
        HalfEdgeMesh::validate(self)
    }
}
