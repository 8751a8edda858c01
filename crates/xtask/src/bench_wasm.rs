//! `cargo xtask bench-wasm`: the `mesh_build` benchmark's builders against
//! the floor, compiled for wasm32 with the browser build's profile
//! (crates/bench-wasm), run under node and then in headless Chromium, the
//! engine the page runs on, each printed as the native bench prints them.

use std::{path::Path, process::Command};

use crate::{process, serve, test, toolchain::WasmToolchain, web_build};

const PACKAGE: &str = "edgewise-bench-wasm";
/// The browser build's profile: what the page runs.
const PROFILE: &str = "web";

/// Instantiates the module with the clock and the output it imports, and
/// runs it.
const RUNNER: &str = r"
import { readFileSync } from 'node:fs';
const bytes = readFileSync(process.argv[2]);
let memory;
const { instance } = await WebAssembly.instantiate(bytes, {
  bench: {
    now: () => performance.now(),
    print: (text, len) => process.stdout.write(Buffer.from(memory.buffer, text, len)),
  },
});
memory = instance.exports.memory;
instance.exports.run();
";

pub fn run(root: &Path) -> anyhow::Result<()> {
    let toolchain = WasmToolchain::find()?;
    let target_dir = web_build::target_dir(root);
    let mut build = toolchain.cargo("build", &target_dir);
    build.args(["--locked", "--profile", PROFILE, "--package", PACKAGE]);
    process::run("the wasm32 benchmark's build", &mut build)?;
    let wasm = toolchain
        .artifact_dir(&target_dir, PROFILE)
        .join("edgewise_bench_wasm.wasm");

    if process::output_of(Command::new("node").arg("--version")).is_none() {
        process::ensure_debian_packages("the wasm32 benchmark", &[("/usr/bin/node", "nodejs")])?;
    }
    let runner = target_dir.join("bench-wasm.mjs");
    std::fs::write(&runner, RUNNER)?;
    eprintln!("==> the builders against the floor, as wasm32 under node:\n");
    process::run("node", Command::new("node").arg(&runner).arg(&wasm))?;

    // The page's engine: the module served beside an empty page, which the
    // browser tests' `bench_wasm` driver opens and runs.
    let page = target_dir.join("bench-wasm-page");
    std::fs::create_dir_all(&page)?;
    std::fs::copy(&wasm, page.join("edgewise_bench_wasm.wasm"))?;
    std::fs::write(
        page.join("index.html"),
        "<!doctype html><title>bench-wasm</title>",
    )?;
    let addr = serve::serve_in_background(&page)?;
    eprintln!("\n==> the builders against the floor, as wasm32 in headless Chromium:\n");
    test::run_browser_bench(
        root,
        "bench_wasm",
        &[("EDGEWISE_URL", format!("http://{addr}/"))],
    )
}
