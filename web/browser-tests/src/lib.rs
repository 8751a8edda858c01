//! A harness for testing Edgewise in a real headless Chromium.
//!
//! `cargo xtask test` serves dist/ and runs these tests with `EDGEWISE_URL`
//! pointing at it. Each test takes a fresh tab in the Chromium the suite
//! shares (or launches one of its own, for other options), opens the page,
//! waits for `window.edgewise`, drives the app through that API, and checks
//! console errors and screenshots.

use std::{
    path::PathBuf,
    time::{Duration, Instant},
};

use anyhow::{Context as _, bail};
use fantoccini::{Client, wd::WebDriverCompatibleCommand};
use serde_json::{Value, json};

mod chromium;
pub mod proxy;
mod shared;

use chromium::Chromium;

/// How long the page may take to download, compile and start the wasm.
const START_TIMEOUT: Duration = Duration::from_secs(120);

/// JavaScript that declares `fireMouse(target, type, x, y, buttons)`: the
/// pointer event and then the mouse event `type` (`'move'`, `'down'`,
/// `'up'`) of the primary mouse at client `(x, y)`, with `buttons` held, as
/// a browser sends them to `target`.
pub const FIRE_MOUSE: &str = "
  const fireMouse = (target, type, x, y, buttons) => {
    const init = { clientX: x, clientY: y, bubbles: true, cancelable: true,
                   pointerId: 1, pointerType: 'mouse', isPrimary: true, button: 0, buttons };
    target.dispatchEvent(new PointerEvent('pointer' + type, init));
    target.dispatchEvent(new MouseEvent('mouse' + type, init));
  };
";

/// JavaScript that declares `fireTouch(type, x, y)`: the touch event `type`
/// (`'start'`, `'move'`, `'end'`) of one finger at client `(x, y)` on the
/// canvas, as a touch screen sends it.
pub const FIRE_TOUCH: &str = "
  const fireTouch = (type, x, y) => {
    const canvas = document.querySelector('canvas');
    const touch = new Touch({ identifier: 1, target: canvas, clientX: x, clientY: y,
                              pageX: x, pageY: y, screenX: x, screenY: y });
    const held = type === 'end' ? [] : [touch];
    canvas.dispatchEvent(new TouchEvent('touch' + type, {
      touches: held, targetTouches: held, changedTouches: [touch],
      bubbles: true, cancelable: true }));
  };
";

/// Statements that press the mouse in the middle of `canvas` (declared by
/// [`Browser::canvas_when`]) and drag it left and right, a pointer move per
/// animation frame, until `window.__release` is set; the mouse is then
/// released. They follow [`FIRE_MOUSE`].
pub const DRAG_IN_VIEW: &str = "
  const r = canvas.getBoundingClientRect();
  const y = r.top + r.height * 0.4;
  let x = r.left + r.width * 0.4, step = 4;
  const fire = (type, buttons) => fireMouse(canvas, type, x, y, buttons);
  window.__release = false;
  fire('move', 0);
  fire('down', 1);
  (async () => {
    while (!window.__release) {
      await new Promise((r) => requestAnimationFrame(r));
      x += step;
      if (Math.abs(x - (r.left + r.width * 0.4)) > 80) step = -step;
      fire('move', 1);
    }
    fire('up', 0);
  })();
";

/// Options for launching the browser.
#[derive(Clone, Debug)]
pub struct LaunchOptions {
    /// Window size in CSS pixels.
    pub window_size: (u32, u32),
    /// What draws WebGL2: these machines have no GPU.
    pub renderer: Renderer,
    /// The app's URL, when not `EDGEWISE_URL` (a [`proxy::Proxy`]'s).
    pub base_url: Option<String>,
    /// A true device pixel ratio other than 1 (`--force-device-scale-factor`),
    /// as a phone's or a high-density laptop's screen has.
    pub device_scale_factor: Option<f64>,
    /// Composite the page on the CPU (`--disable-gpu`), as Chromium does
    /// where it finds no usable GPU: the benchmarks' case. Otherwise the
    /// compositor draws with the [`Renderer`] too, where the 3D view already
    /// is, and no frame is read back from it: the tests, in about a fifth
    /// less time (docs/performance.md).
    pub cpu_compositing: bool,
}

