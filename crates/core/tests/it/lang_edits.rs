//! Editing algorithms of the library, traced: on every sample and every
//! element, an edit either refuses before writing anything or leaves a
//! mesh that validates, with V, E and F changed as its formula says; and
//! the trace's changes step the mesh back and forth exactly.

use crate::lang_support::*;
use edgewise_core::lang::{self, Program, RunOptions, RuntimeErrorKind, Value};
use edgewise_core::mesh::{Edit, Mesh, Polygons};
use edgewise_core::schema::{ElementKind, ElementRef, Records};
use std::sync::Arc;

fn library(name: &str) -> Program {
    lang::library::program(name)
        .expect("the library file exists")
        .expect("the library compiles")
}

fn counts(mesh: &Mesh) -> [i64; 3] {
    let stats = mesh.stats();
    [stats.vertices, stats.edges, stats.faces].map(|n| n as i64)
}

/// Runs `name` on every edge of every sample (both halves, in a half-edge
/// mesh) and checks each outcome; returns how many ran to the end.
fn every_edge(
    program: &Program,
    name: &str,
    structure: fn(&Polygons) -> Mesh,
    delta: impl Fn(&Mesh, ElementRef) -> [i64; 3],
) -> usize {
    let algorithm = Arc::clone(program.algorithm(name).expect("in the library"));
    let param = algorithm
        .params()
        .next()
        .expect("an edge parameter")
        .name
        .clone();
    let mut finished = 0;
    for (sample, polygons) in closed_samples().into_iter().chain(open_samples()) {
        let original = structure(&polygons);
        for id in 0..original.count(ElementKind::Edge) as u32 {
            let edge = ElementRef::new(ElementKind::Edge, id);
            let mut mesh = original.clone();
            let expected = delta(&mesh, edge);
            let trace = lang::run_editing(
                &algorithm,
                &mut mesh,
                &[(param.as_str(), Value::from(edge))],
                RunOptions::default(),
            )
            .expect("inputs fit");
            let context = format!("{name} on {sample}, {edge}");
            match trace.outcome().error() {
                Some(error) => {
                    assert_eq!(error.kind, RuntimeErrorKind::Refused, "{context}: {error}");
                    assert_eq!(trace.changes().len(), 0, "{context} wrote before refusing");
                    assert_eq!(mesh, original, "{context}");
                    continue;
                }
                None => finished += 1,
            }
            let issues = mesh.validate();
            assert!(
                issues.is_empty(),
                "{context}: {issues:#?}\n{}",
                trace.render()
            );
            let [v0, e0, f0] = counts(&original);
            let [v1, e1, f1] = counts(&mesh);
            assert_eq!([v1 - v0, e1 - e0, f1 - f0], expected, "{context}");
            let after = mesh.clone();
            trace
                .seek(&mut mesh, trace.changes().len(), 0)
                .expect("reverts");
            assert_eq!(mesh, original, "{context}: reverting");
            trace
                .seek(&mut mesh, 0, trace.changes().len())
                .expect("replays");
            assert_eq!(mesh, after, "{context}: replaying");
            let mut compacted = mesh.clone();
            compacted.compact();
            assert!(compacted.validate().is_empty(), "{context}: compacted");
        }
    }
    finished
}

fn half_edge(polygons: &Polygons) -> Mesh {
    Mesh::Half(half(polygons))
}

fn winged_edge(polygons: &Polygons) -> Mesh {
    Mesh::Winged(winged(polygons))
}

#[test]
fn flipping_keeps_the_counts() {
    let program = library("half-edge-edits.alg");
    let flipped = every_edge(&program, "flipEdge", half_edge, |_, _| [0, 0, 0]);
    assert!(flipped > 100, "only {flipped} flips ran");
}

#[test]
fn splitting_adds_a_vertex_and_splits_the_triangles_beside() {
    let program = library("half-edge-edits.alg");
    let split = every_edge(&program, "splitEdge", half_edge, |mesh, edge| {
        let triangles = [
            edge,
            mesh.reference(edge, edgewise_core::schema::Column::PairEdge)
                .ok()
                .flatten()
                .expect("paired"),
        ]
        .into_iter()
        .filter(|&h| {
            let face = mesh
                .reference(h, edgewise_core::schema::Column::Face)
                .ok()
                .flatten();
            face.is_some_and(|f| side_count(mesh, f) == 3)
        })
        .count() as i64;
        [1, 1 + triangles, triangles]
    });
    assert!(split > 100, "only {split} splits ran");
}

#[test]
fn winged_flipping_keeps_the_counts() {
    let program = library("winged-edge-edits.alg");
    let flipped = every_edge(&program, "flipEdge", winged_edge, |_, _| [0, 0, 0]);
    assert!(flipped > 50, "only {flipped} flips ran");
}

