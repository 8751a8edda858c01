//! Practice on the tables (docs/practice.md): an exercise opens its
//! instance's mesh, the student writes cells, adds and deletes rows and
//! types positions, and Check grades the tables as they stand. The card at
//! the top of the side panel says the task, the writes used and the
//! feedback; the embed protocol reports each graded step and the score.

use edgewise_core::schema::ElementKind;
use edgewise_model::algorithm::session::Argument;
use edgewise_model::document::Document;
use edgewise_model::practice::{Exercise, Progress, Session, Task, catalog};

use super::EdgewiseApp;
use crate::command::{Command, CommandError};
use crate::embed_event::EmbedEvent;

/// The largest exercise text `startExercise` and a link take.
pub const MAX_EXERCISE_BYTES: usize = 64 * 1024;

impl EdgewiseApp {
    /// Starts an exercise, by a shipped name or from its text, at the
    /// instance `seed` draws (a fresh one if none is given).
    pub(crate) fn start_exercise(
        &mut self,
        exercise: &str,
        seed: Option<u64>,
        progress: Option<&str>,
        name: Option<&str>,
    ) -> Result<(), CommandError> {
        let mut exercise = read_exercise(exercise)?;
        if let Some(name) = name {
            name.clone_into(&mut exercise.name);
        }
        if let Some(progress) = progress {
            let do_it = matches!(exercise.task, edgewise_model::practice::TaskSpec::DoIt(_));
            let progress = Progress::parse(progress, do_it)
                .map_err(|err| format!("startExercise options.progress: {err}"))?;
            let (session, tables) =
                Session::resume(exercise, &progress).map_err(|err| err.to_string())?;
            self.open_attempt_at(session, tables);
            return Ok(());
        }
        let seed = seed.unwrap_or_else(fresh_seed);
        let session = Session::start(exercise, seed).map_err(|err| err.to_string())?;
        self.open_attempt(session);
        Ok(())
    }

    /// `exerciseProgress()`: the attempt on screen, saved, or `None` when
    /// no exercise is open.
    pub fn exercise_progress(&self) -> Option<String> {
        let tab = self.tab();
        let session = tab.practice.as_ref()?;
        let tables = tab
            .document
            .as_ref()
            .map_or(session.start_mesh(), Document::mesh);
        Some(session.progress(tables).to_string())
    }

    /// Shows the session's instance as the tab's mesh and makes it the
    /// tab's exercise.
    fn open_attempt(&mut self, session: Session) {
        let tables = session.start_mesh().clone();
        self.open_attempt_at(session, tables);
    }

    /// [`Self::open_attempt`] with the tables as the student left them.
    fn open_attempt_at(&mut self, session: Session, tables: edgewise_core::mesh::Mesh) {
        let name = format!(
            "exercise {} (seed {})",
            session.exercise.name, session.instance.seed
        );
        let document = Document::from_mesh(&name, tables);
        let label = format!("Opening {name}");
        self.show_document(
            document,
            super::pending::Commit::Open {
                frame: true,
                merge: false,
            },
            label,
        );
        self.embed_events
            .push(EmbedEvent::ExerciseStart(session.state()));
        let tab = self.tab_mut();
        tab.practice = Some(session);
        tab.rediagnose();
        self.show_algorithm_panel = true;
        // The first visit's hint is about the tetrahedron: it makes way for
        // the task (and comes back on the next visit unless dismissed).
        self.tour = None;
        self.explaining = false;
    }

    fn practice(&mut self) -> Result<&mut Session, CommandError> {
        self.tab_mut()
            .practice
            .as_mut()
            .ok_or_else(|| "no exercise is open: start one from the Practice menu".into())
    }

    /// Grades the tables as they stand (Check).
    pub(crate) fn submit_exercise(&mut self) -> Result<(), CommandError> {
        let tab = self.tab_mut();
        let session = tab
            .practice
            .as_mut()
            .ok_or("no exercise is open: start one from the Practice menu")?;
        if session.finished {
            return Err("this attempt is over: start a new instance to try again".into());
        }
        let mesh = tab
            .document
            .as_ref()
            .map(Document::mesh)
            .ok_or("no mesh is open")?;
        session.check(mesh).map_err(|err| err.to_string())?;
        self.report_exercise_step();
        Ok(())
    }

