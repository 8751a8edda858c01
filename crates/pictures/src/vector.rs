//! The view as flat vector shapes, for exports that stay crisp in print:
//! see-through faces as polygons, edges as lines with arrowheads, vertices as
//! discs and ids as labels, in the colours and from the camera of the view
//! on screen, painted far to near.
//!
//! What it leaves out: shading, the orientation marks, the axes and the
//! comparison pointers. A mesh with more than [`MAX_SHAPES_EDGES`] edges is
//! drawn as its faces only, as the view's coarse level of detail does.

use ecolor::Color32;
use emath::{Pos2, Rect, Vec2, vec2};
use glam::Vec3;

use edgewise_core::schema::{ElementKind, ElementRef};

use crate::camera::ViewTransforms;
use crate::options::{DrawIds, ViewOptions};
use crate::palette::{Palette, face_colour, line_colour};
use crate::scene::{Scene, Sizes};
use crate::styles::ElementStyle;

/// Above this many arrows, edges and vertices are left out.
pub const MAX_SHAPES_EDGES: usize = 20_000;
/// At most this many unhighlighted ids are labelled.
const MAX_PLAIN_LABELS: usize = 400;

/// One flat shape, in points from the view's top left.
#[derive(Clone, Debug, PartialEq)]
pub enum Shape {
    Polygon {
        points: Vec<Pos2>,
        fill: Color32,
        /// 0 to 1.
        opacity: f32,
    },
    /// An edge: its shaft, and its head as a triangle at `to`.
    Arrow {
        from: Pos2,
        to: Pos2,
        head: [Pos2; 3],
        colour: Color32,
        width: f32,
    },
    Disc {
        centre: Pos2,
        radius: f32,
        fill: Color32,
    },
    /// A label box centred at `centre`, [`label_size`] big.
    Label {
        centre: Pos2,
        text: String,
        border: Option<Color32>,
    },
}

/// The view at one moment, ready to be written as SVG or PDF.
#[derive(Clone, Debug, PartialEq)]
pub struct VectorView {
    pub size: Vec2,
    pub palette: Palette,
    /// Painted in order.
    pub shapes: Vec<Shape>,
}

/// What the view knows about each element's look.
pub struct Looks<'a> {
    pub styles: &'a std::collections::BTreeMap<ElementRef, ElementStyle>,
    pub fade_others: bool,
}

impl Looks<'_> {
    fn get(&self, element: ElementRef) -> ElementStyle {
        self.styles.get(&element).cloned().unwrap_or(ElementStyle {
            faded: self.fade_others,
            ..ElementStyle::default()
        })
    }

    fn highlighted(&self, element: ElementRef) -> bool {
        self.styles
            .get(&element)
            .is_some_and(|style| style.colour.is_some() || style.label.is_some())
    }
}

/// Builds the vector view of `scene` as `transforms` sees it.
pub fn vector_view(
    scene: &Scene,
    looks: &Looks<'_>,
    transforms: &ViewTransforms,
    options: &ViewOptions,
) -> VectorView {
    let palette = Palette::of(options);
    let viewport = transforms.viewport;
    let origin = viewport.min.to_vec2();
    let local = |p: Pos2| p - origin;
    let project = |world: Vec3| {
        transforms
            .project(world)
            .map(|(at, depth)| (local(at), depth))
    };
    let mut depth_sorted: Vec<(f32, Shape)> = Vec::new();

    // Faces, far to near, under everything else.
    let mut faces: Vec<(f32, Shape)> = Vec::new();
    for (f, corners) in scene.geometry.faces.iter().enumerate() {
        let element = ElementRef::new(ElementKind::Face, f as u32);
        let points: Option<Vec<(Pos2, f32)>> = corners
            .iter()
            .map(|&v| project(scene.position(v)))
            .collect();
        let Some(points) = points.filter(|p| p.len() >= 3) else {
            continue;
        };
        let depth = points.iter().map(|(_, d)| d).sum::<f32>() / points.len() as f32;
        let (fill, mut opacity) = face_colour(&looks.get(element), &palette);
        if options.solid_faces {
            opacity = 1.0;
        }
        faces.push((
            depth,
            Shape::Polygon {
                points: points.into_iter().map(|(p, _)| p).collect(),
                fill,
                opacity,
            },
        ));
    }
    faces.sort_by(|a, b| b.0.total_cmp(&a.0));

    let detailed = scene.edge_count() <= MAX_SHAPES_EDGES;
    let sizes = scene.sizes(options.mesh_scale);
    if detailed {
        for e in 0..scene.edge_count() {
            let element = ElementRef::new(ElementKind::Edge, e as u32);
            let Some((a, b)) = scene.drawn_arrow(e, &sizes) else {
                continue;
            };
            let (Some((from, da)), Some((to, db))) = (project(a), project(b)) else {
                continue;
            };
            let style = looks.get(element);
            let base = if scene.is_boundary_half_edge(e) {
                palette.boundary
            } else {
                palette.line
            };
            let emphasis = if style.colour.is_some() {
                Sizes::EMPHASIS_EDGE
            } else {
                1.0
            };
            let depth = (da + db) * 0.5;
            let points_per_world = 1.0 / transforms.world_per_point(depth).max(1e-9);
            let width = (2.0 * sizes.shaft_radius * points_per_world * emphasis).clamp(0.6, 6.0);
            let head_length =
                (sizes.head_length * points_per_world * emphasis).clamp(4.0, 3.0 * width + 14.0);
            let head_half = (sizes.head_radius * points_per_world * emphasis).clamp(2.0, 10.0);
            depth_sorted.push((
                depth,
                Shape::Arrow {
                    from,
                    to,
                    head: arrowhead(from, to, head_length, head_half),
                    colour: line_colour(&style, &palette, base),
                    width,
                },
            ));
        }
        for v in 0..scene.vertex_count() {
            let element = ElementRef::new(ElementKind::Vertex, v as u32);
            let Some((centre, depth)) = project(scene.position(v as u32)) else {
                continue;
            };
            let style = looks.get(element);
            let emphasis = if style.colour.is_some() {
                Sizes::EMPHASIS_VERTEX
            } else {
                1.0
            };
            let radius = (sizes.vertex_radius / transforms.world_per_point(depth).max(1e-9)
                * emphasis)
                .clamp(1.0, 24.0);
            depth_sorted.push((
                depth,
                Shape::Disc {
                    centre,
                    radius,
                    fill: line_colour(&style, &palette, palette.line),
                },
            ));
        }
    }
    depth_sorted.sort_by(|a, b| b.0.total_cmp(&a.0));

    let mut shapes: Vec<Shape> = faces.into_iter().map(|(_, shape)| shape).collect();
    shapes.extend(depth_sorted.into_iter().map(|(_, shape)| shape));
    shapes.extend(labels(scene, looks, &project, options, viewport));
    VectorView {
        size: viewport.size(),
        palette,
        shapes,
    }
}

