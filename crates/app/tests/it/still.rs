//! The model's `Still`, which `edgewise render` draws from, makes the same
//! pictures as the app without a window: the same SVG and the same PDF
//! handout, byte for byte, for files, links, selections, runs, steps,
//! edits, questions and themes.

use edgewise_app::command::Command;
use edgewise_app::{EdgewiseApp, GraphicsBackend};
use edgewise_core::mesh::Structure;
use edgewise_core::schema::ElementRef;
use edgewise_model::algorithm::session::Argument;
use edgewise_model::course_link::{CourseLink, FetchedMesh};
use edgewise_model::selection::parse_element;
use edgewise_model::still::Still;

const QUESTIONS: &str = include_str!("../../../../algorithms/questions/vertex-adjacent-edge.txt");

/// One moment, set up as `edgewise render` sets it up.
#[derive(Default)]
struct Setup {
    file: Option<(&'static str, Option<Structure>)>,
    link: Option<&'static str>,
    questions: bool,
    dark: bool,
    algorithms: Option<&'static str>,
    run: Option<(&'static str, &'static [(&'static str, f64)])>,
    select: Option<&'static str>,
    step: Option<usize>,
    size: (f32, f32),
}

impl Setup {
    fn args(&self) -> Vec<(String, Argument)> {
        self.run
            .map(|(_, args)| {
                args.iter()
                    .map(|&(name, value)| (name.to_owned(), Argument::Number(value)))
                    .collect()
            })
            .unwrap_or_default()
    }

    fn link(&self) -> Option<CourseLink> {
        let (mut link, messages) = CourseLink::parse_url(self.link?);
        assert!(messages.is_empty(), "{messages:?}");
        if self.questions {
            link.questions = Some(QUESTIONS.to_owned());
        }
        Some(link)
    }

    fn selection(&self) -> Option<ElementRef> {
        self.select
            .map(|text| parse_element(text).expect("an element"))
    }

    fn app(&self) -> EdgewiseApp {
        let mut app = EdgewiseApp::with_backend(GraphicsBackend::None, None);
        if self.dark {
            let mut settings = app.settings().clone();
            settings.dark = true;
            app.set_settings(settings);
        }
        if let Some(link) = self.link() {
            let messages = app.apply_course_link(&link, Vec::new(), None::<FetchedMesh>);
            assert!(messages.is_empty(), "{messages:?}");
        }
        if let Some((file, structure)) = self.file {
            app.execute(Command::LoadMesh {
                bytes: read(file),
                name: file.to_owned(),
                structure,
                diagnose: false,
            })
            .expect("opens");
        }
        app.lay_out_offscreen(self.size.0, self.size.1);
        if let Some(file) = self.algorithms {
            app.load_algorithms(&String::from_utf8_lossy(&read(file)), file)
                .expect("compiles");
        }
        if let Some((name, _)) = self.run {
            app.run_algorithm(name, &self.args()).expect("runs");
            if app.state().trace.is_none() {
                app.execute(Command::Start).expect("starts");
            }
        }
        if let Some(element) = self.selection() {
            app.select(Some(element)).expect("selects");
        }
        if let Some(step) = self.step {
            app.trace_goto(step).expect("steps");
        }
        app.lay_out_offscreen(self.size.0, self.size.1);
        app
    }

    fn still(&self) -> Still {
        let mut still = Still::new(self.dark);
        if let Some(link) = self.link() {
            let messages = still.apply_link(&link, None);
            assert!(messages.is_empty(), "{messages:?}");
        }
        if let Some((file, structure)) = self.file {
            still
                .load_mesh(&read(file), file, structure)
                .expect("opens");
        }
        still.lay_out(self.size.0, self.size.1);
        if let Some(file) = self.algorithms {
            still
                .load_algorithms(&String::from_utf8_lossy(&read(file)), file)
                .expect("compiles");
        }
        if let Some((name, _)) = self.run {
            still.run_algorithm(name, &self.args()).expect("runs");
            if !still.is_traced() {
                still.start().expect("starts");
            }
        }
        if let Some(element) = self.selection() {
            still.select(Some(element)).expect("selects");
        }
        if let Some(step) = self.step {
            still.goto(step).expect("steps");
        }
        still
    }
}

fn read(file: &str) -> Vec<u8> {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../..")
        .join(file);
    std::fs::read(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

fn same_svg(setup: &Setup) -> String {
    let from_app = setup.app().export_svg().expect("the app exports");
    let from_still = setup.still().svg().expect("the still exports");
    assert!(
        from_app == from_still,
        "the pictures differ:\n--- app\n{from_app}\n--- still\n{from_still}"
    );
    from_app
}

fn same_handout(setup: &Setup) -> Vec<u8> {
    let (_, from_app) = setup.app().export_handout().expect("the app exports");
    let (_, from_still) = setup.still().handout().expect("the still exports");
    assert!(from_app == from_still, "the handouts differ");
    from_app
}

#[test]
fn a_selection_is_the_same_picture() {
    let svg = same_svg(&Setup {
        file: Some(("meshes/tetrahedron.wtb", None)),
        select: Some("e0"),
        size: (640.0, 480.0),
        ..Setup::default()
    });
    assert!(svg.contains("Edge 0 selected:"), "{svg}");
}

#[test]
fn a_link_with_a_step_and_questions_is_the_same_picture() {
    let svg = same_svg(&Setup {
        link: Some(
            "https://example.edu/edgewise/?sample=tetrahedron&algorithm=vertexAdjacentEdge&args=v:1&step=12&theme=dark",
        ),
        questions: true,
        size: (800.0, 600.0),
        ..Setup::default()
    });
    assert!(svg.contains("Step 12 of 22"), "{svg}");
    assert!(svg.contains("Question: Now e starts at v."), "{svg}");
    let plain = same_svg(&Setup {
        link: Some(
            "https://example.edu/edgewise/?sample=cube&ids=always&solid=1&camera=0.5,0.3,4,0.1,0,0&colors=selected:ff0000&select=vertex:3&orientation=1",
        ),
        size: (700.0, 500.0),
        ..Setup::default()
    });
    assert!(plain.contains("Vertex 3 selected:"), "{plain}");
}

#[test]
fn an_editing_run_is_the_same_picture_and_handout() {
    let setup = Setup {
        file: Some(("meshes/octahedron.obj", Some(Structure::HalfEdge))),
        algorithms: Some("algorithms/half-edge-edits.alg"),
        run: Some(("flipEdge", &[("h", 0.0)])),
        size: (800.0, 600.0),
        ..Setup::default()
    };
    let handout = same_handout(&setup);
    assert!(handout.starts_with(b"%PDF-"));
    same_svg(&Setup {
        step: Some(30),
        ..setup
    });
}

#[test]
fn a_dark_run_in_the_other_structure_is_the_same_picture_and_handout() {
    let setup = Setup {
        file: Some(("meshes/icosahedron.ply", Some(Structure::HalfEdge))),
        run: Some(("vertexStar", &[("v", 0.0)])),
        dark: true,
        size: (400.0, 300.0),
        ..Setup::default()
    };
    same_handout(&setup);
    same_svg(&Setup {
        step: Some(3),
        ..setup
    });
}
