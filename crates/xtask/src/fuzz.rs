//! `cargo xtask fuzz`: coverage-guided fuzzing of the readers, the algorithm
//! language and course links with cargo-fuzz (libFuzzer, nightly only), and
//! `--make-seeds`, which rebuilds the seed corpus in fuzz/seeds/.
//!
//! The fuzz targets are in fuzz/ (not a workspace member). Each calls one
//! function of `edgewise_core::fuzzing` or `edgewise_app::fuzzing`; the
//! stable replay tests call the same functions on fuzz/seeds/ and
//! tests/fuzz-regressions/, so `cargo xtask test` never needs nightly.

use std::{
    fs,
    io::{BufRead as _, BufReader},
    path::{Path, PathBuf},
    process::{Command, Stdio},
    time::Instant,
};

use anyhow::{Context as _, bail};
use base64::Engine as _;

use crate::process::{self, cargo};

/// Every fuzz target, in the order `cargo xtask fuzz` runs them.
pub const TARGETS: [&str; 10] = [
    "obj",
    "ply",
    "wtb",
    "htb",
    "detect",
    "compile",
    "vm",
    "convert",
    "course_link",
    "link",
];

/// The ids of the conversion seeds' operations, in turn.
const SEED_IDS: [[u8; 3]; 4] = [[0, 1, 2], [3, 0, 1], [1, 2, 0], [2, 3, 1]];

/// Seeds larger than this are left out: libFuzzer's input length follows the
/// largest seed, and big inputs make every iteration slow.
const MAX_SEED_BYTES: u64 = 64 * 1024;

/// The most seconds libFuzzer lets one input run before it reports a hang.
const INPUT_TIMEOUT_S: u32 = 10;

/// The `vm` target's limit instead: it runs each algorithm twice with the
/// real limits (1,000,000 steps, 256 MB), and a run to the memory budget
/// takes about 17 s in the instrumented build (2 s in a release CLI).
const VM_INPUT_TIMEOUT_S: u32 = 60;

/// The `vm` target's memory limit for libFuzzer (its default is 2,048 MB).
/// A run may hold its 256 MB budget in up to a million small allocations;
/// under `AddressSanitizer`, with its shadow memory, per-allocation records
/// and a quarantine of freed memory, that came to 2,075 MB of RSS with
/// 291 MB of it live.
const VM_RSS_LIMIT_MB: u32 = 4096;

/// What one target's run did, for the summary table.
struct Outcome {
    target: &'static str,
    executions: Option<u64>,
    seconds: f64,
    crashes: Vec<String>,
    failed: bool,
}

/// Fuzzes one target, or each in turn, for `seconds` each, then prints a
/// table; fails if any target crashed.
pub fn run(root: &Path, target: Option<&str>, seconds: u64) -> anyhow::Result<()> {
    let targets: Vec<&'static str> = match target {
        None => TARGETS.to_vec(),
        Some(name) => match TARGETS.iter().find(|t| **t == name) {
            Some(t) => vec![*t],
            None => bail!(
                "there is no fuzz target `{name}`; the targets are {}",
                TARGETS.join(", ")
            ),
        },
    };
    ensure_nightly()?;
    ensure_cargo_fuzz()?;
    let mut outcomes = Vec::new();
    for target in targets {
        outcomes.push(run_target(root, target, seconds)?);
        print_table(&outcomes);
    }
    let crashed: Vec<&Outcome> = outcomes
        .iter()
        .filter(|o| o.failed || !o.crashes.is_empty())
        .collect();
    if crashed.is_empty() {
        return Ok(());
    }
    for outcome in &crashed {
        for crash in &outcome.crashes {
            eprintln!("{}: {crash}", outcome.target);
        }
    }
    bail!(
        "{} target(s) crashed or failed; keep each input in tests/fuzz-regressions/TARGET/ \
         (the replay tests run them) and fix the code",
        crashed.len()
    )
}

