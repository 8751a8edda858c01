//! `cargo xtask test`: everything CI checks, in order, with a timing summary.

use std::{path::Path, time::Instant};

use anyhow::Context as _;

use crate::{
    hosts,
    native_tests::{self, NativeTests},
    process::{self, CHECKS_PROFILE, Edgewise, cargo},
    serve, tidy,
    toolchain::WasmToolchain,
    wasm_beside::WasmBeside,
    web_build,
};

const CHROMIUM: &str = "/usr/bin/chromium";
const CHROMEDRIVER: &str = "/usr/bin/chromedriver";
const VULKAN_LOADER: &str = "/usr/lib/x86_64-linux-gnu/libvulkan.so.1";
const LAVAPIPE_ICD: &str = "/usr/share/vulkan/icd.d/lvp_icd.x86_64.json";
/// Vulkan on the CPU, which the native render tests and the browser tests'
/// WebGL2 draw with.
const SOFTWARE_VULKAN: &[(&str, &str)] = &[
    (VULKAN_LOADER, "libvulkan1"),
    (LAVAPIPE_ICD, "mesa-vulkan-drivers"),
];
/// The browser tests' target: `test = false` keeps it out of `--all-targets`,
/// as it needs the served app.
const BROWSER_TESTS: &str = "browser";
/// Their crate, whose `bench_web` binary is `cargo xtask bench-web`.
const BROWSER_TESTS_PACKAGE: &str = "edgewise-browser-tests";
/// The crates that are compiled for wasm32: the browser's, and the wasm32
/// benchmark, whose code exists only there.
const WASM_PACKAGES: [&str; 6] = [
    "edgewise-core",
    "edgewise-bench-wasm",
    "edgewise-pictures",
    "edgewise-model",
    "edgewise-renderer",
    "edgewise-app",
];
/// Of those, the one the browser app's build does not compile.
const WASM_BENCHMARK: &str = "edgewise-bench-wasm";

/// Runs every check CI runs and stops at the first failure.
pub fn run_all(root: &Path) -> anyhow::Result<()> {
    let mut timings = Timings::default();
    let result = run_steps(root, &mut timings);
    timings.print();
    result?;
    eprintln!("==> all checks passed");
    Ok(())
}

fn run_steps(root: &Path, timings: &mut Timings) -> anyhow::Result<()> {
    timings.step("architecture (tidy)", || tidy::run(root))?;
    timings.step("formatting", || {
        process::run(
            "cargo fmt --check",
            cargo().args(["fmt", "--all", "--", "--check"]),
        )
    })?;
    // The wasm build runs beside the native steps (`wasm_beside.rs`).
    let toolchain = timings.step("wasm32 toolchain", WasmToolchain::find)?;
    let wasm = timings.step("wasm build started", || WasmBeside::start(root, toolchain))?;
    timings.step("native build and lints", || {
        process::run(
            "native build and lints",
            workspace_test().args(["--no-run", "--all-targets"]),
        )?;
        // `--all-targets` outweighs `--test`, so the browser tests are built
        // on their own, with everything they share already built.
        process::run(
            "the browser tests' build",
            workspace_test().args(["--no-run", "--test", BROWSER_TESTS]),
        )
    })?;
    let (mut native, edgewise) = timings.step("native tests started, and the doctests", || {
        start_native_tests(root)
    })?;
    timings.step("clippy (the wasm32 benchmark)", || {
        wasm_lints(root, toolchain)
    })?;
    native.check()?;
    let (dist, compiled) = timings.step("wasm build and lints, the rest", || wasm.finish(root))?;
    timings.beside("the wasm build's compile", compiled.as_secs_f64());
    native.check()?;
    timings.step("browser tests", || {
        browser_tests(root, &dist, &edgewise, &[])
    })?;
    let ran = timings.step("native tests, the rest", || native.finish())?;
    timings.beside(
        "native tests, from their start to their end",
        ran.as_secs_f64(),
    );
    Ok(())
}

