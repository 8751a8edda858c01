//! `edgewise render`: the app's SVG pictures and PDF handouts from the
//! command line, byte for byte what the app exports, and every mistake
//! refused with the option or file it comes from.

use crate::common::{code, root, run, scratch, stderr, stdout};
use edgewise_core::schema::{ElementKind, ElementRef};
use edgewise_model::still::Still;

/// Pages of a handout: each page object has `/Type /Page` followed by a
/// space, where the page tree has `/Type /Pages`.
fn pages(pdf: &[u8]) -> usize {
    let needle = b"/Type /Page ";
    pdf.windows(needle.len()).filter(|w| w == needle).count()
}

#[test]
fn an_svg_is_the_models_picture_of_the_moment() {
    let dir = scratch("render-svg");
    let out = dir.join("edge.svg");
    let output = run(&[
        "render",
        &out.to_string_lossy(),
        "meshes/tetrahedron.wtb",
        "--select",
        "e0",
        "--size",
        "640x480",
    ]);
    assert_eq!(code(&output), 0, "{}", stderr(&output));
    assert!(stdout(&output).starts_with("wrote "), "{}", stdout(&output));
    let written = std::fs::read_to_string(&out).expect("the SVG is written");

    // The app's own export is held to the same `Still` by the app's tests
    // (`still.rs` there).
    let mut still = Still::new(false);
    let bytes = std::fs::read(root().join("meshes/tetrahedron.wtb")).expect("the sample");
    still
        .load_mesh(&bytes, "meshes/tetrahedron.wtb", None)
        .expect("opens");
    still.lay_out(640.0, 480.0);
    still
        .select(Some(ElementRef::new(ElementKind::Edge, 0)))
        .expect("selects");
    let exported = still.svg().expect("exports");
    assert_eq!(written, exported);
    assert!(written.contains("width=\"640\""), "{written}");
    assert!(written.contains(">left predecessor</text>"), "{written}");
    assert!(
        written.contains("Edge 0 selected:"),
        "the caption: {written}"
    );
}

#[test]
fn a_pdf_has_a_page_per_step_of_the_run() {
    let dir = scratch("render-pdf");
    let out = dir.join("handout.pdf");
    let output = run(&[
        "render",
        &out.to_string_lossy(),
        "meshes/tetrahedron.wtb",
        "--run",
        "vertexAdjacentEdge",
        "--arg",
        "v=1",
    ]);
    assert_eq!(code(&output), 0, "{}", stderr(&output));
    let pdf = std::fs::read(&out).expect("the PDF is written");
    assert!(pdf.starts_with(b"%PDF-1.4\n"));
    // Table 2 from vertex 1: 22 steps, and the start.
    assert_eq!(pages(&pdf), 23);
    let text = String::from_utf8_lossy(&pdf);
    assert!(text.contains("(Step 2 of 22: Assignment: e := edge 1)"));
    assert!(text.contains("(Page 23 of 23)"));
}

#[test]
fn an_editing_run_and_an_algorithm_file_make_a_handout() {
    let dir = scratch("render-edit");
    let out = dir.join("flip.pdf");
    let output = run(&[
        "render",
        &out.to_string_lossy(),
        "meshes/octahedron.obj",
        "--structure",
        "half",
        "--alg",
        "algorithms/half-edge-edits.alg",
        "--run",
        "flipEdge",
        "--arg",
        "h=0",
    ]);
    assert_eq!(code(&output), 0, "{}", stderr(&output));
    let pdf = std::fs::read(&out).expect("the PDF is written");
    let trace = run(&[
        "trace",
        "algorithms/half-edge-edits.alg",
        "flipEdge",
        "meshes/octahedron.obj",
        "--arg",
        "h=0",
    ]);
    assert_eq!(code(&trace), 0, "{}", stderr(&trace));
    let steps = stdout(&trace)
        .lines()
        .filter(|line| line.starts_with("step "))
        .count();
    assert!(steps > 50, "{}", stdout(&trace));
    assert_eq!(pages(&pdf), steps + 1);
}

#[test]
fn a_course_link_sets_up_the_picture() {
    let dir = scratch("render-link");
    let out = dir.join("step4.svg");
    let output = run(&[
        "render",
        &out.to_string_lossy(),
        "--link",
        "https://example.edu/edgewise/?sample=cube&algorithm=vertexAdjacentEdge&args=v:0&step=4&theme=dark",
    ]);
    assert_eq!(code(&output), 0, "{}", stderr(&output));
    let svg = std::fs::read_to_string(&out).expect("the SVG is written");
    assert!(
        svg.contains("<title>Edgewise: vertexAdjacentEdge on cube.htb</title>"),
        "{svg}"
    );
    assert!(
        svg.contains("Step 4 of 23: Assignment: se := edge 3"),
        "{svg}"
    );
    // The dark theme's background.
    assert!(svg.contains("fill=\"#1e1f22\""), "{svg}");
}

