//! SCORM packages in an LMS's frame (docs/lms.md). `cargo xtask hosts`
//! serves a page that installs scorm-again (the runtime LMSs embed, from
//! npm) as the API and keeps the learner's data across visits, and two
//! packages made by `edgewise package` of this build, unzipped beside it.
//! In each version a student passes a walk, fails a prediction, leaves a
//! do-it half done and closes the page; on return the package resumes the
//! same instance with the same writes, and the finished set passes. The
//! LMS's own records are read back from scorm-again.

use std::time::Duration;

use anyhow::Context as _;
use edgewise_browser_tests::{Browser, ONE_HEAVY_PAGE_AT_A_TIME, SCREENS, student_writes};
use edgewise_core::mesh::operations;
use edgewise_model::practice::{Exercise, Task, catalog};
use serde_json::{Value, json};

const START_TIMEOUT: Duration = Duration::from_secs(240);
const STEP_TIMEOUT: Duration = Duration::from_secs(60);

/// The launch page (in the LMS's frame) and the app (in the launch page's),
/// as expressions in the LMS's page: the package is served from the LMS's
/// origin, so both can be scripted.
const LAUNCH: &str = "document.getElementById('sco').contentWindow";
const APP: &str = "document.getElementById('sco').contentWindow.document.getElementById('edgewise-frame').contentWindow.edgewise";

fn hosts_url() -> anyhow::Result<String> {
    std::env::var("EDGEWISE_HOSTS_URL")
        .context("EDGEWISE_HOSTS_URL is not set: run these tests with `cargo xtask test`")
}

/// The LMS's page for SCORM `version` and `learner`, whose data it keeps
/// under [`lms_key`]: each test is a learner of its own, so that no test
/// finds what another's closing page saved.
fn lms_url(version: &str, learner: &str) -> anyhow::Result<String> {
    Ok(format!(
        "{}scorm/?version={version}&learner={learner}",
        hosts_url()?
    ))
}

/// The localStorage key under which the LMS keeps `learner`'s data.
fn lms_key(version: &str, learner: &str) -> String {
    format!("edgewise-lms-{version}-{learner}")
}

/// Whether the suspend data the LMS holds keeps writes in the do-it's
/// attempt (its fifth field: the attempt, then the writes after the last
/// colon), as a JavaScript expression on the LMS's page.
const DO_IT_WRITES_KEPT: &str = "(window.lms.cmi().suspend_data.split('|')[5] || '').split(':').length === 6 \
     && !(window.lms.cmi().suspend_data.split('|')[5] || '').endsWith(':')";

async fn package_state(browser: &Browser) -> anyhow::Result<Value> {
    browser
        .eval(&format!("return {LAUNCH}.edgewisePackage.state();"))
        .await
}

/// What the LMS holds for the learner now (scorm-again's `cmi`).
async fn cmi(browser: &Browser) -> anyhow::Result<Value> {
    browser.eval("return window.lms.cmi();").await
}

/// Waits until the app in the package shows exercise `name`, and returns
/// its state.
async fn exercise_on_screen(
    browser: &Browser,
    name: &str,
    timeout: Duration,
) -> anyhow::Result<Value> {
    let condition = format!(
        "(() => {{ try {{ const s = {APP}.state(); return s.exercise && s.exercise.name === '{name}'; }} \
           catch (err) {{ return false; }} }})()"
    );
    if let Err(err) = browser.wait_for(&condition, timeout).await {
        let launch = package_state(browser).await.unwrap_or(Value::Null);
        let console = browser.console_errors().await.unwrap_or_default();
        anyhow::bail!("{name} is not on screen: {err}\npackage: {launch}\nconsole: {console:#?}");
    }
    browser
        .eval(&format!("return {APP}.state().exercise;"))
        .await
}

async fn call(browser: &Browser, method: &str, args: &Value) -> anyhow::Result<Value> {
    browser
        .eval_async(&format!("{APP}.{method}(...{args})"))
        .await
}

