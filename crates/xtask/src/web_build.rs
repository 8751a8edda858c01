//! Building the browser app into dist/: wasm32 compile, bindgen, static files,
//! the example pages, and the build's version in the service worker.

use std::{
    path::{Path, PathBuf},
    process::Command,
};

use anyhow::Context as _;

use crate::{process, toolchain::WasmToolchain};

/// The wasm build profile.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Profile {
    Dev,
    Release,
    /// Release code with its functions' name section kept, which the
    /// release build drops, so that a browser's CPU profile names each
    /// function.
    Profiling,
}

impl Profile {
    /// The release build, or the profiling one.
    pub fn release(profiling: bool) -> Self {
        if profiling {
            Self::Profiling
        } else {
            Self::Release
        }
    }

    fn dir_name(self) -> &'static str {
        match self {
            Self::Dev => "debug",
            Self::Release | Self::Profiling => "web",
        }
    }
}

/// The package and binary that make up the browser app.
const APP_PACKAGE: &str = "edgewise-app";
/// The stem of the generated JS and wasm files. The build's version goes
/// into their names (`edgewise_app.<build>.js`, `edgewise_app_bg.<build>.wasm`),
/// which index.html and sw.js name through [`BUILD_PLACEHOLDER`].
const OUT_NAME: &str = "edgewise_app";

/// Whether a wasm build lints the workspace's crates as it compiles them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Lints {
    /// `serve` and the other commands that only need dist/: a newer
    /// toolchain's lints must never stop a lecturer's server.
    Off,
    /// `cargo xtask test` and `browser-test`: clippy, where the toolchain has
    /// it ([`process::lint_with_clippy`]), with every warning an error.
    Clippy,
}

/// Builds the app for the browser into `root/dist` and returns that path.
pub fn build(root: &Path, profile: Profile, lints: Lints) -> anyhow::Result<PathBuf> {
    let toolchain = WasmToolchain::find()?;
    process::run(
        "the wasm build",
        &mut compile(root, toolchain, profile, lints),
    )?;
    assemble(root, toolchain, profile)
}

/// The cargo command that compiles the app to wasm32.
pub fn compile(root: &Path, toolchain: WasmToolchain, profile: Profile, lints: Lints) -> Command {
    eprintln!("==> building {APP_PACKAGE} for wasm32 ({profile:?}, {toolchain:?} toolchain)");
    let mut cmd = toolchain.cargo("build", &target_dir(root));
    cmd.args(["--locked", "--package", APP_PACKAGE, "--bin", APP_PACKAGE]);
    if profile != Profile::Dev {
        // Cargo.toml's `web` profile: release, with LTO, optimised for size.
        cmd.args(["--profile", "web"]);
    }
    if lints == Lints::Clippy && toolchain.has_clippy() {
        process::lint_with_clippy(&mut cmd);
    }
    cmd
}

/// Where the browser app is assembled.
pub fn dist_dir(root: &Path) -> PathBuf {
    root.join("dist")
}

/// Assembles dist/ from what [`compile`] built: the JavaScript bindings,
/// the page and its static files, the build's stamp, and the gzipped
/// copies.
pub fn assemble(
    root: &Path,
    toolchain: WasmToolchain,
    profile: Profile,
) -> anyhow::Result<PathBuf> {
    let wasm = toolchain
        .artifact_dir(&target_dir(root), profile.dir_name())
        .join(format!("{APP_PACKAGE}.wasm"));
    let dist = dist_dir(root);
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
        // The functions' names (1.6 MB) serve a profiler, not a student.
        .remove_name_section(profile == Profile::Release)
        .generate(&dist)
        .with_context(|| format!("wasm-bindgen could not process {}", wasm.display()))?;

    copy_file(&root.join("index.html"), &dist.join("index.html"))?;
    copy_dir(&root.join("web/static"), &dist)?;
    let examples = dist.join("examples");
    std::fs::create_dir_all(&examples)?;
    copy_dir(&root.join("web/examples"), &examples)?;
    let build = stamp_build(&dist)?;
    eprintln!("==> build {build} stamped into the file names, index.html and sw.js");

    let size = std::fs::metadata(dist.join(format!("{OUT_NAME}_bg.{build}.wasm")))
        .map(|m| m.len())
        .unwrap_or(0);
    let gzipped = precompress(&dist)?;
    eprintln!(
        "==> dist/ is ready ({:.1} MB of wasm; {:.1} MB to download, gzipped)",
        size as f64 / 1_000_000.0,
        gzipped as f64 / 1_000_000.0
    );
    Ok(dist)
}

