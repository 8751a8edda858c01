//! The edit menu: right-click an element in the 3D view or its row in a
//! table, or press E with one selected, for the local operations that
//! apply to it. Each is tried on a copy of the mesh when the menu opens; an
//! operation that would be refused is shown greyed out, with the refusal as
//! its reason. An entry applies the native operation; its "trace" button
//! runs the library's traced version instead, one record write at a time.

use edgewise_core::mesh::{EdgeId, FaceId, HalfEdgeId, Structure, VertexId};
use edgewise_core::mesh::{
    Mesh, Navigation as _,
    operations::{self, Operation},
};
use edgewise_core::schema::{ElementKind, ElementRef, Records as _};

use super::EdgewiseApp;
use crate::command::Command;
use crate::state::{EditMenuEntry, EditMenuState};
use edgewise_model::algorithm::session::Argument;
use edgewise_model::document::Document;

/// The operations the menu offers on an edge, in this order.
const EDGE_OPERATIONS: [Operation; 6] = [
    Operation::FlipEdge,
    Operation::SplitEdge,
    Operation::CollapseEdge,
    Operation::Kef,
    Operation::Kev,
    Operation::Kemr,
];

/// The most entries listed for one element (a face's splits, a vertex's
/// dangling edges), so that a huge face keeps the menu on screen.
const MAX_ENTRIES: usize = 24;

/// The width an entry leaves for its small trace button and the gap before it.
const TRACE_BUTTON_ROOM: f32 = 64.0;

/// One operation on the element, and why it would be refused, if it would.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct MenuEntry {
    pub(crate) operation: Operation,
    pub(crate) ids: Vec<u32>,
    pub(crate) label: String,
    pub(crate) refusal: Option<String>,
}

/// An open edit menu: the element, where it opened, and its entries.
pub(crate) struct EditMenu {
    pub(crate) element: ElementRef,
    at: egui::Pos2,
    pub(crate) entries: Vec<MenuEntry>,
    /// Whether the first entry still has to take the keyboard focus, so
    /// that Enter applies it.
    focus_first: bool,
}

impl EditMenu {
    /// The menu for `element` of `mesh`, at `at`; every entry tried on one
    /// copy of the mesh, each change taken back before the next.
    pub(crate) fn new(mesh: &Mesh, element: ElementRef, at: egui::Pos2) -> Self {
        let mut scratch = mesh.clone();
        let entries = candidates(mesh, element)
            .into_iter()
            .map(|(operation, ids, label)| {
                let refusal = match operations::apply(&mut scratch, operation, &ids) {
                    Ok(applied) => {
                        for change in applied.journal.iter().rev() {
                            if change.revert(&mut scratch).is_err() {
                                scratch = mesh.clone();
                                break;
                            }
                        }
                        None
                    }
                    Err(refusal) => Some(refusal.to_string()),
                };
                MenuEntry {
                    operation,
                    ids,
                    label,
                    refusal,
                }
            })
            .collect();
        Self {
            element,
            at,
            entries,
            focus_first: true,
        }
    }
}

impl EditMenu {
    pub(crate) fn state(&self) -> EditMenuState {
        EditMenuState {
            element: self.element,
            entries: self
                .entries
                .iter()
                .map(|entry| EditMenuEntry {
                    operation: entry.operation.name(),
                    ids: entry.ids.clone(),
                    label: entry.label.clone(),
                    refused: entry.refusal.clone(),
                })
                .collect(),
        }
    }
}