/// The software Vulkan that Chromium's WebGL2 (ANGLE on Vulkan) draws
/// with, or none.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Renderer {
    /// Mesa's lavapipe (llvmpipe), which the native render tests draw on
    /// too: the suite took a fifth less time than on `SwiftShader`, every
    /// test passing on both (docs/performance.md).
    #[default]
    Lavapipe,
    /// Chromium's own `SwiftShader`, what Chromium offers without a GPU
    /// (`--enable-unsafe-swiftshader`): the benchmarks' tables were
    /// measured on it, and one start-up test keeps the app drawing there.
    SwiftShader,
    /// WebGL and WebGPU turned off, to test the page's message for that
    /// case.
    None,
}

impl Default for LaunchOptions {
    fn default() -> Self {
        Self {
            window_size: (1280, 800),
            renderer: Renderer::default(),
            base_url: None,
            device_scale_factor: None,
            cpu_compositing: false,
        }
    }
}

/// A screen the layout must hold on: its size in CSS pixels, its device
/// pixel ratio, and whether it is touched rather than clicked.
#[derive(Clone, Copy, Debug)]
pub struct Screen {
    pub name: &'static str,
    pub width: u32,
    pub height: u32,
    pub ratio: f64,
    pub touch: bool,
}

/// The heaviest pages (the screen matrices, the host pages with several
/// embedded views) take turns: two of them side by side on a two-core
/// machine starved a renderer for minutes. `cargo xtask test` runs the
/// suite one test at a time anyway; this keeps them apart when the suite is
/// run with more threads, as plain `cargo test` does.
pub static ONE_HEAVY_PAGE_AT_A_TIME: tokio::sync::Mutex<()> = tokio::sync::Mutex::const_new(());

/// The screens students and lecturers use, each size once: a
/// high-density laptop, a projector, a window on half a laptop's screen
/// (beside the lecture notes), a tablet and a phone. The same size at
/// another ratio lays out the same CSS pixels, and its canvas is checked at
/// ratios 1, 2 and 3 here; 1280×800 at 1 and 1920×1080 at 2 were 17 s of
/// the suite (docs/performance.md).
pub const SCREENS: [Screen; 5] = [
    Screen {
        name: "desktop-1280x800@2",
        width: 1280,
        height: 800,
        ratio: 2.0,
        touch: false,
    },
    Screen {
        name: "desktop-1920x1080@1",
        width: 1920,
        height: 1080,
        ratio: 1.0,
        touch: false,
    },
    Screen {
        name: "window-640x800@1",
        width: 640,
        height: 800,
        ratio: 1.0,
        touch: false,
    },
    Screen {
        name: "tablet-820x1180@2",
        width: 820,
        height: 1180,
        ratio: 2.0,
        touch: true,
    },
    Screen {
        name: "phone-390x844@3",
        width: 390,
        height: 844,
        ratio: 3.0,
        touch: true,
    },
];

/// A headless Chromium session on the served app.
pub struct Browser {
    client: Client,
    base_url: String,
    /// Its own Chromium, or the shared one, handed back when this drops.
    chromium: Option<Chromium>,
    shared: bool,
}

impl Browser {
    /// A fresh tab in the Chromium the tests share (`shared.rs`), on the
    /// served app at 1280×800; a browser of its own if another test holds
    /// that one.
    pub async fn launch() -> anyhow::Result<Self> {
        Self::launch_with(LaunchOptions::default()).await
    }

    /// A browser with `options`: the shared Chromium where they differ from
    /// the default only in the window's size (set as `--window-size` sets
    /// it, and put back when the test is done) or the app's URL; otherwise,
    /// or while another test holds the shared one, a Chromium of its own.
    pub async fn launch_with(options: LaunchOptions) -> anyhow::Result<Self> {
        let base_url = match &options.base_url {
            Some(url) => url.clone(),
            None => env("EDGEWISE_URL")?,
        };
        let default = LaunchOptions::default();
        let shareable = options.renderer == default.renderer
            && options.device_scale_factor.is_none()
            && options.cpu_compositing == default.cpu_compositing;
        if shareable && let Some(chromium) = shared::lend().await? {
            let browser = Self {
                client: chromium.client.clone(),
                base_url,
                chromium: Some(chromium),
                shared: true,
            };
            if options.window_size != default.window_size {
                let (width, height) = options.window_size;
                browser
                    .client
                    .set_window_size(width, height)
                    .await
                    .context("cannot size the window")?;
            }
            return Ok(browser);
        }
        let chromium = Chromium::start(&options).await?;
        Ok(Self {
            client: chromium.client.clone(),
            base_url,
            chromium: Some(chromium),
            shared: false,
        })
    }

