//! The live mesh panel: V, E, F, V − E + F, genus, boundary loops and
//! components, updated at every step of an edit; while an algorithm
//! changes the mesh, or in diagnosis mode, every record that breaks a rule
//! of the structure; undo and redo; and compacting the ids, with the
//! old-to-new mapping it made.

use edgewise_core::mesh::{Edit as _, Renumbering};
use edgewise_core::schema::ElementKind;

use super::EdgewiseApp;
use crate::command::Command;
use edgewise_model::algorithm::session::TraceSession;

/// Renumbered ids listed per table before "and N more".
const MAPPED: usize = 8;

/// Broken records listed before "and N more".
const LISTED: usize = 12;

impl EdgewiseApp {
    pub(super) fn mesh_status_ui(&mut self, ui: &mut egui::Ui) {
        let tab = &mut self.tabs[self.active_tab];
        let Some(stats) = tab.stats() else {
            return;
        };
        let genus: Vec<String> = stats
            .components
            .iter()
            .map(|c| c.genus.map_or_else(|| "–".to_owned(), |g| g.to_string()))
            .collect();
        let line = format!(
            "V {} · E {} · F {} · V − E + F = {} · genus {} · boundary loops {} · components {}",
            stats.vertices,
            stats.edges,
            stats.faces,
            stats.euler_characteristic,
            if genus.is_empty() {
                "–".to_owned()
            } else {
                genus.join(", ")
            },
            stats.boundary_loops,
            stats.components.len()
        );
        ui.label(egui::RichText::new(line).monospace())
            .on_hover_text("Counts and invariants of the mesh as it is now; they update at every step of an edit.");
        let mut command = None;
        let broken = tab.broken();
        if tab.diagnosis {
            ui.label(
                egui::RichText::new("Diagnosis: these tables break the structure's rules.")
                    .strong(),
            );
            ui.weak(
                "Double-click a cell to change it. The mesh opens normally once every record \
                 follows the rules.",
            );
        }
        if !broken.is_empty() {
            let colour = ui.visuals().error_fg_color;
            let when = if tab.diagnosis { "" } else { " at this step" };
            ui.label(
                egui::RichText::new(format!(
                    "{} broken record{}{when}:",
                    tab.broken_total,
                    if tab.broken_total == 1 { "" } else { "s" }
                ))
                .color(colour)
                .strong(),
            );
            // The list scrolls within a quarter of the panel while a trace
            // runs, whose current line and variables need the rest.
            let share = if tab.run.is_active() { 0.25 } else { 0.5 };
            egui::ScrollArea::vertical()
                .id_salt("broken_records")
                .auto_shrink([false, true])
                .max_height(ui.available_height() * share)
                .show(ui, |ui| {
                    // In the language's names (successorEdge), at the panel's size.
                    for issue in broken.iter().take(LISTED) {
                        ui.label(egui::RichText::new(issue.in_language()).color(colour));
                    }
                    if tab.broken_total > LISTED {
                        ui.weak(format!("… and {} more", tab.broken_total - LISTED));
                    }
                });
        } else if tab.run.session().is_some_and(TraceSession::edits) {
            ui.weak("Every record follows the structure's rules at this step.");
        }
        if tab.run.session().is_none() {
            ui.horizontal_wrapped(|ui| {
                let undo = tab.history.last().map(|(label, _)| label.to_owned());
                let redo = tab.history.next().map(str::to_owned);
                let button = |ui: &mut egui::Ui, text: &str, label: &Option<String>| {
                    let hover = label
                        .as_ref()
                        .map_or_else(String::new, |l| format!("{text} {l}"));
                    ui.add_enabled(label.is_some(), egui::Button::new(text))
                        .on_hover_text(hover)
                        .on_disabled_hover_text(format!("Nothing to {}", text.to_lowercase()))
                        .clicked()
                };
                if button(ui, "Undo", &undo) {
                    command = Some(Command::Undo);
                }
                if button(ui, "Redo", &redo) {
                    command = Some(Command::Redo);
                }
                if let Some(label) = &undo {
                    ui.weak(format!("last change: {label}"));
                }
                let deleted = tab
                    .document
                    .as_ref()
                    .map_or(0, |d| d.mesh().deleted_rows().iter().count());
                if deleted > 0
                    && ui
                        .button("Compact ids")
                        .on_hover_text(format!(
                            "Drop the {deleted} deleted rows and renumber the rest in order"
                        ))
                        .clicked()
                {
                    command = Some(Command::CompactIds);
                }
            });
        }
        if let Some(renumbering) = &tab.renumbering {
            let mut dismissed = false;
            egui::CollapsingHeader::new("Compacting renumbered the ids")
                .default_open(true)
                .show(ui, |ui| {
                    renumbering_ui(ui, renumbering);
                    dismissed = ui.button("Dismiss").clicked();
                });
            if dismissed {
                tab.renumbering = None;
            }
        }
        if let Some(command) = command {
            self.issue(command);
        }
    }
}

/// Each table's changed ids as `old → new`, deleted ones as `old → gone`.
fn renumbering_ui(ui: &mut egui::Ui, renumbering: &Renumbering) {
    for kind in ElementKind::ALL {
        let moved: Vec<String> = renumbering
            .changes(kind)
            .map(|(old, new)| match new {
                Some(new) => format!("{old} → {new}"),
                None => format!("{old} → deleted"),
            })
            .collect();
        if moved.is_empty() {
            continue;
        }
        let mut text = format!(
            "{}: {}",
            kind.plural(),
            moved
                .iter()
                .take(MAPPED)
                .cloned()
                .collect::<Vec<_>>()
                .join(", ")
        );
        if moved.len() > MAPPED {
            text.push_str(&format!(", … and {} more", moved.len() - MAPPED));
        }
        ui.label(egui::RichText::new(text).monospace().small());
    }
}
