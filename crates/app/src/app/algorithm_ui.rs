//! The app's algorithm commands (shared by the UI and the JavaScript API),
//! the Algorithm menu, the algorithm panel and the stepping keys.

use crate::command::{Command, CommandError};
use crate::platform::ALGORITHM_FILES;
use edgewise_core::schema::{ElementKind, ElementRef};
use edgewise_model::algorithm::session::Argument;
use std::sync::Arc;

use edgewise_core::schema::Structure;

use super::{AlgorithmTab, EdgewiseApp};
use crate::{algorithm::editor::EditorCommand, state::AlgorithmInfo};
use edgewise_model::{algorithm::library::Origin, algorithm::session, algorithm::session::Run};
use edgewise_pictures::options::PickFilter;

impl EdgewiseApp {
    /// [`Command::LoadAlgorithms`]: adds the algorithms of `source` to the
    /// menu, replacing same-named ones of the same structure. Returns their
    /// names.
    pub(crate) fn add_algorithms(
        &mut self,
        source: &str,
        file: &str,
    ) -> Result<Vec<String>, CommandError> {
        let result = self.algorithms.library.load(source, file);
        self.show_algorithm_panel = true;
        Ok(result?)
    }

    /// [`Command::RunAlgorithm`]: starts `name` for the open mesh's
    /// structure with the given inputs.
    pub(crate) fn start_algorithm(
        &mut self,
        name: &str,
        args: &[(String, Argument)],
    ) -> Result<(), CommandError> {
        let Some(document) = &self.tab().document else {
            return Err("open a mesh before running an algorithm".into());
        };
        let structure = document.structure();
        let algorithm = self.algorithms.find(name, structure)?;
        let inputs = session::argument_inputs(&algorithm, args)?;
        self.set_selection(None)?;
        self.show_algorithm_panel = true;
        self.algorithm_tab = AlgorithmTab::Run;
        let tab = &mut self.tabs[self.active_tab];
        let result = match &tab.document {
            Some(document) => tab
                .run
                .begin(Arc::clone(&algorithm), &inputs, document.mesh()),
            None => Ok(()),
        };
        Ok(result?)
    }

    /// Every algorithm known, for `window.edgewise.algorithms()`.
    pub fn algorithm_list(&self) -> Vec<AlgorithmInfo> {
        self.algorithms
            .library
            .entries()
            .iter()
            .map(|entry| {
                let algorithm = &entry.algorithm;
                AlgorithmInfo {
                    name: algorithm.name.clone(),
                    structure: algorithm.structure.link_name(),
                    parameters: algorithm
                        .params()
                        .map(|p| format!("{} : {}", p.name, p.ty))
                        .collect(),
                    description: algorithm.description.clone(),
                    origin: match &entry.origin {
                        Origin::Library => "library".to_owned(),
                        Origin::User(file) => file.clone(),
                    },
                }
            })
            .collect()
    }

    /// A click on an element in the view or the tables: an input for a
    /// waiting algorithm, nothing while a trace is shown, else a selection.
    /// A click picks an input, selects, or (section 5.4 of the Neperud
    /// paper) ends a finished run, whose marks stay until then.
    pub(super) fn element_clicked(&mut self, element: Option<ElementRef>) {
        match (&self.tab().run.run, element) {
            (Run::Picking(_), Some(element)) => self.issue(Command::Pick(element)),
            (Run::Tracing(session), Some(element))
                if session
                    .quiz
                    .as_ref()
                    .is_some_and(|quiz| quiz.stops_at(session.step())) =>
            {
                self.issue(Command::Answer(element.into()));
            }
            (Run::Tracing(_), element) if self.run_finished() => {
                self.issue(Command::Abort);
                self.issue(Command::Select(element));
            }
            (Run::Picking(_) | Run::Tracing(_), _) => {}
            (Run::Idle, element) => self.issue(Command::Select(element)),
        }
    }

    /// The trace stands at its end and the algorithm finished.
    fn run_finished(&self) -> bool {
        self.tab()
            .run
            .current_frame(&self.theme)
            .is_some_and(|frame| frame.done)
    }

