//! One chromedriver and the headless Chromium it drives, as a process group
//! that ends, and whose profile folder is removed, with its [`Chromium`] or
//! with the test process.

use std::{
    path::{Path, PathBuf},
    process::Stdio,
    time::{Duration, Instant},
};

use anyhow::{Context as _, bail};
use fantoccini::{Client, ClientBuilder, wd::TimeoutConfiguration};
use hyper_util::client::legacy::connect::HttpConnector;
use serde_json::{Value, json};

use crate::{LaunchOptions, Renderer, env};

/// A running chromedriver, its Chromium and the session between them.
pub(crate) struct Chromium {
    pub(crate) client: Client,
    /// The session's timeouts as it started, which a lent session goes back
    /// to (`shared.rs`).
    pub(crate) timeouts: TimeoutConfiguration,
    /// chromedriver, the leader of the group that the Chromium it starts
    /// joins.
    driver: tokio::process::Child,
    /// The input of the [`REAPER`], whose closing ends the group and removes
    /// the profile: when this drops, and when the test process ends in any
    /// way, even killed. The shared session is never dropped, and its
    /// profile (about 100 MB) was left behind by every run of the suite.
    _lifeline: tokio::process::ChildStdin,
}

/// Waits for its input to close, then kills the group `$0` and removes the
/// profile folder `$1` once the group has gone (or after 5 s): a folder
/// removed while Chromium still wrote to it could come back in part. It
/// has a group of its own, so that a Ctrl-C at the terminal, which reaches
/// the tests' group, does not end it before it has cleaned up.
const REAPER: &str = r#"read -r line
kill -s KILL -- "-$0" 2>/dev/null
tries=0
while kill -0 -- "-$0" 2>/dev/null && [ "$tries" -lt 50 ]; do
  sleep 0.1
  tries=$((tries + 1))
done
rm -rf -- "$1""#;

impl Chromium {
    /// Starts chromedriver and a Chromium with `options` (the base URL
    /// aside), and opens a session. Its connection to chromedriver runs on
    /// the runtime this is called on.
    pub(crate) async fn start(options: &LaunchOptions) -> anyhow::Result<Self> {
        let chromium = env("EDGEWISE_CHROMIUM")?;
        let chromedriver = env("EDGEWISE_CHROMEDRIVER")?;

        let port = free_port()?;
        let profile = profile_dir()?;
        // Chromium joins chromedriver's group, so that ending the group
        // ends both.
        let mut driver = tokio::process::Command::new(&chromedriver);
        driver
            .arg(format!("--port={port}"))
            .stdin(Stdio::null())
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .process_group(0);
        if options.renderer == Renderer::Lavapipe {
            // The Vulkan loader offers lavapipe alone, even where a GPU's
            // driver is installed, so that every machine draws alike.
            driver.env("VK_LOADER_DRIVERS_SELECT", "*lvp*");
        }
        let driver = match driver.spawn() {
            Ok(driver) => driver,
            Err(err) => {
                std::fs::remove_dir_all(&profile).ok();
                return Err(err).with_context(|| format!("cannot start {chromedriver}"));
            }
        };
        let lifeline = match start_reaper(&driver, &profile) {
            Ok(lifeline) => lifeline,
            Err(err) => {
                kill_group(&driver);
                std::fs::remove_dir_all(&profile).ok();
                return Err(err);
            }
        };

        let (width, height) = options.window_size;
        let mut args = vec![
            "--headless".to_owned(),
            "--no-sandbox".to_owned(),
            "--disable-dev-shm-usage".to_owned(),
            "--disable-background-networking".to_owned(),
            "--disable-component-update".to_owned(),
            "--disable-sync".to_owned(),
            "--disable-quic".to_owned(),
            "--no-first-run".to_owned(),
            "--hide-scrollbars".to_owned(),
            format!("--window-size={width},{height}"),
            format!("--user-data-dir={}", profile.display()),
        ];
        if options.cpu_compositing {
            args.push("--disable-gpu".to_owned());
        }
        if let Some(ratio) = options.device_scale_factor {
            args.push(format!("--force-device-scale-factor={ratio}"));
        }
        args.extend(
            renderer_args(options.renderer)
                .iter()
                .map(|&arg| arg.to_owned()),
        );
        let mut caps = serde_json::Map::new();
        caps.insert(
            "goog:chromeOptions".to_owned(),
            json!({ "binary": chromium, "args": args }),
        );
        caps.insert("goog:loggingPrefs".to_owned(), json!({ "browser": "ALL" }));

        let webdriver = format!("http://127.0.0.1:{port}");
        // On an error from here, `lifeline` drops: the group ends and the
        // profile goes.
        let client = connect(&webdriver, caps).await?;
        let timeouts = client
            .get_timeouts()
            .await
            .context("cannot read the session's timeouts")?;
        Ok(Self {
            client,
            timeouts,
            driver,
            _lifeline: lifeline,
        })
    }
}

