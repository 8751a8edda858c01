//! The questions of one traced run ([`edgewise_core::lang::question`]):
//! which step asks which, what the student answered, and the card that asks.
//! Play stops at a question not yet answered; a click on an element, a
//! button or a number answers it, once, and the card then says whether it
//! was right and which steps give the answer.

use edgewise_core::lang::question::{Posed, Question, pose};
use edgewise_core::lang::{Trace, Value};
use egui::RichText;

use super::frame::value_text;
use crate::{command::Command, theme::Theme};

/// A student's answer to one question.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Answered {
    pub given: Value,
    pub correct: bool,
}

/// What kind of answer a question takes, as `state()` names it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Expects {
    /// A click on a vertex, an edge or a face (or the null button).
    Element,
    Boolean,
    Number,
}

impl Expects {
    pub fn key(self) -> &'static str {
        match self {
            Expects::Element => "element",
            Expects::Boolean => "boolean",
            Expects::Number => "number",
        }
    }

    fn of(expected: Value) -> Self {
        match expected {
            Value::Boolean(_) => Expects::Boolean,
            Value::Integer(_) | Value::Float(_) => Expects::Number,
            _ => Expects::Element,
        }
    }
}

/// The questions a run asks, with the answers so far.
#[derive(Clone, Debug, Default)]
pub struct Quiz {
    posed: Vec<Posed>,
    answers: Vec<Option<Answered>>,
    /// A sentence for each question the run cannot ask.
    pub problems: Vec<String>,
    /// What the number field holds.
    number_text: String,
}

/// One question as the card and `state()` show it.
#[derive(Clone, Debug, PartialEq)]
pub struct Asked<'q> {
    /// Its place among the run's questions, from 0.
    pub index: usize,
    pub posed: &'q Posed,
    pub expects: Expects,
    pub answered: Option<Answered>,
}

impl Quiz {
    pub fn new(trace: &Trace, questions: &[Question]) -> Self {
        let (posed, problems) = pose(trace, questions);
        Self {
            answers: vec![None; posed.len()],
            posed,
            problems,
            number_text: String::new(),
        }
    }

    pub fn len(&self) -> usize {
        self.posed.len()
    }

    pub fn is_empty(&self) -> bool {
        self.posed.is_empty()
    }

    /// The question asked at `step`: the first one not yet answered there,
    /// else the last one answered.
    pub fn at(&self, step: usize) -> Option<Asked<'_>> {
        let here: Vec<usize> = (0..self.posed.len())
            .filter(|&i| self.posed[i].ask_at == step)
            .collect();
        let index = here
            .iter()
            .copied()
            .find(|&i| self.answers[i].is_none())
            .or(here.last().copied())?;
        self.asked(index)
    }

    /// Question `index` of the run, from 0.
    pub fn asked(&self, index: usize) -> Option<Asked<'_>> {
        let posed = self.posed.get(index)?;
        Some(Asked {
            index,
            posed,
            expects: Expects::of(posed.expected),
            answered: self.answers.get(index).copied().flatten(),
        })
    }

    /// The question at `step` that waits for its answer, if any.
    pub fn waiting(&self, step: usize) -> Option<Asked<'_>> {
        self.at(step).filter(|asked| asked.answered.is_none())
    }

    /// Whether play stops at `step`: a question there waits for its answer.
    pub fn stops_at(&self, step: usize) -> bool {
        self.waiting(step).is_some()
    }

    /// How many were answered, and how many of those rightly.
    pub fn score(&self) -> (usize, usize) {
        let answered = self.answers.iter().flatten();
        (
            answered.clone().count(),
            answered.filter(|a| a.correct).count(),
        )
    }

    /// Answers the question waiting at `step`; returns its index.
    pub fn answer(&mut self, step: usize, given: Value) -> Result<usize, String> {
        let Some(asked) = self.at(step) else {
            return Err(format!(
                "no question is asked at step {step}; {}",
                self.where_asked()
            ));
        };
        if let Some(answered) = asked.answered {
            return Err(format!(
                "the question at step {step} is answered already ({})",
                value_text(answered.given)
            ));
        }
        if let Some(reason) = wrong_kind(asked.expects, given) {
            return Err(reason);
        }
        let index = asked.index;
        let correct = asked.posed.accepts(given);
        self.answers[index] = Some(Answered { given, correct });
        Ok(index)
    }

    /// "questions are asked at steps 0, 4 and 8" or "this run asks none".
    fn where_asked(&self) -> String {
        let steps: Vec<String> = self.posed.iter().map(|p| p.ask_at.to_string()).collect();
        match steps.as_slice() {
            [] => "this run asks none".to_owned(),
            [one] => format!("the question is asked at step {one}"),
            [rest @ .., last] => format!(
                "questions are asked at steps {} and {last}",
                rest.join(", ")
            ),
        }
    }

    /// The question card for `step`: the prompt, the ways to answer, then
    /// the verdict and the steps that explain it. It names only the parts
    /// the window `shows` (an embed may have no code and no tables).
    pub fn question_ui(
        &mut self,
        ui: &mut egui::Ui,
        trace: &Trace,
        step: usize,
        theme: &Theme,
        shows: Shown,
    ) -> Option<Command> {
        let (answered_count, right) = self.score();
        let total = self.len();
        let asked = self.at(step)?;
        let (index, expects, answered) = (asked.index, asked.expects, asked.answered);
        let posed = asked.posed.clone();
        let mut command = None;
        let accent = theme.trace_colour(crate::trace_role::TraceRole::Compared);
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
                        command = answer_buttons_ui(ui, expects, &mut self.number_text, shows);
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
                                theme.trace_colour(crate::trace_role::TraceRole::Output),
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
}

/// What the window around a question card shows besides the view.
#[derive(Clone, Copy, Debug)]
pub struct Shown {
    /// The algorithm's code, so a line number means something.
    pub code: bool,
    /// The tables, where an element can be clicked too.
    pub tables: bool,
}

/// Why `given` cannot answer a question that `expects` another kind.
fn wrong_kind(expects: Expects, given: Value) -> Option<String> {
    let fits = match expects {
        Expects::Element => given.element().is_some() || given == Value::Null,
        Expects::Boolean => matches!(given, Value::Boolean(_)),
        Expects::Number => matches!(given, Value::Integer(_) | Value::Float(_)),
    };
    (!fits).then(|| {
        let wanted = match expects {
            Expects::Element => "a vertex, an edge, a face or null",
            Expects::Boolean => "true or false",
            Expects::Number => "a number",
        };
        format!(
            "this question is answered with {wanted}, not {}",
            value_text(given)
        )
    })
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

/// A typed number: an Integer when it is whole and fits, else a Float.
pub fn number_value(n: f32) -> Value {
    if n.fract() == 0.0 && n.abs() <= 1.0e9 {
        Value::Integer(n as i32)
    } else {
        Value::Float(n)
    }
}
