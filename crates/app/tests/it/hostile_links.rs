//! Hostile course links, applied to the app: an algorithm of 100,000 terms,
//! one nested 100,000 deep, payloads past their limits, and every parameter
//! malformed at once. The app names each problem, keeps what works, and the
//! default view still answers. Each case's messages are in
//! tests/hostile/link-NAME.expected (`EDGEWISE_BLESS=1` rewrites them).

use crate::golden;
use crate::support;

use edgewise_core::schema::{ElementKind, ElementRef};
use std::path::PathBuf;

use edgewise_app::EdgewiseApp;
use edgewise_model::course_link::{self, MAX_INFLATED_BYTES, MAX_PAYLOAD_CHARS};
use egui_kittest::Harness;

fn expected_path(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../../tests/hostile")
        .join(format!("link-{name}.expected"))
}

/// Compares the messages with the case's golden file, messages cut at 300
/// characters each (a rendered error quotes a window of its line).
fn assert_messages(name: &str, messages: &[String]) {
    let actual: String = messages
        .iter()
        .map(|m| {
            let cut: String = m.chars().take(300).collect();
            format!("{cut}\n")
        })
        .collect();
    golden::assert_matches(&expected_path(name), actual);
}

/// The view works after the link: the sample is open and selecting works.
fn assert_default_view_works(harness: &mut Harness<'static, EdgewiseApp>) {
    let state = harness.state().state();
    assert_eq!(state.mesh.as_deref(), Some("tetrahedron.wtb"));
    let edge = ElementRef {
        kind: ElementKind::Edge,
        id: 2,
    };
    harness
        .state_mut()
        .select(Some(edge))
        .expect("selecting still works");
    harness.run();
    assert_eq!(harness.state().state().selection, Some(edge));
    harness
        .state_mut()
        .run_algorithm("vertexAdjacentEdge", &[])
        .expect("the library still runs");
}

#[test]
fn an_algorithm_of_100000_terms_is_named_and_the_view_still_works() {
    let source = format!(
        "algorithm long(n : Integer) : WingedEdge;\nbegin\n  n := n{};\nend\n",
        " + 1".repeat(100_000)
    );
    let fragment = format!("#alg={}", course_link::encode_payload(&source));
    let (mut harness, messages) =
        support::open_link("?sample=tetrahedron&algorithm=long&args=n:1", &fragment);
    assert_messages("alg-100000-terms", &messages);
    assert!(
        messages[0].contains(":3:402: error: this expression is too long"),
        "{messages:?}"
    );
    assert!(harness.state().state().trace.is_none());
    assert_default_view_works(&mut harness);
}

#[test]
fn an_algorithm_nested_100000_deep_is_named_and_the_view_still_works() {
    let source = format!(
        "algorithm deep(b : Boolean) : WingedEdge;\nbegin\n  b := {}b;\nend\n",
        "not ".repeat(100_000)
    );
    let fragment = format!("#alg={}", course_link::encode_payload(&source));
    let (mut harness, messages) =
        support::open_link("?sample=tetrahedron&algorithm=deep", &fragment);
    assert_messages("alg-nested-100000-deep", &messages);
    assert!(
        messages[0].contains("this is nested too deeply (more than 100 levels)"),
        "{messages:?}"
    );
    assert_default_view_works(&mut harness);
}

#[test]
fn payloads_past_their_limits_are_refused_with_their_sizes() {
    // Highly compressible text that inflates past the limit: a small link.
    let bomb = "v 0 0 0\n".repeat(MAX_INFLATED_BYTES / 8 + 1);
    let payload = course_link::encode_payload(&bomb);
    assert!(
        payload.len() < 64 * 1024,
        "the bomb's link is {} characters",
        payload.len()
    );
    let (mut harness, messages) =
        support::open_link("?sample=tetrahedron", &format!("#mesh={payload}"));
    assert_messages("payload-inflates-past-limit", &messages);
    assert!(messages[0].contains("8 MiB"), "{messages:?}");
    assert_default_view_works(&mut harness);

    let long = "A".repeat(MAX_PAYLOAD_CHARS + 1);
    let (mut harness, messages) =
        support::open_link("?sample=tetrahedron", &format!("#alg={long}"));
    assert_messages("payload-too-long", &messages);
    assert!(messages[0].contains("1 MiB"), "{messages:?}");
    assert_default_view_works(&mut harness);
}

#[test]
fn every_parameter_malformed_at_once() {
    let query = "?sample=tetrahedron&sample=%00%ff&structure=round&mesh=..%2f..%2fetc%2fpasswd\
                 &algorithm=%E2%80%AE&args=v:NaN,v:1e999,:,%00:1&step=-0&select=vertex:-1\
                 &camera=NaN,1,2&ids=sometimes&axes=2&orientation=yes!&solid=%20&meshScale=1e308\
                 &labelScale=-Infinity&theme=%3Cscript%3E&embed=2&tables=x&present=maybe\
                 &panels=algorithm,algorithm,nothing&colors=lookup:zzzzzz,nobody:000000\
                 &codeSize=1000000&%ff%fe=1&=&&&";
    let fragment = "#mesh=%%%&format=stl&alg=!!!&unknown=1";
    let (mut harness, messages) = support::open_link(query, fragment);
    assert!(messages.len() >= 20, "{messages:#?}");
    assert_messages("every-parameter-malformed", &messages);
    assert_default_view_works(&mut harness);
}

/// `tests/hostile/run-new-edges-forever.alg` as a link, at its last step:
/// hundreds of thousands of new edges, each a broken record. The panel,
/// `state()` and the views keep at most 1,000 of them, count them all, and
/// a selection and a step still work.
#[test]
fn a_runaway_edit_at_its_last_step_keeps_the_page_usable() {
    let source = std::fs::read_to_string(
        PathBuf::from(env!("CARGO_MANIFEST_DIR"))
            .join("../../tests/hostile/run-new-edges-forever.alg"),
    )
    .expect("the case is committed");
    let fragment = format!("#alg={}", course_link::encode_payload(&source));
    let (mut harness, messages) = support::open_link(
        "?sample=cube&structure=half&algorithm=grow&args=v:0&step=999999",
        &fragment,
    );
    assert!(messages.is_empty(), "{messages:?}");
    harness.run();
    let state = harness.state().state();
    let trace = state.trace.as_ref().expect("the run is open");
    assert!(trace.step + 1 >= trace.steps, "at the last step: {trace:?}");
    assert_eq!(state.broken.len(), 1_000);
    assert!(state.broken_count > 300_000, "{}", state.broken_count);
    assert!(
        state.highlights.len() <= 2_100,
        "{} highlights",
        state.highlights.len()
    );
    harness
        .state_mut()
        .execute(edgewise_app::command::Command::Back(1))
        .expect("steps back");
    harness.run();
    let vertex = ElementRef {
        kind: ElementKind::Vertex,
        id: 3,
    };
    harness.state_mut().select(Some(vertex)).expect("selects");
    harness.run();
    assert_eq!(harness.state().state().selection, Some(vertex));
}
