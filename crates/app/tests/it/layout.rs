//! The layout holds whatever the panels show: a long value in the
//! algorithm panel (loopSubdivide's `points`, an array of vectors) is cut at
//! the panel's edge, the panel takes at most half the window, and the 3D
//! view keeps its room, at the last step, after going back and in the next
//! run; and the line being run stays in sight beside a long list of
//! variables.

use crate::support;

use edgewise_app::state::LayoutState;
use edgewise_core::mesh::Structure;
use edgewise_model::algorithm::session::Argument;

fn layout(harness: &support::AppHarness) -> LayoutState {
    harness.state().state().layout
}

/// The algorithm panel is at most half the window, and the view at least a
/// third of its width and of its height.
fn assert_bounded(layout: &LayoutState, when: &str) {
    let window = layout.window;
    let panel = layout
        .panels
        .get("algorithm")
        .expect("the algorithm panel shows");
    assert!(panel.w <= window.w * 0.5 + 1.0, "{when}: {layout:?}");
    let view = layout.view.expect("the view shows");
    assert!(view.w >= window.w / 3.0, "{when}: {layout:?}");
    assert!(view.h >= window.h / 3.0, "{when}: {layout:?}");
}

#[test]
fn a_long_value_never_squeezes_the_view() {
    let mut harness = support::harness_sized(1280.0, 800.0);
    harness
        .state_mut()
        .load_sample("tetrahedron", Some(Structure::HalfEdge))
        .expect("opens");
    harness.run();
    let before = layout(&harness);
    assert_eq!((before.window.w, before.window.h), (1280.0, 800.0));
    let run = |harness: &mut support::AppHarness| {
        harness
            .state_mut()
            .run_algorithm("loopSubdivide", &[("f".to_owned(), Argument::Number(0.0))])
            .expect("starts");
        harness.run();
    };
    run(&mut harness);
    assert_bounded(&layout(&harness), "at the first step");
    harness.state_mut().trace_goto(usize::MAX).expect("goto");
    harness.run();
    let trace = harness.state().state().trace.expect("tracing");
    let points = trace.variables.get("points").expect("points");
    assert!(points.len() > 100, "a long value: {points}");
    assert_bounded(&layout(&harness), "at the last step");
    harness.state_mut().trace_goto(0).expect("goto");
    harness.run();
    assert_bounded(&layout(&harness), "back at step 0");
    harness.state_mut().abort_algorithm().expect("abort");
    harness.run();
    run(&mut harness);
    assert_bounded(&layout(&harness), "in the next run");
}

/// The Algorithm menu is longer than a 600 px window: it ends inside the
/// window and scrolls to its last entry, "Write or open an algorithm…".
#[test]
fn the_algorithm_menu_scrolls_in_a_short_window() {
    use egui_kittest::kittest::Queryable as _;
    let mut harness = support::harness_sized(1280.0, 600.0);
    harness
        .state_mut()
        .load_sample("cube", Some(Structure::HalfEdge))
        .expect("opens");
    harness.run();
    harness.get_by_label("Algorithm").click();
    harness.run();
    let bottom = |harness: &support::AppHarness, label: &str| {
        harness
            .get_all_by_label(label)
            .last()
            .map(|node| node.rect().bottom())
            .unwrap_or_else(|| panic!("no {label} in the menu"))
    };
    assert!(
        bottom(&harness, "Write or open an algorithm…") > 600.0,
        "the menu fits the window: nothing to scroll"
    );
    let menu = |harness: &support::AppHarness| {
        layout(harness)
            .menus
            .into_iter()
            .find(|m| m.name == "Algorithm")
            .expect("state().layout lists the open Algorithm menu")
    };
    let before = menu(&harness);
    assert!(
        !before.last_entry_visible && before.visible_entries < before.entries,
        "entries scrolled out of the menu are not in sight: {before:?}"
    );
    if let Some(first) = harness.get_all_by_label("vertexAdjacentEdge").next() {
        first.hover();
    }
    for _ in 0..20 {
        harness.event(egui::Event::MouseWheel {
            unit: egui::MouseWheelUnit::Point,
            delta: egui::vec2(0.0, -400.0),
            phase: egui::TouchPhase::Move,
            source: egui::MouseWheelSource::Unknown,
            modifiers: egui::Modifiers::NONE,
        });
        harness.run();
    }
    assert!(
        bottom(&harness, "Write or open an algorithm…") <= 600.0,
        "the last entry cannot be scrolled into view"
    );
    assert!(menu(&harness).last_entry_visible, "{:?}", menu(&harness));
}

/// An embedded view without code or tables asks its questions in its own
/// terms: no source line, and "click the element in the view".
#[test]
fn an_embed_asks_only_about_what_it_shows() {
    use egui_kittest::kittest::Queryable as _;
    for tables in [false, true] {
        let mut harness = support::harness_with("tetrahedron", None);
        harness
            .state_mut()
            .set_embed(Some(edgewise_app::Embed { tables }));
        support::run_vertex_adjacent_edge(&mut harness, 1);
        support::ask(
            &mut harness,
            "line 13: Which edge will e be?
",
        );
        harness.get_by_label("Question 1 of 1");
        let click = if tables {
            "Click the element in the view or the tables, or"
        } else {
            "Click the element in the view, or"
        };
        harness.get_by_label(click);
    }
}

