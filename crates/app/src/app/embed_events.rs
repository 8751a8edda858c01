//! What the app tells a page that embeds it: an event whenever the mesh,
//! the selection or the trace step changes, and the height its content
//! wants (docs/embedding.md, "The embed protocol"). The app observes itself
//! once a frame and queues what changed; the browser delivers the queue as
//! `edgewise:<event>` DOM events, which index.html forwards to the parent
//! frame with `postMessage`.

use edgewise_core::schema::ElementRef;
use serde::Serialize;

use super::EdgewiseApp;
use crate::state::{AnswerState, Counts, TraceState};

/// Events kept for a platform that does not deliver them (natively, until a
/// test takes them).
const QUEUED: usize = 64;

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
        }
    }
}

/// What the last frame's events described.
#[derive(Clone, Debug, Default, PartialEq)]
pub(crate) struct Observed {
    /// Mesh id (new for each mesh, conversion and edit) and structure.
    mesh: Option<(u64, &'static str)>,
    selection: Option<ElementRef>,
    /// Algorithm name, step and step count of the trace.
    step: Option<(String, usize, usize)>,
    height: u32,
}

/// The height an embedded view asks for at `width` CSS pixels: the 3D view
/// at 5:3 (within 240 to 720 pixels), the panels above and below it
/// (`chrome`, as laid out this frame), the message line and the margins.
pub fn preferred_height(width: f32, chrome: f32) -> u32 {
    let view = (width * 0.6).clamp(240.0, 720.0);
    (view + chrome + 48.0).round() as u32
}

impl EdgewiseApp {
    /// Queues an event for each thing that changed since the last frame.
    pub(super) fn observe_for_embedding(&mut self, ctx: &egui::Context) {
        let tab = self.tab();
        let document = tab.document.as_ref();
        let session = tab.run.session();
        let now = Observed {
            mesh: document.map(|d| (d.mesh_id(), d.structure().link_name())),
            selection: document.and_then(crate::document::Document::selection),
            step: session.map(|s| (s.trace.algorithm().name.clone(), s.step(), s.steps())),
            height: preferred_height(ctx.content_rect().width(), self.chrome_height),
        };
        if now == self.embed_observed {
            return;
        }
        let before = std::mem::replace(&mut self.embed_observed, now.clone());
        let mut events = Vec::new();
        if now.mesh != before.mesh {
            let state = self.state();
            events.push(EmbedEvent::MeshChange {
                mesh: state.mesh,
                structure: state.structure,
                counts: state.counts,
            });
        }
        if now.selection != before.selection {
            events.push(EmbedEvent::SelectionChange {
                selection: now.selection,
            });
        }
        if now.step != before.step {
            events.push(EmbedEvent::StepChange {
                trace: self.trace_state().map(Box::new),
            });
        }
        if now.height != before.height {
            events.push(EmbedEvent::Resize { height: now.height });
        }
        self.embed_events.extend(events);
        let excess = self.embed_events.len().saturating_sub(QUEUED);
        self.embed_events.drain(..excess);
    }

    /// Queues `edgewise:answer` for the run's question `index`, just
    /// answered.
    pub(super) fn report_answer(&mut self, index: usize) {
        let answer = self
            .tab()
            .run
            .session()
            .and_then(|session| AnswerState::of(session, index));
        if let Some(answer) = answer {
            self.embed_events.push(EmbedEvent::Answer(answer));
        }
    }

    /// Takes the queued events, oldest first.
    pub fn take_embed_events(&mut self) -> Vec<EmbedEvent> {
        std::mem::take(&mut self.embed_events)
    }
}
