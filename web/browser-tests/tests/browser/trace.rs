//! Tracing algorithms in the browser through `window.edgewise`: run,
//! step, back, goto and abort, the state of lookup and comparison steps
//! (with screenshots), a run-time error, and loading algorithms.

use edgewise_browser_tests::Browser;
use serde_json::Value;

/// Goes to the first step at or after `from` whose operation is `operation`.
async fn goto_first(browser: &Browser, operation: &str, from: u64) -> anyhow::Result<Value> {
    let steps = browser.state().await?["trace"]["steps"]
        .as_u64()
        .unwrap_or(0);
    for k in from..=steps {
        browser
            .eval_async(&format!("window.edgewise.goto({k})"))
            .await?;
        let state = browser.state().await?;
        if state["trace"]["operation"] == operation {
            return Ok(state);
        }
    }
    anyhow::bail!("no {operation} step in the trace")
}

fn roles(state: &Value, role: &str) -> Vec<(String, u64)> {
    state["highlights"]
        .as_array()
        .map(|list| {
            list.iter()
                .filter(|h| h["role"] == role)
                .map(|h| {
                    (
                        h["kind"].as_str().unwrap_or("").to_owned(),
                        h["id"].as_u64().unwrap_or(u64::MAX),
                    )
                })
                .collect()
        })
        .unwrap_or_default()
}

#[tokio::test]
async fn vertex_adjacent_edge_is_traced_step_by_step() -> anyhow::Result<()> {
    let browser = Browser::launch().await?;
    browser.open("").await?;
    for (sample, structure, v, degree) in [
        ("tetrahedron", "winged", 1, 3),
        ("tetrahedron", "half", 1, 3),
        ("cube", "winged", 0, 3),
        ("cube", "half", 0, 3),
    ] {
        let loaded = browser
            .eval_async(&format!(
                "window.edgewise.loadSample('{sample}', {{structure: '{structure}'}})"
            ))
            .await?;
        assert_eq!(loaded, Value::Null);
        let started = browser
            .eval_async(&format!(
                "window.edgewise.run('vertexAdjacentEdge', {{v: {v}}})"
            ))
            .await?;
        assert_eq!(started, Value::Null, "{sample} {structure}");
        let state = browser.state().await?;
        let trace = &state["trace"];
        assert_eq!(trace["algorithm"], "vertexAdjacentEdge");
        assert_eq!(trace["step"], 0);
        assert_eq!(trace["variables"]["v"], format!("Vertex {v}"));

        // A lookup: the vertex and the edge it gives are green.
        let state = goto_first(&browser, "lookup", 1).await?;
        let trace = &state["trace"];
        let span = trace["span"].as_array().expect("a span at a lookup");
        assert!(span[0].as_u64() < span[1].as_u64());
        let looked = roles(&state, "lookup");
        assert!(
            looked.contains(&("vertex".to_owned(), v)),
            "{sample} {structure}: {looked:?}"
        );
        assert!(looked.iter().any(|(kind, _)| kind == "edge"));
        if sample == "tetrahedron" {
            let shot = browser
                .screenshot(&format!("trace-{sample}-{structure}-lookup"))
                .await?;
            assert!(!shot.is_blank(), "{}", shot.path.display());
        }

        // A comparison: two light blue sides.
        let state = goto_first(&browser, "compare", 1).await?;
        assert_eq!(roles(&state, "compared").len(), 2, "{sample} {structure}");
        if sample == "tetrahedron" {
            let shot = browser
                .screenshot(&format!("trace-{sample}-{structure}-compare"))
                .await?;
            assert!(!shot.is_blank(), "{}", shot.path.display());
        }

        // Twenty forward and twenty back give the identical state.
        browser.eval_async("window.edgewise.goto(2)").await?;
        let before = browser.state().await?;
        browser.eval_async("window.edgewise.step(20)").await?;
        browser.eval_async("window.edgewise.back(20)").await?;
        let after = browser.state().await?;
        assert_eq!(after["trace"], before["trace"]);
        assert_eq!(after["highlights"], before["highlights"]);

        // The end: done, with one mark per edge at the vertex.
        browser.eval_async("window.edgewise.goto(1000000)").await?;
        let state = browser.state().await?;
        let trace = &state["trace"];
        assert_eq!(trace["done"], true, "{sample} {structure}: {trace}");
        assert_eq!(
            trace["marked"].as_array().map(Vec::len),
            Some(degree),
            "{sample} {structure}"
        );
        if sample == "cube" && structure == "half" {
            let shot = browser.screenshot("trace-cube-half-done").await?;
            assert!(!shot.is_blank(), "{}", shot.path.display());
        }
        assert_eq!(
            browser.eval_async("window.edgewise.abort()").await?,
            Value::Null
        );
        assert_eq!(browser.state().await?["trace"], Value::Null);
    }
    browser.assert_no_console_errors().await?;
    browser.close().await
}

