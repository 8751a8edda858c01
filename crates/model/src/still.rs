//! One moment of Edgewise set up without a window: a mesh, its look, an
//! algorithm's run at a step or a selection, and a camera framing it in a
//! view of a given size. `edgewise render` draws its pictures from one. The
//! pictures are made by [`crate::moment`] and the steps are those the app
//! takes (the same loaders, argument reading, questions and paint), so a
//! script's picture is byte for byte what the app's Save menu writes.

use std::sync::Arc;

use edgewise_core::mesh::{Issue, Structure};
use edgewise_core::schema::ElementRef;
use edgewise_pictures::camera::{Camera, ViewTransforms};
use edgewise_pictures::geometry::MeshGeometry;
use edgewise_pictures::options::ViewOptions;
use edgewise_pictures::scene::Scene;
use edgewise_pictures::styles::SceneStyles;
use edgewise_pictures::vector::{self, Looks, VectorView};
use emath::{Pos2, Rect, vec2};

use crate::algorithm::library::AlgorithmLibrary;
use crate::algorithm::question_sets::QuestionSets;
use crate::algorithm::run::AlgorithmRun;
use crate::algorithm::session::{Argument, argument_inputs};
use crate::course_link::{CourseLink, FetchedMesh, Follow, MeshSource};
use crate::document::{Document, FIRST_STRUCTURE, structure_for};
use crate::message::{message_line, run_message};
use crate::moment::{self, Marks};
use crate::paint::{MOST_MARKED, scene_styles};
use crate::settings::Settings;
use crate::theme::Theme;

/// One moment, set up step by step as the app would be.
pub struct Still {
    settings: Settings,
    theme: Theme,
    options: ViewOptions,
    library: AlgorithmLibrary,
    /// A link's question set.
    questions: QuestionSets,
    document: Option<Document>,
    run: AlgorithmRun,
    /// How many of an editing run's changes the document's mesh has.
    applied: usize,
    broken: Vec<Issue>,
    /// Set by a link, or framing the mesh once the view has a size.
    camera: Option<Camera>,
    viewport: Option<Rect>,
}

impl Still {
    /// An empty moment in the light or dark theme.
    pub fn new(dark: bool) -> Self {
        let settings = Settings {
            dark,
            ..Settings::default()
        };
        Self {
            theme: settings.theme(),
            settings,
            options: ViewOptions::default(),
            library: AlgorithmLibrary::shipped(),
            questions: QuestionSets::default(),
            document: None,
            run: AlgorithmRun::default(),
            applied: 0,
            broken: Vec::new(),
            camera: None,
            viewport: None,
        }
    }

    /// Opens mesh bytes; `name`'s extension (or the content) gives the
    /// format, and `structure` the structure to build PLY and OBJ as.
    pub fn load_mesh(
        &mut self,
        bytes: &[u8],
        name: &str,
        structure: Option<Structure>,
    ) -> Result<(), String> {
        let structure = structure.unwrap_or_else(|| structure_for(name, FIRST_STRUCTURE));
        self.show(Document::load(bytes, name, structure)?);
        Ok(())
    }

    fn show(&mut self, document: Document) {
        self.document = Some(document);
        self.run = AlgorithmRun::default();
        self.applied = 0;
        self.broken.clear();
        self.camera = None;
    }

