//! What a screen reader gets in place of the canvas, which is one image to
//! it: the three tables as HTML tables with captions and headers, each row's
//! roles as words (a second cue beside colour), and the message line's
//! sentence (the step, or the selection and its references), announced as
//! it changes. The browser platform puts them in a visually hidden part of
//! the page (index.html); natively egui's AccessKit output serves instead.

use std::collections::BTreeMap;
use std::fmt::Write as _;

use edgewise_core::mesh::{Mesh, VertexId};
use edgewise_core::schema::{Column, ElementKind, ElementRef, Records as _};

use crate::{state::HighlightState, tables};

/// Rows mirrored per table; a larger mesh's caption says how many are left
/// out (its rows are still read in the app's tables through AccessKit).
pub const MAX_ROWS: usize = 300;

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
    /// The first rows, up to the limit asked for; `None` cells for a
    /// deleted row.
    pub rows: Vec<(ElementRef, Option<Vec<Cell>>)>,
}

/// The three tables of `mesh` in the app's order, each with at most
/// `max_rows` rows.
pub fn text_tables(mesh: &Mesh, max_rows: usize) -> Vec<TextTable> {
    [
        (ElementKind::Face, "Faces"),
        (ElementKind::Edge, tables::edge_table_title(mesh)),
        (ElementKind::Vertex, "Vertices"),
    ]
    .into_iter()
    .map(|(kind, title)| text_table(mesh, kind, title, max_rows))
    .collect()
}

fn text_table(mesh: &Mesh, kind: ElementKind, title: &'static str, max_rows: usize) -> TextTable {
    let count = mesh.count(kind);
    let columns = Column::table(mesh.structure(), kind);
    let mut headers = Vec::new();
    for entry in columns {
        if entry.column == Column::Position {
            headers.extend(["x", "y", "z"]);
        } else {
            headers.push(entry.header);
        }
    }
    let rows = (0..count.min(max_rows) as u32)
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
        rows,
    }
}

/// The three tables of `mesh` as HTML, with each highlighted row's roles
/// ([`role_words`]) in a last column.
pub fn tables_html(mesh: &Mesh, roles: &BTreeMap<ElementRef, String>) -> String {
    let mut html = String::new();
    for table in text_tables(mesh, MAX_ROWS) {
        table_html(&mut html, mesh, &table, roles);
    }
    html
}

/// Each highlighted row's roles in words, once each: its role cell's text.
pub fn role_words(highlights: &[HighlightState]) -> BTreeMap<ElementRef, String> {
    let mut roles: BTreeMap<ElementRef, Vec<&str>> = BTreeMap::new();
    for highlight in highlights {
        let entry = roles
            .entry(ElementRef::new(highlight.kind, highlight.id))
            .or_default();
        if !entry.contains(&highlight.role.as_str()) {
            entry.push(&highlight.role);
        }
    }
    roles
        .into_iter()
        .map(|(element, words)| (element, words.join(", ")))
        .collect()
}

/// The HTML id of `element`'s role cell in [`tables_html`].
pub fn role_cell_id(element: ElementRef) -> String {
    let kind = match element.kind {
        ElementKind::Vertex => 'v',
        ElementKind::Edge => 'e',
        ElementKind::Face => 'f',
    };
    format!("edgewise_a11y_role_{kind}{}", element.id)
}

/// The role cells whose words differ from `before` to `after`, by HTML id,
/// with their new words: when only the highlights move, these few cells
/// change instead of the whole tables (which Chromium would parse and lay
/// out again, 70 to 110 ms for 900 rows under `SwiftShader`). Rows past
/// [`MAX_ROWS`] are not mirrored.
pub fn role_changes(
    before: &BTreeMap<ElementRef, String>,
    after: &BTreeMap<ElementRef, String>,
) -> Vec<(String, String)> {
    let gone = before
        .keys()
        .filter(|element| !after.contains_key(element))
        .map(|element| (*element, String::new()));
    let changed = after
        .iter()
        .filter(|(element, words)| before.get(element) != Some(words))
        .map(|(element, words)| (*element, words.clone()));
    gone.chain(changed)
        .filter(|(element, _)| (element.id as usize) < MAX_ROWS)
        .map(|(element, words)| (role_cell_id(element), words))
        .collect()
}

