//! Edgewise views in the pages lecturers really make, built with the real
//! tools: a reveal.js deck and `MkDocs` notes from `web/hosts/`, which
//! `cargo xtask hosts` installs from npm and `PyPI` and serves at
//! `EDGEWISE_HOSTS_URL`, another origin than the app's, as a course site
//! is. The frames cannot be scripted from the page (another origin), so
//! the tests watch what the frames post to the page, drive them with real
//! pointer and key input, and look at screenshots.

use std::time::Duration;

use anyhow::{Context as _, bail};
use edgewise_browser_tests::{Browser, LaunchOptions, ONE_HEAVY_PAGE_AT_A_TIME, Screenshot};
use serde_json::Value;

/// A view starts in a fresh frame, rendered on the CPU: on two cores
/// that can take minutes.
const START_TIMEOUT: Duration = Duration::from_secs(240);

/// Where `cargo xtask hosts` (or `cargo xtask test`) serves the hosts.
fn hosts_url() -> anyhow::Result<String> {
    std::env::var("EDGEWISE_HOSTS_URL").context(
        "EDGEWISE_HOSTS_URL is not set: run these tests with `cargo xtask test` \
         (or `cargo xtask browser-test`), or serve the hosts with `cargo xtask hosts`",
    )
}

/// The origin of the app the browser was launched on, as a frame's
/// messages carry it.
fn app_origin(browser: &Browser) -> anyhow::Result<String> {
    Ok(url::Url::parse(browser.base_url())?
        .origin()
        .ascii_serialization())
}

/// Statements that keep every `edgewise:` message the page hears, in
/// `window.__heard`, with what the tests read from it.
const LISTEN: &str = "
  window.__heard = [];
  window.addEventListener('message', (event) => {
    const m = event.data;
    if (!m || typeof m.type !== 'string' || !m.type.startsWith('edgewise:')) return;
    window.__heard.push({
      type: m.type, origin: event.origin,
      step: m.trace ? m.trace.step : null,
      question: m.trace && m.trace.question ? m.trace.question.prompt : null,
      height: typeof m.height === 'number' ? m.height : null,
      correct: typeof m.correct === 'boolean' ? m.correct : null,
      given: m.given ?? null, expected: m.expected ?? null,
    });
  });
  return null;";

/// A JS expression: how many messages of `kind` the page heard from
/// `origin`.
fn heard(kind: &str, origin: &str) -> String {
    format!(
        "window.__heard.filter((m) => m.type === 'edgewise:{kind}' && m.origin === '{origin}').length"
    )
}

/// How many messages the page has heard so far.
async fn heard_count(browser: &Browser) -> anyhow::Result<u64> {
    Ok(browser
        .eval("return window.__heard.length;")
        .await?
        .as_u64()
        .unwrap_or_default())
}

/// A JS expression: whether a `stepchange` to `step` was heard after the
/// first `since` messages.
fn stepped_to(step: u32, since: u64) -> String {
    format!(
        "window.__heard.slice({since}).some((m) => m.type === 'edgewise:stepchange' && m.step === {step})"
    )
}

/// What has the page's focus: a tag name, with the id if any.
const ACTIVE: &str = "const a = document.activeElement; \
                      return a ? a.tagName + (a.id ? '#' + a.id : '') : null;";

/// The rectangle of the first iframe, `[left, top, width, height]` in CSS
/// pixels of the page.
async fn frame_rect(browser: &Browser) -> anyhow::Result<[f64; 4]> {
    let rect = browser
        .eval(
            "const r = document.querySelector('iframe').getBoundingClientRect(); \
             return [r.left, r.top, r.width, r.height];",
        )
        .await?;
    let n = |i: usize| rect[i].as_f64().unwrap_or_default();
    Ok([n(0), n(1), n(2), n(3)])
}

