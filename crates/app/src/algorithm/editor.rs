//! Writing algorithms: type or paste source, see errors at their
//! line:column as you type, and find each algorithm that compiles in the
//! menu at once.

use std::time::Duration;

use edgewise_core::lang::{self, diagnostic::LineIndex};
use egui::{Color32, Stroke, text::LayoutJob};

use super::{
    AlgorithmLibrary,
    highlight::{CodeStyle, Highlighted, Mark},
};
use crate::theme::Theme;

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

/// One problem in the text, placed for the editor.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Problem {
    pub line: u32,
    pub column: u32,
    /// Byte range in the text, underlined.
    pub range: std::ops::Range<usize>,
    pub message: String,
}

/// The editor's text, its problems and what the last compile added.
pub struct AlgorithmEditor {
    pub text: String,
    pending_since: Option<f64>,
    pub problems: Vec<Problem>,
    /// "Added to the menu: a, b", after a good compile.
    pub status: Option<String>,
}

impl Default for AlgorithmEditor {
    fn default() -> Self {
        Self {
            text: TEMPLATE.to_owned(),
            pending_since: None,
            problems: Vec::new(),
            status: None,
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
                let names = library.add(&program, &super::Origin::User(EDITOR_FILE.to_owned()));
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
                        Problem {
                            line: at.line,
                            column: at.column,
                            range: d.span.range(),
                            message,
                        }
                    })
                    .collect();
                self.status = None;
            }
        }
    }

    /// Draws the editor; compiles once typing has paused.
    pub fn ui(&mut self, ui: &mut egui::Ui, library: &mut AlgorithmLibrary, theme: &Theme) {
        let now = ui.input(|i| i.time);
        ui.weak("Write an algorithm; each one that compiles joins the Algorithm menu.");
        if let Some(status) = &self.status {
            ui.colored_label(theme.trace_colour(super::TraceRole::Lookup), status);
        }
        for problem in &self.problems {
            ui.colored_label(
                ui.visuals().error_fg_color,
                format!(
                    "{EDITOR_FILE}:{}:{}: {}",
                    problem.line, problem.column, problem.message
                ),
            );
        }
        let style = CodeStyle::new(14.0, theme.dark);
        let error_colour = ui.visuals().error_fg_color;
        let problems = self.problems.clone();
        let mut layouter = |ui: &egui::Ui, text: &dyn egui::TextBuffer, wrap_width: f32| {
            let text = text.as_str();
            let mut job = layout(text, &style, &problems, error_colour);
            job.wrap.max_width = wrap_width;
            ui.fonts_mut(|f| f.layout_job(job))
        };
        let response = egui::ScrollArea::vertical()
            .id_salt("algorithm_editor")
            .show(ui, |ui| {
                ui.add(
                    egui::TextEdit::multiline(&mut self.text)
                        .code_editor()
                        .desired_width(f32::INFINITY)
                        .desired_rows(18)
                        .layouter(&mut layouter),
                )
            })
            .inner;
        if response.changed() {
            self.pending_since = Some(now);
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
    }
}

/// The coloured text with each problem's range underlined in red.
fn layout(text: &str, style: &CodeStyle, problems: &[Problem], error: Color32) -> LayoutJob {
    let marks: Vec<Mark> = problems
        .iter()
        .map(|p| Mark {
            range: p.range.clone(),
            background: error.gamma_multiply(0.15),
            text: None,
            underline: Stroke::new(2.0, error),
        })
        .collect();
    Highlighted::new(text).layout(text, 0..text.len(), &marks, style)
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