    /// Launches a browser on the app with `sample` open as a half-edge
    /// mesh, its scripts allowed three minutes: under `SwiftShader` a large
    /// mesh's frames are slow.
    pub async fn launch_on_sample(sample: &str) -> anyhow::Result<Self> {
        let browser = Self::launch().await?;
        browser.set_script_timeout(Duration::from_secs(180)).await?;
        browser.open("").await?;
        browser
            .eval_async(&format!(
                "window.edgewise.loadSample('{sample}', {{ structure: 'half' }})"
            ))
            .await?;
        Ok(browser)
    }

    /// The URL of the served app, ending in '/'.
    pub fn base_url(&self) -> &str {
        &self.base_url
    }

    /// Opens the app with `suffix` appended to its URL (e.g. "?embed=1")
    /// and waits until `window.edgewise` exists.
    pub async fn open(&self, suffix: &str) -> anyhow::Result<()> {
        self.goto(suffix).await?;
        self.wait_until_ready().await
    }

    /// Navigates to the app URL plus `suffix` without waiting for the app.
    pub async fn goto(&self, suffix: &str) -> anyhow::Result<()> {
        let url = format!("{}{suffix}", self.base_url);
        self.client
            .goto(&url)
            .await
            .with_context(|| format!("cannot open {url}"))
    }

    /// Navigates to `url`, a page of another site than the app (a host
    /// page that embeds it), without waiting for the app.
    pub async fn goto_url(&self, url: &str) -> anyhow::Result<()> {
        self.client
            .goto(url)
            .await
            .with_context(|| format!("cannot open {url}"))
    }

    /// Opens a second tab and switches to it; [`Self::switch_to`] goes back
    /// to the first with the handle of [`Self::tab`].
    pub async fn new_tab(&self) -> anyhow::Result<fantoccini::wd::WindowHandle> {
        let opened = self.client.new_window(true).await?;
        self.client.switch_to_window(opened.handle.clone()).await?;
        Ok(opened.handle)
    }

    /// The tab commands go to.
    pub async fn tab(&self) -> anyhow::Result<fantoccini::wd::WindowHandle> {
        Ok(self.client.window().await?)
    }

    /// Sends the next commands to `tab`.
    pub async fn switch_to(&self, tab: fantoccini::wd::WindowHandle) -> anyhow::Result<()> {
        Ok(self.client.switch_to_window(tab).await?)
    }

    /// Waits until the page shows its error box (a load that failed, a
    /// browser without 3D) and returns the box's text.
    pub async fn page_error(&self, timeout: Duration) -> anyhow::Result<String> {
        self.wait_for(
            "document.getElementById('edgewise_error').dataset.visible === 'true'",
            timeout,
        )
        .await?;
        let text = self
            .eval("return document.getElementById('edgewise_error').textContent;")
            .await?;
        Ok(text.as_str().unwrap_or_default().to_owned())
    }

    /// Waits until the app has defined `window.edgewise`, failing early with
    /// the page's own message if it shows one.
    pub async fn wait_until_ready(&self) -> anyhow::Result<()> {
        let start = Instant::now();
        loop {
            let status = self
                .eval(
                    "return { ready: !!window.edgewise, error: document.getElementById('edgewise_error')?.dataset.visible === 'true' ? document.getElementById('edgewise_error').textContent : null };",
                )
                .await?;
            if let Some(error) = status["error"].as_str() {
                let console = self.console_errors().await.unwrap_or_default();
                bail!("the page shows an error: {error}\nconsole errors: {console:#?}");
            }
            if status["ready"] == Value::Bool(true) {
                return Ok(());
            }
            if start.elapsed() > START_TIMEOUT {
                let console = self.console_errors().await.unwrap_or_default();
                bail!(
                    "window.edgewise did not appear within {}s; console errors: {console:#?}",
                    START_TIMEOUT.as_secs()
                );
            }
            tokio::time::sleep(Duration::from_millis(250)).await;
        }
    }