/// The distinct colours of `shot` inside `rect` (CSS pixels at ratio 1),
/// capped at `cap`: the shaded 3D view has well over a thousand, a blank
/// frame one, and a line of text a few hundred.
fn colours_in(shot: &Screenshot, rect: [f64; 4], cap: usize) -> usize {
    let mut seen = std::collections::HashSet::new();
    let clamp = |v: f64, max: u32| (v.max(0.0) as u32).min(max);
    let (x0, y0) = (clamp(rect[0], shot.width), clamp(rect[1], shot.height));
    let (x1, y1) = (
        clamp(rect[0] + rect[2], shot.width),
        clamp(rect[1] + rect[3], shot.height),
    );
    for y in y0..y1 {
        for x in x0..x1 {
            seen.insert(shot.pixel(x, y));
            if seen.len() >= cap {
                return cap;
            }
        }
    }
    seen.len()
}

/// How many colours show that the view is drawn (see [`colours_in`]).
const DRAWN: usize = 500;

/// Waits until the page has heard `count` `ready` messages from the app's
/// frame; if it does not, says what the page heard and logged.
async fn wait_for_ready(browser: &Browser, origin: &str, count: usize) -> anyhow::Result<()> {
    let waited = browser
        .wait_for(
            &format!("{} >= {count}", heard("ready", origin)),
            START_TIMEOUT,
        )
        .await;
    if let Err(err) = waited {
        let heard = browser.eval("return window.__heard;").await?;
        let frame = browser
            .eval_async(
                "new Promise((resolve) => { \
                   const f = document.querySelector('iframe'); \
                   const r = f ? f.getBoundingClientRect() : null; \
                   const seen = { src: f && f.src, loading: f && f.loading, top: r && r.top, \
                                  height: r && r.height, visibility: document.visibilityState, \
                                  readyState: document.readyState, frames: false }; \
                   requestAnimationFrame(() => { seen.frames = true; }); \
                   setTimeout(() => resolve(seen), 2000); })",
            )
            .await?;
        // What the app shows inside the frame (WebDriver may look in).
        let inside = browser
            .eval_in_frame(
                0,
                "return { started: !!window.edgewise, readyState: document.readyState, \
                   loading: document.getElementById('edgewise_loading')?.textContent ?? null, \
                   error: document.getElementById('edgewise_error')?.textContent ?? null, \
                   worker: !!(navigator.serviceWorker && navigator.serviceWorker.controller) };",
            )
            .await
            .unwrap_or_else(|err| Value::String(format!("{err:#}")));
        let console = browser.console_errors().await.unwrap_or_default();
        bail!(
            "the view did not start: {err}\nthe page's frame: {frame}\ninside it: {inside}\n\
             heard: {heard}\nconsole: {console:#?}"
        );
    }
    // A view that took the focus as it started has it once it settles.
    view_settled(browser).await
}

/// Waits until the view in the page's first frame has settled: it asks for
/// no more frames, so what it does on its own (take the focus, ask for a
/// height) it has done, and its messages have reached the page. Asked
/// through the embed protocol, as a page on another origin asks.
async fn view_settled(browser: &Browser) -> anyhow::Result<()> {
    let reply = browser
        .eval_async(
            "new Promise((resolve) => { \
               const id = 'settled-' + Math.random(); \
               const hear = (event) => { \
                 const m = event.data; \
                 if (!m || m.type !== 'edgewise:reply' || m.id !== id) return; \
                 window.removeEventListener('message', hear); \
                 resolve(m); \
               }; \
               window.addEventListener('message', hear); \
               document.querySelector('iframe').contentWindow.postMessage( \
                 { type: 'edgewise:call', id, method: 'settled', args: [] }, '*'); \
             })",
        )
        .await?;
    anyhow::ensure!(reply["ok"] == true, "the view did not settle: {reply}");
    Ok(())
}

