//! The top-level eframe application: a mesh document, the 3D view, the
//! tables, and the commands the JavaScript API and the UI share.

use egui_extras::{Size, StripBuilder};

use edgewise_core::{
    formats::{self, Format, SaveOptions},
    mesh::{Mesh, Structure, generate},
};

use crate::{
    GraphicsBackend,
    document::Document,
    files::FileState,
    obj_editor::{EDITOR_FILE, ObjEditor},
    samples::{self, SampleData},
    selection::{self, ElementKind, ElementRef, Role},
    state::{AppState, Counts, DialogState, HighlightState},
    tables::{self, TablesResponse},
    theme::Theme,
    view3d::{DrawIds, ElementStyle, MeshGeometry, Pick, SceneStyles, View3d, ViewOptions},
};

/// The Edgewise application.
pub struct EdgewiseApp {
    backend: GraphicsBackend,
    frames: u64,
    theme: Theme,
    pub(crate) document: Option<Document>,
    /// The last failed load or command, shown until dismissed.
    error: Option<String>,
    view: View3d,
    view_options: ViewOptions,
    styles: SceneStyles,
    /// The document generation `styles` were derived from.
    styles_generation: Option<u64>,
    /// The structure new PLY and OBJ loads are built into.
    pub(crate) structure: Structure,
    obj_editor: ObjEditor,
    show_obj_editor: bool,
    /// The element under the pointer in the 3D view, for the message line.
    hovered: Option<Pick>,
    /// Kept so commands from JavaScript can ask for a new frame.
    ctx: Option<egui::Context>,
    /// Opening and saving files (see `files.rs`).
    pub(crate) files: FileState,
}

impl EdgewiseApp {
    /// Creates the app from eframe's creation context.
    pub fn new(cc: &eframe::CreationContext<'_>) -> Self {
        let mut app = Self::with_backend(
            GraphicsBackend::from_render_state(cc.wgpu_render_state.as_ref()),
            cc.wgpu_render_state.as_ref(),
        );
        app.theme.apply(&cc.egui_ctx);
        app.ctx = Some(cc.egui_ctx.clone());
        app
    }

    /// Creates the app for a known backend; UI tests pass no render state.
    pub fn with_backend(
        backend: GraphicsBackend,
        render_state: Option<&eframe::egui_wgpu::RenderState>,
    ) -> Self {
        Self {
            backend,
            frames: 0,
            theme: Theme::light(),
            document: None,
            error: None,
            view: View3d::new(render_state),
            view_options: ViewOptions::default(),
            styles: SceneStyles::default(),
            styles_generation: None,
            structure: Structure::WingedEdge,
            obj_editor: ObjEditor::default(),
            show_obj_editor: false,
            hovered: None,
            ctx: None,
            files: FileState::default(),
        }
    }

    /// The graphics backend in use.
    pub fn backend(&self) -> GraphicsBackend {
        self.backend
    }

    /// Loads mesh text or bytes; `name` gives the format by its extension
    /// (or the content does). On failure the current mesh stays and the
    /// message is kept in `state().error`.
    pub fn load_mesh(
        &mut self,
        bytes: &[u8],
        name: &str,
        structure: Option<Structure>,
    ) -> Result<(), String> {
        let structure = structure.unwrap_or_else(|| self.default_structure_for(name));
        let loaded = Document::load(bytes, name, structure);
        self.open(loaded, true)
    }

    /// Opens a built-in sample by name (a file stem in meshes/).
    pub fn load_sample(&mut self, name: &str, structure: Option<Structure>) -> Result<(), String> {
        let Some(sample) = samples::find(name) else {
            let names: Vec<&str> = samples::SAMPLES.iter().map(|s| s.name).collect();
            return Err(self.fail(format!(
                "there is no sample called '{name}'; the samples are: {}",
                names.join(", ")
            )));
        };
        let structure = match &sample.data {
            SampleData::File { file_name, .. } => {
                structure.unwrap_or_else(|| self.default_structure_for(file_name))
            }
            SampleData::Torus { .. } => structure.unwrap_or(self.structure),
        };
        let loaded = match &sample.data {
            SampleData::File { file_name, bytes } => Document::load(bytes, file_name, structure),
            SampleData::Torus { nu, nv } => {
                Document::from_polygons(sample.name, &generate::torus(*nu, *nv), structure)
            }
        };
        self.open(loaded, true)
    }

