//! Editing algorithms traced in the app: the shown mesh follows the trace
//! step by step, every broken record is reported while the edit is half
//! done, a finished sound edit is kept with the previous mesh one click
//! away, and an edit abandoned half way is taken back.

use crate::support;

use edgewise_core::mesh::{HalfEdgeId, Mesh, Structure, VertexId};
use edgewise_model::algorithm::session::Argument;

fn end_vertex(harness: &support::AppHarness, h: u32) -> Option<VertexId> {
    let app = harness.state();
    match app.mesh() {
        Some(Mesh::Half(mesh)) => mesh.half_edge(HalfEdgeId::new(h)).map(|h| h.end_vertex),
        _ => None,
    }
}

fn start_flip(harness: &mut support::AppHarness) {
    support::run_flip_edge(harness, 2);
}

#[test]
fn a_traced_flip_breaks_the_records_then_mends_them() {
    let mut harness = support::harness_with("hexagon", Some(Structure::HalfEdge));
    let before = harness.state().mesh().cloned().expect("a mesh");
    start_flip(&mut harness);
    // Up to the first write, the tables are sound.
    let mut writes = 0;
    loop {
        harness.state_mut().trace_step(1).expect("steps");
        harness.run();
        let state = harness.state().state();
        let trace = state.trace.expect("tracing");
        if trace.operation == "write" {
            writes += 1;
            if writes == 1 {
                assert!(!state.broken.is_empty(), "the first write breaks a record");
                assert!(
                    state
                        .broken
                        .iter()
                        .any(|b| b.kind == edgewise_core::schema::ElementKind::Edge && b.id == 2),
                    "{:#?}",
                    state.broken
                );
                assert!(state.broken.iter().all(|b| !b.rule.is_empty()));
                assert!(
                    state.highlights.iter().any(|h| h.role == "broken"),
                    "broken records are painted"
                );
                assert_eq!(end_vertex(&harness, 2), Some(VertexId::new(2)));
            }
        } else if writes == 0 {
            assert!(state.broken.is_empty(), "{:#?}", state.broken);
        }
        if trace.done || trace.error.is_some() {
            assert!(trace.error.is_none(), "{:?}", trace.error);
            break;
        }
    }
    assert!(writes >= 12, "only {writes} writes");
    let state = harness.state().state();
    assert!(state.broken.is_empty(), "{:#?}", state.broken);
    let stats = state.stats.expect("stats");
    assert_eq!((stats.vertices, stats.edges, stats.faces), (7, 12, 6));
    assert_eq!(stats.boundary_loops, 1);
    // Stepping back to the start shows the original tables again.
    harness.state_mut().trace_goto(0).expect("goto");
    harness.run();
    assert_eq!(harness.state().mesh(), Some(&before));
    harness.state_mut().trace_goto(usize::MAX).expect("goto");
    harness.run();
    let after = harness.state().mesh().cloned().expect("a mesh");
    assert_ne!(after, before);
    // A finished, sound edit is kept; the previous mesh is one click away.
    harness.state_mut().abort_algorithm().expect("abort");
    harness.run();
    assert_eq!(harness.state().mesh(), Some(&after));
    harness.state_mut().restore_before_edit().expect("restore");
    harness.run();
    assert_eq!(harness.state().mesh(), Some(&before));
    assert!(harness.state_mut().restore_before_edit().is_err());
}

#[test]
fn an_edit_abandoned_half_way_is_taken_back() {
    let mut harness = support::harness_with("hexagon", Some(Structure::HalfEdge));
    let before = harness.state().mesh().cloned().expect("a mesh");
    start_flip(&mut harness);
    harness.state_mut().trace_goto(70).expect("goto");
    harness.run();
    assert_ne!(harness.state().mesh(), Some(&before));
    assert!(!harness.state().state().broken.is_empty());
    harness.state_mut().abort_algorithm().expect("abort");
    harness.run();
    assert_eq!(harness.state().mesh(), Some(&before));
    let state = harness.state().state();
    assert!(state.broken.is_empty());
    assert!(harness.state_mut().restore_before_edit().is_err());
}

