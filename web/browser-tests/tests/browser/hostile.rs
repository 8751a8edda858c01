//! Hostile input in the browser: course links carrying an algorithm of
//! 100,000 terms or one nested 100,000 deep leave the page alive, name the
//! problem, and the default view still works; JS API calls with wrong
//! arguments are refused with messages that say what was expected; a failed
//! load keeps the previous mesh and algorithm menu.

use std::time::Duration;

use edgewise_browser_tests::Browser;
use serde_json::Value;

const APPLY_TIMEOUT: Duration = Duration::from_secs(30);

/// A fragment `alg=<payload>` for the algorithm text a JS expression makes.
async fn algorithm_fragment(browser: &Browser, source_js: &str) -> anyhow::Result<String> {
    Ok(format!("alg={}", browser.payload(source_js).await?))
}

/// Opens a link whose algorithm cannot compile; checks the page stays alive,
/// the message names `expected`, and the tetrahedron still answers.
async fn open_hostile_link(
    browser: &Browser,
    fragment: &str,
    expected: &str,
    shot: &str,
) -> anyhow::Result<()> {
    browser
        .open(&format!(
            "?sample=tetrahedron&structure=winged&algorithm=hostile#{fragment}"
        ))
        .await?;
    browser
        .wait_for("window.edgewise.state().error !== null", APPLY_TIMEOUT)
        .await?;
    let state = browser.state().await?;
    let error = state["error"].as_str().unwrap_or_default();
    assert!(error.contains(expected), "{error}");
    assert_eq!(state["mesh"], "tetrahedron.wtb");
    // The page is alive: no error box, and commands still work.
    let page_error = browser
        .eval("return document.getElementById('edgewise_error').dataset.visible === 'true'")
        .await?;
    assert_eq!(page_error, Value::Bool(false));
    assert_eq!(
        browser
            .eval_async("window.edgewise.select('edge', 3)")
            .await?,
        Value::Null
    );
    assert_eq!(browser.state().await?["selection"]["id"], 3);
    assert_eq!(
        browser
            .eval_async("window.edgewise.run('vertexAdjacentEdge', {v: 1})")
            .await?,
        Value::Null
    );
    browser.eval_async("window.edgewise.goto(3)").await?;
    assert_eq!(browser.state().await?["trace"]["step"], 3);
    let shot = browser.screenshot(shot).await?;
    assert!(!shot.is_blank(), "{}", shot.path.display());
    browser.assert_no_console_errors().await?;
    Ok(())
}

#[tokio::test]
async fn a_link_with_a_100000_term_algorithm_names_it_and_the_view_works() -> anyhow::Result<()> {
    let browser = Browser::launch().await?;
    browser.open("").await?;
    let fragment = algorithm_fragment(
        &browser,
        "'algorithm hostile(n : Integer) : WingedEdge;\\nbegin\\n  n := n' + ' + 1'.repeat(100000) + ';\\nend\\n'",
    )
    .await?;
    open_hostile_link(
        &browser,
        &fragment,
        "link.alg:3:402: error: this expression is too long",
        "hostile-link-100000-terms",
    )
    .await?;
    browser.close().await
}

#[tokio::test]
async fn a_link_with_a_deeply_nested_algorithm_names_it_and_the_view_works() -> anyhow::Result<()> {
    let browser = Browser::launch().await?;
    browser.open("").await?;
    let fragment = algorithm_fragment(
        &browser,
        "'algorithm hostile(b : Boolean) : WingedEdge;\\nbegin\\n  b := ' + '('.repeat(100000) + 'b' + ')'.repeat(100000) + ';\\nend\\n'",
    )
    .await?;
    open_hostile_link(
        &browser,
        &fragment,
        "this is nested too deeply (more than 100 levels)",
        "hostile-link-nested",
    )
    .await?;
    browser.close().await
}

