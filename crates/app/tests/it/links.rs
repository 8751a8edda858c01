//! Course links applied to the app: a sample with an algorithm at a step,
//! inline mesh text, broken parts falling back with messages, and the Share
//! link of a view reproducing that view.

use crate::support;

use edgewise_core::mesh::{Mesh, Structure, generate, operations::Operation};
use edgewise_core::schema::{ElementKind, ElementRef};
use edgewise_model::{algorithm::session::Argument, course_link};

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
    // A mesh that is not a sample travels as compact polygons, since
    // building from them gives back its tables.
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
    let (url, second) = follow(&first);
    assert!(url.starts_with("https://example.edu/edgewise/?"), "{url}");
    assert!(url.contains("#poly="), "{url}");
    let (a, b) = (first.state().state(), second.state().state());
    assert_eq!(a.trace, b.trace);
    assert_eq!(a.highlights, b.highlights);
    assert_eq!(a.counts, b.counts);
    assert_eq!(a.structure, b.structure);
}

/// Opens the share link of `harness` in a fresh app.
fn follow(harness: &support::AppHarness) -> (String, support::AppHarness) {
    let url = harness
        .state()
        .share_url("https://example.edu/edgewise/")
        .expect("a link");
    let (query, fragment) = url
        .split_once('?')
        .map(|(_, rest)| rest.split_once('#').unwrap_or((rest, "")))
        .expect("a query");
    let (second, messages) = support::open_link(query, fragment);
    assert!(messages.is_empty(), "{messages:?}");
    (url, second)
}

fn mesh(harness: &support::AppHarness) -> Mesh {
    harness.state().mesh().cloned().expect("a mesh is open")
}

/// A scanned-looking mesh the size of the Stanford bunny and more: an
/// icosphere of 5,120 triangles with every vertex moved by a different
/// irregular amount, so no position is a round number.
fn scan_like_obj() -> String {
    let sphere = generate::icosphere(4);
    let mut obj = String::new();
    for (i, p) in sphere.positions().iter().enumerate() {
        let wobble = 1.0 + 0.08 * ((i as f32 * 12.9898).sin() * 43_758.547).fract();
        let p = *p * wobble;
        obj.push_str(&format!("v {} {} {}\n", p.x, p.y, p.z));
    }
    for face in sphere.faces() {
        let corners: Vec<String> = face.iter().map(|v| (v + 1).to_string()).collect();
        obj.push_str(&format!("f {}\n", corners.join(" ")));
    }
    obj
}

#[test]
fn a_bunny_sized_mesh_travels_compactly_with_every_id() {
    for structure in [Structure::HalfEdge, Structure::WingedEdge] {
        let mut first = support::harness();
        first
            .state_mut()
            .load_mesh(scan_like_obj().as_bytes(), "scan.obj", Some(structure))
            .expect("opens");
        first.run();
        let (url, second) = follow(&first);
        assert!(url.contains("#poly="), "{url}");
        assert!(
            url.len() <= 64 * 1024,
            "{structure:?}: the link is {} bytes",
            url.len()
        );
        assert!(
            mesh(&first) == mesh(&second),
            "{structure:?}: the same tables"
        );
    }
}

#[test]
fn an_edited_mesh_whose_polygons_would_renumber_it_travels_as_tables() {
    let mut first = support::harness();
    first
        .state_mut()
        .load_mesh(
            scan_like_obj().as_bytes(),
            "scan.obj",
            Some(Structure::HalfEdge),
        )
        .expect("opens");
    // A flip rewires records in place: built again from its polygons, the
    // mesh would number its half-edges otherwise.
    first
        .state_mut()
        .edit(Operation::FlipEdge, &[7])
        .expect("flips");
    first.run();
    let (url, second) = follow(&first);
    assert!(
        url.contains("#mesh=") && url.contains("format=htb"),
        "{url}"
    );
    assert!(mesh(&first) == mesh(&second), "the same tables");
}
