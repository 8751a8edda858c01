//! The native test executables, run beside the wasm32 steps and the browser
//! tests at the lowest priority, so that they take the CPU those steps leave
//! idle instead of a step of their own.
//!
//! Measured with `vmstat` on the 2-core machine: the wasm build keeps one core
//! idle for about 200 s (its fat-LTO link, and then wasm-opt, ran on one core),
//! and the browser suite leaves 16% of both cores idle (pages waiting on
//! timers and the test's polls).
//!
//! At the same priority the tests slowed those steps about as much as they
//! gained (docs/performance.md), and at nice 19 the browser suite still ran
//! a quarter slower (953 s against 727 s): Chromium's processes hand each
//! frame on to one another, and each hand-over waited for the test's time
//! slice to end. So the tests run under `SCHED_IDLE`, which a waking
//! process of any other policy preempts at once. They stay in the session
//! of `cargo xtask test`, where Chromium and the builds run too: the kernel
//! shares the CPU between sessions (autogroups) first, so a session of
//! their own would give them half the machine whatever their policy.

use std::{
    fs::File,
    io::Write as _,
    path::{Path, PathBuf},
    process::{Child, Command, Stdio},
    sync::{
        Arc, Mutex, MutexGuard,
        atomic::{AtomicBool, Ordering},
    },
    thread::JoinHandle,
    time::{Duration, Instant},
};

use anyhow::{Context as _, bail};

/// One test executable and the package directory cargo would run it in.
pub struct TestExecutable {
    path: PathBuf,
    package_dir: PathBuf,
}

/// What a `cargo test --no-run` selection built.
pub struct Built {
    /// Its test executables, in cargo's order.
    pub tests: Vec<TestExecutable>,
    /// The `edgewise` binary, built for the CLI's tests.
    pub edgewise: Option<PathBuf>,
}

/// Lists what `build` (a `cargo test --no-run` selection whose artifacts are
/// built) made.
pub fn list(build: &mut Command) -> anyhow::Result<Built> {
    let output = build
        .args(["--no-run", "--message-format=json"])
        .stderr(Stdio::inherit())
        .output()
        .context("could not run cargo to list the test executables")?;
    if !output.status.success() {
        bail!("listing the test executables failed ({})", output.status);
    }
    let mut built = Built {
        tests: Vec::new(),
        edgewise: None,
    };
    for line in String::from_utf8_lossy(&output.stdout).lines() {
        let Ok(message) = serde_json::from_str::<serde_json::Value>(line) else {
            continue;
        };
        let (Some(path), Some(manifest)) = (
            message["executable"].as_str(),
            message["manifest_path"].as_str(),
        ) else {
            continue;
        };
        if message["reason"] != "compiler-artifact" {
            continue;
        }
        if message["profile"]["test"].as_bool() == Some(true) {
            built.tests.push(TestExecutable {
                path: path.into(),
                package_dir: Path::new(manifest)
                    .parent()
                    .map_or_else(PathBuf::new, Path::to_path_buf),
            });
        } else if message["target"]["name"] == "edgewise" {
            built.edgewise = Some(path.into());
        }
    }
    if built.tests.is_empty() {
        bail!("cargo listed no test executables");
    }
    Ok(built)
}

/// The executables running one after another on a thread, as `cargo test`
/// runs them; dropping this stops them.
pub struct NativeTests {
    /// Returns how long the executables ran, from the first's start to the
    /// last's end.
    thread: Option<JoinHandle<anyhow::Result<Duration>>>,
    /// What the thread returned, once joined.
    ran: Option<Duration>,
    running: Arc<Mutex<Option<Child>>>,
    stop: Arc<AtomicBool>,
    log: PathBuf,
}

