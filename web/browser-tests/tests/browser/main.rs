//! Edgewise in a real headless Chromium, driven through `window.edgewise`,
//! the pointer, touch and keys.
//!
//! One binary holds all of them, a module each: one link and one process
//! instead of one per file.

mod accessibility;
mod detail;
mod editing;
mod edits;
mod embed_page;
mod embed_script;
mod exports;
mod files;
mod first_visit;
mod hostile;
mod hostile_runs;
mod hosts;
mod hover;
mod links;
mod mesh;
mod offline;
mod practice;
mod progress;
mod scorm;
mod screens;
mod startup;
mod trace;
mod ui_cache;
