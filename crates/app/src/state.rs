//! The app's observable state, as returned by `window.edgewise.state()`.
//!
//! Browser tests and page authors read this instead of the pixels, so every
//! field is plain data that serialises to JSON.

use edgewise_core::schema::{ElementKind, ElementRef};
use std::collections::BTreeMap;

use edgewise_core::mesh::{Issue, MeshStats, Renumbering};
use serde::Serialize;

use crate::code_editor::Diagnostic;
pub use crate::history::HistoryState;
use edgewise_model::{
    algorithm::frame::TraceFrame, algorithm::frame::value_text, algorithm::session::TraceSession,
};

/// A JSON-serialisable snapshot of what the app shows.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct AppState {
    /// The Edgewise version.
    pub version: &'static str,
    /// "webgpu", "webgl2", or a native backend name.
    pub backend: &'static str,
    /// Frames drawn so far; proves the render loop is alive.
    pub frames: u64,
    /// Milliseconds the previous frame took on the page's main thread (the
    /// UI and issuing its drawing), or null before the second frame.
    #[serde(rename = "frameCpuMs")]
    pub frame_cpu_ms: Option<f32>,
    /// The open mesh's name, or null before any mesh is open.
    pub mesh: Option<String>,
    /// "winged" or "half", or null before any mesh is open.
    pub structure: Option<&'static str>,
    pub counts: Counts,
    /// The selected element, or null.
    pub selection: Option<ElementRef>,
    /// The element under the pointer, in the 3D view or in a table, which
    /// both views preview; or null.
    pub hovered: Option<ElementRef>,
    /// The selected element and every element it references.
    pub highlights: Vec<HighlightState>,
    /// The message of the last failed load or command, or null.
    pub error: Option<String>,
    /// Every record that breaks a rule of the structure at the editing
    /// trace's current step, or in diagnosis mode (empty otherwise).
    /// At most the first 1,000 of them; `broken_count` counts them all.
    pub broken: Vec<BrokenState>,
    /// How many records break a rule, all told.
    #[serde(rename = "brokenCount")]
    pub broken_count: usize,
    /// The mesh is a broken table opened to be fixed (see `broken`).
    pub diagnosis: bool,
    /// The exercise being done, or null (docs/practice.md).
    pub exercise: Option<edgewise_model::practice::ExerciseState>,
    /// What undo and redo would take back and make again, oldest first.
    pub history: HistoryState,
    /// The old-to-new ids of the last compacting, until dismissed: per
    /// table, each old id's new id (`null`: deleted), indexed by old id.
    pub renumbering: Option<Renumbering>,
    /// Whether the 3D view's last frame was drawn at the coarse level of
    /// detail: edges as lines and no vertex spheres, highlighted elements
    /// in full (a dense mesh seen from afar).
    #[serde(rename = "coarseView")]
    pub coarse_view: bool,
    /// Whether the view's last change of colours went to the GPU as patches
    /// of the elements it changed (a selection, a step), not every element.
    #[serde(rename = "stylesPatched")]
    pub styles_patched: bool,
    /// [drawn, copied]: how often the coarse view's base image was drawn,
    /// and copied to the screen in place of the mesh's lines and faces;
    /// null without a GPU.
    #[serde(rename = "baseImage")]
    pub base_image: Option<[u64; 2]>,
    /// How many frames drew a large mesh's motion proxy (a simplified copy
    /// of its lines and faces, while the camera moves) in place of the
    /// mesh; null without a GPU.
    #[serde(rename = "motionProxy")]
    pub motion_proxy: Option<u64>,
    /// [drawn, copied]: how often panels (the tables, the menus, the
    /// algorithm panel, the OBJ editor, the welcome card) unchanged since
    /// the frame before were drawn into a texture, and copied from it in
    /// place of drawing them; null without a GPU.
    #[serde(rename = "uiCache")]
    pub ui_cache: Option<[u64; 2]>,
    /// A large mesh being opened or converted a slice per frame, or null.
    pub job: Option<JobState>,
    /// The first-visit hint's three things to try, each true once done, or
    /// null when the hint is not shown (a link, an embed, or dismissed).
    pub welcome: Option<[bool; 3]>,
    /// The edit menu, while it is open: what it offers, and why each
    /// greyed-out entry is refused.
    #[serde(rename = "editMenu")]
    pub edit_menu: Option<EditMenuState>,
    /// V, E, F and the invariants of the mesh as it is now, or null.
    pub stats: Option<StatsState>,
    /// The trace being stepped through, or null.
    pub trace: Option<TraceState>,
    /// An algorithm waiting for its inputs, or null.
    pub pending: Option<PendingState>,
    /// The open tabs; the active one is the mesh everything else describes.
    pub tabs: Vec<TabState>,
    /// Whether the mesh is shown as winged-edge and half-edge side by side.
    #[serde(rename = "sideBySide")]
    pub side_by_side: bool,
    /// The selection in the side-by-side twin (the other structure), or null.
    #[serde(rename = "twinSelection")]
    pub twin_selection: Option<ElementRef>,
    /// Whether the app runs embedded (`?embed=1`: no menu bar).
    pub embed: bool,
    /// The OBJ editor's problems, each marked at its line: `{line, column, message}`.
    pub diagnostics: Vec<Diagnostic>,
    /// The dialog waiting for an answer, or null.
    pub dialog: Option<DialogState>,
    /// Where the window's parts are, as of the last frame drawn.
    pub layout: LayoutState,
}

