//! Edgewise's build tool, run as `cargo xtask <command>`.
//!
//! - `serve [--port N] [--profiling]` builds the app for the browser into
//!   dist/ and serves it.
//! - `test` runs everything CI checks.
//! - `build-web [--dev | --profiling]` only builds dist/.
//! - `browser-test` builds dist/ and runs only the browser tests.
//! - `hosts [--app URL]` installs reveal.js and `MkDocs`, builds a deck and
//!   notes that embed the app, and serves them.
//! - `package ARGS` builds dist/ and runs `edgewise package ARGS` with it:
//!   a SCORM package of the release build (docs/lms.md).
//! - `tidy` checks the invariants ARCHITECTURE.md states (module cycles,
//!   column names, layers, the crate map).
//! - `fuzz [TARGET] [--seconds N]` fuzzes with cargo-fuzz (nightly only);
//!   `fuzz --make-seeds` rebuilds the seed corpus in fuzz/seeds/.

mod bench_wasm;
mod fuzz;
mod hosts;
mod native_tests;
mod process;
mod serve;
mod test;
mod tidy;
mod toolchain;
mod wasm_beside;
mod web_build;

use std::path::PathBuf;

use anyhow::Context as _;
use clap::{Parser, Subcommand};

#[derive(Parser)]
#[command(name = "cargo xtask", about = "Build, serve and test Edgewise.")]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Build the app for the browser (release) into dist/ and serve it until stopped.
    Serve {
        /// The port to serve on.
        #[arg(long, default_value_t = 8080)]
        port: u16,
        /// Keep the functions' names, for a browser profiler.
        #[arg(long)]
        profiling: bool,
    },
    /// Run everything CI checks: formatting, clippy (native and wasm32), native
    /// tests, the wasm build, and the browser tests in headless Chromium.
    Test,
    /// Build the app for the browser into dist/ without serving it.
    BuildWeb {
        /// An unoptimised build, quicker to compile.
        #[arg(long, conflicts_with = "profiling")]
        dev: bool,
        /// Keep the functions' names, for a browser profiler.
        #[arg(long)]
        profiling: bool,
    },
    /// Build dist/ and run only the browser tests.
    BrowserTest {
        /// Only the tests whose names contain one of these (`cargo test`'s
        /// filters), for a quicker check of one page while working on it.
        filters: Vec<String>,
    },
    /// Check the invariants ARCHITECTURE.md states: no module cycles, a
    /// column named only in schema/column.rs, `impl EdgewiseApp` only in
    /// app/, dependencies down the layers, every crate described.
    Tidy,
    /// Install reveal.js and mkdocs from the package registries as web/hosts
    /// pins them, build a deck and lecture notes that embed the app, and
    /// serve them (and dist/) until stopped: the hosts the browser tests use.
    Hosts {
        /// Where the app is served (default: serve the built dist/ here).
        #[arg(long)]
        app: Option<String>,
    },
    /// Build dist/ (release), then make a SCORM package of it: `cargo xtask
    /// package -- week3.zip --scorm 2004 --exercise kev-half-edge` runs
    /// `edgewise package` with these arguments and `--app dist`.
    Package {
        /// The arguments of `edgewise package`.
        #[arg(trailing_var_arg = true, allow_hyphen_values = true)]
        args: Vec<String>,
    },
    /// Build dist/, then measure it in headless Chromium beside a bare WebGL2
    /// page drawing the same torus, and print the table (see README).
    BenchWeb,
    /// Build the `mesh_build` benchmark's builders and floor for wasm32 and
    /// print their medians and ratios under node, then in headless Chromium
    /// (docs/performance.md).
    BenchWasm,
    /// Fuzz one target, or each in turn, with cargo-fuzz and libFuzzer (needs
    /// a nightly toolchain; see docs/reliability.md), then print the
    /// executions, seconds and crashes of each.
    Fuzz {
        /// The target: `obj`, `ply`, `wtb`, `htb`, `detect`, `compile`, `vm`, `convert` or `course_link`
        /// (default: all of them, in that order).
        target: Option<String>,
        /// How long to fuzz each target.
        #[arg(long, default_value_t = 60)]
        seconds: u64,
        /// Rebuild fuzz/seeds/ from the samples, the test inputs, the
        /// algorithm library and the course-link goldens instead of fuzzing.
        #[arg(long, conflicts_with = "target")]
        make_seeds: bool,
    },
}

fn main() -> std::process::ExitCode {
    match run(&Cli::parse()) {
        Ok(()) => std::process::ExitCode::SUCCESS,
        Err(err) => {
            eprintln!("\nxtask: error: {err:#}");
            std::process::ExitCode::FAILURE
        }
    }
}

fn run(cli: &Cli) -> anyhow::Result<()> {
    let root = workspace_root()?;
    std::env::set_current_dir(&root)
        .with_context(|| format!("cannot enter the workspace at {}", root.display()))?;
    match cli.command {
        Command::Serve { port, profiling } => {
            let dist = web_build::build(
                &root,
                web_build::Profile::release(profiling),
                web_build::Lints::Off,
            )?;
            serve::serve_forever(&dist, port)
        }
        Command::Test => test::run_all(&root),
        Command::BuildWeb { dev, profiling } => {
            let profile = if dev {
                web_build::Profile::Dev
            } else {
                web_build::Profile::release(profiling)
            };
            web_build::build(&root, profile, web_build::Lints::Off).map(|_| ())
        }
        Command::BrowserTest { ref filters } => {
            let dist =
                web_build::build(&root, web_build::Profile::Release, web_build::Lints::Clippy)?;
            test::browser_tests(&root, &dist, &process::Edgewise::CargoRun, filters)
        }
        Command::Package { ref args } => {
            let dist = web_build::build(&root, web_build::Profile::Release, web_build::Lints::Off)?;
            let mut package = process::Edgewise::CargoRun.package();
            package.args(args);
            if !args
                .iter()
                .any(|arg| arg == "--app" || arg.starts_with("--app="))
            {
                package.arg("--app").arg(&dist);
            }
            process::run("edgewise package", &mut package)
        }
        Command::Tidy => tidy::run(&root),
        Command::Hosts { ref app } => hosts::serve(&root, app.as_deref()),
        Command::BenchWeb => {
            let dist = web_build::build(&root, web_build::Profile::Release, web_build::Lints::Off)?;
            test::bench_web(&root, &dist)
        }
        Command::BenchWasm => bench_wasm::run(&root),
        Command::Fuzz {
            ref target,
            seconds,
            make_seeds,
        } => {
            if make_seeds {
                fuzz::make_seeds(&root)
            } else {
                fuzz::run(&root, target.as_deref(), seconds)
            }
        }
    }
}

/// The workspace root: the parent of crates/xtask.
fn workspace_root() -> anyhow::Result<PathBuf> {
    let manifest_dir = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    manifest_dir
        .ancestors()
        .nth(2)
        .map(PathBuf::from)
        .context("crates/xtask is not inside a workspace")
}