    /// Waits until `condition` (a JS expression) is true.
    pub async fn wait_for(&self, condition: &str, timeout: Duration) -> anyhow::Result<()> {
        let start = Instant::now();
        while self.eval(&format!("return !!({condition});")).await? != Value::Bool(true) {
            if start.elapsed() > timeout {
                bail!("`{condition}` was still false after {}s", timeout.as_secs());
            }
            tokio::time::sleep(Duration::from_millis(100)).await;
        }
        Ok(())
    }

    /// Runs a script body (use `return`) and returns its JSON result.
    pub async fn eval(&self, script: &str) -> anyhow::Result<Value> {
        self.client
            .execute(script, vec![])
            .await
            .with_context(|| format!("script failed: {script}"))
    }

    /// Runs a script body in the page's frame number `index` (0 is the
    /// first), even one from another origin, and comes back to the page:
    /// for saying what a frame shows when a host page test fails.
    pub async fn eval_in_frame(&self, index: u16, script: &str) -> anyhow::Result<Value> {
        self.client
            .enter_frame(index)
            .await
            .with_context(|| format!("cannot enter frame {index}"))?;
        let value = self.eval(script).await;
        self.client
            .enter_parent_frame()
            .await
            .context("cannot leave the frame")?;
        value
    }

    /// Awaits a JS expression that may be a Promise and returns its JSON value.
    pub async fn eval_async(&self, expression: &str) -> anyhow::Result<Value> {
        let script = format!(
            "const done = arguments[arguments.length - 1];\n\
             Promise.resolve().then(() => ({expression}))\n\
               .then((value) => done({{ ok: value === undefined ? null : value }}))\n\
               .catch((err) => done({{ err: String(err && err.message || err) }}));"
        );
        let result = self
            .client
            .execute_async(&script, vec![])
            .await
            .with_context(|| format!("script failed: {expression}"))?;
        match result.get("err") {
            Some(err) => bail!("`{expression}` threw: {err}"),
            None => Ok(result["ok"].clone()),
        }
    }

