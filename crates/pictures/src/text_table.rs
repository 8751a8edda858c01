//! The three tables as plain data for writers other than the app's own
//! view: the screen readers' HTML, and the SVG and PDF pictures.

use edgewise_core::mesh::{Mesh, VertexId};
use edgewise_core::schema::{Column, ElementKind, ElementRef, Records as _};

/// The edge table's title: "Half-edges" in a half-edge mesh.
pub fn edge_table_title(mesh: &Mesh) -> &'static str {
    match mesh {
        Mesh::Winged(_) => "Edges",
        Mesh::Half(_) => "Half-edges",
    }
}

/// How a row is named to a reader: "half-edge 3" in a half-edge mesh.
pub fn row_name(mesh: &Mesh, element: ElementRef) -> String {
    match (mesh, element.kind) {
        (Mesh::Half(_), ElementKind::Edge) => format!("half-edge {}", element.id),
        _ => element.to_string(),
    }
}

/// One cell of a table as text writers see it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Cell {
    /// A reference: the element named, or none.
    Reference(Option<ElementRef>),
    Coordinate(f32),
}

/// One of the three tables, for writers other than the app's own view
/// (the screen readers' HTML, the SVG and PDF exports).
#[derive(Clone, Debug, PartialEq)]
pub struct TextTable {
    pub kind: ElementKind,
    /// "Faces", "Edges", "Half-edges", "Vertices".
    pub title: &'static str,
    /// Rows in the mesh (deleted ones included).
    pub count: usize,
    /// After `id`: one per cell, `x`, `y` and `z` for a position.
    pub headers: Vec<&'static str>,
    /// The same, as the journal's Table 1 shortens them ("L pred.").
    pub short: Vec<&'static str>,
    /// The first rows, up to the limit asked for; `None` cells for a
    /// deleted row.
    pub rows: Vec<(ElementRef, Option<Vec<Cell>>)>,
}

/// The three tables of `mesh` in the app's order, each with at most
/// `max_rows` rows.
pub fn text_tables(mesh: &Mesh, max_rows: usize) -> Vec<TextTable> {
    [
        (ElementKind::Face, "Faces"),
        (ElementKind::Edge, edge_table_title(mesh)),
        (ElementKind::Vertex, "Vertices"),
    ]
    .into_iter()
    .map(|(kind, title)| {
        let rows = 0..mesh.count(kind).min(max_rows) as u32;
        text_table(mesh, kind, title, rows)
    })
    .collect()
}

/// The tables of `mesh` with only the rows of `elements`, in id order;
/// a table with none of them is left out. A handout's page shows these.
pub fn text_rows(mesh: &Mesh, elements: &[ElementRef]) -> Vec<TextTable> {
    [
        (ElementKind::Face, "Faces"),
        (ElementKind::Edge, edge_table_title(mesh)),
        (ElementKind::Vertex, "Vertices"),
    ]
    .into_iter()
    .filter_map(|(kind, title)| {
        let mut ids: Vec<u32> = elements
            .iter()
            .filter(|e| e.kind == kind && (e.id as usize) < mesh.count(kind))
            .map(|e| e.id)
            .collect();
        ids.sort_unstable();
        ids.dedup();
        (!ids.is_empty()).then(|| text_table(mesh, kind, title, ids))
    })
    .collect()
}

fn text_table(
    mesh: &Mesh,
    kind: ElementKind,
    title: &'static str,
    ids: impl IntoIterator<Item = u32>,
) -> TextTable {
    let count = mesh.count(kind);
    let columns = Column::table(mesh.structure(), kind);
    let (mut headers, mut short) = (Vec::new(), Vec::new());
    for entry in columns {
        if entry.column == Column::Position {
            headers.extend(["x", "y", "z"]);
            short.extend(["x", "y", "z"]);
        } else {
            headers.push(entry.header);
            short.push(entry.short);
        }
    }
    let rows = ids
        .into_iter()
        .map(|id| {
            let element = ElementRef { kind, id };
            if !mesh.contains(element) {
                return (element, None);
            }
            let mut cells = Vec::with_capacity(headers.len());
            for entry in columns {
                if entry.column == Column::Position {
                    let p = mesh.position(VertexId::new(id)).unwrap_or_default();
                    cells.extend([p.x, p.y, p.z].map(Cell::Coordinate));
                } else {
                    let target = mesh.reference(element, entry.column).ok().flatten();
                    cells.push(Cell::Reference(target));
                }
            }
            (element, Some(cells))
        })
        .collect();
    TextTable {
        kind,
        title,
        count,
        headers,
        short,
        rows,
    }
}