async fn wait_finished(browser: &Browser, item: usize) -> anyhow::Result<Value> {
    browser
        .wait_for(
            &format!("{LAUNCH}.edgewisePackage.state().items[{item}].finished"),
            STEP_TIMEOUT,
        )
        .await?;
    package_state(browser).await
}

fn exercise(name: &str) -> anyhow::Result<Exercise> {
    catalog::find(name)
        .context("a shipped exercise")?
        .map_err(|err| anyhow::anyhow!("{err}"))
}

fn seed_of(state: &Value) -> anyhow::Result<u64> {
    state["seed"].as_u64().context("a seed")
}

/// The writes that do do-it exercise `name`'s instance `seed`, in order.
fn do_it_writes(name: &str, seed: u64) -> anyhow::Result<Vec<(&'static str, Value)>> {
    let instance = exercise(name)?.instance(seed)?;
    let Task::DoIt { operation, ids } = &instance.task else {
        anyhow::bail!("{name} is a do-it");
    };
    let mut target = instance.mesh.clone();
    operations::apply(&mut target, *operation, ids)?;
    Ok(student_writes(&instance.mesh, &target))
}

/// The names a version gives its records.
struct Version {
    name: &'static str,
    status: fn(&Value) -> (Value, Value),
    score: fn(&Value) -> Value,
    entry: fn(&Value) -> Value,
    response: &'static str,
    wrong: &'static str,
}

const V1_2: Version = Version {
    name: "1.2",
    status: |cmi| (cmi["core"]["lesson_status"].clone(), Value::Null),
    score: |cmi| cmi["core"]["score"]["raw"].clone(),
    entry: |cmi| cmi["core"]["entry"].clone(),
    response: "student_response",
    wrong: "wrong",
};

const V2004: Version = Version {
    name: "2004",
    status: |cmi| {
        (
            cmi["completion_status"].clone(),
            cmi["success_status"].clone(),
        )
    },
    score: |cmi| cmi["score"]["raw"].clone(),
    entry: |cmi| cmi["entry"].clone(),
    response: "learner_response",
    wrong: "incorrect",
};

/// The interactions the LMS holds, in order.
fn interactions(cmi: &Value) -> Vec<Value> {
    let Some(all) = cmi["interactions"].as_object() else {
        return Vec::new();
    };
    let mut records: Vec<(usize, Value)> = all
        .iter()
        .filter_map(|(n, record)| Some((n.parse().ok()?, record.clone())))
        .collect();
    records.sort_by_key(|(n, _)| *n);
    records.into_iter().map(|(_, record)| record).collect()
}

