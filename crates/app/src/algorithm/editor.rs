//! Writing algorithms: type or paste source, see errors at their
//! line:column as you type, and find each algorithm that compiles in the
//! menu at once.

use std::time::Duration;

use edgewise_core::lang::{self, diagnostic::LineIndex};

use super::{
    AlgorithmLibrary,
    highlight::{CodeStyle, Highlighted},
};
use crate::code_editor::{CodeEditor, Diagnostic};
use edgewise_model::theme::Theme;

/// How long typing must pause before the text is compiled.
const DEBOUNCE: Duration = Duration::from_millis(400);

/// The name algorithms from the editor carry in messages and the menu.
pub const EDITOR_FILE: &str = "editor.alg";

/// A starting point for a new algorithm.
const TEMPLATE: &str = "algorithm myAlgorithm(v : Vertex) : HalfEdge;\n\
description \"Mark the half-edge leaving v's incident edge.\"\n\
var e : Edge;\n\
begin\n\
  highlight v;\n\
  e := v.incidentEdge;\n\
  mark e.pairEdge;\n\
end\n";

/// What the editor asks the app to do with files.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum EditorCommand {
    Open,
    Save,
}

/// The editor's text, its problems and what the last compile added.
pub struct AlgorithmEditor {
    pub text: String,
    pending_since: Option<f64>,
    /// Each error, marked at its line and column in the editor.
    pub problems: Vec<Diagnostic>,
    /// "Added to the menu: a, b", after a good compile.
    pub status: Option<String>,
    /// The name the text is saved under: the opened file's, or a default.
    pub file_name: String,
    /// Why the last typed or pasted text was refused (it was too large).
    pub refused: Option<String>,
}

impl Default for AlgorithmEditor {
    fn default() -> Self {
        Self {
            text: TEMPLATE.to_owned(),
            pending_since: None,
            problems: Vec::new(),
            status: None,
            file_name: "algorithms.alg".to_owned(),
            refused: None,
        }
    }
}

impl AlgorithmEditor {
    /// Replaces the text (an opened file) and compiles it now.
    pub fn set_text(&mut self, text: String, library: &mut AlgorithmLibrary) {
        self.text = text;
        self.pending_since = None;
        self.compile(library);
    }

    /// Compiles the text; algorithms that compile join the menu, replacing
    /// their earlier versions.
    pub fn compile(&mut self, library: &mut AlgorithmLibrary) {
        match lang::compile(&self.text) {
            Ok(program) => {
                self.problems.clear();
                let names = library.add(
                    &program,
                    &edgewise_model::algorithm::library::Origin::User(EDITOR_FILE.to_owned()),
                );
                self.status = Some(format!("In the Algorithm menu: {}", names.join(", ")));
            }
            Err(diagnostics) => {
                let index = LineIndex::new(&self.text);
                self.problems = diagnostics
                    .iter()
                    .filter(|d| d.is_error())
                    .map(|d| {
                        let at = index.line_column(&self.text, d.span.start);
                        let mut message = d.message.clone();
                        if let Some(hint) = &d.hint {
                            message.push_str(&format!(" (hint: {hint})"));
                        }
                        Diagnostic {
                            line: at.line as usize,
                            column: Some(at.column as usize),
                            message,
                        }
                    })
                    .collect();
                self.status = None;
            }
        }
    }

    /// Draws the editor; compiles once typing has paused. Returns a file
    /// command for the app to carry out.
    pub fn ui(
        &mut self,
        ui: &mut egui::Ui,
        library: &mut AlgorithmLibrary,
        theme: &Theme,
    ) -> Option<EditorCommand> {
        let now = ui.input(|i| i.time);
        let mut command = None;
        ui.horizontal(|ui| {
            if ui
                .button("Open file…")
                .on_hover_text("Open a file of algorithms (.alg), or drop one on the window")
                .clicked()
            {
                command = Some(EditorCommand::Open);
            }
            if ui
                .button("Save…")
                .on_hover_text(format!("Save this text as {}", self.file_name))
                .clicked()
            {
                command = Some(EditorCommand::Save);
            }
        });
        ui.weak("Write an algorithm; each one that compiles joins the Algorithm menu.");
        if let Some(status) = &self.status {
            ui.colored_label(
                theme.trace_colour(edgewise_model::trace_role::TraceRole::Lookup),
                status,
            );
        }
        if let Some(first) = self.problems.first() {
            ui.colored_label(
                ui.visuals().error_fg_color,
                format!(
                    "{} problem{}; the first at {EDITOR_FILE}:{}:{}",
                    self.problems.len(),
                    if self.problems.len() == 1 { "" } else { "s" },
                    first.line,
                    first.column.unwrap_or(1)
                ),
            );
        }
        let style = CodeStyle::new(14.0, theme.dark);
        let highlighter = move |_: &egui::Style, text: &str| {
            Highlighted::new(text).layout(text, 0..text.len(), &[], &style)
        };
        if let Some(refused) = &self.refused {
            ui.colored_label(ui.visuals().error_fg_color, refused);
        }
        let output = CodeEditor::new("algorithm_editor", &mut self.text)
            .diagnostics(&self.problems)
            .highlighter(&highlighter)
            .hint_text("algorithm name(v : Vertex) : HalfEdge;\nbegin\n  …\nend")
            .desired_rows(18)
            .max_bytes(lang::MAX_SOURCE_BYTES)
            .show(ui);
        if output.refused.is_some() {
            self.refused = output.refused;
        }
        if output.response.changed() {
            self.pending_since = Some(now);
            self.refused = None;
        }
        if let Some(since) = self.pending_since {
            let wait = DEBOUNCE.as_secs_f64() - (now - since);
            if wait > 0.0 {
                ui.ctx()
                    .request_repaint_after(Duration::from_secs_f64(wait));
            } else {
                self.pending_since = None;
                self.compile(library);
            }
        }
        command
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_template_compiles_into_the_menu() {
        let mut library = AlgorithmLibrary::default();
        let mut editor = AlgorithmEditor::default();
        editor.compile(&mut library);
        assert!(editor.problems.is_empty(), "{:?}", editor.problems);
        assert_eq!(library.entries().len(), 1);
    }

    #[test]
    fn a_mistake_is_placed_at_its_line_and_column() {
        let mut library = AlgorithmLibrary::default();
        let mut editor = AlgorithmEditor {
            text: TEMPLATE.replace("e := v.incidentEdge;", "e := v.incidentEgde;"),
            ..AlgorithmEditor::default()
        };
        editor.compile(&mut library);
        let problem = editor.problems.first().expect("a problem");
        assert_eq!(problem.line, 6);
        assert!(problem.message.contains("incidentEgde"), "{problem:?}");
        assert!(library.entries().is_empty(), "nothing joins the menu");
    }
}
