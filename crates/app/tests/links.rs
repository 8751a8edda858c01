//! Course links applied to the app: a sample with an algorithm at a step,
//! inline mesh text, broken parts falling back with messages, and the Share
//! link of a view reproducing that view.

mod support;

use edgewise_app::{Argument, course_link};
use edgewise_core::mesh::Structure;
use edgewise_core::schema::{ElementKind, ElementRef};

#[test]
fn a_sample_an_algorithm_and_a_step() {
    let (harness, messages) = support::open_link(
        "?sample=tetrahedron&structure=half&algorithm=vertexAdjacentEdge&args=v:1&step=5&ids=always",
        "",
    );
    assert!(messages.is_empty(), "{messages:?}");
    let state = harness.state().state();
    assert_eq!(state.mesh.as_deref(), Some("tetrahedron.wtb"));
    assert_eq!(state.structure, Some("half"));
    let trace = state.trace.expect("the algorithm runs");
    assert_eq!(trace.algorithm, "vertexAdjacentEdge");
    assert_eq!(trace.step, 5);
    assert_eq!(trace.variables["v"], "Vertex 1");
    assert!(state.error.is_none());
}

#[test]
fn inline_obj_text_in_the_fragment() {
    let obj = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n";
    let fragment = format!("#mesh={}&format=obj", course_link::encode_payload(obj));
    let (harness, messages) = support::open_link("?structure=half&select=edge:2", &fragment);
    assert!(messages.is_empty(), "{messages:?}");
    let state = harness.state().state();
    assert_eq!(state.structure, Some("half"));
    assert_eq!((state.counts.vertices, state.counts.faces), (4, 1));
    assert_eq!(
        state.selection,
        Some(ElementRef {
            kind: ElementKind::Edge,
            id: 2
        })
    );
}

#[test]
fn broken_parts_give_messages_and_the_rest_still_applies() {
    let (harness, messages) = support::open_link(
        "?sample=cube&structure=sideways&step=abc&select=edge:999&bogus=1",
        "#mesh=%%%not-base64",
    );
    let state = harness.state().state();
    // The cube still opens (the fragment's broken mesh is refused).
    assert_eq!(state.mesh.as_deref(), Some("cube.htb"));
    let all = messages.join("\n");
    for part in [
        "structure=sideways",
        "step=abc",
        "bogus",
        "#mesh",
        "no edge 999",
    ] {
        assert!(all.contains(part), "no message about {part}:\n{all}");
    }
    let error = state.error.expect("the error panel lists them");
    assert!(
        error.starts_with("Some of this link could not be followed"),
        "{error}"
    );
}

#[test]
fn an_unknown_sample_or_algorithm_is_explained() {
    let (harness, messages) = support::open_link("?sample=teapot&algorithm=spin", "");
    let all = messages.join("\n");
    assert!(
        all.contains("sample=teapot: no sample has that name"),
        "{all}"
    );
    assert!(all.contains("algorithm=spin"), "{all}");
    assert!(harness.state().state().mesh.is_none());
}

#[test]
fn the_share_link_reproduces_the_view() {
    let mut first = support::harness();
    let app = first.state_mut();
    // A mesh that is not a sample travels as its own table text.
    app.load_mesh(
        b"v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0.5 0.5 1\nf 1 2 5\nf 2 3 5\nf 3 4 5\nf 4 1 5\n",
        "pyramid.obj",
        Some(Structure::WingedEdge),
    )
    .expect("opens");
    app.run_algorithm(
        "vertexAdjacentFaceOpen",
        &[("v".to_owned(), Argument::Number(4.0))],
    )
    .expect("runs");
    app.trace_step(7).expect("steps");
    first.run();
    let url = first
        .state()
        .share_url("https://example.edu/edgewise/")
        .expect("a link");
    assert!(url.starts_with("https://example.edu/edgewise/?"), "{url}");
    assert!(url.contains("#mesh="), "{url}");

    let (query, fragment) = url
        .split_once('?')
        .map(|(_, rest)| rest.split_once('#').unwrap_or((rest, "")))
        .expect("a query");
    let (second, messages) = support::open_link(query, fragment);
    assert!(messages.is_empty(), "{messages:?}");
    let (a, b) = (first.state().state(), second.state().state());
    assert_eq!(a.trace, b.trace);
    assert_eq!(a.highlights, b.highlights);
    assert_eq!(a.counts, b.counts);
    assert_eq!(a.structure, b.structure);
}
