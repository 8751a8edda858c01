//! Tracing algorithms in the app, driven natively through `egui_kittest`:
//! the marked output, the line and span, the variables and the highlight
//! roles at chosen steps; stepping forward and back; breakpoints; picking
//! inputs by clicking; and a run-time error on an open mesh.

use crate::support;

use edgewise_core::schema::ElementKind;
use std::collections::BTreeSet;

use edgewise_app::EdgewiseApp;
use edgewise_core::mesh::{EdgeId, HalfEdgeId, Mesh, Structure, VertexId};
use edgewise_model::algorithm::session::Argument;
use egui_kittest::{
    Harness,
    kittest::{NodeT as _, Queryable as _},
};

/// The edges a vertexAdjacentEdge run must mark, worked out from the tables
/// directly: winged edges that start or end at `v`; half-edges that end at
/// `v` (the half-edge version walks the incoming half-edges).
fn edges_at(mesh: &Mesh, v: u32) -> BTreeSet<u32> {
    match mesh {
        Mesh::Winged(m) => (0_u32..)
            .zip(m.edges())
            .filter(|(_, e)| e.start_vertex == VertexId::new(v) || e.end_vertex == VertexId::new(v))
            .map(|(i, _)| i)
            .collect(),
        Mesh::Half(m) => (0_u32..)
            .zip(m.half_edges())
            .filter(|(_, h)| h.end_vertex == VertexId::new(v))
            .map(|(i, _)| i)
            .collect(),
    }
}

fn run(harness: &mut Harness<'static, EdgewiseApp>, name: &str, v: f64) {
    harness
        .state_mut()
        .run_algorithm(name, &[("v".to_owned(), Argument::Number(v))])
        .expect("the algorithm starts");
    harness.run();
}

fn roles_of(state: &edgewise_app::state::AppState, role: &str) -> Vec<(ElementKind, u32)> {
    state
        .highlights
        .iter()
        .filter(|h| h.role == role)
        .map(|h| (h.kind, h.id))
        .collect()
}

#[test]
fn vertex_adjacent_edge_marks_every_edge_at_the_vertex() {
    for (sample, file) in [("tetrahedron", "tetrahedron.wtb"), ("cube", "cube.htb")] {
        for structure in [Structure::WingedEdge, Structure::HalfEdge] {
            let mut harness = support::harness_with(sample, Some(structure));
            let mesh = support::sample_mesh(file, structure);
            run(&mut harness, "vertexAdjacentEdge", 1.0);
            let state = harness.state().state();
            let trace = state.trace.expect("a trace");
            assert_eq!((trace.step, trace.operation), (0, "start"));
            assert_eq!(trace.variables["v"], "Vertex 1");
            assert_eq!(trace.variables["e"], "null");
            assert!(trace.span.is_none());

            harness.state_mut().trace_goto(usize::MAX).expect("goes");
            harness.run();
            let trace = harness.state().state().trace.expect("a trace");
            assert!(trace.done, "{sample} {structure:?}: {}", trace.message);
            assert_eq!(trace.step, trace.steps);
            let marked: BTreeSet<u32> = trace.marked.iter().map(|e| e.id).collect();
            assert_eq!(marked, edges_at(&mesh, 1), "{sample} {structure:?}");
            assert_eq!(marked.len(), trace.marked.len(), "each edge once");
            assert!(
                trace.message.contains("is done. Output:"),
                "{}",
                trace.message
            );
            // Done: labels cleared, marks kept.
            let state = harness.state().state();
            assert!(roles_of(&state, "variable").is_empty());
            assert_eq!(roles_of(&state, "marked").len(), marked.len());
        }
    }
}

