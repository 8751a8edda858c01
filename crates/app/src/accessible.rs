//! What a screen reader gets in place of the canvas, which is one image to
//! it: the three tables as HTML tables with captions and headers, each row's
//! roles as words (a second cue beside colour), and the message line's
//! sentence (the step, or the selection and its references), announced as
//! it changes; and the algorithm panel as controls: the algorithms with
//! their inputs, the step buttons, the current line and the variables. The browser platform puts them in a visually hidden part of
//! the page (index.html); natively egui's AccessKit output serves instead.

use std::collections::{BTreeMap, HashMap};
use std::fmt::Write as _;

use edgewise_core::lang::{Routine, types::Type};
use edgewise_core::mesh::{Mesh, Structure};
use edgewise_core::schema::{ElementKind, ElementRef};
use edgewise_pictures::text_table::{Cell, TextTable, text_tables};

use crate::state::HighlightState;
use edgewise_model::{
    algorithm::frame::TraceFrame, course_link::escape_attribute as escape, trace_role::TraceRole,
};

/// Rows mirrored per table; a larger mesh's caption says how many are left
/// out (its rows are still read in the app's tables through AccessKit).
pub const MAX_ROWS: usize = 300;

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
/// A variable's role names it ("variable e"), from `variable_names`.
pub fn role_words(
    highlights: &[HighlightState],
    variable_names: &HashMap<ElementRef, String>,
) -> BTreeMap<ElementRef, String> {
    let mut roles: BTreeMap<ElementRef, Vec<String>> = BTreeMap::new();
    for highlight in highlights {
        let element = ElementRef::new(highlight.kind, highlight.id);
        let words = match variable_names.get(&element) {
            Some(names) if highlight.role == TraceRole::Variable.key() => {
                let noun = if names.contains(", ") {
                    "variables"
                } else {
                    "variable"
                };
                format!("{noun} {names}")
            }
            _ => highlight.role.clone(),
        };
        let entry = roles.entry(element).or_default();
        if !entry.contains(&words) {
            entry.push(words);
        }
    }
    roles
        .into_iter()
        .map(|(element, words)| (element, words.join(", ")))
        .collect()
}

/// The algorithm panel as the page's copy shows it while a run is open.
#[derive(Clone, Debug, PartialEq)]
pub struct RunCopy {
    /// "vertexAdjacentEdge, step 2 of 22, playing".
    pub status: String,
    /// "Line 13: e := v.incidentEdge;".
    pub line: String,
    /// Each variable's name, type and value ("Edge 3", "null").
    pub variables: Vec<(String, &'static str, String)>,
}

impl RunCopy {
    pub fn new(frame: &TraceFrame, algorithm: &Routine, playing: bool) -> Self {
        let mut status = format!("{}, step {} of {}", algorithm.name, frame.step, frame.steps);
        if frame.done {
            status.push_str(", done");
        } else if playing {
            status.push_str(", playing");
        }
        let code = (frame.line as usize)
            .checked_sub(1)
            .and_then(|index| algorithm.source.lines().nth(index))
            .map_or("", str::trim);
        Self {
            status,
            line: format!("Line {}: {code}", frame.line),
            variables: frame
                .variables
                .iter()
                .map(|v| (v.name.clone(), v.ty, v.value.clone()))
                .collect(),
        }
    }

