//! Grading one answer to an instance, as the app, the CLI and a course's
//! auto-grader all report it.

use edgewise_core::mesh::Mesh;
use edgewise_core::mesh::grade::grade_edit;
use edgewise_core::schema::ElementRef;
use serde::Serialize;

use super::exercise::{Exercise, ExerciseError};
use super::instance::{Instance, Task};

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
        let Task::DoIt { operation, ids } = &instance.task;
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