/// A rectangle in CSS pixels of the page.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct RectState {
    pub x: f32,
    pub y: f32,
    pub w: f32,
    pub h: f32,
}

impl From<egui::Rect> for RectState {
    fn from(rect: egui::Rect) -> Self {
        Self {
            x: rect.min.x,
            y: rect.min.y,
            w: rect.width(),
            h: rect.height(),
        }
    }
}

impl RectState {
    pub fn area(&self) -> f32 {
        self.w * self.h
    }

    /// The part of this rectangle inside `bounds`.
    pub fn within(self, bounds: egui::Rect) -> Self {
        egui::Rect::from_min_size(egui::pos2(self.x, self.y), egui::vec2(self.w, self.h))
            .intersect(bounds)
            .into()
    }
}

/// What is where, with only what is on screen: `{window, view,
/// stepControls, sourceLines, panels: {topBar, algorithm, objEditor, tables}, overlays,
/// menus, topBar, compact}`. Tests and embedding pages check with it that
/// no panel squeezes the 3D view away, no overlay covers a control, and
/// every command can be reached.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct LayoutState {
    pub window: RectState,
    /// The 3D view (both views, side by side), or null before a frame.
    pub view: Option<RectState>,
    /// Step, Back, Play, the slider and Abort, while a trace runs.
    #[serde(rename = "stepControls")]
    pub step_controls: Option<RectState>,
    /// The first and last line of the algorithm's source in sight (the
    /// file's line numbers), while the panel shows a trace's code.
    #[serde(rename = "sourceLines")]
    pub source_lines: Option<[u32; 2]>,
    pub panels: BTreeMap<&'static str, RectState>,
    /// Cards drawn over the rest: the welcome card, the presentation hint.
    pub overlays: Vec<NamedRect>,
    /// The menus open, each with its entries and how many are in sight.
    pub menus: Vec<MenuLayout>,
    /// The top bar's commands; on a small screen, the menu button that holds
    /// the rest.
    #[serde(rename = "topBar")]
    pub top_bar: Vec<NamedRect>,
    /// The small-screen layout: one menu button, the panels as tabs under
    /// the view.
    pub compact: bool,
    /// The commands of the menu being drawn, for its [`MenuLayout`].
    #[serde(skip)]
    pub menu_commands: Vec<NamedRect>,
}

#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct NamedRect {
    pub name: &'static str,
    pub rect: RectState,
}

/// An open menu: its rectangle, its entries (buttons, checkboxes, sub-menus)
/// and how many of them are in sight without scrolling.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct MenuLayout {
    pub name: &'static str,
    pub rect: RectState,
    pub entries: usize,
    #[serde(rename = "visibleEntries")]
    pub visible_entries: usize,
    /// Whether the last entry is in sight (after scrolling, it must be).
    #[serde(rename = "lastEntryVisible")]
    pub last_entry_visible: bool,
    /// The top bar's commands this menu holds, on a small screen.
    pub commands: Vec<NamedRect>,
}

