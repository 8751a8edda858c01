//! The top-level eframe application: a mesh document, the 3D view, the
//! tables, and the commands the JavaScript API and the UI share.

use crate::command::{Command, CommandError};
use edgewise_core::schema::{Column, ElementKind, ElementRef};
use edit_menu::EditMenu;
use egui_extras::{Size, StripBuilder};

use edgewise_core::{
    formats::{self, Format, SaveOptions},
    mesh::{Mesh, Structure},
};

use crate::{
    GraphicsBackend,
    algorithm::Algorithms,
    files::FileState,
    obj_editor::{EDITOR_FILE, MAX_EDITOR_BYTES},
    state::{
        AppState, BrokenState, Counts, DialogState, HighlightState, PendingState, StatsState,
        TraceState,
    },
    tables::{self, TablesResponse},
};
use edgewise_model::{
    algorithm::session::Run, document::Document, message, moment, paint::Paint, practice::Session,
    samples, selection::Role, settings::Settings, theme::Theme,
};
use edgewise_pictures::options::{DrawIds, ViewOptions};
use edgewise_renderer::ui_cache::{PartTextures, UiCache};

pub mod algorithm_ui;
pub mod course;
pub(crate) mod edit_menu;
mod edit_ui;
pub(crate) mod element_box;
pub mod embed;
pub mod embed_events;
pub mod execute;
pub mod files;
pub mod first_visit;
mod focus_ring;
mod open_dialog;
mod package;
mod pane;
mod pending;
mod pictures;
pub(crate) mod practice;
mod readers;
mod screen;
pub mod settings_ui;
mod statistics;
pub(crate) mod tabs;
mod twin;

/// What the algorithm panel shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum AlgorithmTab {
    /// The algorithm view: choose, pick inputs, step.
    Run,
    /// The editor for new algorithms.
    Write,
}

/// The Edgewise application.
pub struct EdgewiseApp {
    backend: GraphicsBackend,
    frames: u64,
    /// Milliseconds the previous frame took on the main thread (its UI and
    /// its rendering commands), from eframe.
    frame_cpu_ms: Option<f32>,
    /// egui's time at the last frame, in seconds: when a command starts
    /// playing, the next automatic step is due a delay after it.
    clock: f64,
    theme: Theme,
    /// Every open mesh; never empty. Commands and drawing act on
    /// `tabs[active_tab]`.
    tabs: Vec<tabs::Tab>,
    active_tab: usize,
    view_options: ViewOptions,
    /// The algorithm library, the run and its trace.
    pub(crate) algorithms: Algorithms,
    show_algorithm_panel: bool,
    algorithm_tab: AlgorithmTab,
    fonts_installed: bool,
    settings: Settings,
    show_settings: bool,
    show_statistics: bool,
    /// The first-visit hint, while shown.
    tour: Option<first_visit::Tour>,
    /// "What am I looking at?" is shown (and has been for a frame).
    explaining: bool,
    explain_shown_once: bool,
    /// This frame's panels, for "What am I looking at?".
    screen_parts: Vec<first_visit::Part>,
    /// Where the parts were drawn in the last frame, for `state().layout`.
    layout: crate::state::LayoutState,
    /// What the screen readers' copy was last built for.
    reader_copy: readers::ReaderCopy,
    embed_observed: embed_events::Observed,
    /// Height of the panels above and below the view this frame, for the
    /// height an embedding page is asked for.
    chrome_height: f32,
    embed_events: Vec<crate::EmbedEvent>,
    /// What is typed in the message line's element box.
    element_box: String,
    /// Where the screenshot `exportImage('png')` asked for arrives.
    screenshot: Option<pictures::ScreenshotSlot>,
    /// The theme key last applied to egui's visuals.
    applied_theme: Option<u64>,
    presentation: Option<settings_ui::Presentation>,
    /// The panels the Present menu offers, as last chosen.
    presentation_choice: settings_ui::Presentation,
    zoom_before_presenting: f32,
    /// For making more views (tabs, side by side); None in headless tests.
    render_state: Option<eframe::egui_wgpu::RenderState>,
    side_by_side: bool,
    /// Embedded in an iframe (`?embed=1`): no menu bar.
    embed: Option<embed::Embed>,
    show_share: bool,
    share_status: Option<String>,
    /// What the last SCORM package download came to, once it has (it is
    /// built asynchronously in the browser).
    package_status: std::rc::Rc<std::cell::RefCell<Option<String>>>,
    /// Whether "Copy embed code" includes the tables.
    share_embed_tables: bool,
    show_obj_editor: bool,
    /// Kept so commands from JavaScript can ask for a new frame.
    ctx: Option<egui::Context>,
    /// Opening and saving files (see `files.rs`).
    pub(crate) files: FileState,
    /// How meshes prepared a slice per frame ended (see `pending.rs`).
    jobs: pending::JobLog,
    focus_ring: focus_ring::FocusRing,
    ui_cache: UiCache,
    /// The small-screen sheet's tab in front.
    sheet: screen::Sheet,
    /// The table shown when only one fits, as last chosen.
    narrow_table: Option<ElementKind>,
    /// Controls sized for a pointer or a finger.
    sizing: screen::Sizing,
}