impl NativeTests {
    /// Starts `executables` with `envs`, their output going to `log`.
    pub fn start(
        executables: Vec<TestExecutable>,
        envs: Vec<(String, String)>,
        log: &Path,
    ) -> anyhow::Result<Self> {
        let file = File::create(log).with_context(|| format!("cannot create {}", log.display()))?;
        let running = Arc::new(Mutex::new(None));
        let stop = Arc::new(AtomicBool::new(false));
        let thread = std::thread::spawn({
            let (running, stop) = (Arc::clone(&running), Arc::clone(&stop));
            move || {
                let started = Instant::now();
                run_each(&executables, &envs, &file, &running, &stop)?;
                Ok(started.elapsed())
            }
        });
        Ok(Self {
            thread: Some(thread),
            ran: None,
            running,
            stop,
            log: log.to_path_buf(),
        })
    }

    /// Fails with the tests' output if they have already failed, so that a
    /// failure stops the run at the next step rather than at the end.
    pub fn check(&mut self) -> anyhow::Result<()> {
        if self.thread.as_ref().is_some_and(JoinHandle::is_finished) {
            let result = self.join();
            if result.is_err() {
                self.print_log();
            }
            result?;
        }
        Ok(())
    }

    /// Waits for the tests and prints their output; returns how long they
    /// ran, from the first's start to the last's end (they may have ended
    /// long before this is called).
    pub fn finish(mut self) -> anyhow::Result<Duration> {
        let result = self.join();
        self.print_log();
        result?;
        self.ran.context("the native tests did not run")
    }

    fn join(&mut self) -> anyhow::Result<()> {
        match self.thread.take().map(JoinHandle::join) {
            Some(Ok(result)) => {
                self.ran = Some(result?);
                Ok(())
            }
            Some(Err(_)) => bail!("the native tests' thread panicked"),
            None => Ok(()),
        }
    }

    fn print_log(&self) {
        match std::fs::read_to_string(&self.log) {
            Ok(text) => eprint!("{text}"),
            Err(error) => eprintln!("cannot read {}: {error}", self.log.display()),
        }
    }
}

impl Drop for NativeTests {
    fn drop(&mut self) {
        self.stop.store(true, Ordering::Relaxed);
        if let Ok(mut running) = self.running.lock()
            && let Some(child) = running.as_mut()
        {
            child.kill().ok();
        }
        self.join().ok();
    }
}

fn lock(running: &Mutex<Option<Child>>) -> anyhow::Result<MutexGuard<'_, Option<Child>>> {
    running
        .lock()
        .map_err(|_| anyhow::anyhow!("the native tests' lock is poisoned"))
}

fn run_each(
    executables: &[TestExecutable],
    envs: &[(String, String)],
    log: &File,
    running: &Mutex<Option<Child>>,
    stop: &AtomicBool,
) -> anyhow::Result<()> {
    for executable in executables {
        if stop.load(Ordering::Relaxed) {
            bail!("the native tests were stopped");
        }
        let name = executable.path.display();
        writeln!(&*log, "     Running {name}")?;
        let child = Command::new("chrt")
            .args(["--idle", "0"])
            .arg(&executable.path)
            .current_dir(&executable.package_dir)
            .envs(envs.iter().map(|(name, value)| (name, value)))
            .stdin(Stdio::null())
            .stdout(log.try_clone()?)
            .stderr(log.try_clone()?)
            .spawn()
            .with_context(|| format!("could not start {name}"))?;
        *lock(running)? = Some(child);
        let status = loop {
            let mut guard = lock(running)?;
            let Some(child) = guard.as_mut() else {
                bail!("{name} was not running");
            };
            if let Some(status) = child.try_wait()? {
                guard.take();
                break status;
            }
            drop(guard);
            std::thread::sleep(Duration::from_millis(100));
        };
        if !status.success() {
            // Said at once, in the middle of another step's output: the run
            // stops at the next step, which may be a quarter of an hour away.
            eprintln!(
                "\n==> native tests failed: {name} ({status}); the run stops after this step"
            );
            bail!("native tests failed: {name} ({status})");
        }
    }
    Ok(())
}