    /// After a write by hand: grades it at once where the exercise asks for
    /// live feedback.
    pub(crate) fn exercise_written(&mut self) {
        let tab = self.tab_mut();
        let (Some(session), Some(document)) = (tab.practice.as_mut(), tab.document.as_ref()) else {
            return;
        };
        if session.grades_live() && session.grade_live(document.mesh()).is_ok() {
            self.report_exercise_step();
        }
    }

    /// A selection during a walk or a prediction is its next answer:
    /// graded at once.
    pub(crate) fn exercise_clicked(&mut self, element: edgewise_core::schema::ElementRef) {
        let Some(session) = self.tab_mut().practice.as_mut() else {
            return;
        };
        if session.click(element).is_some() {
            self.report_exercise_step();
        }
    }

    /// [`Command::AnswerExercise`]: an element or null for the next step.
    pub(crate) fn answer_exercise(
        &mut self,
        given: Option<edgewise_core::schema::ElementRef>,
    ) -> Result<(), CommandError> {
        let session = self.practice()?;
        if session.answer(given).is_none() {
            return Err(match (session.finished, given) {
                (true, _) => "this attempt is over: start a new instance to try again".into(),
                (false, None) => "a walk is answered by clicking an element, not null".into(),
                (false, Some(_)) => "a do-it exercise is answered in the tables, then Check".into(),
            });
        }
        self.report_exercise_step();
        Ok(())
    }

    /// Queues `edgewise:exercisestep`, and `edgewise:score` once the
    /// attempt is over.
    fn report_exercise_step(&mut self) {
        let Some(session) = self.tab().practice.as_ref() else {
            return;
        };
        let step = EmbedEvent::ExerciseStep(session.state());
        let score = session.finished.then(|| {
            let activity = format!(
                "{}?exercise={}",
                crate::platform::page_base(),
                session.exercise.name
            );
            EmbedEvent::Score(session.score(&activity))
        });
        self.embed_events.push(step);
        self.embed_events.extend(score);
    }

    /// The model answer, which scores the attempt 0: the library's traced
    /// run, below the card, to step through. A do-it exercise's traced
    /// operation starts from the instance's tables (the student's writes
    /// undoably put aside); a walk or a prediction runs its algorithm from
    /// the instance's inputs.
    pub(crate) fn show_model_answer(&mut self) -> Result<(), CommandError> {
        let session = self.practice()?;
        session.model_answer().map_err(|e| e.to_string())?;
        let structure = session.exercise.structure;
        let start = session.start_mesh().clone();
        let task = session.instance.task.clone();
        let (name, args) = match task {
            Task::DoIt { operation, ids } => {
                self.restore_instance(start);
                self.traced_operation(operation, &ids, structure)?
            }
            Task::Walk {
                algorithm, args, ..
            }
            | Task::Predict {
                algorithm, args, ..
            } => {
                let args = args
                    .into_iter()
                    .map(|(name, element)| (name, Argument::Number(f64::from(element.id))))
                    .collect();
                (algorithm, args)
            }
        };
        self.report_exercise_step();
        self.start_algorithm(&name, &args)
    }

    /// Puts the instance's tables back, undoably, if the student changed
    /// them.
    fn restore_instance(&mut self, start: edgewise_core::mesh::Mesh) {
        let tab = self.tab_mut();
        let Some(document) = &mut tab.document else {
            return;
        };
        if *document.mesh() == start {
            return;
        }
        let before = document.replace_mesh(start);
        tab.history.record(
            "the instance again, for the model answer".to_owned(),
            crate::history::Kind::Edit,
            Some(before),
            false,
        );
        tab.rediagnose();
    }

    /// The next attempt, on a fresh instance where the exercise draws them.
    pub(crate) fn new_instance(&mut self) -> Result<(), CommandError> {
        let mut session = self.practice()?.clone();
        session.next_attempt().map_err(|err| err.to_string())?;
        self.open_attempt(session);
        Ok(())
    }

    /// Leaves the exercise; the tables stay as they are.
    pub(crate) fn end_exercise(&mut self) -> Result<(), CommandError> {
        self.practice()?;
        let tab = self.tab_mut();
        tab.practice = None;
        tab.rediagnose();
        Ok(())
    }

