//! Editing by hand: undo and redo of every operation and load, compacting
//! with its old-to-new mapping, diagnosis of a broken table fixed cell by
//! cell, and the edit menu on a selected element.

use crate::support;

use edgewise_core::mesh::operations::Operation;
use edgewise_core::mesh::{Mesh, Structure};
use edgewise_core::schema::{Column, ElementKind, ElementRef, Records as _};
use egui_kittest::kittest::Queryable as _;

fn mesh(harness: &support::AppHarness) -> Mesh {
    harness.state().mesh().cloned().expect("a mesh is open")
}

/// The tables as a file holds them, deleted rows and all: the same bytes
/// mean the same records.
fn table_text(mesh: &Mesh) -> String {
    format!("{mesh:?}")
}

/// Every operation the edit menu offers on every element of `sample`, in
/// `structure`, applied in the app then undone and redone.
fn undo_and_redo_every_operation(sample: &str, structure: Structure) -> usize {
    let mut harness = support::harness_with(sample, Some(structure));
    let original = mesh(&harness);
    let mut checked = 0;
    for operation in Operation::ALL {
        let first = operation.arguments()[0].kind;
        for id in 0..original.count(first) as u32 {
            let ids: Vec<u32> = match operation {
                Operation::SplitFace | Operation::Mef | Operation::Mekr => {
                    let Some(ids) = face_cut(&original, id) else {
                        continue;
                    };
                    ids
                }
                Operation::Mev => vec![id, 0],
                _ => vec![id],
            };
            let before = mesh(&harness);
            if harness.state_mut().edit(operation, &ids).is_err() {
                assert_eq!(mesh(&harness), before, "{operation} {ids:?} refused");
                continue;
            }
            harness.run();
            let after = mesh(&harness);
            assert_ne!(after, before, "{operation} {ids:?}");
            harness.state_mut().undo().expect("undoes");
            harness.run();
            assert_eq!(
                table_text(&mesh(&harness)),
                table_text(&before),
                "{sample} {structure:?}: undo {operation} {ids:?}"
            );
            assert_eq!(mesh(&harness), before);
            harness.state_mut().redo().expect("redoes");
            harness.run();
            assert_eq!(mesh(&harness), after, "redo {operation} {ids:?}");
            harness.state_mut().undo().expect("undoes again");
            harness.run();
            checked += 1;
        }
    }
    assert_eq!(mesh(&harness), original);
    checked
}

/// A face and two of its corners two apart, if it has four or more.
fn face_cut(mesh: &Mesh, face: u32) -> Option<Vec<u32>> {
    let polygons = mesh.to_polygons();
    let corners = polygons.face(face as usize)?;
    (corners.len() >= 4).then(|| vec![face, corners[0], corners[2]])
}

#[test]
fn undo_restores_the_tables_exactly_after_every_operation_and_redo_replays_it() {
    let mut checked = 0;
    for structure in [Structure::HalfEdge, Structure::WingedEdge] {
        checked += undo_and_redo_every_operation("hexagon", structure);
        checked += undo_and_redo_every_operation("cube", structure);
    }
    assert!(checked >= 60, "only {checked} operations applied");
}

#[test]
fn loads_and_conversions_undo_and_redo_too() {
    let mut harness = support::harness_with("tetrahedron", None);
    let tetrahedron = mesh(&harness);
    harness
        .state_mut()
        .load_sample("cube", None)
        .expect("opens");
    harness.run();
    let cube = mesh(&harness);
    harness
        .state_mut()
        .switch_structure(Structure::WingedEdge)
        .expect("converts");
    harness.run();
    let history = harness.state().state().history;
    assert_eq!(history.undo.len(), 3, "{history:?}");
    assert_eq!(history.undo[2], "convert to winged-edge");
    harness.state_mut().undo().expect("undoes the conversion");
    harness.state_mut().undo().expect("undoes the load");
    harness.run();
    assert_eq!(mesh(&harness), tetrahedron);
    assert_eq!(harness.state().state().history.redo.len(), 2);
    harness.state_mut().redo().expect("redoes the load");
    harness.run();
    assert_eq!(mesh(&harness), cube);
    // A new change forgets what could be redone.
    let cut = face_cut(&mesh(&harness), 0).expect("a square face");
    harness
        .state_mut()
        .edit(Operation::SplitFace, &cut)
        .expect("splits");
    assert!(harness.state().state().history.redo.is_empty());
    harness.state_mut().undo().expect("undo");
    harness.state_mut().undo().expect("undo");
    harness.state_mut().undo().expect("undo the first load");
    assert!(harness.state().mesh().is_none());
    let refused = harness.state_mut().undo().expect_err("nothing more");
    assert_eq!(refused.as_str(), "nothing to undo");
}