    /// A table file opens as the structure it stores; PLY and OBJ as the
    /// structure currently chosen in the top bar.
    fn default_structure_for(&self, name: &str) -> Structure {
        Format::from_name(name)
            .and_then(Format::native_structure)
            .unwrap_or(self.structure)
    }

    /// Shows a newly loaded document, or keeps the current one and reports why not.
    /// `frame` points the camera at the new mesh; the OBJ editor keeps the
    /// student's view while they type.
    fn open(&mut self, loaded: Result<Document, String>, frame: bool) -> Result<(), String> {
        match loaded {
            Ok(document) => {
                self.structure = document.structure();
                self.view
                    .set_geometry(MeshGeometry::from_mesh(document.mesh()), frame);
                self.document = Some(document);
                self.styles_generation = None;
                self.error = None;
                Ok(())
            }
            Err(message) => Err(self.fail(message)),
        }
    }

    /// Selects an element by kind and id, or clears with `None`.
    pub fn select(&mut self, element: Option<ElementRef>) -> Result<(), String> {
        let Some(document) = &mut self.document else {
            return match element {
                Some(_) => Err(self.fail("no mesh is open".to_owned())),
                None => Ok(()),
            };
        };
        document
            .select(element)
            .map_err(|message| self.fail(message))
    }

    /// Converts the open mesh to the other structure, keeping the selection.
    pub fn switch_structure(&mut self, structure: Structure) -> Result<(), String> {
        self.structure = structure;
        let Some(document) = &mut self.document else {
            return Ok(());
        };
        match document.switch_structure(structure) {
            Ok(()) => {
                self.view
                    .set_geometry(MeshGeometry::from_mesh(document.mesh()), false);
                self.styles_generation = None;
                Ok(())
            }
            Err(message) => Err(self.fail(message)),
        }
    }

    /// Asks for a new frame after a command changed what is shown.
    pub fn request_repaint(&self) {
        if let Some(ctx) = &self.ctx {
            ctx.request_repaint();
        }
    }

    /// Opens or closes the OBJ editor; opening it writes the open mesh as OBJ
    /// so a sample can be edited.
    fn toggle_obj_editor(&mut self) {
        self.show_obj_editor = !self.show_obj_editor;
        if self.show_obj_editor
            && self.obj_editor.text.is_empty()
            && let Some(document) = &self.document
            && let Ok(bytes) = formats::save(document.mesh(), Format::Obj, &SaveOptions::default())
        {
            self.obj_editor
                .set_text(String::from_utf8_lossy(&bytes).into_owned());
        }
    }

    fn obj_editor_ui(&mut self, ui: &mut egui::Ui) {
        ui.strong("OBJ");
        ui.weak("Edit the text: the mesh and its tables follow.");
        if let Some(text) = self.obj_editor.ui(ui) {
            let loaded = Document::parse(text.as_bytes(), EDITOR_FILE, self.structure);
            self.obj_editor.set_error(loaded.as_ref().err());
            let first = self.document.is_none();
            let loaded = loaded.map_err(|err| err.render(EDITOR_FILE).trim_end().to_owned());
            // The editor marks its own problems; the view keeps the last good mesh.
            if self.open(loaded, first).is_err() {
                self.error = None;
            }
        }
    }

    /// Half-edge walking from the keyboard: n successor, p predecessor,
    /// t pair (twin), f face, v end vertex.
    fn keyboard_walk(&mut self, ctx: &egui::Context) {
        if ctx.egui_wants_keyboard_input() {
            return;
        }
        let Some(document) = &self.document else {
            return;
        };
        if !matches!(document.mesh(), Mesh::Half(_)) {
            return;
        }
        let role = ctx.input(|i| {
            [
                (egui::Key::N, Role::SuccessorEdge),
                (egui::Key::P, Role::PredecessorEdge),
                (egui::Key::T, Role::PairEdge),
                (egui::Key::F, Role::Face),
                (egui::Key::V, Role::EndVertex),
            ]
            .into_iter()
            .find(|(key, _)| i.key_pressed(*key))
            .map(|(_, role)| role)
        });
        let target = role.and_then(|role| {
            document
                .highlights()
                .iter()
                .find(|h| h.role == role)
                .map(|h| h.element)
        });
        if let Some(target) = target {
            self.select(Some(target)).ok();
        }
    }