async fn pass_fail_leave_and_resume(version: &Version) -> anyhow::Result<()> {
    let _turn = ONE_HEAVY_PAGE_AT_A_TIME.lock().await;
    let browser = Browser::launch().await?;
    browser.set_script_timeout(Duration::from_secs(120)).await?;
    let lms = lms_url(version.name, "pass-fail-resume")?;

    browser.goto_url(&lms).await?;
    // A package of three exercises fits in 3 MB.
    let bytes = browser
        .eval_async(&format!(
            "fetch('edgewise-{}.zip').then((r) => r.arrayBuffer()).then((b) => b.byteLength)",
            version.name
        ))
        .await?;
    let bytes = bytes.as_u64().context("the zip's size")?;
    assert!(bytes <= 3_000_000, "the package is {bytes} bytes");

    // 1. The walk, every click right: passed.
    let walk = exercise_on_screen(&browser, "walk-face-loop-half-edge", START_TIMEOUT).await?;
    let instance = exercise("walk-face-loop-half-edge")?.instance(seed_of(&walk)?)?;
    let Task::Walk { expected, .. } = &instance.task else {
        anyhow::bail!("a walk");
    };
    for element in expected {
        call(
            &browser,
            "answerExercise",
            &json!([element.kind.prose(), element.id]),
        )
        .await?;
    }
    let state = wait_finished(&browser, 0).await?;
    assert_eq!(state["items"][0]["best"], expected.len(), "{state}");
    let now = cmi(&browser).await?;
    let records = interactions(&now);
    assert_eq!(records.len(), expected.len(), "one record per click: {now}");
    let first = &records[0];
    assert!(
        first["id"]
            .as_str()
            .is_some_and(|id| id.starts_with("walk-face-loop-half-edge-1-")),
        "{first}"
    );
    assert_eq!(first["result"], "correct", "{first}");
    assert!(
        first[version.response]
            .as_str()
            .is_some_and(|r| r.starts_with("half-edge ")),
        "{first}"
    );
    // One of three exercises: a third of the total, below the mark.
    assert_eq!((version.score)(&now), "33.33", "{now}");

    // 2. The prediction, every answer wrong: failed.
    browser
        .eval(&format!("{LAUNCH}.edgewisePackage.open(1); return null;"))
        .await?;
    let predict =
        exercise_on_screen(&browser, "predict-vertex-edges-half-edge", STEP_TIMEOUT).await?;
    let instance = exercise("predict-vertex-edges-half-edge")?.instance(seed_of(&predict)?)?;
    let Task::Predict { lookups, .. } = &instance.task else {
        anyhow::bail!("a prediction");
    };
    for lookup in lookups {
        let wrong = match lookup.answer {
            Some(_) => json!([null]),
            None => json!(["vertex", 0]),
        };
        call(&browser, "answerExercise", &wrong).await?;
    }
    let state = wait_finished(&browser, 1).await?;
    assert_eq!(state["items"][1]["best"], 0, "{state}");
    let now = cmi(&browser).await?;
    let records = interactions(&now);
    assert_eq!(records.len(), expected.len() + lookups.len(), "{now}");
    assert_eq!(
        records.last().map(|r| r["result"].clone()),
        Some(json!(version.wrong))
    );

    // 3. The do-it, half done; then the page is closed.
    browser
        .eval(&format!("{LAUNCH}.edgewisePackage.open(2); return null;"))
        .await?;
    let split = exercise_on_screen(&browser, "split-edge-half-edge", STEP_TIMEOUT).await?;
    let seed = seed_of(&split)?;
    let writes = do_it_writes("split-edge-half-edge", seed)?;
    let half = writes.len() / 2;
    for (method, args) in &writes[..half] {
        call(&browser, method, args).await?;
    }
    let counts = browser
        .eval(&format!("return {APP}.state().counts;"))
        .await?;
    // Kept in suspend_data once the writes settle (without a commit).
    browser.wait_for(DO_IT_WRITES_KEPT, STEP_TIMEOUT).await?;
    let (completion, _) = (version.status)(&cmi(&browser).await?);
    assert_eq!(completion, "incomplete");
    browser
        .screenshot(&format!("scorm-{}-before-leaving", version.name))
        .await?;

    // Leaving ends the attempt with exit = suspend; the LMS brings it back.
    browser.goto_url(&lms).await?;
    let again = exercise_on_screen(&browser, "split-edge-half-edge", START_TIMEOUT).await?;
    assert_eq!(seed_of(&again)?, seed, "the same instance");
    assert_eq!(again["step"], half, "the writes are counted");
    let counts_again = browser
        .eval(&format!("return {APP}.state().counts;"))
        .await?;
    assert_eq!(counts_again, counts, "the same tables");
    let now = cmi(&browser).await?;
    assert_eq!((version.entry)(&now), "resume", "{now}");
    let state = package_state(&browser).await?;
    assert_eq!(state["items"][0]["finished"], true, "{state}");
    assert_eq!(state["items"][1]["finished"], true, "{state}");
    assert_eq!(state["current"], 2, "{state}");

    // The rest of the writes, and Check: two of three passed.
    for (method, args) in &writes[half..] {
        call(&browser, method, args).await?;
    }
    call(&browser, "submitExercise", &json!([])).await?;
    let state = wait_finished(&browser, 2).await?;
    assert_eq!(state["passed"], true, "{state}");
    assert_eq!(state["completed"], true, "{state}");
    let now = cmi(&browser).await?;
    assert_eq!((version.score)(&now), "66.67", "{now}");
    let status = (version.status)(&now);
    if version.name == "1.2" {
        assert_eq!(status.0, "passed", "{now}");
    } else {
        assert_eq!(status, (json!("completed"), json!("passed")), "{now}");
        assert_eq!(now["score"]["scaled"], "0.6667", "{now}");
    }
    let records = interactions(&now);
    let check = records.last().context("the Check's record")?;
    assert_eq!(check["result"], "correct", "{check}");
    assert!(
        check[version.response]
            .as_str()
            .is_some_and(|r| r.starts_with("the tables after")),
        "{check}"
    );
    let errors = &state["lms"]["errors"];
    assert_eq!(errors, &json!([]), "every LMS call succeeded");
    browser
        .screenshot(&format!("scorm-{}-passed", version.name))
        .await?;
    browser.assert_no_console_errors().await?;
    browser.close().await
}

