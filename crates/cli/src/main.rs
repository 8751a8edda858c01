//! The `edgewise` command: inspect, check, convert and trace winged-edge and
//! half-edge meshes and the algorithms that walk them.
//!
//! Exit codes: 0 when all is well, 1 when an input (mesh or algorithm file)
//! is bad or cannot be read, 2 for a wrong command line. Problems go to
//! stderr as `file:line[:column]: message`, like a compiler's.

use std::io::{Read, Write};
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::sync::Arc;

mod package;
mod practice;
mod render;

use clap::{Parser, Subcommand, ValueEnum};
use edgewise_core::formats::{self, Format, Loaded, PlyEncoding, SaveOptions};
use edgewise_core::lang::{self, Algorithm, Program, RunOptions, Value, question};
use edgewise_core::mesh::operations::{self, Operation, Refusal};
use edgewise_core::mesh::{Edit, Mesh, MeshStats, Structure};

/// Inspect, check, convert and trace winged-edge and half-edge meshes.
///
/// Mesh files: .obj, .ply (ASCII or binary), .wtb (winged-edge tables) and
/// .htb (half-edge tables); `-` reads standard input and guesses the format
/// from the content. Exit codes: 0 fine, 1 bad input, 2 usage.
#[derive(Parser, Debug)]
#[command(name = "edgewise", version = edgewise_core::VERSION, about, long_about)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

/// The structure to build or convert to.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
enum StructureArg {
    /// Winged-edge: edge, vertex and face tables.
    #[value(alias = "winged-edge")]
    Winged,
    /// Half-edge: half-edge, vertex and face tables.
    #[value(alias = "half-edge")]
    Half,
}

impl From<StructureArg> for Structure {
    fn from(arg: StructureArg) -> Self {
        match arg {
            StructureArg::Winged => Structure::WingedEdge,
            StructureArg::Half => Structure::HalfEdge,
        }
    }
}

/// How to write a PLY file.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
enum PlyArg {
    /// Text.
    Ascii,
    /// Binary, little-endian.
    Binary,
    /// Binary, big-endian.
    BinaryBigEndian,
}

