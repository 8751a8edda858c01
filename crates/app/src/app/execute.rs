//! [`EdgewiseApp::execute`]: carrying out a [`Command`] on the active tab,
//! and the shorthand methods the Rust API offers for each.

use edgewise_core::{
    mesh::{Structure, operations::Operation},
    schema::ElementRef,
};
use edgewise_model::algorithm::run::AlgorithmRun;
use edgewise_model::algorithm::session::Argument;

use crate::{
    EdgewiseApp,
    command::{Command, CommandError, Reply},
};

impl EdgewiseApp {
    /// Carries out `command` on the active tab and asks for a frame to show
    /// it. A refusal is recorded as the tab's error, then returned.
    pub fn execute(&mut self, command: Command) -> Result<Reply, CommandError> {
        if matches!(
            command,
            Command::Abort
                | Command::CloseAlgorithm
                | Command::RunAlgorithm { .. }
                | Command::Start
                | Command::Edit { .. }
                | Command::Undo
                | Command::Redo
                | Command::RestoreBeforeEdit
                | Command::CompactIds
                | Command::SetCell { .. }
        ) {
            self.tab_mut().finish_edit();
        }
        // An edit by hand shows the panel with the mesh's status, undo and
        // redo.
        let shows_status = matches!(
            command,
            Command::Edit { .. }
                | Command::SetCell { .. }
                | Command::CompactIds
                | Command::AddRow(_)
                | Command::DeleteRow(_)
                | Command::SetPosition { .. }
        );
        let clicked = match &command {
            Command::Select(Some(element)) => Some(*element),
            _ => None,
        };
        let written = matches!(
            command,
            Command::SetCell { .. }
                | Command::AddRow(_)
                | Command::DeleteRow(_)
                | Command::SetPosition { .. }
        );
        let result = self
            .refuse_during_practice(&command)
            .and_then(|()| self.dispatch(command));
        if written && result.is_ok() {
            self.exercise_written();
        }
        if let (Some(element), Ok(_)) = (clicked, &result) {
            self.exercise_clicked(element);
        }
        // A run just traced asks its questions from its first step.
        let run = &mut self.tabs[self.active_tab].run;
        self.algorithms.question_sets.pose(run);
        if shows_status && result.is_ok() {
            self.show_algorithm_panel = true;
        }
        self.tab_mut().sync_edit();
        // The hint notes a selection or a step at once: the next command
        // may undo it before a frame is drawn.
        self.tour_progress(false);
        if let Err(error) = &result {
            self.report(error.to_string());
        }
        self.request_repaint();
        result
    }

    /// [`Self::execute`] for menus and keys, whose refusals the error panel
    /// shows.
    pub(crate) fn issue(&mut self, command: Command) {
        // Recorded by execute; nothing else to do with it here.
        let _reported = self.execute(command);
    }

    /// While an exercise is open the student makes the edit by hand: the
    /// library's operations, traced or not, and a change of structure wait
    /// until it is left (the model answer applies the operation).
    fn refuse_during_practice(&self, command: &Command) -> Result<(), CommandError> {
        let Some(session) = self.tab().practice.as_ref() else {
            return Ok(());
        };
        let what = match command {
            Command::Edit { .. } => "the library's operations",
            // Once the model answer is shown, its run may be stepped.
            Command::RunAlgorithm { .. } if session.model_answer_shown => return Ok(()),
            Command::RunAlgorithm { .. } => "algorithms",
            Command::SetStructure(structure) if *structure != session.exercise.structure => {
                "another structure"
            }
            _ => return Ok(()),
        };
        Err(format!(
            "the exercise {} is open: do the edit by hand in the tables; {what} wait until you \
             leave it (Practice card, Leave)",
            session.exercise.name
        )
        .into())
    }

