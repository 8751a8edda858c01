//! Files written by other tools (trimesh, meshio, plyfile; see
//! tests/external/make.py) load in both structures with the counts their
//! writers put in them: binary and ASCII PLY, double coordinates, normals
//! and colours, `vertex_index` lists with uint counts, an extra element,
//! big-endian data, and OBJ faces in the v//vn form.

use std::path::PathBuf;

use edgewise_core::formats;
use edgewise_core::mesh::Structure;

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
        let bytes = std::fs::read(dir.join(name)).expect("file exists");
        for structure in [Structure::WingedEdge, Structure::HalfEdge] {
            let loaded = formats::load(&bytes, name, structure)
                .unwrap_or_else(|error| panic!("{}", error.render(name)));
            let stats = loaded.mesh.stats();
            assert_eq!(
                vec![stats.vertices, stats.edges, stats.faces],
                counts,
                "{name} as {structure:?}"
            );
            assert_eq!(loaded.mesh.validate(), vec![], "{name}");
            assert_eq!(stats.components.len(), 1, "{name}");
            assert_eq!(stats.boundary_loops, 0, "{name}: every file is closed");
        }
        checked += 1;
    }
    assert_eq!(checked, 6);
}