    /// Applies a parsed link in the app's order (look, mesh, algorithm and
    /// its inputs, questions, step, selection, camera, view options);
    /// returns a message for each part that could not be followed.
    pub fn apply_link(&mut self, link: &CourseLink, fetched: Option<FetchedMesh>) -> Vec<String> {
        let mut messages = Vec::new();
        self.apply_look(link);
        let structure = link.structure;
        let opened = match &link.mesh {
            None => Ok(()),
            Some(MeshSource::Sample(name)) => {
                crate::samples::open(name, structure, FIRST_STRUCTURE).map(|d| self.show(d))
            }
            Some(MeshSource::Inline { text, format }) => {
                self.load_mesh(text.as_bytes(), &format!("link.{format}"), structure)
            }
            Some(MeshSource::Polygons(polygons)) => {
                Document::from_polygons("link.obj", polygons, structure.unwrap_or(FIRST_STRUCTURE))
                    .map(|d| self.show(d))
            }
            Some(MeshSource::Path(path)) => match fetched {
                Some(FetchedMesh {
                    name,
                    bytes: Ok(bytes),
                }) => self.load_mesh(&bytes, &name, structure),
                Some(FetchedMesh {
                    bytes: Err(err), ..
                }) => Err(format!("mesh={path}: {err}")),
                None => Err(format!("mesh={path}: the file was not fetched")),
            },
        };
        if let Err(message) = opened {
            messages.push(message);
        } else if link.mesh.is_none()
            && let Some(structure) = structure
            && let Err(message) = self.switch_structure(structure)
        {
            messages.push(message);
        }
        link.follow(self, &mut messages);
        if let Some(camera) = link.camera {
            self.camera = Some(camera.sanitized());
        }
        link.apply_view_options(&mut self.options);
        messages
    }

    /// A link's theme and colours, for this moment only.
    fn apply_look(&mut self, link: &CourseLink) {
        let settings = link.look(&self.settings);
        if settings != self.settings {
            let (settings, _) = settings.sanitized();
            self.theme = settings.theme();
            self.settings = settings;
        }
    }

    fn switch_structure(&mut self, structure: Structure) -> Result<(), String> {
        let Some(document) = &mut self.document else {
            return Ok(());
        };
        document.switch_structure(structure)?;
        self.run = AlgorithmRun::default();
        Ok(())
    }

    /// Adds the algorithms of `source` (named `file` in messages).
    pub fn load_algorithms(&mut self, source: &str, file: &str) -> Result<(), String> {
        self.library.load(source, file).map(drop)
    }

    /// Starts `name` on the mesh with `args`: it runs at once, or waits
    /// for inputs ([`Self::start`] says which).
    pub fn run_algorithm(&mut self, name: &str, args: &[(String, Argument)]) -> Result<(), String> {
        let Some(document) = &mut self.document else {
            return Err("open a mesh before running an algorithm".to_owned());
        };
        let algorithm = self.library.find_or_explain(name, document.structure())?;
        let inputs = argument_inputs(&algorithm, args)?;
        document.select(None)?;
        let result = self
            .run
            .begin(Arc::clone(&algorithm), &inputs, document.mesh());
        self.questions.pose(&mut self.run);
        result
    }

    /// Runs the algorithm waiting for its inputs with those it has.
    pub fn start(&mut self) -> Result<(), String> {
        let Some(document) = &self.document else {
            return Err("open a mesh before running an algorithm".to_owned());
        };
        let result = self.run.start(document.mesh());
        self.questions.pose(&mut self.run);
        result
    }

    /// The steps of the traced run, if there is one.
    pub fn steps(&self) -> Option<usize> {
        self.run
            .session()
            .map(crate::algorithm::session::TraceSession::steps)
    }

    /// Moves the run to step `k` (clamped), and an editing run's mesh with
    /// it.
    pub fn goto(&mut self, k: usize) -> Result<(), String> {
        self.run.goto(k)?;
        self.sync_edit()
    }

    /// Keeps the mesh at an editing run's step, marking what the changes
    /// so far break, as the app's tab does.
    fn sync_edit(&mut self) -> Result<(), String> {
        let (Some(document), Some(session)) = (&mut self.document, self.run.session()) else {
            return Ok(());
        };
        let wanted = session.changes_wanted();
        if !session.edits() || wanted == self.applied {
            return Ok(());
        }
        let result = document.seek(&session.trace, self.applied, wanted);
        self.applied = wanted;
        self.broken = document.mesh().validate();
        self.broken.truncate(MOST_MARKED);
        result
    }

    /// Selects an element, or clears the selection.
    pub fn select(&mut self, element: Option<ElementRef>) -> Result<(), String> {
        match &mut self.document {
            Some(document) => document.select(element),
            None if element.is_some() => Err("no mesh is open".to_owned()),
            None => Ok(()),
        }
    }

