//! Tables opened for diagnosis: a broken `.wtb` or `.htb` is kept as
//! written so that a student can find and fix what is wrong, instead of
//! refused. Every malformed file of tests/bad-inputs is either refused as
//! before or opened, and the paths the app takes on an opened one (rules,
//! faces, counts, every reference) stay total.

use std::path::PathBuf;

use edgewise_core::formats::{self, Format};
use edgewise_core::mesh::{Element, Mesh, Structure};
use edgewise_core::schema::{Column, ElementKind, ElementRef, Records, RecordsMut};

fn bad_input(name: &str) -> Vec<u8> {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../../tests/bad-inputs")
        .join(name);
    std::fs::read(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

#[test]
fn one_wrong_wing_opens_names_its_edge_and_column_and_fixing_it_validates() {
    let bytes = bad_input("wtb-bad-wing.wtb");
    assert!(formats::load(&bytes, "wtb-bad-wing.wtb", Structure::WingedEdge).is_err());
    let loaded = formats::load_for_diagnosis(&bytes, "wtb-bad-wing.wtb", Structure::HalfEdge)
        .expect("opens for diagnosis");
    assert_eq!(loaded.format, Format::Wtb);
    assert!(loaded.warnings.is_empty());
    let mut mesh = loaded.mesh;
    assert_eq!(
        mesh.structure(),
        Structure::WingedEdge,
        "as the file stores it"
    );
    let issues = mesh.validate();
    let edge_2 = Element::of(Structure::WingedEdge, ElementRef::new(ElementKind::Edge, 2));
    assert!(
        issues
            .iter()
            .any(|issue| issue.element == edge_2 && issue.field == Column::LeftPredecessor),
        "{issues:#?}"
    );
    mesh.set_reference(
        ElementRef::new(ElementKind::Edge, 2),
        Column::LeftPredecessor,
        Some(ElementRef::new(ElementKind::Edge, 0)),
    )
    .expect("writes");
    assert_eq!(mesh.validate(), vec![]);
    let table_2 = std::fs::read(
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../meshes/tetrahedron.wtb"),
    )
    .expect("the sample");
    let expected = formats::load(&table_2, "tetrahedron.wtb", Structure::WingedEdge)
        .expect("loads")
        .mesh;
    assert_eq!(mesh, expected, "the journal's Table 2 again");
}

#[test]
fn a_reference_past_the_table_is_read_as_unset_and_named_at_its_field() {
    let bytes = bad_input("wtb-reference-out-of-range.wtb");
    let loaded = formats::load_for_diagnosis(
        &bytes,
        "wtb-reference-out-of-range.wtb",
        Structure::HalfEdge,
    )
    .expect("opens for diagnosis");
    let warnings: Vec<String> = loaded.warnings.iter().map(ToString::to_string).collect();
    assert_eq!(
        warnings,
        ["26:30: edge 4 end_vertex: vertex 9 does not exist (there are 4); read as unset"]
    );
    let edge_4 = ElementRef::new(ElementKind::Edge, 4);
    assert_eq!(loaded.mesh.reference(edge_4, Column::EndVertex), Ok(None));
    let issues = loaded.mesh.validate();
    assert!(
        issues.iter().any(
            |issue| issue.field == Column::EndVertex && issue.message.contains("it is not set")
        ),
        "{issues:#?}"
    );
}

/// Every broken table file: refused for a malformed row, with the same
/// first message as a plain load, or opened; an opened mesh can be walked.
#[test]
fn every_broken_table_file_is_refused_as_before_or_opened_and_walkable() {
    let folder = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../tests/bad-inputs");
    let mut opened = 0;
    let mut refused = 0;
    for entry in std::fs::read_dir(&folder).expect("tests/bad-inputs") {
        let path = entry.expect("entry").path();
        let name = path
            .file_name()
            .expect("a name")
            .to_string_lossy()
            .into_owned();
        if !(name.ends_with(".wtb") || name.ends_with(".htb")) {
            continue;
        }
        let bytes = std::fs::read(&path).expect("readable");
        let plain = formats::load(&bytes, &name, Structure::HalfEdge);
        match formats::load_for_diagnosis(&bytes, &name, Structure::HalfEdge) {
            Ok(loaded) => {
                opened += 1;
                let mesh: &Mesh = &loaded.mesh;
                assert!(
                    plain.is_err() || mesh.validate().is_empty(),
                    "{name}: a sound file opens sound"
                );
                drop(mesh.to_polygons());
                drop(mesh.live_stats());
                for kind in ElementKind::ALL {
                    for id in 0..mesh.count(kind) as u32 {
                        for entry in Column::table(mesh.structure(), kind) {
                            if let Ok(Some(target)) =
                                mesh.reference(ElementRef::new(kind, id), entry.column)
                            {
                                assert!(
                                    (target.id as usize) < mesh.count(target.kind),
                                    "{name}: {kind:?} {id} {:?} leads past its table",
                                    entry.column
                                );
                            }
                        }
                    }
                }
            }
            Err(error) => {
                refused += 1;
                let plain = plain.expect_err("a plain load refuses it too");
                assert_eq!(
                    error.first().to_string(),
                    plain.first().to_string(),
                    "{name}"
                );
            }
        }
    }
    assert!(
        opened >= 5 && refused >= 5,
        "opened {opened}, refused {refused}"
    );
}