/// libFuzzer needs nightly; say exactly what to install when it is missing.
fn ensure_nightly() -> anyhow::Result<()> {
    let Some(list) = process::output_of(Command::new("rustup").args(["toolchain", "list"])) else {
        bail!(
            "fuzzing needs rustup and a nightly toolchain, and rustup is not installed.\n\
             Install rustup (https://rustup.rs), then: rustup toolchain install nightly\n\
             Without nightly, replay the seeds and the crashes found so far on stable with: \
             cargo test -p edgewise-core --test it fuzz_regressions:: && \
             cargo test -p edgewise-app --test it fuzz_regressions::"
        );
    };
    if !list.lines().any(|line| line.starts_with("nightly")) {
        bail!(
            "fuzzing needs a nightly toolchain (libFuzzer's instrumentation), and rustup has \
             none:\n{list}\
             Install one with: rustup toolchain install nightly\n\
             Without nightly, replay the seeds and the crashes found so far on stable with: \
             cargo test -p edgewise-core --test it fuzz_regressions:: && \
             cargo test -p edgewise-app --test it fuzz_regressions::"
        );
    }
    Ok(())
}

/// `cargo fuzz` itself, built from crates.io when it is missing.
fn ensure_cargo_fuzz() -> anyhow::Result<()> {
    if process::output_of(nightly_cargo().args(["fuzz", "--version"])).is_some() {
        return Ok(());
    }
    eprintln!("==> installing cargo-fuzz (cargo install cargo-fuzz)");
    process::run(
        "cargo install cargo-fuzz",
        cargo().args(["install", "cargo-fuzz"]),
    )
}

/// `cargo +nightly`, without the variables `cargo xtask` (a stable cargo)
/// set, which would make cargo-fuzz call the stable cargo and rustc.
fn nightly_cargo() -> Command {
    let mut cmd = Command::new("cargo");
    cmd.arg("+nightly");
    for variable in [
        "CARGO",
        "RUSTUP_TOOLCHAIN",
        "RUSTC",
        "RUSTDOC",
        "RUSTC_WRAPPER",
    ] {
        cmd.env_remove(variable);
    }
    cmd
}

fn run_target(root: &Path, target: &'static str, seconds: u64) -> anyhow::Result<Outcome> {
    let fuzz = root.join("fuzz");
    let corpus = fuzz.join("corpus").join(target);
    let seeds = fuzz.join("seeds").join(target);
    fs::create_dir_all(&corpus).with_context(|| format!("cannot create {}", corpus.display()))?;
    if !seeds.is_dir() {
        bail!(
            "{} is missing; make the seeds with: cargo xtask fuzz --make-seeds",
            seeds.display()
        );
    }
    eprintln!("\n==> fuzzing {target} for {seconds}s");
    let mut cmd = nightly_cargo();
    cmd.current_dir(root).args(["fuzz", "run"]);
    if matches!(target, "course_link" | "link") {
        // Only these targets need the app, and so eframe and wgpu.
        cmd.args(["--features", "app"]);
    }
    cmd.arg(target)
        .arg(&corpus)
        .arg(&seeds)
        .arg("--")
        .arg(format!("-max_total_time={seconds}"))
        .arg(format!(
            "-timeout={}",
            if target == "vm" {
                VM_INPUT_TIMEOUT_S
            } else {
                INPUT_TIMEOUT_S
            }
        ))
        .arg("-print_final_stats=1")
        .stderr(Stdio::piped());
    if target == "vm" {
        cmd.arg(format!("-rss_limit_mb={VM_RSS_LIMIT_MB}"));
    }
    let mut child = cmd
        .spawn()
        .context("could not start cargo +nightly fuzz run")?;
    let stderr = child
        .stderr
        .take()
        .context("cargo fuzz run has no standard error")?;
    let mut executions = None;
    let mut done_seconds = None;
    let mut started = None;
    let mut crashes = Vec::new();
    for line in BufReader::new(stderr).lines() {
        let line = line.context("reading cargo fuzz run's output")?;
        eprintln!("{line}");
        if line.starts_with("INFO: Seed:") {
            started = Some(Instant::now());
        }
        if let Some(count) = line.strip_prefix("stat::number_of_executed_units:") {
            executions = count.trim().parse().ok();
        }
        if let Some((runs, secs)) = parse_done(&line) {
            executions = executions.or(Some(runs));
            done_seconds = Some(secs);
        }
        // libFuzzer also writes `slow-unit-*` files for inputs over 10 s,
        // which are reports, not failures (the limit is `-timeout`).
        if let Some(path) = line.split("Test unit written to ").nth(1)
            && !path.contains("/slow-unit-")
        {
            crashes.push(path.trim().to_owned());
        }
    }
    let status = child.wait().context("waiting for cargo fuzz run")?;
    let seconds = done_seconds
        .map(|s| s as f64)
        .or_else(|| started.map(|t| t.elapsed().as_secs_f64()))
        .unwrap_or(0.0);
    Ok(Outcome {
        target,
        executions,
        seconds,
        failed: !status.success() && crashes.is_empty(),
        crashes,
    })
}