/// Files worth compressing for the wire.
fn compressible(path: &Path) -> bool {
    matches!(
        path.extension().and_then(|e| e.to_str()),
        Some("wasm" | "js" | "html" | "css" | "svg" | "json" | "webmanifest")
    )
}

/// Writes `NAME.gz` beside every compressible file of `dist` (level 9), for
/// servers to send with `Content-Encoding: gzip`; returns the bytes a
/// browser downloads, with every file that has one counted gzipped.
fn precompress(dist: &Path) -> anyhow::Result<u64> {
    use std::io::Write as _;
    let mut files = Vec::new();
    list_files(dist, &mut files)?;
    let mut total = 0;
    for file in files {
        let bytes = std::fs::read(&file)?;
        if !compressible(&file) {
            total += bytes.len() as u64;
            continue;
        }
        let mut encoder = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::best());
        encoder.write_all(&bytes)?;
        let gzipped = encoder.finish()?;
        total += gzipped.len() as u64;
        let mut name = file.clone().into_os_string();
        name.push(".gz");
        std::fs::write(&name, gzipped)
            .with_context(|| format!("cannot write {}", PathBuf::from(&name).display()))?;
    }
    Ok(total)
}

/// Cargo's target dir: `CARGO_TARGET_DIR` when set (as for plain cargo
/// commands), otherwise the workspace's target/.
pub fn target_dir(root: &Path) -> PathBuf {
    std::env::var_os("CARGO_TARGET_DIR")
        .filter(|dir| !dir.is_empty())
        .map_or_else(|| root.join("target"), |dir| root.join(PathBuf::from(dir)))
}

/// The text in index.html and web/static/sw.js that becomes the build's
/// version.
const BUILD_PLACEHOLDER: &str = "__EDGEWISE_BUILD__";

/// Makes a version from every file in `dist` and writes it into the JS and
/// wasm file names (the JS loading the renamed wasm), index.html and sw.js.
/// A new build thus changes the worker, and browsers fetch the new app
/// shell; an unchanged build keeps its version and its visitors' caches. A
/// page can start only its own build's files, whatever order a deploy
/// uploads them in.
fn stamp_build(dist: &Path) -> anyhow::Result<String> {
    let worker = dist.join("sw.js");
    let mut files = Vec::new();
    list_files(dist, &mut files)?;
    files.retain(|f| *f != worker);
    files.sort();
    let mut hash = Fnv1a::default();
    for file in &files {
        let relative = file.strip_prefix(dist).unwrap_or(file);
        hash.write(relative.to_string_lossy().as_bytes());
        hash.write(&[0]);
        hash.write(
            &std::fs::read(file).with_context(|| format!("cannot read {}", file.display()))?,
        );
    }
    let build = format!("{:016x}", hash.0);

    let wasm = format!("{OUT_NAME}_bg.wasm");
    let js = dist.join(format!("{OUT_NAME}.js"));
    replace_once(
        &js,
        &format!("'{wasm}'"),
        &format!("'{OUT_NAME}_bg.{build}.wasm'"),
    )?;
    rename(&js, &dist.join(format!("{OUT_NAME}.{build}.js")))?;
    rename(
        &dist.join(&wasm),
        &dist.join(format!("{OUT_NAME}_bg.{build}.wasm")),
    )?;
    for page in [dist.join("index.html"), worker] {
        replace_once(&page, BUILD_PLACEHOLDER, &build)?;
    }
    Ok(build)
}

