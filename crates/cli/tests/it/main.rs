//! The `edgewise` command's integration tests, run against the built binary.
//!
//! One binary holds all of them, a module each: one link and one process
//! instead of one per file.

mod common;

mod cli;
mod hostile;
mod package;
mod practice;
mod render;
