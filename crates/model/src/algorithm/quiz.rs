//! The questions of one traced run ([`edgewise_core::lang::question`]):
//! which step asks which, and what the student answered. The app draws the
//! card that asks.
//! Play stops at a question not yet answered; a click on an element, a
//! button or a number answers it, once, and the card then says whether it
//! was right and which steps give the answer.

use edgewise_core::lang::question::{Posed, Question, pose};
use edgewise_core::lang::{Algorithm, Trace, Value};

use super::frame::value_text;

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
    /// What the card's number field holds.
    pub number_text: String,
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

/// The questions a run of `algorithm` asks: its `//?` comments, then the
/// `set` given for it (by a course link or the JavaScript API).
pub fn questions_of(algorithm: &Algorithm, set: Option<&[Question]>) -> Vec<Question> {
    let mut questions = edgewise_core::lang::question::from_comments(algorithm);
    questions.extend(set.unwrap_or_default().iter().cloned());
    questions
}

/// A typed number: an Integer when it is whole and fits, else a Float.
pub fn number_value(n: f32) -> Value {
    if n.fract() == 0.0 && n.abs() <= 1.0e9 {
        Value::Integer(n as i32)
    } else {
        Value::Float(n)
    }
}
