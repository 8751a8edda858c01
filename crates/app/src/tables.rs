//! The face, edge and vertex tables, as the structure really holds them.
//!
//! Rows are virtualised (only visible rows are laid out), so the 200k-face
//! sample scrolls as smoothly as a tetrahedron. A cell holding a reference is
//! a link: clicking it selects that element, so a student can walk the
//! structure from the tables alone.

use edgewise_core::mesh::Mesh;
use egui::RichText;
use egui_extras::{Column, TableBuilder};

use crate::{
    paint::Paint,
    selection::{ElementKind, ElementRef, Role},
};

const ROW_HEIGHT: f32 = 20.0;
/// Shown for a missing (boundary) face.
const NONE: &str = "∅";

/// What the user did in a table this frame.
#[derive(Default)]
pub struct TablesResponse {
    /// A row or a reference cell was clicked.
    pub clicked: Option<ElementRef>,
}

/// One cell of a row.
enum Cell {
    /// The row's own id: clicking it selects the row.
    Id(ElementRef),
    Text(String),
    /// A reference to another element, in the column named by its role.
    Link(Option<ElementRef>, Role),
}

/// Draws one table of `kind` filling `ui`, coloured by `paint`, scrolling
/// just enough to show row `scroll_to` if given.
pub fn table_ui(
    ui: &mut egui::Ui,
    mesh: &Mesh,
    kind: ElementKind,
    paint: &Paint,
    scroll_to: Option<u32>,
    response: &mut TablesResponse,
) {
    let half = matches!(mesh, Mesh::Half(_));
    let headers: &[&str] = match (kind, half) {
        (ElementKind::Vertex, _) => &["id", "x", "y", "z", "incident edge", "labels"],
        (ElementKind::Face, _) => &["id", "incident edge", "labels"],
        (ElementKind::Edge, false) => &[
            "id",
            "start",
            "end",
            "left face",
            "right face",
            "left pred",
            "left succ",
            "right pred",
            "right succ",
            "labels",
        ],
        (ElementKind::Edge, true) => &[
            "id",
            "end vertex",
            "face",
            "pair",
            "successor",
            "start vertex",
            "predecessor",
            "labels",
        ],
    };
    let rows = match kind {
        ElementKind::Vertex => mesh.vertex_count(),
        ElementKind::Edge => mesh.edge_row_count(),
        ElementKind::Face => mesh.face_count(),
    };
    let derived_from = if half && kind == ElementKind::Edge {
        5
    } else {
        usize::MAX
    };

    let mut table = TableBuilder::new(ui)
        .id_salt(kind)
        .striped(true)
        .resizable(true)
        // Fill the panel: a table that shrank to its rows would shrink the panel too.
        .auto_shrink(false)
        .cell_layout(egui::Layout::left_to_right(egui::Align::Center));
    if let Some(row) = scroll_to {
        table = table.scroll_to_row(row as usize, None);
    }
    for (i, _) in headers.iter().enumerate() {
        table = table.column(if i + 1 == headers.len() {
            Column::remainder().at_least(60.0)
        } else {
            Column::auto().at_least(if i == 0 { 36.0 } else { 48.0 })
        });
    }
    table
        .header(ROW_HEIGHT, |mut header| {
            for (i, title) in headers.iter().enumerate() {
                header.col(|ui| {
                    let text = RichText::new(*title).strong();
                    ui.label(if i >= derived_from && i + 1 < headers.len() {
                        text.weak()
                    } else {
                        text
                    });
                });
            }
        })
        .body(|body| {
            body.rows(ROW_HEIGHT, rows, |mut row| {
                let id = row.index() as u32;
                let element = ElementRef { kind, id };
                let row_colour = paint.colour_of(element);
                let selected_row = paint.painted.first().is_some_and(|p| p.element == element);
                let mut cells = row_cells(mesh, element);
                if let (Some(last), Some(labels)) = (cells.last_mut(), paint.labels.get(&element)) {
                    *last = Cell::Text(labels.clone());
                }
                let mut clicked_link = None;
                for (i, cell) in cells.into_iter().enumerate() {
                    row.col(|ui| {
                        if let Some(colour) = row_colour {
                            ui.painter().rect_filled(
                                ui.max_rect().expand2(egui::vec2(4.0, 1.0)),
                                0.0,
                                colour.gamma_multiply(0.28),
                            );
                        }
                        let dim = i >= derived_from && i + 1 < headers.len();
                        match cell {
                            Cell::Id(element) => {
                                let label = ui
                                    .selectable_label(
                                        selected_row,
                                        RichText::new(element.id.to_string()).monospace(),
                                    )
                                    .on_hover_text(format!(
                                        "select {} {}",
                                        element.kind.title().to_lowercase(),
                                        element.id
                                    ));
                                if label.clicked() {
                                    clicked_link = Some(element);
                                }
                            }
                            Cell::Text(text) => {
                                let mut text = RichText::new(text).monospace();
                                if dim {
                                    text = text.weak();
                                }
                                ui.label(text);
                            }
                            Cell::Link(None, _) => {
                                ui.label(RichText::new(NONE).monospace().weak());
                            }
                            Cell::Link(Some(target), role) => {
                                let mut text = RichText::new(target.id.to_string()).monospace();
                                if let Some(tint) = paint.cells.get(&(element, role)) {
                                    text =
                                        text.background_color(tint.gamma_multiply(0.55)).strong();
                                } else if dim {
                                    text = text.weak();
                                }
                                let target_name =
                                    format!("{} {}", target.kind.title().to_lowercase(), target.id);
                                let link =
                                    ui.link(text).on_hover_text(format!("select {target_name}"));
                                // Screen readers (and UI tests) hear which reference this is.
                                let column = headers.get(i).copied().unwrap_or_default();
                                let row_name = format!("{} {}", kind.title().to_lowercase(), id);
                                link.widget_info(|| {
                                    egui::WidgetInfo::labeled(
                                        egui::Role::Link,
                                        true,
                                        format!("{column} of {row_name}: {target_name}"),
                                    )
                                });
                                if link.clicked() {
                                    clicked_link = Some(target);
                                }
                            }
                        }
                    });
                }
                if let Some(target) = clicked_link {
                    response.clicked = Some(target);
                }
            });
        });
}

