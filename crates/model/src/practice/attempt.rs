//! Grading one answer to an instance, as the app, the CLI and a course's
//! auto-grader all report it.

use edgewise_core::mesh::Mesh;
use edgewise_core::mesh::grade::grade_edit;
use edgewise_core::schema::ElementRef;
use serde::Serialize;

use super::exercise::{Exercise, ExerciseError};
use super::instance::{Instance, Task};
use super::walk::Clicks;

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
    /// Grades a whole walk at once (an answer file): `clicks` against what
    /// the walk marks, right steps out of all.
    pub fn grade_clicks(
        &self,
        instance: &Instance,
        clicks: &[ElementRef],
    ) -> Result<Outcome, ExerciseError> {
        let Task::Walk {
            expected, order, ..
        } = &instance.task
        else {
            return Err(ExerciseError {
                source: self.name.clone(),
                at: None,
                message: "a do-it exercise is answered by tables, not by elements clicked"
                    .to_owned(),
            });
        };
        let mut walk = Clicks::default();
        let mut first_wrong = None;
        for (step, &element) in clicks.iter().enumerate() {
            match walk.click(expected, *order, element, self.structure) {
                Some(click) if !click.right && first_wrong.is_none() => {
                    first_wrong = Some(format!("click {}: {}", step + 1, click.feedback));
                }
                Some(_) => {}
                None => {
                    first_wrong.get_or_insert_with(|| {
                        format!(
                            "click {}: the walk marks {} elements, and every one is clicked \
                             already",
                            step + 1,
                            expected.len()
                        )
                    });
                }
            }
        }
        Ok(walk_outcome(&walk, expected, first_wrong))
    }
}

/// The grade of a walk's clicks: right steps out of all, a pass when
/// every element was found right the first time.
pub(super) fn walk_outcome(
    walk: &Clicks,
    expected: &[ElementRef],
    first_wrong: Option<String>,
) -> Outcome {
    let total = expected.len();
    let passed = walk.right == total && walk.wrong == 0;
    let feedback = match first_wrong {
        Some(wrong) => wrong,
        None if walk.done(expected) => format!("Correct: every one of the {total} steps."),
        None => format!(
            "{} of the {total} elements are clicked; the walk marks {} more.",
            walk.found.len(),
            total - walk.found.len()
        ),
    };
    Outcome {
        passed,
        score: walk.right as u32,
        max_score: total as u32,
        feedback,
        element: None,
        fewest_writes: None,
    }
}
