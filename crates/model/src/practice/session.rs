//! One student's go at an exercise: the instance of each attempt, the
//! writes used, the last grade, and the score, as the app shows them,
//! `state().exercise` reports them and the embed protocol sends them.

use edgewise_core::mesh::Mesh;
use serde::Serialize;
use serde_json::{Value, json};

use super::attempt::{Outcome, steps_outcome};
use super::exercise::{Exercise, ExerciseError, Feedback};
use super::instance::{Instance, Task};
use super::seed::Seeded;
use super::walk::{Click, Clicks};

/// An exercise being done.
#[derive(Clone, Debug)]
pub struct Session {
    pub exercise: Exercise,
    pub instance: Instance,
    /// The seed the first attempt drew from; later attempts derive theirs.
    base_seed: u64,
    /// 1 for the first attempt.
    pub attempt: u32,
    /// Writes made by hand on this attempt's tables.
    pub writes: usize,
    /// The last grade, once the answer was checked (or graded live).
    pub last: Option<Outcome>,
    /// The model answer was shown: the attempt scores 0.
    pub model_answer_shown: bool,
    /// The attempt is over: passed, out of attempts, or the model answer
    /// shown.
    pub finished: bool,
    /// A walk's clicks so far.
    pub clicks: Clicks,
    /// A walk's or a prediction's answers this attempt, in order (`None`:
    /// null), which a saved attempt replays.
    pub answers: Vec<Option<edgewise_core::schema::ElementRef>>,
    /// The last graded action, as a gradebook records it.
    pub last_action: Option<Action>,
}

/// One graded action (a Check, a live grade, a click, an answer): what the
/// student gave and whether it was right, for an LMS's interaction record.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct Action {
    pub response: String,
    pub correct: bool,
}

/// `state().exercise`: the exercise as a script or a test reads it.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(rename_all = "camelCase")]
pub struct ExerciseState {
    pub name: String,
    pub title: String,
    pub kind: &'static str,
    pub structure: &'static str,
    pub seed: u64,
    pub attempt: u32,
    /// Attempts allowed; 0 is no limit.
    pub attempts: u32,
    /// Graded actions so far: a do-it exercise's writes.
    pub step: usize,
    /// Steps judged right, out of `total` (a do-it answer is one).
    pub correct: usize,
    pub total: usize,
    pub score: u32,
    pub max_score: u32,
    /// Null until graded.
    pub passed: Option<bool>,
    pub feedback: Option<String>,
    pub task: String,
    /// A do-it task's operation and ids, as `edgewise edit` names them.
    pub operation: Option<&'static str>,
    pub ids: Vec<u32>,
    /// A walk's elements found so far, in order.
    pub found: Vec<edgewise_core::schema::ElementRef>,
    /// The lookup a prediction asks about now (`line 14: half-edge 3.pair`).
    pub question: Option<String>,
    pub fewest_writes: Option<usize>,
    pub feedback_mode: &'static str,
    pub model_answer_offered: bool,
    pub model_answer_shown: bool,
    pub finished: bool,
    /// The last graded action's response and result; the result is null
    /// while feedback waits for the end.
    pub response: Option<String>,
    pub response_correct: Option<bool>,
}

impl Session {
    /// Starts `exercise` at the instance `seed` draws.
    pub fn start(exercise: Exercise, seed: u64) -> Result<Self, ExerciseError> {
        let instance = exercise.instance(seed)?;
        Ok(Self {
            exercise,
            instance,
            base_seed: seed,
            attempt: 1,
            writes: 0,
            last: None,
            model_answer_shown: false,
            finished: false,
            clicks: Clicks::default(),
            answers: Vec::new(),
            last_action: None,
        })
    }

    /// The mesh the student starts each attempt from.
    pub fn start_mesh(&self) -> &Mesh {
        &self.instance.mesh
    }

    /// Whether another attempt may start.
    pub fn attempts_left(&self) -> bool {
        self.exercise.attempts == 0 || self.attempt < self.exercise.attempts
    }

    /// Counts one write by hand.
    pub fn wrote(&mut self) {
        self.writes += 1;
    }

    /// Whether a write should be graded at once.
    pub fn grades_live(&self) -> bool {
        self.exercise.feedback == Feedback::Live && !self.finished
    }

    /// Grades `answer`; a pass, or the last attempt's check, ends the
    /// attempt.
    pub fn check(&mut self, answer: &Mesh) -> Result<&Outcome, ExerciseError> {
        if self.model_answer_shown {
            return Err(self.error("the model answer was shown: start a new instance to try again"));
        }
        if let Some((total, progress)) = self.steps() {
            // Finish on a walk or a prediction ends it where it stands.
            self.finished = true;
            let outcome = steps_outcome(&self.clicks, total, progress, None);
            return Ok(self.last.insert(outcome));
        }
        let outcome = self.exercise.grade(&self.instance, answer)?;
        self.graded_tables(outcome.passed);
        // With feedback at the end, the one Check is the end.
        let last_check = !self.attempts_left() && self.exercise.feedback != Feedback::Live;
        if outcome.passed || last_check || self.exercise.feedback == Feedback::AtEnd {
            self.finished = true;
        }
        Ok(self.last.insert(outcome))
    }

