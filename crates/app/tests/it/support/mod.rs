//! What the headless UI tests share: an app without a GPU in a window of a
//! given size, the sample files as the loaders read them, and rendering
//! egui into pixels.

#![allow(dead_code)]

pub mod app_renderer;
pub mod gpu;

use std::{
    path::{Path, PathBuf},
    sync::Arc,
};

use edgewise_app::{EdgewiseApp, GraphicsBackend};
use edgewise_core::{
    formats,
    mesh::{Mesh, Structure},
};
use edgewise_model::course_link::CourseLink;
use egui_kittest::{Harness, kittest::Queryable as _};

/// The app under test.
pub type AppHarness = Harness<'static, EdgewiseApp>;

/// The app headless (no 3D rendering), in a window `width` by `height`.
pub fn harness_sized(width: f32, height: f32) -> Harness<'static, EdgewiseApp> {
    Harness::builder()
        .with_size(egui::vec2(width, height))
        // A table scrolling to a new selection animates over a few frames.
        .with_max_steps(32)
        .renderer(app_renderer::AppRenderer::lazy())
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

/// [`harness_with`], then vertexAdjacentEdge started from vertex `v`, at
/// step 0.
#[allow(dead_code)] // Not every test file that includes this module uses it.
pub fn harness_tracing(
    sample: &str,
    structure: Option<Structure>,
    v: u32,
) -> Harness<'static, EdgewiseApp> {
    let mut harness = harness_with(sample, structure);
    run_vertex_adjacent_edge(&mut harness, v);
    harness
}

/// Starts vertexAdjacentEdge from vertex `v` and runs a frame.
pub fn run_vertex_adjacent_edge(harness: &mut AppHarness, v: u32) {
    harness
        .state_mut()
        .run_algorithm(
            "vertexAdjacentEdge",
            &[(
                "v".to_owned(),
                edgewise_model::algorithm::session::Argument::Number(f64::from(v)),
            )],
        )
        .expect("vertexAdjacentEdge runs");
    harness.run();
}

/// Starts flipEdge on half-edge `h` and runs a frame.
pub fn run_flip_edge(harness: &mut AppHarness, h: u32) {
    harness
        .state_mut()
        .run_algorithm(
            "flipEdge",
            &[(
                "h".to_owned(),
                edgewise_model::algorithm::session::Argument::Number(f64::from(h)),
            )],
        )
        .expect("flipEdge runs");
    harness.run();
}

/// Sets the running trace's questions (`line 13: Which edge will e be?`)
/// and runs a frame.
pub fn ask(harness: &mut AppHarness, questions: &str) {
    harness
        .state_mut()
        .execute(edgewise_app::command::Command::SetQuestions(
            questions.to_owned(),
        ))
        .expect("asks");
    harness.run();
}

/// A sample file of meshes/, loaded natively as `structure`.
pub fn sample_mesh(file: &str, structure: Structure) -> Mesh {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../meshes")
        .join(file);
    let bytes = std::fs::read(&path).expect("the sample file exists");
    formats::load(&bytes, file, structure)
        .expect("the sample loads")
        .mesh
}

/// A file dropped on the window, as the native integration delivers it.
#[derive(Debug)]
struct DroppedFile {
    path: PathBuf,
    bytes: Vec<u8>,
}

impl egui::DroppedFile for DroppedFile {
    fn path(&self) -> &Path {
        &self.path
    }

    fn bytes(&self) -> Result<Vec<u8>, String> {
        Ok(self.bytes.clone())
    }
}

/// Opens the OBJ editor and types `text` into it, then lets the edit
/// settle (the editor rebuilds the mesh after a pause in typing).
pub fn type_in_obj_editor(harness: &mut Harness<'static, EdgewiseApp>, text: &str) {
    harness.get_by_label("OBJ editor").click();
    harness.run();
    let editor = harness.get_by_role(egui::accesskit::Role::MultilineTextInput);
    editor.focus();
    editor.type_text(text);
    harness.run_steps(60);
}

/// Drops a file called `name` on the window; the next frame receives it.
pub fn drop_file(harness: &mut Harness<'static, EdgewiseApp>, name: &str, bytes: Vec<u8>) {
    harness
        .input_mut()
        .dropped_files
        .push(Arc::new(DroppedFile {
            path: PathBuf::from("/home/student").join(name),
            bytes,
        }));
}

/// A fresh app after following the course link `?query#fragment`, as a
/// page load does, with the link's messages.
pub fn open_link(query: &str, fragment: &str) -> (Harness<'static, EdgewiseApp>, Vec<String>) {
    let mut harness = harness();
    let (link, messages) = CourseLink::parse(query, fragment);
    let messages = harness.state_mut().apply_course_link(&link, messages, None);
    harness.run();
    (harness, messages)
}

/// The largest difference between two pictures' channels, in levels.
pub fn worst_channel_difference(a: &[u8], b: &[u8]) -> u8 {
    a.iter()
        .zip(b)
        .map(|(a, b)| a.abs_diff(*b))
        .max()
        .unwrap_or(0)
}
