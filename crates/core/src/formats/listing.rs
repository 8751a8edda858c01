//! The three tables of a mesh as text, with the columns of the app's table
//! view (one table per element kind, in the papers' vocabulary), `-` for a
//! missing face as in the table files, and coordinates at full precision.
//! For `edgewise tables` and for pasting into notes.

use std::fmt::Write as _;

use crate::mesh::{Mesh, VertexId};
use crate::schema::{Column, ElementKind, ElementRef, Records, Storage, Structure};

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
    let structure = mesh.structure();
    let mut out = format!("{} structure\n\n", structure.prose());
    for kind in [ElementKind::Vertex, ElementKind::Face, ElementKind::Edge] {
        let entries = Column::table(structure, kind);
        let mut headers = vec!["id"];
        for entry in entries {
            match entry.column {
                Column::Position => headers.extend(Column::COORDINATES),
                _ => headers.push(entry.header),
            }
        }
        let rows: Vec<Vec<String>> = (0..mesh.count(kind))
            .map(|index| {
                let id = u32::try_from(index).unwrap_or(u32::MAX);
                let element = ElementRef::new(kind, id);
                let mut row = vec![id.to_string()];
                for entry in entries {
                    if entry.column == Column::Position {
                        let p = mesh.position(VertexId::new(id)).unwrap_or_default();
                        row.extend([p.x, p.y, p.z].map(|c| c.to_string()));
                    } else {
                        let target = mesh.reference(element, entry.column).ok().flatten();
                        row.push(or_dash(target.map(|t| t.id)));
                    }
                }
                row
            })
            .collect();
        let title = match (kind, structure) {
            (ElementKind::Edge, Structure::HalfEdge) => "half-edges",
            _ => kind.plural(),
        };
        table(&mut out, title, &headers, &rows);
        if kind != ElementKind::Edge {
            out.push('\n');
        }
    }
    let derived: Vec<&str> = Column::table(structure, ElementKind::Edge)
        .iter()
        .filter(|entry| entry.storage == Storage::Derived)
        .map(|entry| entry.header)
        .collect();
    if !derived.is_empty() {
        out.push_str(&format!(
            "\n{} are derived (pair's end vertex, inverse of successor), not stored.\n",
            derived.join(" and ")
        ));
    }
    out
}
