//! The Edgewise app: egui panels and a wgpu 3D view in one canvas.
//!
//! The same [`EdgewiseApp`] runs natively (a desktop window, used for
//! development and UI tests) and in the browser (see `web`).

pub mod algorithm;
mod app;
mod backend;
pub mod course_link;
mod document;
mod obj_editor;
pub mod paint;
pub mod samples;
pub mod selection;
pub mod state;
mod tables;
mod theme;
pub mod view3d;

#[cfg(target_arch = "wasm32")]
pub mod web;

pub use app::{EdgewiseApp, algorithm_ui::Argument, parse_structure, structure_name};
pub use backend::GraphicsBackend;
