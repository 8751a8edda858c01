//! The algorithm library, proved against brute-force answers: every
//! algorithm, both structures, every element of every sample mesh, plus
//! random meshes.

use crate::lang_support::*;
use edgewise_core::lang::{
    self, Algorithm, Outcome, Program, RunOptions, Topology, Value, execute,
};
use edgewise_core::mesh::{Polygons, generate};
use edgewise_core::schema::{ElementKind, ElementRef};
use proptest::prelude::*;
use std::sync::Arc;

/// The traversal libraries of the two structures (the editing ones are
/// tested in `lang_edits.rs`).
fn library() -> (Program, Program) {
    let take = |name: &str| {
        lang::library::program(name)
            .expect("shipped")
            .expect("the library compiles")
    };
    (take("winged-edge.alg"), take("half-edge.alg"))
}

fn param_kind(algorithm: &Algorithm) -> ElementKind {
    let param = algorithm
        .params()
        .next()
        .expect("library algorithms take one element");
    param.ty.element_kind().expect("an element parameter")
}

/// Runs `algorithm` on `input` and checks the marked set (and valence)
/// against the brute-force answer; returns a description of any mismatch.
fn check_one(
    algorithm: &Algorithm,
    topology: &dyn Topology,
    polygons: &Polygons,
    input: ElementRef,
) -> Result<(), String> {
    let param = algorithm
        .params()
        .next()
        .expect("one parameter")
        .name
        .clone();
    let expected = brute_force(&algorithm.name, topology, polygons, input)
        .ok_or_else(|| format!("no brute-force answer for {}", algorithm.name))?;
    let run = execute(
        algorithm,
        &topology,
        &[(param.as_str(), Value::from(input))],
        RunOptions::default(),
    )
    .map_err(|e| e.to_string())?;
    if let Outcome::Error(error) = &run.outcome {
        return Err(format!("{} on {input}: {error}", algorithm.name));
    }
    if let Some(valence) = expected.valence {
        let n = run.variable(algorithm, "n");
        if n != Some(Value::Integer(valence)) {
            return Err(format!(
                "{} on {input}: n = {n:?}, expected {valence}",
                algorithm.name
            ));
        }
    }
    let marked = sorted_marked(run.marked.iter().copied());
    if marked != expected.marked {
        return Err(format!(
            "{} ({}) on {input}: marked {marked:?}, expected {:?}",
            algorithm.name, algorithm.structure, expected.marked
        ));
    }
    Ok(())
}

fn all_inputs(topology: &dyn Topology, kind: ElementKind) -> Vec<ElementRef> {
    (0..topology.count(kind) as u32)
        .map(|i| ElementRef::new(kind, i))
        .collect()
}

fn check_everywhere(
    algorithm: &Algorithm,
    topology: &dyn Topology,
    polygons: &Polygons,
    mesh: &str,
) -> usize {
    let mut checked = 0;
    for input in all_inputs(topology, param_kind(algorithm)) {
        if let Err(problem) = check_one(algorithm, topology, polygons, input) {
            panic!("on the {mesh}: {problem}");
        }
        checked += 1;
    }
    checked
}

#[test]
fn both_files_hold_the_same_algorithms_with_descriptions() {
    let (winged, half) = library();
    let names = |p: &Program| p.names().map(str::to_owned).collect::<Vec<_>>();
    assert_eq!(names(&winged), names(&half));
    assert!(winged.algorithms.len() >= 22, "{:?}", names(&winged));
    for algorithm in winged.algorithms.iter().chain(&half.algorithms) {
        assert!(
            algorithm
                .description
                .as_deref()
                .is_some_and(|d| !d.is_empty()),
            "{} has no description",
            algorithm.name
        );
    }
    assert!(
        winged
            .algorithms
            .iter()
            .all(|a| a.structure == edgewise_core::schema::Structure::WingedEdge)
    );
    assert!(
        half.algorithms
            .iter()
            .all(|a| a.structure == edgewise_core::schema::Structure::HalfEdge)
    );
}