    /// Gives the view its size, `width` by `height` points; the camera
    /// frames the mesh unless a link placed it.
    pub fn lay_out(&mut self, width: f32, height: f32) {
        let viewport = Rect::from_min_size(Pos2::ZERO, vec2(width, height));
        self.viewport = Some(viewport);
        if self.camera.is_none()
            && let Some(document) = &self.document
        {
            let mut camera = Camera::default();
            Scene::new(MeshGeometry::from_mesh(document.mesh()))
                .frame(&mut camera, viewport.aspect_ratio());
            self.camera = Some(camera);
        }
        self.options.dark = self.theme.dark;
        self.options.boundary = self.theme.boundary_override;
    }

    /// Whether an algorithm's run is traced.
    pub fn is_traced(&self) -> bool {
        self.run.session().is_some()
    }

    /// The SVG of the moment: the view and the tables, and the message
    /// line as the caption.
    pub fn svg(&self) -> Result<String, String> {
        let document = self
            .document
            .as_ref()
            .ok_or("open a mesh before exporting a picture of it")?;
        moment::check_picture_size(document)?;
        // The step's frame, derived once for both the colours and the caption.
        let frame = self.run.current_frame(&self.theme);
        let marks = Marks {
            last_changes: &[],
            broken: &self.broken,
        };
        let paint = moment::moment_paint(
            document,
            frame.as_deref(),
            self.is_traced(),
            marks,
            &self.theme,
        );
        let styles = scene_styles(document.mesh(), &paint, 0);
        let scene = Scene::new(MeshGeometry::from_mesh(document.mesh()));
        let view = self.view(&scene, &scene, &styles)?;
        let caption = message_line(document, run_message(&self.run.run, frame.as_deref()), None);
        Ok(moment::svg_picture(
            document,
            self.run
                .algorithm()
                .map(|algorithm| algorithm.name.as_str()),
            Some(caption),
            &paint,
            &view,
        ))
    }

    /// A PDF handout of the run, a page per step; its file name and bytes.
    pub fn handout(&self) -> Result<(String, Vec<u8>), String> {
        let (Some(document), Some(session)) = (&self.document, self.run.session()) else {
            return Err("run an algorithm first: a handout has a page per step of its run".into());
        };
        let scene = Scene::new(MeshGeometry::from_mesh(document.mesh()));
        let view_of = |geometry: Option<MeshGeometry>, styles: &SceneStyles| match geometry {
            Some(geometry) => self.view(&Scene::new(geometry), &scene, styles).ok(),
            None => self.view(&scene, &scene, styles).ok(),
        };
        moment::handout(document, session, self.applied, &self.theme, view_of)
    }

    /// `scene` in `styles` as vector shapes, seen by the camera with the
    /// depth range of `framing` (the view's own mesh), as the app's view
    /// draws another moment.
    fn view(
        &self,
        scene: &Scene,
        framing: &Scene,
        styles: &SceneStyles,
    ) -> Result<VectorView, String> {
        let (Some(camera), Some(viewport)) = (self.camera, self.viewport) else {
            return Err("the view has no size yet: lay it out first".to_owned());
        };
        let transforms = ViewTransforms::new(camera, viewport, framing.center, framing.radius);
        let looks = Looks {
            styles: &styles.elements,
            fade_others: styles.fade_others,
        };
        Ok(vector::vector_view(
            scene,
            &looks,
            &transforms,
            &self.options,
        ))
    }
}

impl Follow for Still {
    fn load_algorithms(&mut self, source: &str, file: &str) -> Result<(), String> {
        Still::load_algorithms(self, source, file)
    }

    fn run_algorithm(&mut self, name: &str, args: &[(String, Argument)]) -> Result<(), String> {
        Still::run_algorithm(self, name, args)
    }

    fn set_questions(&mut self, text: &str) -> Result<(), String> {
        self.questions.set(&mut self.run, text)
    }

    fn goto(&mut self, step: usize) -> Result<(), String> {
        Still::goto(self, step)
    }

    fn is_running(&self) -> bool {
        self.run.is_active()
    }

    fn select(&mut self, element: ElementRef) -> Result<(), String> {
        Still::select(self, Some(element))
    }
}
