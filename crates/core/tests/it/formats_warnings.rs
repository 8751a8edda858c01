//! The corpus in tests/warnings/: files that load, but not as written. Each
//! `NAME.EXT` must load in both structures, validate, and give exactly the
//! warnings in `NAME.expected` (`file:line: message`, one a line).
//! `EDGEWISE_BLESS=1` rewrites the expected files, to be reviewed like code.

use crate::golden;

use std::path::PathBuf;

use edgewise_core::formats::{self, Format, SaveOptions};
use edgewise_core::mesh::Structure;

fn corpus_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../tests/warnings")
}

/// How many vertices a "split into 7, 12 and 13" warning adds (two here).
fn copies(message: &str) -> usize {
    message.split_once("; split into ").map_or(0, |(_, ids)| {
        ids.split([',', ' '])
            .filter(|id| id.parse::<u32>().is_ok())
            .count()
            - 1
    })
}

#[test]
fn every_file_loads_with_its_expected_warnings() {
    let dir = corpus_dir();
    let names = golden::corpus_inputs(&dir);
    assert!(
        names.len() >= 2,
        "the corpus has only {} files",
        names.len()
    );
    let mut failures = Vec::new();
    for name in &names {
        let bytes = std::fs::read(dir.join(name)).expect("readable");
        let text = String::from_utf8_lossy(&bytes);
        let written = text.lines().filter(|l| l.starts_with("v ")).count();
        let mut rendered = Vec::new();
        for structure in [Structure::WingedEdge, Structure::HalfEdge] {
            let loaded = formats::load(&bytes, name, structure)
                .unwrap_or_else(|error| panic!("{}", error.render(name)));
            assert_eq!(loaded.mesh.validate(), vec![], "{name}");
            let added: usize = loaded.warnings.iter().map(|w| copies(&w.message)).sum();
            assert_eq!(loaded.mesh.vertex_count(), written + added, "{name}");
            // What was split stays manifold: written back, it loads as is.
            let obj =
                formats::save(&loaded.mesh, Format::Obj, &SaveOptions::default()).expect("saves");
            let again = formats::load(&obj, "again.obj", structure).expect("reloads");
            assert_eq!(again.warnings, vec![], "{name}");
            assert_eq!(again.mesh.stats(), loaded.mesh.stats(), "{name}");
            rendered.push(
                loaded
                    .warnings
                    .iter()
                    .map(|w| format!("{}\n", w.render(name)))
                    .collect::<String>(),
            );
        }
        assert_eq!(rendered[0], rendered[1], "{name}: the structures disagree");
        let rendered = &rendered[0];
        assert!(!rendered.is_empty(), "{name} loads without a warning");
        failures.extend(golden::compare(
            &golden::expected_path(&dir, name),
            rendered,
        ));
    }
    golden::assert_none(&failures);
}

#[test]
fn every_expected_file_has_its_input() {
    golden::assert_every_expected_has_input(&corpus_dir());
}
