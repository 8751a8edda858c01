//! Course links applied to the app, and the app's view written as one: the
//! Share dialog and `window.edgewise.shareUrl()`.
//!
//! A link is applied in the order a lecturer would set the view up: look
//! (theme, colours, embedding), mesh, algorithm and its inputs, step,
//! selection, camera, view options. Each part that cannot be followed adds a
//! message; the rest still applies, and the error panel lists what was
//! ignored.

use std::sync::Arc;

use edgewise_core::{
    formats::{self, Format, SaveOptions},
    lang::Value,
    mesh::Structure,
};

use super::{EdgewiseApp, embed::Embed, settings_ui::Presentation};
use crate::command::Command;
use edgewise_model::{
    algorithm::library::Origin,
    algorithm::session::Argument,
    course_link::{self, CourseLink, ExerciseLink, FetchedMesh, MeshSource, Panels, ThemeChoice},
    practice::catalog,
    selection::Role,
    settings::{self, Settings},
    trace_role::TraceRole,
};

impl EdgewiseApp {
    /// Applies a parsed link. `messages` are the parser's; `fetched` is the
    /// file a `?mesh=` path named, read by the caller (the browser fetches
    /// it). Returns every message, which the error panel also shows.
    pub fn apply_course_link(
        &mut self,
        link: &CourseLink,
        mut messages: Vec<String>,
        fetched: Option<FetchedMesh>,
    ) -> Vec<String> {
        self.apply_link_look(link);
        let structure = link.structure;
        let opened = match &link.mesh {
            None => Ok(()),
            Some(MeshSource::Sample(name)) => self.load_sample(name, structure),
            Some(MeshSource::Inline { text, format }) => {
                self.load_mesh(text.as_bytes(), &format!("link.{format}"), structure)
            }
            Some(MeshSource::Polygons(polygons)) => {
                let structure = structure.unwrap_or(self.tab().structure);
                let loaded = edgewise_model::document::Document::from_polygons(
                    "link.obj", polygons, structure,
                );
                self.open(loaded, true, false)
            }
            Some(MeshSource::Path(path)) => match fetched {
                Some(FetchedMesh {
                    name,
                    bytes: Ok(bytes),
                }) => self.load_mesh(&bytes, &name, structure),
                Some(FetchedMesh {
                    bytes: Err(err), ..
                }) => Err(format!("mesh={path}: {err}").into()),
                None => Err(format!("mesh={path}: the file was not fetched").into()),
            },
        };
        if let Err(message) = opened {
            messages.push(message.into());
        } else if link.mesh.is_none()
            && let Some(structure) = structure
            && let Err(message) = self.switch_structure(structure)
        {
            messages.push(message.into());
        }
        // What follows (an algorithm, a step, a selection) needs the mesh.
        self.finish_pending();

        link.follow(self, &mut messages);
        match &link.exercise {
            Some(exercise) => {
                if let Err(message) = self.start_exercise(exercise.as_str(), link.seed, None, None)
                {
                    messages.push(format!("exercise=: {message}"));
                }
            }
            None if link.seed.is_some() => {
                messages.push("seed= needs an exercise= to draw its instance from".to_owned());
            }
            None => {}
        }
        if let Some(camera) = link.camera {
            self.tab_mut().pane.view.set_camera(camera.sanitized());
        }
        link.apply_view_options(&mut self.view_options);

        self.tab_mut().error = (!messages.is_empty()).then(|| {
            format!(
                "Some of this link could not be followed; the rest is shown.\n{}",
                messages.join("\n")
            )
        });
        self.request_repaint();
        messages
    }

    /// Theme, colours, code size, embedding and presentation from a link.
    /// They apply to this visit only: the user's saved settings stay.
    fn apply_link_look(&mut self, link: &CourseLink) {
        let settings = link.look(&self.settings);
        if settings != self.settings {
            let (settings, message) = settings.sanitized();
            if let Some(message) = message {
                self.report(message);
            }
            self.theme = settings.theme();
            self.algorithms.code_size = settings.code_size;
            self.settings = settings;
        }
        if link.embed {
            self.set_embed(Some(Embed {
                tables: link.tables.unwrap_or(false),
            }));
        }
        if link.present {
            let panels = link.panels.unwrap_or(Panels {
                algorithm: true,
                tables: true,
                menu: false,
            });
            let presentation = Presentation {
                algorithm: panels.algorithm,
                tables: panels.tables,
                menu: panels.menu,
            };
            match self.ctx.clone() {
                Some(ctx) => self.enter_presentation(&ctx, presentation),
                None => self.presentation = Some(presentation),
            }
        }
    }