#[tokio::test]
async fn a_scorm_1_2_package_scores_resumes_and_passes() -> anyhow::Result<()> {
    pass_fail_leave_and_resume(&V1_2).await
}

#[tokio::test]
async fn a_scorm_2004_package_scores_resumes_and_passes() -> anyhow::Result<()> {
    pass_fail_leave_and_resume(&V2004).await
}

/// A student writes in the do-it and at once opens the prediction, whose
/// text arrives a second late (a slow LMS). The write's keep, 400 ms after
/// it, falls while the app still shows the do-it: it must not save the
/// do-it's attempt as the prediction's, from which the prediction would
/// then be resumed.
#[tokio::test]
async fn a_switch_just_after_a_write_keeps_each_attempt_under_its_exercise() -> anyhow::Result<()> {
    let _turn = ONE_HEAVY_PAGE_AT_A_TIME.lock().await;
    let browser = Browser::launch().await?;
    browser.goto_url(&lms_url("2004", "quick-switch")?).await?;
    exercise_on_screen(&browser, "walk-face-loop-half-edge", START_TIMEOUT).await?;
    browser
        .eval(&format!("{LAUNCH}.edgewisePackage.open(2); return null;"))
        .await?;
    let split = exercise_on_screen(&browser, "split-edge-half-edge", STEP_TIMEOUT).await?;
    let writes = do_it_writes("split-edge-half-edge", seed_of(&split)?)?;
    let (method, args) = writes.first().context("a write")?;

    // The launch page's fetches wait a second, and what it asks the app to
    // start is recorded.
    browser
        .eval(&format!(
            "const launch = {LAUNCH};
             const fetch = launch.fetch;
             launch.fetch = (...args) =>
               new Promise((wake) => setTimeout(wake, 1000)).then(() => fetch.apply(launch, args));
             const app = {APP};
             const start = app.startExercise;
             launch.startsAsked = [];
             app.startExercise = (...args) => {{
               launch.startsAsked.push(args[1] ?? null);
               return start.apply(app, args);
             }};
             return null;"
        ))
        .await?;
    call(&browser, method, args).await?;
    browser
        .eval(&format!("{LAUNCH}.edgewisePackage.open(1); return null;"))
        .await?;
    let predict =
        exercise_on_screen(&browser, "predict-vertex-edges-half-edge", STEP_TIMEOUT).await?;

    let asked = browser
        .eval(&format!("return {LAUNCH}.startsAsked;"))
        .await?;
    assert_eq!(
        asked,
        json!([{ "name": "predict-vertex-edges-half-edge" }]),
        "the prediction starts afresh, with no attempt of the do-it's"
    );
    assert_eq!(predict["step"], 0, "{predict}");
    // The do-it's write is kept under the do-it.
    let kept = browser
        .eval(&format!("return {DO_IT_WRITES_KEPT};"))
        .await?;
    assert_eq!(
        kept,
        true,
        "the do-it keeps its write: {}",
        cmi(&browser).await?["suspend_data"]
    );
    browser.assert_no_console_errors().await?;
    browser.close().await
}