#[test]
fn the_readme_lists_every_algorithm() {
    let readme = include_str!("../../../../algorithms/README.md");
    let (winged, _) = library();
    for name in winged.names() {
        assert!(
            readme.contains(&format!("`{name}(")),
            "algorithms/README.md does not list {name}"
        );
    }
}

#[test]
fn every_general_algorithm_matches_brute_force_on_every_closed_mesh() {
    let (winged_lib, half_lib) = library();
    let mut checked = 0;
    for (mesh, polygons) in closed_samples() {
        let we = winged(&polygons);
        let he = half(&polygons);
        for (program, topology) in [
            (&winged_lib, &we as &dyn Topology),
            (&half_lib, &he as &dyn Topology),
        ] {
            for algorithm in program
                .algorithms
                .iter()
                .filter(|a| !is_exercise(&a.name) && a.name != "boundaryLoop")
            {
                checked += check_everywhere(algorithm, topology, &polygons, mesh);
            }
        }
    }
    assert!(checked > 3000, "only {checked} runs");
}

#[test]
fn boundary_aware_algorithms_match_brute_force_on_open_meshes() {
    let (winged_lib, half_lib) = library();
    for (mesh, polygons) in open_samples() {
        let we = winged(&polygons);
        let he = half(&polygons);
        for (program, topology) in [
            (&winged_lib, &we as &dyn Topology),
            (&half_lib, &he as &dyn Topology),
        ] {
            for algorithm in program
                .algorithms
                .iter()
                .filter(|a| applies_on_open_meshes(&a.name))
            {
                check_everywhere(algorithm, topology, &polygons, mesh);
            }
        }
    }
}

#[test]
fn simple_loops_stop_with_a_message_at_a_boundary() {
    let (winged_lib, half_lib) = library();
    let grid = generate::grid(3, 2);
    let (we, he) = (winged(&grid), half(&grid));
    for (program, topology) in [
        (&winged_lib, &we as &dyn Topology),
        (&half_lib, &he as &dyn Topology),
    ] {
        let algorithm = program
            .algorithm("vertexAdjacentFace")
            .expect("in the library");
        // Vertex 0 is a corner of the grid.
        let run = execute(
            algorithm,
            &topology,
            &[("v", Value::Vertex(0))],
            RunOptions::default(),
        )
        .expect("inputs fit");
        let error = run.outcome.error().expect("a corner has a missing face");
        assert!(error.message.starts_with("cannot mark null: "), "{error}");
        assert!(error.message.contains("is on the boundary"), "{error}");
    }
}

fn exercise(name: &str, polygons: &Polygons, mesh: &str) {
    let (winged_lib, half_lib) = library();
    let (we, he) = (winged(polygons), half(polygons));
    for (program, topology) in [
        (&winged_lib, &we as &dyn Topology),
        (&half_lib, &he as &dyn Topology),
    ] {
        let algorithm = program.algorithm(name).expect("in the library");
        let checked = check_everywhere(algorithm, topology, polygons, mesh);
        assert!(checked > 0);
    }
}

#[test]
fn exercise_opposite_face_of_a_vertex_in_a_tetrahedron() {
    exercise(
        "vertexOppositeFace",
        &generate::regular_tetrahedron(),
        "tetrahedron",
    );
}

#[test]
fn exercise_opposite_face_of_a_face_in_a_cube() {
    exercise("faceOppositeFace", &generate::cube_zyx(), "cube");
}

#[test]
fn exercise_opposite_edges_in_quad_meshes() {
    exercise("edgeOppositeEdges", &generate::cube_zyx(), "cube");
    exercise("edgeOppositeEdges", &quad_torus(5, 4), "quad torus");
    exercise("edgeOppositeEdgesOpen", &generate::grid(3, 3), "quad grid");
    exercise(
        "edgeOppositeEdgesOpen",
        &without_faces(&generate::cube_zyx(), &[2]),
        "cube without a face",
    );
}

#[test]
fn exercise_opposite_vertex_in_an_octahedron() {
    exercise("vertexOppositeVertex", &octahedron(), "octahedron");
}

