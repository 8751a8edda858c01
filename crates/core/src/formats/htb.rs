//! `.htb`: the half-edge tables as written, one row per vertex, face and
//! half-edge (format in `docs/formats.md`).

use super::error::FormatError;
use super::rows::{self, Problems, Rows, Section};
use super::wtb;
use crate::mesh::half_edge::{Face, Vertex};
use crate::mesh::{Element, HalfEdge, HalfEdgeMesh, Mesh};
use crate::schema::{ElementKind, Structure};

const HALF_EDGES: Section = Section {
    name: "halfedges",
    element: "half-edge",
    table: (Structure::HalfEdge, ElementKind::Edge),
};

pub(super) fn read(bytes: &[u8]) -> Result<Mesh, FormatError> {
    let text = super::text(bytes)?;
    let mut rows = Rows::new(text);
    rows::header(&mut rows, "htb", "wtb")?;
    let mut problems = Problems::new();
    let (vertices, vertex_places) =
        wtb::read_vertices::<Vertex>(&mut rows, &mut problems, Structure::HalfEdge)?;
    let (faces, face_places) =
        wtb::read_faces::<Face>(&mut rows, &mut problems, Structure::HalfEdge)?;
    let mut half_edges = Vec::new();
    let half_edge_places = rows::section(
        &mut rows,
        &HALF_EDGES,
        &mut problems,
        |fields, line, problems| {
            let mut half_edge = HalfEdge::default();
            rows::fill(&mut half_edge, fields, &HALF_EDGES, line, problems);
            half_edges.push(half_edge);
        },
    )?;
    rows::end(&mut rows, &HALF_EDGES, half_edges.len())?;
    problems.finish()?;

    let mesh = HalfEdgeMesh::from_raw_parts(
        vertices
            .into_iter()
            .map(|(position, vertex)| Vertex { position, ..vertex })
            .collect(),
        faces,
        half_edges,
    );
    let issues = mesh.validate();
    if issues.is_empty() {
        return Ok(Mesh::Half(mesh));
    }
    Err(rows::place_issues(issues, text, |element| match element {
        Element::Vertex(_) => Some(&vertex_places),
        Element::Face(_) => Some(&face_places),
        Element::HalfEdge(_) => Some(&half_edge_places),
        Element::Edge(_) => None,
    }))
}

pub(super) fn write(mesh: &HalfEdgeMesh) -> String {
    let mut out = String::from(
        "# Half-edge tables (Edgewise .htb, see docs/formats.md). Ids count from 0;\n\
         # successors go counter-clockwise around their face; a vertex's incident\n\
         # half-edge ends at it; - is the boundary.\n\
         htb 1\n",
    );
    rows::write_section(&mut out, mesh, &wtb::vertex_section(Structure::HalfEdge));
    rows::write_section(&mut out, mesh, &wtb::face_section(Structure::HalfEdge));
    rows::write_section(&mut out, mesh, &HALF_EDGES);
    out
}
