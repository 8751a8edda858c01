//! The service worker (web/static/sw.js): it takes control of the page, the
//! app starts with the server out of reach, and a new build is offered with
//! a Reload banner. Each test reaches the server through its own proxy, so
//! its worker and caches belong to an origin no other test visits.

use std::time::Duration;

use edgewise_browser_tests::{Browser, LaunchOptions, proxy::Proxy};
use serde_json::Value;

const WORKER_TIMEOUT: Duration = Duration::from_secs(60);

async fn launch_through(proxy: &Proxy) -> anyhow::Result<Browser> {
    Browser::launch_with(LaunchOptions {
        base_url: Some(proxy.url().to_owned()),
        ..LaunchOptions::default()
    })
    .await
}

/// A proxy of its own, a browser through it, the app open and its worker
/// active.
async fn start_with_worker() -> anyhow::Result<(Proxy, Browser)> {
    let proxy = Proxy::start(&std::env::var("EDGEWISE_URL")?).await?;
    let browser = launch_through(&proxy).await?;
    browser.open("").await?;
    wait_for_active_worker(&browser).await?;
    Ok((proxy, browser))
}

/// The one build the worker caches.
async fn the_build(browser: &Browser) -> anyhow::Result<String> {
    let builds = cached_builds(browser).await?;
    match builds.as_slice() {
        [build] => Ok(build.clone()),
        _ => anyhow::bail!("one shell cache expected: {builds:?}"),
    }
}

/// The builds the page's worker caches, from its shell caches' names.
async fn cached_builds(browser: &Browser) -> anyhow::Result<Vec<String>> {
    let caches = browser.eval_async("caches.keys()").await?;
    Ok(caches
        .as_array()
        .into_iter()
        .flatten()
        .filter_map(Value::as_str)
        .filter_map(|name| name.strip_prefix("edgewise-shell-"))
        .map(str::to_owned)
        .collect())
}

/// The builds whose JS the page loaded (from the worker or the network).
async fn loaded_builds(browser: &Browser) -> anyhow::Result<Vec<String>> {
    let names = browser
        .eval(
            "return performance.getEntriesByType('resource').map((e) => new URL(e.name).pathname) \
             .filter((p) => /edgewise_app(_bg)?\\.[0-9a-f]{16}\\.(js|wasm)$/.test(p));",
        )
        .await?;
    Ok(names
        .as_array()
        .into_iter()
        .flatten()
        .filter_map(Value::as_str)
        .filter_map(|path| path.split('.').nth(1))
        .map(str::to_owned)
        .collect())
}

/// Asks the worker registration for an update and waits for the new worker
/// to end its install: `installed`, or `redundant` when it failed.
async fn update_outcome(browser: &Browser) -> anyhow::Result<Value> {
    browser
        .eval_async(
            "navigator.serviceWorker.getRegistration().then((r) => new Promise((resolve) => { \
               r.addEventListener('updatefound', () => { const w = r.installing; \
                 w.addEventListener('statechange', () => { \
                   if (w.state === 'installed' || w.state === 'redundant') resolve(w.state); }); }); \
               r.update().catch((e) => resolve('update failed: ' + e)); }))",
        )
        .await
}

/// Clicks the update banner's Reload and waits until the page has loaded
/// again and the app is ready.
async fn reload_from_banner(browser: &Browser) -> anyhow::Result<()> {
    browser
        .eval(
            "window.edgewiseBeforeUpdate = true; \
             document.getElementById('edgewise_update_reload').click(); return null;",
        )
        .await?;
    browser
        .wait_for("window.edgewiseBeforeUpdate !== true", WORKER_TIMEOUT)
        .await?;
    browser.wait_until_ready().await
}

/// Waits until the worker has installed the shell and is active.
async fn wait_for_active_worker(browser: &Browser) -> anyhow::Result<()> {
    let state = browser
        .eval_async("navigator.serviceWorker.ready.then((r) => r.active.state)")
        .await?;
    assert_eq!(state, "activated");
    Ok(())
}

