//! A small HTTP proxy in front of the test server, for the offline tests: it
//! can cut the network (every connection is closed unanswered, as when the
//! server is unreachable), serve a changed sw.js, as a new build would, and
//! publish the served build under another version, all at once or page
//! first, as an upload that is not atomic does.
//!
//! Each test that needs it starts its own, on its own port, so the service
//! worker it installs belongs to an origin no other test uses.

use std::sync::{Arc, Mutex, PoisonError};

use anyhow::Context as _;
use tokio::{
    io::{AsyncReadExt as _, AsyncWriteExt as _},
    net::{TcpListener, TcpStream},
};

/// The largest request head a browser sends for a static file.
const MAX_HEAD: usize = 64 * 1024;

#[derive(Default)]
struct Settings {
    offline: bool,
    /// Appended to sw.js: a different worker, as after a new build.
    worker_suffix: Option<String>,
    /// The served build published as another one.
    next_build: Option<NextBuild>,
}

/// The served build, renamed: index.html and sw.js name `new` instead of
/// `old`, and `*.<new>.*` files are the `*.<old>.*` ones with their text
/// renamed too, once they have `arrived`; until then they are missing (404),
/// as when the page and worker are uploaded first.
#[derive(Clone)]
struct NextBuild {
    old: String,
    new: String,
    arrived: bool,
}

/// A proxy to the served dist/, listening on 127.0.0.1.
pub struct Proxy {
    url: String,
    settings: Arc<Mutex<Settings>>,
    task: tokio::task::JoinHandle<()>,
}

impl Proxy {
    /// Starts a proxy to `upstream` (the test server's URL, such as
    /// `http://127.0.0.1:8080/`).
    pub async fn start(upstream: &str) -> anyhow::Result<Self> {
        let upstream = url::Url::parse(upstream)
            .with_context(|| format!("EDGEWISE_URL is not a URL: {upstream}"))?;
        let upstream_addr = format!(
            "{}:{}",
            upstream.host_str().context("EDGEWISE_URL has no host")?,
            upstream
                .port_or_known_default()
                .context("EDGEWISE_URL has no port")?
        );
        let listener = TcpListener::bind("127.0.0.1:0").await?;
        let addr = listener.local_addr()?;
        let settings = Arc::new(Mutex::new(Settings::default()));
        let shared = Arc::clone(&settings);
        let task = tokio::spawn(async move {
            while let Ok((client, _)) = listener.accept().await {
                let upstream_addr = upstream_addr.clone();
                let settings = Arc::clone(&shared);
                tokio::spawn(async move {
                    // A browser that hangs up early is not a test failure.
                    forward(client, &upstream_addr, &settings).await.ok();
                });
            }
        });
        Ok(Self {
            url: format!("http://{addr}{}", upstream.path()),
            settings,
            task,
        })
    }

    /// The proxy's URL for the app, ending in '/'.
    pub fn url(&self) -> &str {
        &self.url
    }

    /// Cuts (`true`) or restores (`false`) the network to the server.
    pub fn set_offline(&self, offline: bool) {
        self.settings().offline = offline;
    }

    /// Serves sw.js with `suffix` appended from now on: the browser sees a
    /// new worker on its next update check.
    pub fn change_worker(&self, suffix: &str) {
        self.settings().worker_suffix = Some(suffix.to_owned());
    }

    /// Publishes the served build `old` as build `new` (a 16-digit version,
    /// as the xtask makes). With `files_arrived` false only index.html and
    /// sw.js are new, and the new JS and wasm are missing.
    pub fn publish_as(&self, old: &str, new: &str, files_arrived: bool) {
        self.settings().next_build = Some(NextBuild {
            old: old.to_owned(),
            new: new.to_owned(),
            arrived: files_arrived,
        });
    }

    fn settings(&self) -> std::sync::MutexGuard<'_, Settings> {
        self.settings.lock().unwrap_or_else(PoisonError::into_inner)
    }
}

impl Drop for Proxy {
    fn drop(&mut self) {
        self.task.abort();
    }
}