/// Starts the native tests beside the steps that follow (`native_tests.rs`),
/// then runs the doctests, which target flags leave out and which need
/// cargo's build lock, in the foreground. The benchmarks were built and
/// linted with the rest; run once each in criterion's test mode they would
/// add half a minute and test nothing the tests do not. Also returns the
/// `edgewise` binary that build made, for the host pages.
fn start_native_tests(root: &Path) -> anyhow::Result<(NativeTests, Edgewise)> {
    // The 3D view's render tests draw on the CPU through lavapipe.
    process::ensure_debian_packages(
        "the 3D view's render tests (software Vulkan)",
        SOFTWARE_VULKAN,
    )?;
    let built =
        native_tests::list(workspace_test().args(["--lib", "--bins", "--tests", "--examples"]))?;
    // `cargo run` instead would compile the CLI again, and relink the binary
    // the CLI's tests are running.
    let edgewise = built
        .edgewise
        .map(Edgewise::Built)
        .context("the test build listed no `edgewise` binary for the host pages")?;
    let log = web_build::target_dir(root).join("native-tests.log");
    eprintln!(
        "==> {} native test executables started at the lowest priority; their output, in {}, \
         follows the browser tests",
        built.tests.len(),
        log.display()
    );
    // The rendering tests fail, rather than skip, without an adapter.
    let mut envs = vec![("EDGEWISE_REQUIRE_GPU".to_owned(), "1".to_owned())];
    if std::env::var_os("XDG_RUNTIME_DIR").is_none() {
        // The app's tests start eframe, whose Wayland probe printed "error:
        // XDG_RUNTIME_DIR is invalid or not set" 304 times into the log of
        // a passing run. A private folder of their own quiets it.
        envs.push(("XDG_RUNTIME_DIR".to_owned(), runtime_dir(root)?));
    }
    let native = NativeTests::start(built.tests, envs, &log)?;
    process::run("doctests", workspace_test().arg("--doc"))?;
    Ok((native, edgewise))
}

/// target/xdg-runtime, readable by its owner only, as the XDG base
/// directory specification asks of a runtime directory.
fn runtime_dir(root: &Path) -> anyhow::Result<String> {
    let dir = web_build::target_dir(root).join("xdg-runtime");
    std::fs::create_dir_all(&dir).with_context(|| format!("cannot make {}", dir.display()))?;
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt as _;
        std::fs::set_permissions(&dir, std::fs::Permissions::from_mode(0o700))
            .with_context(|| format!("cannot make {} private", dir.display()))?;
    }
    Ok(dir.display().to_string())
}

/// `cargo test` over the whole workspace, its own crates compiled by
/// clippy-driver ([`process::lint_with_clippy`]). Every step that
/// builds natively (the browser tests' too) selects the same packages with
/// the same environment, so that none rebuilds what another built (a narrower selection unifies features
/// differently and recompiles the crates that share them).
fn workspace_test() -> std::process::Command {
    let mut cmd = cargo();
    cmd.args([
        "test",
        "--locked",
        "--workspace",
        "--profile",
        CHECKS_PROFILE,
    ]);
    process::lint_with_clippy(&mut cmd);
    cmd
}

/// Lints the crates compiled for wasm32 that the wasm build does not: with
/// clippy, the build lints the app and what it uses, so only the wasm32
/// benchmark is checked here (a separate `cargo clippy` of the app checked
/// its dependencies once more, about two minutes of a cold run). Without
/// clippy, every wasm32 crate is checked with rustc's lints.
fn wasm_lints(root: &Path, toolchain: WasmToolchain) -> anyhow::Result<()> {
    let target_dir = web_build::target_dir(root);
    let mut cmd = if toolchain.has_clippy() {
        let mut cmd = toolchain.cargo("clippy", &target_dir);
        cmd.args([
            "--locked",
            "--package",
            WASM_BENCHMARK,
            "--",
            "-D",
            "warnings",
        ]);
        cmd
    } else {
        eprintln!(
            "==> Debian's rustc-web has no clippy: wasm32 code is checked with rustc's lints \
             (clippy's lints run natively on the same code)"
        );
        let mut cmd = toolchain.cargo("check", &target_dir);
        cmd.arg("--locked").env("RUSTFLAGS", "-D warnings");
        for package in WASM_PACKAGES {
            cmd.args(["--package", package]);
        }
        cmd
    };
    process::run("wasm32 lints", &mut cmd)
}