    /// Compresses the text that the JS expression `text_js` makes into a
    /// course-link payload in the page, as docs/embedding.md shows page
    /// authors: deflate-raw with `CompressionStream`, then base64url.
    pub async fn payload(&self, text_js: &str) -> anyhow::Result<String> {
        let payload = self
            .eval_async(&format!(
                "(async () => {{
                    const text = {text_js};
                    const stream = new Blob([text]).stream().pipeThrough(new CompressionStream('deflate-raw'));
                    const bytes = new Uint8Array(await new Response(stream).arrayBuffer());
                    let binary = '';
                    for (const b of bytes) binary += String.fromCharCode(b);
                    return btoa(binary).replace(/\\+/g, '-').replace(/\\//g, '_').replace(/=+$/, '');
                }})()"
            ))
            .await?;
        payload
            .as_str()
            .map(str::to_owned)
            .context("the page made no payload")
    }

    /// Awaits a JS API command that must be refused: its Promise must reject
    /// (the API's convention), and the rejection's message is returned.
    pub async fn refusal(&self, expression: &str) -> anyhow::Result<Value> {
        match self.eval_async(expression).await {
            Ok(value) => bail!("`{expression}` resolved to {value}; it must be refused"),
            Err(error) => {
                let text = format!("{error:#}");
                let prefix = format!("`{expression}` threw: ");
                let message = text.strip_prefix(&prefix).unwrap_or(&text);
                let message: String = serde_json::from_str(message).unwrap_or(message.to_owned());
                Ok(Value::String(message))
            }
        }
    }

    /// Sends a Chrome DevTools Protocol command through chromedriver.
    pub async fn cdp(&self, command: &str, params: Value) -> anyhow::Result<Value> {
        self.client
            .issue_cmd(Cdp {
                command: command.to_owned(),
                params,
            })
            .await
            .with_context(|| format!("CDP command {command} failed"))
    }

    /// Sizes the window so that the page's viewport is `width` × `height`
    /// CSS pixels: `--window-size` counts the browser's own bars too.
    pub async fn fit_viewport(&self, width: u32, height: u32) -> anyhow::Result<()> {
        for _ in 0..3 {
            let inner = self
                .eval("return [innerWidth, innerHeight, outerWidth, outerHeight];")
                .await?;
            let at = |i: usize| inner[i].as_i64().unwrap_or(0);
            let (dw, dh) = (i64::from(width) - at(0), i64::from(height) - at(1));
            if dw == 0 && dh == 0 {
                return Ok(());
            }
            let outer = |size: i64, extra: i64| u32::try_from(size + extra).unwrap_or(1);
            self.client
                .set_window_size(outer(at(2), dw), outer(at(3), dh))
                .await
                .context("cannot size the window")?;
        }
        let inner = self.eval("return [innerWidth, innerHeight];").await?;
        bail!("the viewport stays {inner} instead of {width}×{height}")
    }

    /// Makes the page a `screen` as `DevTools`' device mode does
    /// (`Emulation.setDeviceMetricsOverride`, and touch for a touch screen);
    /// the page must be loaded again to start on it.
    pub async fn emulate(&self, screen: &Screen) -> anyhow::Result<()> {
        self.cdp(
            "Emulation.setDeviceMetricsOverride",
            json!({ "width": screen.width, "height": screen.height,
                    "deviceScaleFactor": screen.ratio, "mobile": screen.touch }),
        )
        .await?;
        // On a touch screen the page sees touch points and a coarse pointer,
        // and `tap_at` works.
        let touch = screen.touch;
        self.cdp(
            "Emulation.setTouchEmulationEnabled",
            json!({ "enabled": touch, "maxTouchPoints": if touch { 5 } else { 1 } }),
        )
        .await?;
        Ok(())
    }

    /// Taps with one finger at `(x, y)` CSS pixels of the page. The touch
    /// starts and ends in one task, so that both reach the same frame: under
    /// a software renderer a large page's frame can outlast egui's longest
    /// click.
    pub async fn tap_at(&self, x: f64, y: f64) -> anyhow::Result<()> {
        self.eval(&format!(
            "{FIRE_TOUCH}
             fireTouch('start', {x}, {y});
             fireTouch('end', {x}, {y});
             return null;"
        ))
        .await
        .map(drop)
    }

    /// Drags one finger from `(x, y)` by `dy` CSS pixels, a move per
    /// animation frame, as a thumb scrolls a list.
    pub async fn swipe(&self, x: f64, y: f64, dy: f64) -> anyhow::Result<()> {
        self.eval_async(&format!(
            "(async () => {{
             {FIRE_TOUCH}
             fireTouch('start', {x}, {y});
             const steps = 4;
             for (let i = 1; i <= steps; i++) {{
               await new Promise((r) => requestAnimationFrame(r));
               fireTouch('move', {x}, {y} + {dy} * i / steps);
             }}
             await new Promise((r) => requestAnimationFrame(r));
             fireTouch('end', {x}, {y} + {dy});
             }})()"
        ))
        .await
        .map(drop)
    }

    /// Clicks with `button` (`"left"`, `"right"`) at `(x, y)` CSS pixels of
    /// the page, as a real mouse does: moved, pressed, released.
    pub async fn click_at(&self, x: f64, y: f64, button: &str) -> anyhow::Result<()> {
        self.cdp(
            "Input.dispatchMouseEvent",
            json!({ "type": "mouseMoved", "x": x, "y": y }),
        )
        .await?;
        for kind in ["mousePressed", "mouseReleased"] {
            self.cdp(
                "Input.dispatchMouseEvent",
                json!({ "type": kind, "x": x, "y": y, "button": button, "clickCount": 1 }),
            )
            .await?;
        }
        Ok(())
    }

    /// Waits for the page's next animation frame.
    pub async fn next_frame(&self) -> anyhow::Result<()> {
        self.eval_async("new Promise((r) => requestAnimationFrame(r))")
            .await
            .map(drop)
    }

    /// Waits for `count` more animation frames, in which the app draws what
    /// the input it has taken changed (egui lays a new window out in the
    /// frame after the one that shows it), rather than for a fixed time.
    pub async fn frames(&self, count: u32) -> anyhow::Result<()> {
        for _ in 0..count {
            self.next_frame().await?;
        }
        Ok(())
    }

    /// Where the app draws an element, in CSS pixels of the page: its
    /// `screenPosition` plus the canvas's offset; `None` if not in view.
    pub async fn element_at(&self, kind: &str, id: u32) -> anyhow::Result<Option<(f64, f64)>> {
        let at = self
            .eval(&format!(
                "const p = window.edgewise.screenPosition('{kind}', {id});
                 if (!p) return null;
                 const r = document.querySelector('canvas').getBoundingClientRect();
                 return [r.left + p[0], r.top + p[1]];"
            ))
            .await?;
        Ok(at
            .as_array()
            .and_then(|p| Some((p.first()?.as_f64()?, p.get(1)?.as_f64()?))))
    }

    /// Presses and releases a key (`"Enter"`, `"Tab"`, `"ArrowDown"`,
    /// `"PageDown"`, `" "` for Space, `"e"`, `"z"`), with `modifiers` as
    /// CDP counts them (2 is Ctrl, 8 is Shift).
    pub async fn press_key(&self, key: &str, modifiers: u32) -> anyhow::Result<()> {
        // Each named key's `code` and key code.
        const NAMED: &[(&str, &str, u32)] = &[
            ("Enter", "Enter", 13),
            ("Escape", "Escape", 27),
            ("Tab", "Tab", 9),
            (" ", "Space", 32),
            ("/", "Slash", 191),
            ("PageUp", "PageUp", 33),
            ("PageDown", "PageDown", 34),
            ("ArrowLeft", "ArrowLeft", 37),
            ("ArrowUp", "ArrowUp", 38),
            ("ArrowRight", "ArrowRight", 39),
            ("ArrowDown", "ArrowDown", 40),
        ];
        let (code, key_code) = match NAMED.iter().find(|(name, _, _)| *name == key) {
            Some(&(_, code, key_code)) => (code.to_owned(), key_code),
            None => (
                format!("Key{}", key.to_uppercase()),
                u32::from(key.to_ascii_uppercase().bytes().next().unwrap_or(b'A')),
            ),
        };
        let text = if key.len() == 1 && modifiers == 0 {
            key
        } else {
            ""
        };
        self.cdp(
            "Input.dispatchKeyEvent",
            json!({ "type": "keyDown", "key": key, "code": code, "text": text,
                    "windowsVirtualKeyCode": key_code, "modifiers": modifiers }),
        )
        .await?;
        self.cdp(
            "Input.dispatchKeyEvent",
            json!({ "type": "keyUp", "key": key, "code": code,
                    "windowsVirtualKeyCode": key_code, "modifiers": modifiers }),
        )
        .await?;
        Ok(())
    }

    /// How long a script may run before the driver stops it (60 s unless
    /// set): the benchmark waits out frames that take many seconds.
    pub async fn set_script_timeout(&self, timeout: Duration) -> anyhow::Result<()> {
        self.client
            .update_timeouts(fantoccini::wd::TimeoutConfiguration::new(
                Some(timeout),
                Some(timeout),
                Some(Duration::ZERO),
            ))
            .await
            .context("cannot set the script timeout")
    }

    /// Makes every request whose URL matches one of `patterns` (with `*`
    /// wildcards) fail, as a broken network or a bad deploy would.
    pub async fn block_urls(&self, patterns: &[&str]) -> anyhow::Result<()> {
        self.cdp("Network.enable", json!({})).await?;
        self.cdp("Network.setBlockedURLs", json!({ "urls": patterns }))
            .await?;
        Ok(())
    }

    /// Clears the app's and the host pages' storage and service workers, as
    /// a first visit finds them.
    pub async fn clear_site_data(&self) -> anyhow::Result<()> {
        shared::clear_site_data(&self.client, &[&self.base_url]).await
    }

    /// `window.edgewise.state()`.
    pub async fn state(&self) -> anyhow::Result<Value> {
        self.eval("return window.edgewise.state();").await
    }

    /// A `[drawn, copied]` pair of `state()` (`baseImage`, `uiCache`), as
    /// numbers; 0 where null.
    pub async fn drawn_and_copied(&self, key: &str) -> anyhow::Result<[u64; 2]> {
        let state = self.state().await?;
        let count = |i: usize| state[key][i].as_u64().unwrap_or(0);
        Ok([count(0), count(1)])
    }

    /// The console messages of level SEVERE (console.error, uncaught
    /// exceptions, failed loads) since the last call.
    pub async fn console_errors(&self) -> anyhow::Result<Vec<String>> {
        let logs = self
            .client
            .issue_cmd(BrowserLog)
            .await
            .context("cannot read the browser console")?;
        Ok(logs
            .as_array()
            .into_iter()
            .flatten()
            .filter(|entry| entry["level"] == "SEVERE")
            .map(|entry| entry["message"].as_str().unwrap_or_default().to_owned())
            .collect())
    }

    /// Fails if the console has logged any error.
    pub async fn assert_no_console_errors(&self) -> anyhow::Result<()> {
        let errors = self.console_errors().await?;
        if !errors.is_empty() {
            bail!("the console logged errors:\n{}", errors.join("\n"));
        }
        Ok(())
    }

    /// Runs the statements `start`, then reads the canvas as drawn by the
    /// first animation frame after which `condition` (a JavaScript
    /// expression) holds, inside that frame: a `WebDriver` call waits for
    /// frames of its own, and can miss a state that lasts a few frames.
    /// Saved like [`Self::screenshot`].
    pub async fn canvas_when(
        &self,
        start: &str,
        condition: &str,
        name: &str,
    ) -> anyhow::Result<Screenshot> {
        use base64::Engine as _;
        let url = self
            .eval_async(&format!(
                "(async () => {{
                   const canvas = document.querySelector('canvas');
                   {start}
                   for (let i = 0; i < 2000; i++) {{
                     await new Promise((r) => requestAnimationFrame(r));
                     if ({condition}) return canvas.toDataURL('image/png');
                   }}
                   return null;
                 }})()"
            ))
            .await?;
        let url = url
            .as_str()
            .with_context(|| format!("`{condition}` never held"))?;
        let data = url
            .strip_prefix("data:image/png;base64,")
            .context("the canvas gave no PNG")?;
        let bytes = base64::engine::general_purpose::STANDARD.decode(data)?;
        let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("screenshots");
        std::fs::create_dir_all(&dir)?;
        let path = dir.join(format!("{name}.png"));
        std::fs::write(&path, &bytes)?;
        Screenshot::decode(&bytes, path)
    }

    /// Takes a screenshot, saves it as screenshots/`name`.png for people to
    /// look at, and returns its pixels.
    pub async fn screenshot(&self, name: &str) -> anyhow::Result<Screenshot> {
        let bytes = self
            .client
            .screenshot()
            .await
            .context("screenshot failed")?;
        Screenshot::keep(name, &bytes)
    }

    /// Ends the test's use of the browser: closes a browser of its own, and
    /// hands the shared one back for the next test.
    pub async fn close(self) -> anyhow::Result<()> {
        if !self.shared {
            self.client
                .clone()
                .close()
                .await
                .context("cannot close the browser")?;
        }
        Ok(())
    }
}

