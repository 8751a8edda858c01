//! The first visit: the journal's tetrahedron with its tables, the hint of
//! three things to try ticked off as they are done, "What am I looking
//! at?", and a dismissal that lasts.

use crate::support;

use edgewise_core::schema::{ElementKind, ElementRef};
use edgewise_model::algorithm::session::Argument;
use egui_kittest::kittest::Queryable as _;

#[test]
fn the_first_visit_opens_table_2_and_ticks_off_three_things_to_try() {
    let mut harness = support::harness();
    harness.state_mut().first_visit();
    harness.run();
    let state = harness.state().state();
    assert_eq!(state.mesh.as_deref(), Some("tetrahedron.wtb"));
    assert_eq!(state.structure, Some("winged"));
    assert!(
        state.history.undo.is_empty(),
        "the start is not an undoable step"
    );
    assert_eq!(harness.state().tour().map(|t| t.done), Some([false; 3]));
    harness.get_by_label("Welcome to Edgewise");
    harness.get_by_label_contains("Click an edge");

    // 1. An edge (as a click in the view or on its row selects it).
    harness
        .state_mut()
        .select(Some(ElementRef {
            kind: ElementKind::Edge,
            id: 2,
        }))
        .expect("selects");
    harness.run();
    assert_eq!(
        harness.state().tour().map(|t| t.done),
        Some([true, false, false])
    );
    // 2. A reference followed from a table.
    harness
        .get_by_label("incident edge of face 0: edge 0")
        .click();
    harness.run();
    assert_eq!(
        harness.state().tour().map(|t| t.done),
        Some([true, true, false])
    );
    // 3. vertexAdjacentEdge run and stepped.
    harness
        .state_mut()
        .run_algorithm(
            "vertexAdjacentEdge",
            &[("v".to_owned(), Argument::Number(1.0))],
        )
        .expect("runs");
    harness.state_mut().trace_step(1).expect("steps");
    harness.run();
    assert_eq!(harness.state().tour().map(|t| t.done), Some([true; 3]));
    harness.get_by_label_contains("That is the whole idea");
    harness.get_by_label_contains("This is the tetrahedron of the winged-edge paper's Table 2");

    // Over another mesh the hint stays, and no longer names the tetrahedron.
    harness
        .state_mut()
        .load_sample("hexagon", None)
        .expect("loads");
    harness.run();
    harness.get_by_label_contains("Click an edge");
    assert!(
        harness
            .query_by_label_contains("This is the tetrahedron")
            .is_none()
    );

    // What am I looking at? labels the parts, and a click closes it.
    harness.get_by_label("What am I looking at?").click();
    harness.run();
    assert!(harness.state().explaining());
    for part in ["Menus", "The mesh in 3D", "The records", "The algorithm"] {
        harness.get_by_label(part);
    }
    harness.get_by_label("Welcome to Edgewise").click();
    harness.run();
    assert!(!harness.state().explaining());

    // Dismissed, it stays away on the next first visit.
    harness.get_by_label("Dismiss").click();
    harness.run();
    assert!(harness.state().tour().is_none());
    harness.state_mut().first_visit();
    harness.run();
    assert!(harness.state().tour().is_none());
    assert!(harness.query_by_label("Welcome to Edgewise").is_none());
}
