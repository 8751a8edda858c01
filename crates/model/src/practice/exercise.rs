//! The exercise format: a TOML file a lecturer writes (docs/practice.md has
//! its grammar and examples). Reading one checks everything an instance
//! will need, so that a bad file is refused with the line and column of
//! the key at fault before a student ever opens it.

use std::ops::Range;

use edgewise_core::mesh::operations::Operation;
use edgewise_core::mesh::{Mesh, Polygons, Structure, generate};
use serde::Deserialize;
use toml::Spanned;

pub use super::error::ExerciseError;
use super::error::Located;
use super::walk::{Walk, WalkFile};
use crate::document::Document;
use crate::samples;

/// The largest mesh a generator may make, in faces: an exercise is done by
/// hand, and a hostile file must not make the page build a huge mesh.
const MAX_GENERATED_FACES: u64 = 20_000;

/// What the student does.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Kind {
    /// Carries out a local operation on the tables, cell by cell.
    DoIt,
    /// Clicks the elements an algorithm marks.
    Walk,
    /// Says what each lookup of an algorithm gives, before it runs.
    Predict,
}

impl Kind {
    pub fn name(self) -> &'static str {
        match self {
            Self::DoIt => "do-it",
            Self::Walk => "walk",
            Self::Predict => "predict",
        }
    }
}

/// When the student is told whether a step is right.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Feedback {
    /// After every write.
    Live,
    /// When the student presses Check.
    #[default]
    OnCheck,
    /// Only once the attempt is over.
    AtEnd,
}

impl Feedback {
    pub fn name(self) -> &'static str {
        match self {
            Self::Live => "live",
            Self::OnCheck => "on-check",
            Self::AtEnd => "at-end",
        }
    }
}

/// The file as written.
#[derive(Deserialize)]
#[serde(deny_unknown_fields, rename_all = "kebab-case")]
struct File {
    title: String,
    kind: Kind,
    structure: Spanned<String>,
    #[serde(default)]
    about: Option<String>,
    #[serde(default = "one")]
    points: u32,
    #[serde(default)]
    attempts: u32,
    #[serde(default)]
    feedback: Feedback,
    #[serde(default = "yes")]
    model_answer: bool,
    #[serde(default = "yes")]
    fresh_instance: bool,
    mesh: Spanned<MeshFile>,
    #[serde(default)]
    do_it: Option<Spanned<DoItFile>>,
    #[serde(default)]
    walk: Option<Spanned<WalkFile>>,
    #[serde(default)]
    predict: Option<Spanned<WalkFile>>,
}

fn one() -> u32 {
    1
}

