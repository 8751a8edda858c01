//! Running commands and installing Debian packages.

use std::{
    path::{Path, PathBuf},
    process::{Command, Stdio},
    time::{Duration, Instant},
};

use anyhow::{Context as _, bail};

/// Cargo as invoked by `cargo xtask`, so the same toolchain builds everything.
pub fn cargo() -> Command {
    Command::new(std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into()))
}

/// Cargo.toml's profile for xtask itself (.cargo/config.toml's alias), the
/// native tests, and the `edgewise` that `cargo xtask package` and `hosts`
/// run: dev, with its dependencies unoptimised, which halves a cold build,
/// and one set of them for all.
pub const CHECKS_PROFILE: &str = "checks";

/// Joins the arguments cargo-clippy hands clippy-driver.
const CLIPPY_ARGS: &str = "-D__CLIPPY_HACKERY__warnings__CLIPPY_HACKERY__";

/// Has clippy-driver compile the workspace's own crates in `cmd`'s build, as
/// `cargo clippy` would lint them, with every warning an error: one build
/// both lints and makes the artifacts, where `cargo clippy` and then a build
/// would compile every dependency twice. Cargo puts the wrapper in those
/// crates' metadata hash, so linted and unlinted artifacts sit side by side,
/// each compiled once.
pub fn lint_with_clippy(cmd: &mut Command) -> &mut Command {
    cmd.env("RUSTC_WORKSPACE_WRAPPER", clippy_driver())
        .env("CLIPPY_ARGS", CLIPPY_ARGS)
}

/// The toolchain's clippy-driver, found once rather than through the rustup
/// proxy at every compiler call.
fn clippy_driver() -> std::ffi::OsString {
    output_of(Command::new("rustup").args(["which", "clippy-driver"]))
        .map_or_else(|| "clippy-driver".into(), |path| path.trim().into())
}

/// Where the xtask's commands find `edgewise`.
pub enum Edgewise {
    /// Built from this workspace as needed, by `cargo run`.
    CargoRun,
    /// A binary already built: the one `cargo xtask test`'s workspace build
    /// made. `cargo run` of the CLI alone selects other features, so it
    /// compiled core, model and the CLI again (about 19 s) and linked
    /// target/checks/edgewise anew while the CLI's tests were running it.
    Built(PathBuf),
}

impl Edgewise {
    /// `edgewise package`; the caller adds its arguments.
    pub fn package(&self) -> Command {
        let mut cmd = match self {
            Self::CargoRun => {
                let mut cmd = cargo();
                cmd.args([
                    "run",
                    "--quiet",
                    "--locked",
                    "--profile",
                    CHECKS_PROFILE,
                    "--package",
                    "edgewise-cli",
                    "--",
                ]);
                cmd
            }
            Self::Built(path) => Command::new(path),
        };
        cmd.arg("package");
        cmd
    }
}

/// Runs `cmd`, streaming its output, and fails with `what` if it fails.
pub fn run(what: &str, cmd: &mut Command) -> anyhow::Result<()> {
    let status = cmd
        .status()
        .with_context(|| format!("{what}: could not start {:?}", cmd.get_program()))?;
    if !status.success() {
        bail!("{what} failed ({status})");
    }
    Ok(())
}

/// Runs `cmd` quietly with a time limit; true if it finished successfully in time.
pub fn succeeds_within(cmd: &mut Command, limit: Duration) -> bool {
    let Ok(mut child) = cmd.stdout(Stdio::null()).stderr(Stdio::null()).spawn() else {
        return false;
    };
    let start = Instant::now();
    loop {
        match child.try_wait() {
            Ok(Some(status)) => return status.success(),
            Ok(None) if start.elapsed() < limit => std::thread::sleep(Duration::from_millis(200)),
            _ => {
                child.kill().ok();
                child.wait().ok();
                return false;
            }
        }
    }
}

/// The standard output of `cmd`, or None if it cannot run or fails.
pub fn output_of(cmd: &mut Command) -> Option<String> {
    let out = cmd.stderr(Stdio::null()).output().ok()?;
    out.status
        .success()
        .then(|| String::from_utf8_lossy(&out.stdout).into_owned())
}

fn is_root() -> bool {
    output_of(Command::new("id").arg("-u")).is_some_and(|uid| uid.trim() == "0")
}

/// Makes sure each `(file, package)` file exists, installing the missing
/// packages with apt-get when we are root. Otherwise explains what to install.
pub fn ensure_debian_packages(purpose: &str, needs: &[(&str, &str)]) -> anyhow::Result<()> {
    let missing: Vec<&str> = needs
        .iter()
        .filter(|(file, _)| !Path::new(file).exists())
        .map(|(_, package)| *package)
        .collect();
    if missing.is_empty() {
        return Ok(());
    }
    let list = missing.join(" ");
    if !is_root() {
        bail!(
            "{purpose} needs Debian packages that are not installed: {list}\n\
             Install them with: sudo apt-get update && sudo apt-get install -y {list}"
        );
    }
    eprintln!("==> installing {list} for {purpose}");
    run(
        "apt-get update",
        Command::new("apt-get")
            .arg("update")
            .env("DEBIAN_FRONTEND", "noninteractive"),
    )?;
    run(
        "apt-get install",
        Command::new("apt-get")
            .args(["install", "-y", "--no-install-recommends"])
            .args(&missing)
            .env("DEBIAN_FRONTEND", "noninteractive"),
    )?;
    if let Some((file, package)) = needs.iter().find(|(file, _)| !Path::new(file).exists()) {
        bail!("{package} was installed but {file} is still missing");
    }
    Ok(())
}
