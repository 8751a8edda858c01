//! Golden files for the writers: two samples written in every format and
//! encoding, and their tables as `edgewise tables` prints them, compared byte
//! for byte with tests/golden/formats/. `EDGEWISE_BLESS=1` rewrites them.

use crate::golden;

use std::path::PathBuf;

use edgewise_core::formats::{self, Format, PlyEncoding, SaveOptions};
use edgewise_core::mesh::Structure;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// Compares `actual` with the golden file `name` (see [`golden::compare`]).
fn compare(name: &str, actual: &[u8]) -> Option<String> {
    golden::compare(&root().join("tests/golden/formats").join(name), actual)
}

#[test]
fn writers_match_their_golden_files() {
    let mut failures = Vec::new();
    for (sample, structure) in [
        ("tetrahedron.wtb", Structure::WingedEdge),
        ("open-square.wtb", Structure::WingedEdge),
        ("annulus.htb", Structure::HalfEdge),
    ] {
        let bytes = std::fs::read(root().join("meshes").join(sample)).expect("sample");
        let mesh = formats::load(&bytes, sample, structure)
            .expect("loads")
            .mesh;
        let stem = sample.rsplit_once('.').map_or(sample, |(s, _)| s);
        for (suffix, format, ply_encoding) in [
            ("obj", Format::Obj, PlyEncoding::Ascii),
            ("ascii.ply", Format::Ply, PlyEncoding::Ascii),
            ("le.ply", Format::Ply, PlyEncoding::BinaryLittleEndian),
            ("be.ply", Format::Ply, PlyEncoding::BinaryBigEndian),
            ("wtb", Format::Wtb, PlyEncoding::Ascii),
            ("htb", Format::Htb, PlyEncoding::Ascii),
        ] {
            let written =
                formats::save(&mesh, format, &SaveOptions { ply_encoding }).expect("saves");
            failures.extend(compare(&format!("{stem}.{suffix}"), &written));
        }
        for other in [Structure::WingedEdge, Structure::HalfEdge] {
            let converted = mesh.convert_to(other).expect("converts");
            let label = match other {
                Structure::WingedEdge => "winged",
                Structure::HalfEdge => "half",
            };
            let listing = formats::listing(&converted);
            failures.extend(compare(
                &format!("{stem}.{label}.tables.txt"),
                listing.as_bytes(),
            ));
        }
    }
    golden::assert_none(&failures);
}

/// docs/formats.md quotes the tetrahedron in both table formats, some
/// refusals and warnings; they must stay what the code produces.
#[test]
fn the_format_documentation_quotes_real_output() {
    let docs = std::fs::read_to_string(root().join("docs/formats.md")).expect("docs/formats.md");
    let read = |path: &str| std::fs::read_to_string(root().join(path)).expect("quoted file");
    for whole in [
        "meshes/tetrahedron.wtb",
        "tests/golden/formats/tetrahedron.htb",
        "tests/bad-inputs/wtb-bad-wing.expected",
    ] {
        assert!(
            docs.contains(&read(whole)),
            "docs/formats.md does not quote {whole} as it is"
        );
    }
    let mut lines = 0;
    for line in docs.lines() {
        let Some((file, _)) = line.split_once(':') else {
            continue;
        };
        let Some(stem) = file
            .strip_suffix(".wtb")
            .or(file.strip_suffix(".htb"))
            .or(file.strip_suffix(".ply"))
            .or(file.strip_suffix(".obj"))
        else {
            continue;
        };
        // A reference read as unset is what opening the file for diagnosis
        // says of it (docs/formats.md, "Opening broken tables").
        if line.ends_with("; read as unset") {
            let bytes = std::fs::read(root().join(format!("tests/bad-inputs/{file}")))
                .expect("the quoted bad input");
            let loaded = formats::load_for_diagnosis(&bytes, file, Structure::HalfEdge)
                .expect("opens for diagnosis");
            assert!(
                loaded
                    .warnings
                    .iter()
                    .any(|w| format!("{file}:{w}") == line),
                "docs/formats.md: {line}"
            );
            lines += 1;
            continue;
        }
        let expected = ["bad-inputs", "warnings"]
            .map(|dir| format!("tests/{dir}/{stem}.expected"))
            .into_iter()
            .find(|path| root().join(path).exists());
        if let Some(expected) = expected {
            assert!(
                read(&expected).lines().any(|l| l == line),
                "docs/formats.md: {line}"
            );
            lines += 1;
        }
    }
    assert!(lines >= 10, "only {lines} quoted messages found");
}
