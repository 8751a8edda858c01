//! One tab's run of an algorithm: waiting for its inputs, then its recorded
//! trace walked step by step, with the frame of the current step kept for
//! the views.

use std::collections::BTreeSet;
use std::sync::Arc;

use edgewise_core::lang::{Algorithm, Value};
use edgewise_core::mesh::Mesh;
use edgewise_core::schema::ElementRef;

use super::frame::{TraceFrame, frame_at};
use super::session::{PendingRun, Run, TraceSession};
use crate::theme::Theme;

/// One tab's algorithm run: waiting for inputs or being traced, and the
/// frame of its current step.
#[derive(Default)]
pub struct AlgorithmRun {
    pub run: Run,
    /// Bumped on every change of run or step, so views re-derive colours.
    generation: u64,
    /// The frame of the current step, and the (generation, theme key) it is for.
    frame: Option<((u64, u64), TraceFrame)>,
    /// The source line the algorithm view last scrolled to: it scrolls
    /// again only when the current line changes, so a student can scroll
    /// the code while a loop stays on one line.
    pub scrolled_to: Option<u32>,
}

impl AlgorithmRun {
    pub fn generation(&self) -> u64 {
        self.generation
    }

    /// Marks the run changed: views derive its colours again.
    pub fn changed(&mut self) {
        self.generation += 1;
        self.frame = None;
    }

    /// Whether an algorithm is waiting for inputs or being traced.
    pub fn is_active(&self) -> bool {
        !matches!(self.run, Run::Idle)
    }

    /// The algorithm of the current run.
    pub fn algorithm(&self) -> Option<&Arc<Algorithm>> {
        match &self.run {
            Run::Idle => None,
            Run::Picking(pending) => Some(&pending.algorithm),
            Run::Tracing(session) => Some(session.trace.algorithm()),
        }
    }

    pub fn session(&self) -> Option<&TraceSession> {
        match &self.run {
            Run::Tracing(session) => Some(session),
            _ => None,
        }
    }

    pub fn session_mut(&mut self) -> Result<&mut TraceSession, String> {
        match &mut self.run {
            Run::Tracing(session) => Ok(session),
            Run::Picking(pending) => Err(format!(
                "{} is still waiting for its inputs",
                pending.algorithm.name
            )),
            Run::Idle => Err("no algorithm is running".to_owned()),
        }
    }
    /// Starts `algorithm`: it waits for its inputs, or runs at once if it
    /// needs none. `inputs` are given up front (the JavaScript API).
    pub fn begin(
        &mut self,
        algorithm: Arc<Algorithm>,
        inputs: &[(String, Value)],
        mesh: &Mesh,
    ) -> Result<(), String> {
        let mut pending = PendingRun::new(algorithm);
        for (name, value) in inputs {
            if !pending.algorithm.params().any(|p| p.name == *name) {
                let names: Vec<&str> = pending
                    .algorithm
                    .params()
                    .map(|p| p.name.as_str())
                    .collect();
                return Err(format!(
                    "{} has no parameter `{name}` (its parameters: {})",
                    pending.algorithm.name,
                    if names.is_empty() {
                        "none".to_owned()
                    } else {
                        names.join(", ")
                    }
                ));
            }
            pending.set(name, *value);
        }
        let complete = pending.missing().is_none();
        let scalars = pending.has_scalar_inputs() && inputs.is_empty();
        self.run = Run::Picking(pending);
        self.changed();
        if complete && !scalars {
            self.start(mesh)?;
        }
        Ok(())
    }

    /// Gives the waiting algorithm a picked element; runs it once complete.
    pub fn pick(&mut self, element: ElementRef, mesh: &Mesh) -> Result<(), String> {
        let Run::Picking(pending) = &mut self.run else {
            return Err("no algorithm is waiting for an input".to_owned());
        };
        pending.pick(element)?;
        let ready = pending.missing().is_none() && !pending.has_scalar_inputs();
        self.changed();
        if ready {
            self.start(mesh)?;
        }
        Ok(())
    }