/// The operations that take `element` first, with their ids and labels.
fn candidates(mesh: &Mesh, element: ElementRef) -> Vec<(Operation, Vec<u32>, String)> {
    let id = element.id;
    match element.kind {
        ElementKind::Edge => EDGE_OPERATIONS
            .into_iter()
            .map(|op| (op, vec![id], format!("{}: {}", op.name(), op.summary())))
            .collect(),
        ElementKind::Vertex => {
            let mut list = vec![(
                Operation::RemoveVertex,
                vec![id],
                format!("remove-vertex: {}", Operation::RemoveVertex.summary()),
            )];
            let edges: Vec<u32> = match mesh {
                Mesh::Winged(m) => m
                    .around_vertex(VertexId::new(id))
                    .map(EdgeId::raw)
                    .collect(),
                Mesh::Half(m) => m
                    .around_vertex(VertexId::new(id))
                    .map(HalfEdgeId::raw)
                    .collect(),
            };
            list.extend(edges.into_iter().take(MAX_ENTRIES).map(|e| {
                (
                    Operation::Mev,
                    vec![id, e],
                    format!("mev: a dangling edge from vertex {id}, beside edge {e}"),
                )
            }));
            list
        }
        ElementKind::Face => {
            let corners: Vec<u32> = match mesh {
                Mesh::Winged(m) => m
                    .face_vertices(FaceId::new(id))
                    .map(VertexId::raw)
                    .collect(),
                Mesh::Half(m) => m
                    .face_vertices(FaceId::new(id))
                    .map(VertexId::raw)
                    .collect(),
            };
            let n = corners.len();
            let mut list = Vec::new();
            for i in 0..n {
                // Corners two or more apart, each pair once.
                for j in i + 2..n {
                    if i == 0 && j == n - 1 {
                        continue;
                    }
                    let (u, w) = (corners[i], corners[j]);
                    list.push((
                        Operation::SplitFace,
                        vec![id, u, w],
                        format!("split-face: join vertices {u} and {w} across face {id}"),
                    ));
                }
            }
            list.truncate(MAX_ENTRIES);
            list
        }
    }
}

impl EdgewiseApp {
    /// Opens the edit menu on `element` at `at`, selecting it.
    pub(super) fn open_edit_menu(&mut self, element: ElementRef, at: egui::Pos2) {
        self.issue(Command::Select(Some(element)));
        let tab = self.tab_mut();
        tab.edit_menu = tab
            .document
            .as_ref()
            .filter(|d| d.mesh().contains(element))
            .map(|d| EditMenu::new(d.mesh(), element, at));
    }

    /// E opens the menu on the selection, at the top left of the view;
    /// Ctrl+Z undoes, Ctrl+Shift+Z and Ctrl+Y redo (⌘ on a Mac).
    pub(super) fn edit_keys(&mut self, ctx: &egui::Context, view: egui::Rect) {
        if ctx.egui_wants_keyboard_input() {
            return;
        }
        use egui::{Key, KeyboardShortcut, Modifiers};
        let shortcut = |modifiers, key| {
            ctx.input_mut(|i| i.consume_shortcut(&KeyboardShortcut::new(modifiers, key)))
        };
        // The longer shortcut first: Ctrl+Z would match Ctrl+Shift+Z too.
        if shortcut(Modifiers::COMMAND | Modifiers::SHIFT, Key::Z)
            || shortcut(Modifiers::COMMAND, Key::Y)
        {
            self.issue(Command::Redo);
        } else if shortcut(Modifiers::COMMAND, Key::Z) {
            self.issue(Command::Undo);
        }
        if !ctx.input(|i| i.key_pressed(Key::E) && i.modifiers.is_none()) {
            return;
        }
        if let Some(selection) = self.tab().document.as_ref().and_then(Document::selection) {
            self.open_edit_menu(selection, view.left_top() + egui::vec2(12.0, 12.0));
        }
    }

