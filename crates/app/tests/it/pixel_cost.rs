//! How many pixels the app's own shapes cover. A software renderer (the
//! browser's `SwiftShader` on a machine without a usable GPU) pays about
//! 45 ns for each pixel an egui shape covers, whatever its colour, and
//! every frame repaints the whole window: a selection repaints the tables.
//! So the tables keep their shapes to the text, the rows' colours and
//! hairlines, and this test keeps it so; the frame rates themselves are
//! measured by `cargo xtask bench-web`.

use crate::support;

use edgewise_core::{
    mesh::Structure,
    schema::{ElementKind, ElementRef},
};
use egui::epaint::Primitive;
use egui_kittest::kittest::Queryable as _;

/// The area, in points, that the frame's meshes cover within `region`: each
/// triangle's area, scaled by the share of its bounding box that lies in
/// both the region and its clip rectangle.
fn covered_area(harness: &support::AppHarness, region: egui::Rect) -> f32 {
    let output = harness.output().clone();
    let primitives = harness
        .ctx
        .tessellate(output.shapes, output.pixels_per_point);
    let mut area = 0.0;
    for primitive in &primitives {
        let Primitive::Mesh(mesh) = &primitive.primitive else {
            continue;
        };
        let visible = primitive.clip_rect.intersect(region);
        if !visible.is_positive() {
            continue;
        }
        for triangle in mesh.indices.chunks_exact(3) {
            let [a, b, c] = [0, 1, 2].map(|i| mesh.vertices[triangle[i] as usize].pos);
            let bounds = egui::Rect::from_points(&[a, b, c]);
            if bounds.area() <= 0.0 {
                continue;
            }
            let inside = bounds.intersect(visible);
            let share = if inside.is_positive() {
                inside.area() / bounds.area()
            } else {
                0.0
            };
            area += share * ((b - a).x * (c - a).y - (b - a).y * (c - a).x).abs() / 2.0;
        }
    }
    area
}

#[test]
fn the_tables_cover_at_most_two_thirds_of_their_panel_with_shapes() {
    let mut harness = support::harness_with("torus-200k", Some(Structure::HalfEdge));
    // A selection colours its element's row and every row it references.
    harness
        .state_mut()
        .select(Some(ElementRef {
            kind: ElementKind::Edge,
            id: 10,
        }))
        .expect("edge 10 exists");
    harness.run();

    let window = harness.ctx.content_rect();
    let title = harness.get_by_label("Faces").rect();
    let tables = egui::Rect::from_min_max(
        egui::pos2(window.left(), title.top()),
        window.right_bottom(),
    );
    assert!(
        tables.height() > 150.0,
        "the tables panel is open: {tables:?}"
    );
    let covered = covered_area(&harness, tables);
    // Text, the selection's rows and the hairlines cover about half; a
    // stripe behind every other row brought it to nearly all.
    assert!(
        covered > 0.2 * tables.area(),
        "the tables are drawn: {covered:.0} of {:.0} points²",
        tables.area()
    );
    assert!(
        covered < 2.0 / 3.0 * tables.area(),
        "the tables' shapes cover {covered:.0} of their panel's {:.0} points²",
        tables.area()
    );
}