    /// The variables as a description list, every text escaped: names and
    /// values come from a user's algorithm.
    pub fn variables_html(&self) -> String {
        let mut html = String::from("<dl>");
        for (name, ty, value) in &self.variables {
            let _ = write!(
                html,
                "<dt>{}, {}</dt><dd>{}</dd>",
                escape(name),
                escape(ty),
                escape(value)
            );
        }
        html.push_str("</dl>");
        html
    }
}

/// The algorithms for `structure` as forms: each input a labelled field,
/// and a button that runs it. index.html calls `window.edgewise.run` with
/// the fields' values. An input the page cannot give (an Array, a Vector)
/// is left for the app to ask.
pub fn algorithms_html<'a>(
    algorithms: impl IntoIterator<Item = &'a Routine>,
    structure: Structure,
) -> String {
    let mut html = String::new();
    for algorithm in algorithms {
        if algorithm.structure != structure {
            continue;
        }
        let name = escape(&algorithm.name);
        let _ = write!(
            html,
            "<form class=\"edgewise-a11y-run\" data-algorithm=\"{name}\"><fieldset><legend>{name}</legend>"
        );
        if let Some(description) = &algorithm.description {
            let _ = write!(html, "<p>{}</p>", escape(description));
        }
        for param in algorithm.params() {
            let field = escape(&param.name);
            let ty = param.ty.to_string();
            match param.ty {
                Type::Vertex | Type::Edge | Type::Face => {
                    let _ = write!(
                        html,
                        "<label>{field}, a {ty} id <input name=\"{field}\" type=\"number\" min=\"0\" step=\"1\" value=\"0\" required></label>"
                    );
                }
                Type::Integer => {
                    let _ = write!(
                        html,
                        "<label>{field}, an Integer <input name=\"{field}\" type=\"number\" step=\"1\" value=\"0\" required></label>"
                    );
                }
                Type::Boolean => {
                    let _ = write!(
                        html,
                        "<label><input name=\"{field}\" type=\"checkbox\"> {field}, a Boolean</label>"
                    );
                }
                _ => {
                    let _ = write!(html, "<p>{field}, {}: chosen in the app</p>", escape(&ty));
                }
            }
        }
        let _ = write!(
            html,
            "<button type=\"submit\">Run {name}</button></fieldset></form>"
        );
    }
    if html.is_empty() {
        html.push_str("<p>No algorithm works on this mesh's structure.</p>");
    }
    html
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
            edgewise_pictures::text_table::row_name(mesh, *element)
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
                    let _ = write!(
                        html,
                        "<td>{}</td>",
                        edgewise_pictures::text_table::row_name(mesh, *target)
                    );
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
        let html = tables_html(&mesh, &role_words(&highlights, &HashMap::new()));
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
        let before = role_words(
            &[
                highlight(ElementKind::Edge, 3, "selected"),
                highlight(ElementKind::Edge, 4, "next edge"),
                highlight(ElementKind::Vertex, 1, "end vertex"),
                highlight(ElementKind::Vertex, 1, "end vertex"),
                highlight(ElementKind::Face, 900, "face"),
            ],
            &HashMap::new(),
        );
        assert_eq!(
            before[&ElementRef::new(ElementKind::Vertex, 1)],
            "end vertex"
        );
        let after = role_words(
            &[
                highlight(ElementKind::Edge, 4, "next edge"),
                highlight(ElementKind::Edge, 5, "selected"),
                highlight(ElementKind::Vertex, 1, "end vertex"),
                highlight(ElementKind::Vertex, 1, "start vertex"),
                highlight(ElementKind::Face, 901, "face"),
            ],
            &HashMap::new(),
        );
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

    #[test]
    fn a_variables_role_names_it() {
        let edge = ElementRef::new(ElementKind::Edge, 2);
        let variable = |id| HighlightState {
            kind: ElementKind::Edge,
            id,
            role: TraceRole::Variable.key().to_owned(),
            colour: "#8a3fcf".to_owned(),
        };
        let names = HashMap::from([
            (edge, "e".to_owned()),
            (ElementRef::new(ElementKind::Edge, 3), "e, se".to_owned()),
        ]);
        let words = role_words(&[variable(2), variable(3)], &names);
        assert_eq!(words[&edge], "variable e");
        assert_eq!(
            words[&ElementRef::new(ElementKind::Edge, 3)],
            "variables e, se"
        );
    }

    #[test]
    fn the_algorithms_are_forms_with_escaped_labelled_inputs() {
        let source = "algorithm tricky(v : Vertex; deep : Boolean);\n\
                      structuretype WingedEdge\n\
                      description \"<b>bold</b> & more\"\n\
                      begin\n  mark v;\nend;\n";
        let program = edgewise_core::lang::compile(source).expect("compiles");
        let algorithms = || program.algorithms.iter().map(|a| &***a);
        let html = algorithms_html(algorithms(), Structure::WingedEdge);
        assert!(html.contains("data-algorithm=\"tricky\""), "{html}");
        assert!(
            html.contains("<p>&lt;b&gt;bold&lt;/b&gt; &amp; more</p>"),
            "{html}"
        );
        assert!(
            html.contains("<label>v, a Vertex id <input name=\"v\" type=\"number\""),
            "{html}"
        );
        assert!(
            html.contains("type=\"checkbox\"> deep, a Boolean</label>"),
            "{html}"
        );
        assert!(
            html.contains("<button type=\"submit\">Run tricky</button>"),
            "{html}"
        );
        let other = algorithms_html(algorithms(), Structure::HalfEdge);
        assert!(other.contains("No algorithm works"), "{other}");
    }
}
