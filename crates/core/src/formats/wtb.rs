//! `.wtb`: the winged-edge tables as written, one row per vertex, face and
//! edge (format in `docs/formats.md`).

use glam::Vec3;

use super::rows::Section;
use super::tables::TableFile;
use crate::mesh::winged_edge::Vertex;
use crate::mesh::{Element, Issue, Mesh, WingedEdgeMesh};
use crate::schema::{ElementKind, Structure};

impl TableFile for WingedEdgeMesh {
    const MAGIC: &'static str = "wtb";
    const OTHER: &'static str = "htb";
    const PREAMBLE: &'static str = "# Winged-edge tables (Edgewise .wtb, see docs/formats.md). Ids count from 0;\n\
         # faces are traversed clockwise seen from outside; - is the boundary.\n";
    const EDGES: Section = Section {
        name: "edges",
        element: "edge",
        table: (Structure::WingedEdge, ElementKind::Edge),
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
        matches!(element, Element::Edge(_))
    }

    fn into_mesh(self) -> Mesh {
        Mesh::Winged(self)
    }

    fn validate(&self) -> Vec<Issue> {
        WingedEdgeMesh::validate(self)
    }
}
