//! Why an exercise was refused, with the place in its file where there is
//! one: what every part of practice reports.

use std::fmt;
use std::ops::Range;

/// Why an exercise file was refused: where, and what is wrong.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ExerciseError {
    /// The file or exercise name.
    pub source: String,
    /// 1-based line and column, where the fault has a place.
    pub at: Option<(usize, usize)>,
    pub message: String,
}

impl fmt::Display for ExerciseError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.at {
            Some((line, column)) => write!(f, "{}:{line}:{column}: {}", self.source, self.message),
            None => write!(f, "{}: {}", self.source, self.message),
        }
    }
}

impl std::error::Error for ExerciseError {}

/// Builds located errors for one file.
pub(super) struct Located<'a> {
    pub(super) source: &'a str,
    text: &'a str,
}

impl<'a> Located<'a> {
    pub(super) fn new(source: &'a str, text: &'a str) -> Self {
        Self { source, text }
    }

    pub(super) fn error(
        &self,
        span: Option<Range<usize>>,
        message: impl Into<String>,
    ) -> ExerciseError {
        ExerciseError {
            source: self.source.to_owned(),
            at: span.map(|span| line_column(self.text, span.start)),
            message: message.into(),
        }
    }
}

/// The 1-based line and column (in characters) of a byte offset.
fn line_column(text: &str, offset: usize) -> (usize, usize) {
    let before = text.get(..offset.min(text.len())).unwrap_or(text);
    let line = before.matches('\n').count() + 1;
    let column = before
        .rsplit('\n')
        .next()
        .map_or(0, |rest| rest.chars().count())
        + 1;
    (line, column)
}
