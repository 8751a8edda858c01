//! Algorithms: the library and the user's own, running one on the open mesh,
//! and walking its trace in the 3D view, the tables and the algorithm view.
//!
//! - [`library`]: what the Algorithm menu offers;
//! - [`session`]: picking inputs, then stepping through a recorded trace;
//! - [`frame`]: what one step shows (the journal's colours and labels);
//! - [`highlight`]: syntax colouring from the language's lexer;
//! - [`panel`]: the algorithm view and its controls;
//! - [`quiz`]: stop-and-think questions and the student's answers;
//! - [`editor`]: writing, checking, opening and saving algorithms.

pub mod editor;
pub mod frame;
pub mod highlight;
pub mod library;
pub mod panel;
pub mod quiz;
pub mod session;

use edgewise_core::schema::ElementRef;
use edgewise_core::schema::Structure;
use std::collections::{BTreeSet, HashMap};
use std::sync::Arc;

use edgewise_core::{
    lang::{Algorithm, Value, question::Question},
    mesh::Mesh,
};

pub use frame::TraceFrame;
pub use library::{AlgorithmLibrary, Origin};
pub use session::{PendingRun, Run, TraceSession};

use crate::theme::Theme;

/// Seconds between automatic steps when playing, by default.
const DEFAULT_DELAY: f32 = 0.6;

/// The algorithms every tab shares: the library, the editor, breakpoints
/// and how traces play.
pub struct Algorithms {
    pub library: AlgorithmLibrary,
    /// Breakpoint lines, kept per algorithm across runs.
    breakpoints: HashMap<(String, Structure), BTreeSet<u32>>,
    /// Question sets from course links and the JavaScript API, kept per
    /// algorithm across runs, asked besides its `//?` comments.
    question_sets: HashMap<(String, Structure), (String, Vec<Question>)>,
    /// Seconds between automatic steps.
    pub delay: f32,
    pub editor: editor::AlgorithmEditor,
    /// Point size of the algorithm view's code.
    pub code_size: f32,
    /// The colouring of the algorithm on show, keyed by its source.
    highlighted: Option<(Arc<str>, highlight::Highlighted)>,
    /// Where the step controls were drawn this frame, for
    /// `state().layout.stepControls`; the app takes it after each frame.
    pub step_controls: Option<egui::Rect>,
    /// The panel is a small screen's sheet, which scrolls: the source keeps
    /// a least height instead of taking what the controls leave.
    pub in_sheet: bool,
}

impl Default for Algorithms {
    fn default() -> Self {
        Self {
            library: AlgorithmLibrary::shipped(),
            breakpoints: HashMap::new(),
            question_sets: HashMap::new(),
            delay: DEFAULT_DELAY,
            editor: editor::AlgorithmEditor::default(),
            code_size: 14.0,
            highlighted: None,
            step_controls: None,
            in_sheet: false,
        }
    }
}

/// One tab's algorithm run: waiting for inputs or being traced, and the
/// frame of its current step.
#[derive(Default)]
pub struct AlgorithmRun {
    pub run: Run,
    /// Bumped on every change of run or step, so views re-derive colours.
    generation: u64,
    /// The frame of the current step, and the (generation, theme key) it is for.
    frame: Option<((u64, u64), TraceFrame)>,
    /// The step the source view last scrolled to.
    scrolled_to: Option<(u64, usize)>,
}

impl Algorithms {
    /// Looks up `name` for the mesh's structure, explaining a miss.
    pub fn find(&self, name: &str, structure: Structure) -> Result<Arc<Algorithm>, String> {
        if let Some(algorithm) = self.library.find(name, structure) {
            return Ok(Arc::clone(algorithm));
        }
        if self.library.exists_anywhere(name) {
            return Err(format!(
                "`{name}` is written for the {} structure and the mesh is {}; switch the structure to run it",
                structure.other().prose(),
                structure.prose()
            ));
        }
        Err(format!(
            "there is no algorithm called `{name}`; the Algorithm menu lists them"
        ))
    }

    fn key_of(algorithm: &Algorithm) -> (String, Structure) {
        (algorithm.name.clone(), algorithm.structure)
    }

