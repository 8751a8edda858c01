//! The bodies of the `course_link` and `link` fuzz targets in `fuzz/`.
//!
//! The fuzz targets (nightly, libFuzzer) and the replay test
//! (`crates/app/tests/it/fuzz_regressions.rs`, stable, run by `cargo xtask
//! test`) both call it, so a crash found by the fuzzer is replayed by exactly
//! the code that found it. Not part of the app's interface.

use edgewise_core::schema::{ElementKind, ElementRef};

use crate::{EdgewiseApp, GraphicsBackend, command::Command};
use edgewise_model::course_link::FetchedMesh;
use edgewise_model::course_link::{CourseLink, MeshSource, decode_payload};

/// A course link: the input up to the first `#` or NUL byte is the query,
/// the rest the fragment. The whole input is also decoded as a `#mesh=`
/// payload, and the parsed link is written back as a URL.
pub fn course_link(data: &[u8]) {
    let Some((text, search, fragment)) = split_link(data) else {
        return;
    };
    let (link, messages) = CourseLink::parse(search, fragment);
    assert!(messages.iter().all(|message| !message.is_empty()));
    drop(link.to_url("https://example.com/edgewise/"));
    drop(decode_payload("mesh", text));
}

/// The input as a link's query and fragment, split at the first `#` or NUL.
/// Links are `&str`: input that is not UTF-8 never reaches the parser.
fn split_link(data: &[u8]) -> Option<(&str, &str, &str)> {
    let text = std::str::from_utf8(data).ok()?;
    let (search, fragment) = match text.find(['#', '\0']) {
        Some(at) => (&text[..at], &text[at + 1..]),
        None => (text, ""),
    };
    Some((text, search, fragment))
}

/// A whole course link opened in a headless app, as a page opens its
/// address: every parameter applied (a `mesh=` path is answered with the
/// input's own bytes), two frames drawn, `state()` read, then a selection, a
/// step forward and back, and one more frame. Nothing may panic, and every
/// message must say something.
pub fn link(data: &[u8]) {
    let Some((text, search, fragment)) = split_link(data) else {
        return;
    };
    let (link, messages) = CourseLink::parse(search, fragment);
    let fetched = match &link.mesh {
        Some(MeshSource::Path(path)) => Some(FetchedMesh {
            name: path.rsplit('/').next().unwrap_or(path).to_owned(),
            bytes: Ok(text.as_bytes().to_vec()),
        }),
        _ => None,
    };
    let mut app = EdgewiseApp::with_backend(GraphicsBackend::None, None);
    let messages = app.apply_course_link(&link, messages, fetched);
    assert!(messages.iter().all(|message| !message.is_empty()));
    let ctx = egui::Context::default();
    draw_frame(&ctx, &mut app);
    draw_frame(&ctx, &mut app);
    let state = app.state();
    drop(serde_json::to_string(&state));
    // Refusals are fine; only a panic fails.
    let edge = ElementRef::new(ElementKind::Edge, 0);
    drop(app.execute(Command::Select(Some(edge))));
    drop(app.execute(Command::Step(1)));
    drop(app.execute(Command::Back(1)));
    draw_frame(&ctx, &mut app);
}

/// One frame of `app` in a laptop-sized window, without eframe.
fn draw_frame(ctx: &egui::Context, app: &mut EdgewiseApp) {
    let input = egui::RawInput {
        screen_rect: Some(egui::Rect::from_min_size(
            egui::Pos2::ZERO,
            egui::vec2(1280.0, 800.0),
        )),
        ..egui::RawInput::default()
    };
    // Nothing draws the output; its texture changes are dropped knowingly.
    let mut output = ctx.run_ui(input, |ui| app.frame_ui(ui, None));
    output.textures_delta.clear();
}
