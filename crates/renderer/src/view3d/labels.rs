//! Screen-space overlays painted with egui after the 3D pass: id/label boxes,
//! comparison pointers, the hover preview and the axis letters.
//!
//! Labels are culled to the view and capped: highlighted ones always show,
//! the rest (in the Always mode) nearest first, skipping any that would
//! overlap one already placed, up to [`MAX_LABELS`].

use std::collections::HashMap;

use super::axes;
use super::picking::PickAccel;
use edgewise_core::schema::{ElementKind, ElementRef};
use edgewise_pictures::camera::ViewTransforms;
use edgewise_pictures::options::{DrawIds, ViewOptions};
use edgewise_pictures::palette::Palette;
use edgewise_pictures::scene::{Scene, Sizes};
use edgewise_pictures::styles::SceneStyles;
use egui::{Color32, FontId, Painter, Pos2, Rect, Stroke, StrokeKind, Vec2, vec2};

/// Most labels drawn in one frame besides the highlighted ones.
pub const MAX_LABELS: usize = 600;

/// Label candidates gathered per element kind (nearest first) in the Always
/// mode; overlapping ones are dropped, so more are gathered than drawn.
const CANDIDATES: usize = 1500;

/// Everything the overlays need for one frame.
pub struct Overlay<'a> {
    pub painter: &'a Painter,
    pub transforms: &'a ViewTransforms,
    pub scene: &'a Scene,
    pub accel: &'a PickAccel,
    pub styles: &'a SceneStyles,
    pub options: &'a ViewOptions,
    pub sizes: Sizes,
    pub palette: Palette,
}

/// Space between a label's text and its box.
const LABEL_PADDING: Vec2 = vec2(3.0, 1.0);

/// A label box laid out on screen.
struct LaidOut {
    placed: Placed,
    galley: std::sync::Arc<egui::Galley>,
    rect: Rect,
    border: Option<Color32>,
    /// Moved off its element to avoid another label.
    moved: bool,
}

/// A label ready to place: where its box attaches on screen and how.
struct Placed {
    pick: ElementRef,
    /// Bottom-center of the box for vertices and winged edges (drawn above
    /// the element), center for faces and half-edges.
    anchor: Pos2,
    above: bool,
    depth: f32,
}