impl MenuLayout {
    /// Reads what `ui`, a menu's contents after they are drawn, holds: the
    /// clickable widgets on its layer. An entry is in sight when it is on
    /// screen and its parent's clip (a scroll area's viewport) cuts none of
    /// it.
    pub fn of(ui: &egui::Ui, name: &'static str) -> Self {
        let layer = ui.layer_id();
        let visible_area = ui.ctx().content_rect().intersect(ui.clip_rect());
        let (mut entries, mut visible, mut last_visible) = (0, 0, false);
        ui.ctx().viewport(|viewport| {
            for widget in viewport.this_pass.widgets.get_layer(layer) {
                if !widget.sense.senses_click() || widget.sense.senses_drag() {
                    continue;
                }
                entries += 1;
                last_visible = visible_area.contains_rect(widget.rect)
                    && widget.interact_rect.height() >= widget.rect.height() - 0.5;
                visible += usize::from(last_visible);
            }
        });
        Self {
            name,
            rect: ui.min_rect().intersect(visible_area).into(),
            entries,
            visible_entries: visible,
            last_entry_visible: last_visible,
            commands: Vec::new(),
        }
    }
}

/// A broken record: the row, the column (as the language names it) and
/// the rule, in one sentence.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct BrokenState {
    pub kind: ElementKind,
    pub id: u32,
    pub column: &'static str,
    pub rule: String,
}

impl BrokenState {
    pub fn new(issue: &Issue) -> Self {
        let element = ElementRef::from(issue.element);
        Self {
            kind: element.kind,
            id: element.id,
            column: issue
                .field
                .language_name()
                .unwrap_or(issue.field.record_name()),
            rule: issue.message.clone(),
        }
    }
}

/// Counts and invariants, without deleted rows.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct EditMenuState {
    pub element: ElementRef,
    pub entries: Vec<EditMenuEntry>,
}

#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct EditMenuEntry {
    pub operation: &'static str,
    pub ids: Vec<u32>,
    pub label: String,
    pub refused: Option<String>,
}

#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct StatsState {
    pub vertices: usize,
    pub edges: usize,
    pub faces: usize,
    /// V − E + F.
    pub euler: i64,
    /// Each component's genus, or null where it has a boundary.
    pub genus: Vec<Option<u64>>,
    #[serde(rename = "boundaryLoops")]
    pub boundary_loops: usize,
    pub components: usize,
}

impl StatsState {
    pub fn new(stats: &MeshStats) -> Self {
        Self {
            vertices: stats.vertices,
            edges: stats.edges,
            faces: stats.faces,
            euler: stats.euler_characteristic,
            genus: stats.components.iter().map(|c| c.genus).collect(),
            boundary_loops: stats.boundary_loops,
            components: stats.components.len(),
        }
    }
}

/// One tab.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct TabState {
    pub title: String,
    pub active: bool,
}

/// Where a trace is, as `state().trace` reports it.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct TraceState {
    pub algorithm: String,
    /// 'winged' or 'half'.
    pub structure: &'static str,
    /// 0 (inputs picked, nothing run) to `steps`.
    pub step: usize,
    pub steps: usize,
    /// The 1-based source line of the operation shown.
    pub line: u32,
    /// [start, end] byte offsets of the expression in the algorithm's
    /// source file, or null at step 0.
    pub span: Option<[u32; 2]>,
    /// Each variable's value: 'Edge 3', 'Integer 4', 'null'.
    pub variables: BTreeMap<String, String>,
    /// The operation's short name, as [`TraceFrame::operation`] lists them.
    ///
    /// [`TraceFrame::operation`]: edgewise_model::algorithm::frame::TraceFrame::operation
    pub operation: &'static str,
    /// Marked elements in marking order.
    pub marked: Vec<ElementRef>,
    pub done: bool,
    /// The message line's sentence for this step.
    pub message: String,
    /// The run-time error that stopped the run, shown at its last step.
    pub error: Option<String>,
    /// The algorithm's `message` output so far: the latest 200 lines.
    pub output: Vec<String>,
    /// How many `message`s the run printed so far.
    #[serde(rename = "outputCount")]
    pub output_count: usize,
    /// The call stack, the started algorithm first.
    pub calls: Vec<String>,
    /// The question asked at this step, or null.
    pub question: Option<QuestionState>,
    /// The run's questions so far, or null when it asks none.
    pub questions: Option<QuestionsState>,
}

/// A stop-and-think question at the current step.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct QuestionState {
    /// Its place among the run's questions, from 0.
    pub index: usize,
    pub prompt: String,
    /// The source line it asks about.
    pub line: u32,
    /// 'element' (a click, or null), 'boolean' or 'number'.
    pub expects: &'static str,
    /// The answer given, or null while it waits for one.
    pub answer: Option<AnswerState>,
}