    /// The Practice menu: every shipped exercise.
    pub(super) fn practice_menu_ui(&mut self, ui: &mut egui::Ui) {
        let mut chosen = None;
        self.menu_ui(ui, "Practice", |_, ui| {
            ui.set_min_width(240.0_f32.min(ui.ctx().content_rect().width() - 32.0));
            ui.weak("Do an operation on the tables yourself, then Check.");
            for shipped in catalog::SHIPPED {
                if let Ok(exercise) = Exercise::parse(shipped.name, shipped.text)
                    && ui.button(&exercise.title).clicked()
                {
                    chosen = Some(shipped.name);
                }
            }
        });
        if let Some(name) = chosen {
            self.issue(Command::StartExercise {
                exercise: name.to_owned(),
                seed: None,
                progress: None,
                name: None,
            });
        }
    }

    /// The exercise card: the task, what may be written, Check, and the
    /// feedback.
    pub(super) fn practice_ui(&mut self, ui: &mut egui::Ui) {
        let Some(session) = self.tab().practice.as_ref() else {
            return;
        };
        let state = session.state();
        let structure = session.exercise.structure;
        let about = session.exercise.about.clone();
        let mut command = None;
        ui.label(egui::RichText::new(&state.title).strong());
        if let Some(about) = about {
            ui.weak(about.trim());
        }
        ui.label(egui::RichText::new(&state.task).strong());
        let action = if state.operation.is_some() {
            "write"
        } else {
            "click"
        };
        ui.weak(format!(
            "Attempt {}{} · seed {} · {} {action}{} so far",
            state.attempt,
            if state.attempts > 0 {
                format!(" of {}", state.attempts)
            } else {
                String::new()
            },
            state.seed,
            state.step,
            if state.step == 1 { "" } else { "s" }
        ));
        let walk = state.operation.is_none();
        if let Some(question) = &state.question {
            ui.horizontal_wrapped(|ui| {
                ui.label(egui::RichText::new(format!("Now: {question}")).monospace());
                if ui
                    .button("null")
                    .on_hover_text("The lookup gives no element")
                    .clicked()
                {
                    command = Some(Command::AnswerExercise(None));
                }
            });
            ui.weak("Click the element it gives, in the 3D view or in the tables.");
        } else if walk {
            if !state.finished {
                ui.weak("Click each element, in the 3D view or in the tables.");
            }
            if !state.found.is_empty() {
                let found: Vec<String> = state
                    .found
                    .iter()
                    .map(|&e| edgewise_core::mesh::Element::of(structure, e).to_string())
                    .collect();
                ui.label(format!("Found: {}", found.join(", ")));
            }
        } else if !state.finished {
            ui.weak(
                "Double-click a cell to type an id (- for none). Add or delete rows and move \
                 vertices here:",
            );
            self.row_tools_ui(ui, structure, &mut command);
        }
        ui.horizontal_wrapped(|ui| {
            let check = if walk { "Finish" } else { "Check" };
            if !state.finished && ui.button(check).clicked() {
                command = Some(Command::SubmitExercise);
            }
            if state.model_answer_offered
                && !state.model_answer_shown
                && ui
                    .button("Show model answer")
                    .on_hover_text("Apply the library's operation; this attempt then scores 0")
                    .clicked()
            {
                command = Some(Command::ShowModelAnswer);
            }
            if ui.button("New instance").clicked() {
                command = Some(Command::NewInstance);
            }
            if ui.button("Leave").clicked() {
                command = Some(Command::EndExercise);
            }
        });
        if let (Some(passed), Some(feedback)) = (state.passed, &state.feedback) {
            let colour = if passed {
                ui.visuals().widgets.active.fg_stroke.color
            } else {
                ui.visuals().error_fg_color
            };
            ui.label(egui::RichText::new(feedback).color(colour));
            if walk {
                ui.weak(format!(
                    "{} of {} steps right the first time",
                    state.correct, state.total
                ));
            }
            if let Some(fewest) = state.fewest_writes {
                ui.weak(format!(
                    "Score {} of {} · you used {} write{}; the library's operation makes {fewest}",
                    state.score,
                    state.max_score,
                    state.step,
                    if state.step == 1 { "" } else { "s" }
                ));
            }
        }
        ui.separator();
        if let Some(command) = command {
            self.issue(command);
        }
    }