#[test]
fn a_mark_step_shows_its_element_blue_though_a_variable_names_it() {
    let mut harness = support::harness_with("tetrahedron", None);
    run(&mut harness, "vertexAdjacentEdge", 1.0);
    let trace = loop {
        harness.state_mut().trace_step(1).expect("steps");
        harness.run();
        let trace = harness.state().state().trace.expect("a trace");
        assert!(!trace.done, "the run marks something");
        if trace.operation == "mark" {
            break trace;
        }
    };
    let state = harness.state().state();
    let named = trace.variables["e"].clone();
    let first_role = |kind, id| {
        state
            .highlights
            .iter()
            .find(|h| (h.kind, h.id) == (kind, id))
            .map(|h| h.role.clone())
    };
    let &marked = trace.marked.last().expect("one mark so far");
    assert_eq!(
        named,
        format!("Edge {}", marked.id),
        "e names the marked edge"
    );
    assert_eq!(
        first_role(marked.kind, marked.id).as_deref(),
        Some("marked"),
        "{:?}",
        state.highlights
    );
    // The next step, it shows as the variable's again.
    harness.state_mut().trace_step(1).expect("steps");
    harness.run();
    let state = harness.state().state();
    let role = state
        .highlights
        .iter()
        .find(|h| (h.kind, h.id) == (marked.kind, marked.id))
        .map(|h| h.role.clone());
    assert_ne!(role.as_deref(), Some("marked"), "{:?}", state.highlights);
}

#[test]
fn a_finished_run_keeps_only_its_marks_until_an_element_is_picked() {
    let mut harness = support::harness_with("tetrahedron", None);
    run(&mut harness, "vertexAdjacentFace", 1.0);
    // Before the end, the algorithm's `highlight v` shows.
    harness.state_mut().trace_step(2).expect("steps");
    harness.run();
    let state = harness.state().state();
    assert_eq!(roles_of(&state, "highlighted"), [(ElementKind::Vertex, 1)]);

    harness.state_mut().trace_goto(usize::MAX).expect("goes");
    harness.run();
    let state = harness.state().state();
    let trace = state.trace.clone().expect("a trace");
    assert!(trace.done);
    assert!(
        trace.message.contains("Pick an element to end the run"),
        "{}",
        trace.message
    );
    let roles: BTreeSet<&str> = state.highlights.iter().map(|h| h.role.as_str()).collect();
    assert_eq!(roles, BTreeSet::from(["marked"]), "only the marks stay");

    // Picking an element (here in the tables) ends the run and selects it.
    harness
        .get_by_label("incident edge of face 0: edge 0")
        .click();
    harness.run();
    let state = harness.state().state();
    assert!(state.trace.is_none(), "the run ended");
    assert_eq!(
        state.selection.map(|s| (s.kind, s.id)),
        Some((ElementKind::Edge, 0))
    );
    assert!(roles_of(&state, "marked").is_empty());
}

#[test]
fn a_lookup_step_colours_its_base_and_result_and_shows_the_expression() {
    let mut harness = support::harness_with("tetrahedron", None);
    let mesh = support::sample_mesh("tetrahedron.wtb", Structure::WingedEdge);
    let Mesh::Winged(m) = &mesh else {
        unreachable!()
    };
    run(&mut harness, "vertexAdjacentEdge", 1.0);
    // Step 1 is `e := v.incidentEdge`'s lookup.
    harness.state_mut().trace_step(1).expect("steps");
    harness.run();
    let state = harness.state().state();
    let trace = state.trace.clone().expect("a trace");
    assert_eq!(trace.operation, "lookup");
    let source = edgewise_core::lang::library::SOURCES[0].1;
    let [start, end] = trace.span.expect("a span");
    assert_eq!(&source[start as usize..end as usize], "v.incidentEdge");
    assert_eq!(
        source[..start as usize].lines().count() as u32,
        trace.line,
        "the span is on the current line"
    );
    let incident = m.vertices()[1].incident_edge.expect("not isolated");
    assert_eq!(
        roles_of(&state, "lookup"),
        [
            (ElementKind::Vertex, 1),
            (ElementKind::Edge, incident.index() as u32)
        ]
    );
    // The next step assigns it: e names that edge, which turns purple.
    harness.state_mut().trace_step(1).expect("steps");
    harness.run();
    let state = harness.state().state();
    let trace = state.trace.clone().expect("a trace");
    assert_eq!(trace.operation, "assign");
    assert_eq!(trace.variables["e"], format!("Edge {}", incident.index()));
    assert!(roles_of(&state, "variable").contains(&(ElementKind::Edge, incident.index() as u32)));
    // The message line and the algorithm view show the step.
    for text in ["Assignment: e := edge", "step 2 of"] {
        assert!(
            harness.query_all_by_label_contains(text).next().is_some(),
            "{text} is on screen"
        );
    }
}

