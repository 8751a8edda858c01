//! Opening meshes from disk and saving them.
//!
//! Files arrive from the Open mesh… button, from a drop on the window, or
//! (natively) from a typed path. The format comes from the extension: table
//! files open as the structure they store, PLY and OBJ ask which structure to
//! build (`open_dialog.rs`). Save as… writes the open mesh in any
//! format: a download in the browser, a file in the current directory
//! natively (there is no native file dialog, to keep the desktop build free
//! of GTK and D-Bus dependencies).

use edgewise_core::formats::{self, Format};

use crate::{
    EdgewiseApp,
    app::open_dialog::StructureDialog,
    command::{Command, CommandError},
    platform::{FileIo, PendingFile},
    save_format::SaveFormat,
};

/// The extensions Edgewise opens, for messages and the file picker.
pub const OPEN_EXTENSIONS: &str = ".wtb, .htb, .ply or .obj";

/// What the app keeps for opening and saving files.
#[derive(Default)]
pub struct FileState {
    /// The structure question for a PLY or OBJ file, while it is asked.
    pub(crate) dialog: Option<StructureDialog>,
    /// Reading and writing files where the app runs.
    pub(crate) io: FileIo,
    /// A large file, opened once a frame has shown that it is being opened:
    /// reading it blocks the page, so "Opening…" paints first.
    pub(crate) opening: Option<Opening>,
    /// What else is being opened (a large `loadMesh` text), for the overlay.
    pub(crate) busy: Option<String>,
}

/// A large file waiting to be opened, and how many frames have shown so.
pub(crate) struct Opening {
    file: PendingFile,
    frames_shown: u8,
}

/// An egui area is measured, unseen, on its first frame; the second shows it.
const FRAMES_TO_SHOW: u8 = 2;

/// Files larger than this are announced with an overlay before they are
/// read, since reading and drawing them can take seconds in a browser.
pub const ANNOUNCE_BYTES: usize = 2 << 20;

/// "Opening torus.obj (23.4 MB)…".
pub fn opening_label(name: &str, bytes: usize) -> String {
    format!("Opening {name} ({:.1} MB)…", bytes as f64 / 1e6)
}

/// Whether a file holds algorithms (`.alg`) rather than a mesh.
pub fn is_algorithm_file(name: &str) -> bool {
    std::path::Path::new(name)
        .extension()
        .is_some_and(|ext| ext.eq_ignore_ascii_case("alg"))
}

/// The open mesh written in a format, with the name to save it under.
pub struct SavedFile {
    pub name: String,
    pub bytes: Vec<u8>,
}

impl EdgewiseApp {
    /// The open mesh written as `format`, named after the mesh
    /// (`cube.htb` saved as OBJ is `cube.obj`). Table formats convert a mesh
    /// of the other structure.
    pub fn export(&self, format: SaveFormat) -> Result<SavedFile, String> {
        let document = self.tab().document.as_ref().ok_or("no mesh is open")?;
        let bytes = formats::save(document.mesh(), format.format(), &format.options())
            .map_err(|err| format!("cannot save as {}: {err}", format.label()))?;
        Ok(SavedFile {
            name: format!(
                "{}.{}",
                edgewise_model::document::mesh_stem(&document.name),
                format.format().extension()
            ),
            bytes,
        })
    }

    /// [`Command::OpenFile`]: a table file opens as the structure it
    /// stores; for PLY and OBJ the structure dialog asks first. Unknown
    /// extensions are refused with the current mesh kept.
    pub(crate) fn open_named_file(
        &mut self,
        name: &str,
        bytes: Vec<u8>,
    ) -> Result<(), CommandError> {
        if is_algorithm_file(name) {
            return self.open_algorithm_file(name, &bytes);
        }
        let Some(format) = Format::from_name(name) else {
            return Err(format!(
                "{name}: Edgewise opens {OPEN_EXTENSIONS} files; the extension says which"
            )
            .into());
        };
        match format.native_structure() {
            Some(structure) => self.open_bytes(&bytes, name, Some(structure), false),
            None => {
                self.files.dialog = Some(StructureDialog::new(name, bytes, self.tab().structure));
                Ok(())
            }
        }
    }

    /// [`Command::SaveAs`]: a download in the browser, a file in the
    /// current directory natively.
    pub(crate) fn save_as(&mut self, format: SaveFormat) -> Result<(), CommandError> {
        let saved = self.export(format)?;
        self.files.io.write(&saved.name, &saved.bytes)?;
        Ok(())
    }

    /// Takes files dropped on the window this frame (the first one, if
    /// several) and, in the browser, files that finished reading.
    pub(crate) fn receive_files(&mut self, ctx: &egui::Context) {
        if self
            .files
            .opening
            .as_ref()
            .is_some_and(|opening| opening.frames_shown >= FRAMES_TO_SHOW)
            && let Some(Opening { file, .. }) = self.files.opening.take()
        {
            self.issue(Command::OpenFile {
                name: file.name,
                bytes: file.bytes,
            });
        }
        for file in self.files.io.receive(ctx) {
            match file {
                Ok(file) => self.open_or_announce(ctx, file),
                Err(message) => self.report(message),
            }
        }
    }

