//! The first visit: a page opened without a link shows the journal's
//! tetrahedron with its tables and the hint of things to try; a course link
//! or an embedded view opens without either.

use edgewise_browser_tests::Browser;

#[tokio::test]
async fn a_plain_visit_starts_on_table_2_and_links_do_not() -> anyhow::Result<()> {
    let browser = Browser::launch().await?;
    browser.open("").await?;
    let state = browser.state().await?;
    assert_eq!(state["mesh"], "tetrahedron.wtb", "{state}");
    assert_eq!(state["structure"], "winged");
    assert_eq!(state["welcome"], serde_json::json!([false, false, false]));
    assert_eq!(state["history"]["undo"], serde_json::json!([]));
    let shot = browser.screenshot("first-visit").await?;
    assert!(
        shot.distinct_colours(64) > 8,
        "the view and the hint are drawn"
    );

    // Following the hint: an edge selected, then the algorithm stepped.
    browser
        .eval_async("window.edgewise.select('edge', 2)")
        .await?;
    browser
        .eval_async("window.edgewise.run('vertexAdjacentEdge', { v: 1 }).then(() => window.edgewise.step(2))")
        .await?;
    let welcome = browser.state().await?["welcome"].clone();
    assert_eq!(welcome, serde_json::json!([true, false, true]));

    for link in ["?sample=cube", "?embed=1"] {
        browser.open(link).await?;
        let state = browser.state().await?;
        assert!(state["welcome"].is_null(), "{link}: {state}");
        assert_ne!(state["mesh"], "tetrahedron.wtb", "{link}");
    }
    browser.assert_no_console_errors().await?;
    browser.close().await
}
