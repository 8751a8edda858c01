//! The pages lecturers put Edgewise views in, built with the real tools:
//! a reveal.js deck (reveal.js from npm) and `MkDocs` notes (`MkDocs` from
//! `PyPI`), as pinned in `web/hosts/`. The browser test `hosts.rs` opens
//! them with the app served from another origin, as a course site does.
//!
//! Beside them, an LMS for the SCORM packages (docs/lms.md): scorm-again
//! (from npm) as the API, and two packages of dist/ made by `edgewise
//! package` and unzipped by Python's zipfile, served from the same origin
//! as an LMS serves its content. The browser test `scorm.rs` opens it.
//!
//! The tools are installed once, into `web/hosts/node_modules` and
//! `target/hosts-venv`, and again only when their pins change. The pages
//! are built into `target/hosts` for one address of the app on each call.

use std::{
    path::{Path, PathBuf},
    process::Command,
};

use anyhow::{Context as _, bail};

use crate::{
    process::{self, Edgewise},
    serve, web_build,
};

/// Where the snippets in web/hosts (as docs/embedding.md prints them) say
/// the app is served; replaced by the app's real address.
const PLACEHOLDER: &str = "https://example.edu/edgewise/";

/// Installs the tools if needed and builds the deck, the notes and the LMS
/// (its packages made by `edgewise`) into target/hosts for the app at
/// `app_url` (ending in '/'). Returns the folder to serve: `reveal/` holds
/// the deck, `mkdocs/` the notes and `scorm/` the LMS.
pub fn build(root: &Path, app_url: &str, edgewise: &Edgewise) -> anyhow::Result<PathBuf> {
    let source = root.join("web/hosts");
    let target = root.join("target");
    install_npm_tools(&source)?;
    let venv = install_mkdocs(&source, &target.join("hosts-venv"))?;

    let out = target.join("hosts");
    let scratch = target.join("hosts-src");
    for dir in [&out, &scratch] {
        if dir.exists() {
            std::fs::remove_dir_all(dir)
                .with_context(|| format!("cannot clear {}", dir.display()))?;
        }
    }

    // The deck, with reveal.js's built files beside it.
    copy_dir(
        &source.join("node_modules/reveal.js/dist"),
        &out.join("reveal/reveal.js/dist"),
    )?;
    write_for_app(
        &source.join("reveal/index.html"),
        &out.join("reveal/index.html"),
        app_url,
    )?;

    // The notes: a copy of the MkDocs project with the app's address in
    // it, built by MkDocs itself.
    let notes = scratch.join("mkdocs");
    copy_dir(&source.join("mkdocs"), &notes)?;
    write_for_app(
        &source.join("mkdocs/docs/index.md"),
        &notes.join("docs/index.md"),
        app_url,
    )?;
    process::run(
        "mkdocs build",
        Command::new(venv.join("bin/mkdocs"))
            .args(["build", "--strict", "--quiet", "--config-file"])
            .arg(notes.join("mkdocs.yml"))
            .arg("--site-dir")
            .arg(out.join("mkdocs")),
    )?;
    scorm_lms(root, &source, &out.join("scorm"), edgewise)?;
    Ok(out)
}

/// The exercises of the SCORM test packages: a walk the test passes, a
/// prediction it fails, and a do-it it leaves half done and resumes.
const SCORM_EXERCISES: [&str; 3] = [
    "walk-face-loop-half-edge",
    "predict-vertex-edges-half-edge",
    "split-edge-half-edge",
];

/// scorm-again's page as the LMS, and a package of dist/ for each SCORM
/// version unzipped beside it (`package-1.2/`, `package-2004/`).
fn scorm_lms(root: &Path, source: &Path, out: &Path, edgewise: &Edgewise) -> anyhow::Result<()> {
    std::fs::create_dir_all(out).with_context(|| format!("cannot create {}", out.display()))?;
    std::fs::copy(
        source.join("node_modules/scorm-again/dist/scorm-again.min.js"),
        out.join("scorm-again.js"),
    )
    .context("cannot copy scorm-again (is it installed?)")?;
    std::fs::copy(source.join("scorm/index.html"), out.join("index.html"))
        .context("cannot copy web/hosts/scorm/index.html")?;
    let dist = web_build::dist_dir(root);
    if !dist.join("index.html").is_file() {
        bail!("dist/ is not built: the SCORM packages hold it (run `cargo xtask build-web`)");
    }
    for version in ["1.2", "2004"] {
        let zip = out.join(format!("edgewise-{version}.zip"));
        let mut package = edgewise.package();
        package
            .current_dir(root)
            .arg(&zip)
            .args([
                "--scorm",
                version,
                "--title",
                "Week 3: half-edges",
                "--pass-mark",
                "60",
            ])
            .arg("--app")
            .arg(&dist);
        for exercise in SCORM_EXERCISES {
            package.args(["--exercise", exercise]);
        }
        process::run("edgewise package", &mut package)?;
        process::run(
            "unzip (Python's zipfile)",
            Command::new("python3")
                .args(["-m", "zipfile", "-e"])
                .arg(&zip)
                .arg(out.join(format!("package-{version}"))),
        )?;
    }
    Ok(())
}

