//! Files written by other tools (trimesh, meshio, plyfile; see
//! tests/external/make.py) load in both structures with the counts their
//! writers put in them: binary and ASCII PLY, double coordinates, normals
//! and colours, `vertex_index` lists with uint counts, an extra element,
//! big-endian data, and OBJ faces in the v//vn form; and an icosphere with
//! two holes touching at a vertex, which loads with that vertex split. Each
//! converts to the other structure and stays valid.

use std::path::PathBuf;

use edgewise_core::formats;
use edgewise_core::mesh::Structure;

/// A file with vertices where separate fans of faces meet: loading splits
/// each into one vertex per fan, so the mesh has more vertices than the file.
struct Split {
    file: &'static str,
    /// The warnings about the split vertices, in order.
    warnings: &'static [&'static str],
    /// Vertices added (one per extra fan).
    copies: usize,
    /// Boundary loops after the split.
    boundary_loops: usize,
}

/// Every other file loads with the file's counts and is closed.
const SPLIT: [Split; 1] = [Split {
    file: "trimesh-icosphere-touching-holes.ply",
    warnings: &["vertex 139 joined 2 fans of faces; split into 139 and 162"],
    copies: 1,
    // The two holes, opened at the vertex they shared, are one loop.
    boundary_loops: 1,
}];

#[test]
fn files_from_other_tools_load_with_their_counts() {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../tests/external");
    let expected = std::fs::read_to_string(dir.join("expected.txt")).expect("expected.txt");
    let mut checked = 0;
    for line in expected
        .lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
    {
        let fields: Vec<&str> = line.split_whitespace().collect();
        let [name, v, e, f] = fields.as_slice() else {
            panic!("bad line in expected.txt: {line}");
        };
        let counts: Vec<usize> = [v, e, f]
            .iter()
            .map(|n| n.parse().expect("count"))
            .collect();
        let split = SPLIT.iter().find(|split| split.file == *name);
        let copies = split.map_or(0, |split| split.copies);
        let bytes = std::fs::read(dir.join(name)).expect("file exists");
        for structure in [Structure::WingedEdge, Structure::HalfEdge] {
            let loaded = formats::load(&bytes, name, structure)
                .unwrap_or_else(|error| panic!("{}", error.render(name)));
            let stats = loaded.mesh.stats();
            assert_eq!(
                vec![stats.vertices, stats.edges, stats.faces],
                vec![counts[0] + copies, counts[1], counts[2]],
                "{name} as {structure:?}"
            );
            assert_eq!(loaded.mesh.validate(), vec![], "{name}");
            assert_eq!(stats.components.len(), 1, "{name}");
            let other = match structure {
                Structure::WingedEdge => Structure::HalfEdge,
                Structure::HalfEdge => Structure::WingedEdge,
            };
            let converted = loaded.mesh.convert_to(other).expect("converts");
            assert_eq!(converted.validate(), vec![], "{name} as {other:?}");
            assert_eq!(converted.stats(), stats, "{name} as {other:?}");
            let splits: Vec<&str> = loaded
                .warnings
                .iter()
                .map(|w| w.message.as_str())
                .filter(|m| m.contains("fans of faces"))
                .collect();
            match split {
                Some(split) => {
                    assert_eq!(splits, split.warnings, "{name}");
                    assert_eq!(stats.boundary_loops, split.boundary_loops, "{name}");
                }
                None => {
                    assert_eq!(splits, Vec::<&str>::new(), "{name}");
                    assert_eq!(stats.boundary_loops, 0, "{name}: the file is closed");
                }
            }
        }
        checked += 1;
    }
    assert_eq!(checked, 7);
}
