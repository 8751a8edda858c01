//! Replays the fuzz targets' seeds (fuzz/seeds/TARGET/) and every input a
//! fuzzer has crashed on (tests/fuzz-regressions/TARGET/) through the same
//! functions the fuzz targets call, on stable, so `cargo xtask test` keeps
//! each fixed crash fixed without nightly. See docs/reliability.md.

use crate::replay::replay;
use edgewise_core::fuzzing;

#[test]
fn obj() {
    replay("obj", fuzzing::obj);
}

#[test]
fn ply() {
    replay("ply", fuzzing::ply);
}

#[test]
fn wtb() {
    replay("wtb", fuzzing::wtb);
}

#[test]
fn htb() {
    replay("htb", fuzzing::htb);
}

#[test]
fn detect() {
    replay("detect", fuzzing::detect);
}

#[test]
fn compile() {
    replay("compile", fuzzing::compile);
}

#[test]
fn vm() {
    replay("vm", fuzzing::vm);
}

#[test]
fn convert() {
    replay("convert", fuzzing::convert);
}
