//! `.wtb`: the winged-edge tables as written, one row per vertex, face and
//! edge (format in `docs/formats.md`).

use glam::Vec3;

use super::error::FormatError;
use super::rows::{self, Problems, RowPlaces, Rows, Section};
use crate::mesh::winged_edge::{Face, Vertex};
use crate::mesh::{EdgeId, Element, FaceId, Mesh, VertexId, WingedEdge, WingedEdgeMesh};

pub(super) const VERTICES: Section = Section {
    name: "vertices",
    element: "vertex",
    columns: &["x", "y", "z", "incident_edge"],
};
pub(super) const FACES: Section = Section {
    name: "faces",
    element: "face",
    columns: &["incident_edge"],
};
const EDGES: Section = Section {
    name: "edges",
    element: "edge",
    columns: &[
        "start_vertex",
        "end_vertex",
        "left_face",
        "right_face",
        "left_predecessor",
        "left_successor",
        "right_predecessor",
        "right_successor",
    ],
};

/// Vertex rows as read: position and incident edge number.
pub(super) type VertexRows = Vec<(Vec3, Option<u32>)>;

/// Reads the vertex section, shared with `.htb` (whose incident edges are
/// half-edges; `edge` names the kind).
pub(super) fn read_vertices(
    rows: &mut Rows<'_>,
    problems: &mut Problems,
    edge: &str,
) -> Result<(VertexRows, RowPlaces), FormatError> {
    let mut vertices = Vec::new();
    let places = rows::section(rows, &VERTICES, problems, |fields, line, problems| {
        if let [x, y, z, incident] = fields {
            let position = Vec3::new(
                rows::coordinate(x, "x", line, problems),
                rows::coordinate(y, "y", line, problems),
                rows::coordinate(z, "z", line, problems),
            );
            let incident = rows::reference(incident, "incident_edge", edge, true, line, problems);
            vertices.push((position, incident));
        }
    })?;
    Ok((vertices, places))
}

/// Reads the face section, shared with `.htb`.
pub(super) fn read_faces(
    rows: &mut Rows<'_>,
    problems: &mut Problems,
    edge: &str,
) -> Result<(Vec<u32>, RowPlaces), FormatError> {
    let mut faces = Vec::new();
    let places = rows::section(rows, &FACES, problems, |fields, line, problems| {
        if let [incident] = fields {
            let incident = rows::reference(incident, "incident_edge", edge, false, line, problems);
            faces.push(incident.unwrap_or(0));
        }
    })?;
    Ok((faces, places))
}

pub(super) fn read(bytes: &[u8]) -> Result<Mesh, FormatError> {
    let text = super::text(bytes)?;
    let mut rows = Rows::new(text);
    rows::header(&mut rows, "wtb", "htb")?;
    let mut problems = Problems::new();
    let (vertices, vertex_places) = read_vertices(&mut rows, &mut problems, "an edge")?;
    let (faces, face_places) = read_faces(&mut rows, &mut problems, "an edge")?;
    let mut edges = Vec::new();
    let edge_places = rows::section(
        &mut rows,
        &EDGES,
        &mut problems,
        |fields, line, problems| {
            if let [start, end, left, right, lp, ls, rp, rs] = fields {
                let mut vertex = |token, name| {
                    rows::reference(token, name, "a vertex", false, line, problems).unwrap_or(0)
                };
                let (start, end) = (vertex(start, "start_vertex"), vertex(end, "end_vertex"));
                let left = rows::reference(left, "left_face", "a face", true, line, problems);
                let right = rows::reference(right, "right_face", "a face", true, line, problems);
                let mut wing = |token, name| {
                    rows::reference(token, name, "an edge", false, line, problems).unwrap_or(0)
                };
                edges.push(WingedEdge {
                    start_vertex: VertexId::new(start),
                    end_vertex: VertexId::new(end),
                    left_face: left.map(FaceId::new),
                    right_face: right.map(FaceId::new),
                    left_predecessor: EdgeId::new(wing(lp, "left_predecessor")),
                    left_successor: EdgeId::new(wing(ls, "left_successor")),
                    right_predecessor: EdgeId::new(wing(rp, "right_predecessor")),
                    right_successor: EdgeId::new(wing(rs, "right_successor")),
                });
            }
        },
    )?;
    rows::end(&mut rows, &EDGES, edges.len())?;
    problems.finish()?;

    let mesh = WingedEdgeMesh::from_raw_parts(
        vertices
            .into_iter()
            .map(|(position, incident)| Vertex {
                position,
                incident_edge: incident.map(EdgeId::new),
            })
            .collect(),
        faces
            .into_iter()
            .map(|incident| Face {
                incident_edge: EdgeId::new(incident),
            })
            .collect(),
        edges,
    );
    let issues = mesh.validate();
    if issues.is_empty() {
        return Ok(Mesh::Winged(mesh));
    }
    Err(rows::place_issues(issues, text, |element| match element {
        Element::Vertex(_) => Some(&vertex_places),
        Element::Face(_) => Some(&face_places),
        Element::Edge(_) => Some(&edge_places),
        Element::HalfEdge(_) => None,
    }))
}