    fn dispatch(&mut self, command: Command) -> Result<Reply, CommandError> {
        fn done<E: Into<CommandError>>(result: Result<(), E>) -> Result<Reply, CommandError> {
            result.map(|()| Reply::Done).map_err(Into::into)
        }
        match command {
            Command::LoadMesh {
                bytes,
                name,
                structure,
                diagnose,
            } => done(self.open_bytes(&bytes, &name, structure, diagnose)),
            Command::DiagnoseRefused => done(self.diagnose_refused()),
            Command::LoadSample { name, structure } => done(self.open_sample(&name, structure)),
            Command::OpenFile { name, bytes } => done(self.open_named_file(&name, bytes)),
            Command::ChooseStructure(structure) => done(self.resolve_structure_dialog(structure)),
            Command::Select(element) => done(self.set_selection(element)),
            Command::SetStructure(structure) => {
                // The converted mesh is the one the run left, kept undoably.
                self.tab_mut().end_run();
                done(self.convert_to(structure))
            }
            Command::LoadAlgorithms { source, file } => {
                self.add_algorithms(&source, &file).map(Reply::Algorithms)
            }
            Command::RunAlgorithm { name, args } => done(self.start_algorithm(&name, &args)),
            Command::Pick(element) => done(
                self.tab_mut()
                    .with_mesh(|run, mesh| run.pick(element, mesh)),
            ),
            Command::Start => done(self.tab_mut().with_mesh(AlgorithmRun::start)),
            Command::Step(n) => done(self.tab_mut().run.step(n)),
            Command::Answer(given) => {
                let index = self.tab_mut().run.answer(given)?;
                self.report_answer(index);
                Ok(Reply::Done)
            }
            Command::SetQuestions(text) => {
                let run = &mut self.tabs[self.active_tab].run;
                done(self.algorithms.question_sets.set(run, &text))
            }
            Command::Back(n) => done(self.tab_mut().run.back(n)),
            Command::SetPlaying(on) => {
                let now = self.clock;
                done(self.tab_mut().run.set_playing(on, now))
            }
            Command::StepOver => done(self.tab_mut().run.step_over()),
            Command::StepOut => done(self.tab_mut().run.step_out()),
            Command::Goto(k) => done(self.tab_mut().run.goto(k)),
            Command::Abort => done(self.tab_mut().run.abort()),
            Command::CloseAlgorithm => {
                self.show_algorithm_panel = false;
                self.tab_mut().end_run();
                Ok(Reply::Done)
            }
            Command::Cancel => done(self.cancel_pending()),
            Command::ToggleBreakpoint(line) => {
                let run = &mut self.tabs[self.active_tab].run;
                self.algorithms.toggle_breakpoint(run, line);
                Ok(Reply::Done)
            }
            Command::ContinueToBreakpoint => {
                let run = &mut self.tabs[self.active_tab].run;
                done(self.algorithms.continue_to_breakpoint(run))
            }
            Command::NewTab => Ok(Reply::Tab(self.open_tab())),
            Command::SwitchTab(index) => done(self.activate_tab(index)),
            Command::CloseTab(index) => done(self.remove_tab(index)),
            Command::SetSideBySide(on) => done(self.show_twin(on)),
            Command::SaveAs(format) => done(self.save_as(format)),
            Command::SavePicture => {
                let svg = self.export_svg()?;
                let name = self.tab().document.as_ref().map_or_else(
                    || "edgewise.svg".to_owned(),
                    |document| {
                        format!(
                            "{}.svg",
                            edgewise_model::document::mesh_stem(&document.name)
                        )
                    },
                );
                done(self.files.io.write(&name, svg.as_bytes()).map(drop))
            }
            Command::SaveHandout => {
                let (name, pdf) = self.export_handout()?;
                done(self.files.io.write(&name, &pdf).map(drop))
            }
            Command::Edit { operation, ids } => {
                done(self.tab_mut().apply_operation(operation, &ids))
            }
            Command::RestoreBeforeEdit => done(self.tab_mut().restore_before_edit()),
            Command::Undo => done(self.tab_mut().undo()),
            Command::Redo => done(self.tab_mut().redo()),
            Command::AddRow(kind) => done(self.tab_mut().add_row(kind)),
            Command::DeleteRow(element) => done(self.tab_mut().delete_row(element)),
            Command::SetPosition { vertex, position } => {
                done(self.tab_mut().set_position(vertex, position))
            }
            Command::StartExercise {
                exercise,
                seed,
                progress,
                name,
            } => done(self.start_exercise(&exercise, seed, progress.as_deref(), name.as_deref())),
            Command::AnswerExercise(given) => done(self.answer_exercise(given)),
            Command::SubmitExercise => done(self.submit_exercise()),
            Command::ShowModelAnswer => done(self.show_model_answer()),
            Command::NewInstance => done(self.new_instance()),
            Command::EndExercise => done(self.end_exercise()),
            Command::CompactIds => done(self.tab_mut().compact_ids()),
            Command::SetCell {
                element,
                column,
                target,
            } => done(self.tab_mut().set_cell(element, &column, target)),
        }
    }

