//! The body of the `course_link` fuzz target in `fuzz/`.
//!
//! The fuzz target (nightly, libFuzzer) and the replay test
//! (`crates/app/tests/fuzz_regressions.rs`, stable, run by `cargo xtask
//! test`) both call it, so a crash found by the fuzzer is replayed by exactly
//! the code that found it. Not part of the app's interface.

use crate::course_link::{CourseLink, decode_payload};

/// A course link: the input up to the first `#` or NUL byte is the query,
/// the rest the fragment. The whole input is also decoded as a `#mesh=`
/// payload, and the parsed link is written back as a URL.
pub fn course_link(data: &[u8]) {
    // Links are `&str`: input that is not UTF-8 never reaches the parser.
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let (search, fragment) = match text.find(['#', '\0']) {
        Some(at) => (&text[..at], &text[at + 1..]),
        None => (text, ""),
    };
    let (link, messages) = CourseLink::parse(search, fragment);
    assert!(messages.iter().all(|message| !message.is_empty()));
    drop(link.to_url("https://example.com/edgewise/"));
    drop(decode_payload("mesh", text));
}