/// However a finished traced edit ends (Abort, ✖, choosing another
/// algorithm and picking its input, a new load), the edit is in the history:
/// undo gives back exactly the mesh it started from, and redo the edit.
#[test]
fn a_traced_edit_ended_any_way_is_undone_exactly() {
    use edgewise_app::command::Command;
    use edgewise_core::schema::{ElementKind, ElementRef};
    type Ending = fn(&mut support::AppHarness);
    let endings: [(&str, Ending); 4] = [
        ("Abort", |h| {
            h.state_mut().abort_algorithm().expect("abort");
        }),
        ("✖", |h| {
            h.state_mut()
                .execute(Command::CloseAlgorithm)
                .expect("close");
        }),
        ("a pick", |h| {
            let app = h.state_mut();
            app.run_algorithm("vertexAdjacentEdge", &[])
                .expect("waits for v");
            app.execute(Command::Pick(ElementRef::new(ElementKind::Vertex, 0)))
                .expect("picked");
            app.abort_algorithm().expect("abort");
        }),
        ("a new load", |h| {
            h.state_mut().load_sample("cube", None).expect("loads");
            h.run();
            h.state_mut().undo().expect("undo the load");
        }),
    ];
    for (way, end) in endings {
        let mut harness = support::harness_with("hexagon", Some(Structure::HalfEdge));
        let before = harness.state().mesh().cloned().expect("a mesh");
        start_flip(&mut harness);
        harness.state_mut().trace_goto(usize::MAX).expect("goto");
        harness.run();
        let after = harness.state().mesh().cloned().expect("a mesh");
        assert_ne!(after, before, "{way}");
        end(&mut harness);
        harness.run();
        assert!(
            harness.state().state().trace.is_none(),
            "{way}: the run ended"
        );
        assert_eq!(
            harness.state().mesh(),
            Some(&after),
            "{way}: the edit stays"
        );
        harness.state_mut().undo().expect("undo the edit");
        harness.run();
        assert_eq!(harness.state().mesh(), Some(&before), "{way}: undo");
        harness.state_mut().redo().expect("redo the edit");
        harness.run();
        assert_eq!(harness.state().mesh(), Some(&after), "{way}: redo");
    }
}

#[test]
fn a_refused_edit_changes_nothing_and_says_why() {
    let mut harness = support::harness_with("hexagon", Some(Structure::HalfEdge));
    let before = harness.state().mesh().cloned().expect("a mesh");
    // Half-edge 0 runs along the boundary: its pair has no face.
    harness
        .state_mut()
        .run_algorithm("flipEdge", &[("h".to_owned(), Argument::Number(0.0))])
        .expect("starts");
    harness.state_mut().trace_goto(usize::MAX).expect("goto");
    harness.run();
    let state = harness.state().state();
    let error = state.trace.and_then(|t| t.error).expect("refused");
    assert!(
        error.contains("is on the boundary; a flip needs two faces"),
        "{error}"
    );
    assert_eq!(harness.state().mesh(), Some(&before));
}

#[test]
fn native_operations_apply_or_refuse_with_the_reason() {
    use edgewise_core::mesh::operations::Operation;
    let mut harness = support::harness_with("hexagon", Some(Structure::HalfEdge));
    let before = harness.state().mesh().cloned().expect("a mesh");
    let refused = harness
        .state_mut()
        .edit(Operation::FlipEdge, &[0])
        .expect_err("a boundary edge cannot flip");
    assert!(refused.starts_with("flip-edge 0: "), "{refused}");
    assert!(refused.contains("on the boundary"), "{refused}");
    assert_eq!(
        harness.state().state().error.as_deref(),
        Some(refused.as_str())
    );
    assert_eq!(harness.state().mesh(), Some(&before));

    harness
        .state_mut()
        .edit(Operation::CollapseEdge, &[2])
        .expect("an inner edge collapses");
    harness.run();
    let state = harness.state().state();
    assert_eq!(state.error, None);
    let stats = state.stats.expect("stats");
    // One vertex, three edges and two faces fewer; the rows stay as gaps.
    assert_eq!((stats.vertices, stats.edges, stats.faces), (6, 9, 4));
    assert_eq!(state.counts.vertices, 7);
    assert!(state.highlights.iter().any(|h| h.role == "deleted"));
    harness.state_mut().restore_before_edit().expect("restores");
    harness.run();
    assert_eq!(harness.state().mesh(), Some(&before));
}

#[test]
fn a_course_link_opens_an_edit_at_a_step_and_shares_it_back() {
    let (mut harness, messages) = support::open_link(
        "?sample=hexagon&structure=half&algorithm=flipEdge&args=h:2&step=70",
        "",
    );
    assert!(messages.is_empty(), "{messages:?}");
    let state = harness.state().state();
    let trace = state.trace.expect("the edit runs");
    assert_eq!((trace.algorithm.as_str(), trace.step), ("flipEdge", 70));
    assert!(!state.broken.is_empty(), "half way, records are broken");
    // The half-done mesh is what the view shows; the link reproduces it.
    assert_eq!(end_vertex(&harness, 2), Some(VertexId::new(2)));
    let url = harness
        .state_mut()
        .share_url("https://example.org/edgewise/")
        .expect("a link");
    assert!(url.contains("algorithm=flipEdge"), "{url}");
    assert!(url.contains("step=70"), "{url}");
}