/// The vertex section, shared with `.htb`.
pub(super) fn write_vertices(
    out: &mut String,
    vertices: impl Iterator<Item = (Vec3, Option<u32>)>,
) {
    let rows: Vec<Vec<String>> = vertices
        .enumerate()
        .map(|(id, (p, incident))| {
            vec![
                id.to_string(),
                p.x.to_string(),
                p.y.to_string(),
                p.z.to_string(),
                rows::cell(incident),
            ]
        })
        .collect();
    out.push_str(&format!("\nvertices {}\n", rows.len()));
    let mut columns = vec!["id"];
    columns.extend(VERTICES.columns);
    rows::write_table(out, &columns, &rows);
}

/// The face section, shared with `.htb`.
pub(super) fn write_faces(out: &mut String, faces: impl Iterator<Item = u32>) {
    let rows: Vec<Vec<String>> = faces
        .enumerate()
        .map(|(id, incident)| vec![id.to_string(), incident.to_string()])
        .collect();
    out.push_str(&format!("\nfaces {}\n", rows.len()));
    let mut columns = vec!["id"];
    columns.extend(FACES.columns);
    rows::write_table(out, &columns, &rows);
}

pub(super) fn write(mesh: &WingedEdgeMesh) -> String {
    let mut out = String::from(
        "# Winged-edge tables (Edgewise .wtb, see docs/formats.md). Ids count from 0;\n\
         # faces are traversed clockwise seen from outside; - is the boundary.\n\
         wtb 1\n",
    );
    write_vertices(
        &mut out,
        mesh.vertices()
            .iter()
            .map(|v| (v.position, v.incident_edge.map(EdgeId::raw))),
    );
    write_faces(&mut out, mesh.faces().iter().map(|f| f.incident_edge.raw()));
    let rows: Vec<Vec<String>> = mesh
        .edges()
        .iter()
        .enumerate()
        .map(|(id, e)| {
            vec![
                id.to_string(),
                e.start_vertex.raw().to_string(),
                e.end_vertex.raw().to_string(),
                rows::cell(e.left_face.map(FaceId::raw)),
                rows::cell(e.right_face.map(FaceId::raw)),
                e.left_predecessor.raw().to_string(),
                e.left_successor.raw().to_string(),
                e.right_predecessor.raw().to_string(),
                e.right_successor.raw().to_string(),
            ]
        })
        .collect();
    out.push_str(&format!("\nedges {}\n", rows.len()));
    let mut columns = vec!["id"];
    columns.extend(EDGES.columns);
    rows::write_table(&mut out, &columns, &rows);
    out
}