/// Serves `dist` and the host pages that embed it (hosts.rs), each on its
/// own origin, and runs the browser tests against them in headless Chromium.
/// `edgewise` makes the host pages' SCORM packages; `filters`, if any, pick
/// the tests whose names contain one of them.
pub fn browser_tests(
    root: &Path,
    dist: &Path,
    edgewise: &Edgewise,
    filters: &[String],
) -> anyhow::Result<()> {
    // Their WebGL2 draws on lavapipe (`Renderer` in the browser tests).
    process::ensure_debian_packages(
        "the browser tests",
        &[
            &[(CHROMIUM, "chromium"), (CHROMEDRIVER, "chromium-driver")],
            SOFTWARE_VULKAN,
        ]
        .concat(),
    )?;
    let addr = serve::serve_in_background(dist)?;
    let url = format!("http://{addr}/");
    let hosts_addr = serve::serve_in_background(&hosts::build(root, &url, edgewise)?)?;
    let hosts_url = format!("http://{hosts_addr}/");
    eprintln!("==> browser tests against {url}, hosts at {hosts_url}");
    process::run(
        "browser tests",
        workspace_test()
            .current_dir(root)
            .args(["--test", BROWSER_TESTS])
            // One test at a time: two software-rendered pages side by side on
            // a two-core machine starved each other's renderers past the
            // tests' waits (a host page, then the edit menu's undo).
            .args(["--", "--test-threads=1"])
            .args(filters)
            .env("EDGEWISE_URL", &url)
            .env("EDGEWISE_HOSTS_URL", &hosts_url)
            .env("EDGEWISE_CHROMIUM", CHROMIUM)
            .env("EDGEWISE_CHROMEDRIVER", CHROMEDRIVER),
    )
}

/// `cargo xtask bench-web`: serves dist/ and web/bench/, and runs the
/// benchmark driver of the browser tests' crate, which prints the table.
pub fn bench_web(root: &Path, dist: &Path) -> anyhow::Result<()> {
    let app = serve::serve_in_background(dist)?;
    let baseline = serve::serve_in_background(&root.join("web/bench"))?;
    eprintln!("==> benchmarking http://{app}/ beside http://{baseline}/baseline.html");
    run_browser_bench(
        root,
        "bench_web",
        &[
            ("EDGEWISE_URL", format!("http://{app}/")),
            ("EDGEWISE_BASELINE_URL", format!("http://{baseline}/")),
            ("EDGEWISE_DIST", dist.display().to_string()),
        ],
    )
}

/// Runs benchmark driver `bin` of the browser tests' crate in headless
/// Chromium, with `vars` set (the pages it measures).
pub fn run_browser_bench(root: &Path, bin: &str, vars: &[(&str, String)]) -> anyhow::Result<()> {
    process::ensure_debian_packages(
        "the browser benchmarks",
        &[(CHROMIUM, "chromium"), (CHROMEDRIVER, "chromium-driver")],
    )?;
    let mut command = cargo();
    command
        .current_dir(root)
        .args([
            "run",
            "--locked",
            "--package",
            BROWSER_TESTS_PACKAGE,
            "--bin",
            bin,
        ])
        .env("EDGEWISE_CHROMIUM", CHROMIUM)
        .env("EDGEWISE_CHROMEDRIVER", CHROMEDRIVER);
    for (name, value) in vars {
        command.env(name, value);
    }
    process::run(bin, &mut command)
}

/// How long each step took, printed at the end so slow steps stand out, and
/// how long the work beside the steps ran.
#[derive(Default)]
struct Timings {
    steps: Vec<(&'static str, f64)>,
    beside: Vec<(&'static str, f64)>,
}

impl Timings {
    fn step<T>(
        &mut self,
        name: &'static str,
        f: impl FnOnce() -> anyhow::Result<T>,
    ) -> anyhow::Result<T> {
        eprintln!("\n==> {name}");
        let start = Instant::now();
        let result = f();
        self.steps.push((name, start.elapsed().as_secs_f64()));
        result
    }

    fn beside(&mut self, name: &'static str, secs: f64) {
        self.beside.push((name, secs));
    }

    fn print(&self) {
        eprintln!("\n==> timings");
        for (name, secs) in &self.steps {
            eprintln!("    {name:<38} {secs:>7.1} s");
        }
        let all: f64 = self.steps.iter().map(|(_, secs)| secs).sum();
        eprintln!("    {:<38} {all:>7.1} s", "all steps");
        for (name, secs) in &self.beside {
            eprintln!("    beside them: {name}, {secs:.1} s");
        }
    }
}
