//! `edgewise practice`: the shipped exercises, an instance of one, and
//! grading an answer offline, as a course's auto-grader calls it
//! (docs/practice.md). A pass exits 0 and a fail 1, like a test.

use std::path::{Path, PathBuf};

use clap::Subcommand;
use edgewise_core::formats::{self, Format};
use edgewise_model::practice::{Exercise, Instance, Kind, Task, catalog};
use serde_json::json;

use crate::{Failure, Outcome, emit, load, read_text, shown};

#[derive(Subcommand, Debug)]
pub enum PracticeCommand {
    /// Name every shipped exercise with its kind and structure.
    List {
        /// One JSON array instead of a table.
        #[arg(long)]
        json: bool,
    },
    /// Print an instance of an exercise: the task in words and the tables.
    Show {
        /// A shipped exercise's name, or an exercise file (.toml).
        exercise: String,
        /// The seed that draws the instance.
        #[arg(long, default_value_t = 0)]
        seed: u64,
        /// One JSON object instead of text.
        #[arg(long)]
        json: bool,
        /// Also write the instance's mesh as a table file (.wtb or .htb).
        #[arg(long, value_name = "OUT")]
        mesh: Option<PathBuf>,
    },
    /// Grade an answer: for a do-it exercise the tables after the edit (a
    /// .wtb or .htb file), for a walk the elements clicked, one a line
    /// (`edge 3`). Exit 0 for a pass, 1 for a fail.
    Check {
        /// A shipped exercise's name, or an exercise file (.toml).
        exercise: String,
        /// The answer: a .wtb or .htb file, or a walk's elements (`-` reads
        /// standard input).
        answer: PathBuf,
        /// The seed of the instance the answer is for.
        #[arg(long, default_value_t = 0)]
        seed: u64,
        /// One JSON object instead of text.
        #[arg(long)]
        json: bool,
    },
}

pub fn run(command: PracticeCommand) -> Outcome {
    match command {
        PracticeCommand::List { json } => {
            list(json);
            Ok(())
        }
        PracticeCommand::Show {
            exercise,
            seed,
            json,
            mesh,
        } => show(&exercise, seed, json, mesh.as_deref()),
        PracticeCommand::Check {
            exercise,
            answer,
            seed,
            json,
        } => check(&exercise, &answer, seed, json),
    }
}

fn list(json: bool) {
    let exercises: Vec<Exercise> = catalog::SHIPPED
        .iter()
        .filter_map(|shipped| Exercise::parse(shipped.name, shipped.text).ok())
        .collect();
    if json {
        let rows: Vec<_> = exercises
            .iter()
            .map(|e| {
                json!({
                    "name": e.name,
                    "title": e.title,
                    "kind": e.kind.name(),
                    "structure": e.structure.prose(),
                })
            })
            .collect();
        emit(&format!("{}\n", serde_json::Value::Array(rows)));
        return;
    }
    let width = exercises.iter().map(|e| e.name.len()).max().unwrap_or(0);
    let mut text = String::new();
    for e in &exercises {
        text.push_str(&format!(
            "{:<width$}  {:<6}  {:<11}  {}\n",
            e.name,
            e.kind.name(),
            e.structure.prose(),
            e.title
        ));
    }
    emit(&text);
}

/// A shipped exercise by name, or an exercise file by path.
/// A shipped exercise by name, or an exercise file, read.
pub fn exercise(name: &str) -> Result<Exercise, Failure> {
    let read = match catalog::find(name) {
        Some(read) => read,
        None if name.ends_with(".toml") || Path::new(name).exists() => {
            let path = Path::new(name);
            Exercise::parse(&shown(path), &read_text(path)?)
        }
        None => {
            eprintln!(
                "edgewise: no exercise is named `{name}`; the exercises are {} (or give a .toml file)",
                catalog::names().join(", ")
            );
            return Err(Failure::Usage);
        }
    };
    read.map_err(|err| {
        eprintln!("{err}");
        Failure::Input
    })
}

fn instance(exercise: &Exercise, seed: u64) -> Result<Instance, Failure> {
    exercise.instance(seed).map_err(|err| {
        eprintln!("{err}");
        Failure::Input
    })
}

fn show(name: &str, seed: u64, json: bool, mesh: Option<&Path>) -> Outcome {
    let exercise = exercise(name)?;
    let instance = instance(&exercise, seed)?;
    let task = instance.task.describe(exercise.structure);
    if let Some(out) = mesh {
        write_tables(&instance, out)?;
    }
    if json {
        let mut object = json!({
            "name": exercise.name,
            "title": exercise.title,
            "kind": exercise.kind.name(),
            "structure": exercise.structure.prose(),
            "seed": seed,
            "task": task,
            "points": exercise.points,
        });
        let details = match &instance.task {
            Task::DoIt { operation, ids } => json!({ "operation": operation.name(), "ids": ids }),
            Task::Walk {
                algorithm, args, ..
            } => json!({ "algorithm": algorithm, "args": args_json(args) }),
            Task::Predict {
                algorithm,
                args,
                lookups,
            } => {
                // Only how many: the questions after the first name the
                // answers before them.
                json!({ "algorithm": algorithm, "args": args_json(args), "lookups": lookups.len() })
            }
        };
        if let (Some(map), serde_json::Value::Object(more)) = (object.as_object_mut(), details) {
            map.extend(more);
        }
        emit(&format!("{object}\n"));
    } else {
        let mut text = format!(
            "{} ({}, {}, seed {seed})\n\n",
            exercise.title,
            exercise.kind.name(),
            exercise.structure.prose()
        );
        if let Some(about) = &exercise.about {
            text.push_str(about.trim());
            text.push_str("\n\n");
        }
        text.push_str(&format!("Task: {task}\n\n"));
        text.push_str(&formats::listing(&instance.mesh));
        emit(&text);
    }
    Ok(())
}

