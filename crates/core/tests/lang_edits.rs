//! Editing algorithms of the library, traced: on every sample and every
//! element, an edit either refuses before writing anything or leaves a
//! mesh that validates, with V, E and F changed as its formula says; and
//! the trace's changes step the mesh back and forth exactly.

mod lang_support;

use edgewise_core::lang::{self, Program, RunOptions, RuntimeErrorKind, Value};
use edgewise_core::mesh::{Edit, Mesh, Polygons};
use edgewise_core::schema::{ElementKind, ElementRef, Records};
use lang_support::*;
use std::sync::Arc;

fn library(name: &str) -> Program {
    let (file, text) = lang::library::SOURCES
        .iter()
        .find(|(file, _)| *file == name)
        .expect("the library file exists");
    lang::compile_rendered(text, Some(file)).expect("the library compiles")
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
                &[("h", Value::from(edge))],
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

mod golden;

/// A traced flip and split, step by step, with every write and its old
/// value: what a student steps through.
#[test]
fn traced_edits_render_as_recorded() {
    let program = library("half-edge-edits.alg");
    let mut out = String::new();
    // Two triangles on the same three vertices: no edge of it can split.
    let dihedron = Polygons::from_triangles(
        vec![glam::Vec3::ZERO, glam::Vec3::X, glam::Vec3::Y],
        &[[0, 1, 2], [1, 0, 2]],
    );
    for (name, polygons, edge) in [
        ("flipEdge", octahedron(), 0),
        ("splitEdge", edgewise_core::mesh::generate::tetrahedron(), 0),
        ("splitEdge", dihedron, 0),
    ] {
        let algorithm = program.algorithm(name).expect("shipped");
        let mut mesh = half_edge(&polygons);
        let trace = lang::run_editing(
            algorithm,
            &mut mesh,
            &[("h", Value::Edge(edge))],
            RunOptions::default(),
        )
        .expect("inputs fit");
        out.push_str(&format!("# {name} on half-edge {edge}\n"));
        out.push_str(&trace.render());
        out.push_str("changes:\n");
        for change in trace.changes() {
            out.push_str(&format!("  {change}\n"));
        }
        out.push('\n');
    }
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../tests/algorithms/edits/half-edge.txt");
    let problems: Vec<String> = golden::compare(&path, &out).into_iter().collect();
    golden::assert_none(&problems);
}

/// The traced library edits and the native operations (the CLI's and the
/// JS API's) agree: on every edge where the native one applies, the traced
/// one leaves identical tables; where it refuses, so does the traced one.
#[test]
fn traced_edits_match_the_native_operations() {
    use edgewise_core::mesh::operations::{self, Operation};
    let program = library("half-edge-edits.alg");
    for (name, operation) in [
        ("flipEdge", Operation::FlipEdge),
        ("splitEdge", Operation::SplitEdge),
    ] {
        let algorithm = program.algorithm(name).expect("shipped");
        let mut compared = 0;
        for (sample, polygons) in closed_samples().into_iter().chain(open_samples()) {
            let original = half_edge(&polygons);
            for id in 0..original.count(ElementKind::Edge) as u32 {
                let context = format!("{name} on {sample}, half-edge {id}");
                let mut native = original.clone();
                let native_result = operations::apply(&mut native, operation, &[id]);
                let mut traced = original.clone();
                let trace = lang::run_editing(
                    algorithm,
                    &mut traced,
                    &[("h", Value::Edge(id))],
                    RunOptions::default(),
                )
                .expect("inputs fit");
                match (&native_result, trace.outcome().error()) {
                    (Ok(_), None) => {
                        assert_eq!(traced, native, "{context}");
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