/// `Done 123456 runs in 60 second(s)`: libFuzzer's last line when no input
/// crashed.
fn parse_done(line: &str) -> Option<(u64, u64)> {
    let rest = line.strip_prefix("Done ")?;
    let (runs, rest) = rest.split_once(" runs in ")?;
    let (secs, _) = rest.split_once(" second")?;
    Some((runs.trim().parse().ok()?, secs.trim().parse().ok()?))
}

fn print_table(outcomes: &[Outcome]) {
    eprintln!(
        "\n{:<12} {:>14} {:>9} {:>8}",
        "target", "executions", "seconds", "crashes"
    );
    for outcome in outcomes {
        let executions = outcome
            .executions
            .map_or_else(|| "?".to_owned(), |n| n.to_string());
        let crashes = if outcome.failed {
            "failed".to_owned()
        } else {
            outcome.crashes.len().to_string()
        };
        eprintln!(
            "{:<12} {executions:>14} {:>9.0} {crashes:>8}",
            outcome.target, outcome.seconds
        );
    }
}

// ---------------------------------------------------------------------------
// The seed corpus.

/// The mesh formats' seed sources: the samples, the malformed inputs, files
/// written by other libraries, and the golden files in every encoding (PLY
/// ASCII, binary little-endian and big-endian).
const MESH_SOURCES: [&str; 4] = [
    "meshes",
    "tests/bad-inputs",
    "tests/external",
    "tests/golden/formats",
];

/// The selector bytes of the `detect` target: the index of a file name in
/// `edgewise_core::fuzzing::DETECT_NAMES`, plus 0x80 for winged-edge.
const DETECT_NO_NAME: u8 = 0;
const DETECT_NO_EXTENSION: u8 = 1;
const DETECT_BY_EXTENSION: [(&str, u8); 4] = [("obj", 2), ("ply", 3), ("wtb", 4), ("htb", 5)];
const DETECT_UNKNOWN_EXTENSION: u8 = 6;

/// Course links that open a view without any message.
const VALID_LINKS: [&str; 12] = [
    "?sample=cube&structure=half&algorithm=vertexStar&step=3",
    "?sample=cube&structure=half&alg=vertexStar&step=3",
    "?sample=tetrahedron&structure=winged&algorithm=vertexAdjacentEdge&args=v:1&step=3",
    "?sample=torus&structure=winged&select=e12&camera=1.2,0.4,3.5,0,0,0",
    "?mesh=meshes/torus.obj&structure=half&ids=vertices,edges&axes=1&orientation=0&solid=1",
    "?sample=octahedron&meshScale=1.5&labelScale=2&theme=dark&embed=1&tables=0",
    "?sample=annulus&present=1&panels=algorithm,tables,menu&codeSize=18",
    "?sample=quad-grid&colors=marked:ff8800,selected:00aaff,leftFace:102030",
    "?sample=cube&structure=half&algorithm=faceAdjacentVertex&args=f:2&step=0&select=v3",
    "?sample=icosahedron&structure=winged&algorithm=vertexAdjacentFace&args=v:0&step=100",
    "?",
    "",
];

