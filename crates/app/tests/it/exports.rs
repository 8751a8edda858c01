//! Pictures for slides and handouts: the SVG export holds the view as
//! vector shapes, the tables with the highlighted rows and their roles, and
//! the message line, as well-formed XML (tests/golden/export-*.svg;
//! `EDGEWISE_BLESS=1` rewrites them).

use crate::support;

use crate::golden;

use edgewise_core::mesh::Structure;
use edgewise_core::schema::{ElementKind, ElementRef};

fn golden_path(name: &str) -> std::path::PathBuf {
    std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/golden")
        .join(format!("export-{name}.svg"))
}

/// Reads `svg` through an XML parser: it fails on anything malformed.
fn well_formed(svg: &str) {
    let mut reader = quick_xml::Reader::from_str(svg);
    loop {
        match reader.read_event() {
            Ok(quick_xml::events::Event::Eof) => break,
            Ok(_) => {}
            Err(error) => panic!(
                "not well-formed at byte {}: {error}\n{svg}",
                reader.buffer_position()
            ),
        }
    }
}

fn count(svg: &str, tag: &str) -> usize {
    svg.matches(&format!("<{tag} ")).count()
}

#[test]
fn a_selection_exports_with_its_roles_in_the_tables() {
    let mut harness = support::harness_with("tetrahedron", Some(Structure::WingedEdge));
    harness
        .state_mut()
        .select(Some(ElementRef::new(ElementKind::Edge, 0)))
        .expect("selects");
    harness.run();
    let svg = harness.state().export_svg().expect("exports");
    well_formed(&svg);
    assert!(
        svg.starts_with("<svg xmlns=\"http://www.w3.org/2000/svg\""),
        "{svg}"
    );
    assert!(
        svg.contains("<title>Edgewise: tetrahedron.wtb</title>"),
        "{svg}"
    );
    // Four faces, six arrows (each a shaft and a head), four vertices.
    assert_eq!(count(&svg, "line"), 6);
    assert_eq!(count(&svg, "polygon"), 4 + 6);
    assert_eq!(count(&svg, "circle"), 4);
    assert!(svg.contains(">Faces: 4 rows</text>"), "{svg}");
    assert!(svg.contains(">Edges: 6 rows</text>"), "{svg}");
    assert!(svg.contains(">Vertices: 4 rows</text>"), "{svg}");
    assert!(svg.contains(">selected</text>"), "{svg}");
    assert!(svg.contains(">left predecessor</text>"), "{svg}");
    assert!(svg.contains("Edge 0 selected:"), "the caption: {svg}");
    golden::assert_matches(&golden_path("tetrahedron-edge-0"), &svg);
}

#[test]
fn a_trace_step_exports_with_its_sentence() {
    let mut harness = support::harness_tracing("cube", Some(Structure::HalfEdge), 0);
    harness.state_mut().trace_goto(4).expect("steps");
    harness.run();
    let svg = harness.state().export_svg().expect("exports");
    well_formed(&svg);
    assert!(
        svg.contains("<title>Edgewise: vertexAdjacentEdge on cube.htb</title>"),
        "{svg}"
    );
    assert!(svg.contains("Step 4 of "), "{svg}");
    assert!(svg.contains(">Half-edges: 24 rows</text>"), "{svg}");
    assert!(
        svg.contains(">lookup</text>") || svg.contains(">variable</text>"),
        "{svg}"
    );
    golden::assert_matches(&golden_path("cube-trace-step-4"), &svg);
}

#[test]
fn without_a_mesh_the_export_says_why() {
    let mut harness = support::harness();
    harness.run();
    let error = harness.state().export_svg().expect_err("no mesh");
    assert_eq!(
        error.as_str(),
        "open a mesh before exporting a picture of it"
    );
}

/// The PDF's page count, from its page tree.
fn page_count(pdf: &[u8]) -> usize {
    let text = String::from_utf8_lossy(pdf);
    text.split("/Type /Pages ")
        .nth(1)
        .and_then(|rest| rest.split("/Count ").nth(1))
        .and_then(|rest| rest.split_whitespace().next())
        .and_then(|count| count.parse().ok())
        .unwrap_or(0)
}

/// Keeps a handout in the target folder, to be looked at.
fn keep(name: &str, bytes: &[u8]) {
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR"));
    std::fs::write(dir.join(name), bytes).expect("written");
}

#[test]
fn a_handout_has_a_page_per_step_and_follows_an_edit() {
    let harness = support::harness_tracing("tetrahedron", Some(Structure::WingedEdge), 1);
    let (name, pdf) = harness.state().export_handout().expect("a handout");
    keep(&name, &pdf);
    assert_eq!(name, "tetrahedron-vertexAdjacentEdge.pdf");
    assert!(pdf.starts_with(b"%PDF-1.4\n") && pdf.ends_with(b"%%EOF\n"));
    assert_eq!(page_count(&pdf), 23, "the start and 22 steps");
    let text = String::from_utf8_lossy(&pdf);
    assert!(
        text.contains("(Step 7 of 22: Lookup"),
        "the step's sentence"
    );
    assert!(text.contains("(Page 23 of 23)"));
    // The code beside the view, the current line on its band, and the
    // rows the step paints; the labels' glyphs drawn, not spelled.
    assert!(
        text.contains("/BaseFont /Courier"),
        "labels and code in Courier"
    );
    assert!(text.contains("( 13    e := v.incidentEdge;)"), "the code");
    assert!(text.contains("0.85 0.92 1 rg"), "the current line's band");
    assert!(
        text.contains("(Edges \\(the rows painted at this step\\))"),
        "the painted rows"
    );
    assert!(!text.contains("->"), "no arrow spelled out");
    assert!(!text.contains(": ok"), "no check mark spelled out");

    // An edit: the pages follow the mesh as the run changes it.
    let mut harness = support::harness_with("octahedron", Some(Structure::HalfEdge));
    support::run_flip_edge(&mut harness, 0);
    let (name, pdf) = harness.state().export_handout().expect("a handout");
    keep(&name, &pdf);
    let steps = harness.state().state().trace.expect("tracing").steps;
    assert_eq!(page_count(&pdf), steps + 1);
    let text = String::from_utf8_lossy(&pdf);
    assert!(text.contains("Write"), "the writes have pages");

    let mut harness = support::harness_with("cube", None);
    harness.run();
    let error = harness.state().export_handout().expect_err("no run");
    assert_eq!(
        error.as_str(),
        "run an algorithm first: a handout has a page per step of its run"
    );
}

#[test]
fn a_mesh_too_large_for_a_vector_picture_is_refused() {
    let mut harness = support::harness_with("icosphere-20k", None);
    harness.run();
    assert!(harness.state().export_svg().is_ok(), "20,480 faces draw");
    let mut harness = support::harness_with("torus-200k", None);
    for _ in 0..600 {
        harness.step();
        if harness.state().state().job.is_none() {
            break;
        }
    }
    let error = harness.state().export_svg().expect_err("too large");
    assert_eq!(
        error.as_str(),
        "torus-200k has 199712 faces; a vector picture holds at most 50000: save a PNG of it instead"
    );
}