    /// Grades a write as it is made (live feedback): the attempt ends only
    /// on a pass.
    pub fn grade_live(&mut self, answer: &Mesh) -> Result<&Outcome, ExerciseError> {
        let outcome = self.exercise.grade(&self.instance, answer)?;
        self.graded_tables(outcome.passed);
        if outcome.passed {
            self.finished = true;
        }
        Ok(self.last.insert(outcome))
    }

    /// A walk's or a prediction's steps and how many are answered; `None`
    /// for a do-it exercise.
    fn steps(&self) -> Option<(usize, usize)> {
        match &self.instance.task {
            Task::DoIt { .. } => None,
            Task::Walk { expected, .. } => Some((expected.len(), self.clicks.found.len())),
            Task::Predict { lookups, .. } => Some((lookups.len(), self.clicks.answered())),
        }
    }

    /// Grades a click of a walk, or an answer of a prediction (`None`:
    /// null); it ends once every step is answered. `None` when there is
    /// nothing to answer (a do-it exercise, a finished attempt, a null in
    /// a walk).
    pub fn answer(&mut self, given: Option<edgewise_core::schema::ElementRef>) -> Option<Click> {
        if self.finished {
            return None;
        }
        let structure = self.exercise.structure;
        let click = match (&self.instance.task, given) {
            (
                Task::Walk {
                    expected, order, ..
                },
                Some(element),
            ) => self.clicks.click(expected, *order, element, structure)?,
            (Task::Predict { lookups, .. }, given) => {
                self.clicks.predict(lookups, given, structure)?
            }
            _ => return None,
        };
        self.answers.push(given);
        self.last_action = Some(Action {
            response: answer_name(structure, given),
            correct: click.right,
        });
        let (total, progress) = self.steps()?;
        let done = progress >= total;
        let mut outcome = steps_outcome(&self.clicks, total, progress, None);
        if !done {
            outcome.feedback.clone_from(&click.feedback);
        }
        self.finished = done;
        self.last = Some(outcome);
        Some(click)
    }

    /// Records a grade of the tables as the last action.
    pub(super) fn graded_tables(&mut self, passed: bool) {
        let s = if self.writes == 1 { "" } else { "s" };
        self.last_action = Some(Action {
            response: format!("the tables after {} write{s}", self.writes),
            correct: passed,
        });
    }

    /// [`Self::answer`] with an element: a click.
    pub fn click(&mut self, element: edgewise_core::schema::ElementRef) -> Option<Click> {
        self.answer(Some(element))
    }

    /// The question a prediction asks now, if one waits.
    pub fn question(&self) -> Option<String> {
        match &self.instance.task {
            Task::Predict { lookups, .. } if !self.finished => lookups
                .get(self.clicks.answered())
                .map(|l| format!("line {}: {}", l.line, l.question)),
            _ => None,
        }
    }

    /// Marks the model answer shown, which ends the attempt with a score of
    /// 0. The app shows it: a do-it's traced operation, a walk's marks, a
    /// prediction's lookups (named in the feedback).
    pub fn model_answer(&mut self) -> Result<(), ExerciseError> {
        if !self.exercise.model_answer {
            return Err(self.error("this exercise does not offer its model answer"));
        }
        let mut feedback = "The model answer is shown: this attempt scores 0.".to_owned();
        match &self.instance.task {
            Task::Walk { expected, .. } => self.clicks.found.clone_from(expected),
            Task::Predict { lookups, .. } => {
                let structure = self.exercise.structure;
                let given: Vec<String> = lookups
                    .iter()
                    .map(|l| format!("{} = {}", l.question, answer_name(structure, l.answer)))
                    .collect();
                feedback.push_str(&format!(" The lookups give: {}.", given.join("; ")));
            }
            Task::DoIt { .. } => {}
        }
        self.model_answer_shown = true;
        self.finished = true;
        let fewest = self.last.as_ref().and_then(|o| o.fewest_writes);
        self.last = Some(Outcome {
            passed: false,
            score: 0,
            max_score: self.max_score(),
            feedback,
            element: None,
            fewest_writes: fewest,
        });
        Ok(())
    }

    /// The next attempt: a fresh instance where the exercise draws them.
    pub fn next_attempt(&mut self) -> Result<(), ExerciseError> {
        if !self.attempts_left() {
            return Err(self.error(&format!("all {} attempts are used", self.exercise.attempts)));
        }
        self.go_to_attempt(self.attempt + 1)
    }

    /// Starts attempt `attempt` afresh, on its instance.
    pub(super) fn go_to_attempt(&mut self, attempt: u32) -> Result<(), ExerciseError> {
        if attempt != self.attempt {
            let seed = if self.exercise.fresh_instance {
                attempt_seed(self.base_seed, attempt)
            } else {
                self.base_seed
            };
            self.instance = self.exercise.instance(seed)?;
        }
        self.attempt = attempt;
        self.writes = 0;
        self.last = None;
        self.model_answer_shown = false;
        self.finished = false;
        self.clicks = Clicks::default();
        self.answers.clear();
        self.last_action = None;
        Ok(())
    }

