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

/// The three tables of `mesh` as HTML, with each highlighted row's roles
/// (`highlights`, as `state().highlights` lists them) in a last column.
pub fn tables_html(mesh: &Mesh, highlights: &[HighlightState]) -> String {
    let mut roles: BTreeMap<(ElementKind, u32), Vec<&str>> = BTreeMap::new();
    for highlight in highlights {
        let entry = roles.entry((highlight.kind, highlight.id)).or_default();
        if !entry.contains(&highlight.role.as_str()) {
            entry.push(&highlight.role);
        }
    }
    let mut html = String::new();
    for (kind, title) in [
        (ElementKind::Face, "Faces"),
        (ElementKind::Edge, tables::edge_table_title(mesh)),
        (ElementKind::Vertex, "Vertices"),
    ] {
        table_html(&mut html, mesh, kind, title, &roles);
    }
    html
}

fn table_html(
    html: &mut String,
    mesh: &Mesh,
    kind: ElementKind,
    title: &str,
    roles: &BTreeMap<(ElementKind, u32), Vec<&str>>,
) {
    let count = mesh.count(kind);
    let shown = count.min(MAX_ROWS);
    let columns = Column::table(mesh.structure(), kind);
    let _ = write!(html, "<table><caption>{title}: {count} rows");
    if shown < count {
        let _ = write!(html, ", the first {shown} here");
    }
    html.push_str("</caption><thead><tr><th scope=\"col\">id</th>");
    for entry in columns {
        if entry.column == Column::Position {
            html.push_str(
                "<th scope=\"col\">x</th><th scope=\"col\">y</th><th scope=\"col\">z</th>",
            );
        } else {
            let _ = write!(html, "<th scope=\"col\">{}</th>", entry.header);
        }
    }
    html.push_str("<th scope=\"col\">role</th></tr></thead><tbody>");
    for id in 0..shown as u32 {
        let element = ElementRef { kind, id };
        let _ = write!(
            html,
            "<tr><th scope=\"row\">{}</th>",
            tables::row_name(mesh, element)
        );
        if !mesh.contains(element) {
            let _ = write!(
                html,
                "<td colspan=\"{}\">deleted</td></tr>",
                columns.len() + 1
            );
            continue;
        }
        for entry in columns {
            if entry.column == Column::Position {
                let p = mesh.position(VertexId::new(id)).unwrap_or_default();
                let _ = write!(
                    html,
                    "<td>{:.3}</td><td>{:.3}</td><td>{:.3}</td>",
                    p.x, p.y, p.z
                );
            } else {
                match mesh.reference(element, entry.column).ok().flatten() {
                    Some(target) => {
                        let _ = write!(html, "<td>{}</td>", tables::row_name(mesh, target));
                    }
                    None => html.push_str("<td>none</td>"),
                }
            }
        }
        let role = roles
            .get(&(kind, id))
            .map(|r| r.join(", "))
            .unwrap_or_default();
        let _ = write!(html, "<td>{role}</td></tr>");
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
        let html = tables_html(&mesh, &highlights);
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
        assert!(html.contains("<td>selected</td></tr>"), "{html}");
        assert!(
            html.contains("<td>0.500</td><td>0.800</td><td>-0.300</td>"),
            "{html}"
        );
    }

    #[test]
    fn a_large_mesh_is_mirrored_in_part_and_says_so() {
        let (mesh, _) =
            Mesh::build(&generate::grid(30, 30), Structure::WingedEdge).expect("builds");
        let html = tables_html(&mesh, &[]);
        assert!(
            html.contains("Faces: 900 rows, the first 300 here"),
            "{}",
            &html[..200]
        );
        assert_eq!(html.matches("<tr><th scope=\"row\">").count(), 3 * MAX_ROWS);
    }
}