fn table_html(
    html: &mut String,
    mesh: &Mesh,
    table: &TextTable,
    roles: &BTreeMap<ElementRef, String>,
) {
    let _ = write!(
        html,
        "<table><caption>{}: {} rows",
        table.title, table.count
    );
    if table.rows.len() < table.count {
        let _ = write!(html, ", the first {} here", table.rows.len());
    }
    html.push_str("</caption><thead><tr><th scope=\"col\">id</th>");
    for header in &table.headers {
        let _ = write!(html, "<th scope=\"col\">{header}</th>");
    }
    html.push_str("<th scope=\"col\">role</th></tr></thead><tbody>");
    for (element, cells) in &table.rows {
        let _ = write!(
            html,
            "<tr><th scope=\"row\">{}</th>",
            tables::row_name(mesh, *element)
        );
        let Some(cells) = cells else {
            let _ = write!(
                html,
                "<td colspan=\"{}\">deleted</td></tr>",
                table.headers.len() + 1
            );
            continue;
        };
        for cell in cells {
            match cell {
                Cell::Coordinate(x) => {
                    let _ = write!(html, "<td>{x:.3}</td>");
                }
                Cell::Reference(Some(target)) => {
                    let _ = write!(html, "<td>{}</td>", tables::row_name(mesh, *target));
                }
                Cell::Reference(None) => html.push_str("<td>none</td>"),
            }
        }
        let role = roles.get(element).map_or("", String::as_str);
        let id = role_cell_id(*element);
        let _ = write!(html, "<td id=\"{id}\">{role}</td></tr>");
    }
    html.push_str("</tbody></table>");
}

#[cfg(test)]
mod tests {
    use edgewise_core::mesh::{Structure, generate};

    use super::*;

    #[test]
    fn the_tables_have_captions_headers_and_roles_in_words() {
        let (mesh, _) = Mesh::build(&generate::tetrahedron(), Structure::HalfEdge).expect("builds");
        let highlights = [HighlightState {
            kind: ElementKind::Edge,
            id: 3,
            role: "selected".to_owned(),
            colour: "#ff0000".to_owned(),
        }];
        let html = tables_html(&mesh, &role_words(&highlights));
        assert_eq!(html.matches("<table>").count(), 3);
        assert!(html.contains("<caption>Faces: 4 rows</caption>"), "{html}");
        assert!(
            html.contains("<caption>Half-edges: 12 rows</caption>"),
            "{html}"
        );
        assert!(html.contains("<th scope=\"col\">pair</th>"), "{html}");
        assert!(
            html.contains("<tr><th scope=\"row\">half-edge 3</th>"),
            "{html}"
        );
        assert!(
            html.contains("<td id=\"edgewise_a11y_role_e3\">selected</td></tr>"),
            "{html}"
        );
        assert!(
            html.contains("<td>0.500</td><td>0.800</td><td>-0.300</td>"),
            "{html}"
        );
    }

    #[test]
    fn a_large_mesh_is_mirrored_in_part_and_says_so() {
        let (mesh, _) =
            Mesh::build(&generate::grid(30, 30), Structure::WingedEdge).expect("builds");
        let html = tables_html(&mesh, &BTreeMap::new());
        assert!(
            html.contains("Faces: 900 rows, the first 300 here"),
            "{}",
            &html[..200]
        );
        assert_eq!(html.matches("<tr><th scope=\"row\">").count(), 3 * MAX_ROWS);
    }

    #[test]
    fn only_the_role_cells_that_change_are_named() {
        let highlight = |kind, id, role: &str| HighlightState {
            kind,
            id,
            role: role.to_owned(),
            colour: "#ff0000".to_owned(),
        };
        let before = role_words(&[
            highlight(ElementKind::Edge, 3, "selected"),
            highlight(ElementKind::Edge, 4, "next edge"),
            highlight(ElementKind::Vertex, 1, "end vertex"),
            highlight(ElementKind::Vertex, 1, "end vertex"),
            highlight(ElementKind::Face, 900, "face"),
        ]);
        assert_eq!(
            before[&ElementRef::new(ElementKind::Vertex, 1)],
            "end vertex"
        );
        let after = role_words(&[
            highlight(ElementKind::Edge, 4, "next edge"),
            highlight(ElementKind::Edge, 5, "selected"),
            highlight(ElementKind::Vertex, 1, "end vertex"),
            highlight(ElementKind::Vertex, 1, "start vertex"),
            highlight(ElementKind::Face, 901, "face"),
        ]);
        assert_eq!(
            role_changes(&before, &after),
            vec![
                ("edgewise_a11y_role_e3".to_owned(), String::new()),
                (
                    "edgewise_a11y_role_v1".to_owned(),
                    "end vertex, start vertex".to_owned()
                ),
                ("edgewise_a11y_role_e5".to_owned(), "selected".to_owned()),
            ],
            "unchanged rows and rows past the mirrored ones are left"
        );
    }
}
