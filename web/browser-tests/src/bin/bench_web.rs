//! `cargo xtask bench-web`: the served release build in headless Chromium,
//! driven through `window.edgewise` and pointer events, beside two bare
//! WebGL2 pages: the same torus (web/bench/baseline.html), and an empty
//! frame presented as wgpu presents (web/bench/present.html). Prints one
//! table.
//!
//! Environment (set by the xtask): `EDGEWISE_URL` (the app),
//! `EDGEWISE_BASELINE_URL` (web/bench/, the bare pages), `EDGEWISE_DIST` (dist/, for
//! the transfer sizes), `EDGEWISE_CHROMIUM` and `EDGEWISE_CHROMEDRIVER`.

use std::io::Write as _;
use std::path::Path;
use std::time::Duration;

use anyhow::Context as _;
use edgewise_browser_tests::{Browser, FIRE_MOUSE, LaunchOptions, Renderer};
use serde_json::{Value, json};

/// How long each orbit is measured.
const ORBIT_SECONDS: f64 = 4.0;

/// How long after its last frame the app is taken to be at rest: longer
/// than the view waits for a moved camera to rest (`MOTION_SETTLE`).
const REST_MS: u32 = 1000;

/// Installed before any page script: when `window.edgewise` appears, the
/// time of every animation frame, so the longest gap between two (the page
/// frozen) can be found for any interval, and every long task (over 50 ms)
/// on the main thread.
const PROBE: &str = "
  window.__bench = { readyAt: null, frameTimes: [], longTasks: [] };
  const poll = setInterval(() => {
    if (window.edgewise) { window.__bench.readyAt = performance.now(); clearInterval(poll); }
  }, 5);
  const tick = (t) => { window.__bench.frameTimes.push(t); requestAnimationFrame(tick); };
  requestAnimationFrame(tick);
  new PerformanceObserver((list) => {
    for (const task of list.getEntries()) window.__bench.longTasks.push([task.startTime, task.duration]);
  }).observe({ type: 'longtask' });
";

/// Times an awaited API call in the page up to the next painted frame, in
/// milliseconds; then waits for the app's last frame of it (a large mesh
/// goes on drawing for some frames after its promise settles) and gives
/// the longest time meanwhile that the page painted no frame (the longest
/// freeze), the longest task, and the time to that last frame.
fn timed(call: &str) -> String {
    format!(
        "(async () => {{
           const start = performance.now();
           await {call};
           await new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r)));
           const shown = performance.now();
           const frames = () => window.edgewise.state().frames;
           let seen = frames(), end = shown, quiet = 0;
           while (quiet < 3 && performance.now() - start < 10000) {{
             await new Promise((r) => requestAnimationFrame(r));
             const now = frames();
             if (now !== seen) {{ seen = now; end = performance.now(); quiet = 0; }} else quiet += 1;
           }}
           const times = [start, ...window.__bench.frameTimes.filter((t) => t > start && t <= end), end];
           let longest = 0;
           for (let i = 1; i < times.length; i++) longest = Math.max(longest, times[i] - times[i - 1]);
           const tasks = window.__bench.longTasks.filter(([t]) => t >= start - 1 && t <= end);
           const longestTask = Math.max(0, ...tasks.map(([, d]) => d));
           window.__bench.frameTimes = [];
           window.__bench.longTasks = [];
           return [shown - start, longest, longestTask, end - start];
         }})()"
    )
}

/// The note of a [`timed`] call: its longest freeze and longest task.
fn freezes(timed: &Value) -> String {
    format!(
        "longest freeze {}, longest task {}; last frame at {}",
        ms(&timed[1]),
        ms(&timed[2]),
        ms(&timed[3])
    )
}