    /// Adding and deleting rows and typing a position, which the tables'
    /// cells do not offer.
    fn row_tools_ui(
        &mut self,
        ui: &mut egui::Ui,
        structure: edgewise_core::mesh::Structure,
        command: &mut Option<Command>,
    ) {
        let edge = match structure {
            edgewise_core::mesh::Structure::HalfEdge => "half-edge",
            edgewise_core::mesh::Structure::WingedEdge => "edge",
        };
        ui.horizontal_wrapped(|ui| {
            ui.label("New row:");
            for (kind, label) in [
                (ElementKind::Vertex, "vertex"),
                (ElementKind::Edge, edge),
                (ElementKind::Face, "face"),
            ] {
                if ui.button(label).clicked() {
                    *command = Some(Command::AddRow(kind));
                }
            }
        });
        let form_id = ui.make_persistent_id("practice row form");
        let mut form: RowForm = ui.data_mut(|d| d.get_temp(form_id).unwrap_or_default());
        ui.horizontal_wrapped(|ui| {
            ui.label("Delete a");
            ui.selectable_value(&mut form.kind, ElementKind::Vertex, "vertex");
            ui.selectable_value(&mut form.kind, ElementKind::Edge, edge);
            ui.selectable_value(&mut form.kind, ElementKind::Face, "face");
            ui.label("row:");
            ui.add(
                egui::TextEdit::singleline(&mut form.id)
                    .desired_width(48.0)
                    .hint_text("id"),
            );
            if ui.button("Delete").clicked() {
                match form.id.trim().parse::<u32>() {
                    Ok(id) => {
                        *command = Some(Command::DeleteRow(
                            edgewise_core::schema::ElementRef::new(form.kind, id),
                        ));
                    }
                    Err(_) => self.report(format!("`{}` is not a row id", form.id.trim())),
                }
            }
        });
        ui.horizontal_wrapped(|ui| {
            ui.label("Vertex");
            ui.add(
                egui::TextEdit::singleline(&mut form.vertex)
                    .desired_width(40.0)
                    .hint_text("id"),
            );
            ui.label("at");
            ui.add(
                egui::TextEdit::singleline(&mut form.position)
                    .desired_width(120.0)
                    .hint_text("x y z"),
            );
            if ui.button("Move").clicked() {
                match parse_position(&form.vertex, &form.position) {
                    Ok((vertex, position)) => {
                        *command = Some(Command::SetPosition { vertex, position });
                    }
                    Err(message) => self.report(message),
                }
            }
        });
        ui.data_mut(|d| d.insert_temp(form_id, form));
    }
}

/// What the row tools' fields hold between frames.
#[derive(Clone, Debug)]
struct RowForm {
    kind: ElementKind,
    id: String,
    vertex: String,
    position: String,
}

impl Default for RowForm {
    fn default() -> Self {
        Self {
            kind: ElementKind::Vertex,
            id: String::new(),
            vertex: String::new(),
            position: String::new(),
        }
    }
}

/// A typed vertex id and position: three numbers, by spaces or commas.
fn parse_position(vertex: &str, position: &str) -> Result<(u32, [f32; 3]), String> {
    let vertex = vertex
        .trim()
        .parse::<u32>()
        .map_err(|_| format!("`{}` is not a vertex id", vertex.trim()))?;
    let numbers: Vec<f32> = position
        .split(|c: char| c == ',' || c.is_whitespace())
        .filter(|part| !part.is_empty())
        .map(|part| {
            part.parse::<f32>()
                .map_err(|_| format!("`{part}` is not a number"))
        })
        .collect::<Result<_, _>>()?;
    match numbers.as_slice() {
        [x, y, z] if x.is_finite() && y.is_finite() && z.is_finite() => Ok((vertex, [*x, *y, *z])),
        _ => Err(format!(
            "a position is three finite numbers, x y z; `{}` is not",
            position.trim()
        )),
    }
}

/// A shipped exercise by name, or an exercise file's text.
fn read_exercise(exercise: &str) -> Result<Exercise, CommandError> {
    if let Some(found) = catalog::find(exercise) {
        return found.map_err(|err| err.to_string().into());
    }
    if !exercise.contains('=') {
        return Err(format!(
            "no exercise is named `{exercise}`; the exercises are {} (or give an exercise's text)",
            catalog::names().join(", ")
        )
        .into());
    }
    if exercise.len() > MAX_EXERCISE_BYTES {
        return Err(format!(
            "the exercise is {} bytes; the most is {MAX_EXERCISE_BYTES}",
            exercise.len()
        )
        .into());
    }
    Exercise::parse("exercise", exercise).map_err(|err| err.to_string().into())
}

/// A seed for a fresh instance: from the clock, small enough to read out.
fn fresh_seed() -> u64 {
    let nanos = web_time::SystemTime::now()
        .duration_since(web_time::UNIX_EPOCH)
        .map_or(1, |d| u64::from(d.subsec_nanos()) ^ d.as_secs());
    nanos % 999_999 + 1
}