    /// Shorthand for [`Command::LoadMesh`]. On failure the current mesh
    /// stays and the message is kept in `state().error`.
    pub fn load_mesh(
        &mut self,
        bytes: &[u8],
        name: &str,
        structure: Option<Structure>,
    ) -> Result<(), CommandError> {
        self.execute(Command::LoadMesh {
            bytes: bytes.to_vec(),
            name: name.to_owned(),
            structure,
            diagnose: false,
        })
        .map(drop)
    }

    /// [`Command::LoadMesh`] in diagnosis mode: a table file whose tables
    /// break the rules opens with its broken records marked.
    pub fn load_mesh_for_diagnosis(
        &mut self,
        bytes: &[u8],
        name: &str,
    ) -> Result<(), CommandError> {
        self.execute(Command::LoadMesh {
            bytes: bytes.to_vec(),
            name: name.to_owned(),
            structure: None,
            diagnose: true,
        })
        .map(drop)
    }

    /// Shorthand for [`Command::LoadSample`].
    pub fn load_sample(
        &mut self,
        name: &str,
        structure: Option<Structure>,
    ) -> Result<(), CommandError> {
        self.execute(Command::LoadSample {
            name: name.to_owned(),
            structure,
        })
        .map(drop)
    }

    /// Shorthand for [`Command::OpenFile`].
    pub fn open_file(&mut self, name: &str, bytes: Vec<u8>) -> Result<(), CommandError> {
        self.execute(Command::OpenFile {
            name: name.to_owned(),
            bytes,
        })
        .map(drop)
    }

    /// Shorthand for [`Command::ChooseStructure`].
    pub fn answer_structure_dialog(
        &mut self,
        structure: Option<Structure>,
    ) -> Result<(), CommandError> {
        self.execute(Command::ChooseStructure(structure)).map(drop)
    }

    /// Shorthand for [`Command::Select`].
    pub fn select(&mut self, element: Option<ElementRef>) -> Result<(), CommandError> {
        self.execute(Command::Select(element)).map(drop)
    }

    /// Shorthand for [`Command::SetStructure`].
    pub fn switch_structure(&mut self, structure: Structure) -> Result<(), CommandError> {
        self.execute(Command::SetStructure(structure)).map(drop)
    }

    /// Shorthand for [`Command::LoadAlgorithms`]; returns the names loaded.
    pub fn load_algorithms(
        &mut self,
        source: &str,
        file: &str,
    ) -> Result<Vec<String>, CommandError> {
        match self.execute(Command::LoadAlgorithms {
            source: source.to_owned(),
            file: file.to_owned(),
        })? {
            Reply::Algorithms(names) => Ok(names),
            _ => Ok(Vec::new()),
        }
    }

    /// Shorthand for [`Command::RunAlgorithm`].
    pub fn run_algorithm(
        &mut self,
        name: &str,
        args: &[(String, Argument)],
    ) -> Result<(), CommandError> {
        self.execute(Command::RunAlgorithm {
            name: name.to_owned(),
            args: args.to_vec(),
        })
        .map(drop)
    }

