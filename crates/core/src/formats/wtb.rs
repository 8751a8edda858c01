//! `.wtb`: the winged-edge tables as written, one row per vertex, face and
//! edge (format in `docs/formats.md`).

use glam::Vec3;

use super::error::FormatError;
use super::rows::{self, Problems, RowPlaces, Rows, Section};
use crate::mesh::winged_edge::{Face, Vertex};
use crate::mesh::{Element, Mesh, WingedEdge, WingedEdgeMesh};
use crate::schema::{Column, ElementKind, Record, Structure};

/// The vertex section of `structure`'s file.
pub(super) fn vertex_section(structure: Structure) -> Section {
    Section {
        name: "vertices",
        element: "vertex",
        table: (structure, ElementKind::Vertex),
    }
}

/// The face section of `structure`'s file.
pub(super) fn face_section(structure: Structure) -> Section {
    Section {
        name: "faces",
        element: "face",
        table: (structure, ElementKind::Face),
    }
}

const EDGES: Section = Section {
    name: "edges",
    element: "edge",
    table: (Structure::WingedEdge, ElementKind::Edge),
};

/// Reads the vertex section, shared with `.htb`: each row's position and
/// its record's references.
pub(super) fn read_vertices<V: Record>(
    rows: &mut Rows<'_>,
    problems: &mut Problems,
    structure: Structure,
) -> Result<(Vec<(Vec3, V)>, RowPlaces), FormatError> {
    let mut vertices = Vec::new();
    let section = vertex_section(structure);
    let places = rows::section(rows, &section, problems, |fields, line, problems| {
        if let [x, y, z, ..] = fields {
            let [x_name, y_name, z_name] = Column::COORDINATES;
            let position = Vec3::new(
                rows::coordinate(x, x_name, line, problems),
                rows::coordinate(y, y_name, line, problems),
                rows::coordinate(z, z_name, line, problems),
            );
            let mut vertex = V::default();
            rows::fill(&mut vertex, fields, &section, line, problems);
            vertices.push((position, vertex));
        }
    })?;
    Ok((vertices, places))
}

/// Reads the face section, shared with `.htb`.
pub(super) fn read_faces<F: Record>(
    rows: &mut Rows<'_>,
    problems: &mut Problems,
    structure: Structure,
) -> Result<(Vec<F>, RowPlaces), FormatError> {
    let mut faces = Vec::new();
    let section = face_section(structure);
    let places = rows::section(rows, &section, problems, |fields, line, problems| {
        let mut face = F::default();
        rows::fill(&mut face, fields, &section, line, problems);
        faces.push(face);
    })?;
    Ok((faces, places))
}

pub(super) fn read(bytes: &[u8]) -> Result<Mesh, FormatError> {
    let text = super::text(bytes)?;
    let mut rows = Rows::new(text);
    rows::header(&mut rows, "wtb", "htb")?;
    let mut problems = Problems::new();
    let (vertices, vertex_places) =
        read_vertices::<Vertex>(&mut rows, &mut problems, Structure::WingedEdge)?;
    let (faces, face_places) = read_faces::<Face>(&mut rows, &mut problems, Structure::WingedEdge)?;
    let mut edges = Vec::new();
    let edge_places = rows::section(
        &mut rows,
        &EDGES,
        &mut problems,
        |fields, line, problems| {
            let mut edge = WingedEdge::default();
            rows::fill(&mut edge, fields, &EDGES, line, problems);
            edges.push(edge);
        },
    )?;
    rows::end(&mut rows, &EDGES, edges.len())?;
    problems.finish()?;

    let mesh = WingedEdgeMesh::from_raw_parts(
        vertices
            .into_iter()
            .map(|(position, vertex)| Vertex { position, ..vertex })
            .collect(),
        faces,
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

pub(super) fn write(mesh: &WingedEdgeMesh) -> String {
    let mut out = String::from(
        "# Winged-edge tables (Edgewise .wtb, see docs/formats.md). Ids count from 0;\n\
         # faces are traversed clockwise seen from outside; - is the boundary.\n\
         wtb 1\n",
    );
    rows::write_section(&mut out, mesh, &vertex_section(Structure::WingedEdge));
    rows::write_section(&mut out, mesh, &face_section(Structure::WingedEdge));
    rows::write_section(&mut out, mesh, &EDGES);
    out
}
