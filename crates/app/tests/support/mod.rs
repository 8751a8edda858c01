//! What the headless UI tests share: an app without a GPU in a window of a
//! given size, the sample files as the loaders read them, and rendering
//! egui into pixels.

#![allow(dead_code)]

pub mod gpu;

use edgewise_app::{EdgewiseApp, GraphicsBackend};
use edgewise_core::{
    formats,
    mesh::{Mesh, Structure},
};
use egui_kittest::Harness;

/// The app headless (no 3D rendering), in a window `width` by `height`.
pub fn harness_sized(width: f32, height: f32) -> Harness<'static, EdgewiseApp> {
    Harness::builder()
        .with_size(egui::vec2(width, height))
        // A table scrolling to a new selection animates over a few frames.
        .with_max_steps(32)
        .build_eframe(|_cc| EdgewiseApp::with_backend(GraphicsBackend::None, None))
}

/// The app headless in a laptop-sized window.
pub fn harness() -> Harness<'static, EdgewiseApp> {
    harness_sized(1400.0, 900.0)
}

/// The app headless with a built-in sample open as `structure` (or as the
/// sample file's own structure).
pub fn harness_with(sample: &str, structure: Option<Structure>) -> Harness<'static, EdgewiseApp> {
    let mut harness = harness();
    harness
        .state_mut()
        .load_sample(sample, structure)
        .expect("the sample opens");
    harness.run();
    harness
}

/// A sample file of meshes/, loaded natively as `structure`.
pub fn sample_mesh(file: &str, structure: Structure) -> Mesh {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../meshes")
        .join(file);
    let bytes = std::fs::read(&path).expect("the sample file exists");
    formats::load(&bytes, file, structure)
        .expect("the sample loads")
        .mesh
}
