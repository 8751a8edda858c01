//! Golden tests: rendered error messages of a corpus of broken algorithms,
//! traces of library algorithms on small meshes, and disassembly. The
//! expected files live in tests/algorithms/ at the workspace root; run with
//! `EDGEWISE_BLESS=1` to rewrite them after an intended change.

use crate::golden;

use crate::lang_support::*;
use edgewise_core::lang::{self, Program, RunOptions, Topology, Value};
use edgewise_core::mesh::generate;
use std::fmt::Write as _;
use std::fs;
use std::path::{Path, PathBuf};

fn golden_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../tests/algorithms")
}

#[test]
fn error_corpus_renders_as_recorded() {
    let folder = golden_root().join("errors");
    let mut cases: Vec<PathBuf> = fs::read_dir(&folder)
        .expect("tests/algorithms/errors exists")
        .map(|entry| entry.expect("readable folder").path())
        .filter(|path| path.extension().is_some_and(|e| e == "alg"))
        .collect();
    cases.sort();
    assert!(cases.len() >= 30, "only {} broken algorithms", cases.len());
    let mut problems = Vec::new();
    for case in &cases {
        let source = fs::read_to_string(case).expect("readable case");
        let name = case
            .file_name()
            .expect("a file")
            .to_string_lossy()
            .into_owned();
        let diagnostics = lang::check(&source);
        if diagnostics.is_empty() {
            problems.push(format!("{name} compiled without errors"));
            continue;
        }
        let rendered = lang::render_all(&diagnostics, &source, Some(&name));
        problems.extend(golden::compare(&case.with_extension("txt"), &rendered));
    }
    golden::assert_none(&problems);
}

/// Runtime errors: each file in tests/algorithms/runtime/ runs its last
/// algorithm on the tetrahedron of its structure, every element input 0
/// and every number 0 (a `// step limit: N` line raises the limit); the
/// trace's last steps and the error are the golden text.
#[test]
fn runtime_errors_render_as_recorded() {
    let folder = golden_root().join("runtime");
    let mut cases: Vec<PathBuf> = fs::read_dir(&folder)
        .expect("tests/algorithms/runtime exists")
        .map(|entry| entry.expect("readable folder").path())
        .filter(|path| path.extension().is_some_and(|e| e == "alg"))
        .collect();
    cases.sort();
    let tetrahedron = generate::tetrahedron();
    let (winged_mesh, half_mesh) = (winged(&tetrahedron), half(&tetrahedron));
    let mut problems = Vec::new();
    for case in &cases {
        let source = fs::read_to_string(case).expect("readable case");
        let name = case.file_name().expect("a file").to_string_lossy();
        let program =
            lang::compile_rendered(&source, Some(&name)).unwrap_or_else(|e| panic!("{e}"));
        let algorithm = program.algorithms.last().expect("an algorithm");
        let step_limit = source
            .lines()
            .find_map(|line| line.strip_prefix("// step limit: "))
            .map_or(lang::DEFAULT_STEP_LIMIT, |n| {
                n.trim().parse().expect("a number")
            });
        let args: Vec<(&str, Value)> = algorithm
            .params()
            .map(|p| {
                let value = match p.ty.element_kind() {
                    Some(kind) => Value::from(edgewise_core::schema::ElementRef::new(kind, 0)),
                    None => p.ty.default_value(),
                };
                (p.name.as_str(), value)
            })
            .collect();
        let topology: &dyn Topology = match algorithm.structure {
            edgewise_core::schema::Structure::WingedEdge => &winged_mesh,
            edgewise_core::schema::Structure::HalfEdge => &half_mesh,
        };
        let trace = lang::run(
            algorithm,
            &topology,
            &args,
            RunOptions {
                step_limit,
                ..RunOptions::default()
            },
        )
        .expect("inputs fit");
        assert!(trace.outcome().error().is_some(), "{name} ran to the end");
        let lines: Vec<String> = (0..trace.len()).map(|i| trace.render_line(i)).collect();
        let shown = lines.len().saturating_sub(6);
        let mut out = String::new();
        if shown > 0 {
            let _ = writeln!(out, "… {shown} steps before");
        }
        for line in &lines[shown..] {
            let _ = writeln!(out, "{line}");
        }
        if let Some(error) = trace.outcome().error() {
            let _ = writeln!(out, "error: {error}");
        }
        problems.extend(golden::compare(&case.with_extension("txt"), &out));
    }
    golden::assert_none(&problems);
}

#[test]
fn every_error_points_into_its_file() {
    for entry in fs::read_dir(golden_root().join("errors")).expect("folder") {
        let path = entry.expect("entry").path();
        if path.extension().is_none_or(|e| e != "alg") {
            continue;
        }
        let source = fs::read_to_string(&path).expect("readable");
        for diagnostic in lang::check(&source) {
            assert!(
                diagnostic.span.end as usize <= source.len(),
                "{}: {diagnostic:?}",
                path.display()
            );
            assert!(!diagnostic.message.is_empty());
        }
    }
}

/// The traversal libraries of the two structures.
fn library() -> (Program, Program) {
    let take = |name: &str| {
        lang::library::program(name)
            .expect("shipped")
            .expect("the library compiles")
    };
    (take("winged-edge.alg"), take("half-edge.alg"))
}

