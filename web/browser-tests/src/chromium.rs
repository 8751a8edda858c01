//! One chromedriver and the headless Chromium it drives, as a process group
//! that ends with its [`Chromium`] or with the test process.

use std::{
    path::PathBuf,
    process::Stdio,
    time::{Duration, Instant},
};

use anyhow::{Context as _, bail};
use fantoccini::{Client, ClientBuilder, wd::TimeoutConfiguration};
use hyper_util::client::legacy::connect::HttpConnector;
use serde_json::{Value, json};

use crate::{LaunchOptions, env};

/// A running chromedriver, its Chromium and the session between them.
pub(crate) struct Chromium {
    pub(crate) client: Client,
    /// The session's timeouts as it started, which a lent session goes back
    /// to (`shared.rs`).
    pub(crate) timeouts: TimeoutConfiguration,
    /// `sh`, the leader of the group that chromedriver and the Chromium it
    /// starts belong to.
    group: tokio::process::Child,
    /// The group's standard input, whose closing kills the group: when this
    /// drops, and when the test process ends in any way, even killed, so no
    /// Chromium goes on drawing after the tests (the shared session is
    /// never dropped).
    _lifeline: tokio::process::ChildStdin,
    _profile: TempDir,
}

impl Chromium {
    /// Starts chromedriver and a Chromium with `options` (the base URL
    /// aside), and opens a session. Its connection to chromedriver runs on
    /// the runtime this is called on.
    pub(crate) async fn start(options: &LaunchOptions) -> anyhow::Result<Self> {
        let chromium = env("EDGEWISE_CHROMIUM")?;
        let chromedriver = env("EDGEWISE_CHROMEDRIVER")?;

        let port = free_port()?;
        // chromedriver in the background; `sh` waits for its input to
        // close, then kills its own group.
        let mut group = tokio::process::Command::new("sh")
            .args([
                "-c",
                "\"$0\" --port=\"$1\" & read -r line; kill -s KILL 0",
                &chromedriver,
                &port.to_string(),
            ])
            .stdin(Stdio::piped())
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            // Chromium joins chromedriver's group, so that ending the group
            // ends both.
            .process_group(0)
            .spawn()
            .with_context(|| format!("cannot start {chromedriver}"))?;
        let lifeline = group
            .stdin
            .take()
            .context("chromedriver's group has no input")?;
        let profile = TempDir::new("edgewise-chromium")?;

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
            format!("--user-data-dir={}", profile.0.display()),
        ];
        if options.cpu_compositing {
            args.push("--disable-gpu".to_owned());
        }
        if let Some(ratio) = options.device_scale_factor {
            args.push(format!("--force-device-scale-factor={ratio}"));
        }
        if options.without_3d {
            args.push("--disable-3d-apis".to_owned());
            args.push("--disable-webgl".to_owned());
        } else {
            // WebGL2 rendered on the CPU: these machines have no GPU.
            args.push("--use-angle=swiftshader".to_owned());
            args.push("--enable-unsafe-swiftshader".to_owned());
        }
        let mut caps = serde_json::Map::new();
        caps.insert(
            "goog:chromeOptions".to_owned(),
            json!({ "binary": chromium, "args": args }),
        );
        caps.insert("goog:loggingPrefs".to_owned(), json!({ "browser": "ALL" }));

        let webdriver = format!("http://127.0.0.1:{port}");
        // On an error from here, `lifeline` drops and the group ends.
        let client = connect(&webdriver, caps).await?;
        let timeouts = client
            .get_timeouts()
            .await
            .context("cannot read the session's timeouts")?;
        Ok(Self {
            client,
            timeouts,
            group,
            _lifeline: lifeline,
            _profile: profile,
        })
    }
}

/// A test that fails drops its browser without closing it, and the
/// Chromium would go on drawing the app (a software-rendered frame loop per
/// failed test, slowing every test after it): the whole group goes at once.
/// The lifeline alone would end it too, but only once `sh` reads the closed
/// pipe; killing here, before the fields drop, stops Chromium before its
/// profile folder is removed under it.
impl Drop for Chromium {
    fn drop(&mut self) {
        if let Some(group) = self.group.id() {
            std::process::Command::new("kill")
                .args(["-s", "KILL", "--", &format!("-{group}")])
                .stderr(Stdio::null())
                .status()
                .ok();
        }
    }
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

/// A temporary directory removed on drop.
struct TempDir(PathBuf);

impl TempDir {
    fn new(prefix: &str) -> anyhow::Result<Self> {
        let nanos = std::time::SystemTime::now()
            .duration_since(std::time::UNIX_EPOCH)
            .map(|d| d.as_nanos())
            .unwrap_or_default();
        let dir = std::env::temp_dir().join(format!("{prefix}-{}-{nanos}", std::process::id()));
        std::fs::create_dir_all(&dir)?;
        Ok(Self(dir))
    }
}

impl Drop for TempDir {
    fn drop(&mut self) {
        std::fs::remove_dir_all(&self.0).ok();
    }
}