#[tokio::test]
async fn the_worker_controls_the_page_after_a_reload() -> anyhow::Result<()> {
    let (proxy, browser) = start_with_worker().await?;

    browser.open("").await?;
    let worker = browser
        .eval("return navigator.serviceWorker.controller?.scriptURL ?? null;")
        .await?;
    assert_eq!(worker, format!("{}sw.js", proxy.url()));

    // The shell's cache is named after this build, stamped in by the xtask.
    let caches = browser.eval_async("caches.keys()").await?;
    let names: Vec<&str> = caches
        .as_array()
        .into_iter()
        .flatten()
        .filter_map(Value::as_str)
        .collect();
    let shell = names
        .iter()
        .find(|name| name.starts_with("edgewise-shell-"))
        .unwrap_or_else(|| panic!("no shell cache in {names:?}"));
    let build = shell.trim_start_matches("edgewise-shell-");
    assert!(
        build.len() == 16 && build.bytes().all(|b| b.is_ascii_hexdigit()),
        "the build version was not stamped: {shell}"
    );
    let cached = browser
        .eval_async(&format!(
            "caches.open('{shell}').then((c) => c.keys()).then((ks) => ks.map((r) => new URL(r.url).pathname))"
        ))
        .await?;
    // The JS and wasm carry the build in their names too.
    for file in [
        "/",
        "/index.html",
        &format!("/edgewise_app.{build}.js"),
        &format!("/edgewise_app_bg.{build}.wasm"),
        "/favicon.svg",
        "/examples/embed.html",
    ] {
        assert!(
            cached.as_array().into_iter().flatten().any(|p| p == file),
            "{file} is not in the shell cache: {cached}"
        );
    }
    let update_shown = browser
        .eval("return !document.getElementById('edgewise_update').hidden;")
        .await?;
    assert_eq!(
        update_shown, false,
        "the update banner shows on a first visit"
    );

    browser.assert_no_console_errors().await?;
    browser.close().await
}

#[tokio::test]
async fn the_app_starts_with_the_server_out_of_reach() -> anyhow::Result<()> {
    let (proxy, browser) = start_with_worker().await?;

    proxy.set_offline(true);
    let probe = browser
        .eval_async("fetch('not-cached.txt').then(() => 'reached', () => 'cut')")
        .await?;
    assert_eq!(probe, "cut", "the network to the server is still up");
    // The probe's own failure is logged; what follows must log nothing.
    browser.console_errors().await?;

    // A course link's page, which differs from the cached one by its query.
    browser.open("?embed=1&sample=cube").await?;
    browser
        .wait_for(
            "window.edgewise.state().frames >= 2",
            Duration::from_secs(30),
        )
        .await?;
    let error = browser
        .eval_async("window.edgewise.loadSample('tetrahedron')")
        .await?;
    assert_eq!(error, Value::Null);
    let shot = browser.screenshot("offline").await?;
    assert!(!shot.is_blank(), "{} is blank", shot.path.display());
    // The browser's own failed update check of sw.js may be logged; the
    // page itself must log nothing.
    let errors: Vec<String> = browser
        .console_errors()
        .await?
        .into_iter()
        .filter(|e| !e.contains("sw.js"))
        .collect();
    assert!(errors.is_empty(), "console errors offline: {errors:#?}");

    proxy.set_offline(false);
    browser.close().await
}

