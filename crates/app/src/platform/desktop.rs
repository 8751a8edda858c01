//! The desktop (development and UI tests): a typed path and dropped files,
//! files written to the current directory, settings for the session only.

use super::{PendingFile, RunText};

/// Opening and saving files natively.
#[derive(Default)]
pub struct FileIo {
    /// The path typed into the Open box.
    path: String,
    /// Where the last save went, shown in the Save as… menu.
    saved: Option<String>,
}

impl FileIo {
    /// Writes `bytes` to `name` in the current directory; returns what to
    /// tell the user.
    pub fn write(&mut self, name: &str, bytes: &[u8]) -> Result<String, String> {
        let said = std::env::current_dir()
            .map(|dir| dir.join(name))
            .and_then(|path| std::fs::write(&path, bytes).map(|()| path))
            .map(|path| format!("Saved {}", path.display()))
            .map_err(|err| format!("cannot write {name}: {err}"))?;
        self.saved = Some(said.clone());
        Ok(said)
    }

    /// The file dropped on the window this frame, read.
    pub fn receive(&mut self, ctx: &egui::Context) -> Vec<Result<PendingFile, String>> {
        let dropped = ctx.input(|i| i.raw.dropped_files.first().cloned());
        dropped
            .map(|file| read(file.path(), file.bytes()))
            .into_iter()
            .collect()
    }

    /// The Open mesh… menu: a path box and the hint that files can be
    /// dropped on the window.
    pub fn open_ui(
        &mut self,
        ui: &mut egui::Ui,
        extensions: &str,
    ) -> Option<Result<PendingFile, String>> {
        let mut open = false;
        ui.menu_button("Open mesh…", |ui| {
            ui.label(format!("Path of a {extensions} file:"));
            let response = ui.add(
                egui::TextEdit::singleline(&mut self.path)
                    .desired_width(320.0)
                    .hint_text("meshes/cube.htb"),
            );
            open = ui.button("Open").clicked()
                || (response.lost_focus() && ui.input(|i| i.key_pressed(egui::Key::Enter)));
            ui.weak("Or drop a file on the window.");
            if open {
                ui.close();
            }
        });
        open.then(|| {
            let path = std::path::PathBuf::from(self.path.trim());
            let bytes = std::fs::read(&path).map_err(|err| err.to_string());
            read(&path, bytes)
        })
    }

    /// Where saved files go, under Save as….
    pub fn save_note_ui(&self, ui: &mut egui::Ui) {
        ui.separator();
        match &self.saved {
            Some(saved) => ui.weak(saved.as_str()),
            None => ui.weak("Files go to the current directory."),
        };
    }

    /// There is no native file picker: what to tell the user instead.
    pub fn pick(
        &self,
        _ctx: &egui::Context,
        _accept: &str,
    ) -> Result<Option<&'static str>, String> {
        Ok(Some(
            "Drop the file on the window, or type its path in Open mesh….",
        ))
    }
}

/// A file read from `path`, named by its last component.
fn read(path: &std::path::Path, bytes: Result<Vec<u8>, String>) -> Result<PendingFile, String> {
    let name = path.file_name().map_or_else(
        || path.display().to_string(),
        |n| n.to_string_lossy().into_owned(),
    );
    match bytes {
        Ok(bytes) => Ok(PendingFile { name, bytes }),
        Err(err) => Err(format!("{name}: cannot read the file: {err}")),
    }
}

/// Settings last the session natively.
pub fn load_settings(_key: &str) -> Option<String> {
    None
}

/// Settings last the session natively.
pub fn store_settings(_key: &str, _json: &str) {}

/// A window's surface is sized by winit.
pub fn fit_canvas() -> bool {
    false
}

/// A desktop's pointer is a mouse; a touch seen says otherwise.
pub fn coarse_pointer() -> bool {
    false
}

/// Enters or leaves fullscreen for a presentation.
pub fn set_fullscreen(ctx: &egui::Context, on: bool) {
    ctx.send_viewport_cmd(egui::ViewportCommand::Fullscreen(on));
}

/// Only a browser leaves fullscreen by itself.
pub fn left_fullscreen() -> bool {
    false
}

/// Natively there is no page; links name the local server `cargo xtask
/// serve` runs.
pub fn page_base() -> String {
    "http://127.0.0.1:8080/".to_owned()
}

/// Natively there is no page to tell: the events stay queued for tests
/// (`EdgewiseApp::take_embed_events`), the oldest dropped past a bound.
pub fn deliver_events(_events: &mut Vec<crate::EmbedEvent>) {}

/// Natively egui's AccessKit output is what screen readers read.
pub const READER_COPY: bool = false;

pub fn show_to_readers(_tables: Option<&str>, _message: Option<&str>) {}

pub fn change_for_readers(_cells: &[(String, String)], _message: Option<&str>) {}

pub fn show_run_to_readers(_run: Option<&RunText<'_>>) {}

pub fn show_algorithms_to_readers(_html: &str) {}

/// Builds `package` from the release in `dist/` and writes it as `name` in
/// the current directory; `status` then holds what to tell the user.
#[expect(
    clippy::needless_pass_by_value,
    reason = "the same signature as the browser's, which moves these into its task"
)]
pub fn download_package(
    package: edgewise_model::package::Package,
    name: String,
    status: std::rc::Rc<std::cell::RefCell<Option<String>>>,
    _ctx: egui::Context,
) {
    let said = edgewise_model::package::AppFiles::read(|file| {
        let path = std::path::Path::new("dist").join(file);
        std::fs::read(&path).map_err(|err| format!("{}: {err}", path.display()))
    })
    .and_then(|app| package.zip(&app))
    .map_err(|err| err.to_string())
    .and_then(|bytes| {
        std::fs::write(&name, &bytes)
            .map(|()| format!("Saved {name} ({:.1} MB)", bytes.len() as f64 / 1e6))
            .map_err(|err| format!("cannot write {name}: {err}"))
    });
    *status.borrow_mut() =
        Some(said.unwrap_or_else(|err| format!("The package could not be made: {err}")));
}