/// reveal.js: Space, `PageDown` and → move the deck past the Edgewise slide
/// until the reader clicks the view; then → steps the view and the deck
/// stays; Escape hands the keys back to the deck.
#[tokio::test]
async fn a_reveal_deck_keeps_its_keys_until_the_view_is_clicked() -> anyhow::Result<()> {
    let hosts = hosts_url()?;
    let _turn = ONE_HEAVY_PAGE_AT_A_TIME.lock().await;
    let browser = Browser::launch().await?;
    let origin = app_origin(&browser)?;
    let deck = format!("{hosts}reveal/#/1");
    browser.goto_url(&deck).await?;
    browser
        .wait_for(
            "window.Reveal && Reveal.isReady && Reveal.isReady()",
            Duration::from_secs(30),
        )
        .await
        .with_context(|| format!("reveal.js did not start at {deck}"))?;
    let slide = "return Reveal.getIndices().h;";
    assert_eq!(browser.eval(slide).await?, 1, "the deck opened elsewhere");
    // The Edgewise slide's frame, as reveal.js keeps it until it is shown:
    // the app's address (another origin) in data-src, nothing loaded.
    let frame = browser
        .eval(
            "const f = document.querySelector('iframe'); \
             return { src: f.getAttribute('src'), dataSrc: f.getAttribute('data-src') };",
        )
        .await?;
    assert_eq!(frame["src"], Value::Null, "the frame loaded early: {frame}");
    let data_src = frame["dataSrc"].as_str().unwrap_or_default();
    assert!(
        data_src.starts_with(&format!("{}?embed=1", browser.base_url())),
        "the deck does not embed the app served at {}: {frame}",
        browser.base_url()
    );
    assert_ne!(
        url::Url::parse(&hosts)?.origin().ascii_serialization(),
        origin,
        "the deck must be served from another origin than the app"
    );
    browser.eval(LISTEN).await?;

    // → reaches the Edgewise slide, whose frame loads and starts the view.
    browser.press_key("ArrowRight", 0).await?;
    browser
        .wait_for("Reveal.getIndices().h === 2", Duration::from_secs(10))
        .await?;
    let mut starts = 1;
    wait_for_ready(&browser, &origin, starts).await?;
    let shot = browser.screenshot("host-reveal-view").await?;
    let rect = frame_rect(&browser).await?;
    let colours = colours_in(&shot, rect, DRAWN);
    assert!(
        colours >= DRAWN,
        "the view is not drawn in the slide ({colours} colours in {rect:?}): {}",
        shot.path.display()
    );

    // Space, PageDown and → each move the deck on: the view has not
    // taken the keys. ← comes back to the slide, whose frame reloads.
    for key in [" ", "PageDown", "ArrowRight"] {
        assert_ne!(
            browser.eval(ACTIVE).await?,
            "IFRAME",
            "the view took the focus on its own"
        );
        browser.press_key(key, 0).await?;
        let moved = browser
            .wait_for("Reveal.getIndices().h === 3", Duration::from_secs(10))
            .await;
        if moved.is_err() {
            let shot = browser.screenshot("host-reveal-key-kept").await?;
            bail!(
                "{key:?} did not move the deck past the Edgewise slide (slide {}, focus {}): {}",
                browser.eval(slide).await?,
                browser.eval(ACTIVE).await?,
                shot.path.display()
            );
        }
        browser.press_key("ArrowLeft", 0).await?;
        browser
            .wait_for("Reveal.getIndices().h === 2", Duration::from_secs(10))
            .await?;
        starts += 1;
        wait_for_ready(&browser, &origin, starts).await?;
    }
    // A click on an empty part of the view gives it the keys: → steps the
    // view, and the deck stays on the slide.
    let rect = frame_rect(&browser).await?;
    let before_click = heard_count(&browser).await?;
    browser
        .click_at(rect[0] + rect[2] * 0.1, rect[1] + rect[3] * 0.15, "left")
        .await?;
    assert_eq!(
        browser.eval(ACTIVE).await?,
        "IFRAME",
        "a click on the view did not give it the keys"
    );
    browser.press_key("ArrowRight", 0).await?;
    let stepped = browser
        .wait_for(&stepped_to(1, before_click), Duration::from_secs(30))
        .await;
    let shot = browser.screenshot("host-reveal-keys").await?;
    stepped.with_context(|| format!("→ did not step the clicked view: {}", shot.path.display()))?;
    assert_eq!(
        browser.eval(slide).await?,
        2,
        "→ in the view moved the deck"
    );

    // Escape hands the keys back: the deck's → moves the slide again, and
    // the deck did not take Escape for its own (the overview).
    browser.press_key("Escape", 0).await?;
    view_settled(&browser).await?;
    let shot = browser.screenshot("host-reveal-escape").await?;
    assert_eq!(
        browser.eval("return Reveal.isOverview();").await?,
        false,
        "Escape reached the deck: {}",
        shot.path.display()
    );
    assert_ne!(
        browser.eval(ACTIVE).await?,
        "IFRAME",
        "Escape left the keys with the view: {}",
        shot.path.display()
    );
    let before_escape = heard_count(&browser).await?;
    browser.press_key("ArrowRight", 0).await?;
    browser
        .wait_for("Reveal.getIndices().h === 3", Duration::from_secs(10))
        .await
        .context("→ after Escape did not move the deck")?;
    assert_eq!(
        browser
            .eval(&format!("return {};", stepped_to(2, before_escape)))
            .await?,
        false,
        "→ after Escape stepped the view"
    );
    browser.close().await
}