impl Overlay<'_> {
    fn viewport(&self) -> Rect {
        self.transforms.viewport
    }

    fn font(&self) -> FontId {
        let scale = if self.options.label_scale.is_finite() {
            self.options.label_scale.clamp(0.2, 8.0)
        } else {
            1.0
        };
        FontId::proportional(12.5 * scale)
    }

    /// Projected radius of a vertex sphere in points at `depth`.
    fn vertex_radius_points(&self, depth: f32) -> f32 {
        self.sizes.vertex_radius / self.transforms.world_per_point(depth).max(1e-30)
    }

    /// Where `pick`'s label attaches on screen, or `None` off screen.
    fn place(&self, pick: ElementRef) -> Option<Placed> {
        let world = self.scene.anchor(pick)?;
        let (pos, depth) = self.transforms.project(world)?;
        if !self.viewport().expand(20.0).contains(pos) {
            return None;
        }
        let (anchor, above) = match pick.kind {
            ElementKind::Vertex => {
                let highlighted = self.styles.get(pick).colour.is_some();
                let emphasis = if highlighted {
                    Sizes::EMPHASIS_VERTEX
                } else {
                    1.0
                };
                let radius = (self.vertex_radius_points(depth) * emphasis).max(0.9);
                (pos - vec2(0.0, radius + 2.0), true)
            }
            ElementKind::Edge if !self.scene.geometry.half_edges => (pos - vec2(0.0, 4.0), true),
            ElementKind::Edge | ElementKind::Face => (pos, false),
        };
        Some(Placed {
            pick,
            anchor,
            above,
            depth,
        })
    }

    fn text(&self, pick: ElementRef) -> String {
        match self.styles.label(pick) {
            Some(label) => label.to_owned(),
            None => pick.id.to_string(),
        }
    }

    /// Lays a label box out where it belongs (not painted yet).
    fn lay_out(&self, placed: Placed, border: Option<Color32>) -> LaidOut {
        let galley = self.painter.layout_no_wrap(
            self.text(placed.pick),
            self.font(),
            self.palette.label_text,
        );
        let size = galley.size() + LABEL_PADDING * 2.0;
        let min = if placed.above {
            placed.anchor - vec2(size.x * 0.5, size.y)
        } else {
            placed.anchor - size * 0.5
        };
        LaidOut {
            rect: Rect::from_min_size(min, size),
            placed,
            galley,
            border,
            moved: false,
        }
    }

    /// Moves a label to the nearest free place ([`free_place`]).
    fn nudge(label: &mut LaidOut, occupied: &Occupancy) {
        let rect = free_place(label.rect, occupied);
        label.moved = rect != label.rect;
        label.rect = rect;
    }

    /// Paints a laid-out label, with a leader line back to its element if it
    /// was moved.
    fn paint_label(&self, label: &LaidOut) {
        let corner = match label.placed.pick.kind {
            ElementKind::Vertex => label.rect.height() * 0.5,
            ElementKind::Edge => 2.0,
            ElementKind::Face => 0.0,
        };
        let stroke = match label.border {
            Some(colour) => Stroke::new(1.5, colour),
            None => Stroke::new(1.0, self.palette.label_stroke),
        };
        if label.moved {
            let anchor = label.placed.anchor;
            self.painter.line_segment(
                [anchor, label.rect.clamp(anchor)],
                Stroke::new(1.0, stroke.color),
            );
        }
        self.painter.rect(
            label.rect,
            corner,
            self.palette.label_fill,
            stroke,
            StrokeKind::Inside,
        );
        self.painter.galley(
            label.rect.min + LABEL_PADDING,
            label.galley.clone(),
            self.palette.label_text,
        );
    }

    /// Paints the id/label boxes. `highlighted` lists the elements with a
    /// colour or a label (cached by the view).
    pub fn paint_labels(&self, highlighted: &[ElementRef], hovered: Option<ElementRef>) {
        if self.options.draw_ids == DrawIds::Never {
            return;
        }
        // Highlighted labels: all of them; nearest placed first, each moved
        // off the ones before it, then painted far to near.
        let mut important: Vec<Placed> = highlighted
            .iter()
            .filter(|&&p| Some(p) != hovered)
            .filter_map(|&p| self.place(p))
            .collect();
        important.sort_by(|a, b| a.depth.total_cmp(&b.depth));
        let mut occupied = Occupancy::new(self.font().size);
        // Highlighted vertices stay uncovered: labels move off their spheres.
        for placed in &important {
            if placed.pick.kind == ElementKind::Vertex
                && let Some((pos, depth)) =
                    self.transforms.project(self.scene.position(placed.pick.id))
            {
                let radius =
                    (self.vertex_radius_points(depth) * Sizes::EMPHASIS_VERTEX).max(4.0) + 1.0;
                occupied.claim(Rect::from_center_size(pos, Vec2::splat(radius * 2.0 + 2.0)));
            }
        }
        let mut laid_out = Vec::with_capacity(important.len());
        for placed in important {
            let border = self.styles.get(placed.pick).colour;
            let mut label = self.lay_out(placed, border);
            Self::nudge(&mut label, &occupied);
            occupied.claim(label.rect);
            laid_out.push(label);
        }
        let hover_label = hovered.and_then(|pick| self.place(pick)).map(|placed| {
            let mut label = self.lay_out(placed, Some(self.palette.hover));
            Self::nudge(&mut label, &occupied);
            label
        });
        if let Some(label) = &hover_label {
            occupied.claim(label.rect);
        }

        if self.options.draw_ids == DrawIds::Always {
            let mut rest = self.visible_unhighlighted();
            rest.sort_by(|a, b| a.depth.total_cmp(&b.depth));
            let mut drawn = 0;
            for placed in rest {
                if drawn >= MAX_LABELS {
                    break;
                }
                let estimate = self.estimate_rect(&placed);
                if occupied.is_free(estimate) {
                    occupied.claim(estimate);
                    self.paint_label(&self.lay_out(placed, None));
                    drawn += 1;
                }
            }
        }
        for label in laid_out.iter().rev() {
            self.paint_label(label);
        }
        if let Some(label) = &hover_label {
            self.paint_label(label);
        }
    }

    /// A box size estimate without laying text out (digits are about 0.6 em).
    fn estimate_rect(&self, placed: &Placed) -> Rect {
        let size = self.font().size;
        let characters = placed.pick.id.checked_ilog10().unwrap_or(0) + 1;
        let box_size = vec2(characters as f32 * size * 0.6 + 6.0, size * 1.3 + 2.0);
        if placed.above {
            Rect::from_min_size(placed.anchor - vec2(box_size.x * 0.5, box_size.y), box_size)
        } else {
            Rect::from_center_size(placed.anchor, box_size)
        }
    }

    /// Elements not highlighted whose labels would be on screen, about the
    /// nearest [`CANDIDATES`] of each kind, found front to back through the
    /// picking BVHs so a 200k-face mesh costs no more than a small one.
    fn visible_unhighlighted(&self) -> Vec<Placed> {
        let viewport = self.viewport();
        let eye = self.transforms.eye;
        let keep = |min, max| self.transforms.may_see_box(min, max);
        let mut out = Vec::new();
        let mut collect = |bvh: &super::bvh::Bvh, make: &dyn Fn(u32) -> Option<ElementRef>| {
            let mut found = 0;
            bvh.visit_nearest(eye, keep, |item| {
                if let Some(pick) = make(item)
                    && let Some(placed) = self.place(pick)
                    && viewport.contains(placed.anchor)
                {
                    out.push(placed);
                    found += 1;
                }
                found < CANDIDATES
            });
        };
        collect(&self.accel.vertices, &|v| {
            let pick = ElementRef::new(ElementKind::Vertex, v);
            self.styles.is_plain(pick).then_some(pick)
        });
        collect(&self.accel.edges, &|e| {
            let pick = ElementRef::new(ElementKind::Edge, e);
            self.styles.is_plain(pick).then_some(pick)
        });
        collect(&self.accel.faces, &|t| {
            // A face is found through its first triangle only.
            let face = *self.scene.triangle_faces.get(t as usize)?;
            let first = *self.scene.face_triangle_start.get(face as usize)?;
            let pick = ElementRef::new(ElementKind::Face, face);
            (first == t && self.styles.is_plain(pick)).then_some(pick)
        });
        out
    }

    /// Outlines the hovered element.
    pub fn paint_hover(&self, pick: ElementRef) {
        let colour = self.palette.hover;
        match pick.kind {
            ElementKind::Vertex => {
                if let Some((pos, depth)) = self.transforms.project(self.scene.position(pick.id)) {
                    let radius = self.vertex_radius_points(depth) * Sizes::EMPHASIS_VERTEX + 3.0;
                    self.painter
                        .circle_stroke(pos, radius.max(5.0), Stroke::new(2.0, colour));
                }
            }
            ElementKind::Edge => {
                if let Some((a, b)) = self.scene.drawn_arrow(pick.id as usize, &self.sizes)
                    && let (Some((pa, _)), Some((pb, _))) =
                        (self.transforms.project(a), self.transforms.project(b))
                {
                    self.painter
                        .line_segment([pa, pb], Stroke::new(5.0, colour.gamma_multiply(0.45)));
                }
            }
            ElementKind::Face => {
                let Some(face) = self.scene.geometry.faces.get(pick.id as usize) else {
                    return;
                };
                if face.len() > 256 {
                    return;
                }
                let points: Option<Vec<Pos2>> = face
                    .iter()
                    .map(|&v| {
                        self.transforms
                            .project(self.scene.position(v))
                            .map(|(p, _)| p)
                    })
                    .collect();
                if let Some(mut points) = points
                    && points.len() >= 2
                {
                    if let Some(&first) = points.first() {
                        points.push(first);
                    }
                    self.painter
                        .add(egui::Shape::line(points, Stroke::new(2.0, colour)));
                }
            }
        }
    }

    /// Comparison pointers: an arrow towards each target; a second pointer
    /// at the same element comes from the other side.
    pub fn paint_pointers(&self) {
        let mut seen: Vec<ElementRef> = Vec::new();
        for pointer in &self.styles.pointers {
            let nth = seen.iter().filter(|&&p| p == pointer.target).count();
            seen.push(pointer.target);
            let Some(world) = self.scene.anchor(pointer.target) else {
                continue;
            };
            let Some((pos, depth)) = self.transforms.project(world) else {
                continue;
            };
            if !self.viewport().contains(pos) {
                continue;
            }
            let gap = match pointer.target.kind {
                ElementKind::Vertex => {
                    self.vertex_radius_points(depth) * Sizes::EMPHASIS_VERTEX + 3.0
                }
                ElementKind::Edge | ElementKind::Face => 4.0,
            };
            // From the lower left, then the lower right, then around.
            let angle = std::f32::consts::FRAC_PI_4 * (3.0 - 2.0 * nth as f32);
            let direction = Vec2::angled(angle);
            let tip = pos + direction * gap;
            let tail = tip + direction * 40.0;
            paint_arrow(
                self.painter,
                tail,
                tip,
                pointer.colour,
                self.palette.background,
            );
        }
    }

    /// The axis letters at the axis tips.
    pub fn paint_axis_letters(&self) {
        for (world, letter, colour) in axes::letters(self.scene, &self.palette) {
            if let Some((pos, _)) = self.transforms.project(world)
                && self.viewport().contains(pos)
            {
                self.painter.text(
                    pos,
                    egui::Align2::CENTER_CENTER,
                    letter,
                    FontId::proportional(14.0),
                    colour,
                );
            }
        }
    }
}

