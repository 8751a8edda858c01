//! Several meshes in tabs, and the side-by-side winged-edge / half-edge view
//! with its linked selection.

use crate::support;

use edgewise_core::schema::{ElementKind, ElementRef};
use edgewise_core::{
    formats,
    mesh::{EdgeId, Mesh, Structure},
};
use edgewise_model::algorithm::session::Argument;
use egui_kittest::kittest::Queryable as _;

#[test]
fn tabs_keep_their_own_mesh_and_trace() {
    let mut harness = support::harness();
    let app = harness.state_mut();
    app.load_sample("cube", Some(Structure::HalfEdge))
        .expect("opens");
    app.run_algorithm(
        "vertexAdjacentEdge",
        &[("v".to_owned(), Argument::Number(0.0))],
    )
    .expect("runs");
    app.trace_step(4).expect("steps");
    harness.run();

    harness.get_by_label("View").click();
    harness.run();
    harness.get_by_label("New tab").click();
    harness.run();
    let state = harness.state().state();
    assert_eq!(state.tabs.len(), 2);
    assert!(state.tabs[1].active);
    assert!(state.mesh.is_none() && state.trace.is_none());
    harness
        .state_mut()
        .load_sample("tetrahedron", None)
        .expect("opens");
    harness.run();
    assert_eq!(harness.state().state().tabs[1].title, "tetrahedron.wtb");

    // Back to the first tab: the cube, its trace at step 4.
    harness.get_by_label("cube.htb").click();
    harness.run();
    let state = harness.state().state();
    assert_eq!(state.mesh.as_deref(), Some("cube.htb"));
    assert_eq!(state.trace.expect("kept").step, 4);

    // Closing the active tab shows its neighbour.
    harness.state_mut().close_tab(0).expect("closes");
    harness.run();
    let state = harness.state().state();
    assert_eq!(state.tabs.len(), 1);
    assert_eq!(state.mesh.as_deref(), Some("tetrahedron.wtb"));
    let err = harness
        .state_mut()
        .close_tab(0)
        .expect_err("the last tab stays");
    assert!(err.contains("last tab"), "{err}");
}

#[test]
fn side_by_side_links_the_selection_across_structures() {
    let mut harness = support::harness_with("tetrahedron", None);
    harness
        .state_mut()
        .set_side_by_side(true)
        .expect("converts");
    harness
        .state_mut()
        .select(Some(ElementRef {
            kind: ElementKind::Edge,
            id: 2,
        }))
        .expect("selects");
    harness.run();
    let state = harness.state().state();
    assert!(state.side_by_side);
    let twin = state.twin_selection.expect("the twin follows");
    assert_eq!(twin.kind, ElementKind::Edge);
    // The twin holds winged edge 2's first half-edge, which runs from its
    // start vertex to its end vertex.
    let path =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../meshes/tetrahedron.wtb");
    let bytes = std::fs::read(path).expect("sample");
    let winged = formats::load(&bytes, "tetrahedron.wtb", Structure::WingedEdge)
        .expect("loads")
        .mesh;
    let Mesh::Winged(we) = &winged else {
        unreachable!()
    };
    let edge = we.edges()[EdgeId::new(2).index()];
    let (he, correspondence) = we.to_half_edge_with_correspondence().expect("converts");
    let (first, _) = correspondence.half_edges(EdgeId::new(2)).expect("maps");
    assert_eq!(twin.id as usize, first.index());
    assert_eq!(he.half_edges()[first.index()].end_vertex, edge.end_vertex);
    harness.get_by_label("The same mesh as half-edge");

    // A new mesh rebuilds the twin; turning it off removes it.
    harness
        .state_mut()
        .load_sample("cube", None)
        .expect("opens");
    harness.run();
    harness.get_by_label("The same mesh as winged-edge");
    harness.state_mut().set_side_by_side(false).expect("off");
    harness.run();
    assert!(
        harness
            .query_by_label("The same mesh as winged-edge")
            .is_none()
    );
}

#[test]
fn an_embedded_view_shows_the_view_the_step_controls_and_optional_tables() {
    let mut harness = support::harness();
    let app = harness.state_mut();
    app.set_embed(Some(edgewise_app::Embed { tables: false }));
    app.load_sample("cube", Some(Structure::HalfEdge))
        .expect("opens");
    app.run_algorithm(
        "vertexAdjacentEdge",
        &[("v".to_owned(), Argument::Number(0.0))],
    )
    .expect("runs");
    harness.run();
    assert!(harness.query_by_label("Samples").is_none(), "no menu bar");
    assert!(harness.query_by_label("pair").is_none(), "no tables");
    harness.get_by_label("Step ▶").click();
    harness.run();
    assert_eq!(harness.state().state().trace.expect("runs").step, 1);

    harness
        .state_mut()
        .set_embed(Some(edgewise_app::Embed { tables: true }));
    harness.run();
    harness.get_by_label("pair");
    assert!(harness.query_by_label("Samples").is_none());
}
