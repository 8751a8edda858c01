//! The card that asks a run's questions ([`edgewise_model::algorithm::quiz`]):
//! the prompt, the ways to answer, then the verdict and the steps that
//! explain it.

use edgewise_core::lang::{Trace, Value};
use edgewise_model::algorithm::frame::value_text;
use edgewise_model::algorithm::quiz::{Expects, Quiz, number_value};
use edgewise_model::theme::Theme;
use egui::RichText;

use crate::command::Command;

/// The question card for `step`: the prompt, the ways to answer, then
/// the verdict and the steps that explain it. It names only the parts
/// the window `shows` (an embed may have no code and no tables).
pub fn question_ui(
    quiz: &mut Quiz,
    ui: &mut egui::Ui,
    trace: &Trace,
    step: usize,
    theme: &Theme,
    shows: Shown,
) -> Option<Command> {
    let (answered_count, right) = quiz.score();
    let total = quiz.len();
    let asked = quiz.at(step)?;
    let (index, expects, answered) = (asked.index, asked.expects, asked.answered);
    let posed = asked.posed.clone();
    let mut command = None;
    let accent = theme.trace_colour(edgewise_model::trace_role::TraceRole::Compared);
    egui::Frame::new()
        .fill(accent.gamma_multiply(0.12))
        .stroke(egui::Stroke::new(1.5, accent))
        .inner_margin(8.0)
        .corner_radius(4.0)
        .show(ui, |ui| {
            ui.set_width(ui.available_width());
            let heading = if shows.code {
                format!(
                    "Question {} of {total} (line {})",
                    index + 1,
                    posed.line(trace)
                )
            } else {
                format!("Question {} of {total}", index + 1)
            };
            ui.label(RichText::new(heading).small().strong());
            ui.label(RichText::new(&posed.question.prompt).strong());
            match answered {
                None => {
                    command = answer_buttons_ui(ui, expects, &mut quiz.number_text, shows);
                    if ui
                        .small_button("Skip")
                        .on_hover_text("Show the next step without answering")
                        .clicked()
                    {
                        command = Some(Command::Step(1));
                    }
                }
                Some(answered) => {
                    let (verdict, colour) = if answered.correct {
                        (
                            "Right",
                            theme.trace_colour(edgewise_model::trace_role::TraceRole::Output),
                        )
                    } else {
                        ("Not quite", ui.visuals().error_fg_color)
                    };
                    ui.label(
                        RichText::new(format!(
                            "{verdict}: you answered {}; the answer is {}.",
                            value_text(answered.given),
                            value_text(posed.expected)
                        ))
                        .color(colour)
                        .strong(),
                    );
                    ui.label(posed.explanation(trace));
                    ui.label(
                        RichText::new(format!("{right} of {answered_count} answered right"))
                            .small(),
                    );
                }
            }
        });
    command
}

/// What the window around a question card shows besides the view.
#[derive(Clone, Copy, Debug)]
pub struct Shown {
    /// The algorithm's code, so a line number means something.
    pub code: bool,
    /// The tables, where an element can be clicked too.
    pub tables: bool,
}

/// The buttons or field for an unanswered question.
fn answer_buttons_ui(
    ui: &mut egui::Ui,
    expects: Expects,
    number: &mut String,
    shows: Shown,
) -> Option<Command> {
    let mut command = None;
    ui.horizontal_wrapped(|ui| match expects {
        Expects::Element => {
            ui.label(if shows.tables {
                "Click the element in the view or the tables, or"
            } else {
                "Click the element in the view, or"
            });
            if ui.button("null").clicked() {
                command = Some(Command::Answer(Value::Null));
            }
        }
        Expects::Boolean => {
            for (text, value) in [("True", true), ("False", false)] {
                if ui.button(text).clicked() {
                    command = Some(Command::Answer(Value::Boolean(value)));
                }
            }
        }
        Expects::Number => {
            let field = ui.add(egui::TextEdit::singleline(number).desired_width(80.0));
            let entered = field.lost_focus() && ui.input(|i| i.key_pressed(egui::Key::Enter));
            if (ui.button("Answer").clicked() || entered)
                && let Ok(n) = number.trim().parse::<f32>()
                && n.is_finite()
            {
                command = Some(Command::Answer(number_value(n)));
            }
        }
    });
    command
}