impl EdgewiseApp {
    /// Creates the app from eframe's creation context.
    pub fn new(cc: &eframe::CreationContext<'_>) -> Self {
        let mut app = Self::with_backend(
            GraphicsBackend::from_render_state(cc.wgpu_render_state.as_ref()),
            cc.wgpu_render_state.as_ref(),
        );
        app.ctx = Some(cc.egui_ctx.clone());
        let (settings, message) = crate::stored_settings::load_stored();
        app.set_settings(settings);
        if let Some(message) = message {
            app.report(message);
        }
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
            frame_cpu_ms: None,
            clock: 0.0,
            theme: Theme::light(),
            tabs: vec![tabs::Tab::new(
                render_state,
                edgewise_model::document::FIRST_STRUCTURE,
            )],
            active_tab: 0,
            // The frame is cleared to the view's background (`clear_color`).
            view_options: ViewOptions {
                backdrop_cleared: true,
                ..ViewOptions::default()
            },
            algorithms: Algorithms::default(),
            show_algorithm_panel: false,
            algorithm_tab: AlgorithmTab::Run,
            fonts_installed: false,
            settings: Settings::default(),
            show_settings: false,
            show_statistics: false,
            tour: None,
            explaining: false,
            explain_shown_once: false,
            screen_parts: Vec::new(),
            layout: crate::state::LayoutState::default(),
            reader_copy: readers::ReaderCopy::default(),
            embed_observed: embed_events::Observed::default(),
            chrome_height: 0.0,
            embed_events: Vec::new(),
            element_box: String::new(),
            screenshot: None,
            applied_theme: None,
            presentation: None,
            presentation_choice: settings_ui::Presentation::default(),
            zoom_before_presenting: 1.0,
            render_state: render_state
                .inspect(|rs| PartTextures::install(rs))
                .cloned(),
            side_by_side: false,
            embed: None,
            show_share: false,
            share_status: None,
            package_status: std::rc::Rc::default(),
            share_embed_tables: false,
            show_obj_editor: false,
            ctx: None,
            files: FileState::default(),
            jobs: pending::JobLog::default(),
            focus_ring: focus_ring::FocusRing::default(),
            ui_cache: UiCache::default(),
            sheet: screen::Sheet::default(),
            narrow_table: None,
            sizing: screen::Sizing::default(),
        }
    }

    /// The graphics backend in use.
    pub fn backend(&self) -> GraphicsBackend {
        self.backend
    }

    /// [`Command::LoadMesh`]: `name` gives the format by its extension (or
    /// the content does); on failure the current mesh stays.
    pub(crate) fn open_bytes(
        &mut self,
        bytes: &[u8],
        name: &str,
        structure: Option<Structure>,
        diagnose: bool,
    ) -> Result<(), CommandError> {
        let structure = structure.unwrap_or_else(|| self.default_structure_for(name));
        if diagnose {
            let loaded = Document::load_for_diagnosis(bytes, name, structure);
            return self.open(loaded, true, false);
        }
        let loaded = Document::load(bytes, name, structure);
        // A table file refused for broken records can be opened to fix.
        let diagnosable = loaded.is_err()
            && Document::load_for_diagnosis(bytes, name, structure)
                .is_ok_and(|document| !document.mesh().validate().is_empty());
        let result = self.open(loaded, true, false);
        if diagnosable {
            self.tab_mut().diagnosable = Some((name.to_owned(), bytes.to_vec()));
        }
        result
    }

    /// [`Command::DiagnoseRefused`].
    fn diagnose_refused(&mut self) -> Result<(), CommandError> {
        let (name, bytes) = self
            .tab_mut()
            .diagnosable
            .take()
            .ok_or("no refused table file to open for diagnosis")?;
        self.open_bytes(&bytes, &name, None, true)
    }

    /// [`Command::LoadSample`].
    fn open_sample(
        &mut self,
        name: &str,
        structure: Option<Structure>,
    ) -> Result<(), CommandError> {
        let fallback = self.tab().structure;
        let loaded = samples::open(name, structure, fallback);
        self.open(loaded, true, false)
    }

    /// A table file opens as the structure it stores; PLY and OBJ as the
    /// structure currently chosen in the top bar.
    fn default_structure_for(&self, name: &str) -> Structure {
        edgewise_model::document::structure_for(name, self.tab().structure)
    }

    /// Shows a newly loaded document, undoably, or keeps the current one
    /// and reports why not. `frame` points the camera at the new mesh; the
    /// OBJ editor keeps the student's view while they type, and `merge`s
    /// its keystrokes into one undo step. A document whose tables break the
    /// rules (opened for diagnosis) starts diagnosis mode.
    fn open(
        &mut self,
        loaded: Result<Document, String>,
        frame: bool,
        merge: bool,
    ) -> Result<(), CommandError> {
        let document = loaded?;
        let label = format!("Opening {}", document.name);
        self.show_document(document, pending::Commit::Open { frame, merge }, label);
        Ok(())
    }

    /// [`Command::Select`].
    fn set_selection(&mut self, element: Option<ElementRef>) -> Result<(), CommandError> {
        if element.is_some() {
            self.tab_mut().set_last_changes(Vec::new());
        }
        let Some(document) = &mut self.tab_mut().document else {
            return match element {
                Some(_) => Err("no mesh is open".into()),
                None => Ok(()),
            };
        };
        document.select(element).map_err(CommandError::from)
    }

    /// [`Command::SetStructure`]: converts the open mesh, keeping the
    /// selection.
    fn convert_to(&mut self, structure: Structure) -> Result<(), CommandError> {
        let tab = &mut self.tabs[self.active_tab];
        let Some(document) = &tab.document else {
            tab.structure = structure;
            return Ok(());
        };
        if document.structure() == structure {
            tab.structure = structure;
            return Ok(());
        }
        let mut converted = document.clone();
        converted.switch_structure(structure)?;
        let label = format!("Converting {} to {}", converted.name, structure.prose());
        let commit = pending::Commit::Convert {
            mesh_id: document.mesh_id(),
        };
        self.show_document(converted, commit, label);
        Ok(())
    }

    /// Asks for a new frame after a command changed what is shown.
    pub fn request_repaint(&self) {
        if let Some(ctx) = &self.ctx {
            ctx.request_repaint();
        }
    }

    /// Whether the view shows all it will show without new input: no frame
    /// asked for, now or later, and no mesh being read or shown in slices.
    /// What `settled()` waits for, so that a page or a test can read the
    /// view at rest without guessing how long its frames take.
    pub fn settled(&self) -> bool {
        self.ctx
            .as_ref()
            .is_none_or(|ctx| !ctx.has_requested_repaint())
            && self.tab().pending.is_none()
            && self.files.opening.is_none()
            && self.files.busy.is_none()
    }

    /// Frames drawn so far (`state().frames`).
    pub fn frame_count(&self) -> u64 {
        self.frames
    }

    /// What asked for the frames still to come, for the message of a
    /// view that does not settle.
    pub fn repaint_causes(&self) -> String {
        let causes = self.ctx.as_ref().map(egui::Context::repaint_causes);
        let mut names: Vec<String> = causes
            .into_iter()
            .flatten()
            .map(|cause| cause.to_string().trim_end().to_owned())
            .collect();
        names.sort_unstable();
        names.dedup();
        if names.is_empty() {
            "a mesh being opened or shown".to_owned()
        } else {
            names.join(", ")
        }
    }

    /// Opens or closes the OBJ editor; opening it writes the open mesh as OBJ
    /// so a sample can be edited.
    fn toggle_obj_editor(&mut self) {
        self.show_obj_editor = !self.show_obj_editor;
        if self.show_obj_editor
            && self.tab().obj_editor.text.is_empty()
            && let Some(document) = &self.tab().document
            && let Ok(bytes) = formats::save(document.mesh(), Format::Obj, &SaveOptions::default())
        {
            if bytes.len() > MAX_EDITOR_BYTES {
                self.tab_mut().obj_editor.refused = Some(format!(
                    "{} is {} bytes as OBJ, too large to edit here: this editor holds at most \
                     {MAX_EDITOR_BYTES} bytes",
                    document.name,
                    bytes.len()
                ));
            } else {
                self.tab_mut()
                    .obj_editor
                    .set_text(String::from_utf8_lossy(&bytes).into_owned());
            }
        }
    }

    fn obj_editor_ui(&mut self, ui: &mut egui::Ui) {
        ui.strong("OBJ");
        ui.weak("Edit the text: the mesh and its tables follow.");
        if let Some(edited) = self.tab_mut().obj_editor.ui(ui) {
            let text = edited.text;
            let loaded = Document::parse(text.as_bytes(), EDITOR_FILE, self.tab_mut().structure);
            self.tab_mut().obj_editor.set_error(loaded.as_ref().err());
            // Typing keeps the student's view; a pasted mesh is framed.
            let frame = self.tab().document.is_none() || edited.pasted;
            let loaded = loaded.map_err(|err| err.render(EDITOR_FILE).trim_end().to_owned());
            // The editor marks its own problems; the view keeps the last good mesh.
            let _marked_in_the_editor = self.open(loaded, frame, true);
        }
    }

    /// Walking from the keyboard while no widget has focus: ↑ and ↓ move
    /// the selection along its table (from edge 0 when nothing is
    /// selected); in a half-edge mesh, n successor, p predecessor, t pair
    /// (twin), f face, v end vertex.
    fn keyboard_walk(&mut self, ctx: &egui::Context) {
        if ctx.egui_wants_keyboard_input() {
            return;
        }
        let Some(document) = &self.tab().document else {
            return;
        };
        // Every press counts: a slow frame may gather several (a held key).
        let (up, down) = ctx.input(|i| {
            if i.modifiers.any() {
                (0, 0)
            } else {
                (
                    i.num_presses(egui::Key::ArrowUp),
                    i.num_presses(egui::Key::ArrowDown),
                )
            }
        });
        if up != down && !self.tab().run.is_active() {
            let selected = document.selection();
            let mut next = selected;
            for _ in 0..up.abs_diff(down) {
                match table_neighbour(document.mesh(), next, down > up) {
                    Some(row) => next = Some(row),
                    None => break,
                }
            }
            if next != selected {
                self.issue(Command::Select(next));
            }
            return;
        }
        if !matches!(document.mesh(), Mesh::Half(_)) {
            return;
        }
        let role = ctx.input(|i| {
            [
                (egui::Key::N, Role::Column(Column::SuccessorEdge)),
                (egui::Key::P, Role::Column(Column::PredecessorEdge)),
                (egui::Key::T, Role::Column(Column::PairEdge)),
                (egui::Key::F, Role::Column(Column::Face)),
                (egui::Key::V, Role::Column(Column::EndVertex)),
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
            self.issue(Command::Select(Some(target)));
        }
    }

    /// Where the keyboard focus ring was drawn in the last frame: only
    /// after Tab moved focus, until the next pointer press.
    pub fn focus_ring(&self) -> Option<egui::Rect> {
        self.focus_ring.drawn()
    }

    /// Records a failure for the error panel and `state().error`: what
    /// [`Self::execute`] does with a refused command, and what happens to
    /// failures that come from no command (a settings file, a dropped file
    /// that cannot be read).
    pub(crate) fn report(&mut self, message: String) {
        self.tab_mut().error = Some(message);
    }

    /// A snapshot of the observable state.
    /// The active tab's mesh as it is shown (mid-edit during an editing
    /// trace), or `None` before any mesh is open.
    pub fn mesh(&self) -> Option<&Mesh> {
        self.tab().document.as_ref().map(Document::mesh)
    }

    pub fn state(&self) -> AppState {
        let doc = self.tab().document.as_ref();
        let counts = doc.map_or_else(Counts::default, |d| counts(d.mesh()));
        // The frame derives the paint too; deriving it here lets commands
        // from JavaScript read their effect before the next frame.
        let paint = self.current_paint();
        AppState {
            version: edgewise_core::VERSION,
            backend: self.backend.as_str(),
            frames: self.frames,
            frame_cpu_ms: self.frame_cpu_ms,
            mesh: doc.map(|d| d.name.clone()),
            structure: doc.map(|d| d.structure().link_name()),
            counts,
            selection: doc.and_then(Document::selection),
            hovered: self.tab().hovered.or(self.tab().table_hovered),
            highlights: paint
                .painted
                .iter()
                .map(|p| HighlightState {
                    kind: p.element.kind,
                    id: p.element.id,
                    role: p.role.clone(),
                    colour: edgewise_pictures::palette::to_hex(p.colour),
                })
                .collect(),
            error: self.tab().error.clone(),
            broken: self.tab().broken().iter().map(BrokenState::new).collect(),
            broken_count: self.tab().broken_total,
            diagnosis: self.tab().diagnosis,
            exercise: self.tab().practice.as_ref().map(Session::state),
            history: self.tab().history.state(),
            renumbering: self.tab().renumbering.clone(),
            edit_menu: self.tab().edit_menu.as_ref().map(EditMenu::state),
            coarse_view: self.tab().pane.view.coarse(),
            styles_patched: self.tab().pane.view.styles_patched(),
            base_image: self.tab().pane.view.base_image_counts(),
            motion_proxy: self.tab().pane.view.motion_proxy_frames(),
            ui_cache: self.render_state.as_ref().map(|_| {
                let counts = self.ui_cache.counts();
                [counts.drawn, counts.copied]
            }),
            welcome: self.tour.as_ref().map(|tour| tour.done),
            job: self
                .tab()
                .pending
                .as_ref()
                .map(|pending| crate::state::JobState {
                    id: pending.id,
                    label: pending.label.clone(),
                    progress: pending.progress(),
                }),
            stats: self.tab().stats().as_ref().map(StatsState::new),
            trace: self.trace_state(),
            pending: self.pending_state(),
            tabs: self.tab_states(),
            side_by_side: self.side_by_side,
            twin_selection: self.twin_selection(),
            embed: self.embed.is_some(),
            layout: self.layout.clone(),
            diagnostics: self.tab().obj_editor.diagnostics.clone(),
            dialog: self
                .structure_dialog()
                .map(|(file, structure)| DialogState {
                    kind: "structure",
                    file: file.to_owned(),
                    structure: structure.link_name(),
                }),
        }
    }

    fn trace_state(&self) -> Option<TraceState> {
        let session = self.tab().run.session()?;
        let frame = self.tab().run.current_frame(&self.theme)?;
        Some(TraceState::new(session, &frame))
    }

    fn pending_state(&self) -> Option<PendingState> {
        let Run::Picking(pending) = &self.tab().run.run else {
            return None;
        };
        Some(PendingState {
            algorithm: pending.algorithm.name.clone(),
            parameter: pending.missing().map(|p| p.name.clone()),
            kind: pending.wanted_kind(),
            prompt: pending.prompt(),
        })
    }

    /// The selection's paint, or the current trace step's, with broken
    /// and deleted records marked.
    fn current_paint(&self) -> Paint {
        let tab = self.tab();
        let Some(document) = &tab.document else {
            return Paint::default();
        };
        let frame = tab.run.current_frame(&self.theme);
        let marks = moment::Marks {
            last_changes: tab.last_changes(),
            broken: tab.broken(),
        };
        moment::moment_paint(
            document,
            frame.as_deref(),
            tab.run.session().is_some(),
            marks,
            &self.theme,
        )
    }

    /// Brings the active tab's view up to date with its document: the
    /// geometry when the mesh changed, the colours and labels when the
    /// selection, the trace step, the marks or the theme did (see
    /// [`pane`]).
    fn refresh_styles(&mut self) {
        self.tab_mut().sync_edit();
        let tab = &mut self.tabs[self.active_tab];
        let Some(document) = &tab.document else {
            return;
        };
        tab.pane.follow_mesh(document);
        let Some(key) = tab.paint_key(self.theme.key()) else {
            return;
        };
        if tab.pane.styled_for(key) {
            return;
        }
        let paint = self.current_paint();
        let tab = &mut self.tabs[self.active_tab];
        let Some(document) = &tab.document else {
            return;
        };
        tab.pane.restyle(key, document.mesh(), &paint);
        tab.table_scroll = [ElementKind::Face, ElementKind::Edge, ElementKind::Vertex]
            .into_iter()
            .filter_map(|kind| {
                let focus = paint.focus(kind)?;
                (tab.paint.focus(kind) != Some(focus)).then_some((kind, focus))
            })
            .collect();
        tab.paint = paint;
    }

    /// Draws a panel's contents as a part of the UI cache: copied from a
    /// texture while they stay the same.
    fn cached_part_ui(
        &mut self,
        ui: &mut egui::Ui,
        name: &'static str,
        part_ui: impl FnOnce(&mut Self, &mut egui::Ui),
    ) {
        let mark = UiCache::begin(ui);
        part_ui(self, ui);
        self.ui_cache.end(ui, name, mark);
    }

    /// The top bar: every command, or on a small screen one menu that
    /// holds them; then what is open.
    fn top_bar_ui(&mut self, ui: &mut egui::Ui) {
        ui.horizontal(|ui| {
            if self.layout.compact {
                self.compact_menu_ui(ui);
            } else {
                ui.heading("Edgewise");
                ui.separator();
                self.commands_ui(ui);
                self.measure_bar(ui.cursor().min.x);
            }
            ui.separator();
            if let Some(doc) = &self.tab().document {
                let mesh = doc.mesh();
                let summary = format!(
                    "{}: {} vertices, {} edges, {} faces",
                    shown_name(&doc.name, mesh.structure()),
                    mesh.vertex_count(),
                    mesh.edge_count(),
                    mesh.face_count()
                );
                if ui
                    .add(
                        egui::Label::new(egui::RichText::new(summary).weak())
                            .truncate()
                            .sense(egui::Sense::click()),
                    )
                    .on_hover_text("Click for the mesh's statistics")
                    .clicked()
                {
                    self.show_statistics = true;
                }
            }
        });
    }

    /// The top bar's commands, in a row or down a menu.
    fn commands_ui(&mut self, ui: &mut egui::Ui) {
        let nested = egui::containers::menu::is_in_menu(ui);
        self.files_menu_ui(ui);
        let mut chosen = None;
        self.menu_ui(ui, "Samples", |_, ui| {
            for sample in samples::SAMPLES {
                if ui.button(sample.name).clicked() {
                    chosen = Some(sample.name);
                }
            }
        });
        if let Some(name) = chosen {
            self.issue(Command::LoadSample {
                name: name.to_owned(),
                structure: None,
            });
        }
        ui.separator();
        let mut structure = self.tab().structure;
        let winged = ui.selectable_value(&mut structure, Structure::WingedEdge, "Winged-edge");
        self.record_command("Winged-edge", &winged, nested);
        let half = ui.selectable_value(&mut structure, Structure::HalfEdge, "Half-edge");
        self.record_command("Half-edge", &half, nested);
        if structure != self.tab().structure {
            self.issue(Command::SetStructure(structure));
        }
        ui.separator();
        let editor = ui
            .selectable_label(self.show_obj_editor, "OBJ editor")
            .on_hover_text("Type or paste OBJ text; the mesh and tables follow as you type");
        self.record_command("OBJ editor", &editor, nested);
        if editor.clicked() {
            self.toggle_obj_editor();
        }
        self.algorithm_menu_ui(ui);
        self.practice_menu_ui(ui);
        self.view_options_menu_ui(ui);
        self.help_menu_ui(ui);
        let share = ui
            .add_enabled(self.tab().document.is_some(), egui::Button::new("Share…"))
            .on_hover_text("A link to this view, or code to embed it in lecture notes");
        self.record_command("Share…", &share, nested);
        if share.clicked() {
            self.show_share = true;
            ui.close();
        }
    }

    fn view_options_menu_ui(&mut self, ui: &mut egui::Ui) {
        self.menu_ui(ui, "View", Self::view_options_ui);
    }

    fn view_options_ui(&mut self, ui: &mut egui::Ui) {
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
        if ui
            .button("Statistics")
            .on_hover_text("V, E, F, V − E + F, genus, boundary loops, components and warnings")
            .clicked()
        {
            self.show_statistics = true;
        }
        if ui.button("Frame the mesh").clicked() {
            self.tab_mut().pane.view.frame_all();
        }
        let mut side_by_side = self.side_by_side;
        if ui
            .checkbox(&mut side_by_side, "Winged-edge and half-edge side by side")
            .changed()
        {
            self.issue(Command::SetSideBySide(side_by_side));
        }
        ui.separator();
        let theme_label = if self.theme.dark {
            "Light theme"
        } else {
            "Dark theme"
        };
        if ui.button(theme_label).clicked() {
            self.toggle_theme();
        }
        if ui.button("Settings…").clicked() {
            self.show_settings = true;
        }
        self.present_menu_ui(ui);
        if ui
            .button("New tab")
            .on_hover_text("Open another mesh beside this one, in a tab")
            .clicked()
        {
            self.new_tab();
        }
    }

    /// The message line along the bottom of the 3D view: what is under the
    /// pointer or selected, or what the loader noticed.
    fn message_line_ui(&self, ui: &mut egui::Ui, hovered: Option<ElementRef>) {
        if let Some(text) = self.message_text(hovered) {
            ui.add(egui::Label::new(egui::RichText::new(text).weak()).truncate());
        }
    }

    /// The message line's sentence: the algorithm's step or prompt, the
    /// element under the pointer, the selection and its references, or a
    /// hint. Screen readers hear it too (`accessible.rs`).
    fn message_text(&self, hovered: Option<ElementRef>) -> Option<String> {
        let document = self.tab().document.as_ref()?;
        Some(message::message_line(
            document,
            self.algorithm_message(),
            hovered,
        ))
    }

    fn error_ui(&mut self, ui: &mut egui::Ui) {
        let Some(error) = self.tab().error.clone() else {
            return;
        };
        let (mut dismiss, mut diagnose) = (false, false);
        egui::Frame::new()
            .fill(ui.visuals().error_fg_color.gamma_multiply(0.12))
            .inner_margin(8.0)
            .show(ui, |ui| {
                let colour = ui.visuals().error_fg_color;
                for line in error.lines() {
                    let text = egui::RichText::new(line).color(colour);
                    // A compiler message's source line and caret line up
                    // only in a monospace font, and only unwrapped.
                    let label = if is_source_diagram_line(line) {
                        egui::Label::new(text.monospace()).truncate()
                    } else {
                        egui::Label::new(text).wrap()
                    };
                    ui.add(label);
                }
                ui.horizontal(|ui| {
                    dismiss = ui.button("Dismiss").clicked();
                    if self.tab().diagnosable.is_some()
                        && ui
                            .button("Open it for diagnosis")
                            .on_hover_text(
                                "Open the tables as written, with every broken record marked, \
                                 and fix them cell by cell",
                            )
                            .clicked()
                    {
                        diagnose = true;
                    }
                });
            });
        if dismiss {
            self.tab_mut().error = None;
            self.tab_mut().diagnosable = None;
        }
        if diagnose {
            self.issue(Command::DiagnoseRefused);
        }
    }

    /// The face, edge and vertex tables side by side; the panel's top edge
    /// moves the split between them and the 3D view.
    fn tables_ui(&mut self, ui: &mut egui::Ui) {
        if self.tab().document.is_none() {
            ui.weak("Open a mesh to see its tables.");
            // Keep the panel's size for when a mesh arrives.
            ui.allocate_space(ui.available_size());
            return;
        }
        let mut response = TablesResponse::default();
        let mut chosen_table = None;
        let scroll = std::mem::take(&mut self.tab_mut().table_scroll);
        let tab = &self.tabs[self.active_tab];
        let Some(document) = &tab.document else {
            return;
        };
        let mut table = |ui: &mut egui::Ui, kind: ElementKind, title: &str| {
            let scroll_to = scroll.iter().find(|(k, _)| *k == kind).map(|&(_, id)| id);
            ui.strong(title);
            // A narrow window scrolls a wide table sideways instead of cutting it.
            let scrolled = egui::ScrollArea::horizontal()
                .id_salt(("table_scroll", kind))
                .show(ui, |ui| {
                    tables::table_ui(
                        ui,
                        document.mesh(),
                        kind,
                        &tab.paint,
                        scroll_to,
                        tab.hovered,
                        &mut response,
                    )
                });
            // Scrolled sideways, the ids stay at the table's left edge.
            if scrolled.state.clamped_offset().x > 0.0 {
                scrolled
                    .inner
                    .sticky_ui(ui, scrolled.inner_rect, &tab.paint, &mut response);
            }
        };
        let edge_title = edgewise_pictures::text_table::edge_table_title(document.mesh());
        let titles = [
            (ElementKind::Face, "Faces"),
            (ElementKind::Edge, edge_title),
            (ElementKind::Vertex, "Vertices"),
        ];
        if ui.available_width() < TABLES_SIDE_BY_SIDE {
            // Too narrow for three: one at a time, the selection's first.
            let selected = document.selection().map(|s| s.kind);
            let shown = self.narrow_table.or(selected).unwrap_or(ElementKind::Edge);
            let mut chosen = shown;
            ui.horizontal(|ui| {
                for (kind, title) in titles {
                    ui.selectable_value(&mut chosen, kind, title);
                }
            });
            if chosen != shown {
                chosen_table = Some(chosen);
            }
            let title = titles.iter().find(|(k, _)| *k == shown).map_or("", |t| t.1);
            table(ui, shown, title);
        } else {
            // Each table's share of the width is what its references need,
            // so that a narrow panel (beside a run) cuts the labels first.
            let needs = titles.map(|(kind, _)| tables::references_width(ui, document.mesh(), kind));
            // The edge table takes the remainder, which leaves out the
            // spacing between the cells: count it in the whole.
            let total: f32 = needs.iter().sum::<f32>() + 2.0 * ui.spacing().item_spacing.x;
            let [faces, _, vertices] = needs;
            StripBuilder::new(ui)
                .size(Size::relative(faces / total))
                .size(Size::remainder())
                .size(Size::relative(vertices / total))
                .horizontal(|mut strip| {
                    for (kind, title) in titles {
                        strip.cell(|ui| table(ui, kind, title));
                    }
                });
        }
        if chosen_table.is_some() {
            self.narrow_table = chosen_table;
        }
        self.tab_mut().table_hovered = response.hovered;
        if let Some(clicked) = response.clicked {
            self.element_clicked(Some(clicked));
            self.tour_progress(response.followed);
        }
        if let Some((element, at)) = response.context {
            self.open_edit_menu(element, at);
        }
        if let Some((element, column, typed)) = response.set_cell {
            let command = typed.map(|target| Command::SetCell {
                element,
                column: column.lookup_name().to_owned(),
                target,
            });
            match command {
                Ok(command) => self.issue(command),
                Err(message) => {
                    self.report(format!("{element} {}: {message}", column.record_name()));
                }
            }
        }
    }

    /// The view's options from the theme and the algorithm's inputs.
    fn sync_view_options(&mut self) {
        self.view_options.dark = self.theme.dark;
        self.view_options.boundary = self.theme.boundary_override;
        self.view_options.pickable = self.pick_filter();
    }

    fn view_ui(&mut self, ui: &mut egui::Ui) {
        if self.tab().document.is_none() {
            ui.centered_and_justified(|ui| {
                ui.weak("Open a mesh, pick a sample, or paste OBJ text.");
            });
            return;
        }
        self.refresh_styles();
        self.sync_view_options();
        let rect = ui.available_rect_before_wrap();
        // As tall as its go-to box, which is a touch target on a phone.
        let line_height =
            (ui.text_style_height(&egui::TextStyle::Body) + 8.0).max(ui.spacing().interact_size.y);
        let (view_rect, line_rect) =
            rect.split_top_bottom_at_y((rect.bottom() - line_height).max(rect.top()));
        let hovered = self.tab().hovered.or(self.tab().table_hovered);
        ui.scope_builder(egui::UiBuilder::new().max_rect(line_rect), |ui| {
            ui.with_layout(egui::Layout::right_to_left(egui::Align::Center), |ui| {
                self.element_box_ui(ui);
                ui.with_layout(egui::Layout::left_to_right(egui::Align::Center), |ui| {
                    self.message_line_ui(ui, hovered);
                });
            });
        });
        let response = ui
            .scope_builder(egui::UiBuilder::new().max_rect(view_rect), |ui| {
                let tab = &mut self.tabs[self.active_tab];
                tab.pane.view.set_preview(tab.table_hovered);
                tab.pane.ui(ui, &self.view_options)
            })
            .inner;
        self.tab_mut().hovered = response.hovered;
        if let Some(pick) = response.clicked {
            self.element_clicked(Some(pick));
        } else if response.background_clicked {
            self.element_clicked(None);
        }
        if let Some((pick, at)) = response.context {
            self.open_edit_menu(pick, at);
        }
        self.edit_keys(ui.ctx(), view_rect);
        self.edit_menu_ui(ui.ctx());
    }
}

/// Whether a line of an error belongs to a rendered source excerpt: `  |`,
/// `12 | text`, or `  = hint: …`, as `lang::render_all` writes them.
fn is_source_diagram_line(line: &str) -> bool {
    let trimmed = line.trim_start();
    trimmed.starts_with('|')
        || trimmed.starts_with("= hint:")
        || line.split_once(" |").is_some_and(|(gutter, _)| {
            let gutter = gutter.trim();
            !gutter.is_empty() && gutter.chars().all(|c| c.is_ascii_digit())
        })
}

impl eframe::App for EdgewiseApp {
    fn clear_color(&self, visuals: &egui::Visuals) -> [f32; 4] {
        crate::visuals::backdrop(visuals.dark_mode)
    }

    fn ui(&mut self, ui: &mut egui::Ui, frame: &mut eframe::Frame) {
        self.frame_ui(ui, frame.info().cpu_usage);
    }

    #[cfg(target_arch = "wasm32")]
    fn as_any_mut(&mut self) -> Option<&mut dyn std::any::Any> {
        Some(&mut *self)
    }
}

impl EdgewiseApp {
    /// One frame of the app in `ui`, given how long eframe says the last
    /// frame took. Without eframe (the `link` fuzz target) it runs in a
    /// bare [`egui::Context`].
    pub fn frame_ui(&mut self, ui: &mut egui::Ui, cpu_usage_seconds: Option<f32>) {
        self.frames += 1;
        self.frame_cpu_ms = cpu_usage_seconds.map(|seconds| seconds * 1000.0);
        if !self.fonts_installed {
            crate::visuals::install_fonts(ui.ctx());
            self.fonts_installed = true;
        }
        if self.applied_theme != Some(self.theme.key()) {
            crate::visuals::apply_theme(&self.theme, ui.ctx());
            self.applied_theme = Some(self.theme.key());
        }
        self.receive_files(ui.ctx());
        self.advance_pending(ui.ctx());
        self.play_tick(ui.ctx());
        // Before any panel: the tables and the view draw the same moment.
        self.refresh_styles();
        self.presentation_keys(ui.ctx());
        if crate::platform::fit_canvas() {
            ui.ctx().request_repaint();
        }
        self.size_controls(ui.ctx());
        if let Some(embed) = self.embed {
            self.trace_keys(ui.ctx());
            self.embed_ui(ui, embed);
        } else {
            self.whole_ui(ui);
        }
        let ring = edgewise_pictures::palette::Palette::new(self.theme.dark).hover;
        self.focus_ring.ui(ui.ctx(), ring);
        self.observe_for_embedding(ui.ctx());
        crate::platform::deliver_events(&mut self.embed_events);
        self.mirror_for_readers();
        self.ui_cache.finish(ui.ctx(), self.render_state.as_ref());
    }

    /// The full layout: menus, panels, tables and the view.
    fn whole_ui(&mut self, ui: &mut egui::Ui) {
        let presenting = self.presentation;
        // Panels are bounded by the window, so no content (a long value, a
        // wide table) can squeeze the 3D view away.
        let window = ui.max_rect();
        let fit = self.fit(window.width());
        self.algorithms.in_sheet = fit.sheet;
        self.layout = crate::state::LayoutState {
            window: window.into(),
            compact: fit.folded_bar,
            ..Default::default()
        };
        let mut chrome = 0.0;
        let mut parts = Vec::new();
        let mut part = |rect: egui::Rect, (title, text): (&'static str, &'static str)| {
            parts.push(first_visit::Part { rect, title, text });
            rect.height()
        };
        if presenting.is_none_or(|p| p.menu) {
            chrome += part(
                egui::Panel::top("top_bar")
                    .show(ui, |ui| {
                        self.cached_part_ui(ui, "top bar", Self::top_bar_ui);
                    })
                    .response
                    .rect,
                first_visit::TOP_BAR,
            );
            if self.tabs.len() > 1 {
                chrome += egui::Panel::top("tab_bar")
                    .show(ui, |ui| self.tab_bar_ui(ui))
                    .response
                    .rect
                    .height();
            }
        }
        self.keyboard_walk(ui.ctx());
        self.trace_keys(ui.ctx());
        self.settings_window_ui(ui.ctx());
        self.statistics_window_ui(ui.ctx());
        self.share_window_ui(ui.ctx());
        let algorithm =
            (self.show_algorithm_panel || self.tab().run.is_active() || self.tab().diagnosis)
                && presenting.is_none_or(|p| p.algorithm);
        let tables = presenting.is_none_or(|p| p.tables);
        if fit.sheet {
            let offered = self.sheet_tabs(tables, algorithm);
            if let Some((rect, shown)) = self.sheet_ui(ui, &offered) {
                chrome += part(rect.intersect(window), shown);
            }
        } else {
            if algorithm {
                let rect = egui::Panel::right("algorithm")
                    .resizable(true)
                    .default_size(480.0)
                    .size_range(side_panel_range(window.width(), 300.0))
                    .show(ui, |ui| {
                        self.cached_part_ui(ui, "algorithm panel", Self::algorithm_panel_ui);
                    })
                    .response
                    .rect;
                self.layout.panels.insert("algorithm", rect.into());
                part(rect, first_visit::ALGORITHM);
            }
            if self.show_obj_editor && presenting.is_none() {
                let editor = egui::Panel::right("obj_editor")
                    .resizable(true)
                    .default_size(320.0)
                    .size_range(side_panel_range(window.width(), 200.0))
                    .show(ui, |ui| {
                        self.cached_part_ui(ui, "OBJ editor", Self::obj_editor_ui);
                    });
                self.layout
                    .panels
                    .insert("objEditor", editor.response.rect.into());
            }
            if tables {
                let rect = egui::Panel::bottom("tables")
                    .resizable(true)
                    .default_size(260.0)
                    .size_range(120.0_f32.min(window.height() * 0.2)..=window.height() * 0.4)
                    .show(ui, |ui| self.cached_part_ui(ui, "tables", Self::tables_ui))
                    .response
                    .rect;
                self.layout.panels.insert("tables", rect.into());
                chrome += part(rect, first_visit::TABLES);
            }
        }
        self.chrome_height = chrome;
        let central = egui::CentralPanel::default().show(ui, |ui| {
            self.error_ui(ui);
            if self.side_by_side && self.tab().document.is_some() {
                StripBuilder::new(ui)
                    .sizes(Size::remainder(), 2)
                    .horizontal(|mut strip| {
                        strip.cell(|ui| self.view_ui(ui));
                        strip.cell(|ui| self.twin_view_ui(ui));
                    });
            } else {
                self.view_ui(ui);
            }
        });
        part(central.response.rect, first_visit::VIEW);
        self.layout.view = Some(central.response.rect.into());
        self.layout.step_controls = self.algorithms.step_controls.take().map(Into::into);
        self.layout.source_lines = self.algorithms.source_lines.take();
        if let Some(top_bar) = parts.iter().find(|p| p.title == first_visit::TOP_BAR.0) {
            self.layout.panels.insert("topBar", top_bar.rect.into());
        }
        // What shows: a panel's content larger than the panel is cut at the
        // window, and egui reports the panel as large as its content.
        for panel in self.layout.panels.values_mut() {
            *panel = panel.within(window);
        }
        self.screen_parts = parts;
        self.presentation_hint_ui(ui.ctx());
        self.tour_progress(false);
        self.tour_ui(ui.ctx());
        self.explain_ui(ui.ctx());
        self.files_overlay_ui(ui.ctx());
        self.pending_ui(ui.ctx());
    }
}

/// A mesh's name as the top bar shows it: a table file of the other
/// structure says what it is shown as ("tetrahedron.wtb, shown as
/// half-edge"), so a student never reads one structure's name over the
/// other's tables.
fn shown_name(name: &str, structure: Structure) -> std::borrow::Cow<'_, str> {
    let other = structure.other();
    let extension = std::path::Path::new(name)
        .extension()
        .and_then(std::ffi::OsStr::to_str);
    if extension.is_some_and(|e| e.eq_ignore_ascii_case(other.table_extension())) {
        format!("{name}, shown as {}", structure.prose()).into()
    } else {
        name.into()
    }
}