/// The buttons of the question card: each run of the buttons' fill in
/// the first row of buttons under the step controls, as `[x, y]` centres
/// in CSS pixels of the page, left to right. `controls_bottom` is where the
/// step controls end, in the page.
fn card_buttons(shot: &Screenshot, rect: [f64; 4], controls_bottom: f64) -> Vec<[f64; 2]> {
    // egui's light theme fills a button with this grey.
    const FILL: [u8; 3] = [230, 230, 230];
    let x0 = rect[0].max(0.0) as u32;
    let x1 = ((rect[0] + rect[2]) as u32).min(shot.width);
    let y1 = ((rect[1] + rect[3]) as u32).min(shot.height);
    // The first row, from the top, with a run of fill as wide as a button.
    let wide_run = |y: u32| {
        let mut run = 0;
        (x0..x1).any(|x| {
            run = if shot.pixel(x, y) == FILL { run + 1 } else { 0 };
            run >= 20
        })
    };
    let Some(top) = (controls_bottom.max(0.0) as u32..y1).find(|&y| wide_run(y)) else {
        return Vec::new();
    };
    let bottom = (top..y1).find(|&y| !wide_run(y)).unwrap_or(y1);
    // Columns with fill anywhere in that band, joined across small gaps
    // (the label's letters).
    let filled = |x: u32| (top..bottom).any(|y| shot.pixel(x, y) == FILL);
    let mut buttons: Vec<[u32; 2]> = Vec::new();
    for x in (x0..x1).filter(|&x| filled(x)) {
        match buttons.last_mut() {
            Some(last) if x - last[1] <= 4 => last[1] = x,
            _ => buttons.push([x, x]),
        }
    }
    let middle = f64::from(top + bottom) / 2.0;
    buttons
        .into_iter()
        .filter(|[from, to]| to - from >= 20)
        .map(|[from, to]| [f64::from(from + to) / 2.0, middle])
        .collect()
}