    /// Records a failure for the error panel and `state().error`.
    pub(crate) fn fail(&mut self, message: String) -> String {
        self.error = Some(message.clone());
        message
    }

    /// A snapshot of the observable state.
    pub fn state(&self) -> AppState {
        let doc = self.document.as_ref();
        let counts = doc.map_or_else(Counts::default, |d| counts(d.mesh()));
        AppState {
            version: edgewise_core::VERSION,
            backend: self.backend.as_str(),
            frames: self.frames,
            mesh: doc.map(|d| d.name.clone()),
            structure: doc.map(|d| structure_name(d.structure())),
            counts,
            selection: doc.and_then(Document::selection),
            highlights: doc
                .map(|d| {
                    d.highlights()
                        .iter()
                        .map(|h| HighlightState {
                            kind: h.element.kind,
                            id: h.element.id,
                            role: h.role.key(),
                        })
                        .collect()
                })
                .unwrap_or_default(),
            error: self.error.clone(),
            diagnostics: self.obj_editor.diagnostics.clone(),
            dialog: self
                .structure_dialog()
                .map(|(file, structure)| DialogState {
                    kind: "structure",
                    file: file.to_owned(),
                    structure: structure_name(structure),
                }),
        }
    }

    /// Re-derives colours and labels when the selection changed.
    fn refresh_styles(&mut self) {
        let Some(document) = &self.document else {
            return;
        };
        if self.styles_generation == Some(document.generation()) {
            return;
        }
        let mesh = document.mesh();
        let mut styles = SceneStyles {
            generation: self.styles.generation + 1,
            vertices: vec![ElementStyle::default(); mesh.vertex_count()],
            edges: vec![ElementStyle::default(); mesh.edge_row_count()],
            faces: vec![ElementStyle::default(); mesh.face_count()],
            pointers: Vec::new(),
        };
        let highlights = document.highlights();
        let any = !highlights.is_empty();
        for list in [&mut styles.vertices, &mut styles.edges, &mut styles.faces] {
            for style in list.iter_mut() {
                style.faded = any;
            }
        }
        // Later roles must not repaint the selected element: go in reverse.
        for h in highlights.iter().rev() {
            let list = match h.element.kind {
                ElementKind::Vertex => &mut styles.vertices,
                ElementKind::Edge => &mut styles.edges,
                ElementKind::Face => &mut styles.faces,
            };
            if let Some(style) = list.get_mut(h.element.id as usize) {
                style.colour = Some(self.theme.role_colour(h.role));
                style.faded = false;
                style.label = selection::role_label(highlights, h.element);
            }
        }
        self.styles = styles;
        self.styles_generation = Some(document.generation());
    }

    fn top_bar_ui(&mut self, ui: &mut egui::Ui) {
        ui.horizontal(|ui| {
            ui.heading("Edgewise");
            ui.separator();
            self.files_menu_ui(ui);
            let mut chosen = None;
            ui.menu_button("Samples", |ui| {
                for sample in samples::SAMPLES {
                    if ui.button(sample.name).clicked() {
                        chosen = Some(sample.name);
                    }
                }
            });
            if let Some(name) = chosen {
                self.load_sample(name, None).ok();
            }
            ui.separator();
            let mut structure = self.structure;
            ui.selectable_value(&mut structure, Structure::WingedEdge, "Winged-edge");
            ui.selectable_value(&mut structure, Structure::HalfEdge, "Half-edge");
            if structure != self.structure {
                self.switch_structure(structure).ok();
            }
            ui.separator();
            if ui
                .selectable_label(self.show_obj_editor, "OBJ editor")
                .on_hover_text("Type or paste OBJ text; the mesh and tables follow as you type")
                .clicked()
            {
                self.toggle_obj_editor();
            }
            self.view_options_menu_ui(ui);
            let theme_label = if self.theme.dark {
                "Light theme"
            } else {
                "Dark theme"
            };
            if ui.button(theme_label).clicked() {
                self.theme = if self.theme.dark {
                    Theme::light()
                } else {
                    Theme::dark()
                };
                self.theme.apply(ui.ctx());
                self.styles_generation = None;
            }
            ui.separator();
            if let Some(doc) = &self.document {
                let mesh = doc.mesh();
                ui.label(format!(
                    "{}: {} vertices, {} edges, {} faces",
                    doc.name,
                    mesh.vertex_count(),
                    mesh.edge_count(),
                    mesh.face_count()
                ));
            }
        });
    }