/// A thick arrow with an outline in `halo` so it reads on any background.
fn paint_arrow(painter: &Painter, tail: Pos2, tip: Pos2, colour: Color32, halo: Color32) {
    let along = (tip - tail).normalized();
    let side = along.rot90();
    let head_base = tip - along * 13.0;
    let head = vec![tip, head_base + side * 7.0, head_base - side * 7.0];
    painter.line_segment([tail, head_base], Stroke::new(6.0, halo));
    painter.add(egui::Shape::convex_polygon(
        head.clone(),
        halo,
        Stroke::new(2.5, halo),
    ));
    painter.line_segment([tail, head_base], Stroke::new(3.5, colour));
    painter.add(egui::Shape::convex_polygon(head, colour, Stroke::NONE));
}

/// Rectangles taken by labels, bucketed in a coarse grid of screen cells so
/// checking a new label against them is cheap.
/// The place nearest `rect` that overlaps no label already placed: a line
/// at a time up or down, then half a box and a box to either side, nearest
/// first. Around a selected element seven role labels crowd a few vertex
/// radii; where even those places are taken, the one that overlaps least.
fn free_place(rect: Rect, occupied: &Occupancy) -> Rect {
    let (across, down) = (rect.width() * 0.5 + 4.0, rect.height() + 2.0);
    let mut offsets: Vec<Vec2> = (-5..=5_i8)
        .flat_map(|k| (-2..=2_i8).map(move |h| vec2(f32::from(h) * across, f32::from(k) * down)))
        .collect();
    // Up before down, and straight before aside, at equal distance.
    offsets.sort_by(|a, b| {
        let key = |v: &Vec2| (v.x.abs() / across * 1.5 + v.y.abs() / down, v.y > 0.0);
        let (ka, kb) = (key(a), key(b));
        ka.0.total_cmp(&kb.0).then(ka.1.cmp(&kb.1))
    });
    let candidates = offsets.iter().map(|&offset| rect.translate(offset));
    candidates
        .clone()
        .find(|candidate| occupied.is_free(*candidate))
        .unwrap_or_else(|| {
            candidates
                .min_by(|a, b| occupied.overlap(*a).total_cmp(&occupied.overlap(*b)))
                .unwrap_or(rect)
        })
}

