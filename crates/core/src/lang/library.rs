//! The algorithm library shipped with Edgewise: the papers' built-in
//! algorithms and exercises, for both structures, compiled into the binary.

use super::{Program, compile_rendered};

/// The library's source files: (file name, text).
pub const SOURCES: [(&str, &str); 6] = [
    (
        "winged-edge.alg",
        include_str!("../../../../algorithms/winged-edge.alg"),
    ),
    (
        "half-edge.alg",
        include_str!("../../../../algorithms/half-edge.alg"),
    ),
    (
        "half-edge-edits.alg",
        include_str!("../../../../algorithms/half-edge-edits.alg"),
    ),
    (
        "winged-edge-edits.alg",
        include_str!("../../../../algorithms/winged-edge-edits.alg"),
    ),
    (
        "half-edge-strips.alg",
        include_str!("../../../../algorithms/half-edge-strips.alg"),
    ),
    (
        "half-edge-subdivision.alg",
        include_str!("../../../../algorithms/half-edge-subdivision.alg"),
    ),
];

/// Compiles every library file. An error here is a bug in a shipped file,
/// which the tests rule out; it is returned rendered rather than panicking.
pub fn load() -> Result<Vec<Program>, String> {
    SOURCES
        .iter()
        .map(|(name, text)| compile_rendered(text, Some(name)))
        .collect()
}

/// Compiles one library file by its name (`"half-edge-edits.alg"`), or
/// `None` if the library has no such file.
pub fn program(file: &str) -> Option<Result<Program, String>> {
    SOURCES
        .iter()
        .find(|(name, _)| *name == file)
        .map(|(name, text)| compile_rendered(text, Some(name)))
}