/// A test that fails drops its browser without closing it: its own
/// Chromium ends (`chromium.rs`), and the shared one goes back.
impl Drop for Browser {
    fn drop(&mut self) {
        if let Some(chromium) = self.chromium.take()
            && self.shared
        {
            shared::give_back(chromium, &self.base_url);
        }
    }
}

/// A decoded screenshot.
pub struct Screenshot {
    pub path: PathBuf,
    pub width: u32,
    pub height: u32,
    /// RGB or RGBA pixels, row by row: left as decoded, since widening a
    /// large screenshot to RGBA in the unoptimised test build took longer
    /// than decoding it.
    pixels: Vec<u8>,
    /// 3 or 4.
    channels: usize,
}

/// Where screenshots and exported pictures are written, to be looked at.
pub fn screenshots_dir() -> anyhow::Result<PathBuf> {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("screenshots");
    std::fs::create_dir_all(&dir)?;
    Ok(dir)
}

impl Screenshot {
    /// Writes PNG `bytes` to the screenshots folder as `name.png` and
    /// decodes them.
    pub fn keep(name: &str, bytes: &[u8]) -> anyhow::Result<Self> {
        let path = screenshots_dir()?.join(format!("{name}.png"));
        std::fs::write(&path, bytes)?;
        Self::decode(bytes, path)
    }