    fn view_options_menu_ui(&mut self, ui: &mut egui::Ui) {
        ui.menu_button("View", |ui| {
            let options = &mut self.view_options;
            ui.label("Draw ids");
            ui.horizontal(|ui| {
                ui.selectable_value(&mut options.draw_ids, DrawIds::Highlighted, "Highlighted");
                ui.selectable_value(&mut options.draw_ids, DrawIds::Always, "Always");
                ui.selectable_value(&mut options.draw_ids, DrawIds::Never, "Never");
            });
            ui.add(egui::Slider::new(&mut options.mesh_scale, 0.25..=4.0).text("Mesh scale"));
            ui.add(egui::Slider::new(&mut options.label_scale, 0.5..=3.0).text("Label scale"));
            ui.checkbox(&mut options.show_axes, "Axes");
            ui.checkbox(&mut options.show_orientation, "Face orientation");
            ui.checkbox(&mut options.solid_faces, "Solid faces");
            if ui.button("Frame the mesh").clicked() {
                self.view.frame_all();
            }
        });
    }

    /// The message line along the bottom of the 3D view: what is under the
    /// pointer or selected, or what the loader noticed.
    fn message_line_ui(&self, ui: &mut egui::Ui, hovered: Option<Pick>) {
        let Some(document) = &self.document else {
            return;
        };
        let text = if let Some(pick) = hovered {
            let e = element_of(pick);
            format!("{} {}: click to select", e.kind.title(), e.id)
        } else if let Some(first) = document.highlights().first() {
            let refs: Vec<String> = document.highlights()[1..]
                .iter()
                .map(|h| format!("{} {}", h.role.key(), h.element.id))
                .collect();
            format!(
                "{} {} selected: {}",
                first.element.kind.title(),
                first.element.id,
                refs.join(", ")
            )
        } else if let Some(warning) = document.warnings.first() {
            format!("Note: {warning}")
        } else {
            "Click a vertex, edge or face, here or in the tables.".to_owned()
        };
        ui.add(egui::Label::new(egui::RichText::new(text).weak()).truncate());
    }

    fn error_ui(&mut self, ui: &mut egui::Ui) {
        let Some(error) = &self.error else {
            return;
        };
        let mut dismiss = false;
        egui::Frame::new()
            .fill(ui.visuals().error_fg_color.gamma_multiply(0.12))
            .inner_margin(8.0)
            .show(ui, |ui| {
                ui.horizontal_wrapped(|ui| {
                    ui.colored_label(ui.visuals().error_fg_color, error.as_str());
                    dismiss = ui.button("Dismiss").clicked();
                });
            });
        if dismiss {
            self.error = None;
        }
    }

    /// The face, edge and vertex tables side by side; the panel's top edge
    /// moves the split between them and the 3D view.
    fn tables_ui(&mut self, ui: &mut egui::Ui) {
        let Some(document) = &self.document else {
            ui.weak("Open a mesh to see its tables.");
            // Keep the panel's size for when a mesh arrives.
            ui.allocate_space(ui.available_size());
            return;
        };
        let mut response = TablesResponse::default();
        let mut table = |ui: &mut egui::Ui, kind: ElementKind, title: &str| {
            ui.strong(title);
            tables::table_ui(
                ui,
                document.mesh(),
                kind,
                document.highlights(),
                &self.theme,
                &mut response,
            );
        };
        let edge_title = match document.mesh() {
            Mesh::Winged(_) => "Edges",
            Mesh::Half(_) => "Half-edges",
        };
        StripBuilder::new(ui)
            .size(Size::relative(0.17).at_least(150.0))
            .size(Size::remainder().at_least(300.0))
            .size(Size::relative(0.28).at_least(220.0))
            .horizontal(|mut strip| {
                strip.cell(|ui| table(ui, ElementKind::Face, "Faces"));
                strip.cell(|ui| table(ui, ElementKind::Edge, edge_title));
                strip.cell(|ui| table(ui, ElementKind::Vertex, "Vertices"));
            });
        if let Some(clicked) = response.clicked {
            self.select(Some(clicked)).ok();
        }
    }