#[test]
fn exercise_extraordinary_vertices() {
    // Every cube vertex has valence 3; on a quad torus all have valence 4.
    let (winged_lib, _) = library();
    let algorithm = winged_lib
        .algorithm("isExtraordinary")
        .expect("in the library");
    let cube = winged(&generate::cube_zyx());
    let torus = winged(&quad_torus(5, 4));
    let run = |topology: &dyn Topology| {
        execute(
            algorithm,
            &topology,
            &[("v", Value::Vertex(0))],
            RunOptions::default(),
        )
        .expect("inputs fit")
    };
    assert_eq!(run(&cube).marked, [ElementRef::new(ElementKind::Vertex, 0)]);
    assert_eq!(
        run(&cube).messages,
        ["vertex 0 is extraordinary: its valence is 3"]
    );
    assert!(run(&torus).marked.is_empty());
    assert_eq!(
        run(&torus).messages,
        ["vertex 0 is regular: its valence is 4"]
    );
}

#[test]
fn boundary_loop_walks_each_hole() {
    let (winged_lib, half_lib) = library();
    let polygons = without_faces(&quad_torus(5, 4), &[0, 12]);
    let (we, he) = (winged(&polygons), half(&polygons));
    for (program, topology) in [
        (&winged_lib, &we as &dyn Topology),
        (&half_lib, &he as &dyn Topology),
    ] {
        let algorithm = program.algorithm("boundaryLoop").expect("in the library");
        let mut loops = 0;
        for input in all_inputs(topology, ElementKind::Edge) {
            check_one(algorithm, topology, &polygons, input).unwrap_or_else(|p| panic!("{p}"));
            let run = execute(
                algorithm,
                &topology,
                &[("e", Value::from(input))],
                RunOptions::default(),
            )
            .expect("fits");
            if run.marked.len() == 4 {
                loops += 1;
            }
        }
        // Two square holes: 4 boundary edges each, found from each of their
        // edges (and, in half-edge, from each interior twin as well).
        assert!(loops >= 8, "{loops}");
    }
}

/// A random valid mesh: a torus grid (triangles or quads) of random size,
/// or a sample solid, with possibly one face removed to open it.
fn random_mesh() -> impl Strategy<Value = (Polygons, bool)> {
    let torus = (4u32..8, 4u32..7, any::<bool>()).prop_map(|(nu, nv, quads)| {
        if quads {
            quad_torus(nu, nv)
        } else {
            generate::torus(nu, nv)
        }
    });
    let solid = (0usize..10).prop_map(|i| closed_samples().swap_remove(i).1);
    (
        prop_oneof![torus, solid],
        proptest::option::of(0usize..1000),
    )
        .prop_map(|(polygons, remove)| match remove {
            Some(r) => (without_faces(&polygons, &[r % polygons.face_count()]), true),
            None => (polygons, false),
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn library_matches_brute_force_on_random_meshes(
        (polygons, open) in random_mesh(),
        pick in any::<u32>(),
    ) {
        let (winged_lib, half_lib) = library();
        let (we, he) = (winged(&polygons), half(&polygons));
        for (program, topology) in [(&winged_lib, &we as &dyn Topology), (&half_lib, &he as &dyn Topology)] {
            for algorithm in &program.algorithms {
                if is_exercise(&algorithm.name) || (open && !applies_on_open_meshes(&algorithm.name)) {
                    continue;
                }
                if !open && algorithm.name == "boundaryLoop" {
                    continue;
                }
                let kind = param_kind(algorithm);
                let count = topology.count(kind) as u32;
                let input = ElementRef::new(kind, pick % count);
                if let Err(problem) = check_one(algorithm, topology, &polygons, input) {
                    prop_assert!(false, "{}", problem);
                }
            }
        }
    }
}

#[test]
fn library_algorithms_share_the_source_text() {
    let (winged_lib, _) = library();
    let first = &winged_lib.algorithms[0];
    assert!(
        first
            .text()
            .starts_with("algorithm vertexAdjacentEdge(v : Vertex);")
    );
    assert!(
        winged_lib
            .algorithms
            .iter()
            .all(|a| Arc::ptr_eq(&a.source, &winged_lib.source))
    );
}