#[test]
fn every_mistake_names_its_option_or_file() {
    let dir = scratch("render-mistakes");
    let bad = dir.join("bad.obj");
    std::fs::write(&bad, "v 0 0 0\nf 1 2 x\n").expect("writable");
    let bad = bad.to_string_lossy().into_owned();
    let out = dir.join("out.svg");
    let out = out.to_string_lossy().into_owned();
    let pdf = dir.join("out.pdf");
    let pdf = pdf.to_string_lossy().into_owned();
    let tetra = "meshes/tetrahedron.wtb";
    let cases: &[(&[&str], i32, &str)] = &[
        (
            &["x.png", tetra],
            2,
            "edgewise: x.png: expected an output ending in .svg",
        ),
        (
            &[&out],
            2,
            "edgewise: give a mesh file, or a course link with --link that names one",
        ),
        (
            &[&out, tetra, "--size", "10x10"],
            2,
            "edgewise: --size 10x10: expected WIDTHxHEIGHT in points, each from 120 to 4096",
        ),
        (
            &[&out, tetra, "--arg", "v=1"],
            2,
            "edgewise: --alg and --arg need --run NAME",
        ),
        (
            &[&out, tetra, "--run", "vertexAdjacentEdge", "--arg", "v=x"],
            2,
            "edgewise: --arg v=x: expected NAME=VALUE",
        ),
        (
            &[&out, tetra, "--run", "vertexAdjacentEdge"],
            1,
            "--arg: no value given for parameter `v` (Vertex); give each input as --arg NAME=VALUE",
        ),
        (
            &[&out, tetra, "--run", "vertexAdjacentEdge", "--arg", "v=99"],
            1,
            "--run: parameter `v`: vertex 99 does not exist (the mesh has 4 vertices)",
        ),
        (
            &[&out, tetra, "--run", "noSuchAlgorithm"],
            1,
            "--run: there is no algorithm called `noSuchAlgorithm`",
        ),
        (
            &[
                &out,
                tetra,
                "--run",
                "vertexAdjacentEdge",
                "--arg",
                "v=1",
                "--step",
                "99",
            ],
            2,
            "edgewise: --step 99: the run has steps 0 to 22",
        ),
        (
            &[&out, tetra, "--step", "2"],
            2,
            "edgewise: --step needs a run",
        ),
        (
            &[&out, tetra, "--select", "q3"],
            2,
            "edgewise: --select: `q3`: type an element as vertex, edge or face and its id",
        ),
        (
            &[&out, tetra, "--select", "e99"],
            1,
            "--select: there is no edge 99 (this mesh has 6, numbered from 0)",
        ),
        (
            &[&pdf, tetra],
            2,
            "edgewise: a .pdf handout has a page per step of a run",
        ),
        (
            &[&out, &bad],
            1,
            "bad.obj:2:7: expected a vertex number (v, v/vt, v//vn or v/vt/vn), found \"x\"",
        ),
        (
            &[&out, tetra, "--alg", &bad, "--run", "x"],
            1,
            "bad.obj:1:1: error: expected `algorithm`, found `v`",
        ),
        (
            &[&out, "--link", "?sample=nope&step=x"],
            1,
            "--link: sample=nope: no sample has that name",
        ),
        (
            &[&out, "--link", "?mesh=../secret.obj"],
            1,
            "--link: mesh=../secret.obj: expected a path inside the app's folder",
        ),
        (
            &[&out, "--link", "?theme=dark"],
            2,
            "edgewise: the link names no mesh",
        ),
        (
            &[&out, tetra, "--link", "?sample=cube"],
            2,
            "the link carries its own mesh; give the file or the link's mesh, not both",
        ),
    ];
    for (args, expected_code, message) in cases {
        let mut all = vec!["render"];
        all.extend_from_slice(args);
        let output = run(&all);
        let stderr = stderr(&output);
        assert_eq!(code(&output), *expected_code, "{args:?}: {stderr}");
        assert!(stderr.contains(message), "{args:?}: {stderr}");
        assert!(
            !std::path::Path::new(&out).exists(),
            "{args:?} wrote a picture"
        );
    }
}