/// Opened outside an LMS, the package says so once and still works.
#[tokio::test]
async fn a_package_without_an_lms_runs_as_a_plain_page() -> anyhow::Result<()> {
    let hosts = hosts_url()?;
    let _turn = ONE_HEAVY_PAGE_AT_A_TIME.lock().await;
    let browser = Browser::launch().await?;
    browser
        .goto_url(&format!("{hosts}scorm/package-1.2/launch.html"))
        .await?;
    let app = "document.getElementById('edgewise-frame').contentWindow.edgewise";
    let started = browser
        .wait_for(
            &format!(
                "(() => {{ try {{ return {app}.state().exercise.name === 'walk-face-loop-half-edge'; }} \
                   catch (err) {{ return false; }} }})()"
            ),
            START_TIMEOUT,
        )
        .await;
    if let Err(err) = started {
        let seen = browser
            .eval(&format!(
                "const f = document.getElementById('edgewise-frame'); \
                 let app = null; try {{ app = {app} ? {app}.state().exercise : 'no API'; }} catch (e) {{ app = String(e); }} \
                 return {{ src: f.src, package: window.edgewisePackage && window.edgewisePackage.state(), app }};"
            ))
            .await?;
        let console = browser.console_errors().await.unwrap_or_default();
        anyhow::bail!("{err}\nseen: {seen}\nconsole: {console:#?}");
    }
    let line = browser
        .eval("return document.getElementById('edgewise-lms').textContent;")
        .await?;
    assert!(
        line.as_str().is_some_and(|l| l.contains("No LMS found")),
        "{line}"
    );
    let state = browser
        .eval("return window.edgewisePackage.state();")
        .await?;
    assert_eq!(state["lms"]["found"], false, "{state}");
    assert_eq!(state["lms"]["errors"], json!([]), "{state}");
    browser.screenshot("scorm-plain-page").await?;

    // On a phone the items become a row above the view, each a finger's
    // height, and the view keeps most of the screen.
    let phone = SCREENS
        .iter()
        .find(|s| s.name.starts_with("phone"))
        .context("a phone")?;
    browser.emulate(phone).await?;
    browser
        .wait_for(
            &format!("innerWidth === {}", phone.width),
            Duration::from_secs(10),
        )
        .await?;
    let layout = browser
        .eval(
            "const nav = document.querySelector('nav').getBoundingClientRect(); \
             const frame = document.getElementById('edgewise-frame').getBoundingClientRect(); \
             const button = document.querySelector('nav button').getBoundingClientRect(); \
             return { navBottom: nav.bottom, frameTop: frame.top, frameHeight: frame.height, \
                      frameWidth: frame.width, buttonHeight: button.height, width: innerWidth, height: innerHeight };",
        )
        .await?;
    let n = |key: &str| layout[key].as_f64().unwrap_or_default();
    assert!(
        n("frameTop") >= n("navBottom") - 1.0,
        "the items sit above the view: {layout}"
    );
    assert!(
        n("frameWidth") >= n("width") - 1.0,
        "the view spans the phone: {layout}"
    );
    assert!(
        n("frameHeight") >= 0.5 * n("height"),
        "the view keeps most of it: {layout}"
    );
    assert!(
        n("buttonHeight") >= 44.0,
        "items are a finger's height: {layout}"
    );
    browser.screenshot("scorm-plain-page-phone").await?;
    browser.assert_no_console_errors().await?;
    browser.close().await
}

