//! The layout on every screen students and lecturers use: a laptop at
//! device pixel ratio 2, a projector at 1 and a window on half a laptop's
//! screen, each at its true ratio; a tablet and a phone (touch)
//! under Chromium's device emulation (what `DevTools`' device mode and
//! lecturers' previews use, and what a phone's browser shows). In each of six
//! states (the first visit's welcome card, a run's first step, loopSubdivide
//! at its last step, the edit menu, a question waiting, the Algorithm menu)
//! `state().layout` must show the 3D view holding a third of the window, no
//! overlay over the step controls, and every command and menu entry within
//! reach; and the canvas must be drawn at the screen's ratio. A screenshot
//! of each is kept.

use std::time::Duration;

use anyhow::{Context as _, bail, ensure};
use edgewise_browser_tests::{
    Browser, FIRE_MOUSE, LaunchOptions, ONE_HEAVY_PAGE_AT_A_TIME, SCREENS, Screen,
};
use serde_json::Value;

const QUESTIONS: &str = include_str!("../../../../algorithms/questions/vertex-adjacent-edge.txt");
const WAIT: Duration = Duration::from_secs(60);

#[derive(Clone, Copy, Debug)]
struct Rect {
    x: f64,
    y: f64,
    w: f64,
    h: f64,
}

impl Rect {
    fn of(value: &Value) -> anyhow::Result<Self> {
        let at = |key: &str| {
            value[key]
                .as_f64()
                .with_context(|| format!("{key} in {value}"))
        };
        Ok(Self {
            x: at("x")?,
            y: at("y")?,
            w: at("w")?,
            h: at("h")?,
        })
    }

    fn area(self) -> f64 {
        self.w * self.h
    }

    fn intersects(self, other: Self) -> bool {
        self.x < other.x + other.w
            && other.x < self.x + self.w
            && self.y < other.y + other.h
            && other.y < self.y + self.h
    }

    /// Inside `outer`, give or take a pixel.
    fn inside(self, outer: Self) -> bool {
        self.x >= outer.x - 1.0
            && self.y >= outer.y - 1.0
            && self.x + self.w <= outer.x + outer.w + 1.0
            && self.y + self.h <= outer.y + outer.h + 1.0
    }

    /// A pixel inside each edge: rectangles that only touch do not meet.
    fn inset(self) -> Self {
        Self {
            x: self.x + 1.0,
            y: self.y + 1.0,
            w: self.w - 2.0,
            h: self.h - 2.0,
        }
    }

    fn centre(self) -> (f64, f64) {
        (self.x + self.w / 2.0, self.y + self.h / 2.0)
    }
}

/// One screen, seen one way (true ratio or emulated).
struct Seen<'a> {
    browser: &'a Browser,
    screen: Screen,
    how: &'static str,
}

