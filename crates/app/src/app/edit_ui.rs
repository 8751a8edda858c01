//! The live mesh panel: V, E, F, V − E + F, genus, boundary loops and
//! components, updated at every step of an edit, and, while an algorithm
//! changes the mesh, every record that breaks a rule of the structure.

use super::EdgewiseApp;
use crate::{algorithm::TraceSession, command::Command};

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
        let broken = &tab.broken;
        if !broken.is_empty() {
            let colour = ui.visuals().error_fg_color;
            ui.label(
                egui::RichText::new(format!(
                    "{} broken record{} at this step:",
                    broken.len(),
                    if broken.len() == 1 { "" } else { "s" }
                ))
                .color(colour)
                .strong(),
            );
            for issue in broken.iter().take(LISTED) {
                ui.label(egui::RichText::new(issue.to_string()).color(colour).small());
            }
            if broken.len() > LISTED {
                ui.weak(format!("… and {} more", broken.len() - LISTED));
            }
        } else if tab.run.session().is_some_and(TraceSession::edits) {
            ui.weak("Every record follows the structure's rules at this step.");
        }
        if tab.run.session().is_none()
            && let Some((name, _)) = &tab.before_edit
        {
            ui.horizontal(|ui| {
                ui.weak(format!("{name} changed the mesh."));
                if ui
                    .button("Restore the previous mesh")
                    .on_hover_text("Put back the mesh as it was before the edit")
                    .clicked()
                {
                    command = Some(Command::RestoreBeforeEdit);
                }
            });
        }
        if let Some(command) = command {
            self.issue(command);
        }
    }
}
