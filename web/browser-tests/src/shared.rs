//! The one Chromium that [`Browser::launch_with`](crate::Browser::launch_with)
//! lends to the tests in turn. Starting a Chromium and loading its first
//! page cost about 1.4 s more than a fresh tab in a running one (its GPU
//! process and the renderer's compiled shaders are warm), and most tests
//! differ from the default options in the window's size or the app's URL
//! at most (docs/performance.md).
//!
//! Each test gets the session as a new test would find a new browser: a
//! fresh tab (new session storage, no `DevTools` overrides: blocked URLs,
//! device emulation, touch) in a window of the default size, with the
//! app's, the host pages' and the last test's own origin's (a proxy's)
//! storage and service workers cleared, the timeouts as they started and
//! the console log read out. The HTTP cache stays: the pages are the same
//! build throughout.

use std::{
    sync::{Mutex, OnceLock, PoisonError},
    time::Duration,
};

use anyhow::Context as _;
use fantoccini::Client;
use serde_json::json;

use crate::{BrowserLog, Cdp, LaunchOptions, chromium::Chromium, env};

enum Slot {
    Unstarted,
    /// Handed back, and being reset by a task on [`runtime`]: the last
    /// test's page (a large mesh, a runaway run) closes at once, rather than
    /// staying open beside the tests that launch their own browser until a
    /// test asks for this one.
    Resetting(tokio::task::JoinHandle<(Chromium, anyhow::Result<()>)>),
    /// A test holds it; another that asks meanwhile (plain `cargo test`
    /// runs tests side by side) starts its own.
    Lent,
}

static SLOT: Mutex<Slot> = Mutex::new(Slot::Unstarted);

/// A reset takes well under a second; one that takes this long is stuck
/// on what the last test left, and a new browser is quicker.
const RESET_LIMIT: Duration = Duration::from_secs(30);

/// The shared Chromium, reset for a new test, or `None` while another test
/// holds it.
pub(crate) async fn lend() -> anyhow::Result<Option<Chromium>> {
    let resetting = match std::mem::replace(&mut *slot(), Slot::Lent) {
        Slot::Lent => return Ok(None),
        Slot::Resetting(reset) => Some(reset),
        Slot::Unstarted => None,
    };
    if let Some(mut reset) = resetting {
        // A test that failed can leave the browser unusable or stuck;
        // dropping it, or aborting its reset, ends its processes.
        match tokio::time::timeout(RESET_LIMIT, &mut reset).await {
            Ok(Ok((chromium, Ok(())))) => return Ok(Some(chromium)),
            Ok(Ok((_, Err(err)))) => {
                eprintln!("the shared Chromium could not be reset ({err:#}); starting another");
            }
            Ok(Err(err)) => {
                eprintln!("the shared Chromium's reset panicked ({err}); starting another");
            }
            Err(_) => {
                reset.abort();
                eprintln!(
                    "the shared Chromium's reset took over {} s; starting another",
                    RESET_LIMIT.as_secs()
                );
            }
        }
    }
    let started = runtime()
        .spawn(async { Chromium::start(&LaunchOptions::default()).await })
        .await
        .context("the shared Chromium's start panicked")
        .and_then(|started| started);
    if started.is_err() {
        *slot() = Slot::Unstarted;
    }
    started.map(Some)
}

/// Hands the session back once a test is done with it, passed or failed,
/// and starts its reset; `base_url` is the app's URL the test used.
pub(crate) fn give_back(chromium: Chromium, base_url: &str) {
    let base_url = base_url.to_owned();
    let reset = runtime().spawn(async move {
        let reset = fresh_tab(&chromium, &base_url).await;
        (chromium, reset)
    });
    *slot() = Slot::Resetting(reset);
}

fn slot() -> std::sync::MutexGuard<'static, Slot> {
    SLOT.lock().unwrap_or_else(PoisonError::into_inner)
}

/// The runtime the session's connection and its resets run on: each test
/// has a runtime, which ends with it, and the session must outlive them all.
fn runtime() -> &'static tokio::runtime::Runtime {
    static RUNTIME: OnceLock<tokio::runtime::Runtime> = OnceLock::new();
    RUNTIME.get_or_init(|| {
        tokio::runtime::Builder::new_multi_thread()
            .worker_threads(1)
            .thread_name("shared-chromium")
            .enable_all()
            .build()
            .expect("a thread for the shared Chromium's connection")
    })
}

/// Opens a new tab and closes every other, then puts back the window's
/// size and clears what the last test left in the profile (see the module
/// notes).
async fn fresh_tab(chromium: &Chromium, base_url: &str) -> anyhow::Result<()> {
    let client = &chromium.client;
    let old = client.windows().await?;
    // The last test may have left its commands on a tab it closed.
    let first = old.first().context("the session has no window")?;
    client.switch_to_window(first.clone()).await?;
    let tab = client.new_window(true).await?.handle;
    for window in old {
        client.switch_to_window(window).await?;
        client.close_window().await?;
    }
    client.switch_to_window(tab).await?;
    client.update_timeouts(chromium.timeouts.clone()).await?;
    let (width, height) = LaunchOptions::default().window_size;
    client.set_window_size(width, height).await?;
    clear_site_data(client, &[base_url]).await?;
    client.issue_cmd(BrowserLog).await?;
    Ok(())
}

/// Clears the storage and service workers of the app, the host pages and
/// the `others` URLs' origins, as a first visit finds them, from whatever
/// page `client` is on.
pub(crate) async fn clear_site_data(client: &Client, others: &[&str]) -> anyhow::Result<()> {
    let served = ["EDGEWISE_URL", "EDGEWISE_HOSTS_URL"]
        .into_iter()
        .filter_map(|variable| env(variable).ok());
    let mut urls: Vec<String> = served
        .chain(others.iter().map(|&url| url.to_owned()))
        .collect();
    urls.sort();
    urls.dedup();
    for url in urls {
        client
            .issue_cmd(Cdp {
                command: "Storage.clearDataForOrigin".to_owned(),
                params: json!({
                    "origin": url.trim_end_matches('/'),
                    "storageTypes": "cookies,local_storage,indexeddb,service_workers,cache_storage,file_systems",
                }),
            })
            .await
            .with_context(|| format!("cannot clear the storage of {url}"))?;
    }
    Ok(())
}
