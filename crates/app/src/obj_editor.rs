//! The OBJ editor: type or paste OBJ text and watch the mesh and its tables
//! follow (the "paste an OBJ and watch its records appear" use). Edits are
//! debounced; a broken edit is marked at its line and column in the text,
//! and the last good mesh stays on screen.

use std::time::Duration;

use edgewise_core::formats::{FormatError, Location};

use crate::code_editor::{CodeEditor, Diagnostic};

/// How long typing must pause before the text is rebuilt, once a line is
/// ended (Enter) or after a paste.
const DEBOUNCE: Duration = Duration::from_millis(350);

/// How long typing within a line must pause: `f 1 2 3` on the way to
/// `f 1 2 3 4` is a valid triangle, and must not replace the last good mesh
/// while the student is still typing the line.
const LINE_PAUSE: Duration = Duration::from_millis(900);

/// Text to build, and whether a paste made it (a new mesh, to be framed).
pub struct Edited {
    pub text: String,
    pub pasted: bool,
}

/// The most text the editor holds: it lays out and rebuilds its whole text,
/// so larger meshes are opened as files instead.
pub const MAX_EDITOR_BYTES: usize = 1 << 20;

/// The name loads from the editor get, so messages read `editor.obj:5: …`.
pub const EDITOR_FILE: &str = "editor.obj";

/// The editor's text and when it last changed.
#[derive(Default)]
pub struct ObjEditor {
    pub text: String,
    /// Seconds (egui time) of the last unbuilt edit, and how long it waits.
    pending_since: Option<(f64, Duration)>,
    /// Whether a paste is among the unbuilt edits.
    pasted: bool,
    /// The problems of the last failed build that have a line.
    pub diagnostics: Vec<Diagnostic>,
    /// Problems of the last failed build without a line (the mesh as a whole).
    pub file_problems: Vec<String>,
    /// Why the last typed or pasted text was refused (it was too large).
    pub refused: Option<String>,
}

impl ObjEditor {
    /// Replaces the text, e.g. with the open mesh written as OBJ.
    pub fn set_text(&mut self, text: String) {
        self.text = text;
        self.pending_since = None;
        self.set_error(None);
    }

    /// Records the outcome of building the text: marks on its lines, or none.
    pub fn set_error(&mut self, error: Option<&FormatError>) {
        self.diagnostics.clear();
        self.file_problems.clear();
        for problem in error.map(FormatError::problems).unwrap_or_default() {
            match problem.location {
                Location::Line { line, column } => self.diagnostics.push(Diagnostic {
                    line,
                    column,
                    message: problem.message.clone(),
                }),
                Location::File | Location::Byte(_) => {
                    self.file_problems.push(problem.to_string());
                }
            }
        }
    }

    pub fn has_error(&self) -> bool {
        !self.diagnostics.is_empty() || !self.file_problems.is_empty()
    }

    /// Draws the editor. Returns the text to build once typing has paused.
    pub fn ui(&mut self, ui: &mut egui::Ui) -> Option<Edited> {
        let now = ui.input(|i| i.time);
        let (pasted, line_ended) = ui.input(|i| {
            let pasted = i.events.iter().any(|e| matches!(e, egui::Event::Paste(_)));
            let ended = i.events.iter().any(|e| match e {
                egui::Event::Text(text) => text.contains('\n'),
                egui::Event::Key { key, pressed, .. } => *pressed && *key == egui::Key::Enter,
                _ => false,
            });
            (pasted, ended)
        });
        for problem in &self.file_problems {
            ui.colored_label(ui.visuals().error_fg_color, problem);
        }
        if self.has_error() {
            ui.weak("The last good mesh stays on screen.");
        }
        if let Some(refused) = &self.refused {
            ui.colored_label(ui.visuals().error_fg_color, refused);
        }
        let output = CodeEditor::new("obj_editor", &mut self.text)
            .diagnostics(&self.diagnostics)
            .hint_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3")
            .max_bytes(MAX_EDITOR_BYTES)
            .show(ui);
        if let Some(refused) = output.refused {
            self.refused = Some(format!("{refused}; open larger meshes with Open mesh…"));
        }
        if output.response.changed() {
            let pause = if pasted || line_ended {
                DEBOUNCE
            } else {
                LINE_PAUSE
            };
            self.pending_since = Some((now, pause));
            self.pasted |= pasted;
            self.refused = None;
        }
        let (since, pause) = self.pending_since?;
        let wait = pause.as_secs_f64() - (now - since);
        if wait > 0.0 {
            ui.ctx()
                .request_repaint_after(Duration::from_secs_f64(wait));
            return None;
        }
        self.pending_since = None;
        Some(Edited {
            text: self.text.clone(),
            pasted: std::mem::take(&mut self.pasted),
        })
    }
}