struct Occupancy {
    cell: f32,
    cells: HashMap<(i32, i32), Vec<Rect>>,
}

impl Occupancy {
    fn new(font_size: f32) -> Self {
        Self {
            cell: (font_size * 3.0).max(8.0),
            cells: HashMap::new(),
        }
    }

    fn cells_of(&self, rect: Rect) -> impl Iterator<Item = (i32, i32)> + use<> {
        let cell = self.cell;
        let to_cell = move |x: f32| (x / cell).floor() as i32;
        let (x0, x1) = (to_cell(rect.min.x), to_cell(rect.max.x));
        let (y0, y1) = (to_cell(rect.min.y), to_cell(rect.max.y));
        (x0..=x1).flat_map(move |x| (y0..=y1).map(move |y| (x, y)))
    }

    fn is_free(&self, rect: Rect) -> bool {
        let rect = rect.shrink(1.0);
        self.cells_of(rect).all(|c| {
            self.cells
                .get(&c)
                .is_none_or(|taken| taken.iter().all(|r| !r.intersects(rect)))
        })
    }

    /// How much of `rect` labels already cover, in square points.
    fn overlap(&self, rect: Rect) -> f32 {
        let rect = rect.shrink(1.0);
        let mut seen: Vec<Rect> = Vec::new();
        for c in self.cells_of(rect) {
            for taken in self.cells.get(&c).into_iter().flatten() {
                if !seen.contains(taken) {
                    seen.push(*taken);
                }
            }
        }
        seen.iter()
            .map(|taken| taken.intersect(rect))
            .filter(Rect::is_positive)
            .map(|both| both.area())
            .sum()
    }