impl Seen<'_> {
    async fn layout(&self) -> anyhow::Result<Value> {
        // Two frames, so that the layout is of what the last command did.
        self.browser.frames(2).await?;
        Ok(self.browser.state().await?["layout"].take())
    }

    /// Clicks or taps, as the screen is used. A click's press and release
    /// go in one task, so that they reach the same frame: a frame at a high
    /// ratio under a software renderer can outlast egui's longest click.
    async fn press(&self, (x, y): (f64, f64)) -> anyhow::Result<()> {
        if self.screen.touch {
            return self.browser.tap_at(x, y).await;
        }
        self.browser
            .eval(&format!(
                "{FIRE_MOUSE}
                 const canvas = document.querySelector('canvas');
                 fireMouse(canvas, 'move', {x}, {y}, 0);
                 fireMouse(canvas, 'down', {x}, {y}, 1);
                 fireMouse(canvas, 'up', {x}, {y}, 0);
                 return null;"
            ))
            .await
            .map(drop)
    }

    /// The checks every state must pass, and its screenshot.
    async fn check(&self, state: &str) -> anyhow::Result<Value> {
        let layout = self.layout().await?;
        let at = format!("{} ({}), {state}: {layout}", self.screen.name, self.how);
        let window = Rect::of(&layout["window"]).context(at.clone())?;
        ensure!(
            (window.w - f64::from(self.screen.width)).abs() <= 1.0
                && (window.h - f64::from(self.screen.height)).abs() <= 1.0,
            "the window is laid out at the screen's size in CSS pixels; {at}"
        );
        let view = Rect::of(&layout["view"]).context(at.clone())?;
        ensure!(
            view.area() >= window.area() / 3.0 - 1.0,
            "the 3D view holds a third of the window; {at}"
        );
        let panels = layout["panels"].as_object().context("panels")?;
        for (name, panel) in panels {
            let panel = Rect::of(panel)?;
            for (other, rect) in panels.iter().filter(|(other, _)| *other > name) {
                ensure!(
                    !panel.intersects(Rect::of(rect)?.inset()),
                    "the {name} and {other} panels do not overlap; {at}"
                );
            }
            ensure!(panel.inside(window), "the {name} panel is on screen; {at}");
            ensure!(
                !panel.intersects(view.inset()),
                "the {name} panel leaves the view alone; {at}"
            );
        }
        if let Ok(controls) = Rect::of(&layout["stepControls"]) {
            ensure!(
                controls.inside(window),
                "the step controls are on screen; {at}"
            );
            for overlay in layout["overlays"].as_array().into_iter().flatten() {
                ensure!(
                    !Rect::of(&overlay["rect"])?.intersects(controls),
                    "no overlay covers the step controls; {at}"
                );
            }
        }
        let bar = layout["topBar"].as_array().context("topBar")?;
        ensure!(!bar.is_empty(), "the top bar shows; {at}");
        for command in bar {
            ensure!(
                Rect::of(&command["rect"])?.inside(window),
                "every top-bar command is on screen: {}; {at}",
                command["name"]
            );
        }
        let canvas = self
            .browser
            .eval(
                "const c = document.querySelector('canvas');
                 return [c.width, c.clientWidth, c.height, c.clientHeight, devicePixelRatio];",
            )
            .await?;
        let number = |i: usize| canvas[i].as_f64().unwrap_or(0.0);
        let ratio = number(4);
        ensure!(
            (ratio - self.screen.ratio).abs() < 0.01,
            "the page's devicePixelRatio is the screen's: {canvas}; {at}"
        );
        ensure!(
            (number(0) - number(1) * ratio).abs() <= ratio + 1.0
                && (number(2) - number(3) * ratio).abs() <= ratio + 1.0,
            "the canvas is drawn at the screen's ratio: {canvas}; {at}"
        );
        let name = format!("screen-{}-{}-{state}", self.screen.name, self.how);
        let shot = self.browser.screenshot(&name).await?;
        ensure!(!shot.is_blank(), "{name}: the page is drawn");
        Ok(layout)
    }

    /// Opens the top bar's menu `name`, through the folded menu on a small
    /// screen, and returns the open menus.
    async fn open_menu(&self, name: &str) -> anyhow::Result<Vec<Value>> {
        let layout = self.layout().await?;
        let bar = layout["topBar"].as_array().context("topBar")?;
        let find = |commands: &[Value], name: &str| {
            commands
                .iter()
                .find(|c| c["name"] == name)
                .map(|c| Rect::of(&c["rect"]))
        };
        if let Some(button) = find(bar, name) {
            self.press(button?.centre()).await?;
        } else {
            let fold = find(bar, "Menu").with_context(|| format!("no {name} or Menu: {layout}"))?;
            self.press(fold?.centre()).await?;
            self.menu_opens("Menu").await?;
            let layout = self.layout().await?;
            let menu = menu(&layout, "Menu")?;
            let commands = menu["commands"].as_array().context("commands")?;
            let window = Rect::of(&layout["window"])?;
            for command in commands {
                ensure!(
                    Rect::of(&command["rect"])?.inside(window),
                    "every folded command is on screen: {command}; {layout}"
                );
            }
            let button = find(commands, name).with_context(|| format!("{name} in {menu}"))?;
            self.press(button?.centre()).await?;
        }
        self.menu_opens(name).await
    }

    /// Waits for the menu `name` to open (a frame at a high ratio under a
    /// software renderer takes a while) and returns the open menus.
    async fn menu_opens(&self, name: &str) -> anyhow::Result<Vec<Value>> {
        let mut layout = self.layout().await?;
        for _ in 0..50 {
            if menu(&layout, name).is_ok() {
                break;
            }
            tokio::time::sleep(Duration::from_millis(200)).await;
            layout = self.layout().await?;
        }
        menu(&layout, name)?;
        Ok(layout["menus"].as_array().cloned().unwrap_or_default())
    }

    /// Scrolls the menu `name` with the wheel (or a finger) until its last
    /// entry is in sight, nearly a menu's height at a time, as a reader
    /// pages down: each turn is a scroll animation and two frames, over a
    /// second at a high ratio under a software renderer.
    async fn reach_last_entry(&self, name: &str) -> anyhow::Result<()> {
        let mut pointer = None;
        for _ in 0..40 {
            let layout = self.layout().await?;
            let open = menu(&layout, name)?;
            let window = Rect::of(&layout["window"])?;
            let rect = Rect::of(&open["rect"])?;
            ensure!(
                rect.inside(window),
                "the {name} menu is on screen: {layout}"
            );
            if open["lastEntryVisible"] == true {
                return Ok(());
            }
            let (x, y) = rect.centre();
            let page = rect.h * 0.9;
            if self.screen.touch {
                // A thumb pushes the list up: each swipe is a dozen frames,
                // slow at a phone's ratio.
                self.browser.swipe(x, rect.y + rect.h * 0.95, -page).await?;
                continue;
            }
            // The pointer moves over the menu once; a move per turn cost
            // a frame each.
            if pointer != Some((x, y)) {
                self.browser
                    .cdp(
                        "Input.dispatchMouseEvent",
                        serde_json::json!({ "type": "mouseMoved", "x": x, "y": y }),
                    )
                    .await?;
                pointer = Some((x, y));
            }
            self.browser
                .cdp(
                    "Input.dispatchMouseEvent",
                    serde_json::json!({ "type": "mouseWheel", "x": x, "y": y,
                                        "deltaX": 0, "deltaY": page }),
                )
                .await?;
        }
        bail!("the {name} menu's last entry could not be scrolled into sight")
    }

    async fn run(&self, call: &str) -> anyhow::Result<Value> {
        self.browser
            .eval_async(&format!("window.edgewise.{call}"))
            .await
    }

    /// Every state, from a fresh page.
    async fn every_state(&self) -> anyhow::Result<()> {
        let start = std::time::Instant::now();
        let result = self.every_state_inner().await;
        eprintln!(
            "{} ({}): {:.1} s",
            self.screen.name,
            self.how,
            start.elapsed().as_secs_f64()
        );
        result
    }

    async fn every_state_inner(&self) -> anyhow::Result<()> {
        self.browser.clear_site_data().await?;
        self.browser.open("").await?;
        self.browser
            .wait_for("window.edgewise.state().layout.overlays.length > 0", WAIT)
            .await?;
        self.check("welcome").await?;

        // The run the welcome card's third hint asks for, card still open.
        self.run("run('vertexAdjacentEdge', {v: 0})").await?;
        self.run("step(1)").await?;
        let layout = self.check("first-step").await?;
        ensure!(
            layout["stepControls"].is_object(),
            "{}: a run shows its step controls: {layout}",
            self.screen.name
        );
        ensure!(
            layout["overlays"].as_array().is_some_and(|o| !o.is_empty()),
            "the welcome card is still open: {layout}"
        );

        self.run(&format!("ask({})", serde_json::to_string(QUESTIONS)?))
            .await?;
        self.run("goto(0)").await?;
        let question = self.browser.state().await?;
        ensure!(
            question["trace"]["question"].is_object(),
            "a question waits at step 0: {question}"
        );
        self.check("question").await?;

        self.run("closeAlgorithm()").await?;
        self.run("select('edge', 0)").await?;
        self.browser.press_key("e", 0).await?;
        self.browser
            .wait_for("window.edgewise.state().editMenu", WAIT)
            .await?;
        let layout = self.check("edit-menu").await?;
        let edit = menu(&layout, "Edit")?;
        ensure!(
            Rect::of(&edit["rect"])?.inside(Rect::of(&layout["window"])?),
            "the edit menu is on screen: {layout}"
        );
        self.browser.press_key("Escape", 0).await?;

        // Before the large run: a tap spans two frames, and under a software
        // renderer a large page's frame can outlast egui's longest click.
        self.open_menu("Algorithm").await?;
        self.check("algorithm-menu").await?;
        self.reach_last_entry("Algorithm").await?;
        self.browser
            .screenshot(&format!(
                "screen-{}-{}-algorithm-menu-scrolled",
                self.screen.name, self.how
            ))
            .await?;
        self.browser.press_key("Escape", 0).await?;

        self.run("loadSample('tetrahedron', { structure: 'half' })")
            .await?;
        self.run("run('loopSubdivide', {f: 0})").await?;
        self.run("goto(1000000)").await?;
        let layout = self.check("loop-subdivide-last-step").await?;
        if let Ok(panel) = Rect::of(&layout["panels"]["algorithm"]) {
            let window = Rect::of(&layout["window"])?;
            ensure!(
                panel.w <= window.w / 2.0 + 1.0 || self.screen.width < 700,
                "the algorithm panel takes at most half the width: {layout}"
            );
        }

        self.browser.assert_no_console_errors().await
    }
}