/// Drags across the middle of the canvas for `seconds`, one pointer move
/// per animation frame, and counts the app's frames meanwhile; also the
/// mean time a frame took on the main thread (`state().frameCpuMs`), the
/// share of frames drawn from the motion proxy, and, after the release,
/// when the app drew its last frame (the view rested: no frame for
/// [`REST_MS`]) and the longest task until then.
fn orbit(seconds: f64) -> String {
    format!(
        "(async () => {{
           const canvas = document.querySelector('canvas');
           const r = canvas.getBoundingClientRect();
           const y = r.top + r.height * 0.4;
           let x = r.left + r.width * 0.3;
           {FIRE_MOUSE}
           const fire = (type, x, buttons) => fireMouse(canvas, type, x, y, buttons);
           fire('move', x, 0);
           fire('down', x, 1);
           const before = window.edgewise.state().frames;
           const proxyBefore = window.edgewise.state().motionProxy || 0;
           const start = performance.now();
           let step = 3, cpu = 0, samples = 0, seen = before;
           while (performance.now() - start < {seconds} * 1000) {{
             await new Promise((r) => requestAnimationFrame(r));
             const state = window.edgewise.state();
             if (state.frames !== seen && state.frameCpuMs !== null) {{
               cpu += state.frameCpuMs; samples += 1; seen = state.frames;
             }}
             x += step;
             if (x > r.left + r.width * 0.7 || x < r.left + r.width * 0.3) step = -step;
             fire('move', x, 1);
           }}
           const frames = window.edgewise.state().frames - before;
           const secs = (performance.now() - start) / 1000;
           const proxied = (window.edgewise.state().motionProxy || 0) - proxyBefore;
           fire('up', x, 0);
           const up = performance.now();
           let last = up, lastFrame = window.edgewise.state().frames;
           while (performance.now() - last < {REST_MS} && performance.now() - up < 20000) {{
             await new Promise((r) => requestAnimationFrame(r));
             const now = window.edgewise.state().frames;
             if (now !== lastFrame) {{ lastFrame = now; last = performance.now(); }}
           }}
           const tasks = window.__bench.longTasks.filter(([t]) => t >= up - 1 && t <= last);
           const longestTask = Math.max(0, ...tasks.map(([, d]) => d));
           return [frames / secs, samples ? cpu / samples : null, proxied / Math.max(frames, 1),
                   last - up, longestTask];
         }})()"
    )
}

/// Frames per second of a bare page in web/bench/ that counts its frames
/// in `window.baseline.frames`, over [`ORBIT_SECONDS`].
async fn page_fps(base_url: &str, page: &str, window_size: (u32, u32)) -> anyhow::Result<Value> {
    let browser = Browser::launch_with(LaunchOptions {
        window_size,
        base_url: Some(base_url.to_owned()),
        renderer: Renderer::SwiftShader,
        cpu_compositing: true,
        ..LaunchOptions::default()
    })
    .await?;
    browser.goto(page).await?;
    browser
        .wait_for(
            "window.baseline && window.baseline.frames > 3",
            Duration::from_secs(120),
        )
        .await?;
    let rate = browser
        .eval_async(&format!(
            "(async () => {{
               const before = window.baseline.frames, start = performance.now();
               await new Promise((r) => setTimeout(r, {ORBIT_SECONDS} * 1000));
               return (window.baseline.frames - before) / ((performance.now() - start) / 1000);
             }})()"
        ))
        .await?;
    browser.close().await?;
    Ok(rate)
}

struct Row {
    what: String,
    app: String,
    baseline: String,
    note: String,
}

fn row(what: &str, app: String, baseline: &str, note: String) -> Row {
    Row {
        what: what.to_owned(),
        app,
        baseline: baseline.to_owned(),
        note,
    }
}

fn ms(value: &Value) -> String {
    value
        .as_f64()
        .map_or_else(|| "–".to_owned(), |v| format!("{v:.0} ms"))
}

fn fps(value: &Value) -> String {
    value
        .as_f64()
        .map_or_else(|| "–".to_owned(), |v| format!("{v:.1} frames/s"))
}

/// The bytes of every file in dist/, raw and as downloaded gzipped: the
/// build's own `.gz` copy where it made one, else gzipped here (level 9).
fn transfer(dist: &Path) -> anyhow::Result<(u64, u64)> {
    let mut raw = 0;
    let mut gzipped = 0;
    for entry in std::fs::read_dir(dist).with_context(|| format!("{}", dist.display()))? {
        let path = entry?.path();
        if !path.is_file() || path.extension().is_some_and(|e| e == "gz") {
            continue;
        }
        let bytes = std::fs::read(&path)?;
        raw += bytes.len() as u64;
        let mut precompressed = path.clone().into_os_string();
        precompressed.push(".gz");
        if let Ok(meta) = std::fs::metadata(&precompressed) {
            gzipped += meta.len();
            continue;
        }
        let mut encoder = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::best());
        encoder.write_all(&bytes)?;
        gzipped += encoder.finish()?.len() as u64;
    }
    Ok((raw, gzipped))
}

