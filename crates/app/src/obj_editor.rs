//! The OBJ editor: type or paste OBJ text and watch the mesh and its tables
//! follow (the "paste an OBJ and watch its records appear" use). Edits are
//! debounced; a broken edit shows its message with the line, and the last
//! good mesh stays on screen.

use std::time::Duration;

/// How long typing must pause before the text is rebuilt.
const DEBOUNCE: Duration = Duration::from_millis(350);

/// The name loads from the editor get, so messages read `editor.obj:5: …`.
pub const EDITOR_FILE: &str = "editor.obj";

/// The editor's text and when it last changed.
#[derive(Default)]
pub struct ObjEditor {
    pub text: String,
    /// Seconds (egui time) of the last unbuilt edit.
    pending_since: Option<f64>,
    /// The message of the last failed build of this text, if any.
    pub error: Option<String>,
}

impl ObjEditor {
    /// Replaces the text, e.g. with the open mesh written as OBJ.
    pub fn set_text(&mut self, text: String) {
        self.text = text;
        self.pending_since = None;
        self.error = None;
    }

    /// Draws the editor. Returns the text to build once typing has paused.
    pub fn ui(&mut self, ui: &mut egui::Ui) -> Option<String> {
        let now = ui.input(|i| i.time);
        if let Some(error) = &self.error {
            ui.colored_label(ui.visuals().error_fg_color, error);
            ui.weak("The last good mesh stays on screen.");
        }
        let response = egui::ScrollArea::vertical()
            .show(ui, |ui| {
                ui.add(
                    egui::TextEdit::multiline(&mut self.text)
                        .code_editor()
                        .desired_width(f32::INFINITY)
                        .desired_rows(20)
                        .hint_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3"),
                )
            })
            .inner;
        if response.changed() {
            self.pending_since = Some(now);
        }
        let since = self.pending_since?;
        let wait = DEBOUNCE.as_secs_f64() - (now - since);
        if wait > 0.0 {
            ui.ctx()
                .request_repaint_after(Duration::from_secs_f64(wait));
            return None;
        }
        self.pending_since = None;
        Some(self.text.clone())
    }
}