#[test]
fn a_comparison_step_points_at_both_sides() {
    let mut harness = support::harness_with("cube", Some(Structure::HalfEdge));
    run(&mut harness, "vertexAdjacentEdge", 0.0);
    let steps = harness.state().state().trace.expect("a trace").steps;
    let mut compared = None;
    for k in 1..=steps {
        harness.state_mut().trace_goto(k).expect("goes");
        let state = harness.state().state();
        if state.trace.as_ref().expect("a trace").operation == "compare" {
            compared = Some(state);
            break;
        }
    }
    let state = compared.expect("the loop compares e with se");
    let sides = roles_of(&state, "compared");
    assert_eq!(sides.len(), 2, "{:?}", state.highlights);
    let trace = state.trace.expect("a trace");
    for (kind, id) in sides {
        assert_eq!(kind, ElementKind::Edge);
        assert!(
            trace.variables.values().any(|v| *v == format!("Edge {id}")),
            "each side is the value of e or se"
        );
    }
    assert!(
        trace.message.starts_with("Comparison e <> se"),
        "{}",
        trace.message
    );
}

#[test]
fn twenty_steps_forward_and_back_return_to_the_same_state() {
    let mut harness = support::harness_with("octahedron", Some(Structure::HalfEdge));
    run(&mut harness, "vertexAdjacentFace", 2.0);
    harness.state_mut().trace_step(5).expect("steps");
    harness.run();
    let before = harness.state().state();
    harness.state_mut().trace_step(20).expect("steps");
    harness.run();
    let after_forward = harness.state().state();
    assert_ne!(after_forward.trace, before.trace);
    harness.state_mut().trace_back(20).expect("steps back");
    harness.run();
    let after = harness.state().state();
    assert_eq!(after.trace, before.trace);
    assert_eq!(after.highlights, before.highlights);
}

#[test]
fn a_run_time_error_on_an_open_mesh_stops_where_it_happened() {
    let mut harness = support::harness_with("open-square", Some(Structure::HalfEdge));
    let mesh = support::sample_mesh("open-square.wtb", Structure::HalfEdge);
    let Mesh::Half(m) = &mesh else { unreachable!() };
    // A corner vertex: walking its faces meets the boundary's null face.
    let corner = (0..m.vertices().len() as u32)
        .find(|&v| {
            m.half_edges()
                .iter()
                .filter(|h| h.end_vertex == VertexId::new(v))
                .any(|h| h.face.is_none())
        })
        .expect("a boundary vertex");
    run(&mut harness, "vertexAdjacentFace", f64::from(corner));
    harness.state_mut().trace_goto(usize::MAX).expect("goes");
    harness.run();
    let trace = harness.state().state().trace.expect("a trace");
    let error = trace.error.expect("the run stops on an error");
    assert!(!trace.done);
    assert_eq!(trace.step, trace.steps, "the trace stays where it stopped");
    assert!(error.contains("null"), "{error}");
    assert!(
        trace.message.starts_with("Stopped at line"),
        "{}",
        trace.message
    );
    assert!(
        harness
            .query_all_by_label_contains("Stopped at line")
            .next()
            .is_some()
    );
}