#[tokio::test]
async fn wrong_arguments_are_refused_with_what_was_expected() -> anyhow::Result<()> {
    let browser = Browser::launch().await?;
    browser.open("").await?;
    assert_eq!(
        browser
            .eval_async("window.edgewise.loadSample('cube', {structure: 'half'})")
            .await?,
        Value::Null
    );
    let cases = [
        (
            "window.edgewise.setSideBySide('no')",
            "setSideBySide(on): on must be true or false, not the string 'no'",
        ),
        (
            "window.edgewise.select('edge', NaN)",
            "select(kind, id): id must be a whole number from 0, not NaN",
        ),
        (
            "window.edgewise.select('edge', -1)",
            "select(kind, id): id must be a whole number from 0, not -1",
        ),
        (
            "window.edgewise.select('edge', 1.5)",
            "select(kind, id): id must be a whole number from 0, not 1.5",
        ),
        (
            "window.edgewise.select('corner', 1)",
            "select(kind, id): kind must be 'vertex', 'edge' or 'face', not the string 'corner'",
        ),
        (
            "window.edgewise.select('edge', 99999)",
            "there is no edge 99999 (this mesh has 24, numbered from 0)",
        ),
        (
            "window.edgewise.loadMesh(42)",
            "loadMesh(text, options): text must be a string, not 42",
        ),
        (
            "window.edgewise.loadMesh('v 0 0 0', {formt: 'obj'})",
            "loadMesh(text, options): there is no option 'formt'; the options are format and structure",
        ),
        (
            "window.edgewise.loadMesh('v 0 0 0', {format: 'stl'})",
            "loadMesh(text, options): options.format must be 'obj', 'ply', 'wtb' or 'htb', not 'stl'",
        ),
        (
            "window.edgewise.loadSample('cube', {structure: 'round'})",
            "loadSample(name, options): options.structure must be 'winged' or 'half', not 'round'",
        ),
        (
            "window.edgewise.loadSample('no-such-mesh')",
            "there is no sample called 'no-such-mesh'",
        ),
        (
            "window.edgewise.run('vertexStar', {v: 'one'})",
            "run(name, args): args.v must be a whole number (an id) or a boolean, not the string 'one'",
        ),
        (
            "window.edgewise.run('vertexStar', [0])",
            "run(name, args): args must be an object such as {v: 0}, not an array",
        ),
        (
            "window.edgewise.run('vertexStar', {w: 0})",
            "vertexStar has no parameter `w`",
        ),
        (
            "window.edgewise.step(-1)",
            "step(n): n must be a whole number from 0, not -1",
        ),
        (
            "window.edgewise.goto()",
            "goto(k): k must be a whole number from 0, not undefined (it is missing)",
        ),
        ("window.edgewise.switchTab(7)", "there is no tab 7"),
        (
            "window.edgewise.settled('soon')",
            "settled(timeoutMs): timeoutMs must be a whole number from 0, not the string 'soon'",
        ),
        (
            "window.edgewise.edit('FLIP-EDGE', [0])",
            "edit(op, ids): op must be one of 'flip-edge',",
        ),
        (
            "window.edgewise.setStructure(true)",
            "setStructure(name): name must be 'winged' or 'half', not true",
        ),
        (
            "window.edgewise.loadAlgorithms('x'.repeat(2 * 1024 * 1024))",
            "loadAlgorithms(source, file): source is 2097152 characters long; it may hold at most 1048576",
        ),
    ];
    for (call, expected) in cases {
        let message = browser.refusal(call).await?;
        let message = message.as_str().unwrap_or_default();
        assert!(message.contains(expected), "{call}: {message}");
    }
    // Nothing changed: the cube is still open, alone, as half-edge.
    let state = browser.state().await?;
    assert_eq!(state["mesh"], "cube.htb");
    assert_eq!(state["structure"], "half");
    assert_eq!(state["sideBySide"], false);
    browser.assert_no_console_errors().await?;
    browser.close().await
}

