//! The library's Loop subdivision pass, traced, checked against Loop's
//! rules computed here from the polygons: every triangle is cut in the four
//! the scheme makes, each new vertex sits at its edge point, each old vertex
//! moves by Warren's weights (or the boundary rule), and the trace steps
//! the mesh back to where it started.

use std::collections::{BTreeMap, BTreeSet};

use crate::lang_support::*;
use edgewise_core::lang::{self, RunOptions, RuntimeErrorKind, Value};
use edgewise_core::mesh::{Mesh, Polygons, generate};
use edgewise_core::schema::{ElementKind, Records};
use glam::Vec3;

fn subdivide(polygons: &Polygons) -> (Mesh, lang::Trace) {
    let program = lang::library::program("half-edge-subdivision.alg")
        .expect("the library file exists")
        .expect("the library compiles");
    let algorithm = program.algorithm("loopSubdivide").expect("shipped");
    let mut mesh = Mesh::Half(half(polygons));
    let trace = lang::run_editing(
        algorithm,
        &mut mesh,
        &[("f", Value::Face(0))],
        RunOptions::default(),
    )
    .expect("inputs fit");
    (mesh, trace)
}

fn edge_key(a: u32, b: u32) -> (u32, u32) {
    (a.min(b), a.max(b))
}

/// For each edge, the corners opposite it (one on the boundary, two inside).
fn opposite_corners(polygons: &Polygons) -> BTreeMap<(u32, u32), Vec<u32>> {
    let mut corners: BTreeMap<(u32, u32), Vec<u32>> = BTreeMap::new();
    for face in polygons.faces() {
        for i in 0..3 {
            let (a, b, c) = (face[i], face[(i + 1) % 3], face[(i + 2) % 3]);
            corners.entry(edge_key(a, b)).or_default().push(c);
        }
    }
    corners
}

/// Loop's positions: the old vertices' (by id) and each edge's point.
fn loop_positions(polygons: &Polygons) -> (Vec<Vec3>, BTreeMap<(u32, u32), Vec3>) {
    let p = polygons.positions();
    let corners = opposite_corners(polygons);
    let mut neighbours: Vec<BTreeSet<u32>> = vec![BTreeSet::new(); p.len()];
    let mut boundary: Vec<Vec<u32>> = vec![Vec::new(); p.len()];
    let mut points = BTreeMap::new();
    for (&(a, b), opposite) in &corners {
        neighbours[a as usize].insert(b);
        neighbours[b as usize].insert(a);
        let (pa, pb) = (p[a as usize], p[b as usize]);
        let point = match opposite[..] {
            [c, d] => (pa + pb) * 0.375 + (p[c as usize] + p[d as usize]) * 0.125,
            _ => {
                boundary[a as usize].push(b);
                boundary[b as usize].push(a);
                (pa + pb) / 2.0
            }
        };
        points.insert((a, b), point);
    }
    let moved = (0..p.len())
        .map(|v| {
            if let [x, y] = boundary[v][..] {
                return p[v] * 0.75 + (p[x as usize] + p[y as usize]) * 0.125;
            }
            let n = neighbours[v].len() as f32;
            let beta = if neighbours[v].len() == 3 {
                0.1875
            } else {
                3.0 / (8.0 * n)
            };
            let sum: Vec3 = neighbours[v].iter().map(|&w| p[w as usize]).sum();
            p[v] * (1.0 - n * beta) + sum * beta
        })
        .collect();
    (moved, points)
}

/// A face as a tuple starting at its least vertex, keeping its turn.
fn canonical(face: &[u32]) -> Vec<u32> {
    let at = face
        .iter()
        .enumerate()
        .min_by_key(|&(_, v)| v)
        .map_or(0, |(i, _)| i);
    face[at..].iter().chain(&face[..at]).copied().collect()
}

fn close(a: Vec3, b: Vec3) -> bool {
    (a - b).abs().max_element() <= 1e-5 * (1.0 + a.abs().max_element())
}

