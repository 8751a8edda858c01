//! `.htb`: the half-edge tables as written, one row per vertex, face and
//! half-edge (format in `docs/formats.md`).

use super::error::FormatError;
use super::rows::{self, Problems, Rows, Section};
use super::wtb;
use crate::mesh::half_edge::{Face, Vertex};
use crate::mesh::{Element, FaceId, HalfEdge, HalfEdgeId, HalfEdgeMesh, Mesh, VertexId};

const HALF_EDGES: Section = Section {
    name: "halfedges",
    element: "half-edge",
    columns: &["end_vertex", "face", "pair_edge", "successor_edge"],
};

pub(super) fn read(bytes: &[u8]) -> Result<Mesh, FormatError> {
    let text = super::text(bytes)?;
    let mut rows = Rows::new(text);
    rows::header(&mut rows, "htb", "wtb")?;
    let mut problems = Problems::new();
    let (vertices, vertex_places) = wtb::read_vertices(&mut rows, &mut problems, "a half-edge")?;
    let (faces, face_places) = wtb::read_faces(&mut rows, &mut problems, "a half-edge")?;
    let mut half_edges = Vec::new();
    let half_edge_places = rows::section(
        &mut rows,
        &HALF_EDGES,
        &mut problems,
        |fields, line, problems| {
            if let [end, face, pair, successor] = fields {
                let end = rows::reference(end, "end_vertex", "a vertex", false, line, problems);
                let face = rows::reference(face, "face", "a face", true, line, problems);
                let mut half = |token, name| {
                    rows::reference(token, name, "a half-edge", false, line, problems).unwrap_or(0)
                };
                half_edges.push(HalfEdge {
                    end_vertex: VertexId::new(end.unwrap_or(0)),
                    face: face.map(FaceId::new),
                    pair_edge: HalfEdgeId::new(half(pair, "pair_edge")),
                    successor_edge: HalfEdgeId::new(half(successor, "successor_edge")),
                });
            }
        },
    )?;
    rows::end(&mut rows, &HALF_EDGES, half_edges.len())?;
    problems.finish()?;

    let mesh = HalfEdgeMesh::from_raw_parts(
        vertices
            .into_iter()
            .map(|(position, incident)| Vertex {
                position,
                incident_edge: incident.map(HalfEdgeId::new),
            })
            .collect(),
        faces
            .into_iter()
            .map(|incident| Face {
                incident_edge: HalfEdgeId::new(incident),
            })
            .collect(),
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
    wtb::write_vertices(
        &mut out,
        mesh.vertices()
            .iter()
            .map(|v| (v.position, v.incident_edge.map(HalfEdgeId::raw))),
    );
    wtb::write_faces(&mut out, mesh.faces().iter().map(|f| f.incident_edge.raw()));
    let rows: Vec<Vec<String>> = mesh
        .half_edges()
        .iter()
        .enumerate()
        .map(|(id, h)| {
            vec![
                id.to_string(),
                h.end_vertex.raw().to_string(),
                rows::cell(h.face.map(FaceId::raw)),
                h.pair_edge.raw().to_string(),
                h.successor_edge.raw().to_string(),
            ]
        })
        .collect();
    out.push_str(&format!("\nhalfedges {}\n", rows.len()));
    let mut columns = vec!["id"];
    columns.extend(HALF_EDGES.columns);
    rows::write_table(&mut out, &columns, &rows);
    out
}
