//! `edgewise render`: the app's pictures from the command line, for
//! scripted course material. A [`Still`] sets the moment up as the app
//! would, without a window or a GPU, and the pictures come from the same
//! code as the app's, so a handout made here is the same file as the one
//! its Save menu makes.

use std::path::Path;

use edgewise_core::mesh::Structure;
use edgewise_model::algorithm::session::Argument;
use edgewise_model::course_link::{CourseLink, FetchedMesh, MeshSource};
use edgewise_model::still::Still;

use super::{Failure, Outcome, StructureArg, emit, read_bytes, read_text, shown};

/// The smallest and largest view, in points on a side.
const SIDE: (f32, f32) = (120.0, 4096.0);

/// What `edgewise render` was asked for.
pub struct Request<'a> {
    pub output: &'a Path,
    pub meshfile: Option<&'a Path>,
    pub link: Option<&'a str>,
    pub structure: Option<StructureArg>,
    pub algfile: Option<&'a Path>,
    pub run: Option<&'a str>,
    pub args: &'a [String],
    pub step: Option<usize>,
    pub select: Option<&'a str>,
    pub size: &'a str,
    pub dark: bool,
}

/// What the output's extension asks for.
enum Picture {
    /// The view and the tables at one moment.
    Svg,
    /// A page per step of the run.
    Handout,
}

/// Reports a refusal from the app that names its own place (a file's
/// `name:line:column`).
fn reported(error: impl std::fmt::Display) -> Failure {
    eprintln!("{error}");
    Failure::Input
}

/// Reports a refusal from the app, naming the option it came from.
fn refused(place: &str, error: impl std::fmt::Display) -> Failure {
    eprintln!("{place}: {error}");
    Failure::Input
}

fn usage(message: impl std::fmt::Display) -> Failure {
    eprintln!("edgewise: {message}");
    Failure::Usage
}

/// Reads `WIDTHxHEIGHT` in points.
fn parse_size(text: &str) -> Result<(f32, f32), Failure> {
    let side = |part: &str| {
        part.trim()
            .parse::<f32>()
            .ok()
            .filter(|x| (SIDE.0..=SIDE.1).contains(x))
    };
    let parsed = text
        .split_once(['x', 'X'])
        .and_then(|(w, h)| Some((side(w)?, side(h)?)));
    parsed.ok_or_else(|| {
        usage(format!(
            "--size {text}: expected WIDTHxHEIGHT in points, each from {} to {}, such as 800x600",
            SIDE.0, SIDE.1
        ))
    })
}

