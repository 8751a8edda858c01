//! The Edgewise app: egui panels and a wgpu 3D view in one canvas.
//!
//! The same [`EdgewiseApp`] runs natively (a desktop window, used for
//! development and UI tests) and in the browser (see `web`).

pub mod accessible;
pub mod algorithm;
mod app;
mod backend;
pub mod code_editor;
pub mod command;
mod embed_event;
#[doc(hidden)]
pub mod fuzzing;
pub mod history;
pub mod obj_editor;
mod platform;
pub mod save_format;
pub mod state;
mod stored_settings;
mod tables;
pub mod visuals;
pub use app::embed_events::preferred_height;
pub use embed_event::EmbedEvent;

#[cfg(target_arch = "wasm32")]
pub mod web;

pub use app::files;
pub use app::{EdgewiseApp, embed::Embed, settings_ui::Presentation};
pub use backend::GraphicsBackend;