    /// Only the kind of element a waiting algorithm needs can be picked.
    pub(super) fn pick_filter(&self) -> PickFilter {
        match &self.tab().run.run {
            Run::Picking(pending) => match pending.wanted_kind() {
                Some(ElementKind::Vertex) => PickFilter::Only(ElementKind::Vertex),
                Some(ElementKind::Edge) => PickFilter::Only(ElementKind::Edge),
                Some(ElementKind::Face) => PickFilter::Only(ElementKind::Face),
                None => PickFilter::All,
            },
            _ => PickFilter::All,
        }
    }

    /// The message line while an algorithm runs: its prompt or the step.
    pub(super) fn algorithm_message(&self) -> Option<String> {
        let frame = self.tab().run.current_frame(&self.theme);
        edgewise_model::message::run_message(&self.tab().run.run, frame.as_deref())
    }

    /// Advances a playing trace and schedules the next frame for it.
    pub(super) fn play_tick(&mut self, ctx: &egui::Context) {
        let now = ctx.input(|i| i.time);
        self.clock = now;
        if let Some(wait) = self
            .algorithms
            .tick(&mut self.tabs[self.active_tab].run, now)
        {
            ctx.request_repaint_after(std::time::Duration::from_secs_f64(wait.max(0.0)));
        }
    }

    /// Space or → steps, ← steps back, Home and End jump, P plays or pauses,
    /// O steps over a call and U out of one.
    pub(super) fn trace_keys(&mut self, ctx: &egui::Context) {
        if ctx.egui_wants_keyboard_input() || self.tab().run.session().is_none() {
            return;
        }
        // Shift with an arrow or Home moves the camera instead.
        let (forward, back, home, end, play) = ctx.input(|i| {
            let plain = !i.modifiers.shift;
            (
                i.key_pressed(egui::Key::Space) || (plain && i.key_pressed(egui::Key::ArrowRight)),
                plain && i.key_pressed(egui::Key::ArrowLeft),
                plain && i.key_pressed(egui::Key::Home),
                i.key_pressed(egui::Key::End),
                i.key_pressed(egui::Key::P),
            )
        });
        let (over, out) = ctx.input(|i| (i.key_pressed(egui::Key::O), i.key_pressed(egui::Key::U)));
        let calls = self
            .tab()
            .run
            .session()
            .is_some_and(|s| s.trace.algorithm().calls_others());
        let commands = [
            (forward, Command::Step(1)),
            (back, Command::Back(1)),
            (home, Command::Goto(0)),
            (end, Command::Goto(usize::MAX)),
            (over && calls, Command::StepOver),
            (out && calls, Command::StepOut),
        ];
        for (pressed, command) in commands {
            if pressed {
                self.issue(command);
            }
        }
        if play {
            let playing = self.tab().run.session().is_some_and(|s| s.playing);
            self.issue(Command::SetPlaying(!playing));
        }
    }

    /// The Algorithm menu: the library for the mesh's structure, the other
    /// structure's algorithms greyed with a hint, and the editor.
    pub(super) fn algorithm_menu_ui(&mut self, ui: &mut egui::Ui) {
        let structure = self.tabs[self.active_tab]
            .document
            .as_ref()
            .map(edgewise_model::document::Document::structure);
        let mut chosen = None;
        let mut write = false;
        self.menu_ui(ui, "Algorithm", |this, ui| {
            ui.set_min_width(260.0_f32.min(ui.ctx().content_rect().width() - 32.0));
            let Some(structure) = structure else {
                ui.weak("Open a mesh to run algorithms on it.");
                return;
            };
            this.algorithm_entries_ui(ui, structure, &mut chosen);
            if ui.button("Write or open an algorithm…").clicked() {
                write = true;
            }
        });
        if let Some(name) = chosen {
            self.issue(Command::RunAlgorithm {
                name,
                args: Vec::new(),
            });
        }
        if write {
            self.show_algorithm_panel = true;
            self.algorithm_tab = AlgorithmTab::Write;
        }
    }

