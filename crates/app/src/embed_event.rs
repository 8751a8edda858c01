//! The events the embed protocol sends a host page (docs/embedding.md,
//! "The embed protocol"). The app queues them (`app/embed_events.rs`) and
//! the platform delivers them; the type sits below both.

use edgewise_core::schema::ElementRef;
use serde::Serialize;

use edgewise_model::practice::ExerciseState;

use crate::state::{AnswerState, Counts, TraceState};

/// One event, named `edgewise:<name>` on the page.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(untagged)]
pub enum EmbedEvent {
    /// The app has started and applied its link: `window.edgewise` and the
    /// embed commands work from now on.
    Ready {
        version: &'static str,
        /// "webgpu" or "webgl2".
        backend: &'static str,
    },
    /// A mesh was opened, converted or edited (`mesh` null: none is open).
    MeshChange {
        mesh: Option<String>,
        structure: Option<&'static str>,
        counts: Counts,
    },
    SelectionChange {
        selection: Option<ElementRef>,
    },
    /// The trace moved, started or ended (`trace` null: no run).
    StepChange {
        /// Boxed: the other events are small.
        trace: Option<Box<TraceState>>,
    },
    /// The content's preferred height in CSS pixels, for the iframe.
    Resize {
        height: u32,
    },
    /// A question was answered.
    Answer(AnswerState),
    /// An exercise or a new attempt of one started.
    ExerciseStart(ExerciseState),
    /// An action of an exercise was graded (a check, or a write with live
    /// feedback).
    ExerciseStep(ExerciseState),
    /// An attempt ended with a score: `{exercise, seed, attempt, score,
    /// maxScore, passed, statement}`, the statement shaped as xAPI.
    Score(serde_json::Value),
}

impl EmbedEvent {
    /// The event's name after `edgewise:`.
    pub fn name(&self) -> &'static str {
        match self {
            Self::Ready { .. } => "ready",
            Self::MeshChange { .. } => "meshchange",
            Self::SelectionChange { .. } => "selectionchange",
            Self::StepChange { .. } => "stepchange",
            Self::Resize { .. } => "resize",
            Self::Answer(_) => "answer",
            Self::ExerciseStart(_) => "exercisestart",
            Self::ExerciseStep(_) => "exercisestep",
            Self::Score(_) => "score",
        }
    }
}