/// Replaces the one `from` in `file`'s text; more than one (or none) means
/// the file is not what the build expects.
fn replace_once(file: &Path, from: &str, to: &str) -> anyhow::Result<()> {
    let text =
        std::fs::read_to_string(file).with_context(|| format!("cannot read {}", file.display()))?;
    anyhow::ensure!(
        text.matches(from).count() == 1,
        "{} should name {from} exactly once",
        file.display()
    );
    std::fs::write(file, text.replace(from, to))
        .with_context(|| format!("cannot write {}", file.display()))
}

fn rename(from: &Path, to: &Path) -> anyhow::Result<()> {
    std::fs::rename(from, to)
        .with_context(|| format!("cannot rename {} to {}", from.display(), to.display()))
}

/// 64-bit FNV-1a: stable across Rust versions, unlike std's hasher, so the
/// same files always give the same build version.
struct Fnv1a(u64);

impl Default for Fnv1a {
    fn default() -> Self {
        Self(0xcbf2_9ce4_8422_2325)
    }
}

impl Fnv1a {
    fn write(&mut self, bytes: &[u8]) {
        for &byte in bytes {
            self.0 = (self.0 ^ u64::from(byte)).wrapping_mul(0x0100_0000_01b3);
        }
    }
}

fn list_files(dir: &Path, out: &mut Vec<PathBuf>) -> anyhow::Result<()> {
    for entry in std::fs::read_dir(dir).with_context(|| format!("cannot read {}", dir.display()))? {
        let entry = entry?;
        if entry.file_type()?.is_dir() {
            list_files(&entry.path(), out)?;
        } else {
            out.push(entry.path());
        }
    }
    Ok(())
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_build_version_depends_on_the_files_only_and_names_them() {
        let dist = std::env::temp_dir().join(format!("edgewise-stamp-{}", std::process::id()));
        std::fs::create_dir_all(dist.join("examples")).unwrap();
        let stamp = |wasm: &str| {
            std::fs::write(
                dist.join("sw.js"),
                format!("const BUILD = '{BUILD_PLACEHOLDER}';"),
            )
            .unwrap();
            std::fs::write(
                dist.join("index.html"),
                format!("const BUILD = '{BUILD_PLACEHOLDER}';"),
            )
            .unwrap();
            std::fs::write(
                dist.join("edgewise_app.js"),
                "new URL('edgewise_app_bg.wasm', import.meta.url)",
            )
            .unwrap();
            std::fs::write(dist.join("edgewise_app_bg.wasm"), wasm).unwrap();
            std::fs::write(dist.join("examples/embed.html"), "<p>").unwrap();
            let build = stamp_build(&dist).unwrap();
            for page in ["sw.js", "index.html"] {
                let text = std::fs::read_to_string(dist.join(page)).unwrap();
                assert_eq!(text, format!("const BUILD = '{build}';"));
            }
            let js = std::fs::read_to_string(dist.join(format!("edgewise_app.{build}.js")));
            assert_eq!(
                js.unwrap(),
                format!("new URL('edgewise_app_bg.{build}.wasm', import.meta.url)")
            );
            let wasm_file = dist.join(format!("edgewise_app_bg.{build}.wasm"));
            assert_eq!(std::fs::read_to_string(&wasm_file).unwrap(), wasm);
            std::fs::remove_file(dist.join(format!("edgewise_app.{build}.js"))).unwrap();
            std::fs::remove_file(wasm_file).unwrap();
            build
        };
        let first = stamp("one");
        assert_eq!(first.len(), 16);
        assert_eq!(stamp("one"), first, "the same files, the same version");
        assert_ne!(stamp("two"), first, "a new wasm, a new version");
        std::fs::remove_dir_all(&dist).ok();
    }
}