/// Rebuilds fuzz/seeds/TARGET/ for every target from the files in the
/// repository.
pub fn make_seeds(root: &Path) -> anyhow::Result<()> {
    let seeds = root.join("fuzz/seeds");
    let mut set = SeedSet::default();

    for dir in MESH_SOURCES {
        for file in files_in(&root.join(dir))? {
            let Some(extension) = file.extension().and_then(|e| e.to_str()) else {
                continue;
            };
            let extension = extension.to_ascii_lowercase();
            let Some(&(_, selector)) = DETECT_BY_EXTENSION.iter().find(|(e, _)| *e == extension)
            else {
                continue;
            };
            let Some(bytes) = read_seed(&file)? else {
                continue;
            };
            let name = seed_name(root, &file);
            set.add(&extension, &name, bytes.clone());
            // Detection: by the extension, and by content (no name, no
            // extension), in both structures.
            let winged = if name.len().is_multiple_of(2) {
                0x80
            } else {
                0
            };
            for (tag, selector) in [
                ("ext", selector | winged),
                ("noname", DETECT_NO_NAME | (winged ^ 0x80)),
                ("noext", DETECT_NO_EXTENSION | winged),
            ] {
                set.add(
                    "detect",
                    &format!("{tag}-{name}"),
                    prefixed(selector, &bytes),
                );
            }
        }
    }
    set.add(
        "detect",
        "unknown-extension.txt",
        prefixed(DETECT_UNKNOWN_EXTENSION, b"v 0 0 0\n"),
    );

    let mut algorithms = Vec::new();
    for file in files_in(&root.join("algorithms"))? {
        if file.extension().is_some_and(|e| e == "alg") {
            let text = fs::read_to_string(&file)
                .with_context(|| format!("cannot read {}", file.display()))?;
            let name = seed_name(root, &file);
            set.add("compile", &name, text.clone().into_bytes());
            for (algorithm, chunk) in split_algorithms(&text) {
                algorithms.push((format!("{name}-{algorithm}"), chunk));
            }
        }
    }
    for (name, chunk) in &algorithms {
        set.add("compile", name, chunk.clone().into_bytes());
        // The VM: after a NUL, the mesh (tetrahedron or cube) and the
        // arguments' bytes.
        for (mesh, arguments) in [(0u8, [0u8, 1, 2, 3]), (1, [5, 7, 0, 2])] {
            let mut bytes = chunk.clone().into_bytes();
            bytes.push(0);
            bytes.push(mesh);
            bytes.extend_from_slice(&arguments);
            set.add("vm", &format!("{name}-mesh{mesh}"), bytes);
        }
    }
    for file in files_in(&root.join("tests/algorithms/errors"))? {
        if file.extension().is_some_and(|e| e == "alg")
            && let Some(bytes) = read_seed(&file)?
        {
            set.add("compile", &seed_name(root, &file), bytes.clone());
            set.add("vm", &seed_name(root, &file), bytes);
        }
    }

    // The runaway runs of the hostile corpus, with their memory budget.
    for file in files_in(&root.join("tests/hostile"))? {
        let is_run = file
            .file_name()
            .and_then(|n| n.to_str())
            .is_some_and(|n| n.starts_with("run-") && n.ends_with(".alg"));
        if is_run && let Some(bytes) = read_seed(&file)? {
            set.add("vm", &seed_name(root, &file), bytes);
        }
    }

    // Conversions: every operation once on each sample and structure, then
    // the same on the octahedron read from OBJ (after a NUL).
    let octahedron_obj = fs::read(root.join("meshes/octahedron.obj"))
        .context("cannot read meshes/octahedron.obj")?;
    for choice in 0u8..4 {
        let mut chain = vec![choice];
        for (operation, ids) in (0u8..16).zip(SEED_IDS.iter().cycle()) {
            chain.push(operation);
            chain.extend_from_slice(ids);
        }
        set.add(
            "convert",
            &format!("every-operation-{choice}"),
            chain.clone(),
        );
        let mut with_obj = chain;
        with_obj.push(0);
        with_obj.extend_from_slice(&octahedron_obj);
        set.add("convert", &format!("octahedron-{choice}"), with_obj);
    }

    let messages = root.join("tests/golden/course-link-messages.txt");
    let text = fs::read_to_string(&messages)
        .with_context(|| format!("cannot read {}", messages.display()))?;
    for (i, line) in text
        .lines()
        .filter(|l| l.starts_with('?') || l.starts_with('#'))
        .enumerate()
    {
        set.add(
            "course_link",
            &format!("golden-{i:03}"),
            line.as_bytes().to_vec(),
        );
    }
    for (i, link) in VALID_LINKS.iter().enumerate() {
        set.add(
            "course_link",
            &format!("valid-{i:02}"),
            link.as_bytes().to_vec(),
        );
    }
    let octahedron = fs::read_to_string(root.join("meshes/octahedron.obj"))
        .context("cannot read meshes/octahedron.obj")?;
    set.add(
        "course_link",
        "inline-mesh",
        format!(
            "?structure=half#mesh={}&format=obj",
            encode_payload(&octahedron)
        )
        .into_bytes(),
    );
    set.add(
        "course_link",
        "payload-only",
        encode_payload(&octahedron).into_bytes(),
    );
    if let Some((name, chunk)) = algorithms.first() {
        let algorithm = name.rsplit('-').next().unwrap_or(name);
        set.add(
            "course_link",
            "inline-algorithm",
            format!(
                "?sample=cube&structure=winged&algorithm={algorithm}&args=v:0&step=2#alg={}",
                encode_payload(chunk)
            )
            .into_bytes(),
        );
    }

    // `link` opens the same links in a whole app.
    let links: Vec<_> = set
        .0
        .iter()
        .filter(|(target, ..)| target == "course_link")
        .map(|(_, name, bytes)| (name.clone(), bytes.clone()))
        .collect();
    for (name, bytes) in links {
        set.add("link", &name, bytes);
    }
    set.write(&seeds)
}