fn check(name: &str, polygons: &Polygons) {
    let (mesh, trace) = subdivide(polygons);
    assert!(
        trace.outcome().error().is_none(),
        "{name}: {:?}",
        trace.outcome()
    );
    let issues = mesh.validate();
    assert!(issues.is_empty(), "{name}: {issues:#?}");
    let (v, f) = (polygons.vertex_count(), polygons.face_count());
    let e = opposite_corners(polygons).len();
    let stats = mesh.stats();
    assert_eq!(
        [stats.vertices, stats.edges, stats.faces],
        [v + e, 2 * e + 3 * f, 4 * f],
        "{name}: V, E, F"
    );

    let result = mesh.to_polygons();
    let positions = result.positions();
    let (moved, points) = loop_positions(polygons);
    for (id, expected) in moved.iter().enumerate() {
        assert!(
            close(positions[id], *expected),
            "{name}: old vertex {id} at {} not {expected}",
            positions[id]
        );
    }
    // A new vertex is on one old edge: name it by the edge's ends, which
    // are its only old neighbours.
    let old = v as u32;
    let mut old_neighbours: BTreeMap<u32, BTreeSet<u32>> = BTreeMap::new();
    for face in result.faces() {
        for i in 0..face.len() {
            let (a, b) = (face[i], face[(i + 1) % face.len()]);
            if a >= old && b < old {
                old_neighbours.entry(a).or_default().insert(b);
            }
            if b >= old && a < old {
                old_neighbours.entry(b).or_default().insert(a);
            }
        }
    }
    let mut on_edge = BTreeMap::new();
    for (&new, ends) in &old_neighbours {
        let ends: Vec<u32> = ends.iter().copied().collect();
        let [a, b] = ends[..] else {
            panic!("{name}: new vertex {new} touches old vertices {ends:?}");
        };
        let expected = points[&edge_key(a, b)];
        assert!(
            close(positions[new as usize], expected),
            "{name}: vertex {new} on edge {a}–{b} at {} not {expected}",
            positions[new as usize]
        );
        on_edge.insert(edge_key(a, b), new);
    }
    assert_eq!(on_edge.len(), e, "{name}: one new vertex per edge");

    // The four triangles of each old one, turning the same way.
    let mid = |a: u32, b: u32| on_edge[&edge_key(a, b)];
    let mut expected: Vec<Vec<u32>> = Vec::new();
    for face in polygons.faces() {
        let (a, b, c) = (face[0], face[1], face[2]);
        let (ab, bc, ca) = (mid(a, b), mid(b, c), mid(c, a));
        expected.extend([
            vec![a, ab, ca],
            vec![b, bc, ab],
            vec![c, ca, bc],
            vec![ab, bc, ca],
        ]);
    }
    let mut expected: Vec<Vec<u32>> = expected.iter().map(|f| canonical(f)).collect();
    let mut made: Vec<Vec<u32>> = result.faces().map(canonical).collect();
    expected.sort();
    made.sort();
    assert_eq!(made, expected, "{name}: the triangles");
}

#[test]
fn loop_subdivision_cuts_each_triangle_in_four_and_moves_by_loops_weights() {
    let hexagon = generate::hexagon();
    let mut samples = vec![
        ("tetrahedron", generate::regular_tetrahedron()),
        ("octahedron", octahedron()),
        ("icosahedron", icosahedron()),
        ("triangle torus 6×4", generate::torus(6, 4)),
        ("hexagon", hexagon),
    ];
    samples.extend(
        open_samples()
            .into_iter()
            .filter(|(_, p)| p.faces().all(|f| f.len() == 3)),
    );
    assert!(samples.len() >= 7, "{}", samples.len());
    for (name, polygons) in &samples {
        check(name, polygons);
    }
}

/// Thousands of records: the 24 × 12 torus (576 triangles) becomes 2,304,
/// within the default step limit, and the trace steps it back exactly.
#[test]
fn a_pass_over_thousands_of_records_replays_both_ways() {
    let polygons = generate::torus(24, 12);
    check("torus 24×12", &polygons);
    let (mut mesh, trace) = subdivide(&polygons);
    let changes = trace.changes().len();
    assert!(changes > 10_000, "only {changes} changes");
    let after = mesh.clone();
    trace.seek(&mut mesh, changes, 0).expect("reverts");
    assert_eq!(mesh, Mesh::Half(half(&polygons)));
    trace.seek(&mut mesh, 0, changes).expect("replays");
    assert_eq!(mesh, after);
}

#[test]
fn a_mesh_with_a_quad_is_refused_before_any_write() {
    let (mesh, trace) = subdivide(&generate::cube());
    let error = trace.outcome().error().expect("refused");
    assert_eq!(error.kind, RuntimeErrorKind::Refused);
    assert!(
        error
            .message
            .contains("is not a triangle; Loop subdivision cuts triangles"),
        "{error}"
    );
    assert_eq!(trace.changes().len(), 0);
    assert_eq!(mesh.count(ElementKind::Face), 6);
}