#[tokio::test]
async fn errors_are_reported_and_the_trace_stays() -> anyhow::Result<()> {
    let browser = Browser::launch().await?;
    browser.open("").await?;
    browser
        .eval_async("window.edgewise.loadSample('open-square', {structure: 'half'})")
        .await?;
    // vertexAdjacentFace assumes a closed mesh; at a corner it meets a null face.
    let mut stopped = None;
    for v in 0..9 {
        browser
            .eval_async(&format!(
                "window.edgewise.run('vertexAdjacentFace', {{v: {v}}})"
            ))
            .await?;
        browser.eval_async("window.edgewise.goto(100000)").await?;
        let state = browser.state().await?;
        if state["trace"]["error"].is_string() {
            stopped = Some(state);
            break;
        }
    }
    let state = stopped.expect("some boundary vertex stops the run");
    let trace = &state["trace"];
    assert_eq!(trace["step"], trace["steps"]);
    assert_eq!(trace["done"], false);
    assert!(
        trace["message"]
            .as_str()
            .is_some_and(|m| m.starts_with("Stopped at line")),
        "{trace}"
    );
    let shot = browser.screenshot("trace-open-square-error").await?;
    assert!(!shot.is_blank(), "{}", shot.path.display());

    // Commands and sources that are wrong say why.
    let message = browser
        .refusal("window.edgewise.run('noSuchAlgorithm')")
        .await?;
    assert!(
        message
            .as_str()
            .is_some_and(|m| m.contains("no algorithm called")),
        "{message}"
    );
    let message = browser
        .refusal("window.edgewise.loadAlgorithms('algorithm a(v : Vertex) : HalfEdge;\\nbegin\\n  mark v.incidentEgde;\\nend\\n', 'mine.alg')")
        .await?;
    assert!(
        message
            .as_str()
            .is_some_and(|m| m.starts_with("mine.alg:3:")),
        "{message}"
    );
    let loaded = browser
        .eval_async("window.edgewise.loadAlgorithms('algorithm a(v : Vertex) : HalfEdge;\\nbegin\\n  mark v.incidentEdge;\\nend\\n', 'mine.alg')")
        .await?;
    assert_eq!(loaded, Value::Null);
    let list = browser.eval("return window.edgewise.algorithms()").await?;
    assert!(
        list.as_array().is_some_and(|l| l
            .iter()
            .any(|a| a["name"] == "a" && a["origin"] == "mine.alg")),
        "{list}"
    );
    assert_eq!(
        browser
            .eval_async("window.edgewise.run('a', {v: 0})")
            .await?,
        Value::Null
    );
    browser.eval_async("window.edgewise.step(3)").await?;
    assert_eq!(browser.state().await?["trace"]["done"], true);
    browser.assert_no_console_errors().await?;
    browser.close().await
}

/// A step repaints a few frames and then nothing: the tables and the code
/// jump to their row and line. A smooth scroll took seven frames a step,
/// each a whole repaint, which a slow machine pays for every key press.
/// `settled()` says when the view asks for no more frames; ten animation
/// frames later none has been drawn. A playing run never settles, and
/// `settled` says what keeps it drawing.
#[tokio::test]
async fn a_step_repaints_a_few_frames_then_rests() -> anyhow::Result<()> {
    let browser = Browser::launch().await?;
    browser.open("?sample=cube&structure=half").await?;
    browser
        .eval_async(
            "window.edgewise.run('vertexStar', { v: 0 }).then(() => window.edgewise.settled())",
        )
        .await?;
    for step in 1..=4 {
        let frames = browser
            .eval_async(
                "(async () => {
                   const before = window.edgewise.state().frames;
                   await window.edgewise.step(1);
                   const settled = await window.edgewise.settled();
                   for (let i = 0; i < 10; i++) {
                     await new Promise((r) => requestAnimationFrame(r));
                   }
                   return [settled - before, window.edgewise.state().frames - before];
                 })()",
            )
            .await?;
        let [until_settled, after] = [0, 1].map(|i| frames[i].as_u64().unwrap_or(u64::MAX));
        assert!(
            (1..=3).contains(&until_settled),
            "step {step} repainted {until_settled} frames before it settled"
        );
        assert_eq!(
            after, until_settled,
            "step {step} went on drawing after it settled"
        );
    }
    let refusal = browser
        .refusal("window.edgewise.play().then(() => window.edgewise.settled(300))")
        .await?;
    let refusal = refusal.as_str().unwrap_or_default();
    assert!(
        refusal.starts_with("the view did not settle within 300 ms: it kept asking for frames ("),
        "a playing run: {refusal}"
    );
    browser.eval_async("window.edgewise.pause()").await?;
    browser.eval_async("window.edgewise.settled()").await?;
    browser.assert_no_console_errors().await?;
    browser.close().await
}