#[tokio::test]
async fn a_new_build_is_offered_with_a_reload_banner() -> anyhow::Result<()> {
    let (proxy, browser) = start_with_worker().await?;
    browser.open("").await?;

    proxy.change_worker("\n// The next build.\n");
    browser
        .eval_async("navigator.serviceWorker.getRegistration().then((r) => r.update())")
        .await?;
    browser
        .wait_for(
            "!document.getElementById('edgewise_update').hidden",
            WORKER_TIMEOUT,
        )
        .await?;
    let text = browser
        .eval("return document.getElementById('edgewise_update').textContent;")
        .await?;
    assert!(
        text.as_str()
            .unwrap_or_default()
            .contains("A new version of Edgewise is available"),
        "{text}"
    );
    let shot = browser.screenshot("update-banner").await?;
    assert!(!shot.is_blank());

    // Reload: the waiting worker takes over and the page loads again.
    reload_from_banner(&browser).await?;
    let after = browser
        .eval(
            "return { banner: !document.getElementById('edgewise_update').hidden, \
             controlled: navigator.serviceWorker.controller?.state ?? null };",
        )
        .await?;
    assert_eq!(after["banner"], false, "{after}");
    assert_eq!(after["controlled"], "activated", "{after}");
    browser
        .eval_async("navigator.serviceWorker.getRegistration().then((r) => r.waiting === null || Promise.reject('a worker still waits'))")
        .await?;

    browser.assert_no_console_errors().await?;
    browser.close().await
}

/// An upload that puts index.html and sw.js on the server before the JS and
/// wasm: the new worker's install fails and the old build keeps running,
/// whole; once the files arrive the new build is offered, and Reload works in
/// both open tabs (the second one finds the new worker already active).
#[tokio::test]
async fn an_upload_in_any_order_never_mixes_builds() -> anyhow::Result<()> {
    const NEXT: &str = "0123456789abcdef";
    let (proxy, browser) = start_with_worker().await?;
    browser.open("").await?;
    let old = &the_build(&browser).await?;
    assert_eq!(loaded_builds(&browser).await?, [old.clone(), old.clone()]);

    // The page and worker of the next build arrive first.
    proxy.publish_as(old, NEXT, false);
    assert_eq!(update_outcome(&browser).await?, "redundant");
    browser.open("?sample=cube").await?;
    assert_eq!(loaded_builds(&browser).await?, [old.clone(), old.clone()]);
    assert_eq!(cached_builds(&browser).await?, std::slice::from_ref(old));
    let banner = browser
        .eval("return !document.getElementById('edgewise_update').hidden;")
        .await?;
    assert_eq!(banner, false, "a build that is not all there was offered");
    assert_eq!(browser.state().await?["mesh"], "cube.htb");

    // A second tab on the old build; then the JS and wasm arrive.
    let first = browser.tab().await?;
    let second = browser.new_tab().await?;
    browser.open("").await?;
    browser.switch_to(first.clone()).await?;
    proxy.publish_as(old, NEXT, true);
    assert_eq!(update_outcome(&browser).await?, "installed");
    let banner_shown = "!document.getElementById('edgewise_update').hidden";
    browser.wait_for(banner_shown, WORKER_TIMEOUT).await?;
    reload_from_banner(&browser).await?;
    assert_eq!(loaded_builds(&browser).await?, [NEXT, NEXT]);

    // The other tab still offers the update; its Reload loads the new build.
    browser.switch_to(second).await?;
    browser.wait_for(banner_shown, WORKER_TIMEOUT).await?;
    assert_eq!(loaded_builds(&browser).await?, [old.clone(), old.clone()]);
    reload_from_banner(&browser).await?;
    assert_eq!(loaded_builds(&browser).await?, [NEXT, NEXT]);
    assert_eq!(cached_builds(&browser).await?, [NEXT]);
    browser.assert_no_console_errors().await?;
    browser.close().await
}

/// A first visit during such an upload: the page names the missing build
/// and asks to reload in a minute, rather than starting anything.
#[tokio::test]
async fn a_first_visit_during_an_upload_says_to_reload() -> anyhow::Result<()> {
    let (proxy, browser) = start_with_worker().await?;
    let old = &the_build(&browser).await?;
    // Another profile's first visit: no worker, no cache.
    let fresh = launch_through(&proxy).await?;
    proxy.publish_as(old, "0123456789abcdef", false);
    fresh.goto("").await?;
    let text = fresh.page_error(WORKER_TIMEOUT).await?;
    assert!(
        text.contains("the files of build 0123456789abcdef could not be fetched")
            && text.contains("reload in a minute"),
        "{text}"
    );
    fresh.close().await?;
    browser.close().await
}