    /// The seed the first attempt drew from.
    pub fn base_seed(&self) -> u64 {
        self.base_seed
    }

    pub(super) fn error(&self, message: &str) -> ExerciseError {
        ExerciseError {
            source: self.exercise.name.clone(),
            at: None,
            message: message.to_owned(),
        }
    }

    /// The most an attempt scores: the points of a do-it exercise, a walk's
    /// number of steps.
    pub fn max_score(&self) -> u32 {
        match &self.instance.task {
            Task::DoIt { .. } => self.exercise.points,
            Task::Walk { expected, .. } => expected.len() as u32,
            Task::Predict { lookups, .. } => lookups.len() as u32,
        }
    }

    pub fn state(&self) -> ExerciseState {
        let (operation, ids) = match &self.instance.task {
            Task::DoIt { operation, ids } => (Some(operation.name()), ids.clone()),
            Task::Walk { .. } | Task::Predict { .. } => (None, Vec::new()),
        };
        let (step, correct, total) = match &self.instance.task {
            Task::DoIt { .. } => (
                self.writes,
                usize::from(self.last.as_ref().is_some_and(|o| o.passed)),
                1,
            ),
            Task::Walk { expected, .. } => {
                (self.clicks.answered(), self.clicks.right, expected.len())
            }
            Task::Predict { lookups, .. } => {
                (self.clicks.answered(), self.clicks.right, lookups.len())
            }
        };
        let found = self.clicks.found.clone();
        // Feedback at the end shows nothing of a grade before the end.
        let last = self
            .last
            .as_ref()
            .filter(|_| self.finished || self.exercise.feedback != Feedback::AtEnd);
        ExerciseState {
            name: self.exercise.name.clone(),
            title: self.exercise.title.clone(),
            kind: self.exercise.kind.name(),
            structure: self.exercise.structure.prose(),
            seed: self.instance.seed,
            attempt: self.attempt,
            attempts: self.exercise.attempts,
            step,
            correct,
            total,
            score: last.map_or(0, |o| o.score),
            max_score: self.max_score(),
            passed: last.map(|o| o.passed),
            feedback: last.map(|o| o.feedback.clone()),
            task: self.instance.task.describe(self.exercise.structure),
            operation,
            ids,
            found,
            question: self.question(),
            fewest_writes: last.and_then(|o| o.fewest_writes),
            feedback_mode: self.exercise.feedback.name(),
            model_answer_offered: self.exercise.model_answer,
            model_answer_shown: self.model_answer_shown,
            finished: self.finished,
            response: self.last_action.as_ref().map(|a| a.response.clone()),
            response_correct: self
                .last_action
                .as_ref()
                .filter(|_| self.finished || self.exercise.feedback != Feedback::AtEnd)
                .map(|a| a.correct),
        }
    }

    /// The `edgewise:score` event's detail, with an xAPI statement a
    /// learning-record store or an H5P wrapper can forward as it is;
    /// `activity` is the exercise's IRI (the page's address for it).
    pub fn score(&self, activity: &str) -> Value {
        let state = self.state();
        let passed = state.passed == Some(true);
        let scaled = if state.max_score == 0 {
            0.0
        } else {
            f64::from(state.score) / f64::from(state.max_score)
        };
        let verb = if passed { "passed" } else { "failed" };
        json!({
            "exercise": state.name,
            "seed": state.seed,
            "attempt": state.attempt,
            "score": state.score,
            "maxScore": state.max_score,
            "passed": passed,
            "statement": {
                "verb": {
                    "id": format!("http://adlnet.gov/expapi/verbs/{verb}"),
                    "display": { "en-US": verb },
                },
                "object": {
                    "objectType": "Activity",
                    "id": activity,
                    "definition": {
                        "name": { "en-US": state.title },
                        "type": "http://adlnet.gov/expapi/activities/assessment",
                    },
                },
                "result": {
                    "score": {
                        "scaled": scaled,
                        "raw": state.score,
                        "min": 0,
                        "max": state.max_score,
                    },
                    "success": passed,
                    "completion": state.finished,
                    "response": state.feedback,
                },
                "context": {
                    "extensions": {
                        "https://edgewise.app/xapi/seed": state.seed,
                        "https://edgewise.app/xapi/attempt": state.attempt,
                    },
                },
            },
        })
    }
}

/// An answer as the card and a gradebook name it: `half-edge 7`, `null`.
fn answer_name(
    structure: edgewise_core::mesh::Structure,
    answer: Option<edgewise_core::schema::ElementRef>,
) -> String {
    answer.map_or_else(
        || "null".to_owned(),
        |e| edgewise_core::mesh::Element::of(structure, e).to_string(),
    )
}

/// The seed of a later attempt: mixed, so that attempts of neighbouring
/// seeds do not share instances.
fn attempt_seed(base: u64, attempt: u32) -> u64 {
    let mut mixed = Seeded::new(base ^ (u64::from(attempt) << 32));
    mixed.next()
}
