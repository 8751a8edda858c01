//! The core's integration tests: formats, language and mesh operations.
//!
//! One binary holds all of them, a module each: one link and one process
//! instead of one per file.

mod golden;
mod lang_support;
mod replay;

mod formats_bad_inputs;
mod formats_diagnosis;
mod formats_external;
mod formats_golden;
mod formats_ply;
mod formats_round_trip;
mod formats_warnings;
mod fuzz_regressions;
mod hostile;
mod lang_calls;
mod lang_edit_properties;
mod lang_edits;
mod lang_golden;
mod lang_library;
mod lang_limits;
mod lang_questions;
mod lang_subdivision;
mod lang_vm;
mod mesh_grading;
mod mesh_hand;
mod mesh_operations;
mod mesh_properties;
mod mesh_refusals;
