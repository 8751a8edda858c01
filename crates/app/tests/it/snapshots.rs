//! Pictures of the whole app, 3D view included, compared with the PNGs in
//! tests/snapshots/ (`UPDATE_SNAPSHOTS=1` rewrites them after a deliberate
//! change; a failed comparison leaves `*.new.png` and `*.diff.png` beside
//! them).
//!
//! kittest's own wgpu renderer draws without a depth buffer, which the 3D
//! view's paint callback needs, so these tests render through
//! [`AppRenderer`]: the same `egui_wgpu` renderer with the `Depth24Plus`
//! attachment the app gets from eframe. Without a wgpu adapter (no GPU and
//! no lavapipe) a plain `cargo test` says so and skips them; `cargo xtask
//! test` sets `EDGEWISE_REQUIRE_GPU`, which makes that a failure.

#![allow(clippy::unwrap_used)]

use crate::support;

use crate::support::app_renderer::AppRenderer;
use edgewise_app::EdgewiseApp;
use edgewise_core::mesh::Structure;
use edgewise_core::schema::{ElementKind, ElementRef};
use edgewise_model::{algorithm::session::Argument, settings::Settings};
use egui_kittest::{Harness, SnapshotOptions, kittest::Queryable as _};

/// Lavapipe and the text rasteriser are deterministic on one machine; the
/// threshold absorbs small differences between Mesa versions.
fn options() -> SnapshotOptions {
    SnapshotOptions::new().threshold(1.5).max_failed_pixels(400)
}

/// The app in a window of `size` points at `pixels_per_point`, drawing its
/// 3D view; None without a wgpu adapter.
fn harness(size: egui::Vec2, pixels_per_point: f32) -> Option<Harness<'static, EdgewiseApp>> {
    let Some(state) = support::gpu::render_state() else {
        eprintln!("no wgpu adapter (install mesa-vulkan-drivers): snapshots skipped");
        return None;
    };
    Some(
        Harness::builder()
            .with_size(size)
            .with_max_steps(32)
            .with_pixels_per_point(pixels_per_point)
            .renderer(AppRenderer::drawing_3d(state))
            .build_eframe(|cc| EdgewiseApp::new(cc)),
    )
}

#[test]
fn tetrahedron_winged_edge_with_edge_0_selected_light() {
    let Some(mut harness) = harness(egui::vec2(1280.0, 800.0), 1.0) else {
        return;
    };
    let app = harness.state_mut();
    app.load_sample("tetrahedron", Some(Structure::WingedEdge))
        .unwrap();
    app.select(Some(ElementRef {
        kind: ElementKind::Edge,
        id: 0,
    }))
    .unwrap();
    harness.run();
    harness.snapshot_options("tetrahedron-winged-edge0-light", &options());
}

#[test]
fn cube_half_edge_dark_at_lecture_hall_scale() {
    let Some(mut harness) = harness(egui::vec2(1280.0, 720.0), 1.5) else {
        return;
    };
    let app = harness.state_mut();
    app.set_settings(Settings {
        dark: true,
        ..Settings::default()
    });
    app.load_sample("cube", Some(Structure::HalfEdge)).unwrap();
    app.select(Some(ElementRef {
        kind: ElementKind::Face,
        id: 2,
    }))
    .unwrap();
    harness.run();
    harness.snapshot_options("cube-half-edge-face2-dark-lecture", &options());
}

/// The OBJ editor after a good square and then a face naming a missing
/// vertex: the square stays in the view, the bad line is marked.
fn obj_editor_with_an_error(dark: bool, name: &str) {
    let Some(mut harness) = harness(egui::vec2(1280.0, 800.0), 1.0) else {
        return;
    };
    if dark {
        harness.state_mut().set_settings(Settings {
            dark: true,
            ..Settings::default()
        });
        harness.run();
    }
    support::type_in_obj_editor(
        &mut harness,
        "# a square, then a broken triangle\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n",
    );
    let editor = harness.get_by_role(egui::accesskit::Role::MultilineTextInput);
    editor.type_text("f 1 2 17\n");
    harness.run_steps(60);
    let state = harness.state().state();
    assert_eq!(state.counts.faces, 1, "the square stays");
    assert_eq!(state.diagnostics.len(), 1);
    harness.snapshot_options(name, &options());
}

#[test]
fn obj_editor_with_an_inline_error_light() {
    obj_editor_with_an_error(false, "obj-editor-error-light");
}