#[test]
fn compacting_maps_every_reference_through_the_renumbering() {
    for structure in [Structure::HalfEdge, Structure::WingedEdge] {
        let mut harness = support::harness_with("hexagon", Some(structure));
        let refused = harness.state_mut().compact_ids().expect_err("no gaps yet");
        assert!(refused.as_str().contains("no deleted rows"), "{refused}");
        // Collapsing an inner edge leaves a vertex, edges and faces as gaps.
        let inner = (0..mesh(&harness).count(ElementKind::Edge) as u32)
            .find(|&e| {
                harness
                    .state_mut()
                    .edit(Operation::CollapseEdge, &[e])
                    .is_ok()
            })
            .expect("an inner edge collapses");
        harness.run();
        let gapped = mesh(&harness);
        harness.state_mut().compact_ids().expect("compacts");
        harness.run();
        let compacted = mesh(&harness);
        let state = harness.state().state();
        let renumbering = state.renumbering.expect("the mapping is shown");
        let map = |element: ElementRef| {
            let table = match element.kind {
                ElementKind::Vertex => &renumbering.vertices,
                ElementKind::Edge => &renumbering.edges,
                ElementKind::Face => &renumbering.faces,
            };
            table[element.id as usize].map(|id| ElementRef::new(element.kind, id))
        };
        let mut mapped = 0;
        for kind in ElementKind::ALL {
            assert!(
                (0..gapped.count(kind) as u32).any(|id| map(ElementRef::new(kind, id)).is_none())
                    || kind == ElementKind::Vertex,
                "collapse {inner}: a {kind:?} row was deleted"
            );
            for id in 0..gapped.count(kind) as u32 {
                let old = ElementRef::new(kind, id);
                let Some(new) = map(old) else {
                    assert!(!gapped.contains(old), "{old} is live but unmapped");
                    continue;
                };
                for entry in Column::table(structure, kind) {
                    if entry.column == Column::Position {
                        continue;
                    }
                    let before = gapped.reference(old, entry.column).expect("readable");
                    let after = compacted.reference(new, entry.column).expect("readable");
                    assert_eq!(after, before.and_then(map), "{old} {:?}", entry.column);
                    mapped += 1;
                }
            }
        }
        assert!(mapped > 50);
        assert_eq!(compacted.validate(), vec![]);
        // Compacting is undone like any edit.
        harness.state_mut().undo().expect("undoes");
        harness.run();
        assert_eq!(mesh(&harness), gapped);
    }
}

fn bad_wing() -> Vec<u8> {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../tests/bad-inputs/wtb-bad-wing.wtb");
    std::fs::read(path).expect("the fixture")
}

#[test]
fn a_wrong_wing_is_diagnosed_and_setting_the_cell_right_ends_diagnosis() {
    let mut harness = support::harness();
    // A plain load refuses it, and offers to open it for diagnosis.
    let refused = harness
        .state_mut()
        .load_mesh(&bad_wing(), "wtb-bad-wing.wtb", None)
        .expect_err("broken tables are refused");
    assert!(
        refused.as_str().contains("edge 2 left_predecessor"),
        "{refused}"
    );
    harness.run();
    harness.get_by_label("Open it for diagnosis").click();
    harness.run();
    let state = harness.state().state();
    assert!(state.diagnosis, "{state:?}");
    assert_eq!(state.error, None);
    assert!(
        state
            .broken
            .iter()
            .any(|b| b.kind == ElementKind::Edge && b.id == 2 && b.column == "leftPredecessor"),
        "{:?}",
        state.broken
    );
    assert!(state.highlights.iter().any(|h| h.role == "broken"));
    harness.snapshot("diagnosis_wrong_wing");

    // Operations wait until the tables are sound.
    let refused = harness
        .state_mut()
        .edit(Operation::FlipEdge, &[0])
        .expect_err("refused");
    assert!(refused.as_str().contains("broken records"), "{refused}");

    // The wrong cell, set right: the journal's Table 2, and diagnosis ends.
    let edge_2 = ElementRef::new(ElementKind::Edge, 2);
    harness
        .state_mut()
        .set_cell(edge_2, "leftPredecessor", Some(0))
        .expect("sets the cell");
    harness.run();
    let state = harness.state().state();
    assert!(!state.diagnosis);
    assert!(state.broken.is_empty(), "{:?}", state.broken);
    let table_2 = support::sample_mesh("tetrahedron.wtb", Structure::WingedEdge);
    assert_eq!(mesh(&harness), table_2);
    // Undo takes the fix back, and diagnosis with it.
    harness.state_mut().undo().expect("undoes");
    harness.run();
    assert!(harness.state().state().diagnosis);
}

