//! Practice in a real Chromium: a walk clicked with the pointer and by
//! `select`, a wrong click named; a flip exercise done cell by cell through
//! `window.edgewise` passes; one cell short, Check names the difference;
//! the model answer scores 0; the second attempt draws a fresh instance;
//! and a course page on another origin, driving the view with
//! `edgewise:call`, hears its `edgewise:score`.

use std::time::Duration;

use anyhow::Context as _;
use edgewise_browser_tests::{Browser, student_writes};
use edgewise_core::formats;
use edgewise_core::mesh::{Mesh, Structure};
use serde_json::{Value, json};

const EXERCISE: &str = "flip-edge-half-edge";
const SEED: u64 = 3;
const START_TIMEOUT: Duration = Duration::from_secs(240);

/// The open mesh's tables, as the page exports them.
async fn tables(browser: &Browser) -> anyhow::Result<Mesh> {
    let exported = browser
        .eval_async("window.edgewise.exportMesh('htb')")
        .await?;
    let text = exported["text"].as_str().context("exported text")?;
    Ok(
        formats::load(text.as_bytes(), "answer.htb", Structure::HalfEdge)
            .map_err(|err| anyhow::anyhow!(err.render("answer.htb")))?
            .mesh,
    )
}

async fn call(browser: &Browser, method: &str, args: &Value) -> anyhow::Result<Value> {
    browser
        .eval_async(&format!("window.edgewise.{method}(...{args})"))
        .await
}

async fn exercise(browser: &Browser) -> anyhow::Result<Value> {
    Ok(browser.state().await?["exercise"].clone())
}

/// The model answer's tables and the instance's, by the page itself.
async fn start_and_target(browser: &Browser) -> anyhow::Result<(Mesh, Mesh)> {
    let start = format!("window.edgewise.startExercise('{EXERCISE}', {{ seed: {SEED} }})");
    browser.eval_async(&start).await?;
    let before = tables(browser).await?;
    // The model answer is the library's traced operation: its last
    // step's tables are the result.
    browser
        .eval_async("window.edgewise.showModelAnswer()")
        .await?;
    browser.eval_async("window.edgewise.goto(100000)").await?;
    let target = tables(browser).await?;
    browser.eval_async(&start).await?;
    Ok((before, target))
}

#[tokio::test]
async fn a_flip_done_cell_by_cell_passes_and_one_cell_short_is_named() -> anyhow::Result<()> {
    let browser = Browser::launch().await?;
    browser.set_script_timeout(Duration::from_secs(120)).await?;
    browser.open("").await?;
    let (before, target) = start_and_target(&browser).await?;
    let state = exercise(&browser).await?;
    assert_eq!(state["name"], EXERCISE);
    assert_eq!(state["seed"], SEED);
    assert_eq!(state["attempt"], 1);
    assert_eq!(state["passed"], Value::Null);

    let mut calls = student_writes(&before, &target);
    assert!(calls.len() >= 6, "a flip writes several cells: {calls:?}");
    let last = calls.pop().context("a last write")?;
    for (method, args) in &calls {
        call(&browser, method, args).await?;
    }
    browser
        .eval_async("window.edgewise.submitExercise()")
        .await?;
    let state = exercise(&browser).await?;
    assert_eq!(state["passed"], false, "{state}");
    let feedback = state["feedback"].as_str().unwrap_or_default();
    assert!(
        feedback.contains("flip-edge") || feedback.contains("do not hold together"),
        "{feedback}"
    );
    browser.screenshot("practice-flip-one-cell-short").await?;

    call(&browser, last.0, &last.1).await?;
    browser
        .eval_async("window.edgewise.submitExercise()")
        .await?;
    let state = exercise(&browser).await?;
    assert_eq!(state["passed"], true, "{state}");
    assert_eq!(state["score"], 1);
    assert_eq!(state["step"], calls.len() + 1);
    browser.screenshot("practice-flip-passed").await?;
    browser.assert_no_console_errors().await?;
    browser.close().await
}

#[tokio::test]
async fn the_model_answer_scores_zero_and_the_next_attempt_is_a_fresh_instance()
-> anyhow::Result<()> {
    let browser = Browser::launch().await?;
    browser.set_script_timeout(Duration::from_secs(120)).await?;
    browser.open("").await?;
    let start = format!("window.edgewise.startExercise('{EXERCISE}', {{ seed: {SEED} }})");
    browser.eval_async(&start).await?;
    let task = exercise(&browser).await?["task"].clone();
    browser
        .eval_async("window.edgewise.showModelAnswer()")
        .await?;
    let state = exercise(&browser).await?;
    assert_eq!(state["modelAnswerShown"], true);
    assert_eq!(state["score"], 0);
    assert_eq!(state["finished"], true);
    browser.screenshot("practice-model-answer").await?;
    let refused = browser.refusal("window.edgewise.submitExercise()").await?;
    assert!(
        refused
            .as_str()
            .is_some_and(|r| r.contains("attempt is over")),
        "{refused}"
    );

    browser.eval_async("window.edgewise.newInstance()").await?;
    let second = exercise(&browser).await?;
    assert_eq!(second["attempt"], 2);
    assert_ne!(second["seed"], SEED);
    assert_ne!(second["task"], task, "{second}");
    assert_eq!(second["finished"], false);
    browser.assert_no_console_errors().await?;
    browser.close().await
}