impl From<PlyArg> for PlyEncoding {
    fn from(arg: PlyArg) -> Self {
        match arg {
            PlyArg::Ascii => PlyEncoding::Ascii,
            PlyArg::Binary => PlyEncoding::BinaryLittleEndian,
            PlyArg::BinaryBigEndian => PlyEncoding::BinaryBigEndian,
        }
    }
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Print the format, structure, counts, boundary loops, components, Euler
    /// characteristic, genus and warnings of a mesh file.
    Info {
        /// The mesh file (`-` for standard input).
        file: PathBuf,
        /// The structure to build (default: a table file's own, else winged).
        #[arg(long, value_enum)]
        structure: Option<StructureArg>,
    },
    /// Validate a mesh file: list every problem and exit 1 if there is any.
    Check {
        /// The mesh file (`-` for standard input).
        file: PathBuf,
        /// The structure to build (default: a table file's own, else winged).
        #[arg(long, value_enum)]
        structure: Option<StructureArg>,
    },
    /// Convert a mesh file to another format, chosen by OUT's extension.
    Convert {
        /// The mesh file to read (`-` for standard input).
        input: PathBuf,
        /// The file to write: .obj, .ply, .wtb or .htb.
        output: PathBuf,
        /// The structure to build when reading (default: the output's own,
        /// else the input's own, else half-edge, which keeps faces as listed).
        #[arg(long, value_enum)]
        structure: Option<StructureArg>,
        /// The PLY encoding to write.
        #[arg(long, value_enum, default_value = "ascii")]
        ply: PlyArg,
    },
    /// Apply a local operation to a mesh and write the result, printing V, E
    /// and F before and after. A refused operation prints why and exits 1.
    #[command(after_help = operations_help())]
    Edit {
        /// The mesh file to read (`-` for standard input).
        input: PathBuf,
        /// The file to write: .obj, .ply, .wtb or .htb.
        output: PathBuf,
        /// The operation (see below).
        operation: String,
        /// The ids it takes, in order. An edge is an edge id, or either of
        /// its half-edges in a half-edge mesh.
        #[arg(value_name = "ID", required = true)]
        ids: Vec<u32>,
        /// The structure to edit (default: a table file's own, else the
        /// output's, else winged).
        #[arg(long, value_enum)]
        structure: Option<StructureArg>,
        /// The PLY encoding to write.
        #[arg(long, value_enum, default_value = "ascii")]
        ply: PlyArg,
    },
    /// Print the vertex, face and edge (or half-edge) tables.
    Tables {
        /// The mesh file (`-` for standard input).
        file: PathBuf,
        /// The structure to show (default: a table file's own, else winged).
        #[arg(long, value_enum)]
        structure: Option<StructureArg>,
    },
    /// Run an algorithm on a mesh and print every step, then what it marked.
    Trace {
        /// The algorithm file.
        algfile: PathBuf,
        /// The algorithm's name in that file.
        name: String,
        /// The mesh file, built in the structure the algorithm declares.
        meshfile: PathBuf,
        /// A parameter value, such as `v=3` (repeat for each parameter).
        #[arg(long = "arg", value_name = "NAME=VALUE")]
        args: Vec<String>,
        /// The most operations to run before stopping the algorithm.
        #[arg(long, default_value_t = lang::DEFAULT_STEP_LIMIT)]
        step_limit: usize,
        /// The most memory, in MB, the run may keep for its trace, variables,
        /// arrays and new rows before stopping the algorithm.
        #[arg(long, value_name = "MB", default_value_t = lang::DEFAULT_MEMORY_LIMIT as u64 >> 20,
              value_parser = clap::value_parser!(u64).range(1..=65_536))]
        memory_limit: u64,
        /// For an algorithm that changes the mesh: write the mesh it leaves
        /// (ids compacted) here, in the format of the extension. Nothing is
        /// written if the run stops on an error or leaves broken records.
        #[arg(long, value_name = "OUT")]
        save: Option<PathBuf>,
        /// A question set (`line 7: prompt` or `step 12: prompt` per line):
        /// print each question with the step it is asked at and the answer
        /// the run gives it, as the app will check it. `//?` comments in the
        /// algorithm are printed as well.
        #[arg(long, value_name = "SET")]
        questions: Option<PathBuf>,
    },
    /// Draw the app's view, with the tables, as an SVG picture of one moment
    /// or a PDF handout of a run (a page per step), as the app's Save menu
    /// does.
    #[command(after_help = RENDER_EXAMPLES)]
    Render {
        /// The file to write: .svg (the view and the tables at one step) or
        /// .pdf (a handout of the run, a page per step).
        output: PathBuf,
        /// The mesh file (`-` for standard input); with --link, the file its
        /// `mesh=` names.
        meshfile: Option<PathBuf>,
        /// A course link, whole or its `?…#…` part: the mesh, algorithm,
        /// inputs, step, selection, camera and colours, as the app opens it.
        /// A `mesh=` path is read from MESHFILE, else under this folder.
        #[arg(long)]
        link: Option<String>,
        /// The structure to build (default: a table file's own, else winged).
        #[arg(long, value_enum)]
        structure: Option<StructureArg>,
        /// An algorithm file to load besides the app's library.
        #[arg(long = "alg", value_name = "ALGFILE")]
        algfile: Option<PathBuf>,
        /// The algorithm to run, from ALGFILE or the app's library.
        #[arg(long, value_name = "NAME")]
        run: Option<String>,
        /// An input, such as `v=3` (repeat for each input).
        #[arg(long = "arg", value_name = "NAME=VALUE")]
        args: Vec<String>,
        /// The step to draw in an SVG (default: the start, or the link's).
        #[arg(long)]
        step: Option<usize>,
        /// An element to select: `e3`, `vertex 1`, `f0`.
        #[arg(long, value_name = "ELEMENT")]
        select: Option<String>,
        /// The view's size in points.
        #[arg(long, value_name = "WIDTHxHEIGHT", default_value = "800x600")]
        size: String,
        /// The dark theme.
        #[arg(long)]
        dark: bool,
    },
    /// Practise: list the shipped exercises, show an instance of one, or
    /// grade an answer offline (exit 0 for a pass, 1 for a fail).
    Practice {
        #[command(subcommand)]
        command: practice::PracticeCommand,
    },
    /// Make a SCORM package for an LMS: exercises it scores and views it
    /// shows, with the release app inside (docs/lms.md).
    #[command(after_help = PACKAGE_EXAMPLES)]
    Package {
        /// The package to write (.zip).
        output: PathBuf,
        /// The SCORM version: 1.2, or 2004 (4th edition).
        #[arg(long, value_name = "1.2|2004")]
        scorm: String,
        /// A shipped exercise's name or an exercise file (.toml); repeat for
        /// more.
        #[arg(long = "exercise", value_name = "NAME|FILE")]
        exercises: Vec<String>,
        /// A course link to show as a view with no score; repeat for more.
        #[arg(long = "link", value_name = "URL")]
        links: Vec<String>,
        /// The title the LMS lists.
        #[arg(long, default_value = "Edgewise practice")]
        title: String,
        /// The share of the total, in percent, that passes.
        #[arg(
            long,
            value_name = "N",
            default_value = "80",
            allow_hyphen_values = true
        )]
        pass_mark: String,
        /// The release app to put inside (what `cargo xtask build-web` makes).
        #[arg(long, value_name = "DIR", default_value = "dist")]
        app: PathBuf,
    },
    /// Check an algorithm file: print every error and exit 1 if there is any.
    CheckAlg {
        /// The algorithm file.
        algfile: PathBuf,
    },
    /// Print the compiled code of one algorithm, or of every algorithm in a file.
    Disasm {
        /// The algorithm file.
        algfile: PathBuf,
        /// The algorithm to show (default: all of them).
        name: Option<String>,
    },
}