#[test]
fn setting_a_cell_names_what_is_wrong_with_the_request() {
    let mut harness = support::harness_with("tetrahedron", None);
    let edge_2 = ElementRef::new(ElementKind::Edge, 2);
    let cases = [
        (
            edge_2,
            "rightSuccessor",
            Some(9),
            "setCell(edge 2, rightSuccessor, 9): there is no edge 9 (this mesh has 6, numbered from 0)",
        ),
        (
            edge_2,
            "next",
            Some(1),
            "setCell(edge 2, next, 1): `next` is a column of a half-edge mesh; an edge of a winged-edge mesh has",
        ),
        (
            ElementRef::new(ElementKind::Vertex, 1),
            "leftFace",
            Some(1),
            "`leftFace` is a column of an edge; a vertex of a winged-edge mesh has",
        ),
        (
            edge_2,
            "startVertex",
            None,
            "setCell(edge 2, startVertex, null): the start vertex of edge 2 cannot be empty",
        ),
    ];
    for (element, column, target, expected) in cases {
        let refused = harness
            .state_mut()
            .set_cell(element, column, target)
            .expect_err("refused");
        assert!(refused.as_str().contains(expected), "{refused}");
        assert!(!harness.state().state().diagnosis);
    }
    // A write that breaks the mesh starts diagnosis; undo ends it.
    harness
        .state_mut()
        .set_cell(edge_2, "rightSuccessor", Some(5))
        .expect("sets");
    assert!(harness.state().state().diagnosis);
    harness.state_mut().undo().expect("undoes");
    assert!(!harness.state().state().diagnosis);
}

#[test]
fn the_edit_menu_offers_what_applies_and_says_why_the_rest_is_refused() {
    let mut harness = support::harness_with("hexagon", Some(Structure::HalfEdge));
    harness
        .state_mut()
        .select(Some(ElementRef::new(ElementKind::Edge, 0)))
        .expect("selects");
    harness.run();
    harness.key_press(egui::Key::E);
    harness.run();
    let menu = harness.state().state().edit_menu.expect("the menu is open");
    assert_eq!(menu.element, ElementRef::new(ElementKind::Edge, 0));
    let flip = menu
        .entries
        .iter()
        .find(|e| e.operation == "flip-edge")
        .expect("flip is offered");
    assert!(
        flip.refused
            .as_deref()
            .is_some_and(|r| r.contains("on the boundary")),
        "{flip:?}"
    );
    let split = menu
        .entries
        .iter()
        .find(|e| e.operation == "split-edge")
        .expect("split is offered");
    assert_eq!(split.refused, None);
    harness.snapshot("edit_menu_boundary_edge");
    // Enter applies the first entry that applies: the split.
    harness.key_press(egui::Key::Enter);
    harness.run();
    let state = harness.state().state();
    assert!(state.edit_menu.is_none());
    assert_eq!(
        state.history.undo.last().map(String::as_str),
        Some("split-edge 0")
    );
    let stats = state.stats.expect("stats");
    assert_eq!((stats.vertices, stats.edges, stats.faces), (8, 14, 7));
    // What the split wrote and made stays marked until the next click.
    let roles: Vec<&str> = state.highlights.iter().map(|h| h.role.as_str()).collect();
    assert!(
        roles.contains(&"written") && roles.contains(&"created"),
        "{roles:?}"
    );
    harness.snapshot("edit_menu_split_applied");
    harness
        .state_mut()
        .select(Some(ElementRef::new(ElementKind::Vertex, 7)))
        .expect("selects the new vertex");
    let state = harness.state().state();
    assert!(state.highlights.iter().all(|h| h.role != "written"));
}

#[test]
fn a_table_file_with_a_reference_past_its_table_opens_for_diagnosis_with_the_place() {
    let mut harness = support::harness();
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../tests/bad-inputs/wtb-reference-out-of-range.wtb");
    let bytes = std::fs::read(path).expect("the fixture");
    harness
        .state_mut()
        .load_mesh_for_diagnosis(&bytes, "wtb-reference-out-of-range.wtb")
        .expect("opens");
    harness.run();
    let state = harness.state().state();
    assert!(state.diagnosis);
    assert!(
        state
            .broken
            .iter()
            .any(|b| b.id == 4 && b.rule.contains("not set")),
        "{:?}",
        state.broken
    );
    assert_eq!(state.counts.edges, 6);
    // The view draws what it can: the other five edges and the faces.
    harness.snapshot("diagnosis_reference_past_the_table");
}