#[test]
fn inputs_are_picked_by_clicking_only_the_needed_kind() {
    let mut harness = support::harness_with("tetrahedron", None);
    harness.get_by_label("Algorithm").click();
    harness.run();
    harness
        .get_all_by_label("vertexAdjacentFace")
        .find(|node| !node.accesskit_node().is_disabled())
        .expect("the winged-edge entry is enabled")
        .click();
    harness.run();
    let pending = harness.state().state().pending.expect("waiting for v");
    assert_eq!(pending.parameter.as_deref(), Some("v"));
    assert_eq!(pending.kind, Some(ElementKind::Vertex));
    assert_eq!(
        harness
            .get_all_by_label_contains("pick a Vertex for v")
            .count(),
        2,
        "the prompt is in the panel and on the message line"
    );

    // A face is refused, with a reason, and the algorithm keeps waiting.
    harness
        .get_by_label("incident edge of face 0: edge 0")
        .click();
    harness.run();
    assert!(harness.state().state().pending.is_some());
    assert!(harness.state().state().error.is_some_and(|e| {
        e.contains("needs a Vertex for v, not a edge") || e.contains("not a edge")
    }),);

    // The start vertex of edge 0 is a vertex: it starts the run.
    let mesh = support::sample_mesh("tetrahedron.wtb", Structure::WingedEdge);
    let Mesh::Winged(m) = &mesh else {
        unreachable!()
    };
    let start = m.edges()[0].start_vertex.index();
    harness
        .get_by_label(&format!("start of edge 0: vertex {start}"))
        .click();
    harness.run();
    let trace = harness.state().state().trace.expect("running");
    assert_eq!(trace.variables["v"], format!("Vertex {start}"));

    // Space steps, ← steps back, and the Step button steps.
    harness.key_press(egui::Key::Space);
    harness.run();
    assert_eq!(harness.state().state().trace.expect("running").step, 1);
    harness.get_by_label("Step ▶").click();
    harness.run();
    assert_eq!(harness.state().state().trace.expect("running").step, 2);
    harness.key_press(egui::Key::ArrowLeft);
    harness.run();
    assert_eq!(harness.state().state().trace.expect("running").step, 1);

    // Abort returns the mesh to its plain look.
    harness.get_by_label("✖ Abort").click();
    harness.run();
    let state = harness.state().state();
    assert!(state.trace.is_none() && state.pending.is_none());
    assert!(state.highlights.is_empty());
    let _ = (EdgeId::new(0), HalfEdgeId::new(0));
}

