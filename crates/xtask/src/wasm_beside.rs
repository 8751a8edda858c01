//! The wasm build of `cargo xtask test`, run beside the native build.
//!
//! The two builds write to different directories of target/ (the `checks`
//! profile natively, the `web` profile for wasm32, each with its own build
//! scripts), so neither waits for the other's lock. After a one-line change
//! in the app the native build and the doctests take about 7 s, which the
//! wasm build's 50 s (its fat-LTO link on one core) now covers; on a cold
//! run each fills the other's single-core moments (docs/performance.md).
//!
//! Its cargo writes to a log, so that its output does not interleave with
//! the native build's; the log is printed, and dist/ assembled, where the
//! wasm build used to run.

use std::{
    fs::File,
    path::{Path, PathBuf},
    process::Child,
    time::{Duration, Instant},
};

use anyhow::{Context as _, bail};

use crate::{
    toolchain::WasmToolchain,
    web_build::{self, Lints, Profile},
};

/// The build's cargo, running; dropping it stops it.
pub struct WasmBeside {
    cargo: Option<Child>,
    toolchain: WasmToolchain,
    log: PathBuf,
    started: Instant,
}

impl WasmBeside {
    /// Starts compiling the release build, linted, with cargo's output in
    /// target/wasm-build.log.
    pub fn start(root: &Path, toolchain: WasmToolchain) -> anyhow::Result<Self> {
        let log = web_build::target_dir(root).join("wasm-build.log");
        let file =
            File::create(&log).with_context(|| format!("cannot create {}", log.display()))?;
        let cargo = web_build::compile(root, toolchain, Profile::Release, Lints::Clippy)
            .stdout(file.try_clone()?)
            .stderr(file)
            .spawn()
            .context("cannot start the wasm build")?;
        eprintln!(
            "==> started beside the native build; its output, in {}, follows the native steps",
            log.display()
        );
        Ok(Self {
            cargo: Some(cargo),
            toolchain,
            log,
            started: Instant::now(),
        })
    }

    /// Waits for the compile, prints its output, assembles dist/, and
    /// returns dist/ and how long the compile ran.
    pub fn finish(mut self, root: &Path) -> anyhow::Result<(PathBuf, Duration)> {
        let mut cargo = self
            .cargo
            .take()
            .context("the wasm build was already waited for")?;
        let status = cargo.wait().context("cannot wait for the wasm build")?;
        let ran = self.started.elapsed();
        let output = std::fs::read_to_string(&self.log)
            .with_context(|| format!("cannot read {}", self.log.display()))?;
        eprint!("{output}");
        if !status.success() {
            bail!("the wasm build failed ({status}); its output is above");
        }
        let dist = web_build::assemble(root, self.toolchain, Profile::Release)?;
        Ok((dist, ran))
    }
}

impl Drop for WasmBeside {
    /// A native step that fails ends the run, and the build with it.
    fn drop(&mut self) {
        if let Some(mut cargo) = self.cargo.take() {
            cargo.kill().ok();
            cargo.wait().ok();
        }
    }
}