#[test]
fn obj_editor_with_an_inline_error_dark() {
    obj_editor_with_an_error(true, "obj-editor-error-dark");
}

#[test]
fn structure_dialog() {
    let Some(mut harness) = harness(egui::vec2(1280.0, 800.0), 1.0) else {
        return;
    };
    harness.state_mut().load_sample("octahedron", None).unwrap();
    harness
        .state_mut()
        .open_file(
            "quad.obj",
            b"v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n".to_vec(),
        )
        .unwrap();
    harness.run();
    harness.snapshot_options("structure-dialog", &options());
}

/// A trace at the first step whose operation is `operation`.
fn trace_at(
    harness: &mut Harness<'static, EdgewiseApp>,
    sample: &str,
    structure: Structure,
    v: f64,
    operation: &str,
) {
    let app = harness.state_mut();
    app.load_sample(sample, Some(structure)).unwrap();
    app.run_algorithm(
        "vertexAdjacentEdge",
        &[("v".to_owned(), Argument::Number(v))],
    )
    .unwrap();
    for _ in 0..200 {
        harness.state_mut().trace_step(1).unwrap();
        let state = harness.state().state();
        if state.trace.as_ref().unwrap().operation == operation {
            break;
        }
    }
    harness.run();
}

#[test]
fn trace_lookup_step_light() {
    let Some(mut harness) = harness(egui::vec2(1440.0, 900.0), 1.0) else {
        return;
    };
    trace_at(
        &mut harness,
        "tetrahedron",
        Structure::WingedEdge,
        1.0,
        "lookup",
    );
    harness.snapshot_options("trace-lookup-tetrahedron-winged-light", &options());
}

#[test]
fn trace_comparison_step_dark() {
    let Some(mut harness) = harness(egui::vec2(1440.0, 900.0), 1.0) else {
        return;
    };
    harness.state_mut().set_settings(Settings {
        dark: true,
        ..Settings::default()
    });
    trace_at(&mut harness, "cube", Structure::HalfEdge, 0.0, "compare");
    harness.snapshot_options("trace-compare-cube-half-dark", &options());
}

#[test]
fn algorithm_editor_with_errors_light() {
    let Some(mut harness) = harness(egui::vec2(1440.0, 900.0), 1.0) else {
        return;
    };
    let app = harness.state_mut();
    app.load_sample("cube", Some(Structure::HalfEdge)).unwrap();
    app.open_file(
        "walks.alg",
        b"// Two mistakes: a misspelt lookup and a missing `:=`.\nalgorithm walk(v : Vertex) : HalfEdge;\nvar e : Edge;\nbegin\n  e := v.incidentEgde;\n  e = e.pairEdge;\n  mark e;\nend\n"
            .to_vec(),
    )
    .unwrap();
    harness.run();
    harness.snapshot_options("algorithm-editor-errors-light", &options());
}

/// A course link whose algorithm is 100,000 terms long: the error panel
/// quotes the line around the place, with the caret under it in a monospace
/// font, and the view below still works.
#[test]
fn hostile_link_error_light() {
    let Some(mut harness) = harness(egui::vec2(1280.0, 800.0), 1.0) else {
        return;
    };
    let source = format!(
        "algorithm long(n : Integer) : WingedEdge;\nbegin\n  n := n{};\nend\n",
        " + 1".repeat(100_000)
    );
    let fragment = format!(
        "#alg={}",
        edgewise_model::course_link::encode_payload(&source)
    );
    let (link, messages) =
        edgewise_model::course_link::CourseLink::parse("?sample=tetrahedron", &fragment);
    let messages = harness.state_mut().apply_course_link(&link, messages, None);
    assert_eq!(messages.len(), 1, "{messages:?}");
    harness.run();
    harness.snapshot_options("hostile-link-error-light", &options());
}

#[test]
fn the_first_visit_with_its_hint_and_the_parts_explained() {
    let Some(mut harness) = harness(egui::vec2(1280.0, 800.0), 1.0) else {
        return;
    };
    harness.state_mut().first_visit();
    harness.run();
    harness.snapshot_options("first-visit", &options());
    harness.get_by_label("What am I looking at?").click();
    harness.run();
    harness.snapshot_options("first-visit-explained", &options());
}