#[test]
fn winged_splitting_adds_a_vertex_and_splits_the_triangles_beside() {
    use edgewise_core::schema::Column;
    let program = library("winged-edge-edits.alg");
    let split = every_edge(&program, "splitEdge", winged_edge, |mesh, edge| {
        let triangles = [Column::LeftFace, Column::RightFace]
            .into_iter()
            .filter_map(|side| mesh.reference(edge, side).ok().flatten())
            .filter(|&f| winged_side_count(mesh, f) == 3)
            .count() as i64;
        [1, 1 + triangles, triangles]
    });
    assert!(split > 50, "only {split} splits ran");
}

/// The sides of a winged-edge face, going round it by the wings.
fn winged_side_count(mesh: &Mesh, face: ElementRef) -> usize {
    use edgewise_core::schema::Column;
    let reference = |e, column| mesh.reference(e, column).ok().flatten();
    let start = reference(face, Column::IncidentEdge).expect("a face has an edge");
    let mut e = start;
    let mut n = 0;
    loop {
        n += 1;
        let column = if reference(e, Column::RightFace) == Some(face) {
            Column::RightSuccessor
        } else {
            Column::LeftSuccessor
        };
        e = reference(e, column).expect("a successor");
        if e == start || n > 100 {
            return n;
        }
    }
}

/// The flips and splits of the two structures give the same meshes, up to
/// how each numbers its edges: the same V, E and F, and the same faces.
#[test]
fn both_structures_flip_and_split_alike() {
    let half_program = library("half-edge-edits.alg");
    let winged_program = library("winged-edge-edits.alg");
    for polygons in [octahedron(), icosahedron()] {
        let winged_original = winged_edge(&polygons);
        for id in 0..winged_original.count(ElementKind::Edge) as u32 {
            let edge = ElementRef::new(ElementKind::Edge, id);
            let Some((a, b)) = ends(&winged_original, edge) else {
                continue;
            };
            let half_mesh = half_edge(&polygons);
            let half_id = (0..half_mesh.count(ElementKind::Edge) as u32)
                .map(|h| ElementRef::new(ElementKind::Edge, h))
                .find(|&h| ends(&half_mesh, h) == Some((a, b)))
                .expect("the same edge");
            for name in ["flipEdge", "splitEdge"] {
                let mut winged_mesh = winged_original.clone();
                let mut one = half_mesh.clone();
                for (program, mesh, argument, param) in [
                    (&winged_program, &mut winged_mesh, edge, "e"),
                    (&half_program, &mut one, half_id, "h"),
                ] {
                    let algorithm = program.algorithm(name).expect("shipped");
                    let run = lang::execute_editing(
                        algorithm,
                        mesh,
                        &[(param, Value::from(argument))],
                        RunOptions::default(),
                    )
                    .expect("fits");
                    assert_eq!(run.outcome, lang::Outcome::Finished, "{name} {argument}");
                }
                assert_eq!(counts(&winged_mesh), counts(&one), "{name} {edge}");
                assert_eq!(faces(&winged_mesh), faces(&one), "{name} {edge}");
            }
        }
    }
}

/// An edge's start and end vertex ids.
fn ends(mesh: &Mesh, edge: ElementRef) -> Option<(u32, u32)> {
    use edgewise_core::schema::Column;
    let start = mesh.reference(edge, Column::StartVertex).ok()??;
    let end = mesh.reference(edge, Column::EndVertex).ok()??;
    Some((start.id, end.id))
}

/// Every face as its sorted vertex ids, sorted.
fn faces(mesh: &Mesh) -> Vec<Vec<u32>> {
    let polygons = mesh.to_polygons();
    let mut faces: Vec<Vec<u32>> = polygons
        .faces()
        .map(|f| {
            let mut f = f.to_vec();
            f.sort_unstable();
            f
        })
        .collect();
    faces.sort();
    faces
}

fn side_count(mesh: &Mesh, face: ElementRef) -> usize {
    use edgewise_core::schema::Column;
    let start = mesh
        .reference(face, Column::IncidentEdge)
        .ok()
        .flatten()
        .expect("a face has an edge");
    let mut h = start;
    let mut n = 0;
    loop {
        n += 1;
        h = mesh
            .reference(h, Column::SuccessorEdge)
            .ok()
            .flatten()
            .expect("a successor");
        if h == start || n > 100 {
            return n;
        }
    }
}

use crate::golden;

