//! The one rule for golden files, shared by the tests of every crate (the
//! app's tests include this file by its path): `EDGEWISE_BLESS` set to
//! anything but `0` rewrites the files; otherwise each must match byte for
//! byte.

#![allow(dead_code)]

use std::path::Path;

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