#[test]
fn editing_disassembly_renders_as_recorded() {
    let programs = lang::library::load().expect("the library compiles");
    let mut problems = Vec::new();
    for (program, (file, _)) in programs.iter().zip(lang::library::SOURCES) {
        let Some(stem) = file.strip_suffix("-edits.alg") else {
            continue;
        };
        let text = lang::disassemble_all(program.algorithms.iter().map(AsRef::as_ref));
        problems.extend(golden::compare(
            &golden_root().join(format!("disasm/{stem}-edits.txt")),
            &text,
        ));
    }
    golden::assert_none(&problems);
}

fn trace_text(
    program: &Program,
    name: &str,
    topology: &dyn Topology,
    mesh: &str,
    args: &[(&str, Value)],
) -> String {
    let algorithm = program.algorithm(name).expect("in the library");
    let trace = lang::run(algorithm, &topology, args, RunOptions::default()).expect("inputs fit");
    let shown: Vec<String> = args.iter().map(|(n, v)| format!("{n} = {v}")).collect();
    let mut out = String::new();
    let _ = writeln!(
        out,
        "# {} on the {mesh} ({}), {}",
        algorithm.name,
        algorithm.structure,
        shown.join(", ")
    );
    out.push_str(&trace.render());
    out
}

#[test]
fn library_traces_render_as_recorded() {
    let (winged_lib, half_lib) = library();
    let tetra = generate::regular_tetrahedron();
    let (we_tetra, he_tetra) = (winged(&tetra), half(&tetra));
    let cube = generate::cube_zyx();
    let (we_cube, he_cube) = (winged(&cube), half(&cube));
    let octa = octahedron();
    let grid = generate::grid(2, 2);
    let (we_grid, he_grid) = (winged(&grid), half(&grid));
    let table_2 = generate::table_2();
    let v = |i| [("v", Value::Vertex(i))];
    let f = |i| [("f", Value::Face(i))];
    let e = |i| [("e", Value::Edge(i))];
    let cases: Vec<(&str, String)> = vec![
        (
            "table-2-vertexAdjacentEdge-A",
            trace_text(
                &winged_lib,
                "vertexAdjacentEdge",
                &table_2,
                "tetrahedron of Table 2",
                &v(0),
            ),
        ),
        (
            "winged-tetrahedron-vertexAdjacentEdge",
            trace_text(
                &winged_lib,
                "vertexAdjacentEdge",
                &we_tetra,
                "tetrahedron",
                &v(0),
            ),
        ),
        (
            "half-tetrahedron-vertexAdjacentEdge",
            trace_text(
                &half_lib,
                "vertexAdjacentEdge",
                &he_tetra,
                "tetrahedron",
                &v(0),
            ),
        ),
        (
            "winged-tetrahedron-vertexOppositeFace",
            trace_text(
                &winged_lib,
                "vertexOppositeFace",
                &we_tetra,
                "tetrahedron",
                &v(2),
            ),
        ),
        (
            "winged-cube-vertexValence",
            trace_text(&winged_lib, "vertexValence", &we_cube, "cube", &v(0)),
        ),
        (
            "half-cube-isExtraordinary",
            trace_text(&half_lib, "isExtraordinary", &he_cube, "cube", &v(5)),
        ),
        (
            "half-cube-faceAdjacentVertex",
            trace_text(&half_lib, "faceAdjacentVertex", &he_cube, "cube", &f(0)),
        ),
        (
            "winged-cube-faceOppositeFace",
            trace_text(&winged_lib, "faceOppositeFace", &we_cube, "cube", &f(1)),
        ),
        (
            "half-cube-vertexLink",
            trace_text(&half_lib, "vertexLink", &he_cube, "cube", &v(0)),
        ),
        (
            "half-octahedron-vertexOppositeVertex",
            trace_text(
                &half_lib,
                "vertexOppositeVertex",
                &half(&octa),
                "octahedron",
                &v(0),
            ),
        ),
        (
            "winged-grid-boundaryLoop",
            trace_text(
                &winged_lib,
                "boundaryLoop",
                &we_grid,
                "2×2 quad grid",
                &e(0),
            ),
        ),
        (
            "half-grid-vertexAdjacentFace-at-corner",
            trace_text(
                &half_lib,
                "vertexAdjacentFace",
                &he_grid,
                "2×2 quad grid",
                &v(0),
            ),
        ),
        (
            "winged-grid-vertexAdjacentFace-at-corner",
            trace_text(
                &winged_lib,
                "vertexAdjacentFace",
                &we_grid,
                "2×2 quad grid",
                &v(2),
            ),
        ),
        (
            "half-grid-vertexAdjacentFaceOpen-at-corner",
            trace_text(
                &half_lib,
                "vertexAdjacentFaceOpen",
                &he_grid,
                "2×2 quad grid",
                &v(0),
            ),
        ),
    ];
    let folder = golden_root().join("traces");
    let problems: Vec<String> = cases
        .iter()
        .filter_map(|(name, text)| golden::compare(&folder.join(format!("{name}.txt")), text))
        .collect();
    golden::assert_none(&problems);
}

#[test]
fn disassembly_renders_as_recorded() {
    let (winged_lib, half_lib) = library();
    let mut problems = Vec::new();
    for (program, file) in [(&winged_lib, "winged-edge"), (&half_lib, "half-edge")] {
        let text = lang::disassemble_all(program.algorithms.iter().map(AsRef::as_ref));
        problems.extend(golden::compare(
            &golden_root().join(format!("disasm/{file}.txt")),
            &text,
        ));
    }
    golden::assert_none(&problems);
}