const RENDER_EXAMPLES: &str = "Examples:
  edgewise render tetra.svg meshes/tetrahedron.wtb --select e0
  edgewise render handout.pdf meshes/tetrahedron.wtb --run vertexAdjacentEdge --arg v=1
  edgewise render step4.svg --link 'https://example.edu/edgewise/?sample=cube&algorithm=vertexAdjacentEdge&args=v:0&step=4'";

const PACKAGE_EXAMPLES: &str = "Examples:
  edgewise package week3.zip --scorm 2004 --exercise split-edge-half-edge --exercise walk-face-loop-half-edge --pass-mark 70
  edgewise package tour.zip --scorm 1.2 --exercise my-exercise.toml --link 'https://example.edu/edgewise/?sample=cube' --title 'Week 3'";

/// How a command ended, mapped to the exit code.
enum Failure {
    /// The input is bad (exit 1); the message is already printed.
    Input,
    /// The command line is wrong (exit 2); the message is already printed.
    Usage,
}

type Outcome = Result<(), Failure>;

fn main() -> ExitCode {
    let cli = Cli::parse();
    let outcome = match cli.command {
        Command::Info { file, structure } => info(&file, structure),
        Command::Check { file, structure } => check(&file, structure),
        Command::Convert {
            input,
            output,
            structure,
            ply,
        } => convert(&input, &output, structure, ply),
        Command::Edit {
            input,
            output,
            operation,
            ids,
            structure,
            ply,
        } => edit(&input, &output, &operation, &ids, structure, ply),
        Command::Tables { file, structure } => tables(&file, structure),
        Command::Trace {
            algfile,
            name,
            meshfile,
            args,
            step_limit,
            memory_limit,
            save,
            questions,
        } => trace(
            &algfile,
            &name,
            &meshfile,
            &args,
            RunOptions {
                step_limit,
                memory_limit: usize::try_from(memory_limit << 20).unwrap_or(usize::MAX),
            },
            save.as_deref(),
            questions.as_deref(),
        ),
        Command::Render {
            output,
            meshfile,
            link,
            structure,
            algfile,
            run,
            args,
            step,
            select,
            size,
            dark,
        } => render::render(&render::Request {
            output: &output,
            meshfile: meshfile.as_deref(),
            link: link.as_deref(),
            structure,
            algfile: algfile.as_deref(),
            run: run.as_deref(),
            args: &args,
            step,
            select: select.as_deref(),
            size: &size,
            dark,
        }),
        Command::Practice { command } => practice::run(command),
        Command::Package {
            output,
            scorm,
            exercises,
            links,
            title,
            pass_mark,
            app,
        } => package::package(&package::Request {
            output: &output,
            scorm: &scorm,
            exercises: &exercises,
            links: &links,
            title: &title,
            pass_mark: &pass_mark,
            app: &app,
        }),
        Command::CheckAlg { algfile } => check_alg(&algfile),
        Command::Disasm { algfile, name } => disasm(&algfile, name.as_deref()),
    };
    match outcome {
        Ok(()) => ExitCode::SUCCESS,
        Err(Failure::Input) => ExitCode::from(1),
        Err(Failure::Usage) => ExitCode::from(2),
    }
}