#[test]
fn a_shared_link_to_a_half_done_edit_carries_the_mesh_it_started_from() {
    let mut harness = support::harness();
    let obj = std::fs::read(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../meshes/hexagon.obj"),
    )
    .expect("sample");
    harness
        .state_mut()
        .load_mesh(&obj, "pasted.obj", Some(Structure::HalfEdge))
        .expect("loads");
    harness.run();
    start_flip(&mut harness);
    harness.state_mut().trace_goto(70).expect("goto");
    harness.run();
    let shown = harness.state().mesh().cloned().expect("a mesh");
    let url = harness
        .state()
        .share_url("https://example.org/edgewise/")
        .expect("a link");
    let (query, fragment) = url
        .strip_prefix("https://example.org/edgewise/")
        .and_then(|rest| rest.split_once('#'))
        .expect("a link with the mesh in its fragment");
    let (opened, messages) = support::open_link(query, &format!("#{fragment}"));
    assert!(messages.is_empty(), "{messages:?}");
    let state = opened.state().state();
    assert_eq!(state.trace.map(|t| t.step), Some(70));
    assert_eq!(opened.state().mesh(), Some(&shown));
}

#[test]
fn calls_are_stepped_into_over_and_out_of_with_the_call_stack_shown() {
    let mut harness = support::harness_with("hexagon", Some(Structure::HalfEdge));
    harness
        .state_mut()
        .run_algorithm("splitEdge", &[("h".to_owned(), Argument::Number(2.0))])
        .expect("the split starts");
    harness.run();
    // Step into the first call of cutCorner.
    let call_step = loop {
        harness.state_mut().trace_step(1).expect("steps");
        let trace = harness.state().state().trace.expect("tracing");
        if trace.calls.len() == 2 {
            assert_eq!(trace.calls[0], "splitEdge");
            assert!(
                trace.calls[1].starts_with("cutCorner (called on line "),
                "{:?}",
                trace.calls
            );
            // The variables shown are the callee's.
            assert!(trace.variables.contains_key("t"), "{:?}", trace.variables);
            assert!(!trace.variables.contains_key("gp"), "{:?}", trace.variables);
            break trace.step - 1;
        }
        assert!(!trace.done, "splitEdge never called cutCorner");
    };
    // Out of it: back in splitEdge, after the call.
    harness.state_mut().trace_step_out().expect("steps out");
    let after = harness.state().state().trace.expect("tracing");
    assert_eq!(after.calls, ["splitEdge"]);
    assert!(after.step > call_step + 2);
    // Over it, from the call's own step: the same place, in one go.
    harness.state_mut().trace_goto(call_step).expect("goto");
    harness.state_mut().trace_step_over().expect("steps over");
    let over = harness.state().state().trace.expect("tracing");
    assert_eq!(over.calls, ["splitEdge"]);
    assert!(over.step > call_step + 2, "{} after {call_step}", over.step);
    // Outside a call there is nothing to step out of.
    let refused = harness.state_mut().trace_step_out().expect_err("refused");
    assert!(refused.contains("not inside a call"), "{refused}");
}

/// A file opened in the middle of a traced edit: the edit, left unsound,
/// goes back to the mesh it started from, and then the new mesh replaces
/// it. The 3D view must show the new mesh, not the old one that the undone
/// edit put back for a moment.
#[test]
fn a_load_in_the_middle_of_an_edit_shows_the_new_mesh_in_the_view() {
    use edgewise_core::schema::ElementRef;
    let mut harness = support::harness_with("hexagon", Some(Structure::HalfEdge));
    start_flip(&mut harness);
    loop {
        harness.state_mut().trace_step(1).expect("steps");
        harness.run();
        if !harness.state().state().broken.is_empty() {
            break;
        }
    }
    let eighth = ElementRef::vertex(VertexId::new(7));
    assert_eq!(
        harness.state().screen_position(eighth),
        None,
        "the hexagon has seven vertices"
    );
    harness
        .state_mut()
        .load_sample("cube", None)
        .expect("loads");
    harness.run();
    harness.run();
    assert_eq!(harness.state().state().counts.vertices, 8);
    assert!(
        harness.state().screen_position(eighth).is_some(),
        "the view draws the cube's eighth vertex"
    );
}