/// An answered question, as `state()` and `edgewise:answer` report it.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct AnswerState {
    /// Its place among the run's questions, from 0.
    pub index: usize,
    pub prompt: String,
    pub line: u32,
    /// The step it is asked at.
    pub step: usize,
    /// 'Edge 3', 'Boolean true', 'Integer 4', 'null'.
    pub given: String,
    pub expected: String,
    pub correct: bool,
    /// The steps that give the answer, as the trace prints them.
    pub explanation: String,
}

impl AnswerState {
    /// Question `index` of `session`'s run, if it was answered.
    pub fn of(session: &TraceSession, index: usize) -> Option<Self> {
        let asked = session.quiz.as_ref()?.asked(index)?;
        let answered = asked.answered?;
        let trace = &session.trace;
        Some(Self {
            index,
            prompt: asked.posed.question.prompt.clone(),
            line: asked.posed.line(trace),
            step: asked.posed.ask_at,
            given: value_text(answered.given),
            expected: value_text(asked.posed.expected),
            correct: answered.correct,
            explanation: asked.posed.explanation(trace),
        })
    }
}

/// How a run's questions went.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct QuestionsState {
    /// How many the run asks.
    pub asked: usize,
    pub answered: usize,
    pub right: usize,
    /// Why some questions are not asked (a line the run never reaches).
    pub problems: Vec<String>,
}

impl TraceState {
    pub fn new(session: &TraceSession, frame: &TraceFrame) -> Self {
        let algorithm = session.trace.algorithm();
        let quiz = session.quiz.as_ref();
        let question = quiz
            .and_then(|quiz| quiz.at(session.step()))
            .map(|asked| QuestionState {
                index: asked.index,
                prompt: asked.posed.question.prompt.clone(),
                line: asked.posed.line(&session.trace),
                expects: asked.expects.key(),
                answer: AnswerState::of(session, asked.index),
            });
        let questions = quiz
            .filter(|quiz| !quiz.is_empty() || !quiz.problems.is_empty())
            .map(|quiz| {
                let (answered, right) = quiz.score();
                QuestionsState {
                    asked: quiz.len(),
                    answered,
                    right,
                    problems: quiz.problems.clone(),
                }
            });
        Self {
            question,
            questions,
            algorithm: algorithm.name.clone(),
            structure: algorithm.structure.link_name(),
            step: frame.step,
            steps: frame.steps,
            line: frame.line,
            span: frame.span.map(|(start, end)| [start, end]),
            variables: frame
                .variables
                .iter()
                .map(|v| (v.name.clone(), v.value.clone()))
                .collect(),
            operation: frame.operation,
            marked: frame.marked.clone(),
            done: frame.done,
            message: frame.message.clone(),
            error: frame.error.clone(),
            output: frame.output.clone(),
            output_count: frame.output_count,
            calls: frame.calls.clone(),
        }
    }
}

/// An algorithm waiting for inputs.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct PendingState {
    pub algorithm: String,
    /// The parameter the next pick gives, or null when all are given.
    pub parameter: Option<String>,
    /// The kind of element that can be picked, or null.
    pub kind: Option<ElementKind>,
    /// "vertexAdjacentEdge: pick a Vertex for v".
    pub prompt: Option<String>,
}

/// An open dialog: `kind` is `'structure'` (which structure to build a PLY or
/// OBJ file as), with the file and the choice it offers first.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct DialogState {
    pub kind: &'static str,
    pub file: String,
    pub structure: &'static str,
}

/// Table sizes. In a winged-edge mesh `halfedges` is twice `edges`, the
/// number of half-edges the same mesh would have.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
pub struct Counts {
    pub vertices: usize,
    pub edges: usize,
    pub faces: usize,
    pub halfedges: usize,
}

/// One highlighted element and its role ('selected', 'left predecessor').
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct HighlightState {
    pub kind: ElementKind,
    pub id: u32,
    pub role: String,
    /// The colour it is drawn in, `#rrggbb`.
    pub colour: String,
}

/// One entry of `window.edgewise.algorithms()`.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct AlgorithmInfo {
    pub name: String,
    /// 'winged' or 'half'.
    pub structure: &'static str,
    /// "v : Vertex" for each parameter.
    pub parameters: Vec<String>,
    pub description: Option<String>,
    /// 'library', or the file the user loaded it from.
    pub origin: String,
}

/// A large mesh being prepared a slice per frame (`cancel()` drops it).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct JobState {
    pub id: u64,
    /// "Opening torus-200k", "Converting torus-200k to winged-edge".
    pub label: String,
    /// From 0 to 1.
    pub progress: f32,
}
