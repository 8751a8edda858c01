//! Finding a Rust toolchain that can build for wasm32-unknown-unknown.
//!
//! The rustup target is the normal path. Where rustup cannot download it (a
//! machine that reaches only package registries), Debian's `rustc-web` builds
//! the standard library from source (`rust-web-src`) with `-Zbuild-std`, and
//! links with `lld-19`.

use std::{path::PathBuf, process::Command, time::Duration};

use crate::process;

pub const WASM_TARGET: &str = "wasm32-unknown-unknown";

const DEBIAN_RUSTC: &str = "/usr/bin/rustc";
const DEBIAN_CARGO: &str = "/usr/bin/cargo";
const DEBIAN_STD_SRC: &str = "/usr/lib/rustlib/src/rust/library/std/Cargo.toml";
const DEBIAN_WASM_LD: &str = "/usr/lib/llvm-19/bin/wasm-ld";

/// How long `rustup target add` may take before we fall back to Debian's compiler.
const RUSTUP_TIMEOUT: Duration = Duration::from_secs(90);

/// A toolchain that builds for wasm32.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum WasmToolchain {
    /// rustup's toolchain with the wasm32 target installed.
    Rustup,
    /// Debian's rustc-web with the standard library built from source.
    Debian,
}

impl WasmToolchain {
    /// Finds a wasm32 toolchain, installing one if it can.
    ///
    /// `EDGEWISE_WASM_TOOLCHAIN=rustup|debian` forces a choice.
    pub fn find() -> anyhow::Result<Self> {
        match std::env::var("EDGEWISE_WASM_TOOLCHAIN").as_deref() {
            Ok("debian") => return Self::debian(),
            Ok("rustup") => {
                return if rustup_has_target() || rustup_add_target() {
                    Ok(Self::Rustup)
                } else {
                    anyhow::bail!("rustup could not install the {WASM_TARGET} target")
                };
            }
            _ => {}
        }
        if rustup_has_target() {
            return Ok(Self::Rustup);
        }
        if process::output_of(Command::new("rustup").arg("--version")).is_some() {
            eprintln!(
                "==> trying `rustup target add {WASM_TARGET}` (up to {}s)",
                RUSTUP_TIMEOUT.as_secs()
            );
            if rustup_add_target() {
                return Ok(Self::Rustup);
            }
            eprintln!("==> rustup could not add the target; using Debian's rustc-web instead");
        }
        Self::debian()
    }

    fn debian() -> anyhow::Result<Self> {
        process::ensure_debian_packages(
            "building for wasm32 without rustup's target",
            &[
                (DEBIAN_RUSTC, "rustc-web"),
                (DEBIAN_CARGO, "cargo-web"),
                (DEBIAN_STD_SRC, "rust-web-src"),
                (DEBIAN_WASM_LD, "lld-19"),
            ],
        )?;
        Ok(Self::Debian)
    }

    /// A cargo command set up to build for wasm32 with this toolchain.
    ///
    /// `subcommand` is e.g. "build" or "check"; the target, target dir and
    /// build-std flags are already added.
    pub fn cargo(self, subcommand: &str, target_dir: &std::path::Path) -> Command {
        match self {
            Self::Rustup => {
                let mut cmd = process::cargo();
                cmd.arg(subcommand).args(["--target", WASM_TARGET]);
                cmd.arg("--target-dir").arg(target_dir);
                cmd
            }
            Self::Debian => {
                let mut cmd = Command::new(DEBIAN_CARGO);
                // rustup's variables would point Debian's cargo at rustup's compiler.
                for var in [
                    "RUSTUP_TOOLCHAIN",
                    "RUSTUP_HOME",
                    "CARGO",
                    "RUSTC",
                    "RUSTDOC",
                ] {
                    cmd.env_remove(var);
                }
                cmd.env("RUSTC", DEBIAN_RUSTC)
                    .env("RUSTDOC", "/usr/bin/rustdoc")
                    .env("RUSTC_BOOTSTRAP", "1")
                    .env("CARGO_TARGET_WASM32_UNKNOWN_UNKNOWN_LINKER", DEBIAN_WASM_LD);
                cmd.arg(subcommand)
                    .args(["--target", WASM_TARGET, "-Zbuild-std=std,panic_abort"]);
                // A separate target dir keeps rustup's and Debian's artifacts apart.
                cmd.arg("--target-dir")
                    .arg(target_dir.join("debian-rustc-web"));
                cmd
            }
        }
    }

    /// Where `cargo()` puts its artifacts for `target_dir`.
    pub fn artifact_dir(self, target_dir: &std::path::Path, profile: &str) -> PathBuf {
        let base = match self {
            Self::Rustup => target_dir.to_path_buf(),
            Self::Debian => target_dir.join("debian-rustc-web"),
        };
        base.join(WASM_TARGET).join(profile)
    }

    /// Whether clippy can lint wasm32 code with this toolchain. Debian ships no
    /// clippy for rustc-web, so there we fall back to rustc's own lints.
    pub fn has_clippy(self) -> bool {
        self == Self::Rustup
    }
}

fn rustup_has_target() -> bool {
    process::output_of(Command::new("rustup").args(["target", "list", "--installed"]))
        .is_some_and(|targets| targets.lines().any(|t| t.trim() == WASM_TARGET))
}

fn rustup_add_target() -> bool {
    process::succeeds_within(
        Command::new("rustup").args(["target", "add", WASM_TARGET]),
        RUSTUP_TIMEOUT,
    ) && rustup_has_target()
}