    fn decode(bytes: &[u8], path: PathBuf) -> anyhow::Result<Self> {
        let mut decoder = png::Decoder::new(std::io::Cursor::new(bytes));
        decoder.set_transformations(png::Transformations::EXPAND);
        let mut reader = decoder.read_info()?;
        let size = reader
            .output_buffer_size()
            .context("screenshot too large to decode")?;
        let mut buf = vec![0; size];
        let info = reader.next_frame(&mut buf)?;
        buf.truncate(info.buffer_size());
        let channels = match info.color_type {
            png::ColorType::Rgba => 4,
            png::ColorType::Rgb => 3,
            other => bail!("unexpected screenshot colour type {other:?}"),
        };
        Ok(Self {
            path,
            width: info.width,
            height: info.height,
            channels,
            pixels: buf,
        })
    }

    /// The number of distinct colours, capped at `cap`.
    pub fn distinct_colours(&self, cap: usize) -> usize {
        let mut seen = std::collections::HashSet::new();
        for pixel in self.pixels.chunks_exact(self.channels) {
            seen.insert([pixel[0], pixel[1], pixel[2]]);
            if seen.len() >= cap {
                break;
            }
        }
        seen.len()
    }

    /// A blank screenshot is one flat colour, or nearly so: a canvas that
    /// never drew, or a page that never loaded.
    pub fn is_blank(&self) -> bool {
        self.distinct_colours(16) < 16
    }