/// Where an arrow's shaft stops: where its head begins, so the tip stays
/// sharp; at the tip itself for an arrow shorter than its head.
pub fn shaft_end(from: Pos2, to: Pos2, head: &[Pos2; 3]) -> Pos2 {
    let base = Pos2::new((head[1].x + head[2].x) * 0.5, (head[1].y + head[2].y) * 0.5);
    if from.distance(to) > from.distance(base) {
        base
    } else {
        to
    }
}

/// The head of an arrow ending at `to`: its tip and the two back corners.
fn arrowhead(from: Pos2, to: Pos2, length: f32, half_width: f32) -> [Pos2; 3] {
    let direction = (to - from).normalized();
    if !direction.x.is_finite() || !direction.y.is_finite() {
        return [to; 3];
    }
    let back = to - direction * length;
    let side = vec2(-direction.y, direction.x) * half_width;
    [to, back + side, back - side]
}

/// Id labels: every highlighted element's (its label, or its id), and with
/// ids shown always, the rest up to [`MAX_PLAIN_LABELS`].
fn labels(
    scene: &Scene,
    looks: &Looks<'_>,
    project: &dyn Fn(Vec3) -> Option<(Pos2, f32)>,
    options: &ViewOptions,
    viewport: Rect,
) -> Vec<Shape> {
    if options.draw_ids == DrawIds::Never {
        return Vec::new();
    }
    let bounds = Rect::from_min_size(Pos2::ZERO, viewport.size());
    let mut out = Vec::new();
    let mut taken: Vec<Rect> = Vec::new();
    let mut plain = 0;
    let kinds = [
        (ElementKind::Face, scene.face_count()),
        (ElementKind::Edge, scene.edge_count()),
        (ElementKind::Vertex, scene.vertex_count()),
    ];
    for (kind, count) in kinds {
        for id in 0..count as u32 {
            let element = ElementRef::new(kind, id);
            let highlighted = looks.highlighted(element);
            if !highlighted {
                if options.draw_ids != DrawIds::Always || plain >= MAX_PLAIN_LABELS {
                    continue;
                }
                plain += 1;
            }
            let Some((at, _)) = scene.anchor(element).and_then(project) else {
                continue;
            };
            if !bounds.contains(at) {
                continue;
            }
            let style = looks.get(element);
            let anchor = match kind {
                ElementKind::Vertex => at - vec2(0.0, 14.0),
                _ => at,
            };
            let text = style.label.clone().unwrap_or_else(|| id.to_string());
            let size = label_size(&text);
            // Moved up or down, a row at a time, off the labels before it.
            let centre = (0..12)
                .map(|step| {
                    let rows = (step + 1) / 2;
                    let sign = if step % 2 == 0 { 1.0 } else { -1.0 };
                    anchor + vec2(0.0, sign * rows as f32 * size.y)
                })
                .find(|c| {
                    let rect = Rect::from_center_size(*c, size);
                    !taken.iter().any(|t: &Rect| t.intersects(rect))
                })
                .unwrap_or(anchor);
            taken.push(Rect::from_center_size(centre, size));
            out.push(Shape::Label {
                centre,
                text,
                border: style.colour,
            });
        }
    }
    out
}

/// The box a label takes, in points: 12-point text with a margin.
pub fn label_size(text: &str) -> Vec2 {
    vec2(text.chars().count() as f32 * 12.0 * 0.62 + 8.0, 18.0)
}

#[cfg(test)]
mod tests {
    use super::*;
    use emath::pos2;

    #[test]
    fn an_arrowhead_points_along_its_edge() {
        let [tip, left, right] = arrowhead(pos2(0.0, 0.0), pos2(10.0, 0.0), 4.0, 2.0);
        assert_eq!(tip, pos2(10.0, 0.0));
        assert_eq!(left, pos2(6.0, 2.0));
        assert_eq!(right, pos2(6.0, -2.0));
        let degenerate = arrowhead(pos2(1.0, 1.0), pos2(1.0, 1.0), 4.0, 2.0);
        assert_eq!(degenerate, [pos2(1.0, 1.0); 3]);
    }
}
