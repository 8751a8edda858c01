//! The app's observable state, as returned by `window.edgewise.state()`.
//!
//! Browser tests and page authors read this instead of the pixels, so every
//! field is plain data that serialises to JSON.

use serde::Serialize;

use crate::{
    code_editor::Diagnostic,
    selection::{ElementKind, ElementRef},
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
    /// The open mesh's name, or null before any mesh is open.
    pub mesh: Option<String>,
    /// "winged" or "half", or null before any mesh is open.
    pub structure: Option<&'static str>,
    pub counts: Counts,
    /// The selected element, or null.
    pub selection: Option<ElementRef>,
    /// The selected element and every element it references.
    pub highlights: Vec<HighlightState>,
    /// The message of the last failed load or command, or null.
    pub error: Option<String>,
    /// The OBJ editor's problems, each marked at its line: `{line, column, message}`.
    pub diagnostics: Vec<Diagnostic>,
    /// The dialog waiting for an answer, or null.
    pub dialog: Option<DialogState>,
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
}