    /// Records the waiting algorithm's run and stops at step 0. On an input
    /// error the algorithm keeps waiting.
    pub fn start(&mut self, mesh: &Mesh) -> Result<(), String> {
        let Run::Picking(pending) = &self.run else {
            return Err("no algorithm is waiting to start".to_owned());
        };
        let session = pending.start(mesh)?;
        self.run = Run::Tracing(Box::new(session));
        self.changed();
        Ok(())
    }

    /// Answers the question asked at the current step; returns its index
    /// among the run's questions.
    pub fn answer(&mut self, given: Value) -> Result<usize, String> {
        let session = self.session_mut()?;
        let step = session.step();
        let quiz = session.quiz.as_mut().ok_or("this run asks no questions")?;
        let index = quiz.answer(step, given)?;
        self.changed();
        Ok(index)
    }

    pub fn step(&mut self, n: usize) -> Result<(), String> {
        self.session_mut()?.forward(n);
        self.changed();
        Ok(())
    }

    pub fn step_over(&mut self) -> Result<(), String> {
        self.session_mut()?.step_over();
        self.changed();
        Ok(())
    }

    pub fn step_out(&mut self) -> Result<(), String> {
        self.session_mut()?.step_out()?;
        self.changed();
        Ok(())
    }

    pub fn back(&mut self, n: usize) -> Result<(), String> {
        self.session_mut()?.back(n);
        self.changed();
        Ok(())
    }

    pub fn goto(&mut self, k: usize) -> Result<(), String> {
        self.session_mut()?.goto(k);
        self.changed();
        Ok(())
    }

    /// Stops the run; the mesh returns to its plain look.
    pub fn abort(&mut self) -> Result<(), String> {
        if !self.is_active() {
            return Err("no algorithm is running".to_owned());
        }
        self.run = Run::Idle;
        self.changed();
        Ok(())
    }

    /// The mesh changed under the run (a new file, a structure switch): the
    /// trace no longer describes it.
    pub fn mesh_changed(&mut self) {
        if self.is_active() {
            self.run = Run::Idle;
            self.changed();
        }
    }

    /// Plays or pauses the trace; at its end Play starts it over.
    pub fn set_playing(&mut self, playing: bool, now: f64) -> Result<(), String> {
        let session = self.session_mut()?;
        if playing && session.at_end() {
            session.goto(0);
        }
        session.playing = playing;
        session.last_auto_step = now;
        self.changed();
        Ok(())
    }

    /// Advances a playing trace when `delay` seconds have passed, stopping
    /// at `breakpoints`; returns how long to wait for the next step.
    pub fn tick(&mut self, now: f64, delay: f64, breakpoints: &BTreeSet<u32>) -> Option<f64> {
        let Run::Tracing(session) = &mut self.run else {
            return None;
        };
        if !session.playing {
            return None;
        }
        let due = session.last_auto_step + delay;
        if now < due {
            return Some(due - now);
        }
        session.auto_step(breakpoints);
        session.last_auto_step = now;
        let playing = session.playing;
        self.changed();
        playing.then_some(delay)
    }

    /// The frame of the current step: the cached one when it is current
    /// (the app derives it before drawing), else derived now without caching.
    pub fn current_frame(&self, theme: &Theme) -> Option<std::borrow::Cow<'_, TraceFrame>> {
        let Run::Tracing(session) = &self.run else {
            return None;
        };
        let key = (self.generation, theme.key());
        Some(match &self.frame {
            Some((k, frame)) if *k == key => std::borrow::Cow::Borrowed(frame),
            _ => std::borrow::Cow::Owned(frame_at(&session.trace, session.step(), theme)),
        })
    }

    /// The frame of the current step, derived once per change.
    pub fn frame(&mut self, theme: &Theme) -> Option<&TraceFrame> {
        let key = (self.generation, theme.key());
        let Run::Tracing(session) = &self.run else {
            return None;
        };
        if self.frame.as_ref().is_none_or(|(k, _)| *k != key) {
            let frame = frame_at(&session.trace, session.step(), theme);
            self.frame = Some((key, frame));
        }
        self.frame.as_ref().map(|(_, frame)| frame)
    }
}