/// Proxies whose traps throw, revoked proxies, throwing getters, Symbols,
/// `BigInt`s and a 2³²−1-long array: each command still returns a Promise
/// (never throws at once), which rejects naming the argument, and the page
/// goes on.
#[tokio::test]
async fn exotic_arguments_give_rejected_promises() -> anyhow::Result<()> {
    let browser = Browser::launch_on_sample("cube").await?;
    // Each call runs inside the page; `outcome` tells a synchronous throw
    // from a rejection.
    browser
        .eval(
            "window.outcome = (call) => { let p; \
               try { p = call(); } catch (e) { return Promise.resolve('threw at once: ' + e); } \
               if (!(p instanceof Promise)) return Promise.resolve('not a Promise'); \
               return p.then(() => 'resolved', (e) => 'rejected: ' + e.message); }; \
             window.hostile = { \
               ownKeys: new Proxy({}, { ownKeys() { throw new Error('keys trap'); } }), \
               revoked: (() => { const r = Proxy.revocable({}, {}); r.revoke(); return r.proxy; })(), \
               getter: { get structure() { throw new Error('getter trap'); } }, \
               arg: { get v() { throw new Error('argument trap'); } }, \
               ids: new Proxy([0], { get(t, k) { if (k === '0') throw new Error('item trap'); return t[k]; } }), \
               length: new Proxy([0], { get(t, k) { if (k === 'length') throw new Error('length trap'); return t[k]; } }), \
             }; return 1;",
        )
        .await?;
    let cases = [
        (
            "window.edgewise.loadSample('cube', hostile.ownKeys)",
            "rejected: loadSample(name, options): options could not be read: it threw 'Error: keys trap'",
        ),
        (
            "window.edgewise.loadSample('cube', hostile.revoked)",
            "rejected: loadSample(name, options): options could not be read: it threw 'TypeError:",
        ),
        (
            "window.edgewise.loadSample('cube', hostile.getter)",
            "rejected: loadSample(name, options): options.structure could not be read: it threw 'Error: getter trap'",
        ),
        (
            "window.edgewise.run('vertexStar', hostile.arg)",
            "rejected: run(name, args): args.v could not be read: it threw 'Error: argument trap'",
        ),
        (
            "window.edgewise.run('vertexStar', hostile.revoked)",
            "rejected: run(name, args): args could not be read: it threw 'TypeError:",
        ),
        (
            "window.edgewise.edit('flip-edge', hostile.ids)",
            "rejected: edit(op, ids): ids could not be read: it threw 'Error: item trap'",
        ),
        (
            "window.edgewise.edit('flip-edge', hostile.length)",
            "rejected: edit(op, ids): ids could not be read: it threw 'Error: length trap'",
        ),
        (
            "window.edgewise.edit('flip-edge', new Array(2 ** 32 - 1))",
            "rejected: edit(op, ids): ids must be at most three ids, not an array",
        ),
        (
            "window.edgewise.select('edge', 3n)",
            "rejected: select(kind, id): id must be a whole number from 0, not a BigInt",
        ),
        (
            "window.edgewise.select(Symbol('edge'), 3)",
            "rejected: select(kind, id): kind must be 'vertex', 'edge' or 'face', not a Symbol",
        ),
        (
            "window.edgewise.loadMesh(hostile.revoked)",
            "rejected: loadMesh(text, options): text must be a string, not an object",
        ),
    ];
    for (call, expected) in cases {
        let outcome = browser
            .eval_async(&format!("window.outcome(() => {call})"))
            .await?;
        let outcome = outcome.as_str().unwrap_or_default();
        assert!(outcome.starts_with(expected), "{call}: {outcome}");
    }
    // The page goes on: the cube is open, and a selection and an edit work.
    assert_eq!(browser.state().await?["mesh"], "cube.htb");
    browser
        .eval_async("window.edgewise.select('edge', 3)")
        .await?;
    assert_eq!(browser.state().await?["selection"]["id"], 3);
    browser
        .eval_async("window.edgewise.edit('split-edge', [3])")
        .await?;
    browser.assert_no_console_errors().await?;
    browser.close().await
}

#[tokio::test]
async fn a_failed_load_keeps_the_mesh_and_the_algorithm_menu() -> anyhow::Result<()> {
    let browser = Browser::launch().await?;
    browser.open("").await?;
    browser
        .eval_async("window.edgewise.loadSample('tetrahedron')")
        .await?;
    let mine = "algorithm mine(v : Vertex) : WingedEdge;\\nbegin\\n  mark v.incidentEdge;\\nend\\n";
    assert_eq!(
        browser
            .eval_async(&format!(
                "window.edgewise.loadAlgorithms('{mine}', 'mine.alg')"
            ))
            .await?,
        Value::Null
    );
    let before = browser.eval("return window.edgewise.algorithms()").await?;
    let refusals = [
        "window.edgewise.loadMesh('v 0 0 0\\nv 1 0 0\\nf 1 2 3\\n', {format: 'obj'})",
        "window.edgewise.loadMesh('ply\\nformat ascii 1.0\\nelement vertex 4000000000\\nend_header\\n', {format: 'ply'})",
        "window.edgewise.loadMesh('v 0 0 0\\u0000', {format: 'obj'})",
        "window.edgewise.loadAlgorithms('algorithm mine(v : Vertex) : WingedEdge;\\nbegin\\n  mark v' + '.incidentEdge.endVertex'.repeat(20000) + ';\\nend\\n', 'mine.alg')",
    ];
    for call in refusals {
        browser.refusal(call).await?;
        let state = browser.state().await?;
        assert_eq!(state["mesh"], "tetrahedron.wtb", "{call}");
        assert_eq!(state["counts"]["faces"], 4, "{call}");
        let after = browser.eval("return window.edgewise.algorithms()").await?;
        assert_eq!(after, before, "{call}");
    }
    assert_eq!(
        browser
            .eval_async("window.edgewise.run('mine', {v: 0})")
            .await?,
        Value::Null
    );
    browser.assert_no_console_errors().await?;
    browser.close().await
}