/// Writes to stdout; a closed pipe (`edgewise tables big.ply | head`) just
/// ends the output.
fn emit(text: &str) {
    let mut stdout = std::io::stdout().lock();
    let _ = stdout.write_all(text.as_bytes());
    let _ = stdout.flush();
}

/// The name a file is shown under in messages.
fn shown(path: &Path) -> String {
    if path == Path::new("-") {
        "<stdin>".to_owned()
    } else {
        path.display().to_string()
    }
}

fn read_bytes(path: &Path) -> Result<Vec<u8>, Failure> {
    let result = if path == Path::new("-") {
        let mut bytes = Vec::new();
        std::io::stdin().read_to_end(&mut bytes).map(|_| bytes)
    } else {
        std::fs::read(path)
    };
    result.map_err(|error| {
        eprintln!("{}: cannot read the file: {error}", shown(path));
        Failure::Input
    })
}

fn read_text(path: &Path) -> Result<String, Failure> {
    let bytes = read_bytes(path)?;
    match lang::source_text(&bytes, Some(&shown(path))) {
        Ok(text) => Ok(text.to_owned()),
        Err(rendered) => {
            eprint!("{rendered}");
            Err(Failure::Input)
        }
    }
}

/// The format of a mesh file: by extension, by content for `-` or a name
/// without one.
fn format_of(path: &Path, bytes: &[u8]) -> Result<Format, Failure> {
    let name = if path == Path::new("-") {
        String::new()
    } else {
        path.to_string_lossy().into_owned()
    };
    Format::detect(bytes, &name).map_err(|error| {
        eprint!("{}", error.render(&shown(path)));
        Failure::Input
    })
}

/// Reads and builds a mesh file, printing its problems on failure.
fn load(path: &Path, structure: impl FnOnce(Format) -> Structure) -> Result<Loaded, Failure> {
    let bytes = read_bytes(path)?;
    let format = format_of(path, &bytes)?;
    formats::load_as(&bytes, format, structure(format)).map_err(|error| {
        eprint!("{}", error.render(&shown(path)));
        Failure::Input
    })
}

/// The structure to build: the one asked for, else a table file's own, else
/// winged-edge.
fn default_structure(asked: Option<StructureArg>) -> impl FnOnce(Format) -> Structure {
    move |format| {
        asked
            .map(Structure::from)
            .or(format.native_structure())
            .unwrap_or(Structure::WingedEdge)
    }
}

fn genus_text(stats: &MeshStats) -> String {
    match stats.components.as_slice() {
        [] => "- (no faces)".to_owned(),
        [only] => only.genus.map_or_else(
            || "- (the surface has a boundary)".to_owned(),
            |g| g.to_string(),
        ),
        _ => "- (several components; see below)".to_owned(),
    }
}

