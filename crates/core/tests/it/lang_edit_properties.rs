//! Random sequences of traced edits: after every step of the sequence the
//! traced library edit and the native operation agree table for table (or
//! both refuse, the traced one before writing anything), and the mesh
//! validates. The starting meshes are closed and open, triangles and not,
//! in both structures.

use std::sync::Arc;

use edgewise_core::lang::{self, Algorithm, RunOptions, Value};
use edgewise_core::mesh::operations::{self, Operation};
use edgewise_core::mesh::{Mesh, Structure, generate};
use edgewise_core::schema::{ElementKind, Records};
use proptest::prelude::*;

fn library(file: &str, name: &str) -> Arc<Algorithm> {
    let program = lang::library::program(file)
        .expect("the library file exists")
        .expect("the library compiles");
    Arc::clone(program.algorithm(name).expect("in the library"))
}

fn start(which: u8) -> Mesh {
    let polygons = match which % 4 {
        0 => generate::regular_tetrahedron(),
        1 => generate::torus(5, 4),
        2 => generate::hexagon(),
        _ => generate::grid(3, 2),
    };
    let structure = if which % 8 < 4 {
        Structure::HalfEdge
    } else {
        Structure::WingedEdge
    };
    Mesh::build(&polygons, structure).expect("a valid sample").0
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 32, ..ProptestConfig::default() })]

    #[test]
    fn traced_edits_stay_valid_and_match_the_native_ones(
        which in any::<u8>(),
        steps in proptest::collection::vec((any::<bool>(), any::<u16>()), 1..10),
    ) {
        let mut mesh = start(which);
        let (file, param) = match mesh.structure() {
            Structure::HalfEdge => ("half-edge-edits.alg", "h"),
            Structure::WingedEdge => ("winged-edge-edits.alg", "e"),
        };
        let (flip, split) = (library(file, "flipEdge"), library(file, "splitEdge"));
        for (flipping, pick) in steps {
            let (algorithm, operation) = if flipping {
                (&flip, Operation::FlipEdge)
            } else {
                (&split, Operation::SplitEdge)
            };
            let id = u32::from(pick) % mesh.count(ElementKind::Edge) as u32;
            let mut native = mesh.clone();
            let native_ok = operations::apply(&mut native, operation, &[id]).is_ok();
            let mut traced = mesh.clone();
            let trace = lang::run_editing(
                algorithm,
                &mut traced,
                &[(param, Value::Edge(id))],
                RunOptions::default(),
            )
            .expect("inputs fit");
            match trace.outcome().error() {
                None => {
                    prop_assert!(native_ok, "{operation:?} {id}: only the native one refused");
                    prop_assert_eq!(&traced, &native);
                    prop_assert!(traced.validate().is_empty());
                    mesh = traced;
                }
                Some(_) => {
                    prop_assert_eq!(trace.changes().len(), 0);
                    prop_assert_eq!(&traced, &mesh);
                    prop_assert!(!native_ok, "{operation:?} {id}: only the traced one refused");
                }
            }
        }
    }
}
