//! The question sets that course links and the JavaScript API give, kept
//! per algorithm (by name and structure) across runs and asked besides its
//! `//?` comments.

use std::collections::HashMap;

use edgewise_core::lang::Algorithm;
use edgewise_core::lang::question::{Question, parse_set};
use edgewise_core::mesh::Structure;

use super::quiz::{Quiz, questions_of};
use super::run::AlgorithmRun;
use super::session::Run;

/// Each algorithm's set: its text as given, and the questions read from it.
#[derive(Clone, Debug, Default)]
pub struct QuestionSets {
    sets: HashMap<(String, Structure), (String, Vec<Question>)>,
}

fn key_of(algorithm: &Algorithm) -> (String, Structure) {
    (algorithm.name.clone(), algorithm.structure)
}

impl QuestionSets {
    /// The questions a run of `algorithm` asks: its `//?` comments, then
    /// the set given for it.
    pub fn questions_for(&self, algorithm: &Algorithm) -> Vec<Question> {
        let set = self.sets.get(&key_of(algorithm));
        questions_of(algorithm, set.map(|(_, set)| set.as_slice()))
    }

    /// The set given for `algorithm`, as written, for share links.
    pub fn text_for(&self, algorithm: &Algorithm) -> Option<&str> {
        self.sets
            .get(&key_of(algorithm))
            .map(|(text, _)| text.as_str())
    }

    /// Gives the running algorithm a question set (replacing the last one)
    /// and asks it from the current run on.
    pub fn set(&mut self, run: &mut AlgorithmRun, text: &str) -> Result<(), String> {
        let Some(algorithm) = run.algorithm().cloned() else {
            return Err("start an algorithm before giving it questions".to_owned());
        };
        let set = parse_set(text).map_err(|error| format!("questions:{error}"))?;
        self.sets.insert(key_of(&algorithm), (text.to_owned(), set));
        if let Run::Tracing(session) = &mut run.run {
            session.quiz = None;
        }
        self.pose(run);
        Ok(())
    }

    /// Poses the run's questions if it is traced and has not yet.
    pub fn pose(&self, run: &mut AlgorithmRun) {
        let Run::Tracing(session) = &mut run.run else {
            return;
        };
        if session.quiz.is_none() {
            let questions = self.questions_for(session.trace.algorithm());
            session.quiz = Some(Quiz::new(&session.trace, &questions));
            run.changed();
        }
    }
}
