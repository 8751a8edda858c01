//! The three tables of a mesh as text, with the columns of the app's table
//! view (one table per element kind, in the papers' vocabulary), `-` for a
//! missing face as in the table files, and coordinates at full precision.
//! For `edgewise tables` and for pasting into notes.

use std::fmt::Write as _;

use crate::mesh::{EdgeId, FaceId, HalfEdgeId, HalfEdgeMesh, Mesh, WingedEdgeMesh};

fn or_dash<T: ToString>(value: Option<T>) -> String {
    value.map_or_else(|| "-".to_owned(), |v| v.to_string())
}

/// Appends a titled table, every column padded to its widest cell.
fn table(out: &mut String, title: &str, columns: &[&str], rows: &[Vec<String>]) {
    let _ = writeln!(out, "{title} ({})", rows.len());
    let mut widths: Vec<usize> = columns.iter().map(|c| c.chars().count()).collect();
    for row in rows {
        for (width, cell) in widths.iter_mut().zip(row) {
            *width = (*width).max(cell.chars().count());
        }
    }
    let mut line = String::new();
    let header = columns.iter().map(|c| (*c).to_owned()).collect::<Vec<_>>();
    for row in std::iter::once(&header).chain(rows) {
        line.clear();
        line.push_str("  ");
        for (i, (cell, &width)) in row.iter().zip(&widths).enumerate() {
            if i > 0 {
                line.push_str("  ");
            }
            let _ = write!(line, "{cell:<width$}");
        }
        out.push_str(line.trim_end());
        out.push('\n');
    }
}

/// The vertex, face and edge (or half-edge) tables of `mesh`.
///
/// ```
/// use edgewise_core::formats;
/// use edgewise_core::mesh::{Mesh, Polygons, Structure};
/// use glam::Vec3;
///
/// let triangle = Polygons::from_triangles(vec![Vec3::ZERO, Vec3::X, Vec3::Y], &[[0, 1, 2]]);
/// let (mesh, _) = Mesh::build(&triangle, Structure::HalfEdge)?;
/// let text = formats::listing(&mesh);
/// assert!(text.contains("half-edges (6)"));
/// # Ok::<(), edgewise_core::mesh::BuildError>(())
/// ```
pub fn listing(mesh: &Mesh) -> String {
    match mesh {
        Mesh::Winged(mesh) => winged(mesh),
        Mesh::Half(mesh) => half(mesh),
    }
}

/// The vertex and face tables, which both structures lay out alike: each
/// row's incident-edge reference as a raw id.
fn vertex_and_face_tables(
    out: &mut String,
    vertices: impl Iterator<Item = (glam::Vec3, Option<u32>)>,
    face_incident_edges: impl Iterator<Item = u32>,
) {
    let rows: Vec<Vec<String>> = vertices
        .enumerate()
        .map(|(id, (position, incident_edge))| {
            vec![
                id.to_string(),
                position.x.to_string(),
                position.y.to_string(),
                position.z.to_string(),
                or_dash(incident_edge),
            ]
        })
        .collect();
    table(
        out,
        "vertices",
        &["id", "x", "y", "z", "incident edge"],
        &rows,
    );
    out.push('\n');
    let rows: Vec<Vec<String>> = face_incident_edges
        .enumerate()
        .map(|(id, edge)| vec![id.to_string(), edge.to_string()])
        .collect();
    table(out, "faces", &["id", "incident edge"], &rows);
    out.push('\n');
}

fn winged(mesh: &WingedEdgeMesh) -> String {
    let mut out = String::from("winged-edge structure\n\n");
    vertex_and_face_tables(
        &mut out,
        mesh.vertices()
            .iter()
            .map(|v| (v.position, v.incident_edge.map(EdgeId::raw))),
        mesh.faces().iter().map(|f| f.incident_edge.raw()),
    );
    let rows: Vec<Vec<String>> = mesh
        .edges()
        .iter()
        .enumerate()
        .map(|(id, e)| {
            vec![
                id.to_string(),
                e.start_vertex.raw().to_string(),
                e.end_vertex.raw().to_string(),
                or_dash(e.left_face.map(FaceId::raw)),
                or_dash(e.right_face.map(FaceId::raw)),
                e.left_predecessor.raw().to_string(),
                e.left_successor.raw().to_string(),
                e.right_predecessor.raw().to_string(),
                e.right_successor.raw().to_string(),
            ]
        })
        .collect();
    table(
        &mut out,
        "edges",
        &[
            "id",
            "start",
            "end",
            "left face",
            "right face",
            "left pred",
            "left succ",
            "right pred",
            "right succ",
        ],
        &rows,
    );
    out
}

fn half(mesh: &HalfEdgeMesh) -> String {
    let mut out = String::from("half-edge structure\n\n");
    vertex_and_face_tables(
        &mut out,
        mesh.vertices()
            .iter()
            .map(|v| (v.position, v.incident_edge.map(HalfEdgeId::raw))),
        mesh.faces().iter().map(|f| f.incident_edge.raw()),
    );
    let rows: Vec<Vec<String>> = mesh
        .half_edges()
        .iter()
        .enumerate()
        .map(|(id, h)| {
            vec![
                id.to_string(),
                h.end_vertex.raw().to_string(),
                or_dash(h.face.map(FaceId::raw)),
                h.pair_edge.raw().to_string(),
                h.successor_edge.raw().to_string(),
                or_dash(
                    mesh.start_vertex(HalfEdgeId::new(id as u32))
                        .map(crate::mesh::VertexId::raw),
                ),
                or_dash(
                    mesh.predecessor_edge(HalfEdgeId::new(id as u32))
                        .map(HalfEdgeId::raw),
                ),
            ]
        })
        .collect();
    table(
        &mut out,
        "half-edges",
        &[
            "id",
            "end vertex",
            "face",
            "pair",
            "successor",
            "start vertex",
            "predecessor",
        ],
        &rows,
    );
    out.push_str("\nstart vertex and predecessor are derived (pair's end vertex, inverse of successor), not stored.\n");
    out
}