/// The screens to check: all of them, or those whose names contain
/// `EDGEWISE_SCREENS` (`phone`, `@2`) while working on one.
fn screens() -> impl Iterator<Item = Screen> {
    let only = std::env::var("EDGEWISE_SCREENS").unwrap_or_default();
    SCREENS.into_iter().filter(move |s| s.name.contains(&only))
}

fn menu<'a>(layout: &'a Value, name: &str) -> anyhow::Result<&'a Value> {
    layout["menus"]
        .as_array()
        .into_iter()
        .flatten()
        .find(|m| m["name"] == name)
        .with_context(|| format!("the {name} menu is open: {layout}"))
}

/// The windows of desktop browsers. A touch screen's browser shows a mobile
/// viewport, which the test below makes; a desktop window at a phone's size
/// and ratio, touched, is no screen anyone has (it was 102 s of the suite).
#[tokio::test]
async fn every_window_at_its_true_ratio() -> anyhow::Result<()> {
    let _turn = ONE_HEAVY_PAGE_AT_A_TIME.lock().await;
    for screen in screens().filter(|screen| !screen.touch) {
        // At ratio 1, the shared Chromium, sized to the screen.
        let ratio = (screen.ratio > 1.0).then_some(screen.ratio);
        let browser = Browser::launch_with(LaunchOptions {
            window_size: (screen.width, screen.height),
            device_scale_factor: ratio,
            ..LaunchOptions::default()
        })
        .await?;
        browser.goto("").await?;
        browser.fit_viewport(screen.width, screen.height).await?;
        let seen = Seen {
            browser: &browser,
            screen,
            how: "true",
        };
        seen.every_state()
            .await
            .with_context(|| format!("{} at its true ratio", screen.name))?;
        browser.close().await?;
    }
    Ok(())
}

/// The touch screens as `DevTools`' device mode makes them: a mobile
/// viewport at the device's ratio, touched. A desktop under emulation is the
/// window of the test above, page for page, so it is not run twice.
#[tokio::test]
async fn every_touch_screen_under_device_emulation() -> anyhow::Result<()> {
    let _turn = ONE_HEAVY_PAGE_AT_A_TIME.lock().await;
    let browser = Browser::launch().await?;
    for screen in screens().filter(|screen| screen.touch) {
        browser.emulate(&screen).await?;
        let seen = Seen {
            browser: &browser,
            screen,
            how: "emulated",
        };
        seen.every_state()
            .await
            .with_context(|| format!("{} under emulation", screen.name))?;
    }
    browser.close().await
}