    fn view_ui(&mut self, ui: &mut egui::Ui) {
        if self.document.is_none() {
            ui.centered_and_justified(|ui| {
                ui.weak("Open a mesh, pick a sample, or paste OBJ text.");
            });
            return;
        }
        self.refresh_styles();
        self.view_options.dark = self.theme.dark;
        let rect = ui.available_rect_before_wrap();
        let line_height = ui.text_style_height(&egui::TextStyle::Body) + 8.0;
        let (view_rect, line_rect) =
            rect.split_top_bottom_at_y((rect.bottom() - line_height).max(rect.top()));
        let hovered = self.hovered;
        ui.scope_builder(egui::UiBuilder::new().max_rect(line_rect), |ui| {
            self.message_line_ui(ui, hovered);
        });
        let response = ui
            .scope_builder(egui::UiBuilder::new().max_rect(view_rect), |ui| {
                self.view.ui(ui, &self.styles, &self.view_options)
            })
            .inner;
        self.hovered = response.hovered;
        if let Some(pick) = response.clicked {
            self.select(Some(element_of(pick))).ok();
        } else if response.background_clicked {
            self.select(None).ok();
        }
    }
}

impl eframe::App for EdgewiseApp {
    fn ui(&mut self, ui: &mut egui::Ui, _frame: &mut eframe::Frame) {
        self.frames += 1;
        self.receive_files(ui.ctx());
        egui::Panel::top("top_bar").show(ui, |ui| self.top_bar_ui(ui));
        self.keyboard_walk(ui.ctx());
        if self.show_obj_editor {
            egui::Panel::right("obj_editor")
                .resizable(true)
                .default_size(320.0)
                .show(ui, |ui| self.obj_editor_ui(ui));
        }
        egui::Panel::bottom("tables")
            .resizable(true)
            .default_size(260.0)
            .min_size(120.0)
            .show(ui, |ui| self.tables_ui(ui));
        egui::CentralPanel::default().show(ui, |ui| {
            self.error_ui(ui);
            self.view_ui(ui);
        });
        self.files_overlay_ui(ui.ctx());
    }

    #[cfg(target_arch = "wasm32")]
    fn as_any_mut(&mut self) -> Option<&mut dyn std::any::Any> {
        Some(&mut *self)
    }
}

fn element_of(pick: Pick) -> ElementRef {
    match pick {
        Pick::Vertex(id) => ElementRef {
            kind: ElementKind::Vertex,
            id,
        },
        Pick::Edge(id) => ElementRef {
            kind: ElementKind::Edge,
            id,
        },
        Pick::Face(id) => ElementRef {
            kind: ElementKind::Face,
            id,
        },
    }
}

fn counts(mesh: &Mesh) -> Counts {
    Counts {
        vertices: mesh.vertex_count(),
        edges: mesh.edge_count(),
        faces: mesh.face_count(),
        halfedges: mesh.edge_count() * 2,
    }
}

/// The JavaScript API's structure names.
pub fn structure_name(structure: Structure) -> &'static str {
    match structure {
        Structure::WingedEdge => "winged",
        Structure::HalfEdge => "half",
    }
}

/// Parses the JavaScript API's structure names.
pub fn parse_structure(name: &str) -> Option<Structure> {
    match name {
        "winged" | "winged-edge" | "wtb" => Some(Structure::WingedEdge),
        "half" | "half-edge" | "htb" => Some(Structure::HalfEdge),
        _ => None,
    }
}
