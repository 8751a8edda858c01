//! The question a PLY or OBJ file raises when it is opened: which structure
//! to build from its polygons. Table files answer it themselves.

use edgewise_core::mesh::Structure;

use crate::{
    EdgewiseApp,
    command::{Command, CommandError},
};

/// A polygon file waiting for the student to choose a structure.
pub struct StructureDialog {
    /// The file name, shown in the title and kept as the mesh's name.
    pub name: String,
    bytes: Vec<u8>,
    /// The structure the Open button builds; starts as the current one.
    pub choice: Structure,
    /// Drawn at least once: the Enter that opened the file (in the native
    /// path box) must not also answer the dialog.
    shown: bool,
}

/// What the student answered.
enum Answer {
    Open(Structure),
    Cancel,
}

impl StructureDialog {
    pub fn new(name: &str, bytes: Vec<u8>, current: Structure) -> Self {
        Self {
            name: name.to_owned(),
            bytes,
            choice: current,
            shown: false,
        }
    }

    /// Draws the modal. Enter opens, Escape or a click outside cancels.
    fn ui(&mut self, ctx: &egui::Context) -> Option<Answer> {
        let enter = self.shown && ctx.input(|i| i.key_pressed(egui::Key::Enter));
        self.shown = true;
        let modal = egui::Modal::new(egui::Id::unique("structure_dialog")).show(ctx, |ui| {
            ui.set_width(460.0);
            ui.heading(format!("Open {}", self.name));
            ui.add_space(4.0);
            ui.label("This file holds polygons. Which structure should Edgewise build from them?");
            ui.add_space(8.0);
            ui.radio_value(
                &mut self.choice,
                Structure::WingedEdge,
                "Winged-edge: one record per edge, with its two faces and four wings",
            );
            ui.radio_value(
                &mut self.choice,
                Structure::HalfEdge,
                "Half-edge: two records per edge, one for each side",
            );
            ui.add_space(12.0);
            ui.horizontal(|ui| {
                let open = egui::Button::new("Open").fill(ui.visuals().selection.bg_fill);
                if ui.add(open).clicked() || enter {
                    Some(Answer::Open(self.choice))
                } else if ui.button("Cancel").clicked() {
                    Some(Answer::Cancel)
                } else {
                    None
                }
            })
            .inner
        });
        if modal.should_close() {
            return Some(Answer::Cancel);
        }
        modal.inner
    }
}

impl EdgewiseApp {
    /// Shows the structure dialog while a file waits for an answer.
    pub(crate) fn structure_dialog_ui(&mut self, ctx: &egui::Context) {
        let Some(dialog) = &mut self.files.dialog else {
            return;
        };
        match dialog.ui(ctx) {
            Some(Answer::Open(structure)) => {
                // The dialog closes either way; a failed load is reported.
                self.issue(Command::ChooseStructure(Some(structure)));
            }
            Some(Answer::Cancel) => {
                self.files.dialog = None;
            }
            None => {}
        }
    }

    /// [`Command::ChooseStructure`]: builds the waiting file as
    /// `structure`, or with `None` cancels and keeps the current mesh.
    pub(crate) fn resolve_structure_dialog(
        &mut self,
        structure: Option<Structure>,
    ) -> Result<(), CommandError> {
        let Some(dialog) = self.files.dialog.take() else {
            return Err("no file is waiting for a structure".into());
        };
        match structure {
            Some(structure) => self.open_bytes(&dialog.bytes, &dialog.name, Some(structure), false),
            None => Ok(()),
        }
    }

    /// The file the structure dialog asks about, and its current choice.
    pub fn structure_dialog(&self) -> Option<(&str, Structure)> {
        self.files
            .dialog
            .as_ref()
            .map(|d| (d.name.as_str(), d.choice))
    }
}
