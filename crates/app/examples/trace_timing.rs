//! Reports what tracing costs on a large mesh: recording a run, and one
//! step of the UI (re-deriving the colours and labels of every element and
//! laying out the frame), headless.
//!
//! `cargo run --release -p edgewise-app --example trace_timing`

use std::time::Instant;

use edgewise_app::{EdgewiseApp, GraphicsBackend};
use edgewise_core::mesh::Structure;
use edgewise_model::algorithm::session::Argument;
use egui_kittest::Harness;

fn main() {
    for structure in [Structure::HalfEdge, Structure::WingedEdge] {
        let mut harness = Harness::builder()
            .with_size(egui::vec2(1440.0, 900.0))
            .build_eframe(|_cc| EdgewiseApp::with_backend(GraphicsBackend::None, None));
        if let Err(message) = harness
            .state_mut()
            .load_sample("torus-200k", Some(structure))
        {
            eprintln!("cannot open the 200k torus: {message}");
            return;
        }
        harness.run();

        // A selection with the frame after it, as a click makes one.
        let selections = 20_u32;
        let start = Instant::now();
        for e in 0..selections {
            let edge = edgewise_core::schema::ElementRef::new(
                edgewise_core::schema::ElementKind::Edge,
                1000 + 7 * e,
            );
            harness.state_mut().select(Some(edge)).ok();
            harness.step();
        }
        let per_selection = start.elapsed() / selections;
        harness.state_mut().select(None).ok();
        harness.run();

        let start = Instant::now();
        let started = harness
            .state_mut()
            .run_algorithm("vertexStar", &[("v".to_owned(), Argument::Number(1000.0))]);
        if let Err(message) = started {
            eprintln!("cannot run vertexStar: {message}");
            return;
        }
        let record = start.elapsed();
        harness.run();

        let steps = harness
            .state()
            .state()
            .trace
            .map_or(0, |trace| trace.steps)
            .min(40);
        let start = Instant::now();
        for _ in 0..steps {
            harness.state_mut().trace_step(1).ok();
            harness.step();
        }
        let per_step = start.elapsed() / u32::try_from(steps.max(1)).unwrap_or(1);
        println!(
            "200k-face torus, {structure:?}: a selection with its frame (headless) {:.1} ms; \
             recording vertexStar {:.2} ms; one step with the frame drawn (headless) {:.1} ms, \
             over {steps} steps",
            per_selection.as_secs_f64() * 1e3,
            record.as_secs_f64() * 1e3,
            per_step.as_secs_f64() * 1e3,
        );
    }
}
