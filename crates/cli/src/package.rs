//! `edgewise package`: a SCORM package of exercises and views for an LMS
//! (docs/lms.md). Everything is checked before anything is written.

use std::path::{Path, PathBuf};

use edgewise_model::package::{AppFiles, Item, Package, Scorm};

use crate::{Failure, Outcome, practice};

pub struct Request<'a> {
    pub output: &'a Path,
    pub scorm: &'a str,
    pub exercises: &'a [String],
    pub links: &'a [String],
    pub title: &'a str,
    pub pass_mark: &'a str,
    pub app: &'a Path,
}

pub fn package(request: &Request<'_>) -> Outcome {
    let usage = |message: String| {
        eprintln!("edgewise: {message}");
        Failure::Usage
    };
    let scorm = Scorm::parse(request.scorm).ok_or_else(|| {
        usage(format!(
            "--scorm {}: the versions are 1.2 and 2004 (4th edition)",
            request.scorm
        ))
    })?;
    if request.output.extension().and_then(|e| e.to_str()) != Some("zip") {
        return Err(usage(format!(
            "{}: a package is a .zip file",
            request.output.display()
        )));
    }
    let mut items = Vec::new();
    for name in request.exercises {
        let mut exercise = practice::exercise(name)?;
        // A file's exercise is named by its stem, as the package stores it.
        if exercise.name.ends_with(".toml")
            && let Some(stem) = Path::new(name).file_stem().and_then(|s| s.to_str())
        {
            stem.clone_into(&mut exercise.name);
        }
        items.push(Item::Exercise(Box::new(exercise)));
    }
    for (n, link) in request.links.iter().enumerate() {
        items.push(Item::view(n + 1, link).map_err(|err| usage(err.to_string()))?);
    }
    let package = Package::new(scorm, request.title, request.pass_mark, items)
        .map_err(|err| usage(err.to_string()))?;
    let app = AppFiles::read(|name| {
        let path: PathBuf = request.app.join(name);
        std::fs::read(&path).map_err(|err| format!("{}: {err}", path.display()))
    })
    .map_err(|err| usage(err.to_string()))?;
    let zip = package.zip(&app).map_err(|err| usage(err.to_string()))?;
    if let Err(err) = std::fs::write(request.output, &zip) {
        eprintln!("edgewise: {}: {err}", request.output.display());
        return Err(Failure::Input);
    }
    let exercises = request.exercises.len();
    let views = request.links.len();
    eprintln!(
        "{}: SCORM {} package of {exercises} exercise{} and {views} view{}, {:.2} MB",
        request.output.display(),
        scorm.name(),
        if exercises == 1 { "" } else { "s" },
        if views == 1 { "" } else { "s" },
        zip.len() as f64 / 1e6
    );
    Ok(())
}
