//! The lecture-note snippets of docs/embedding.md: each is there, titled,
//! loads `edgewise-embed.js` when it uses it, and carries a course link that
//! parses without a single complaint and names a real sample and algorithm.

use edgewise_model::course_link::{CourseLink, MeshSource};

const DOC: &str = include_str!("../../../../docs/embedding.md");
const SERVED_AT: &str = "https://example.edu/edgewise/";

/// The first fenced block after `<!-- snippet: name -->`.
fn snippet(name: &str) -> &'static str {
    let marker = format!("<!-- snippet: {name} -->");
    let after = &DOC[DOC.find(&marker).unwrap_or_else(|| panic!("no {marker}"))..];
    let start = after.find("```").expect("a fenced block");
    let block = &after[start..];
    let body = &block[block.find('\n').expect("a fence line") + 1..];
    let end = body.find("\n```").expect("the block ends");
    &body[..end]
}

/// Every attribute value `name="…"` in `html`.
fn attributes<'a>(html: &'a str, name: &str) -> Vec<&'a str> {
    let pattern = format!("{name}=\"");
    html.match_indices(&pattern)
        .map(|(at, _)| {
            let value = &html[at + pattern.len()..];
            &value[..value.find('"').expect("the value ends")]
        })
        .collect()
}

#[test]
fn every_lecture_tool_snippet_carries_a_titled_working_link() {
    let algorithms: Vec<&str> = edgewise_core::lang::library::SOURCES
        .iter()
        .flat_map(|(_, source)| source.lines())
        .filter_map(|line| line.strip_prefix("algorithm "))
        .filter_map(|rest| rest.split('(').next())
        .collect();
    for name in ["quarto", "myst", "mkdocs", "reveal"] {
        let html = snippet(name);
        let links: Vec<&str> = ["data-edgewise", "data-src"]
            .iter()
            .flat_map(|attribute| attributes(html, attribute))
            .collect();
        assert_eq!(links.len(), 1, "{name}: one view\n{html}");
        let titles: Vec<&str> = ["data-title", "title"]
            .iter()
            .flat_map(|attribute| attributes(html, attribute))
            .collect();
        assert!(
            titles
                .iter()
                .any(|t| t.starts_with("Edgewise: ") && t.len() > 20),
            "{name}: a title that says what the view shows\n{html}"
        );
        if html.contains("data-edgewise") {
            assert!(
                html.contains(&format!(
                    "<script src=\"{SERVED_AT}edgewise-embed.js\"></script>"
                )),
                "{name}: loads the embed script\n{html}"
            );
        }
        let link = links[0]
            .strip_prefix(SERVED_AT)
            .unwrap_or_else(|| panic!("{name}: served at {SERVED_AT}"));
        let query = link.strip_prefix('?').expect("a query");
        let (parsed, messages) = CourseLink::parse(query, "");
        assert_eq!(messages, Vec::<String>::new(), "{name}: {link}");
        let Some(MeshSource::Sample(sample)) = &parsed.mesh else {
            panic!("{name}: a sample mesh");
        };
        assert!(
            edgewise_model::samples::find(sample).is_some(),
            "{name}: {sample}"
        );
        if let Some(algorithm) = &parsed.algorithm {
            assert!(
                algorithms.contains(&algorithm.as_str()),
                "{name}: {algorithm}"
            );
        }
    }
}