    /// Draws the open edit menu; closes it on a choice, Escape or a click
    /// elsewhere.
    pub(super) fn edit_menu_ui(&mut self, ctx: &egui::Context) {
        let structure = self.tab().document.as_ref().map(Document::structure);
        let Some(menu) = self.tab_mut().edit_menu.as_mut() else {
            return;
        };
        let mut chosen = None;
        let focus_first = std::mem::take(&mut menu.focus_first);
        let area = egui::Area::new(egui::Id::unique("edit_menu"))
            .order(egui::Order::Foreground)
            .fixed_pos(menu.at)
            .constrain(true)
            .show(ctx, |ui| {
                egui::Frame::menu(ui.style()).show(ui, |ui| {
                    ui.set_max_width(460.0_f32.min(ctx.content_rect().width() - 24.0));
                    ui.strong(format!("Edit {}", menu.element));
                    let mut focused = !focus_first;
                    for entry in &menu.entries {
                        ui.horizontal(|ui| {
                            let enabled = entry.refusal.is_none();
                            // A long entry wraps on a phone rather than
                            // pushing its trace button off the screen.
                            let room = ui.available_width() - TRACE_BUTTON_ROOM;
                            let button = ui
                                .scope(|ui| {
                                    ui.set_max_width(room);
                                    ui.add_enabled(enabled, egui::Button::new(&entry.label).wrap())
                                })
                                .inner;
                            let button = match &entry.refusal {
                                Some(reason) => button.on_disabled_hover_text(reason),
                                None => button,
                            };
                            if enabled && !focused {
                                button.request_focus();
                                focused = true;
                            }
                            if button.clicked() {
                                chosen = Some(Choice::Apply(Command::Edit {
                                    operation: entry.operation,
                                    ids: entry.ids.clone(),
                                }));
                            }
                            if ui
                                .add_enabled(enabled, egui::Button::new("trace").small())
                                .on_hover_text(format!(
                                    "Run {} from the library, one record write at a time",
                                    entry.operation.algorithm()
                                ))
                                .clicked()
                            {
                                chosen = Some(Choice::Trace(entry.clone()));
                            }
                        });
                    }
                    if menu.entries.iter().any(|e| e.refusal.is_some()) {
                        ui.weak("Greyed out: hover for the reason it is refused.");
                    }
                    if structure.is_none() {
                        ui.weak("No mesh is open.");
                    }
                });
                crate::state::MenuLayout::of(ui, "Edit")
            });
        self.layout.menus.push(area.inner.clone());
        let clicked_outside = ctx.input(|i| i.pointer.any_click())
            && !area
                .response
                .rect
                .contains(ctx.pointer_interact_pos().unwrap_or_default())
            && !focus_first;
        let escape = ctx.input(|i| i.key_pressed(egui::Key::Escape));
        if chosen.is_some() || clicked_outside || escape {
            self.tab_mut().edit_menu = None;
        }
        let command = match chosen {
            Some(Choice::Apply(command)) => command,
            Some(Choice::Trace(entry)) => match structure {
                Some(structure) => match self.traced(&entry, structure) {
                    Ok(command) => command,
                    Err(message) => {
                        self.report(message);
                        return;
                    }
                },
                None => return,
            },
            None => return,
        };
        self.issue(command);
    }

    /// The library's traced version of an entry, with its ids as the
    /// algorithm's arguments in order (MEV's one edge given twice).
    fn traced(&self, entry: &MenuEntry, structure: Structure) -> Result<Command, String> {
        let (name, args) = self.traced_operation(entry.operation, &entry.ids, structure)?;
        Ok(Command::RunAlgorithm { name, args })
    }

    /// The library algorithm that traces `operation` and its inputs for
    /// `ids`: what the edit menu's trace button and a do-it exercise's
    /// model answer run.
    pub(super) fn traced_operation(
        &self,
        operation: Operation,
        ids: &[u32],
        structure: Structure,
    ) -> Result<(String, Vec<(String, Argument)>), String> {
        let name = operation.algorithm();
        let algorithm = self
            .algorithms
            .find(name, structure)
            .map_err(|error| error.to_string())?;
        let mut ids = ids.to_vec();
        if operation == Operation::Mev && ids.len() == 2 {
            ids.push(ids[1]);
        }
        let args = algorithm
            .params()
            .zip(ids)
            .map(|(param, id)| (param.name.clone(), Argument::Number(f64::from(id))))
            .collect();
        Ok((name.to_owned(), args))
    }
}

/// What the menu was asked for.
enum Choice {
    Apply(Command),
    Trace(MenuEntry),
}
