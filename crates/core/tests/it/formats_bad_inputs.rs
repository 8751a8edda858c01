//! The malformed-file corpus in tests/bad-inputs/: each `NAME.EXT` must be
//! refused with exactly the messages in `NAME.expected` (as the CLI prints
//! them, `file:line:column: message`). `EDGEWISE_BLESS=1` rewrites the
//! expected files, to be reviewed like code.
//!
//! Also: oversized input is refused before parsing, and no byte sequence makes
//! a reader panic (truncations and corruptions of every sample, and random
//! bytes).

use crate::golden;

use std::path::PathBuf;

use edgewise_core::formats::{self, Format, Location, MAX_FILE_BYTES};
use edgewise_core::mesh::Structure;
use proptest::prelude::*;

fn corpus_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../tests/bad-inputs")
}

fn structure_for(name: &str) -> Structure {
    Format::from_name(name)
        .and_then(Format::native_structure)
        .unwrap_or(Structure::WingedEdge)
}

#[test]
fn every_bad_input_is_refused_with_its_expected_message() {
    let dir = corpus_dir();
    let names = golden::corpus_inputs(&dir);
    assert!(
        names.len() >= 40,
        "the corpus has only {} files",
        names.len()
    );
    let mut failures = Vec::new();
    for name in &names {
        let bytes = std::fs::read(dir.join(name)).expect("readable");
        let rendered = match formats::load(&bytes, name, structure_for(name)) {
            Ok(_) => format!("{name}: LOADED, but this file must be refused\n"),
            Err(error) => error.render(name),
        };
        failures.extend(golden::compare(
            &golden::expected_path(&dir, name),
            &rendered,
        ));
    }
    golden::assert_none(&failures);
}

#[test]
fn every_expected_file_has_its_input() {
    golden::assert_every_expected_has_input(&corpus_dir());
}

#[test]
fn the_corpus_covers_what_the_issue_asks_for() {
    let dir = corpus_dir();
    let expected = |stem: &str| {
        std::fs::read_to_string(dir.join(format!("{stem}.expected"))).expect("expected file")
    };
    assert!(expected("ply-binary-truncated").contains("the file ends inside"));
    assert!(expected("ply-wrong-vertex-count").contains("values"));
    assert!(expected("obj-non-manifold-edge").contains("non-manifold edge"));
    assert!(expected("obj-inconsistent-orientation").contains("inconsistent orientation"));
    assert!(expected("wtb-bad-wing").contains("edge 2 left_predecessor"));
    assert!(expected("htb-wrong-pair").contains("half-edge 5 pair_edge"));
    assert!(expected("wtb-ids-out-of-order").contains("expected the id 1"));
    assert!(expected("obj-nan-coordinate").contains("finite number"));
    assert!(expected("ply-binary-huge-count").contains("4000000000"));
}

#[test]
fn a_table_file_with_one_wrong_wing_names_the_edge_and_column() {
    let bytes = std::fs::read(corpus_dir().join("wtb-bad-wing.wtb")).expect("corpus file");
    let error =
        formats::load(&bytes, "wtb-bad-wing.wtb", Structure::WingedEdge).expect_err("refused");
    // The row of edge 2 is line 24; its left_predecessor is the sixth field,
    // at column 71. The wrong wing also breaks the walks that pass it, which
    // are reported too, but the edge itself is named at its field.
    let wing = error
        .problems()
        .iter()
        .find(|p| p.message.starts_with("edge 2 "))
        .expect("edge 2 is named");
    assert_eq!(wing.location, Location::at(24, 71));
    assert_eq!(
        wing.message,
        "edge 2 left_predecessor: edge 3 does not border face 0, the left face of this edge"
    );
}

#[test]
fn files_over_the_size_limit_are_refused_before_reading() {
    let bytes = vec![b' '; MAX_FILE_BYTES + 1];
    for name in ["big.obj", "big.ply", "big.wtb", "big.htb"] {
        let error = formats::load(&bytes, name, Structure::HalfEdge).expect_err("too big");
        assert_eq!(
            error.render(name),
            format!(
                "{name}: the file is {} bytes; Edgewise reads files of at most {MAX_FILE_BYTES} bytes (256 MiB)\n",
                MAX_FILE_BYTES + 1
            )
        );
    }
}

/// Every sample, as bytes with its file name.
fn samples() -> Vec<(String, Vec<u8>)> {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../meshes");
    let mut files: Vec<(String, Vec<u8>)> = std::fs::read_dir(dir)
        .expect("meshes/")
        .map(|e| e.expect("entry").path())
        .filter(|p| p.extension().is_some_and(|e| e != "md"))
        .map(|p| {
            (
                p.file_name().expect("name").to_string_lossy().into_owned(),
                std::fs::read(&p).expect("read"),
            )
        })
        .filter(|(_, bytes)| bytes.len() < 100_000)
        .collect();
    files.sort();
    files
}

#[test]
fn truncated_samples_are_refused_without_panicking() {
    for (name, bytes) in samples() {
        let step = (bytes.len() / 97).max(1);
        for end in (0..bytes.len()).step_by(step) {
            // Whatever the result, it must come back (no panic, no hang);
            // a cut inside a comment or at a line end can still be valid.
            let _ = formats::load(&bytes[..end], &name, structure_for(&name));
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn corrupted_samples_never_panic(index in 0usize..64, at in any::<prop::sample::Index>(), byte in any::<u8>()) {
        let samples = samples();
        let (name, mut bytes) = samples[index % samples.len()].clone();
        let at = at.index(bytes.len());
        bytes[at] = byte;
        let _ = formats::load(&bytes, &name, structure_for(&name));
    }

    #[test]
    fn random_bytes_never_panic(bytes in prop::collection::vec(any::<u8>(), 0..512), format in 0usize..4) {
        let format = Format::ALL[format];
        let _ = formats::load_as(&bytes, format, Structure::HalfEdge);
        let _ = formats::load_as(&bytes, format, Structure::WingedEdge);
    }

    #[test]
    fn random_headers_never_panic(count in any::<u32>(), tail in prop::collection::vec(any::<u8>(), 0..64)) {
        let mut bytes = format!(
            "ply\nformat binary_little_endian 1.0\nelement vertex {count}\nproperty double x\n\
             property float y\nproperty short z\nelement face {count}\n\
             property list uint ushort vertex_index\nend_header\n"
        ).into_bytes();
        bytes.extend(tail);
        let _ = formats::load_as(&bytes, Format::Ply, Structure::HalfEdge);
    }
}

#[test]
fn the_format_comes_from_the_extension_or_else_the_content() {
    let detect = |bytes: &[u8], name: &str| Format::detect(bytes, name).expect("detected");
    let wtb = b"# a comment\n\nwtb 1\n";
    assert_eq!(detect(wtb, ""), Format::Wtb);
    assert_eq!(detect(b"htb 1\n", "pasted"), Format::Htb);
    assert_eq!(detect(b"ply\r\nformat ascii 1.0\n", ""), Format::Ply);
    assert_eq!(detect(b"v 0 0 0\n", ""), Format::Obj);
    // The extension wins over the content, in any case, as a name or bare.
    assert_eq!(detect(wtb, "dir.v2/cube.OBJ"), Format::Obj);
    assert_eq!(detect(wtb, "ply"), Format::Ply);
    assert_eq!(detect(wtb, ".htb"), Format::Htb);
    let error = Format::detect(wtb, "cube.stl").expect_err("unknown extension");
    assert!(error.first().message.starts_with("cannot read .stl files"));
}