/// `cargo xtask hosts`: builds the hosts for the app at `app` (or for
/// dist/, served here) and serves them until stopped.
pub fn serve(root: &Path, app: Option<&str>) -> anyhow::Result<()> {
    let app_url = match app {
        Some(url) if url.ends_with('/') => url.to_owned(),
        Some(url) => format!("{url}/"),
        None => {
            let dist = web_build::dist_dir(root);
            if !dist.join("index.html").is_file() {
                bail!("dist/ is not built: run `cargo xtask build-web` first, or pass --app URL");
            }
            format!("http://{}/", serve::serve_in_background(&dist)?)
        }
    };
    let hosts = build(root, &app_url, &Edgewise::CargoRun)?;
    let addr = serve::serve_in_background(&hosts)?;
    println!("The app:          {app_url}");
    println!("reveal.js deck:   http://{addr}/reveal/");
    println!("MkDocs notes:     http://{addr}/mkdocs/");
    println!(
        "An LMS (SCORM):   http://{addr}/scorm/?version=1.2 (or 2004; &learner=NAME for a new learner)"
    );
    println!("For the tests:    EDGEWISE_URL={app_url} EDGEWISE_HOSTS_URL=http://{addr}/");
    println!("(Ctrl+C stops)");
    loop {
        std::thread::park();
    }
}

/// `npm ci` in `web/hosts` (reveal.js and scorm-again), unless
/// `node_modules` already holds what package-lock.json pins.
fn install_npm_tools(source: &Path) -> anyhow::Result<()> {
    let lock = read(&source.join("package-lock.json"))?;
    let stamp = source.join("node_modules/.edgewise-installed");
    if std::fs::read_to_string(&stamp).is_ok_and(|installed| installed == lock) {
        return Ok(());
    }
    if process::output_of(Command::new("npm").arg("--version")).is_none() {
        // Debian's nodejs and npm, where nothing else gives them.
        process::ensure_debian_packages("the reveal.js deck", &[("/usr/bin/npm", "npm")])?;
    }
    eprintln!("==> installing reveal.js and scorm-again from npm (web/hosts/package-lock.json)");
    process::run(
        "npm ci (web/hosts)",
        Command::new("npm")
            .args(["ci", "--no-audit", "--no-fund"])
            .current_dir(source),
    )?;
    write(&stamp, &lock)
}

/// A virtual environment with `MkDocs`, as requirements.txt pins it, unless
/// it is there already. Returns the environment's folder.
fn install_mkdocs(source: &Path, venv: &Path) -> anyhow::Result<PathBuf> {
    let requirements = source.join("requirements.txt");
    let pins = read(&requirements)?;
    let stamp = venv.join(".edgewise-installed");
    if std::fs::read_to_string(&stamp).is_ok_and(|installed| installed == pins) {
        return Ok(venv.to_path_buf());
    }
    eprintln!("==> installing MkDocs from PyPI (web/hosts/requirements.txt)");
    if venv.exists() {
        std::fs::remove_dir_all(venv)
            .with_context(|| format!("cannot clear {}", venv.display()))?;
    }
    let make_venv = || {
        process::run(
            "python3 -m venv",
            Command::new("python3").args(["-m", "venv"]).arg(venv),
        )
    };
    if make_venv().is_err() {
        // Debian's python3 makes virtual environments only with python3-venv.
        std::fs::remove_dir_all(venv).ok();
        process::ensure_debian_packages(
            "MkDocs's virtual environment",
            &[("/usr/share/doc/python3-venv", "python3-venv")],
        )?;
        make_venv()?;
    }
    process::run(
        "pip install (web/hosts/requirements.txt)",
        Command::new(venv.join("bin/pip"))
            .args(["install", "--quiet", "--requirement"])
            .arg(&requirements),
    )?;
    write(&stamp, &pins)?;
    Ok(venv.to_path_buf())
}

/// Copies `from` to `to` with the placeholder address replaced by
/// `app_url`; a file without the placeholder is an error, since its view
/// would point nowhere.
fn write_for_app(from: &Path, to: &Path, app_url: &str) -> anyhow::Result<()> {
    let text = read(from)?;
    if !text.contains(PLACEHOLDER) {
        bail!("{} does not embed the app at {PLACEHOLDER}", from.display());
    }
    write(to, &text.replace(PLACEHOLDER, app_url))
}

fn copy_dir(from: &Path, to: &Path) -> anyhow::Result<()> {
    std::fs::create_dir_all(to).with_context(|| format!("cannot create {}", to.display()))?;
    let entries = std::fs::read_dir(from)
        .with_context(|| format!("cannot read {} (is the tool installed?)", from.display()))?;
    for entry in entries {
        let entry = entry?;
        let path = entry.path();
        let dest = to.join(entry.file_name());
        if entry.file_type()?.is_dir() {
            copy_dir(&path, &dest)?;
        } else {
            std::fs::copy(&path, &dest)
                .with_context(|| format!("cannot copy {} to {}", path.display(), dest.display()))?;
        }
    }
    Ok(())
}

fn read(path: &Path) -> anyhow::Result<String> {
    std::fs::read_to_string(path).with_context(|| format!("cannot read {}", path.display()))
}

fn write(path: &Path, text: &str) -> anyhow::Result<()> {
    if let Some(dir) = path.parent() {
        std::fs::create_dir_all(dir).with_context(|| format!("cannot create {}", dir.display()))?;
    }
    std::fs::write(path, text).with_context(|| format!("cannot write {}", path.display()))
}
