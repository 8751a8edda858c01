//! `cargo xtask test`: everything CI checks, in order, with a timing summary.

use std::{path::Path, time::Instant};

use crate::{
    hosts,
    process::{self, cargo},
    serve, tidy,
    toolchain::WasmToolchain,
    web_build,
};

const CHROMIUM: &str = "/usr/bin/chromium";
const CHROMEDRIVER: &str = "/usr/bin/chromedriver";
const VULKAN_LOADER: &str = "/usr/lib/x86_64-linux-gnu/libvulkan.so.1";
const LAVAPIPE_ICD: &str = "/usr/share/vulkan/icd.d/lvp_icd.x86_64.json";
const BROWSER_TESTS: &str = "edgewise-browser-tests";
/// The crates that are compiled for the browser.
const WASM_PACKAGES: [&str; 5] = [
    "edgewise-core",
    "edgewise-pictures",
    "edgewise-model",
    "edgewise-renderer",
    "edgewise-app",
];

/// Runs every check CI runs and stops at the first failure.
pub fn run_all(root: &Path) -> anyhow::Result<()> {
    let mut timings = Timings::default();

    timings.step("architecture (tidy)", || tidy::run(root))?;
    timings.step("formatting", || {
        process::run(
            "cargo fmt --check",
            cargo().args(["fmt", "--all", "--", "--check"]),
        )
    })?;
    timings.step("clippy (native)", || {
        process::run(
            "clippy (native)",
            cargo().args([
                "clippy",
                "--locked",
                "--workspace",
                "--all-targets",
                "--",
                "-D",
                "warnings",
            ]),
        )
    })?;
    let toolchain = timings.step("wasm32 toolchain", WasmToolchain::find)?;
    timings.step("clippy (wasm32)", || wasm_lints(root, toolchain))?;
    timings.step("native tests", || {
        // The 3D view's render tests draw on the CPU through lavapipe.
        process::ensure_debian_packages(
            "the 3D view's render tests (software Vulkan)",
            &[
                (VULKAN_LOADER, "libvulkan1"),
                (LAVAPIPE_ICD, "mesa-vulkan-drivers"),
            ],
        )?;
        process::run(
            "native tests",
            cargo()
                .args([
                    "test",
                    "--locked",
                    "--workspace",
                    "--exclude",
                    BROWSER_TESTS,
                ])
                // The rendering tests fail, rather than skip, without an adapter.
                .env("EDGEWISE_REQUIRE_GPU", "1"),
        )
    })?;
    let dist = timings.step("wasm build", || {
        web_build::build(root, web_build::Profile::Release)
    })?;
    timings.step("browser tests", || browser_tests(root, &dist))?;

    timings.print();
    eprintln!("==> all checks passed");
    Ok(())
}

/// Lints the crates that run in the browser, as compiled for wasm32.
fn wasm_lints(root: &Path, toolchain: WasmToolchain) -> anyhow::Result<()> {
    let target_dir = web_build::target_dir(root);
    let mut cmd = if toolchain.has_clippy() {
        toolchain.cargo("clippy", &target_dir)
    } else {
        eprintln!(
            "==> Debian's rustc-web has no clippy: wasm32 code is checked with rustc's lints \
             (clippy's lints run natively on the same code)"
        );
        let mut cmd = toolchain.cargo("check", &target_dir);
        cmd.env("RUSTFLAGS", "-D warnings");
        cmd
    };
    cmd.arg("--locked");
    for package in WASM_PACKAGES {
        cmd.args(["--package", package]);
    }
    if toolchain.has_clippy() {
        cmd.args(["--", "-D", "warnings"]);
    }
    process::run("wasm32 lints", &mut cmd)
}

/// Serves `dist` and the host pages that embed it (hosts.rs), each on its
/// own origin, and runs the browser tests against them in headless Chromium.
pub fn browser_tests(root: &Path, dist: &Path) -> anyhow::Result<()> {
    process::ensure_debian_packages(
        "the browser tests",
        &[(CHROMIUM, "chromium"), (CHROMEDRIVER, "chromium-driver")],
    )?;
    let addr = serve::serve_in_background(dist)?;
    let url = format!("http://{addr}/");
    let hosts_addr = serve::serve_in_background(&hosts::build(root, &url)?)?;
    let hosts_url = format!("http://{hosts_addr}/");
    eprintln!("==> browser tests against {url}, hosts at {hosts_url}");
    process::run(
        "browser tests",
        cargo()
            .current_dir(root)
            .args(["test", "--locked", "--package", BROWSER_TESTS])
            // One test at a time: two software-rendered pages side by side on
            // a two-core machine starved each other's renderers past the
            // tests' waits (a host page, then the edit menu's undo).
            .args(["--", "--test-threads=1"])
            .env("EDGEWISE_URL", &url)
            .env("EDGEWISE_HOSTS_URL", &hosts_url)
            .env("EDGEWISE_CHROMIUM", CHROMIUM)
            .env("EDGEWISE_CHROMEDRIVER", CHROMEDRIVER),
    )
}

/// `cargo xtask bench-web`: serves dist/ and web/bench/, and runs the
/// benchmark driver of the browser tests' crate, which prints the table.
pub fn bench_web(root: &Path, dist: &Path) -> anyhow::Result<()> {
    process::ensure_debian_packages(
        "the web benchmark",
        &[(CHROMIUM, "chromium"), (CHROMEDRIVER, "chromium-driver")],
    )?;
    let app = serve::serve_in_background(dist)?;
    let baseline = serve::serve_in_background(&root.join("web/bench"))?;
    eprintln!("==> benchmarking http://{app}/ beside http://{baseline}/baseline.html");
    process::run(
        "web benchmark",
        cargo()
            .current_dir(root)
            .args([
                "run",
                "--locked",
                "--package",
                BROWSER_TESTS,
                "--bin",
                "bench_web",
            ])
            .env("EDGEWISE_URL", format!("http://{app}/"))
            .env("EDGEWISE_BASELINE_URL", format!("http://{baseline}/"))
            .env("EDGEWISE_DIST", dist)
            .env("EDGEWISE_CHROMIUM", CHROMIUM)
            .env("EDGEWISE_CHROMEDRIVER", CHROMEDRIVER),
    )
}

/// How long each step took, printed at the end so slow steps stand out.
#[derive(Default)]
struct Timings(Vec<(&'static str, f64)>);

impl Timings {
    fn step<T>(
        &mut self,
        name: &'static str,
        f: impl FnOnce() -> anyhow::Result<T>,
    ) -> anyhow::Result<T> {
        eprintln!("\n==> {name}");
        let start = Instant::now();
        let result = f();
        self.0.push((name, start.elapsed().as_secs_f64()));
        if result.is_err() {
            self.print();
        }
        result
    }

    fn print(&self) {
        eprintln!("\n==> timings");
        for (name, secs) in &self.0 {
            eprintln!("    {name:<20} {secs:>7.1} s");
        }
    }
}