    /// The current view as a link: a sample by name or the mesh's own table
    /// text (so every id is reproduced), the algorithm with its inputs and
    /// step, the selection, camera and view options, and the look where it
    /// differs from the defaults.
    pub fn course_link(&self) -> CourseLink {
        let mut link = CourseLink::default();
        if let Some(document) = &self.tab().document {
            link.structure = Some(document.structure());
            link.mesh = Some(match &document.sample {
                Some(name) => MeshSource::Sample(name.clone()),
                None => {
                    let mesh = self.tab().mesh_before_trace();
                    let mesh = mesh.as_deref().unwrap_or(document.mesh());
                    match self.tab().exact_polygons(mesh) {
                        Some(polygons) => MeshSource::Polygons(polygons),
                        None => tables_source(mesh),
                    }
                }
            });
            link.selection = document.selection();
        }
        let run = self.tab().run.algorithm().map(|algorithm| {
            let inputs: Vec<(String, Value)> = match &self.tab().run.run {
                edgewise_model::algorithm::session::Run::Tracing(session) => algorithm
                    .params()
                    .zip(session.trace.initial_variables())
                    .map(|(p, v)| (p.name.clone(), v))
                    .collect(),
                edgewise_model::algorithm::session::Run::Picking(pending) => pending.inputs.clone(),
                edgewise_model::algorithm::session::Run::Idle => Vec::new(),
            };
            (Arc::clone(algorithm), inputs)
        });
        if let Some((algorithm, inputs)) = run {
            link.algorithm = Some(algorithm.name.clone());
            let user_made = self.algorithms.library.entries().iter().any(|e| {
                Arc::ptr_eq(&e.algorithm, &algorithm) && matches!(e.origin, Origin::User(_))
            });
            if user_made {
                link.algorithm_source = Some(algorithm.source.to_string());
            }
            link.questions = self
                .algorithms
                .question_sets
                .text_for(&algorithm)
                .map(str::to_owned);
            link.args = inputs
                .into_iter()
                .filter_map(|(name, value)| Some((name, argument_of(value)?)))
                .collect();
            link.step = self.tabs[self.active_tab]
                .run
                .session()
                .map(edgewise_model::algorithm::session::TraceSession::step);
            link.selection = None;
        }
        // An exercise's link opens the exercise at its instance: the mesh
        // is the instance's, not the student's tables.
        if let Some(session) = &self.tab().practice {
            let exercise = &session.exercise;
            let shipped = catalog::SHIPPED.iter().any(|e| e.name == exercise.name);
            link.exercise = Some(if shipped {
                ExerciseLink::Name(exercise.name.clone())
            } else {
                ExerciseLink::Text(exercise.text.clone())
            });
            link.seed = Some(session.instance.seed);
            link.mesh = None;
            link.structure = None;
            link.selection = None;
        }
        link.camera = Some(self.tab().pane.view.camera());
        link.set_view_options(&self.view_options);
        let defaults = Settings::default();
        if self.settings.dark != defaults.dark {
            link.theme = Some(if self.settings.dark {
                ThemeChoice::Dark
            } else {
                ThemeChoice::Light
            });
        }
        for (key, hex) in &self.settings.colours {
            let known = TraceRole::parse(key).is_some() || Role::from_setting_key(key).is_some();
            if let (true, Some(colour)) = (known, settings::parse_hex(hex)) {
                let [r, g, b, _] = colour.to_srgba_unmultiplied();
                link.colors.insert(key.clone(), [r, g, b]);
            }
        }
        if self.settings.code_size != defaults.code_size {
            link.code_size = Some(self.settings.code_size);
        }
        link
    }

    /// The absolute URL of the current view, given the page's own address.
    pub fn share_url(&self, base: &str) -> Result<String, String> {
        self.course_link().to_url_checked(base)
    }

    /// The embed code's size for what the embedded view will show, as the
    /// embedded app asks for it: 720 px wide, the view at 5:3, the step
    /// controls and the question card of a run, and the tables if asked.
    pub fn embed_size(&self, tables: bool) -> (u32, u32) {
        const WIDTH: f32 = 720.0;
        let mut chrome = 0.0;
        if let Some(session) = self.tab().run.session() {
            chrome += super::embed::CONTROLS_HEIGHT;
            if session.quiz.is_some() {
                chrome += crate::algorithm::panel::EMBED_CARD_HEIGHT;
            }
        }
        if tables {
            chrome += super::embed::TABLES_HEIGHT;
        }
        (
            WIDTH as u32,
            super::embed_events::preferred_height(WIDTH, chrome),
        )
    }

    /// The embed's title, which names the frame for screen readers and in
    /// the page's source: the mesh, and the algorithm and step of a run.
    pub fn embed_title(&self) -> String {
        let tab = self.tab();
        let Some(document) = &tab.document else {
            return "Edgewise: an interactive mesh view".to_owned();
        };
        let mesh = super::shown_name(&document.name, document.structure());
        match tab.run.session() {
            Some(session) => format!(
                "Edgewise: {} on {mesh}, step {} of {}",
                session.trace.algorithm().name,
                session.step(),
                session.steps()
            ),
            None => format!("Edgewise: {mesh}, {} tables", document.structure().prose()),
        }
    }