/// The cells of one row; each reference carries the role naming its column.
fn row_cells(mesh: &Mesh, element: ElementRef) -> Vec<Cell> {
    let role_of = |target: Option<ElementRef>, role: Role| -> Cell { Cell::Link(target, role) };
    let labels = Cell::Text(String::new());
    let index = element.id as usize;
    let id = Cell::Id(element);
    match (mesh, element.kind) {
        (Mesh::Winged(m), ElementKind::Vertex) => match m.vertices().get(index) {
            Some(v) => vec![
                id,
                coordinate(v.position.x),
                coordinate(v.position.y),
                coordinate(v.position.z),
                role_of(v.incident_edge.map(ElementRef::edge), Role::IncidentEdge),
                labels,
            ],
            None => Vec::new(),
        },
        (Mesh::Half(m), ElementKind::Vertex) => match m.vertices().get(index) {
            Some(v) => vec![
                id,
                coordinate(v.position.x),
                coordinate(v.position.y),
                coordinate(v.position.z),
                role_of(
                    v.incident_edge.map(ElementRef::half_edge),
                    Role::IncidentEdge,
                ),
                labels,
            ],
            None => Vec::new(),
        },
        (Mesh::Winged(m), ElementKind::Face) => match m.faces().get(index) {
            Some(f) => vec![
                id,
                role_of(Some(ElementRef::edge(f.incident_edge)), Role::IncidentEdge),
                labels,
            ],
            None => Vec::new(),
        },
        (Mesh::Half(m), ElementKind::Face) => match m.faces().get(index) {
            Some(f) => vec![
                id,
                role_of(
                    Some(ElementRef::half_edge(f.incident_edge)),
                    Role::IncidentEdge,
                ),
                labels,
            ],
            None => Vec::new(),
        },
        (Mesh::Winged(m), ElementKind::Edge) => match m.edges().get(index) {
            Some(e) => vec![
                id,
                role_of(Some(ElementRef::vertex(e.start_vertex)), Role::StartVertex),
                role_of(Some(ElementRef::vertex(e.end_vertex)), Role::EndVertex),
                role_of(e.left_face.map(ElementRef::face), Role::LeftFace),
                role_of(e.right_face.map(ElementRef::face), Role::RightFace),
                role_of(
                    Some(ElementRef::edge(e.left_predecessor)),
                    Role::LeftPredecessor,
                ),
                role_of(
                    Some(ElementRef::edge(e.left_successor)),
                    Role::LeftSuccessor,
                ),
                role_of(
                    Some(ElementRef::edge(e.right_predecessor)),
                    Role::RightPredecessor,
                ),
                role_of(
                    Some(ElementRef::edge(e.right_successor)),
                    Role::RightSuccessor,
                ),
                labels,
            ],
            None => Vec::new(),
        },
        (Mesh::Half(m), ElementKind::Edge) => match m.half_edges().get(index) {
            Some(h) => {
                let hid = edgewise_core::mesh::HalfEdgeId::new(element.id);
                vec![
                    id,
                    role_of(Some(ElementRef::vertex(h.end_vertex)), Role::EndVertex),
                    role_of(h.face.map(ElementRef::face), Role::Face),
                    role_of(Some(ElementRef::half_edge(h.pair_edge)), Role::PairEdge),
                    role_of(
                        Some(ElementRef::half_edge(h.successor_edge)),
                        Role::SuccessorEdge,
                    ),
                    role_of(
                        m.start_vertex(hid).map(ElementRef::vertex),
                        Role::StartVertex,
                    ),
                    role_of(
                        m.predecessor_edge(hid).map(ElementRef::half_edge),
                        Role::PredecessorEdge,
                    ),
                    labels,
                ]
            }
            None => Vec::new(),
        },
    }
}

fn coordinate(value: f32) -> Cell {
    Cell::Text(format!("{value:.3}"))
}