    fn claim(&mut self, rect: Rect) {
        let rect = rect.shrink(1.0);
        for c in self.cells_of(rect) {
            self.cells.entry(c).or_default().push(rect);
        }
    }
}

#[cfg(test)]
mod tests {
    use egui::pos2;

    use super::*;

    #[test]
    fn occupancy_rejects_overlaps() {
        let mut grid = Occupancy::new(12.0);
        let a = Rect::from_min_size(pos2(0.0, 0.0), vec2(30.0, 15.0));
        assert!(grid.is_free(a));
        grid.claim(a);
        assert!(!grid.is_free(a.translate(vec2(5.0, 0.0))));
        assert!(grid.is_free(a.translate(vec2(100.0, 0.0))));
        // Near but not touching: free, even in the same cell.
        assert!(grid.is_free(a.translate(vec2(31.0, 0.0))));
    }

    #[test]
    fn a_crowded_label_goes_to_the_nearest_free_place() {
        let label = Rect::from_min_size(pos2(100.0, 100.0), vec2(80.0, 16.0));
        let mut grid = Occupancy::new(12.0);
        assert_eq!(free_place(label, &grid), label, "free: it stays");
        // Its own place and the lines above and below it are taken.
        for k in -5..=5 {
            grid.claim(label.translate(vec2(0.0, k as f32 * 18.0)));
        }
        let moved = free_place(label, &grid);
        assert!(grid.is_free(moved), "{moved:?}");
        assert_eq!(
            moved.center().y,
            label.center().y,
            "beside, on its own line"
        );
        // Everything around taken: the least covered place.
        let mut full = Occupancy::new(12.0);
        for k in -6..=6 {
            for h in -3..=3 {
                if (k, h) != (-5, 2) {
                    full.claim(label.translate(vec2(h as f32 * 44.0, k as f32 * 18.0)));
                }
            }
        }
        let least = free_place(label, &full);
        assert!(
            full.overlap(least) < full.overlap(label),
            "{least:?} overlaps less than where it was"
        );
    }
}