    /// The breakpoint lines of `algorithm`.
    pub fn breakpoints(&self, algorithm: Option<&Arc<Algorithm>>) -> BTreeSet<u32> {
        algorithm
            .and_then(|algorithm| self.breakpoints.get(&Self::key_of(algorithm)))
            .cloned()
            .unwrap_or_default()
    }

    /// Sets or clears a breakpoint on `line` of the run's algorithm.
    pub fn toggle_breakpoint(&mut self, run: &mut AlgorithmRun, line: u32) {
        let Some(algorithm) = run.algorithm() else {
            return;
        };
        let set = self.breakpoints.entry(Self::key_of(algorithm)).or_default();
        if !set.remove(&line) {
            set.insert(line);
        }
        run.changed();
    }

    /// The questions a run of `algorithm` asks: its `//?` comments, then
    /// the set given for it.
    pub fn questions_for(&self, algorithm: &Algorithm) -> Vec<Question> {
        let mut questions = edgewise_core::lang::question::from_comments(algorithm);
        if let Some((_, set)) = self.question_sets.get(&Self::key_of(algorithm)) {
            questions.extend(set.iter().cloned());
        }
        questions
    }

    /// The question set given for `algorithm`, as written, for share links.
    pub fn question_set_text(&self, algorithm: &Algorithm) -> Option<&str> {
        self.question_sets
            .get(&Self::key_of(algorithm))
            .map(|(text, _)| text.as_str())
    }

    /// Gives the running algorithm a question set (replacing the last one)
    /// and asks it from the current run on.
    pub fn set_questions(&mut self, run: &mut AlgorithmRun, text: &str) -> Result<(), String> {
        let Some(algorithm) = run.algorithm().cloned() else {
            return Err("start an algorithm before giving it questions".to_owned());
        };
        let set = edgewise_core::lang::question::parse_set(text)
            .map_err(|error| format!("questions:{error}"))?;
        self.question_sets
            .insert(Self::key_of(&algorithm), (text.to_owned(), set));
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
            session.quiz = Some(quiz::Quiz::new(&session.trace, &questions));
            run.changed();
        }
    }

    /// Advances `run` if it is playing; see [`AlgorithmRun::tick`].
    pub fn tick(&self, run: &mut AlgorithmRun, now: f64) -> Option<f64> {
        let breakpoints = self.breakpoints(run.algorithm());
        run.tick(now, f64::from(self.delay), &breakpoints)
    }

    /// Jumps `run` to the next step on a breakpoint line (or the end).
    pub fn continue_to_breakpoint(&self, run: &mut AlgorithmRun) -> Result<(), String> {
        let breakpoints = self.breakpoints(run.algorithm());
        let session = run.session_mut()?;
        let target = session.next_breakpoint(&breakpoints);
        session.goto(target);
        run.changed();
        Ok(())
    }

    /// The syntax colouring of `algorithm`'s source, cached.
    fn highlighted(&mut self, source: &Arc<str>) -> &highlight::Highlighted {
        if self
            .highlighted
            .as_ref()
            .is_some_and(|(s, _)| !Arc::ptr_eq(s, source))
        {
            self.highlighted = None;
        }
        &self
            .highlighted
            .get_or_insert_with(|| (Arc::clone(source), highlight::Highlighted::new(source)))
            .1
    }
}

impl AlgorithmRun {
    pub fn generation(&self) -> u64 {
        self.generation
    }

    fn changed(&mut self) {
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

    fn session_mut(&mut self) -> Result<&mut TraceSession, String> {
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
            _ => std::borrow::Cow::Owned(frame::frame_at(&session.trace, session.step(), theme)),
        })
    }

    /// The frame of the current step, derived once per change.
    pub fn frame(&mut self, theme: &Theme) -> Option<&TraceFrame> {
        let key = (self.generation, theme.key());
        let Run::Tracing(session) = &self.run else {
            return None;
        };
        if self.frame.as_ref().is_none_or(|(k, _)| *k != key) {
            let frame = frame::frame_at(&session.trace, session.step(), theme);
            self.frame = Some((key, frame));
        }
        self.frame.as_ref().map(|(_, frame)| frame)
    }
}