/// The least width, in points, in which the three tables fit side by side.
const TABLES_SIDE_BY_SIDE: f32 = 690.0;

/// The widths a side panel may take in a window `window_width` wide: at
/// most half of it, and `least` when the window has room.
fn side_panel_range(window_width: f32, least: f32) -> egui::Rangef {
    let most = window_width * 0.5;
    egui::Rangef::new(least.min(most), most)
}

/// A short guide: what to click, the keys, and what the colours mean.
impl EdgewiseApp {
    fn help_menu_ui(&mut self, ui: &mut egui::Ui) {
        self.menu_ui(ui, "Help", |this, ui| {
            if ui.button("What am I looking at?").clicked() {
                this.explaining = true;
            }
            if ui.button("Things to try").clicked() {
                this.tour = Some(first_visit::Tour::default());
            }
            ui.separator();
            help_text_ui(ui);
        });
    }
}

/// Every key the app answers, as Help lists it.
pub const HELP_KEYS: [(&str, &str); 14] = [
    (
        "/",
        "go to an element: type e 3, vertex 1 or f2, then Enter",
    ),
    ("↑  ↓", "the row above or below in the selection's table"),
    (
        "n  p  t  f  v",
        "half-edge walking: successor, predecessor, pair, face, end vertex",
    ),
    (
        "Tab  Enter",
        "move through the tables; follow the reference in a cell",
    ),
    ("E", "the edit menu of the selected element"),
    ("Ctrl+Z  Ctrl+Y", "undo and redo (Ctrl+Shift+Z redoes too)"),
    ("Space  →", "step the algorithm forward"),
    ("←", "step back"),
    ("O  U", "step over a call; step out of the current call"),
    ("Home  End", "the first and the last step"),
    ("P", "play or pause"),
    (
        "Shift+arrows  +  −  Shift+Home",
        "turn, zoom and frame the camera",
    ),
    (
        "Esc",
        "close a menu; leave the presentation; in a page, give the keys back",
    ),
    ("double-click", "frame the mesh"),
];