#[tokio::main]
async fn main() -> anyhow::Result<()> {
    let baseline_url = std::env::var("EDGEWISE_BASELINE_URL").context("EDGEWISE_BASELINE_URL")?;
    let dist = std::env::var("EDGEWISE_DIST").context("EDGEWISE_DIST")?;
    let window_size = (1280, 800);
    let mut rows = Vec::new();

    // The bare pages first: the torus in plain WebGL2, and an empty frame
    // presented as wgpu presents on WebGL2.
    let baseline_fps = page_fps(&baseline_url, "baseline.html", window_size).await?;
    let floor_fps = page_fps(&baseline_url, "present.html", window_size).await?;
    rows.push(row(
        "an empty frame, presented as wgpu does",
        String::new(),
        &fps(&floor_fps),
        "web/bench/present.html: the most any frame of the app reaches here".to_owned(),
    ));

    let app = Browser::launch_with(LaunchOptions {
        window_size,
        renderer: Renderer::SwiftShader,
        cpu_compositing: true,
        ..LaunchOptions::default()
    })
    .await?;
    // A frame of the 3D view on torus-200k can take many seconds on the
    // software renderer: wait for it rather than fail.
    app.set_script_timeout(Duration::from_secs(600)).await?;
    app.cdp(
        "Page.addScriptToEvaluateOnNewDocument",
        json!({ "source": PROBE }),
    )
    .await?;
    app.open("").await?;
    app.wait_for("window.__bench.readyAt !== null", Duration::from_secs(120))
        .await?;
    let ready = app.eval("return window.__bench.readyAt;").await?;
    rows.push(row(
        "start-up to window.edgewise",
        ms(&ready),
        "",
        "from navigation start".to_owned(),
    ));

    let mut torus_fps = Value::Null;
    for sample in ["cube", "icosphere-20k", "torus-200k"] {
        let loaded = app
            .eval_async(&timed(&format!(
                "window.edgewise.loadSample('{sample}', {{ structure: 'half' }})"
            )))
            .await?;
        if sample == "torus-200k" {
            rows.push(row(
                "torus-200k: load (half-edge)",
                ms(&loaded[0]),
                "",
                freezes(&loaded),
            ));
        }
        let orbited = app.eval_async(&orbit(ORBIT_SECONDS)).await?;
        let rate = orbited[0].clone();
        let baseline_cell = if sample == "torus-200k" {
            torus_fps = rate.clone();
            fps(&baseline_fps)
        } else {
            String::new()
        };
        let proxied = orbited[2].as_f64().unwrap_or(0.0);
        let proxy_note = if proxied > 0.0 {
            format!(
                "; {:.0}% of frames from the motion proxy; at rest {} after the release \
                 (longest task {})",
                proxied * 100.0,
                ms(&orbited[3]),
                ms(&orbited[4])
            )
        } else {
            String::new()
        };
        rows.push(row(
            &format!("orbit {sample}"),
            fps(&rate),
            &baseline_cell,
            format!("main thread {} a frame{proxy_note}", ms(&orbited[1])),
        ));
    }
    if let (Some(app_fps), Some(base)) = (torus_fps.as_f64(), baseline_fps.as_f64())
        && app_fps > 0.0
    {
        rows.push(row(
            "torus-200k frame time, app ÷ baseline",
            format!("{:.1}×", base / app_fps),
            "1×",
            "goal: at most 2×".to_owned(),
        ));
    }

    for (what, call) in [
        (
            "torus-200k: select an edge",
            "window.edgewise.select('edge', 1000)",
        ),
        (
            "torus-200k: select another edge",
            "window.edgewise.select('edge', 5000)",
        ),
        (
            "torus-200k: convert to winged-edge",
            "window.edgewise.setStructure('winged')",
        ),
        (
            "torus-200k: run vertexStar (records the trace)",
            "window.edgewise.run('vertexStar', { v: 0 })",
        ),
        ("torus-200k: one step", "window.edgewise.step(1)"),
        ("torus-200k: another step", "window.edgewise.step(1)"),
    ] {
        let taken = app.eval_async(&timed(call)).await?;
        rows.push(row(what, ms(&taken[0]), "", freezes(&taken)));
    }
    app.close().await?;

    let (raw, gzipped) = transfer(Path::new(&dist))?;
    rows.push(row(
        "transfer: dist/ raw, gzipped",
        format!("{:.1} MB", raw as f64 / 1e6),
        "",
        format!("{:.1} MB gzipped (level 9)", gzipped as f64 / 1e6),
    ));

    println!("| measure | app | bare WebGL2 | note |");
    println!("| --- | --- | --- | --- |");
    for r in rows {
        println!("| {} | {} | {} | {} |", r.what, r.app, r.baseline, r.note);
    }
    Ok(())
}
