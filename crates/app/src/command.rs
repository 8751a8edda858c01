//! Everything a user can ask of the app. Menus, keys, the algorithm view,
//! the JavaScript API and course links all build a [`Command`] and hand it
//! to `EdgewiseApp::execute` (in `app/execute.rs`), which carries it out on
//! the active tab and, if it is refused, records why in one place: the
//! tab's error panel and `state().error`.

use std::fmt;

use edgewise_core::{
    lang::Value,
    mesh::{Structure, operations::Operation},
    schema::{ElementKind, ElementRef},
};

use crate::save_format::SaveFormat;
use edgewise_model::algorithm::session::Argument;

/// Something the user asked the app to do.
#[derive(Clone, Debug, PartialEq)]
pub enum Command {
    /// Opens mesh text or bytes; `name`'s extension (or the content) gives
    /// the format, and `structure` the structure to build PLY and OBJ as.
    LoadMesh {
        bytes: Vec<u8>,
        name: String,
        structure: Option<Structure>,
        /// Open a `.wtb` or `.htb` whose tables break the rules anyway, in
        /// diagnosis mode, instead of refusing it.
        diagnose: bool,
    },
    /// Opens the table file the last refused load was, in diagnosis mode.
    DiagnoseRefused,
    /// Opens a built-in sample by name (a file stem in meshes/).
    LoadSample {
        name: String,
        structure: Option<Structure>,
    },
    /// A file from disk, a drop or the picker: `.alg` files go to the
    /// algorithm editor, table files open as their structure, PLY and OBJ
    /// ask which structure to build.
    OpenFile {
        name: String,
        bytes: Vec<u8>,
    },
    /// Answers the structure dialog; `None` cancels it.
    ChooseStructure(Option<Structure>),
    /// Selects an element, or clears the selection.
    Select(Option<ElementRef>),
    /// Converts the open mesh, and builds later PLY and OBJ loads, as
    /// `structure`.
    SetStructure(Structure),
    /// Compiles algorithms and adds them to the menu.
    LoadAlgorithms {
        source: String,
        file: String,
    },
    /// Starts an algorithm with the given inputs; missing element inputs
    /// are then picked by clicking.
    RunAlgorithm {
        name: String,
        args: Vec<(String, Argument)>,
    },
    /// Gives the algorithm waiting for inputs a picked element.
    Pick(ElementRef),
    /// Runs the algorithm waiting for inputs once they are all given.
    Start,
    /// Steps the trace forward.
    Step(usize),
    /// Answers the question asked at the current step: an element (or
    /// null), true or false, or a number.
    Answer(Value),
    /// Gives the running algorithm a question set (`line 7: prompt` or
    /// `step 12: prompt` per line), asked from now on besides its `//?`
    /// comments.
    SetQuestions(String),
    /// Drops the mesh being opened or converted a slice per frame.
    Cancel,
    /// Steps the trace back.
    Back(usize),
    /// Plays (true) or pauses (false) the trace.
    SetPlaying(bool),
    /// Runs the call on the next step as one step.
    StepOver,
    /// Runs to the step after the current call returns.
    StepOut,
    /// Goes to a step (clamped to the trace).
    Goto(usize),
    /// Stops the running algorithm.
    Abort,
    /// Closes the algorithm panel, ending any run as Abort does (✖).
    CloseAlgorithm,
    /// Sets or clears a breakpoint on a source line of the running algorithm.
    ToggleBreakpoint(u32),
    /// Goes to the next step on a breakpoint line (or the end).
    ContinueToBreakpoint,
    NewTab,
    SwitchTab(usize),
    /// Closes a tab; the last one stays.
    CloseTab(usize),
    /// Shows the mesh as both structures side by side, or one.
    SetSideBySide(bool),
    /// Saves the open mesh in a format: a download in the browser, a file
    /// natively.
    SaveAs(SaveFormat),
    /// Saves the view and its tables as SVG (a download in the browser).
    SavePicture,
    /// Saves the run as a PDF handout, a page per step.
    SaveHandout,
    /// Applies a local operation (an edge flip, an Euler operator) to the
    /// open mesh, or refuses with the reason and leaves it as it was.
    Edit {
        operation: Operation,
        ids: Vec<u32>,
    },
    /// Puts back the mesh from before the last edit, if the last change
    /// was an edit.
    RestoreBeforeEdit,
    /// Takes back the last load or edit.
    Undo,
    /// Makes the last undone load or edit again.
    Redo,
    /// Drops deleted rows and renumbers the rest.
    CompactIds,
    /// Appends an empty row to a table by hand (a new vertex, edge or
    /// half-edge, or face, its references unset).
    AddRow(ElementKind),
    /// Marks a row deleted by hand.
    DeleteRow(ElementRef),
    /// Moves a vertex by hand to a typed position.
    SetPosition {
        vertex: u32,
        position: [f32; 3],
    },
    /// Starts an exercise: a shipped one's name or an exercise file's text,
    /// at the instance `seed` draws (a random one if none is given).
    StartExercise {
        exercise: String,
        seed: Option<u64>,
        /// A saved attempt (`exerciseProgress()`) to resume instead: its
        /// instance, writes and answers.
        progress: Option<String>,
        /// What scores and messages call an exercise given as text (a
        /// package's file stem); `exercise` without it.
        name: Option<String>,
    },
    /// Answers a walk's next click or a prediction's lookup: an element, or
    /// null (a prediction only). A selection during either does the same.
    AnswerExercise(Option<ElementRef>),
    /// Grades the exercise's answer as the tables now hold it (Check), or
    /// ends a walk or a prediction where it stands (Finish).
    SubmitExercise,
    /// Shows the library's result as the model answer; the attempt scores 0.
    ShowModelAnswer,
    /// Starts the exercise's next attempt, on a fresh instance where it
    /// draws them.
    NewInstance,
    /// Leaves the exercise; the mesh stays as it is.
    EndExercise,
    /// Sets one reference of a record by hand (a table cell): `column` is
    /// named as the language names it (`leftSuccessor`, `pair`), and
    /// `target` is the id of the element it is to name, or `None`.
    SetCell {
        element: ElementRef,
        column: String,
        target: Option<u32>,
    },
}

/// What a command that succeeded has to say.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Reply {
    Done,
    /// The names of the algorithms loaded.
    Algorithms(Vec<String>),
    /// The index of the tab opened.
    Tab(usize),
}

/// Why a command was refused, in one or more sentences that name the place
/// (`file:line:column`, the element, the parameter).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CommandError(String);

impl CommandError {
    pub fn as_str(&self) -> &str {
        &self.0
    }
}

impl fmt::Display for CommandError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for CommandError {}

impl std::ops::Deref for CommandError {
    type Target = str;

    fn deref(&self) -> &str {
        &self.0
    }
}

impl From<String> for CommandError {
    fn from(message: String) -> Self {
        Self(message)
    }
}

impl From<&str> for CommandError {
    fn from(message: &str) -> Self {
        Self(message.to_owned())
    }
}

impl From<CommandError> for String {
    fn from(error: CommandError) -> Self {
        error.0
    }
}