fn help_text_ui(ui: &mut egui::Ui) {
    {
        ui.set_max_width(420.0_f32.min(ui.ctx().content_rect().width() - 32.0));
        ui.strong("Edgewise");
        ui.label(
            "Click a vertex, an edge or a face, in the 3D view or in a table: it is \
             highlighted with every element its record refers to, labelled with its role. \
             Every reference in a table is a link.",
        );
        ui.separator();
        ui.strong("Keys");
        egui::Grid::new("help_keys").num_columns(2).show(ui, |ui| {
            for (keys, what) in HELP_KEYS {
                ui.monospace(keys);
                ui.label(what);
                ui.end_row();
            }
        });
        ui.separator();
        ui.strong("Camera");
        ui.label(
            "Drag to orbit; wheel, pinch or right-drag to zoom; middle- or shift-drag to pan.",
        );
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

/// The row above (`down` false) or below `from` in its table, over deleted
/// rows; with nothing selected, the first or last edge. `None` at either
/// end of the table.
fn table_neighbour(
    mesh: &dyn edgewise_core::schema::Records,
    from: Option<ElementRef>,
    down: bool,
) -> Option<ElementRef> {
    let kind = from.map_or(ElementKind::Edge, |e| e.kind);
    let count = u32::try_from(mesh.count(kind)).unwrap_or(u32::MAX);
    let ids: Box<dyn Iterator<Item = u32>> = match (from, down) {
        (None, true) => Box::new(0..count),
        (None, false) => Box::new((0..count).rev()),
        (Some(e), true) => Box::new(e.id.saturating_add(1)..count),
        (Some(e), false) => Box::new((0..e.id.min(count)).rev()),
    };
    ids.map(|id| ElementRef::new(kind, id))
        .find(|&element| mesh.contains(element))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_table_file_of_the_other_structure_says_what_it_is_shown_as() {
        assert_eq!(
            shown_name("tetrahedron.wtb", Structure::HalfEdge),
            "tetrahedron.wtb, shown as half-edge"
        );
        assert_eq!(
            shown_name("tetrahedron.wtb", Structure::WingedEdge),
            "tetrahedron.wtb"
        );
        assert_eq!(
            shown_name("cube.HTB", Structure::WingedEdge),
            "cube.HTB, shown as winged-edge"
        );
        assert_eq!(shown_name("bunny.obj", Structure::HalfEdge), "bunny.obj");
    }
}