    /// The top bar's Open mesh… and Save as… entries.
    pub(crate) fn files_menu_ui(&mut self, ui: &mut egui::Ui) {
        let nested = egui::containers::menu::is_in_menu(ui);
        let open = ui.scope(|ui| self.open_button_ui(ui)).response;
        self.record_command("Open mesh…", &open, nested);
        let mut chosen = None;
        let has_mesh = self.tab().document.is_some();
        ui.add_enabled_ui(has_mesh, |ui| {
            self.menu_ui(ui, "Save as…", |this, ui| {
                for format in SaveFormat::ALL {
                    if ui.button(format.label()).clicked() {
                        chosen = Some(Command::SaveAs(format));
                    }
                }
                ui.separator();
                if ui
                    .button("Picture of the view (.svg)")
                    .on_hover_text("The 3D view as vector shapes, with the tables beside it")
                    .clicked()
                {
                    chosen = Some(Command::SavePicture);
                }
                let running = this.tab().run.session().is_some();
                if ui
                    .add_enabled(running, egui::Button::new("Handout of the run (.pdf)"))
                    .on_hover_text("A page per step of the algorithm's run, for printing")
                    .on_disabled_hover_text("Run an algorithm first")
                    .clicked()
                {
                    chosen = Some(Command::SaveHandout);
                }
                this.files.io.save_note_ui(ui);
            })
            .on_disabled_hover_text("Open a mesh first");
        });
        if let Some(command) = chosen {
            self.issue(command);
        }
    }

    /// Open mesh…: the browser's picker, or natively a path box.
    fn open_button_ui(&mut self, ui: &mut egui::Ui) {
        match self.files.io.open_ui(ui, OPEN_EXTENSIONS) {
            Some(Ok(file)) => self.open_or_announce(ui.ctx(), file),
            Some(Err(message)) => self.report(message),
            None => {}
        }
    }

    /// Opens a small file now; a large one on the next frame, after this
    /// one has shown that it is being opened.
    fn open_or_announce(&mut self, ctx: &egui::Context, file: PendingFile) {
        if file.bytes.len() > ANNOUNCE_BYTES && self.files.opening.is_none() {
            self.files.opening = Some(Opening {
                file,
                frames_shown: 0,
            });
            ctx.request_repaint();
        } else {
            self.issue(Command::OpenFile {
                name: file.name,
                bytes: file.bytes,
            });
        }
    }

    /// The structure dialog, a hint while files are dragged over the window,
    /// and what is being opened while a large file is read.
    pub(crate) fn files_overlay_ui(&mut self, ctx: &egui::Context) {
        self.structure_dialog_ui(ctx);
        let opening = self.files.opening.as_mut().map(|opening| {
            opening.frames_shown = opening.frames_shown.saturating_add(1);
            ctx.request_repaint();
            opening_label(&opening.file.name, opening.file.bytes.len())
        });
        if let Some(label) = opening.or_else(|| self.files.busy.clone()) {
            egui::Area::new(egui::Id::unique("opening"))
                .order(egui::Order::Foreground)
                .anchor(egui::Align2::CENTER_CENTER, egui::Vec2::ZERO)
                .show(ctx, |ui| {
                    egui::Frame::popup(ui.style()).show(ui, |ui| {
                        ui.horizontal(|ui| {
                            ui.spinner();
                            ui.heading(label);
                        });
                        ui.label("The page may pause while the mesh is read and drawn.");
                    });
                });
        }
        if ctx.input(|i| i.raw.hovered_files.is_empty()) {
            return;
        }
        let painter = ctx.layer_painter(egui::LayerId::new(
            egui::Order::Foreground,
            egui::Id::unique("drop_hint"),
        ));
        let rect = ctx.content_rect();
        let visuals = ctx.global_style().visuals.clone();
        // Panels have no fill of their own (see `theme::backdrop`).
        let backdrop = edgewise_pictures::palette::Palette::new(visuals.dark_mode).background;
        painter.rect_filled(rect, 0.0, backdrop.gamma_multiply(0.9));
        painter.rect_stroke(
            rect.shrink(12.0),
            12.0,
            egui::Stroke::new(3.0, visuals.selection.stroke.color),
            egui::StrokeKind::Inside,
        );
        painter.text(
            rect.center(),
            egui::Align2::CENTER_CENTER,
            format!("Drop a {OPEN_EXTENSIONS} file to open it"),
            egui::FontId::proportional(28.0),
            visuals.strong_text_color(),
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn save_formats_round_trip_their_keys() {
        for format in SaveFormat::ALL {
            assert_eq!(SaveFormat::parse(format.key()), Some(format));
        }
        assert_eq!(SaveFormat::parse("stl"), None);
    }
}