#[tokio::test]
async fn a_course_page_on_another_origin_hears_the_score() -> anyhow::Result<()> {
    let hosts = std::env::var("EDGEWISE_HOSTS_URL")
        .context("EDGEWISE_HOSTS_URL is not set: run these tests with `cargo xtask test`")?;
    let browser = Browser::launch().await?;
    browser.set_script_timeout(START_TIMEOUT).await?;
    // The writes, worked out in the app's own page first.
    browser.open("").await?;
    let (before, target) = start_and_target(&browser).await?;
    let calls = student_writes(&before, &target);
    let app_origin = url::Url::parse(browser.base_url())?
        .origin()
        .ascii_serialization();

    browser
        .goto_url(&format!("{hosts}course-page.html"))
        .await?;
    browser
        .eval(&format!(
            "document.body.innerHTML = ''; window.__heard = []; \
             window.addEventListener('message', (e) => {{ \
               if (e.data && typeof e.data.type === 'string') \
                 window.__heard.push({{ origin: e.origin, data: e.data }}); }}); \
             const frame = document.createElement('iframe'); frame.id = 'view'; \
             frame.width = 900; frame.height = 640; \
             frame.src = '{}index.html?embed=1&exercise={EXERCISE}&seed={SEED}'; \
             document.body.append(frame); return location.origin;",
            browser.base_url()
        ))
        .await?;
    browser
        .wait_for(
            "window.__heard.some((m) => m.data.type === 'edgewise:ready')",
            START_TIMEOUT,
        )
        .await?;
    let mut id = 0;
    for (method, args) in calls
        .iter()
        .map(|(m, a)| (*m, a.clone()))
        .chain([("submitExercise", json!([]))])
    {
        id += 1;
        browser
            .eval(&format!(
                "document.getElementById('view').contentWindow.postMessage( \
                   {{ type: 'edgewise:call', id: {id}, method: '{method}', args: {args} }}, '*'); \
                 return null;"
            ))
            .await?;
        browser
            .wait_for(
                &format!(
                    "window.__heard.some((m) => m.data.type === 'edgewise:reply' && m.data.id === {id})"
                ),
                Duration::from_secs(60),
            )
            .await?;
    }
    browser
        .wait_for(
            "window.__heard.some((m) => m.data.type === 'edgewise:score')",
            Duration::from_secs(60),
        )
        .await?;
    let score = browser
        .eval("return window.__heard.find((m) => m.data.type === 'edgewise:score');")
        .await?;
    assert_eq!(score["origin"], app_origin.as_str());
    let data = &score["data"];
    assert_eq!(data["exercise"], EXERCISE);
    assert_eq!(data["seed"], SEED);
    assert_eq!(data["passed"], true, "{data}");
    assert_eq!(data["score"], 1);
    assert_eq!(data["maxScore"], 1);
    assert_eq!(
        data["statement"]["verb"]["id"],
        "http://adlnet.gov/expapi/verbs/passed"
    );
    assert_eq!(data["statement"]["result"]["score"]["scaled"], 1.0);
    let replies = browser
        .eval("return window.__heard.filter((m) => m.data.type === 'edgewise:reply' && !m.data.ok).map((m) => m.data);")
        .await?;
    assert_eq!(replies, json!([]), "every call was answered ok");
    browser
        .screenshot("practice-score-on-a-course-page")
        .await?;
    browser.close().await
}

/// The journal's Table 2 walk from vertex 1 (the edges around B): the
/// first edge clicked with the pointer in the 3D view, the next by
/// `select`; then a second go with a wrong click, named and corrected.
#[tokio::test]
async fn a_walk_is_clicked_and_a_wrong_click_is_named() -> anyhow::Result<()> {
    let browser = Browser::launch().await?;
    browser.set_script_timeout(Duration::from_secs(120)).await?;
    browser.open("").await?;
    let start = "window.edgewise.startExercise('walk-vertex-edges-winged-edge', { seed: 0 })";
    browser.eval_async(start).await?;
    let state = exercise(&browser).await?;
    assert_eq!(state["kind"], "walk");
    assert_eq!(state["total"], 3);
    browser.frames(2).await?;
    let (x, y) = browser
        .element_at("edge", 1)
        .await?
        .context("edge 1 is in view")?;
    browser.click_at(x, y, "left").await?;
    browser
        .wait_for(
            "window.edgewise.state().exercise.step === 1",
            Duration::from_secs(30),
        )
        .await?;
    let state = exercise(&browser).await?;
    assert_eq!(state["correct"], 1, "{state}");
    for id in [3, 2] {
        browser
            .eval_async(&format!("window.edgewise.select('edge', {id})"))
            .await?;
    }
    let state = exercise(&browser).await?;
    assert_eq!(state["passed"], true, "{state}");
    assert_eq!(state["score"], 3);
    assert_eq!(
        state["found"],
        json!([
            { "kind": "edge", "id": 1 }, { "kind": "edge", "id": 3 }, { "kind": "edge", "id": 2 }
        ])
    );

    browser.eval_async(start).await?;
    browser
        .eval_async("window.edgewise.select('edge', 2)")
        .await?;
    let state = exercise(&browser).await?;
    assert_eq!(state["correct"], 0);
    let feedback = state["feedback"].as_str().unwrap_or_default();
    assert!(
        feedback.contains("Not edge 2: the walk marks edge 1 next"),
        "{feedback}"
    );
    browser.screenshot("practice-walk-wrong-click").await?;
    browser.assert_no_console_errors().await?;
    browser.close().await
}