#[test]
fn a_question_answered_wrongly_with_its_explanation() {
    let Some(mut harness) = harness(egui::vec2(1440.0, 900.0), 1.0) else {
        return;
    };
    let app = harness.state_mut();
    app.load_sample("tetrahedron", Some(Structure::WingedEdge))
        .unwrap();
    app.run_algorithm(
        "vertexAdjacentEdge",
        &[("v".to_owned(), Argument::Number(1.0))],
    )
    .unwrap();
    app.execute(edgewise_app::command::Command::SetQuestions(
        include_str!("../../../../algorithms/questions/vertex-adjacent-edge.txt").to_owned(),
    ))
    .unwrap();
    app.trace_goto(6).unwrap();
    harness.run();
    harness.snapshot_options("question-asked", &options());
    harness
        .state_mut()
        .execute(edgewise_app::command::Command::Answer(
            edgewise_core::lang::Value::Edge(2),
        ))
        .unwrap();
    harness.run();
    harness.snapshot_options("question-answered-wrongly", &options());
}

#[test]
fn keyboard_focus_ring_light() {
    let Some(mut harness) = harness(egui::vec2(1280.0, 800.0), 1.0) else {
        return;
    };
    harness
        .state_mut()
        .load_sample("tetrahedron", Some(Structure::WingedEdge))
        .unwrap();
    harness.run();
    for _ in 0..3 {
        harness.key_press(egui::Key::Tab);
        harness.run();
    }
    assert!(harness.state().focus_ring().is_some());
    harness.snapshot_options("keyboard-focus-ring-light", &options());
}

/// The practice card after a check that found a wrong cell: the task, the
/// row tools, the feedback naming the difference.
#[test]
fn a_flip_exercise_checked_with_one_wrong_cell() {
    use edgewise_app::command::Command;
    let Some(mut harness) = harness(egui::vec2(1280.0, 800.0), 1.0) else {
        return;
    };
    let app = harness.state_mut();
    app.execute(Command::StartExercise {
        exercise: "flip-edge-half-edge".to_owned(),
        seed: Some(3),
        progress: None,
        name: None,
    })
    .unwrap();
    // Half-edge 16's end moved to the flip's new end; the rest not yet done.
    app.execute(Command::SetCell {
        element: ElementRef::new(ElementKind::Edge, 16),
        column: "endVertex".to_owned(),
        target: Some(0),
    })
    .unwrap();
    app.execute(Command::SubmitExercise).unwrap();
    harness.run();
    let exercise = harness.state().state().exercise.unwrap();
    assert_eq!(exercise.passed, Some(false));
    harness.snapshot_options("practice-flip-one-wrong-cell", &options());
}

/// A walk with one click right and one corrected: the card lists what is
/// found and says what the walk marks next.
#[test]
fn a_walk_with_a_wrong_click_corrected() {
    use edgewise_app::command::Command;
    let Some(mut harness) = harness(egui::vec2(1280.0, 800.0), 1.0) else {
        return;
    };
    let app = harness.state_mut();
    app.execute(Command::StartExercise {
        exercise: "walk-vertex-edges-winged-edge".to_owned(),
        seed: Some(0),
        progress: None,
        name: None,
    })
    .unwrap();
    for id in [1, 2] {
        app.execute(Command::Select(Some(ElementRef::new(
            ElementKind::Edge,
            id,
        ))))
        .unwrap();
    }
    harness.run();
    let exercise = harness.state().state().exercise.unwrap();
    assert_eq!((exercise.correct, exercise.step), (1, 2));
    harness.snapshot_options("practice-walk-one-corrected", &options());
}

/// A prediction after one right answer and one wrong: the question the run
/// asks now, with its null button.
#[test]
fn a_prediction_asking_its_third_lookup() {
    use edgewise_app::command::Command;
    let Some(mut harness) = harness(egui::vec2(1280.0, 800.0), 1.0) else {
        return;
    };
    let app = harness.state_mut();
    app.execute(Command::StartExercise {
        exercise: "predict-vertex-edges-winged-edge".to_owned(),
        seed: Some(0),
        progress: None,
        name: None,
    })
    .unwrap();
    app.execute(Command::AnswerExercise(Some(ElementRef::new(
        ElementKind::Edge,
        1,
    ))))
    .unwrap();
    app.execute(Command::AnswerExercise(None)).unwrap();
    harness.run();
    let exercise = harness.state().state().exercise.unwrap();
    assert_eq!((exercise.correct, exercise.step), (1, 2));
    harness.snapshot_options("practice-predict-third-lookup", &options());
}