/// Chromium's flags for `renderer`.
fn renderer_args(renderer: Renderer) -> &'static [&'static str] {
    match renderer {
        // Chromium's list of driver bugs turns ES3, and so WebGL2, off on
        // llvmpipe; lavapipe is no GPU to protect from them.
        Renderer::Lavapipe => &[
            "--use-angle=vulkan",
            "--ignore-gpu-blocklist",
            "--disable-gpu-driver-bug-workarounds",
        ],
        Renderer::SwiftShader => &["--use-angle=swiftshader", "--enable-unsafe-swiftshader"],
        Renderer::None => &["--disable-3d-apis", "--disable-webgl"],
    }
}

/// A test that fails drops its browser without closing it, and the
/// Chromium would go on drawing the app (a software-rendered frame loop per
/// failed test, slowing every test after it): the whole group goes at once,
/// rather than once the reaper reads its closed input.
impl Drop for Chromium {
    fn drop(&mut self) {
        kill_group(&self.driver);
    }
}

/// Kills chromedriver and the Chromium it started.
fn kill_group(driver: &tokio::process::Child) {
    if let Some(group) = driver.id() {
        std::process::Command::new("kill")
            .args(["-s", "KILL", "--", &format!("-{group}")])
            .stderr(Stdio::null())
            .status()
            .ok();
    }
}

/// Starts the [`REAPER`] of `driver`'s group and folder `profile`, and
/// returns its input.
fn start_reaper(
    driver: &tokio::process::Child,
    profile: &Path,
) -> anyhow::Result<tokio::process::ChildStdin> {
    let group = driver.id().context("chromedriver has already ended")?;
    let mut reaper = tokio::process::Command::new("sh")
        .arg("-c")
        .arg(REAPER)
        .arg(group.to_string())
        .arg(profile)
        .stdin(Stdio::piped())
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .process_group(0)
        .spawn()
        .context("cannot start the shell that ends Chromium")?;
    reaper
        .stdin
        .take()
        .context("the shell that ends Chromium has no input")
}

async fn connect(webdriver: &str, caps: serde_json::Map<String, Value>) -> anyhow::Result<Client> {
    // chromedriver needs a moment to start listening.
    let start = Instant::now();
    loop {
        match ClientBuilder::new(HttpConnector::new())
            .capabilities(caps.clone())
            .connect(webdriver)
            .await
        {
            Ok(client) => return Ok(client),
            Err(err) if start.elapsed() > Duration::from_secs(20) => {
                bail!("cannot start a Chromium session through chromedriver: {err}")
            }
            Err(_) => tokio::time::sleep(Duration::from_millis(200)).await,
        }
    }
}

fn free_port() -> anyhow::Result<u16> {
    Ok(std::net::TcpListener::bind("127.0.0.1:0")?
        .local_addr()?
        .port())
}

/// A new, empty profile folder for one Chromium.
fn profile_dir() -> anyhow::Result<PathBuf> {
    let nanos = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map(|d| d.as_nanos())
        .unwrap_or_default();
    let dir =
        std::env::temp_dir().join(format!("edgewise-chromium-{}-{nanos}", std::process::id()));
    std::fs::create_dir_all(&dir)
        .with_context(|| format!("cannot make Chromium's profile folder {}", dir.display()))?;
    Ok(dir)
}