/// A walk's inputs as `{name: id}`.
fn args_json(args: &[(String, edgewise_core::schema::ElementRef)]) -> serde_json::Value {
    args.iter()
        .map(|(name, element)| (name.clone(), json!(element.id)))
        .collect::<serde_json::Map<_, _>>()
        .into()
}

/// Writes the instance's mesh as its structure's table file.
fn write_tables(instance: &Instance, out: &Path) -> Outcome {
    let format = table_format(instance, out)?;
    let bytes =
        formats::save(&instance.mesh, format, &formats::SaveOptions::default()).map_err(|err| {
            eprintln!("{}: {err}", out.display());
            Failure::Input
        })?;
    std::fs::write(out, bytes).map_err(|err| {
        eprintln!("{}: cannot write the file: {err}", out.display());
        Failure::Input
    })
}

fn table_format(instance: &Instance, out: &Path) -> Result<Format, Failure> {
    let wanted = match instance.mesh.structure() {
        edgewise_core::mesh::Structure::WingedEdge => Format::Wtb,
        edgewise_core::mesh::Structure::HalfEdge => Format::Htb,
    };
    match Format::from_name(&out.to_string_lossy()) {
        Some(format) if format == wanted => Ok(format),
        _ => {
            eprintln!(
                "edgewise: the instance is in the {} structure: write it as a .{} file",
                instance.mesh.structure().prose(),
                if wanted == Format::Wtb { "wtb" } else { "htb" }
            );
            Err(Failure::Usage)
        }
    }
}

fn check(name: &str, answer: &Path, seed: u64, json: bool) -> Outcome {
    let exercise = exercise(name)?;
    let instance = instance(&exercise, seed)?;
    let outcome = match instance.task {
        Task::DoIt { .. } => grade_tables(&exercise, &instance, answer)?,
        Task::Walk { .. } | Task::Predict { .. } => {
            let clicks = read_clicks(answer)?;
            exercise.grade_clicks(&instance, &clicks).map_err(|err| {
                eprintln!("{err}");
                Failure::Input
            })?
        }
    };
    report(&exercise, &outcome, seed, json)
}

/// A walk's or a prediction's answer: an element a line (`edge 3`, `v 1`,
/// `half-edge 9`), or `null`; blank lines and `#` comments are skipped.
fn read_clicks(answer: &Path) -> Result<Vec<Option<edgewise_core::schema::ElementRef>>, Failure> {
    let text = read_text(answer)?;
    let mut clicks = Vec::new();
    for (number, line) in text.lines().enumerate() {
        let line = line.split('#').next().unwrap_or_default().trim();
        if line.is_empty() {
            continue;
        }
        if line.eq_ignore_ascii_case("null") {
            clicks.push(None);
            continue;
        }
        let element = edgewise_model::selection::parse_element(line).map_err(|message| {
            eprintln!("{}:{}: {message}", shown(answer), number + 1);
            Failure::Input
        })?;
        clicks.push(Some(element));
    }
    Ok(clicks)
}

/// A do-it answer: the tables of a .wtb or .htb file.
fn grade_tables(
    exercise: &Exercise,
    instance: &Instance,
    answer: &Path,
) -> Result<edgewise_model::practice::Outcome, Failure> {
    let loaded = load(answer, |format| {
        format.native_structure().unwrap_or(exercise.structure)
    })?;
    if loaded.format.native_structure().is_none() {
        eprintln!(
            "{}: an answer is the tables after the edit: a .wtb or .htb file, not {}",
            shown(answer),
            loaded.format.description()
        );
        return Err(Failure::Input);
    }
    exercise.grade(instance, &loaded.mesh).map_err(|err| {
        eprintln!("{err}");
        Failure::Input
    })
}

/// Prints a grade; a fail is exit 1.
fn report(
    exercise: &Exercise,
    outcome: &edgewise_model::practice::Outcome,
    seed: u64,
    json: bool,
) -> Outcome {
    if json {
        let mut object = serde_json::to_value(outcome).unwrap_or_default();
        if let Some(map) = object.as_object_mut() {
            map.insert("exercise".to_owned(), json!(exercise.name));
            map.insert("seed".to_owned(), json!(seed));
        }
        emit(&format!("{object}\n"));
    } else {
        let verdict = if outcome.passed { "pass" } else { "fail" };
        let unit = match exercise.kind {
            Kind::DoIt => "points",
            Kind::Walk | Kind::Predict => "steps right",
        };
        let mut text = format!(
            "{}: {verdict} ({} of {} {unit})\n{}\n",
            exercise.name, outcome.score, outcome.max_score, outcome.feedback
        );
        if let Some(fewest) = outcome.fewest_writes {
            text.push_str(&format!("The library's operation makes {fewest} writes.\n"));
        }
        emit(&text);
    }
    if outcome.passed {
        Ok(())
    } else {
        Err(Failure::Input)
    }
}