    /// The Algorithm menu's entries: the library for `structure`, then the
    /// other structure's algorithms greyed with a hint.
    fn algorithm_entries_ui(
        &self,
        ui: &mut egui::Ui,
        structure: Structure,
        chosen: &mut Option<String>,
    ) {
        for (label, ours) in [(structure.prose(), true), (other(structure).prose(), false)] {
            ui.label(egui::RichText::new(format!("For {label} meshes")).strong());
            // Helpers, which the others call, are left to the panel.
            for entry in self.algorithms.library.entries() {
                let algorithm = &entry.algorithm;
                if (algorithm.structure == structure) != ours || algorithm.is_helper() {
                    continue;
                }
                let button = ui.add_enabled(
                    ours,
                    egui::Button::new(egui::RichText::new(&algorithm.name).monospace()),
                );
                let button = if ours {
                    button.on_hover_text(algorithm.signature())
                } else {
                    button.on_disabled_hover_text(format!(
                        "Written for {} meshes: switch the structure in the top bar to run it",
                        algorithm.structure.prose()
                    ))
                };
                if button.has_focus() {
                    button.scroll_to_me(None);
                }
                if button.clicked() {
                    *chosen = Some(algorithm.name.clone());
                }
            }
            ui.separator();
        }
    }

    /// The side panel: the algorithm view or the algorithm editor.
    pub(super) fn algorithm_panel_ui(&mut self, ui: &mut egui::Ui) {
        ui.horizontal(|ui| {
            ui.selectable_value(&mut self.algorithm_tab, AlgorithmTab::Run, "Algorithm");
            ui.selectable_value(&mut self.algorithm_tab, AlgorithmTab::Write, "Write");
            ui.with_layout(egui::Layout::right_to_left(egui::Align::Center), |ui| {
                if ui.button("✖").on_hover_text("Close the panel").clicked() {
                    self.issue(Command::CloseAlgorithm);
                }
            });
        });
        ui.separator();
        match self.algorithm_tab {
            AlgorithmTab::Run => {
                self.practice_ui(ui);
                // A phone's sheet keeps its height for the trace: the top bar
                // already counts the mesh's elements.
                if !(self.algorithms.in_sheet && self.tab().run.is_active()) {
                    self.mesh_status_ui(ui);
                    ui.separator();
                }
                let tab = &mut self.tabs[self.active_tab];
                // An exercise is done by hand: the algorithms wait until it
                // is left, but for the run a model answer plays.
                if tab.practice.is_some() && !tab.run.is_active() {
                    return;
                }
                let mesh = tab
                    .document
                    .as_ref()
                    .map(edgewise_model::document::Document::mesh);
                if let Some(command) = self
                    .algorithms
                    .panel_ui(&mut tab.run, ui, &self.theme, mesh)
                {
                    self.issue(command);
                }
            }
            AlgorithmTab::Write => {
                let Self {
                    algorithms, theme, ..
                } = self;
                match algorithms.editor.ui(ui, &mut algorithms.library, theme) {
                    Some(EditorCommand::Open) => self.pick_algorithm_file(ui.ctx()),
                    Some(EditorCommand::Save) => {
                        let editor = &mut self.algorithms.editor;
                        match self
                            .files
                            .io
                            .write(&editor.file_name, editor.text.as_bytes())
                        {
                            Ok(said) => editor.status = Some(said),
                            Err(message) => self.report(message),
                        }
                    }
                    None => {}
                }
            }
        }
    }
}

impl EdgewiseApp {
    /// Puts an opened `.alg` file in the algorithm editor and compiles it:
    /// its algorithms join the menu, or its errors are marked at their lines.
    pub(crate) fn open_algorithm_file(
        &mut self,
        name: &str,
        bytes: &[u8],
    ) -> Result<(), CommandError> {
        let text = match edgewise_core::lang::source_text(bytes, Some(name)) {
            Ok(text) => text,
            Err(rendered) => return Err(rendered.trim_end().into()),
        };
        let editor = &mut self.algorithms.editor;
        editor.file_name = name.to_owned();
        editor.set_text(text.to_owned(), &mut self.algorithms.library);
        self.show_algorithm_panel = true;
        self.algorithm_tab = AlgorithmTab::Write;
        Ok(())
    }

    /// The browser's file picker for algorithm files; natively, files are
    /// dropped on the window (or opened by path through Open mesh…).
    fn pick_algorithm_file(&mut self, ctx: &egui::Context) {
        match self.files.io.pick(ctx, ALGORITHM_FILES) {
            Ok(None) => {}
            Ok(Some(hint)) => self.algorithms.editor.status = Some(hint.to_owned()),
            Err(message) => self.report(message),
        }
    }
}

fn other(structure: Structure) -> Structure {
    match structure {
        Structure::WingedEdge => Structure::HalfEdge,
        Structure::HalfEdge => Structure::WingedEdge,
    }
}
