//! Edgewise core: the winged-edge and half-edge mesh structures, their file
//! formats, and the small algorithm language that walks them.
//!
//! This crate has no UI or browser dependency, so the app (native and wasm32)
//! and the `edgewise` command share exactly the same logic.

pub mod formats;
#[doc(hidden)]
pub mod fuzzing;
pub mod lang;
pub mod mesh;
pub mod schema;

/// The version of Edgewise, shared by the app, the CLI and the JavaScript API.
pub const VERSION: &str = env!("CARGO_PKG_VERSION");