fn yes() -> bool {
    true
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct MeshFile {
    #[serde(default)]
    sample: Option<Spanned<String>>,
    #[serde(default)]
    text: Option<String>,
    #[serde(default)]
    format: Option<Spanned<String>>,
    #[serde(default)]
    generator: Option<Spanned<String>>,
    #[serde(default)]
    size: Option<Spanned<Vec<u32>>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct DoItFile {
    operation: Spanned<String>,
    #[serde(default)]
    ids: Option<Spanned<Vec<u32>>>,
}

/// Where the mesh of every instance comes from.
#[derive(Clone, Debug)]
pub enum MeshSource {
    Sample(String),
    Text { text: String, name: String },
    Generated(Generator),
}

/// A generated mesh with its parameters.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Generator {
    Tetrahedron,
    Cube,
    OpenSquare,
    Grid(u32, u32),
    Torus(u32, u32),
    Icosphere(u32),
}

impl Generator {
    fn polygons(self) -> Polygons {
        match self {
            Self::Tetrahedron => generate::tetrahedron(),
            Self::Cube => generate::cube(),
            Self::OpenSquare => generate::open_square(),
            Self::Grid(nx, ny) => generate::grid(nx, ny),
            Self::Torus(nu, nv) => generate::torus(nu, nv),
            Self::Icosphere(levels) => generate::icosphere(levels),
        }
    }
}

/// A do-it task as the file gives it: the operation, and the ids of the
/// lecturer's own instance (seed 0) if the file names them.
#[derive(Clone, Debug)]
pub struct DoIt {
    pub operation: Operation,
    pub ids: Option<Vec<u32>>,
}

/// What an exercise asks, as its file gives it.
#[derive(Clone, Debug)]
pub enum TaskSpec {
    DoIt(DoIt),
    Walk(Walk),
}

/// An exercise, read and checked.
#[derive(Clone, Debug)]
pub struct Exercise {
    /// The shipped name, or the file's stem.
    pub name: String,
    pub title: String,
    pub kind: Kind,
    pub structure: Structure,
    /// Prose shown above the task.
    pub about: Option<String>,
    pub points: u32,
    /// Attempts allowed; 0 is no limit.
    pub attempts: u32,
    pub feedback: Feedback,
    pub model_answer: bool,
    /// Whether each attempt draws a new instance.
    pub fresh_instance: bool,
    pub mesh: MeshSource,
    pub task: TaskSpec,
    /// The file's text, for a link that carries the exercise.
    pub text: String,
    /// The start mesh, built once.
    start: Mesh,
}

impl Exercise {
    /// Reads an exercise from its text; `name` is how messages and scores
    /// name it.
    pub fn parse(name: &str, text: &str) -> Result<Self, ExerciseError> {
        let at = Located::new(name, text);
        let file: File = toml::from_str(text)
            .map_err(|err| at.error(err.span(), err.message().trim_end().to_owned()))?;
        let structure = match file.structure.get_ref().as_str() {
            "half-edge" => Structure::HalfEdge,
            "winged-edge" => Structure::WingedEdge,
            other => {
                return Err(at.error(
                    Some(file.structure.span()),
                    format!("structure `{other}` is not one of half-edge, winged-edge"),
                ));
            }
        };
        let mesh_span = file.mesh.span();
        let mesh = mesh_source(&at, file.mesh.into_inner(), mesh_span.clone())?;
        let spans = [
            ("do-it", file.do_it.as_ref().map(Spanned::span)),
            ("walk", file.walk.as_ref().map(Spanned::span)),
            ("predict", file.predict.as_ref().map(Spanned::span)),
        ];
        let kind = file.kind;
        let task = match kind {
            Kind::DoIt => TaskSpec::DoIt(do_it(&at, table(&at, kind, file.do_it, &spans)?)?),
            Kind::Walk => TaskSpec::Walk(Walk::parse(
                &at,
                table(&at, kind, file.walk, &spans)?,
                structure,
                false,
            )?),
            Kind::Predict => TaskSpec::Walk(Walk::parse(
                &at,
                table(&at, kind, file.predict, &spans)?,
                structure,
                true,
            )?),
        };
        let start =
            build(&mesh, structure).map_err(|message| at.error(Some(mesh_span), message))?;
        Ok(Self {
            name: name.to_owned(),
            title: file.title,
            kind: file.kind,
            structure,
            about: file.about,
            points: file.points,
            attempts: file.attempts,
            feedback: file.feedback,
            model_answer: file.model_answer,
            fresh_instance: file.fresh_instance,
            mesh,
            task,
            text: text.to_owned(),
            start,
        })
    }

    /// The mesh every instance starts from.
    pub fn start(&self) -> &Mesh {
        &self.start
    }
}

/// The task table of `kind`'s exercise, refusing the other kinds' tables.
fn table<T>(
    at: &Located<'_>,
    kind: Kind,
    wanted: Option<Spanned<T>>,
    spans: &[(&str, Option<Range<usize>>)],
) -> Result<T, ExerciseError> {
    if let Some((other, span)) = spans
        .iter()
        .find(|(name, span)| *name != kind.name() && span.is_some())
    {
        return Err(at.error(
            span.clone(),
            format!(
                "a {} exercise has a [{}] table, not [{other}]",
                kind.name(),
                kind.name()
            ),
        ));
    }
    wanted.map(Spanned::into_inner).ok_or_else(|| {
        at.error(
            None,
            format!("a {} exercise needs a [{}] table", kind.name(), kind.name()),
        )
    })
}

fn mesh_source(
    at: &Located<'_>,
    mesh: MeshFile,
    span: Range<usize>,
) -> Result<MeshSource, ExerciseError> {
    match (mesh.sample, mesh.text, mesh.generator) {
        (Some(sample), None, None) => {
            if samples::find(sample.get_ref()).is_none() {
                let names: Vec<&str> = samples::SAMPLES.iter().map(|s| s.name).collect();
                return Err(at.error(
                    Some(sample.span()),
                    format!(
                        "there is no sample called `{}`; the samples are: {}",
                        sample.get_ref(),
                        names.join(", ")
                    ),
                ));
            }
            Ok(MeshSource::Sample(sample.into_inner()))
        }
        (None, Some(text), None) => {
            let format = mesh
                .format
                .as_ref()
                .map_or_else(|| "obj".to_owned(), |f| f.get_ref().clone());
            if !["obj", "ply", "wtb", "htb"].contains(&format.as_str()) {
                return Err(at.error(
                    mesh.format.as_ref().map(Spanned::span),
                    format!("format `{format}` is not one of obj, ply, wtb, htb"),
                ));
            }
            Ok(MeshSource::Text {
                text,
                name: format!("{}.{format}", at.source),
            })
        }
        (None, None, Some(generator)) => Ok(MeshSource::Generated(self::generator(
            at,
            &generator,
            mesh.size.as_ref(),
        )?)),
        _ => Err(at.error(
            Some(span),
            "[mesh] needs exactly one of `sample`, `text` or `generator`",
        )),
    }
}

fn generator(
    at: &Located<'_>,
    name: &Spanned<String>,
    size: Option<&Spanned<Vec<u32>>>,
) -> Result<Generator, ExerciseError> {
    let sizes = size.map_or(&[][..], |s| s.get_ref().as_slice());
    let size_span = size.map(Spanned::span).or_else(|| Some(name.span()));
    let pair = |what: &str| match sizes {
        [a, b] if *a >= 1 && *b >= 1 => Ok((*a, *b)),
        _ => Err(at.error(
            size_span.clone(),
            format!("the {what} generator needs `size = [columns, rows]`, each at least 1"),
        )),
    };
    let generated = match name.get_ref().as_str() {
        "tetrahedron" => Generator::Tetrahedron,
        "cube" => Generator::Cube,
        "open-square" => Generator::OpenSquare,
        "grid" => {
            let (nx, ny) = pair("grid")?;
            Generator::Grid(nx, ny)
        }
        "torus" => {
            let (nu, nv) = pair("torus")?;
            if nu < 3 || nv < 3 {
                return Err(at.error(size_span, "a torus needs at least 3 × 3 vertices"));
            }
            Generator::Torus(nu, nv)
        }
        "icosphere" => match sizes {
            [levels] if *levels <= 5 => Generator::Icosphere(*levels),
            _ => {
                return Err(at.error(
                    size_span,
                    "the icosphere generator needs `size = [levels]`, 0 to 5",
                ));
            }
        },
        other => {
            return Err(at.error(
                Some(name.span()),
                format!(
                    "there is no generator `{other}`; the generators are tetrahedron, cube, \
                     open-square, grid, torus, icosphere"
                ),
            ));
        }
    };
    let faces = match generated {
        Generator::Grid(a, b) => u64::from(a) * u64::from(b),
        Generator::Torus(a, b) => 2 * u64::from(a) * u64::from(b),
        _ => 0,
    };
    if faces > MAX_GENERATED_FACES {
        return Err(at.error(
            size_span,
            format!("that makes {faces} faces; an exercise mesh may have {MAX_GENERATED_FACES}"),
        ));
    }
    Ok(generated)
}

fn do_it(at: &Located<'_>, task: DoItFile) -> Result<DoIt, ExerciseError> {
    let operation = Operation::parse(task.operation.get_ref())
        .map_err(|err| at.error(Some(task.operation.span()), err.to_string()))?;
    let ids = match task.ids {
        None => None,
        Some(ids) => {
            let arguments = operation.arguments();
            let least = arguments.iter().filter(|a| !a.optional).count();
            let given = ids.get_ref().len();
            if given < least || given > arguments.len() {
                let roles: Vec<String> = arguments.iter().map(ToString::to_string).collect();
                return Err(at.error(
                    Some(ids.span()),
                    format!(
                        "{operation} takes {} ({}); `ids` gives {given}",
                        if least == arguments.len() {
                            least.to_string()
                        } else {
                            format!("{least} to {}", arguments.len())
                        },
                        roles.join(", ")
                    ),
                ));
            }
            Some(ids.into_inner())
        }
    };
    Ok(DoIt { operation, ids })
}

/// The start mesh in `structure`.
fn build(source: &MeshSource, structure: Structure) -> Result<Mesh, String> {
    let document = match source {
        MeshSource::Sample(name) => samples::open(name, Some(structure), structure)?,
        MeshSource::Text { text, name } => Document::load(text.as_bytes(), name, structure)?,
        MeshSource::Generated(generator) => {
            Document::from_polygons("generated", &generator.polygons(), structure)?
        }
    };
    Ok(document.mesh().clone())
}
