//! Every sample in meshes/ loads, validates and round-trips through every
//! format in both structures; the 200k-face benchmark torus does too.

use std::collections::BTreeSet;
use std::path::PathBuf;

use edgewise_core::formats::{self, Format, PlyEncoding, SaveOptions};
use edgewise_core::mesh::{Mesh, Polygons, Structure, generate};

fn meshes_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../meshes")
}

/// Every sample file (name, bytes), sorted by name.
fn samples() -> Vec<(String, Vec<u8>)> {
    let mut files: Vec<(String, Vec<u8>)> = std::fs::read_dir(meshes_dir())
        .expect("meshes/ exists")
        .map(|entry| entry.expect("entry").path())
        .filter(|path| path.extension().is_some_and(|ext| ext != "md"))
        .map(|path| {
            let name = path
                .file_name()
                .expect("name")
                .to_string_lossy()
                .into_owned();
            (name, std::fs::read(&path).expect("readable"))
        })
        .collect();
    files.sort();
    files
}

const STRUCTURES: [Structure; 2] = [Structure::WingedEdge, Structure::HalfEdge];

/// Every way to write a file.
fn targets() -> Vec<(Format, PlyEncoding)> {
    vec![
        (Format::Obj, PlyEncoding::Ascii),
        (Format::Ply, PlyEncoding::Ascii),
        (Format::Ply, PlyEncoding::BinaryLittleEndian),
        (Format::Ply, PlyEncoding::BinaryBigEndian),
        (Format::Wtb, PlyEncoding::Ascii),
        (Format::Htb, PlyEncoding::Ascii),
    ]
}

fn save(mesh: &Mesh, format: Format, ply_encoding: PlyEncoding) -> Vec<u8> {
    formats::save(mesh, format, &SaveOptions { ply_encoding }).expect("saves")
}

/// Faces as cycles starting at their lowest vertex, so two listings of the
/// same polygons compare equal whatever vertex each face starts at.
fn face_cycles(polygons: &Polygons) -> BTreeSet<Vec<u32>> {
    polygons
        .faces()
        .map(|face| {
            let lowest = (0..face.len()).min_by_key(|&i| face[i]).unwrap_or(0);
            let mut cycle = face.to_vec();
            cycle.rotate_left(lowest);
            cycle
        })
        .collect()
}

#[test]
fn the_library_has_every_sample_the_issue_lists() {
    let names: Vec<String> = samples().into_iter().map(|(name, _)| name).collect();
    for expected in [
        "tetrahedron.wtb",
        "cube.htb",
        "octahedron.obj",
        "icosahedron.ply",
        "dodecahedron.obj",
        "triangular-prism.obj",
        "square-pyramid.obj",
        "quad-grid.obj",
        "open-square.wtb",
        "annulus.htb",
        "torus.obj",
        "double-torus.obj",
        "sphere.obj",
        "icosphere-20k.ply",
        "quad-sphere.obj",
        "quad-sphere-triangles.obj",
    ] {
        assert!(names.iter().any(|n| n == expected), "missing {expected}");
    }
    let readme = std::fs::read_to_string(meshes_dir().join("README.md")).expect("README");
    for name in &names {
        assert!(
            readme.contains(name.as_str()),
            "meshes/README.md does not list {name}"
        );
    }
}

#[test]
fn every_sample_loads_and_validates_in_both_structures() {
    for (name, bytes) in samples() {
        for structure in STRUCTURES {
            let loaded = formats::load(&bytes, &name, structure)
                .unwrap_or_else(|e| panic!("{}", e.render(&name)));
            assert_eq!(loaded.mesh.structure(), structure);
            assert!(loaded.warnings.is_empty(), "{name}: {:?}", loaded.warnings);
            assert_eq!(loaded.mesh.validate(), vec![], "{name}");
        }
    }
}

#[test]
fn samples_teach_what_the_readme_says() {
    let stats = |name: &str| {
        let bytes = std::fs::read(meshes_dir().join(name)).expect("sample");
        let loaded = formats::load(&bytes, name, Structure::HalfEdge).expect("loads");
        loaded.mesh.stats()
    };
    /// File, V, E, F, boundary loops, genus of its single component.
    type Expected<'a> = (&'a str, usize, usize, usize, usize, Option<u64>);
    let expected: [Expected<'_>; 16] = [
        ("tetrahedron.wtb", 4, 6, 4, 0, Some(0)),
        ("cube.htb", 8, 12, 6, 0, Some(0)),
        ("octahedron.obj", 6, 12, 8, 0, Some(0)),
        ("icosahedron.ply", 12, 30, 20, 0, Some(0)),
        ("dodecahedron.obj", 20, 30, 12, 0, Some(0)),
        ("triangular-prism.obj", 6, 9, 5, 0, Some(0)),
        ("square-pyramid.obj", 5, 8, 5, 0, Some(0)),
        ("quad-grid.obj", 25, 40, 16, 1, None),
        ("open-square.wtb", 4, 5, 2, 1, None),
        ("annulus.htb", 48, 80, 32, 2, None),
        ("torus.obj", 288, 576, 288, 0, Some(1)),
        ("double-torus.obj", 48, 100, 50, 0, Some(2)),
        ("sphere.obj", 242, 720, 480, 0, Some(0)),
        ("icosphere-20k.ply", 10242, 30720, 20480, 0, Some(0)),
        ("quad-sphere.obj", 98, 192, 96, 0, Some(0)),
        ("quad-sphere-triangles.obj", 98, 288, 192, 0, Some(0)),
    ];
    for (name, v, e, f, loops, genus) in expected {
        let stats = stats(name);
        assert_eq!(
            (
                stats.vertices,
                stats.edges,
                stats.faces,
                stats.boundary_loops
            ),
            (v, e, f, loops),
            "{name}"
        );
        assert_eq!(stats.connected_components(), 1, "{name}");
        assert_eq!(stats.components[0].genus, genus, "{name}");
    }
}