#[test]
fn a_breakpoint_set_on_a_line_number_stops_play() {
    let mut harness = support::harness_with("cube", Some(Structure::HalfEdge));
    run(&mut harness, "vertexAdjacentEdge", 0.0);
    // The `e.mark;` line of the half-edge library.
    let source = edgewise_core::lang::library::SOURCES[1].1;
    let mark_line = source
        .lines()
        .position(|l| l.trim() == "e.mark;")
        .expect("the line exists") as u32
        + 1;
    harness
        .get_by_label(&format!("breakpoint line {mark_line}"))
        .click();
    harness.run();
    harness.get_by_label("▶ Play").click();
    // Play steps every delay; run until it pauses.
    for _ in 0..400 {
        harness.run_steps(4);
        if harness.query_all_by_label("❚❚ Pause").next().is_none() {
            break;
        }
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    let trace = harness.state().state().trace.expect("running");
    assert_eq!(trace.line, mark_line, "paused on the breakpoint: {trace:?}");
    assert_eq!(trace.operation, "mark");
    assert!(!trace.done);
}

#[test]
fn a_loaded_algorithm_joins_the_menu_and_replaces_its_namesake() {
    let mut harness = support::harness_with("cube", Some(Structure::HalfEdge));
    let names = harness
        .state_mut()
        .load_algorithms(
            "algorithm vertexAdjacentEdge(v : Vertex) : HalfEdge;\nvar e : Edge;\nbegin\n  e := v.incidentEdge;\n  mark e;\nend\n",
            "mine.alg",
        )
        .expect("compiles");
    assert_eq!(names, ["vertexAdjacentEdge"]);
    run(&mut harness, "vertexAdjacentEdge", 0.0);
    harness.state_mut().trace_goto(usize::MAX).expect("goes");
    let trace = harness.state().state().trace.expect("running");
    assert_eq!(trace.marked.len(), 1, "the replacement ran");

    let err = harness
        .state_mut()
        .load_algorithms(
            "algorithm broken(v : Vertex) : HalfEdge;\nbegin\n  mark v.incidentEgde;\nend\n",
            "bad.alg",
        )
        .expect_err("does not compile");
    assert!(err.starts_with("bad.alg:3:"), "{err}");

    let err = harness
        .state_mut()
        .run_algorithm(
            "edgeOppositeEdges",
            &[("x".to_owned(), Argument::Number(0.0))],
        )
        .expect_err("no parameter x");
    assert!(err.contains("no parameter `x`"), "{err}");
}

#[test]
fn a_changed_trace_colour_is_used_and_reset_restores_the_journals() {
    let mut harness = support::harness_with("tetrahedron", None);
    let mut settings = harness.state().settings().clone();
    settings.set_colour(
        edgewise_model::trace_role::TraceRole::Lookup,
        egui::Color32::from_rgb(0x12, 0x34, 0x56),
    );
    harness.state_mut().set_settings(settings);
    run(&mut harness, "vertexAdjacentEdge", 1.0);
    harness.state_mut().trace_step(1).expect("steps");
    harness.run();
    let state = harness.state().state();
    let lookup = state
        .highlights
        .iter()
        .find(|h| h.role == "lookup")
        .expect("a lookup");
    assert_eq!(lookup.colour, "#123456");

    harness.get_by_label("View").click();
    harness.run();
    harness.get_by_label("Settings…").click();
    harness.run();
    harness
        .get_by_label("Reset to the journal's colours")
        .click();
    harness.run();
    let state = harness.state().state();
    let lookup = state
        .highlights
        .iter()
        .find(|h| h.role == "lookup")
        .expect("a lookup");
    assert_ne!(lookup.colour, "#123456");
    assert!(harness.state().settings().colours.is_empty());
}

#[test]
fn presenting_shows_the_chosen_panels_and_escape_leaves() {
    let mut harness = support::harness_with("cube", Some(Structure::HalfEdge));
    run(&mut harness, "vertexAdjacentEdge", 0.0);
    let ctx = harness.ctx.clone();
    harness.state_mut().enter_presentation(
        &ctx,
        edgewise_app::Presentation {
            algorithm: true,
            tables: false,
            menu: false,
        },
    );
    harness.run();
    assert!(harness.query_by_label("Samples").is_none(), "no menu bar");
    assert!(
        harness.query_by_label("left pred").is_none() && harness.query_by_label("pair").is_none(),
        "no tables"
    );
    harness.get_by_label("Step ▶");
    harness.get_by_label("Esc leaves the presentation");
    assert!(ctx.zoom_factor() > 1.2, "larger type");

    harness.key_press(egui::Key::Escape);
    harness.run();
    assert!(harness.state().presentation().is_none());
    harness.get_by_label("Samples");
    harness.get_by_label("pair");
    assert!((ctx.zoom_factor() - 1.0).abs() < 1e-6);
}

#[test]
fn an_algorithm_file_opens_in_the_editor_and_joins_the_menu() {
    let mut harness = support::harness();
    harness
        .state_mut()
        .open_file(
            "walks.alg",
            b"algorithm twoSteps(e : Edge) : HalfEdge;\nbegin\n  mark e.successorEdge.successorEdge;\nend\n"
                .to_vec(),
        )
        .expect("opens");
    harness.run();
    let list = harness.state().algorithm_list();
    assert!(
        list.iter()
            .any(|a| a.name == "twoSteps" && a.structure == "half"),
        "{list:?}"
    );
    harness.get_by_label_contains("In the Algorithm menu: twoSteps");

    // A broken file is marked at its line; nothing joins the menu.
    harness
        .state_mut()
        .open_file(
            "broken.alg",
            b"algorithm oops(e : Edge) : HalfEdge;\nbegin\n  mark e.sucessorEdge;\nend\n".to_vec(),
        )
        .expect("opens in the editor");
    harness.run();
    harness.get_by_label_contains("editor.alg:3:");
    assert!(
        !harness
            .state()
            .algorithm_list()
            .iter()
            .any(|a| a.name == "oops")
    );
}

/// Inside a call, a step's sentence names the called algorithm's variables
/// (flipEdge calls `joined`, whose `g := g.next.pair` was told as an
/// assignment to flipEdge's `h1`).
#[test]
fn a_step_inside_a_call_names_the_called_algorithms_variable() {
    let mut harness = support::harness_with("octahedron", Some(Structure::HalfEdge));
    support::run_flip_edge(&mut harness, 0);
    let steps = harness.state().state().trace.expect("tracing").steps;
    let mut inside = 0;
    for step in 1..=steps {
        harness.state_mut().trace_goto(step).expect("goto");
        let trace = harness.state().state().trace.expect("tracing");
        let Some(assigned) = trace.message.strip_prefix("Assignment: ") else {
            continue;
        };
        let name = assigned.split(" := ").next().unwrap_or_default();
        assert!(
            trace.variables.contains_key(name),
            "step {step} in {:?}: {} names {name}, not one of {:?}",
            trace.calls,
            trace.message,
            trace.variables.keys().collect::<Vec<_>>()
        );
        if trace.calls.len() > 1 {
            inside += 1;
        }
    }
    assert!(inside > 0, "some assignments ran inside a call");
}
