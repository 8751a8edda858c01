//! Practice: exercises a student does rather than watches, each drawn as a
//! fresh instance from a seed and graded step by step (docs/practice.md).
//!
//! - [`exercise`] reads the exercise format (TOML) and says where a file is
//!   wrong;
//! - [`catalog`] holds the exercises Edgewise ships;
//! - [`instance`] draws an instance from a seed, always one the task applies
//!   to and worth doing;
//! - [`attempt`] grades an answer: a do-it answer by the core's grader
//!   ([`edgewise_core::mesh::grade`]);
//! - [`progress`] saves an attempt as short text and brings it back;
//! - [`session`] is one student's go: attempts, writes, grades and the
//!   score the embed protocol reports.

pub mod attempt;
pub mod catalog;
mod error;
pub mod exercise;
pub mod instance;
pub mod progress;
mod seed;
pub mod session;
pub mod walk;

pub use attempt::Outcome;
pub use exercise::{Exercise, ExerciseError, Feedback, Kind, TaskSpec};
pub use instance::{Instance, Task};
pub use progress::Progress;
pub use session::{Action, ExerciseState, Session};
pub use walk::{Click, Order};

#[cfg(test)]
mod tests;