/// What a mesh becomes through `format`: itself, or for a table file of the
/// other structure, itself converted there and back (a conversion numbers the
/// elements its own way).
fn through(mesh: &Mesh, format: Format) -> Mesh {
    match format.native_structure() {
        Some(native) if native != mesh.structure() => mesh
            .convert_to(native)
            .and_then(|m| m.convert_to(mesh.structure()))
            .expect("converts"),
        _ => mesh.clone(),
    }
}

fn assert_same_shape(a: &Mesh, b: &Mesh, name: &str) {
    assert_eq!(a.positions(), b.positions(), "{name}");
    assert_eq!(
        face_cycles(&a.to_polygons()),
        face_cycles(&b.to_polygons()),
        "{name}"
    );
    assert_eq!(a.stats(), b.stats(), "{name}");
}

/// The sample as loaded, then written as OBJ and read again: the builder's
/// numbering, which every later round trip must reproduce exactly.
fn canonical(name: &str, bytes: &[u8], structure: Structure) -> Mesh {
    let original = formats::load(bytes, name, structure).expect("loads").mesh;
    let obj = save(&original, Format::Obj, PlyEncoding::Ascii);
    let rebuilt = formats::load(&obj, "x.obj", structure)
        .expect("reloads")
        .mesh;
    // Writing polygons may renumber a table file's edges, never its shape.
    assert_same_shape(&rebuilt, &original, name);
    rebuilt
}

#[test]
fn every_sample_round_trips_through_every_format() {
    for (name, bytes) in samples() {
        for structure in STRUCTURES {
            let mesh = canonical(&name, &bytes, structure);
            for (format, encoding) in targets() {
                let written = save(&mesh, format, encoding);
                let back = formats::load(&written, format.extension(), structure)
                    .unwrap_or_else(|e| panic!("{name} via {format:?}: {e}"));
                let expected = through(&mesh, format);
                assert!(
                    back.mesh == expected,
                    "{name} as {structure:?} via {format:?} {encoding:?}"
                );
                assert_same_shape(&back.mesh, &mesh, &name);
                // Writing again gives the same bytes.
                assert!(
                    save(&back.mesh, format, encoding) == written,
                    "{name} via {format:?} {encoding:?} writes different bytes the second time"
                );
            }
        }
    }
}

#[test]
fn table_files_load_exactly_as_written() {
    for (name, bytes) in samples() {
        let Some(format) = Format::from_name(&name) else {
            continue;
        };
        let Some(native) = format.native_structure() else {
            continue;
        };
        let loaded = formats::load(&bytes, &name, native).expect("loads");
        assert_eq!(loaded.converted_from, None);
        let written = save(&loaded.mesh, format, PlyEncoding::Ascii);
        let again = formats::load(&written, &name, native).expect("reloads");
        assert!(again.mesh == loaded.mesh, "{name}");
        // The sample files are exactly what the writer produces after their
        // descriptive comment lines.
        let text = String::from_utf8(bytes).expect("text");
        assert!(
            text.ends_with(std::str::from_utf8(&written).expect("text")),
            "{name} differs from what the writer produces"
        );
        let other = match native {
            Structure::WingedEdge => Structure::HalfEdge,
            Structure::HalfEdge => Structure::WingedEdge,
        };
        let converted = formats::load(written.as_slice(), &name, other).expect("converts");
        assert_eq!(converted.converted_from, Some(native));
        assert_eq!(converted.mesh.stats(), loaded.mesh.stats());
    }
}

/// Each format once, in the structure it stores (debug builds are slow, and
/// the samples above already cover every pairing).
#[test]
fn the_200k_face_torus_round_trips_through_every_format() {
    let polygons = generate::torus(316, 316);
    assert_eq!(polygons.face_count(), 199_712);
    for (structure, format, encoding) in [
        (Structure::HalfEdge, Format::Obj, PlyEncoding::Ascii),
        (
            Structure::HalfEdge,
            Format::Ply,
            PlyEncoding::BinaryLittleEndian,
        ),
        (Structure::HalfEdge, Format::Htb, PlyEncoding::Ascii),
        (Structure::WingedEdge, Format::Ply, PlyEncoding::Ascii),
        (Structure::WingedEdge, Format::Wtb, PlyEncoding::Ascii),
    ] {
        let (mesh, _) = Mesh::build(&polygons, structure).expect("builds");
        let written = save(&mesh, format, encoding);
        let back = formats::load(&written, format.extension(), structure).expect("loads");
        assert!(
            back.mesh == mesh,
            "{structure:?} via {format:?} {encoding:?}"
        );
    }
}

#[test]
fn the_generated_icospheres_are_their_sample_files_exactly() {
    // The app generates icosphere-20k rather than ship it: every id and
    // every position bit must be the file's.
    for (name, levels) in [("icosahedron.ply", 0), ("icosphere-20k.ply", 5)] {
        let bytes = std::fs::read(meshes_dir().join(name)).expect("sample");
        for structure in STRUCTURES {
            let file = formats::load(&bytes, name, structure).expect("loads").mesh;
            let (generated, warnings) =
                Mesh::build(&generate::icosphere(levels), structure).expect("builds");
            assert!(warnings.is_empty(), "{name}: {warnings:?}");
            assert!(generated == file, "{name} as {structure:?}");
        }
    }
}
