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
pub mod highlight;
pub mod panel;
pub mod quiz_ui;

use edgewise_core::schema::Structure;
use std::collections::{BTreeSet, HashMap};
use std::sync::Arc;

use edgewise_core::lang::Algorithm;

use edgewise_model::algorithm::frame::TraceFrame;
use edgewise_model::algorithm::library::AlgorithmLibrary;
use edgewise_model::algorithm::question_sets::QuestionSets;
use edgewise_model::algorithm::run::AlgorithmRun;
use edgewise_model::algorithm::session::Run;

/// Seconds between automatic steps when playing, by default.
const DEFAULT_DELAY: f32 = 0.6;

/// The algorithms every tab shares: the library, the editor, breakpoints
/// and how traces play.
pub struct Algorithms {
    pub library: AlgorithmLibrary,
    /// Breakpoint lines, kept per algorithm across runs.
    breakpoints: HashMap<(String, Structure), BTreeSet<u32>>,
    /// Question sets from course links and the JavaScript API.
    pub question_sets: QuestionSets,
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
    /// The first and last source line in sight this frame, for
    /// `state().layout.sourceLines`; the app takes it after each frame.
    pub source_lines: Option<[u32; 2]>,
    /// The panel is a small screen's sheet, which scrolls: the source keeps
    /// a least height instead of taking what the controls leave.
    pub in_sheet: bool,
}

impl Default for Algorithms {
    fn default() -> Self {
        Self {
            library: AlgorithmLibrary::shipped(),
            breakpoints: HashMap::new(),
            question_sets: QuestionSets::default(),
            delay: DEFAULT_DELAY,
            editor: editor::AlgorithmEditor::default(),
            code_size: 14.0,
            highlighted: None,
            step_controls: None,
            source_lines: None,
            in_sheet: false,
        }
    }
}

impl Algorithms {
    /// Looks up `name` for the mesh's structure, explaining a miss.
    pub fn find(&self, name: &str, structure: Structure) -> Result<Arc<Algorithm>, String> {
        self.library.find_or_explain(name, structure)
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
