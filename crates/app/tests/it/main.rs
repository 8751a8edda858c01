//! The app's integration tests: the UI through `egui_kittest`, its
//! snapshots and the 3D view's renders.
//!
//! One binary holds all of them, a module each: one link and one process
//! instead of one per file.

#[path = "../../../core/tests/it/golden/mod.rs"]
mod golden;
#[path = "../../../core/tests/it/replay/mod.rs"]
mod replay;
mod support;

mod docs_snippets;
mod edits;
mod embed_events;
mod exports;
mod files;
mod first_visit;
mod fuzz_regressions;
mod history;
mod hostile_links;
mod keyboard;
mod layout;
mod limits;
mod links;
mod pending;
mod pixel_cost;
mod practice;
mod questions;
mod snapshots;
mod still;
mod tabs;
mod trace;
mod ui;
mod ui_cache_render;
mod view3d_render;
