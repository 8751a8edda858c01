//! The app's observable state, as returned by `window.edgewise.state()`.
//!
//! Browser tests and page authors read this instead of the pixels, so every
//! field is plain data that serialises to JSON.

use serde::Serialize;

/// A JSON-serialisable snapshot of what the app shows.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct AppState {
    /// The Edgewise version.
    pub version: &'static str,
    /// "webgpu", "webgl2", or a native backend name.
    pub backend: &'static str,
    /// Frames drawn so far; proves the render loop is alive.
    pub frames: u64,
}