/// Share's package, built in the page from its own files, is byte for byte
/// the one the library makes of dist/ (what `edgewise package` writes).
#[tokio::test]
async fn the_page_builds_the_package_the_command_builds() -> anyhow::Result<()> {
    use base64::Engine as _;
    use edgewise_model::package::{AppFiles, Item, Package, Scorm};
    let _turn = ONE_HEAVY_PAGE_AT_A_TIME.lock().await;
    let browser = Browser::launch().await?;
    browser.set_script_timeout(Duration::from_secs(120)).await?;
    browser.open("").await?;
    browser
        .eval_async("window.edgewise.startExercise('kev-half-edge', { seed: 3 })")
        .await?;
    let exported = browser
        .eval_async("window.edgewise.exportPackage('2004')")
        .await?;
    assert_eq!(exported["name"], "kev-half-edge-scorm-2004.zip");
    let zipped = base64::engine::general_purpose::STANDARD
        .decode(exported["base64"].as_str().context("base64")?)?;

    let dist = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../dist");
    let app = AppFiles::read(|name| std::fs::read(dist.join(name)).map_err(|e| e.to_string()))?;
    let kev = exercise("kev-half-edge")?;
    let title = kev.title.clone();
    let package = Package::new(
        Scorm::V2004,
        &title,
        "80",
        vec![Item::Exercise(Box::new(kev))],
    )?;
    assert!(
        zipped == package.zip(&app)?,
        "the page's package ({} bytes) differs from the library's",
        zipped.len()
    );
    let refused = browser
        .refusal("window.edgewise.exportPackage('2005')")
        .await?;
    assert!(
        refused
            .as_str()
            .is_some_and(|m| m.contains("'1.2' or '2004'")),
        "{refused}"
    );
    browser.assert_no_console_errors().await?;
    browser.close().await
}

/// SCORM 1.2 keeps 4,096 characters of `suspend_data`. When the saved
/// attempts pass it, the runtime leaves out the largest unfinished attempt's
/// progress first, and keeps every score.
#[tokio::test]
async fn a_1_2_package_keeps_its_suspend_data_within_4096_characters() -> anyhow::Result<()> {
    const LIMIT: usize = 4096;
    const LEARNER: &str = "full-suspend-data";
    let hosts = hosts_url()?;
    let _turn = ONE_HEAVY_PAGE_AT_A_TIME.lock().await;
    let browser = Browser::launch().await?;
    // What an earlier visit left in the LMS: the walk finished at 5/5, the
    // prediction open, and the do-it's writes filling the rest of the room.
    let head = "E1|1|0|5~5~fs~|0~0~s~|0~0~s~1:7:1:999::";
    let mut writes = String::new();
    while head.len() + writes.len() + 3 <= LIMIT - 6 {
        writes.push_str("+v,");
    }
    writes.push_str("+v");
    let saved = format!("{head}{writes}");
    assert!(saved.len() <= LIMIT && saved.len() > LIMIT - 12);
    // Any page of the LMS's site reaches its storage.
    browser
        .goto_url(&format!("{hosts}scorm/scorm-again.js"))
        .await?;
    browser
        .eval(&format!(
            "localStorage.setItem('{key}', JSON.stringify({{ \
               core: {{ exit: 'suspend', lesson_status: 'incomplete' }}, suspend_data: '{saved}' }})); \
             return null;",
            key = lms_key("1.2", LEARNER),
        ))
        .await?;
    // That page's missing icon is the site's, not the package's.
    browser.console_errors().await?;
    browser.goto_url(&lms_url("1.2", LEARNER)?).await?;
    exercise_on_screen(&browser, "predict-vertex-edges-half-edge", START_TIMEOUT).await?;
    // The prediction's own attempt joins the data and passes the limit.
    browser
        .wait_for(
            "window.lms.cmi().suspend_data.split('|')[4].includes(':')",
            STEP_TIMEOUT,
        )
        .await?;
    let now = cmi(&browser).await?;
    let suspend = now["suspend_data"].as_str().context("suspend_data")?;
    assert!(suspend.len() <= LIMIT, "{} characters", suspend.len());
    assert!(
        suspend.contains("|5~5~fs~|"),
        "the walk's score is kept: {suspend}"
    );
    assert!(
        !suspend.contains("+v"),
        "the do-it's writes are left out: {suspend}"
    );
    assert_eq!((V1_2.entry)(&now), "resume", "{now}");
    let state = package_state(&browser).await?;
    assert_eq!(state["items"][0]["best"], 5, "{state}");
    assert_eq!(state["lms"]["errors"], json!([]), "{state}");
    browser.assert_no_console_errors().await?;
    browser.close().await
}
