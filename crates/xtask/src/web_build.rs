//! Building the browser app into dist/: wasm32 compile, bindgen, static files.

use std::path::{Path, PathBuf};

use anyhow::Context as _;

use crate::{process, toolchain::WasmToolchain};

/// The wasm build profile.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Profile {
    Dev,
    Release,
}

impl Profile {
    fn dir_name(self) -> &'static str {
        match self {
            Self::Dev => "debug",
            Self::Release => "release",
        }
    }
}

/// The package and binary that make up the browser app.
const APP_PACKAGE: &str = "edgewise-app";
/// The stem of the generated JS and wasm files; index.html imports `edgewise_app.js`.
const OUT_NAME: &str = "edgewise_app";

/// Builds the app for the browser into `root/dist` and returns that path.
pub fn build(root: &Path, profile: Profile) -> anyhow::Result<PathBuf> {
    let toolchain = WasmToolchain::find()?;
    let target_dir = root.join("target");
    eprintln!("==> building {APP_PACKAGE} for wasm32 ({profile:?}, {toolchain:?} toolchain)");

    let mut cmd = toolchain.cargo("build", &target_dir);
    cmd.args(["--locked", "--package", APP_PACKAGE, "--bin", APP_PACKAGE]);
    if profile == Profile::Release {
        cmd.arg("--release");
    }
    process::run("the wasm build", &mut cmd)?;

    let wasm = toolchain
        .artifact_dir(&target_dir, profile.dir_name())
        .join(format!("{APP_PACKAGE}.wasm"));
    let dist = root.join("dist");
    if dist.exists() {
        std::fs::remove_dir_all(&dist)
            .with_context(|| format!("cannot clear {}", dist.display()))?;
    }
    std::fs::create_dir_all(&dist)?;

    eprintln!("==> generating JavaScript bindings");
    wasm_bindgen_cli_support::Bindgen::new()
        .input_path(&wasm)
        .out_name(OUT_NAME)
        .web(true)?
        .typescript(false)
        // init() then finds the wasm file beside the JS file by itself.
        .omit_default_module_path(false)
        .debug(profile == Profile::Dev)
        .generate(&dist)
        .with_context(|| format!("wasm-bindgen could not process {}", wasm.display()))?;

    copy_file(&root.join("index.html"), &dist.join("index.html"))?;
    copy_dir(&root.join("web/static"), &dist)?;

    let wasm_out = dist.join(format!("{OUT_NAME}_bg.wasm"));
    let size = std::fs::metadata(&wasm_out).map(|m| m.len()).unwrap_or(0);
    eprintln!(
        "==> dist/ is ready ({:.1} MB of wasm)",
        size as f64 / 1_000_000.0
    );
    Ok(dist)
}

fn copy_file(from: &Path, to: &Path) -> anyhow::Result<()> {
    std::fs::copy(from, to)
        .with_context(|| format!("cannot copy {} to {}", from.display(), to.display()))?;
    Ok(())
}

/// Copies the files of `from` (recursively) into `to`.
fn copy_dir(from: &Path, to: &Path) -> anyhow::Result<()> {
    for entry in
        std::fs::read_dir(from).with_context(|| format!("cannot read {}", from.display()))?
    {
        let entry = entry?;
        let target = to.join(entry.file_name());
        if entry.file_type()?.is_dir() {
            std::fs::create_dir_all(&target)?;
            copy_dir(&entry.path(), &target)?;
        } else {
            copy_file(&entry.path(), &target)?;
        }
    }
    Ok(())
}