fn info(path: &Path, structure: Option<StructureArg>) -> Outcome {
    let loaded = load(path, default_structure(structure))?;
    let stats = loaded.mesh.stats();
    let name = shown(path);
    let mut structure_text = loaded.mesh.structure().prose().to_owned();
    if let Some(from) = loaded.converted_from {
        structure_text.push_str(&format!(
            " (converted from the file's {} tables)",
            from.prose()
        ));
    }
    let mut out = String::new();
    let mut line = |label: &str, value: &str| out.push_str(&format!("{label:<22}{value}\n"));
    line("file:", &name);
    line("format:", loaded.format.description());
    line("structure:", &structure_text);
    line("vertices:", &stats.vertices.to_string());
    line("edges:", &stats.edges.to_string());
    line("faces:", &stats.faces.to_string());
    line("half-edges:", &stats.half_edges.to_string());
    line("boundary loops:", &stats.boundary_loops.to_string());
    line("components:", &stats.connected_components().to_string());
    line(
        "Euler characteristic:",
        &stats.euler_characteristic.to_string(),
    );
    line("genus:", &genus_text(&stats));
    if stats.components.len() > 1 {
        for c in &stats.components {
            out.push_str(&format!(
                "  component from {}: V {}, E {}, F {}, boundary loops {}, χ {}, genus {}\n",
                c.first_vertex,
                c.vertices,
                c.edges,
                c.faces,
                c.boundary_loops,
                c.euler_characteristic,
                c.genus.map_or_else(|| "-".to_owned(), |g| g.to_string())
            ));
        }
    }
    if loaded.warnings.is_empty() {
        out.push_str(&format!("{:<22}none\n", "warnings:"));
    } else {
        out.push_str(&format!("{:<22}{}\n", "warnings:", loaded.warnings.len()));
        for warning in &loaded.warnings {
            out.push_str(&format!("  {}\n", warning.render(&name)));
        }
    }
    emit(&out);
    Ok(())
}

fn check(path: &Path, structure: Option<StructureArg>) -> Outcome {
    let loaded = load(path, default_structure(structure))?;
    let name = shown(path);
    // Loading already validated; a non-empty list here would be a builder bug,
    // but it is reported the same way rather than trusted away.
    let issues = loaded.mesh.validate();
    for issue in &issues {
        eprintln!("{name}: {issue}");
    }
    for warning in &loaded.warnings {
        eprintln!("{}", warning.render(&name).replacen(": ", ": warning: ", 1));
    }
    if !issues.is_empty() {
        return Err(Failure::Input);
    }
    let mesh = &loaded.mesh;
    emit(&format!(
        "{name}: ok ({} vertices, {} edges, {} faces; {})\n",
        mesh.vertex_count(),
        mesh.edge_count(),
        mesh.face_count(),
        mesh.structure().prose()
    ));
    Ok(())
}

/// The format to write, from the output's extension.
fn output_format(output: &Path) -> Result<Format, Failure> {
    Format::from_name(&output.to_string_lossy())
        .filter(|_| output.extension().is_some())
        .ok_or_else(|| {
            eprintln!(
                "edgewise: cannot tell the format of {}: give it a .obj, .ply, .wtb or .htb extension",
                output.display()
            );
            Failure::Usage
        })
}

/// Writes `mesh` to `output` in `format`; returns the number of bytes.
fn write_mesh(
    mesh: &Mesh,
    input: &Path,
    output: &Path,
    format: Format,
    ply: PlyArg,
) -> Result<usize, Failure> {
    let options = SaveOptions {
        ply_encoding: ply.into(),
    };
    let bytes = formats::save(mesh, format, &options).map_err(|error| {
        eprintln!("{}: {error}", shown(input));
        Failure::Input
    })?;
    std::fs::write(output, &bytes).map_err(|error| {
        eprintln!("{}: cannot write the file: {error}", output.display());
        Failure::Input
    })?;
    Ok(bytes.len())
}

fn convert(input: &Path, output: &Path, structure: Option<StructureArg>, ply: PlyArg) -> Outcome {
    let target = output_format(output)?;
    let loaded = load(input, |format| {
        structure
            .map(Structure::from)
            .or(target.native_structure())
            .or(format.native_structure())
            .unwrap_or(Structure::HalfEdge)
    })?;
    let written = write_mesh(&loaded.mesh, input, output, target, ply)?;
    emit(&format!(
        "{} -> {}: {} vertices, {} faces, {written} bytes\n",
        shown(input),
        output.display(),
        loaded.mesh.vertex_count(),
        loaded.mesh.face_count(),
    ));
    Ok(())
}

