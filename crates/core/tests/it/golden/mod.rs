//! The one rule for golden files, shared by the tests of every crate (the
//! app's tests include this file by its path): `EDGEWISE_BLESS` set to
//! anything but `0` rewrites the files; otherwise each must match byte for
//! byte.

#![allow(dead_code)]

use std::path::{Path, PathBuf};

/// Whether this run rewrites golden files instead of comparing with them.
pub fn blessing() -> bool {
    std::env::var_os("EDGEWISE_BLESS").is_some_and(|v| v != "0")
}

/// Compares `actual` with the golden file at `path`, or rewrites the file
/// when blessing. Returns the difference, so that a test can report all its
/// files at once.
pub fn compare(path: &Path, actual: impl AsRef<[u8]>) -> Option<String> {
    let actual = actual.as_ref();
    if blessing() {
        if let Some(folder) = path.parent() {
            std::fs::create_dir_all(folder).expect("the golden file's folder can be made");
        }
        std::fs::write(path, actual).expect("the golden file can be written");
        return None;
    }
    let expected = std::fs::read(path).unwrap_or_default();
    (expected != actual).then(|| {
        format!(
            "{} differs (EDGEWISE_BLESS=1 rewrites it):\n--- expected\n{}\n--- actual\n{}",
            path.display(),
            String::from_utf8_lossy(&expected),
            String::from_utf8_lossy(actual)
        )
    })
}

/// Fails with every difference [`compare`] found.
pub fn assert_none(differences: &[String]) {
    assert!(
        differences.is_empty(),
        "{} golden files differ:\n\n{}",
        differences.len(),
        differences.join("\n\n")
    );
}

/// Compares one file and fails at once on a difference.
pub fn assert_matches(path: &Path, actual: impl AsRef<[u8]>) {
    assert_none(&compare(path, actual).into_iter().collect::<Vec<_>>());
}

/// The inputs of a corpus folder, by name and sorted: every file but the
/// `.expected` ones and the README.
pub fn corpus_inputs(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|entry| {
            entry
                .expect("entry")
                .file_name()
                .to_string_lossy()
                .into_owned()
        })
        .filter(|name| !name.ends_with(".expected") && name != "README.md")
        .collect();
    names.sort();
    names
}

/// The name without its extension: `obj-empty.obj` is `obj-empty`.
fn stem(name: &str) -> &str {
    name.rsplit_once('.').map_or(name, |(stem, _)| stem)
}

/// Where the expected outcome of the corpus input `name` is kept:
/// `STEM.expected` beside it.
pub fn expected_path(dir: &Path, name: &str) -> PathBuf {
    dir.join(format!("{}.expected", stem(name)))
}

/// Fails if a `.expected` file of the corpus has no input beside it.
pub fn assert_every_expected_has_input(dir: &Path) {
    let stems: Vec<String> = corpus_inputs(dir)
        .iter()
        .map(|name| stem(name).to_owned())
        .collect();
    for entry in std::fs::read_dir(dir).expect("the corpus folder") {
        let name = entry
            .expect("entry")
            .file_name()
            .to_string_lossy()
            .into_owned();
        if let Some(stem) = name.strip_suffix(".expected") {
            assert!(stems.iter().any(|s| s == stem), "{name} has no input file");
        }
    }
}