    /// Shorthand for [`Command::Step`].
    pub fn trace_step(&mut self, n: usize) -> Result<(), CommandError> {
        self.execute(Command::Step(n)).map(drop)
    }

    /// Shorthand for [`Command::Back`].
    pub fn trace_back(&mut self, n: usize) -> Result<(), CommandError> {
        self.execute(Command::Back(n)).map(drop)
    }

    /// Shorthand for [`Command::StepOver`].
    pub fn trace_step_over(&mut self) -> Result<(), CommandError> {
        self.execute(Command::StepOver).map(drop)
    }

    /// Shorthand for [`Command::StepOut`].
    pub fn trace_step_out(&mut self) -> Result<(), CommandError> {
        self.execute(Command::StepOut).map(drop)
    }

    /// Shorthand for [`Command::Goto`].
    pub fn trace_goto(&mut self, k: usize) -> Result<(), CommandError> {
        self.execute(Command::Goto(k)).map(drop)
    }

    /// Shorthand for [`Command::Abort`].
    pub fn abort_algorithm(&mut self) -> Result<(), CommandError> {
        self.execute(Command::Abort).map(drop)
    }

    /// Shorthand for [`Command::Edit`].
    pub fn edit(&mut self, operation: Operation, ids: &[u32]) -> Result<(), CommandError> {
        self.execute(Command::Edit {
            operation,
            ids: ids.to_vec(),
        })
        .map(drop)
    }

    /// Shorthand for [`Command::RestoreBeforeEdit`].
    pub fn restore_before_edit(&mut self) -> Result<(), CommandError> {
        self.execute(Command::RestoreBeforeEdit).map(drop)
    }

    /// Shorthand for [`Command::Undo`].
    pub fn undo(&mut self) -> Result<(), CommandError> {
        self.execute(Command::Undo).map(drop)
    }

    /// Shorthand for [`Command::Redo`].
    pub fn redo(&mut self) -> Result<(), CommandError> {
        self.execute(Command::Redo).map(drop)
    }

    /// Shorthand for [`Command::CompactIds`].
    pub fn compact_ids(&mut self) -> Result<(), CommandError> {
        self.execute(Command::CompactIds).map(drop)
    }

    /// Shorthand for [`Command::SetCell`].
    pub fn set_cell(
        &mut self,
        element: ElementRef,
        column: &str,
        target: Option<u32>,
    ) -> Result<(), CommandError> {
        self.execute(Command::SetCell {
            element,
            column: column.to_owned(),
            target,
        })
        .map(drop)
    }

    /// Shorthand for [`Command::NewTab`]; returns the new tab's index.
    pub fn new_tab(&mut self) -> usize {
        match self.execute(Command::NewTab) {
            Ok(Reply::Tab(index)) => index,
            _ => self.active_tab,
        }
    }

    /// Shorthand for [`Command::SwitchTab`].
    pub fn switch_tab(&mut self, index: usize) -> Result<(), CommandError> {
        self.execute(Command::SwitchTab(index)).map(drop)
    }

    /// Shorthand for [`Command::CloseTab`].
    pub fn close_tab(&mut self, index: usize) -> Result<(), CommandError> {
        self.execute(Command::CloseTab(index)).map(drop)
    }

    /// Shorthand for [`Command::SetSideBySide`].
    pub fn set_side_by_side(&mut self, on: bool) -> Result<(), CommandError> {
        self.execute(Command::SetSideBySide(on)).map(drop)
    }

    /// Where `element` is in the 3D view, in CSS pixels from the canvas's
    /// top left, as of the last frame: for pointer events and for pages
    /// that point at an element. `None` if it is not in view.
    pub fn screen_position(&self, element: ElementRef) -> Option<[f32; 2]> {
        let zoom = self.ctx.as_ref().map_or(1.0, egui::Context::zoom_factor);
        let at = self.tab().pane.view.screen_position(element)?;
        Some([at.x * zoom, at.y * zoom])
    }
}
