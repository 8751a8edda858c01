//! Replays the `course_link` and `link` fuzz targets' seeds (fuzz/seeds/TARGET/) and every input a
//! fuzzer has crashed on (tests/fuzz-regressions/TARGET/) through the same
//! functions the fuzz targets call, on stable, so `cargo xtask test` keeps
//! each fixed crash fixed without nightly. See docs/reliability.md.

use crate::replay::replay;
use edgewise_app::fuzzing;

#[test]
fn course_link() {
    replay("course_link", fuzzing::course_link);
}

#[test]
fn link() {
    replay("link", fuzzing::link);
}