    /// The Share window: the link to copy, and an iframe snippet for notes.
    pub(super) fn share_window_ui(&mut self, ctx: &egui::Context) {
        if !self.show_share {
            return;
        }
        let base = crate::platform::page_base();
        // An open exercise is shared as the exercise: at its instance's
        // seed, or, ticked, with none, so that each student draws a fresh one.
        let fresh_id = egui::Id::unique("edgewise share fresh instance");
        let mut fresh = ctx.data(|d| d.get_temp::<bool>(fresh_id).unwrap_or(false));
        let exercise = self
            .tab()
            .practice
            .as_ref()
            .map(|session| (session.exercise.name.clone(), session.instance.seed));
        let url = match exercise {
            Some(_) if fresh => {
                let mut link = self.course_link();
                link.seed = None;
                link.to_url_checked(&base)
            }
            _ => self.share_url(&base),
        };
        let mut open = true;
        egui::Window::new("Share this view")
            .open(&mut open)
            .collapsible(false)
            .resizable(false)
            .show(ctx, |ui| {
                ui.set_max_width(520.0);
                let url = match url {
                    Ok(url) => url,
                    Err(message) => {
                        ui.colored_label(ui.visuals().error_fg_color, message);
                        return;
                    }
                };
                match &exercise {
                    Some((name, seed)) => {
                        ui.label(format!(
                            "Share as an exercise: this link opens {name} at {}.",
                            if fresh {
                                "a fresh instance for each student".to_owned()
                            } else {
                                format!("seed {seed}, the same instance for everyone")
                            }
                        ));
                        ui.checkbox(&mut fresh, "a fresh instance for each student");
                    }
                    None => {
                        ui.label(
                            "This link opens Edgewise on the same mesh, algorithm step, \
                             selection and camera.",
                        );
                    }
                }
                let mut shown = url.clone();
                let name = ui.weak("The link:");
                ui.add(
                    egui::TextEdit::multiline(&mut shown)
                        .desired_rows(3)
                        .desired_width(f32::INFINITY)
                        .font(egui::TextStyle::Monospace),
                )
                .labelled_by(name.id);
                ui.horizontal(|ui| {
                    if ui.button("Copy link").clicked() {
                        ui.ctx().copy_text(url.clone());
                        self.share_status = Some("Link copied.".to_owned());
                    }
                    if ui.button("Copy embed code").clicked() {
                        let mut embed = self.course_link();
                        embed.embed = true;
                        embed.tables = Some(self.share_embed_tables);
                        let snippet = embed.to_url_checked(&base).map(|url| {
                            let size = self.embed_size(self.share_embed_tables);
                            course_link::embed_snippet(&url, size, &self.embed_title())
                        });
                        match snippet {
                            Ok(snippet) => {
                                ui.ctx().copy_text(snippet);
                                self.share_status =
                                    Some("Embed code copied: paste it into your notes.".to_owned());
                            }
                            Err(message) => self.share_status = Some(message),
                        }
                    }
                    ui.checkbox(&mut self.share_embed_tables, "with the tables");
                });
                ui.separator();
                self.scorm_download_ui(ui);
                if let Some(status) = &self.share_status {
                    ui.weak(status.as_str());
                }
            });
        ctx.data_mut(|d| d.insert_temp(fresh_id, fresh));
        if !open {
            self.share_status = None;
        }
        self.show_share = open;
    }
}

/// The app follows a link's algorithm, step and selection through its
/// commands, as a user would.
impl course_link::Follow for EdgewiseApp {
    fn load_algorithms(&mut self, source: &str, file: &str) -> Result<(), String> {
        Ok(self.load_algorithms(source, file).map(drop)?)
    }

    fn run_algorithm(&mut self, name: &str, args: &[(String, Argument)]) -> Result<(), String> {
        Ok(self.run_algorithm(name, args)?)
    }

    fn set_questions(&mut self, text: &str) -> Result<(), String> {
        Ok(self
            .execute(Command::SetQuestions(text.to_owned()))
            .map(drop)?)
    }

    fn goto(&mut self, step: usize) -> Result<(), String> {
        Ok(self.trace_goto(step)?)
    }

    fn is_running(&self) -> bool {
        self.tab().run.is_active()
    }

    fn select(&mut self, element: edgewise_core::schema::ElementRef) -> Result<(), String> {
        Ok(self.select(Some(element))?)
    }
}

/// A link argument for a value: element ids and integers as numbers.
fn argument_of(value: Value) -> Option<Argument> {
    match value {
        Value::Vertex(i) | Value::Edge(i) | Value::Face(i) => Some(Argument::Number(f64::from(i))),
        Value::Integer(n) => Some(Argument::Number(f64::from(n))),
        Value::Float(x) => Some(Argument::Number(f64::from(x))),
        Value::Boolean(b) => Some(Argument::Boolean(b)),
        Value::Null | Value::Vector(_) | Value::Array(_) => None,
    }
}

/// The mesh as its own table text (`#mesh=`, `format=wtb` or `htb`): every
/// id as it is, whatever edits made of them.
fn tables_source(mesh: &edgewise_core::mesh::Mesh) -> MeshSource {
    let format = match mesh.structure() {
        Structure::WingedEdge => Format::Wtb,
        Structure::HalfEdge => Format::Htb,
    };
    let text = formats::save(mesh, format, &SaveOptions::default())
        .map(|bytes| String::from_utf8_lossy(&bytes).into_owned())
        .unwrap_or_default();
    MeshSource::Inline {
        text,
        format: format.extension().to_owned(),
    }
}