/// With a run open at 1280×800 every column of the winged-edge table shows
/// inside the tables panel, headed as the journal shortens it ("R succ."),
/// so the right traversal that vertexAdjacentEdge reads is in sight.
#[test]
fn every_edge_column_shows_beside_a_run() {
    use egui_kittest::kittest::Queryable as _;
    let mut harness = support::harness_sized(1280.0, 800.0);
    harness
        .state_mut()
        .load_sample("tetrahedron", Some(Structure::WingedEdge))
        .expect("opens");
    // Shown first across the whole window, with full headers, as a link
    // opens it before the run starts.
    harness.run();
    support::run_vertex_adjacent_edge(&mut harness, 0);
    let layout = layout(&harness);
    let (tables, algorithm) = (layout.panels["tables"], layout.panels["algorithm"]);
    assert!(
        tables.x + tables.w <= algorithm.x + 1.0,
        "the tables stop at the algorithm panel: {layout:?}"
    );
    // The edge table ends a cell spacing before the vertex table's title.
    let spacing = 8.0;
    let vertices = harness.get_by_label("Vertices").rect().left() - spacing;
    let edges = harness.get_by_label("Edges").rect().left();
    for header in [
        "L face", "R face", "L pred.", "L succ.", "R pred.", "R succ.",
    ] {
        let rect = harness.get_by_label(header).rect();
        assert!(
            rect.left() >= edges && rect.right() <= vertices,
            "{header} at {rect:?} shows between {edges} and {vertices}"
        );
    }
    // And the vertex table's last reference before the panel's edge.
    let incident = harness
        .get_all_by_label("inc. edge")
        .map(|node| node.rect())
        .max_by(|a, b| a.right().total_cmp(&b.right()))
        .expect("the vertex table's incident edge");
    // Within the panel's margin.
    assert!(
        incident.right() <= tables.x + tables.w - spacing,
        "inc. edge at {incident:?} shows within {tables:?}"
    );
}

/// A table too narrow for its references scrolls sideways, and its ids stay
/// at its left edge, where they still answer the pointer.
#[test]
fn the_id_column_stays_while_a_table_scrolls_sideways() {
    use egui_kittest::kittest::Queryable as _;
    let mut harness = support::harness_sized(720.0, 800.0);
    harness
        .state_mut()
        .load_sample("tetrahedron", Some(Structure::WingedEdge))
        .expect("opens");
    support::run_vertex_adjacent_edge(&mut harness, 0);
    let tables = layout(&harness).panels["tables"];
    // Row 3's id, at the table's left edge.
    let id_at_left = |harness: &support::AppHarness| -> Vec<egui::Rect> {
        harness
            .get_all_by_label("3")
            .map(|node| node.rect())
            .filter(|rect| rect.left() >= tables.x && rect.left() < tables.x + 24.0)
            .collect()
    };
    let before = id_at_left(&harness);
    assert_eq!(
        before.len(),
        1,
        "id 3 at the left of {tables:?}: {before:?}"
    );
    let start = harness.get_by_label("start").rect();
    harness.hover_at(start.center());
    harness.event(egui::Event::MouseWheel {
        unit: egui::MouseWheelUnit::Point,
        delta: egui::vec2(-400.0, 0.0),
        phase: egui::TouchPhase::Move,
        source: egui::MouseWheelSource::Wheel,
        modifiers: egui::Modifiers::NONE,
    });
    harness.run();
    let scrolled = harness.get_by_label("start").rect();
    assert!(
        scrolled.left() < start.left() - 50.0,
        "the table scrolled sideways: start went from {start:?} to {scrolled:?}"
    );
    let last = harness.get_by_label("R succ.").rect();
    assert!(
        last.right() <= tables.x + tables.w + 1.0,
        "the last reference came into view: {last:?} in {tables:?}"
    );
    let after = id_at_left(&harness);
    assert_eq!(after, before, "id 3 stays where it was");
    harness.hover_at(before[0].center());
    harness.run();
    let hovered = harness.state().state().hovered;
    assert_eq!(
        hovered.map(|e| (e.kind, e.id)),
        Some((edgewise_core::schema::ElementKind::Edge, 3)),
        "the sticky id previews its row"
    );
}

/// The line being run stays in sight, with the lines around it, however many
/// variables and broken records the step lists: a flip's ten variables and
/// eight broken records had left the source three lines of a laptop's
/// window. Going to a step scrolls the code to it in the same frame, and
/// going back to step 0 scrolls it back to the header.
#[test]
fn the_current_line_stays_in_sight_beside_many_variables() {
    let mut harness = support::harness_sized(1280.0, 800.0);
    harness
        .state_mut()
        .load_sample("hexagon", Some(Structure::HalfEdge))
        .expect("opens");
    harness.run();
    support::run_flip_edge(&mut harness, 2);
    for step in [70, usize::MAX, 0, 70, 71] {
        harness.state_mut().trace_goto(step).expect("goto");
        // In the first frame after the step, not a frame later.
        harness.step();
        let state = harness.state().state();
        let trace = state.trace.expect("tracing");
        assert!(trace.variables.len() >= 10, "{:?}", trace.variables);
        let [first, last] = state.layout.source_lines.expect("the source shows");
        assert!(
            (first..=last).contains(&trace.line),
            "step {}: line {} is out of sight, lines {first}..={last} show",
            trace.step,
            trace.line
        );
        assert!(
            last - first + 1 >= 8,
            "step {}: only lines {first}..={last} show",
            trace.step
        );
        if step == 70 || step == 71 {
            // In the middle of the code, the line is scrolled to the middle
            // of the view: the rows are where the offset assumed.
            let middle = (first + last) / 2;
            assert!(
                trace.line.abs_diff(middle) <= 1,
                "step {}: line {} is not centred in lines {first}..={last}",
                trace.step,
                trace.line
            );
        }
        assert_bounded(&state.layout, "beside ten variables");
    }
}
