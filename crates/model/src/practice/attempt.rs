//! Grading one answer to an instance, as the app, the CLI and a course's
//! auto-grader all report it.

use edgewise_core::mesh::Mesh;
use edgewise_core::mesh::grade::grade_edit;
use edgewise_core::schema::ElementRef;
use serde::Serialize;

use super::exercise::{Exercise, ExerciseError};
use super::instance::{Instance, Task};
use super::walk::{Click, Clicks};

/// The grade of an answer.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "camelCase")]
pub struct Outcome {
    pub passed: bool,
    pub score: u32,
    pub max_score: u32,
    /// What is right, or the first difference, in the tables' words.
    pub feedback: String,
    /// The answer's row the feedback is about.
    #[serde(skip)]
    pub element: Option<ElementRef>,
    /// For a do-it task: the fewest writes the operation needs.
    pub fewest_writes: Option<usize>,
}

impl Exercise {
    /// Grades `answer` for `instance` (drawn from this exercise).
    pub fn grade(&self, instance: &Instance, answer: &Mesh) -> Result<Outcome, ExerciseError> {
        let Task::DoIt { operation, ids } = &instance.task else {
            return Err(ExerciseError {
                source: self.name.clone(),
                at: None,
                message: "a walk is answered by the elements clicked, not by tables".to_owned(),
            });
        };
        let grade = grade_edit(&instance.mesh, *operation, ids, answer).map_err(|refusal| {
            ExerciseError {
                source: self.name.clone(),
                at: None,
                message: format!("the instance is refused: {refusal}"),
            }
        })?;
        let passed = grade.passed();
        let (feedback, element) = match grade.difference {
            None => (
                format!(
                    "Correct: the tables hold the result of {operation} {}.",
                    ids.iter()
                        .map(ToString::to_string)
                        .collect::<Vec<_>>()
                        .join(" ")
                ),
                None,
            ),
            Some(difference) => (difference.message, difference.element),
        };
        Ok(Outcome {
            passed,
            score: if passed { self.points } else { 0 },
            max_score: self.points,
            feedback,
            element,
            fewest_writes: Some(grade.fewest_writes),
        })
    }
}

impl Exercise {
    /// Grades a whole walk or prediction at once (an answer file): each
    /// answer (`None`: null) against the trace, right steps out of all.
    pub fn grade_clicks(
        &self,
        instance: &Instance,
        answers: &[Option<ElementRef>],
    ) -> Result<Outcome, ExerciseError> {
        let (total, what) = match &instance.task {
            Task::Walk { expected, .. } => (expected.len(), "the walk marks"),
            Task::Predict { lookups, .. } => (lookups.len(), "the run looks up"),
            Task::DoIt { .. } => {
                return Err(ExerciseError {
                    source: self.name.clone(),
                    at: None,
                    message: "a do-it exercise is answered by tables, not by elements clicked"
                        .to_owned(),
                });
            }
        };
        let mut clicks = Clicks::default();
        let mut first_wrong = None;
        for (step, &given) in answers.iter().enumerate() {
            let graded = match (&instance.task, given) {
                (
                    Task::Walk {
                        expected, order, ..
                    },
                    Some(element),
                ) => clicks.click(expected, *order, element, self.structure),
                (Task::Walk { .. }, None) => {
                    clicks.wrong += 1;
                    Some(Click {
                        right: false,
                        feedback: "null is not an element the walk marks".to_owned(),
                    })
                }
                (Task::Predict { lookups, .. }, given) => {
                    clicks.predict(lookups, given, self.structure)
                }
                (Task::DoIt { .. }, _) => None,
            };
            match graded {
                Some(click) if !click.right && first_wrong.is_none() => {
                    first_wrong = Some(format!("answer {}: {}", step + 1, click.feedback));
                }
                Some(_) => {}
                None => {
                    first_wrong.get_or_insert_with(|| {
                        format!(
                            "answer {}: {what} {total} elements, and every one is answered \
                             already",
                            step + 1
                        )
                    });
                }
            }
        }
        let progress = match &instance.task {
            Task::Walk { .. } => clicks.found.len(),
            _ => clicks.answered(),
        };
        Ok(steps_outcome(&clicks, total, progress, first_wrong))
    }
}

/// The grade of a walk's clicks or a prediction's answers: right steps out
/// of all (`progress` of `total` answered), a pass when every step was
/// right the first time.
pub(super) fn steps_outcome(
    clicks: &Clicks,
    total: usize,
    progress: usize,
    first_wrong: Option<String>,
) -> Outcome {
    let passed = clicks.right == total && clicks.wrong == 0;
    let feedback = match first_wrong {
        Some(wrong) => wrong,
        None if passed => format!("Correct: every one of the {total} steps."),
        None if progress >= total => format!(
            "Done: {} of the {total} steps right the first time.",
            clicks.right
        ),
        None => format!(
            "{progress} of the {total} steps are answered; {} remain.",
            total - progress
        ),
    };
    Outcome {
        passed,
        score: clicks.right as u32,
        max_score: total as u32,
        feedback,
        element: None,
        fewest_writes: None,
    }
}