/// The operations, their ids and what they do, for `edit --help`.
fn operations_help() -> String {
    let mut text = String::from("Operations, with the ids each takes in order:\n");
    for operation in Operation::ALL {
        text.push_str("  ");
        text.push_str(operation.name());
        for argument in operation.arguments() {
            let role = argument.role;
            text.push_str(&if argument.optional {
                format!(" [<{role}>]")
            } else {
                format!(" <{role}>")
            });
        }
        text.push_str(&format!("\n      {}\n", operation.summary()));
    }
    text
}

/// "V 6, E 12, F 8, V − E + F = 2".
fn counts_text(stats: &MeshStats) -> String {
    format!(
        "V {}, E {}, F {}, V − E + F = {}",
        stats.vertices, stats.edges, stats.faces, stats.euler_characteristic
    )
}

fn edit(
    input: &Path,
    output: &Path,
    operation: &str,
    ids: &[u32],
    structure: Option<StructureArg>,
    ply: PlyArg,
) -> Outcome {
    let operation = Operation::parse(operation).map_err(|error| {
        eprintln!("edgewise: {error}");
        Failure::Usage
    })?;
    let target = output_format(output)?;
    let mut mesh = load(input, |format| {
        structure
            .map(Structure::from)
            .or(format.native_structure())
            .or(target.native_structure())
            .unwrap_or(Structure::WingedEdge)
    })?
    .mesh;
    let before = mesh.stats();
    let listed: Vec<String> = ids.iter().map(ToString::to_string).collect();
    let asked = format!("{operation} {}", listed.join(" "));
    if let Err(refusal) = operations::apply(&mut mesh, operation, ids) {
        eprintln!("{}: {asked}: {refusal}", shown(input));
        return Err(match refusal {
            Refusal::Arguments { .. } => Failure::Usage,
            _ => Failure::Input,
        });
    }
    mesh.compact();
    let after = mesh.stats();
    let written = write_mesh(&mesh, input, output, target, ply)?;
    emit(&format!(
        "{}: {asked} ({})\nbefore: {}\nafter:  {}\nwrote {} ({written} bytes)\n",
        shown(input),
        mesh.structure().prose(),
        counts_text(&before),
        counts_text(&after),
        output.display(),
    ));
    Ok(())
}

fn tables(path: &Path, structure: Option<StructureArg>) -> Outcome {
    let loaded = load(path, default_structure(structure))?;
    emit(&formats::listing(&loaded.mesh));
    Ok(())
}

/// Compiles an algorithm file, printing its errors on failure.
fn compile(path: &Path) -> Result<Program, Failure> {
    let source = read_text(path)?;
    lang::compile_rendered(&source, Some(&shown(path))).map_err(|rendered| {
        eprint!("{rendered}");
        Failure::Input
    })
}

fn find<'p>(program: &'p Program, path: &Path, name: &str) -> Result<&'p Arc<Algorithm>, Failure> {
    program.algorithm(name).ok_or_else(|| {
        let names: Vec<&str> = program.names().collect();
        eprintln!(
            "{}: no algorithm is named `{name}`; the file has: {}",
            shown(path),
            names.join(", ")
        );
        Failure::Usage
    })
}