/// The seeds of every target, by target.
#[derive(Default)]
struct SeedSet(Vec<(String, String, Vec<u8>)>);

impl SeedSet {
    fn add(&mut self, target: &str, name: &str, bytes: Vec<u8>) {
        self.0.push((target.to_owned(), name.to_owned(), bytes));
    }

    fn write(&self, seeds: &Path) -> anyhow::Result<()> {
        for target in TARGETS {
            let dir = seeds.join(target);
            if dir.exists() {
                fs::remove_dir_all(&dir)
                    .with_context(|| format!("cannot empty {}", dir.display()))?;
            }
            fs::create_dir_all(&dir).with_context(|| format!("cannot create {}", dir.display()))?;
            let mine: Vec<_> = self.0.iter().filter(|(t, _, _)| t == target).collect();
            let mut total = 0;
            for (_, name, bytes) in &mine {
                let path = dir.join(name);
                fs::write(&path, bytes)
                    .with_context(|| format!("cannot write {}", path.display()))?;
                total += bytes.len();
            }
            eprintln!("{target:<12} {:>4} seeds {:>8} bytes", mine.len(), total);
        }
        Ok(())
    }
}

/// The files directly in `dir`, sorted.
fn files_in(dir: &Path) -> anyhow::Result<Vec<PathBuf>> {
    let mut files = Vec::new();
    for entry in fs::read_dir(dir).with_context(|| format!("cannot list {}", dir.display()))? {
        let path = entry?.path();
        if path.is_file() {
            files.push(path);
        }
    }
    files.sort();
    Ok(files)
}

/// A file's bytes, or `None` (with a note) if it is too large to be a seed.
fn read_seed(file: &Path) -> anyhow::Result<Option<Vec<u8>>> {
    let size = fs::metadata(file)
        .with_context(|| format!("cannot read {}", file.display()))?
        .len();
    if size > MAX_SEED_BYTES {
        eprintln!(
            "skipping {} ({size} bytes, more than {MAX_SEED_BYTES})",
            file.display()
        );
        return Ok(None);
    }
    fs::read(file)
        .map(Some)
        .with_context(|| format!("cannot read {}", file.display()))
}

/// `tests/bad-inputs/obj-empty.obj` → `tests-bad-inputs-obj-empty.obj`.
fn seed_name(root: &Path, file: &Path) -> String {
    let relative = file.strip_prefix(root).unwrap_or(file);
    relative
        .to_string_lossy()
        .replace(['/', '\\'], "-")
        .to_string()
}

fn prefixed(selector: u8, bytes: &[u8]) -> Vec<u8> {
    let mut out = Vec::with_capacity(bytes.len() + 1);
    out.push(selector);
    out.extend_from_slice(bytes);
    out
}

/// An algorithm file cut before each line that starts with `algorithm`, each
/// piece named by its algorithm.
fn split_algorithms(text: &str) -> Vec<(String, String)> {
    let mut pieces: Vec<(String, String)> = Vec::new();
    for line in text.lines() {
        if let Some(rest) = line.strip_prefix("algorithm ") {
            let name: String = rest
                .trim_start()
                .chars()
                .take_while(|c| c.is_alphanumeric() || *c == '_')
                .collect();
            pieces.push((name, String::new()));
        }
        if let Some((_, piece)) = pieces.last_mut() {
            piece.push_str(line);
            piece.push('\n');
        }
    }
    pieces
}

/// DEFLATE then base64url, as the app's Share dialog writes `#mesh=` and
/// `#alg=` payloads.
fn encode_payload(text: &str) -> String {
    let engine = base64::engine::GeneralPurpose::new(
        &base64::alphabet::URL_SAFE,
        base64::engine::general_purpose::NO_PAD,
    );
    engine.encode(miniz_oxide::deflate::compress_to_vec(text.as_bytes(), 9))
}
