//! What the app tells a page that embeds it: an event whenever the mesh,
//! the selection or the trace step changes, and the height its content
//! wants (docs/embedding.md, "The embed protocol"). The app observes itself
//! once a frame and queues what changed; the browser delivers the queue as
//! `edgewise:<event>` DOM events, which index.html forwards to the parent
//! frame with `postMessage`.

use edgewise_core::schema::ElementRef;

use super::EdgewiseApp;
use crate::{EmbedEvent, state::AnswerState};

/// Events kept for a platform that does not deliver them (natively, until a
/// test takes them).
const QUEUED: usize = 64;

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
            selection: document.and_then(edgewise_model::document::Document::selection),
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