/// Answers one request on `client` from the upstream server, one request per
/// connection (`Connection: close`), which keeps the proxy simple.
async fn forward(
    mut client: TcpStream,
    upstream_addr: &str,
    settings: &Mutex<Settings>,
) -> anyhow::Result<()> {
    let head = read_head(&mut client).await?;
    let (offline, suffix, next_build) = {
        let s = settings.lock().unwrap_or_else(PoisonError::into_inner);
        (s.offline, s.worker_suffix.clone(), s.next_build.clone())
    };
    if offline {
        // Dropping the connection unanswered is what a dead network looks like.
        return Ok(());
    }
    let mut head = String::from_utf8_lossy(&head).into_owned();
    let path = head.split_whitespace().nth(1).unwrap_or("/").to_owned();
    let file = path.split(['?', '#']).next().unwrap_or_default().to_owned();
    let renamed = next_build
        .as_ref()
        .filter(|next| file.contains(&format!(".{}.", next.new)));
    if let Some(next) = renamed {
        if !next.arrived {
            client
                .write_all(
                    b"HTTP/1.1 404 Not Found\r\nContent-Length: 0\r\nConnection: close\r\n\r\n",
                )
                .await?;
            client.shutdown().await?;
            return Ok(());
        }
        head = head.replacen(&next.new, &next.old, 1);
    }
    let mut request = String::new();
    for (i, line) in head.split("\r\n").enumerate() {
        let name = line
            .split(':')
            .next()
            .unwrap_or_default()
            .to_ascii_lowercase();
        // Bodies are asked for uncompressed, so that sw.js can be changed,
        // and always whole: a server's 304 would hide the change.
        let dropped = matches!(
            name.as_str(),
            "connection" | "keep-alive" | "accept-encoding" | "if-modified-since" | "if-none-match"
        );
        if line.is_empty() || (i > 0 && dropped) {
            continue;
        }
        request.push_str(line);
        request.push_str("\r\n");
    }
    request.push_str("Connection: close\r\n\r\n");

    let mut server = TcpStream::connect(upstream_addr).await?;
    server.write_all(request.as_bytes()).await?;
    let mut response = Vec::new();
    server.read_to_end(&mut response).await?;

    let is_worker = file.ends_with("/sw.js");
    if let (true, Some(suffix)) = (is_worker, suffix) {
        response = rewrite_body(&response, |body| [body, suffix.as_bytes()].concat())?;
    }
    let was_renamed = renamed.is_some();
    let names_build = is_worker
        || file.ends_with('/')
        || file.ends_with(".html")
        || (was_renamed && file.ends_with(".js"));
    if let (true, Some(next)) = (names_build, &next_build) {
        response = rewrite_body(&response, |body| {
            String::from_utf8_lossy(body)
                .replace(&next.old, &next.new)
                .into_bytes()
        })?;
    }
    client.write_all(&response).await?;
    client.shutdown().await?;
    Ok(())
}

async fn read_head(client: &mut TcpStream) -> anyhow::Result<Vec<u8>> {
    let mut head = Vec::new();
    let mut buf = [0; 4096];
    while !head.windows(4).any(|w| w == b"\r\n\r\n") {
        let n = client.read(&mut buf).await?;
        anyhow::ensure!(n > 0, "the browser closed the connection");
        head.extend_from_slice(&buf[..n]);
        anyhow::ensure!(head.len() <= MAX_HEAD, "request head too large");
    }
    Ok(head)
}

/// Rewrites an HTTP response's body with `change` and fixes its
/// Content-Length.
fn rewrite_body(response: &[u8], change: impl FnOnce(&[u8]) -> Vec<u8>) -> anyhow::Result<Vec<u8>> {
    let split = response
        .windows(4)
        .position(|w| w == b"\r\n\r\n")
        .context("the server's response has no header end")?;
    let head = String::from_utf8_lossy(&response[..split]);
    let body = &response[split + 4..];
    let mut out = String::new();
    for line in head.split("\r\n") {
        if !line.to_ascii_lowercase().starts_with("content-length:") {
            out.push_str(line);
            out.push_str("\r\n");
        }
    }
    let body = change(body);
    out.push_str(&format!("Content-Length: {}\r\n\r\n", body.len()));
    let mut bytes = out.into_bytes();
    bytes.extend_from_slice(&body);
    Ok(bytes)
}