/// Draws what `request` asks for and writes it.
pub fn render(request: &Request<'_>) -> Outcome {
    let picture = match request
        .output
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase)
        .as_deref()
    {
        Some("svg") => Picture::Svg,
        Some("pdf") => Picture::Handout,
        _ => {
            return Err(usage(format!(
                "{}: expected an output ending in .svg (the view and the tables at one step) \
                 or .pdf (a handout of the run, a page per step)",
                request.output.display()
            )));
        }
    };
    if request.meshfile.is_none() && request.link.is_none() {
        return Err(usage(
            "give a mesh file, or a course link with --link that names one",
        ));
    }
    let (width, height) = parse_size(request.size)?;
    let mut args: Vec<(String, Argument)> = Vec::with_capacity(request.args.len());
    for arg in request.args {
        let parsed = arg.split_once('=').and_then(|(name, value)| {
            Some((name.trim().to_owned(), Argument::parse(value.trim())?))
        });
        args.push(parsed.ok_or_else(|| {
            usage(format!(
                "--arg {arg}: expected NAME=VALUE with a number (an element's id) or \
                 true/false, such as --arg v=1"
            ))
        })?);
    }
    if request.run.is_none() && (!args.is_empty() || request.algfile.is_some()) {
        return Err(usage(
            "--alg and --arg need --run NAME: the algorithm to run",
        ));
    }
    let selection = request
        .select
        .map(|text| {
            edgewise_model::selection::parse_element(text)
                .map_err(|e| usage(format!("--select: {e}")))
        })
        .transpose()?;

    let mut still = Still::new(request.dark);
    let structure = request.structure.map(Structure::from);
    match request.link {
        Some(link) => open_link(&mut still, link, request.meshfile, structure)?,
        None => {
            if let Some(path) = request.meshfile {
                let bytes = read_bytes(path)?;
                still
                    .load_mesh(&bytes, &shown(path), structure)
                    .map_err(reported)?;
            }
        }
    }
    still.lay_out(width, height);

    if let Some(path) = request.algfile {
        let source = read_text(path)?;
        still
            .load_algorithms(&source, &shown(path))
            .map_err(reported)?;
    }
    if let Some(name) = request.run {
        still
            .run_algorithm(name, &args)
            .map_err(|e| refused("--run", e))?;
        if !still.is_traced() {
            // Still waiting for inputs: starting says which.
            still.start().map_err(|e| {
                refused(
                    "--arg",
                    format!("{e}; give each input as --arg NAME=VALUE, such as --arg v=1"),
                )
            })?;
        }
    }
    if let Some(element) = selection {
        still
            .select(Some(element))
            .map_err(|e| refused("--select", e))?;
    }
    if let Some(step) = request.step {
        let steps = still.steps().ok_or_else(|| {
            usage("--step needs a run: give --run NAME, or a link with algorithm=")
        })?;
        if step > steps {
            return Err(usage(format!(
                "--step {step}: the run has steps 0 to {steps}"
            )));
        }
        still.goto(step).map_err(|e| refused("--step", e))?;
    }
    if matches!(picture, Picture::Handout) && !still.is_traced() {
        return Err(usage(
            "a .pdf handout has a page per step of a run: give --run NAME, or a link with algorithm=",
        ));
    }
    let bytes = match picture {
        Picture::Svg => still.svg().map(String::into_bytes),
        Picture::Handout => still.handout().map(|(_, bytes)| bytes),
    }
    .map_err(|e| refused(&request.output.display().to_string(), e))?;
    std::fs::write(request.output, &bytes).map_err(|error| {
        eprintln!(
            "{}: cannot write the file: {error}",
            request.output.display()
        );
        Failure::Input
    })?;
    emit(&format!(
        "wrote {} ({} bytes)\n",
        request.output.display(),
        bytes.len()
    ));
    Ok(())
}

/// Opens `link` as the app opens a course link. A `mesh=` path in it is
/// read from `meshfile` when one is given, else from that path under the
/// current folder (a link's paths never leave it: they are relative, with
/// no `..`).
fn open_link(
    still: &mut Still,
    link: &str,
    meshfile: Option<&Path>,
    structure: Option<Structure>,
) -> Result<(), Failure> {
    let (mut parsed, messages) = CourseLink::parse_url(link);
    link_refused(&messages)?;
    if structure.is_some() {
        parsed.structure = structure;
    }
    let fetched = match (&parsed.mesh, meshfile) {
        (Some(MeshSource::Path(_)) | None, Some(path)) => {
            if parsed.mesh.is_none() {
                parsed.mesh = Some(MeshSource::Path(shown(path)));
            }
            Some(FetchedMesh {
                name: shown(path),
                bytes: Ok(read_bytes(path)?),
            })
        }
        (Some(MeshSource::Path(path)), None) => Some(FetchedMesh {
            name: path.clone(),
            bytes: std::fs::read(path).map_err(|error| format!("cannot read the file: {error}")),
        }),
        (Some(_), Some(path)) => {
            return Err(usage(format!(
                "{}: the link carries its own mesh; give the file or the link's mesh, not both",
                shown(path)
            )));
        }
        (Some(_), None) => None,
        (None, None) => {
            return Err(usage(
                "the link names no mesh (sample=, mesh=, #mesh= or #poly=); give a mesh file too",
            ));
        }
    };
    link_refused(&still.apply_link(&parsed, fetched))
}

/// Reports each message about the link; any is a refusal.
fn link_refused(messages: &[String]) -> Result<(), Failure> {
    for message in messages {
        eprintln!("--link: {message}");
    }
    if messages.is_empty() {
        Ok(())
    } else {
        Err(Failure::Input)
    }
}