/// A traced flip and split of each structure, step by step, with every
/// write and its old value, and the calls to the helpers indented: what a
/// student steps through.
#[test]
fn traced_edits_render_as_recorded() {
    // Two triangles on the same three vertices: no edge of it can split.
    let dihedron = Polygons::from_triangles(
        vec![glam::Vec3::ZERO, glam::Vec3::X, glam::Vec3::Y],
        &[[0, 1, 2], [1, 0, 2]],
    );
    let mut problems = Vec::new();
    for (file, structure, param, golden) in [
        (
            "half-edge-edits.alg",
            half_edge as fn(&Polygons) -> Mesh,
            "h",
            "half-edge",
        ),
        ("winged-edge-edits.alg", winged_edge, "e", "winged-edge"),
    ] {
        let program = library(file);
        let mut out = String::new();
        for (name, polygons, edge) in [
            ("flipEdge", octahedron(), 0),
            ("splitEdge", edgewise_core::mesh::generate::tetrahedron(), 0),
            ("splitEdge", dihedron.clone(), 0),
        ] {
            let algorithm = program.algorithm(name).expect("shipped");
            let mut mesh = structure(&polygons);
            let trace = lang::run_editing(
                algorithm,
                &mut mesh,
                &[(param, Value::Edge(edge))],
                RunOptions::default(),
            )
            .expect("inputs fit");
            out.push_str(&format!("# {name} on {golden} {edge}\n"));
            out.push_str(&trace.render());
            out.push_str("changes:\n");
            for change in trace.changes() {
                out.push_str(&format!("  {change}\n"));
            }
            out.push('\n');
        }
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join(format!("../../tests/algorithms/edits/{golden}.txt"));
        problems.extend(golden::compare(&path, &out));
    }
    golden::assert_none(&problems);
}

/// The traced library edits and the native operations (the CLI's and the
/// JS API's) agree: on every edge where the native one applies, the traced
/// one leaves identical tables; where it refuses, so does the traced one.
#[test]
fn traced_edits_match_the_native_operations() {
    use edgewise_core::mesh::operations::{self, Operation};
    for (file, structure, param) in [
        (
            "half-edge-edits.alg",
            half_edge as fn(&Polygons) -> Mesh,
            "h",
        ),
        ("winged-edge-edits.alg", winged_edge, "e"),
    ] {
        let program = library(file);
        for (name, operation) in [
            ("flipEdge", Operation::FlipEdge),
            ("splitEdge", Operation::SplitEdge),
        ] {
            let algorithm = program.algorithm(name).expect("shipped");
            let mut compared = 0;
            for (sample, polygons) in closed_samples().into_iter().chain(open_samples()) {
                let original = structure(&polygons);
                for id in 0..original.count(ElementKind::Edge) as u32 {
                    let context = format!("{file} {name} on {sample}, edge {id}");
                    let mut native = original.clone();
                    let native_result = operations::apply(&mut native, operation, &[id]);
                    let mut traced = original.clone();
                    let trace = lang::run_editing(
                        algorithm,
                        &mut traced,
                        &[(param, Value::Edge(id))],
                        RunOptions::default(),
                    )
                    .expect("inputs fit");
                    match (&native_result, trace.outcome().error()) {
                        (Ok(_), None) => {
                            assert!(
                                traced == native,
                                "{context}: {}",
                                differences(&traced, &native)
                            );
                            compared += 1;
                        }
                        (Err(_), Some(_)) => {}
                        (Ok(_), Some(error)) => {
                            panic!("{context}: only the traced one refused: {error}")
                        }
                        (Err(refusal), None) => {
                            panic!("{context}: only the native one refused: {refusal}")
                        }
                    }
                }
            }
            assert!(compared > 100, "{name}: only {compared} compared");
        }
    }
}

/// The rows where two meshes of one structure differ, as `traced | native`.
fn differences(traced: &Mesh, native: &Mesh) -> String {
    use edgewise_core::schema::{Column, ElementRef};
    let mut out = String::new();
    for kind in ElementKind::ALL {
        let rows = traced.count(kind).max(native.count(kind)) as u32;
        for id in 0..rows {
            let element = ElementRef::new(kind, id);
            for entry in Column::table(traced.structure(), kind) {
                let (a, b) = (
                    traced.reference(element, entry.column),
                    native.reference(element, entry.column),
                );
                if a != b {
                    out.push_str(&format!("\n  {element} {}: {a:?} | {b:?}", entry.header));
                }
            }
        }
    }
    out
}

#[test]
fn helpers_are_the_algorithms_the_others_call() {
    for file in ["half-edge-edits.alg", "winged-edge-edits.alg"] {
        let program = library(file);
        let helper = |name: &str| program.algorithm(name).expect("shipped").is_helper();
        assert!(!helper("flipEdge") && !helper("splitEdge"), "{file}");
        assert!(
            helper("isTriangle") && helper("joined") && helper("cutCorner"),
            "{file}"
        );
    }
}
