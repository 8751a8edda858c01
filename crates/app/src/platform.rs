//! What differs between the browser and the desktop, behind one interface:
//! reading and writing files, keeping settings, fullscreen, the page's
//! address, telling an embedding page what changed, and the page's copy
//! of the app for screen readers. The rest of the app is the same on both; `cfg(target_arch)`
//! chooses the implementation here and nowhere else in the UI code.
//!
//! - `browser.rs`: a file picker and dropped files read asynchronously into
//!   an inbox the app empties each frame, downloads through a Blob URL, local
//!   storage, the Fullscreen API, SCORM packages of the page's own files.
//! - `desktop.rs`: a typed path (there is no native file dialog, which keeps
//!   the desktop build free of GTK and D-Bus), files written to the current
//!   directory, settings kept for the session only.

#[cfg(target_arch = "wasm32")]
mod browser;
#[cfg(not(target_arch = "wasm32"))]
mod desktop;

#[cfg(target_arch = "wasm32")]
pub use browser::{
    CANVAS_ID, FileIo, READER_COPY, change_for_readers, coarse_pointer, deliver_events,
    download_package, fetch_bytes, fit_canvas, js_error_text, left_fullscreen, load_settings,
    package_zip, page_base, set_fullscreen, show_algorithms_to_readers, show_run_to_readers,
    show_to_readers, store_settings,
};
#[cfg(not(target_arch = "wasm32"))]
pub use desktop::{
    FileIo, READER_COPY, change_for_readers, coarse_pointer, deliver_events, download_package,
    fit_canvas, left_fullscreen, load_settings, page_base, set_fullscreen,
    show_algorithms_to_readers, show_run_to_readers, show_to_readers, store_settings,
};

/// A file read from disk, waiting to be opened.
pub struct PendingFile {
    /// The file name (no directories), which gives the format.
    pub name: String,
    pub bytes: Vec<u8>,
}

/// A run's place as the page's copy for screen readers shows it.
#[cfg_attr(
    not(target_arch = "wasm32"),
    expect(dead_code, reason = "the desktop has no page copy to fill")
)]
pub struct RunText<'a> {
    /// "vertexAdjacentEdge, step 2 of 22, playing".
    pub status: &'a str,
    /// "Line 13: e := v.incidentEdge;".
    pub line: &'a str,
    /// The variables as HTML, every text escaped.
    pub variables_html: &'a str,
}

/// The files a picker offers for algorithms, as a file input's `accept`.
pub const ALGORITHM_FILES: &str = ".alg,.txt";