fn trace(
    algfile: &Path,
    name: &str,
    meshfile: &Path,
    args: &[String],
    options: RunOptions,
    save: Option<&Path>,
    question_set: Option<&Path>,
) -> Outcome {
    let target = save.map(output_format).transpose()?;
    let program = compile(algfile)?;
    let algorithm = find(&program, algfile, name)?;
    let mut questions = question::from_comments(algorithm);
    if let Some(path) = question_set {
        let text = read_text(path)?;
        let set = question::parse_set(&text).map_err(|error| {
            eprintln!("{}:{error}", shown(path));
            Failure::Input
        })?;
        questions.extend(set);
    }
    let mut inputs: Vec<(String, Value)> = Vec::with_capacity(args.len());
    for arg in args {
        let parsed = algorithm.parse_argument(arg).map_err(|error| {
            eprintln!("edgewise: --arg {arg}: {error}");
            Failure::Usage
        })?;
        inputs.push(parsed);
    }
    let structure = algorithm.structure;
    let mut mesh = load(meshfile, |_| structure)?.mesh;
    let inputs: Vec<(&str, Value)> = inputs.iter().map(|(n, v)| (n.as_str(), *v)).collect();
    let before = mesh.live_stats();
    let run = if algorithm.edits() {
        lang::run_editing(algorithm, &mut mesh, &inputs, options)
    } else {
        match &mesh {
            Mesh::Winged(mesh) => lang::run(algorithm, mesh, &inputs, options),
            Mesh::Half(mesh) => lang::run(algorithm, mesh, &inputs, options),
        }
    };
    let trace = run.map_err(|error| {
        eprintln!("edgewise: {error}");
        Failure::Usage
    })?;
    // Streamed: a run near its memory budget prints hundreds of MB.
    {
        let mut stdout = std::io::BufWriter::new(std::io::stdout().lock());
        for line in trace.lines() {
            if writeln!(stdout, "{line}").is_err() {
                break;
            }
        }
        let _ = stdout.flush();
    }
    let mut out = String::new();
    out.push_str(&trace.render_marked());
    out.push('\n');
    out.push_str(&render_questions(&trace, &questions));
    if algorithm.edits() {
        out.push_str(&format!(
            "changes: {}\nbefore: {}\nafter:  {}\n",
            trace.changes().len(),
            counts_text(&before),
            counts_text(&mesh.live_stats())
        ));
    }
    emit(&out);
    if let Some(error) = trace.outcome().error() {
        eprintln!(
            "{}:{}: error: {}",
            shown(algfile),
            error.line,
            error.message
        );
        return Err(Failure::Input);
    }
    let broken = mesh.validate();
    if !broken.is_empty() {
        eprintln!(
            "{}: {name} left {} broken record{}:",
            shown(algfile),
            broken.len(),
            if broken.len() == 1 { "" } else { "s" }
        );
        for issue in &broken {
            eprintln!("  {issue}");
        }
        return Err(Failure::Input);
    }
    if let (Some(path), Some(format)) = (save, target) {
        mesh.compact();
        let written = write_mesh(&mesh, meshfile, path, format, PlyArg::Ascii)?;
        emit(&format!("wrote {} ({written} bytes)\n", path.display()));
    }
    Ok(())
}

/// Each question the run asks, at its step, with its answer and the steps
/// that give it; then the questions it cannot ask, and why.
fn render_questions(trace: &lang::Trace, questions: &[question::Question]) -> String {
    if questions.is_empty() {
        return String::new();
    }
    let (posed, problems) = question::pose(trace, questions);
    let mut out = String::from("questions:\n");
    for p in &posed {
        out.push_str(&format!(
            "  at step {} (before line {}): {}\n    answer: {}. {}\n",
            p.ask_at,
            p.line(trace),
            p.question.prompt,
            p.expected,
            p.explanation(trace)
        ));
    }
    for problem in &problems {
        out.push_str(&format!("  not asked: {problem}\n"));
    }
    out
}

fn check_alg(path: &Path) -> Outcome {
    let source = read_text(path)?;
    let name = shown(path);
    match lang::compile(&source) {
        Ok(program) => {
            let mut out = format!("{name}: ok, {} algorithms\n", program.algorithms.len());
            for algorithm in &program.algorithms {
                out.push_str(&format!("  {}\n", algorithm.signature()));
            }
            emit(&out);
            Ok(())
        }
        Err(diagnostics) => {
            eprint!("{}", lang::render_all(&diagnostics, &source, Some(&name)));
            Err(Failure::Input)
        }
    }
}

fn disasm(path: &Path, name: Option<&str>) -> Outcome {
    let program = compile(path)?;
    let text = match name {
        Some(name) => lang::disassemble(find(&program, path, name)?),
        None => lang::disassemble_all(program.algorithms.iter().map(AsRef::as_ref)),
    };
    emit(&text);
    Ok(())
}