/// `MkDocs`: a view with a question set in built notes keeps its frame's
/// height while the student answers, by clicking an edge, clicking
/// False, and typing an edge, and steps on between the questions.
#[tokio::test]
async fn mkdocs_notes_keep_a_question_views_height_while_it_is_answered() -> anyhow::Result<()> {
    let hosts = hosts_url()?;
    let _turn = ONE_HEAVY_PAGE_AT_A_TIME.lock().await;
    // Tall enough for the whole frame: its question card is at the bottom.
    let browser = Browser::launch_with(LaunchOptions {
        window_size: (1280, 1100),
        ..LaunchOptions::default()
    })
    .await?;
    browser.set_script_timeout(START_TIMEOUT).await?;
    let origin = app_origin(&browser)?;
    let notes = format!("{hosts}mkdocs/");
    browser.goto_url(&notes).await?;
    let page = browser
        .eval(
            "const f = document.querySelector('[data-edgewise] iframe'); \
             return { title: document.querySelector('h1')?.textContent, src: f?.src ?? null };",
        )
        .await?;
    assert_eq!(
        page["title"], "Walking around a vertex",
        "not the notes: {page}"
    );
    let src = page["src"].as_str().unwrap_or_default();
    assert!(
        src.starts_with(&format!("{}?", browser.base_url())) && src.contains("#ask="),
        "edgewise-embed.js did not make a frame of the app with questions: {page}"
    );
    browser.eval(LISTEN).await?;
    // The view loads lazily: the reader scrolls to it.
    browser
        .eval("document.querySelector('iframe').scrollIntoView({block: 'center'}); return null;")
        .await?;
    wait_for_ready(&browser, &origin, 1).await?;
    let view = "document.querySelector('[data-edgewise]').edgewise";

    // The view asks for its height once; the page gives it.
    browser
        .wait_for(&heard("resize", &origin), Duration::from_secs(60))
        .await?;
    view_settled(&browser).await?;
    let asked = browser
        .eval(
            "return window.__heard.filter((m) => m.type === 'edgewise:resize').map((m) => m.height);",
        )
        .await?;
    let height = || async {
        browser
            .eval("return document.querySelector('iframe').getBoundingClientRect().height;")
            .await
    };
    // The whole frame in sight, just under the theme's bar: the card is
    // at its bottom. At once: the theme scrolls smoothly, and a frame
    // measured mid-scroll sends the clicks below (an unoptimised screenshot
    // decode once hid this by taking longer than the scroll).
    browser
        .eval(
            "const r = document.querySelector('iframe').getBoundingClientRect(); \
             window.scrollBy({ top: r.top - 60, behavior: 'instant' }); return null;",
        )
        .await?;
    let first = height().await?;
    assert_eq!(
        asked.as_array().and_then(|a| a.last()),
        Some(&first),
        "the frame is not as tall as the view asked: {asked}"
    );
    let resizes = browser
        .eval(&format!("return {};", heard("resize", &origin)))
        .await?;
    // After each answer or step: the frame as tall as at first, and no
    // other height asked for in between.
    let same_height = |moment: &'static str| {
        let resizes = resizes.clone();
        let first = first.clone();
        let browser = &browser;
        async move {
            view_settled(browser).await?;
            let now = height().await?;
            let asked = browser
                .eval(&format!(
                    "return window.__heard.filter((m) => m.type === 'edgewise:resize').slice({resizes}).map((m) => m.height);"
                ))
                .await?;
            if now != first
                || asked
                    .as_array()
                    .is_some_and(|a| a.iter().any(|h| *h != first))
            {
                let shot = browser.screenshot(&format!("host-mkdocs-{moment}")).await?;
                bail!(
                    "{moment}: the frame was {first} px tall and is {now} px; the view asked for {asked}: {}",
                    shot.path.display()
                );
            }
            anyhow::Ok(())
        }
    };

    // Question 1, at step 0, asks for an edge: the student clicks it in
    // the view (where the view draws edge 1, asked through the embed
    // protocol, is where a student sees it).
    let question = "return window.__heard.filter((m) => m.type === 'edgewise:stepchange').pop()?.question ?? null;";
    assert_eq!(
        browser.eval(question).await?,
        "Which edge will e be after the lookup v.incidentEdge?"
    );
    // Steps the view with → from step `from` until it asks `prompt` (by
    // step `limit` at most), the height checked after each step.
    let step_until = |prompt: &'static str, from: u32, limit: u32| {
        let (browser, same_height) = (&browser, &same_height);
        async move {
            let mut steps = from;
            while browser.eval(question).await? != prompt {
                steps += 1;
                assert!(steps <= limit, "{prompt:?} was never asked");
                let before = heard_count(browser).await?;
                browser.press_key("ArrowRight", 0).await?;
                browser
                    .wait_for(&stepped_to(steps, before), Duration::from_secs(30))
                    .await
                    .with_context(|| format!("→ did not step the view to step {steps}"))?;
                same_height("stepped").await?;
            }
            anyhow::Ok(steps)
        }
    };
    let shot = browser.screenshot("host-mkdocs-question-1").await?;
    let rect = frame_rect(&browser).await?;
    let colours = colours_in(&shot, rect, DRAWN);
    assert!(
        colours >= DRAWN,
        "the view is not drawn in the notes ({colours} colours in {rect:?}): {}",
        shot.path.display()
    );
    let at = browser
        .eval_async(&format!("{view}.call('screenPosition', 'edge', 1)"))
        .await?;
    let (x, y) = (
        at[0].as_f64().context("edge 1 is not drawn")?,
        at[1].as_f64().context("edge 1 is not drawn")?,
    );
    let answered = |n: usize| format!("{} >= {n}", heard("answer", &origin));
    browser.click_at(rect[0] + x, rect[1] + y, "left").await?;
    browser
        .wait_for(&answered(1), Duration::from_secs(30))
        .await
        .context("a click on edge 1 did not answer question 1")?;
    let answer = last_answer(&browser).await?;
    assert_eq!(answer["given"], "Edge 1", "{answer}");
    assert_eq!(answer["correct"], true, "{answer}");
    same_height("answered-1").await?;
    browser.screenshot("host-mkdocs-answered-1").await?;

    // The click gave the view the keys: → steps to question 2, which
    // asks true or false.
    let steps = step_until("Is v the start vertex of e?", 0, 10).await?;
    let shot = browser.screenshot("host-mkdocs-question-2").await?;
    let controls = browser
        .eval_async(&format!(
            "{view}.call('state').then((s) => s.layout.stepControls)"
        ))
        .await?;
    let controls_bottom = rect[1]
        + controls["y"].as_f64().unwrap_or_default()
        + controls["h"].as_f64().unwrap_or_default();
    let buttons = card_buttons(&shot, rect, controls_bottom);
    let [_, [x, y]] = buttons[..] else {
        bail!(
            "the card under the step controls shows {} buttons, not True and False: {}",
            buttons.len(),
            shot.path.display()
        );
    };
    browser.click_at(x, y, "left").await?;
    browser
        .wait_for(&answered(2), Duration::from_secs(30))
        .await
        .with_context(|| format!("a click on False at ({x}, {y}) did not answer question 2"))?;
    let answer = last_answer(&browser).await?;
    assert_eq!(answer["given"], "Boolean false", "{answer}");
    assert_eq!(answer["correct"], true, "{answer}");
    same_height("answered-2").await?;
    browser.screenshot("host-mkdocs-answered-2").await?;

    // Question 3 asks for an edge again: the student types it, in the box
    // that `/` opens.
    let steps = step_until(
        "e does not start at v. Which edge is e's right successor?",
        steps,
        20,
    )
    .await?;
    // A moment between keys, as a student types: the box takes the keys
    // from the frame after `/` focused it.
    for key in ["/", "e", " ", "5", "Enter"] {
        browser.press_key(key, 0).await?;
        tokio::time::sleep(Duration::from_millis(200)).await;
    }
    let typed = browser
        .wait_for(&answered(3), Duration::from_secs(30))
        .await;
    let shot = browser.screenshot("host-mkdocs-answered-3").await?;
    if let Err(err) = typed {
        let heard = browser
            .eval("return window.__heard.filter((m) => m.type !== 'edgewise:resize');")
            .await?;
        bail!(
            "typing e 5 did not answer question 3: {err}\nheard: {heard}\n{}",
            shot.path.display()
        );
    }
    // A wrong answer, so that the card's longer verdict is seen too.
    let answer = last_answer(&browser).await?;
    assert_eq!(answer["given"], "Edge 5", "{answer}");
    assert_eq!(answer["expected"], "Edge 3", "{answer}");
    assert_eq!(answer["correct"], false, "{answer}");
    same_height("answered-3").await?;

    // On past the last question: the card stays, and so does the height.
    let before = heard_count(&browser).await?;
    browser.press_key("ArrowRight", 0).await?;
    browser
        .wait_for(&stepped_to(steps + 1, before), Duration::from_secs(30))
        .await?;
    same_height("after-the-questions").await?;
    browser.close().await
}

/// The last `edgewise:answer` the page heard.
async fn last_answer(browser: &Browser) -> anyhow::Result<Value> {
    browser
        .eval("return window.__heard.filter((m) => m.type === 'edgewise:answer').pop() ?? null;")
        .await
}