    /// How many pixels are `colour`, give or take `tolerance` per channel.
    pub fn count(&self, colour: [u8; 3], tolerance: u8) -> usize {
        self.pixels
            .chunks_exact(self.channels)
            .filter(|p| (0..3).all(|c| p[c].abs_diff(colour[c]) <= tolerance))
            .count()
    }

    /// The RGB colour at (x, y).
    pub fn pixel(&self, x: u32, y: u32) -> [u8; 3] {
        let i = (y * self.width + x) as usize * self.channels;
        [self.pixels[i], self.pixels[i + 1], self.pixels[i + 2]]
    }
}

/// Chromedriver's (non-standard) command for the browser console log.
#[derive(Debug)]
pub(crate) struct BrowserLog;

impl WebDriverCompatibleCommand for BrowserLog {
    fn endpoint(
        &self,
        base_url: &url::Url,
        session_id: Option<&str>,
    ) -> Result<url::Url, url::ParseError> {
        base_url.join(&format!(
            "session/{}/se/log",
            session_id.unwrap_or_default()
        ))
    }

    fn method_and_body(&self, _request_url: &url::Url) -> (http::Method, Option<String>) {
        (
            http::Method::POST,
            Some(json!({ "type": "browser" }).to_string()),
        )
    }
}

/// Chromedriver's command for running a DevTools Protocol command.
#[derive(Debug)]
pub(crate) struct Cdp {
    pub(crate) command: String,
    pub(crate) params: Value,
}

impl WebDriverCompatibleCommand for Cdp {
    fn endpoint(
        &self,
        base_url: &url::Url,
        session_id: Option<&str>,
    ) -> Result<url::Url, url::ParseError> {
        base_url.join(&format!(
            "session/{}/goog/cdp/execute",
            session_id.unwrap_or_default()
        ))
    }

    fn method_and_body(&self, _request_url: &url::Url) -> (http::Method, Option<String>) {
        (
            http::Method::POST,
            Some(json!({ "cmd": self.command, "params": self.params }).to_string()),
        )
    }
}

pub(crate) fn env(name: &str) -> anyhow::Result<String> {
    std::env::var(name).with_context(|| {
        format!("{name} is not set: run the browser tests with `cargo xtask test` (or `cargo xtask browser-test`)")
    })
}

/// The `window.edgewise` calls, as `(method, args)`, that turn `current`
/// into `target`: a student's fewest writes, as a saved attempt stores them.
pub fn student_writes(
    current: &edgewise_core::mesh::Mesh,
    target: &edgewise_core::mesh::Mesh,
) -> Vec<(&'static str, Value)> {
    use edgewise_model::practice::progress::{Write, writes_between};
    writes_between(current, target)
        .into_iter()
        .map(|write| match write {
            Write::AddRow(kind) => ("addRow", json!([kind.prose()])),
            Write::Reference {
                element,
                column,
                target,
            } => (
                "setCell",
                json!([
                    element.kind.prose(),
                    element.id,
                    column.lookup_name(),
                    target
                ]),
            ),
            Write::Position { vertex, position } => ("setPosition", json!([vertex, position])),
            Write::DeleteRow(row) => ("deleteRow", json!([row.kind.prose(), row.id])),
        })
        .collect()
}
