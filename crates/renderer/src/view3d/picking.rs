//! CPU ray picking: vertex spheres, edge arrows (as capsules) and face
//! triangles, each kind through its own BVH built once per mesh.
//!
//! Vertices and edges are picked within a few pixels of the cursor, not only
//! on exact hits, so thin arrows stay easy to click. Vertices win over edges,
//! edges over faces; within a kind an exact hit wins by depth, otherwise the
//! nearest on screen. Faces are see-through, so they hide nothing unless
//! they are drawn solid.

use glam::Vec3;

use super::PickFilter;
use super::bvh::{Bvh, ray_box};
use edgewise_core::schema::{ElementKind, ElementRef};
use edgewise_pictures::camera::{Ray, ViewTransforms};
use edgewise_pictures::scene::{Scene, Sizes};

/// How close (in points) the cursor must come to a vertex or an edge.
pub const VERTEX_TOLERANCE: f32 = 7.0;
pub const EDGE_TOLERANCE: f32 = 5.0;

/// The BVHs of one mesh. Vertex and edge boxes are the bare points and
/// segments; queries widen them by the tolerance at each node's depth.
#[derive(Default)]
pub struct PickAccel {
    pub vertices: Bvh,
    pub edges: Bvh,
    /// Over triangles (see [`Scene::triangles`]).
    pub faces: Bvh,
}

impl PickAccel {
    /// Every hierarchy at once.
    #[cfg(test)]
    pub fn new(scene: &Scene) -> Self {
        let mut accel = Self::default();
        for kind in [ElementKind::Vertex, ElementKind::Edge, ElementKind::Face] {
            accel.build(scene, kind);
        }
        accel
    }

    /// Builds the hierarchy of one kind of element (a slice of
    /// [`super::Preparation`]).
    pub fn build(&mut self, scene: &Scene, kind: ElementKind) {
        match kind {
            ElementKind::Vertex => {
                let boxes: Vec<(Vec3, Vec3)> = (0..scene.vertex_count())
                    .map(|v| {
                        let p = scene.position(u32::try_from(v).unwrap_or(u32::MAX));
                        (p, p)
                    })
                    .collect();
                self.vertices = Bvh::build(&boxes);
            }
            ElementKind::Edge => {
                let boxes: Vec<(Vec3, Vec3)> = scene
                    .arrow_starts
                    .iter()
                    .zip(&scene.arrow_ends)
                    .map(|(a, b)| (a.min(*b), a.max(*b)))
                    .collect();
                self.edges = Bvh::build(&boxes);
            }
            ElementKind::Face => {
                let boxes: Vec<(Vec3, Vec3)> = scene
                    .triangles
                    .iter()
                    .map(|t| {
                        let [a, b, c] = t.map(|v| scene.position(v));
                        (a.min(b).min(c), a.max(b).max(c))
                    })
                    .collect();
                self.faces = Bvh::build(&boxes);
            }
        }
    }
}

/// A candidate of one kind: exact hits rank by depth, near misses by screen
/// distance, and exact hits beat near misses.
#[derive(Clone, Copy, Debug)]
struct Candidate {
    index: u32,
    exact: bool,
    depth: f32,
    screen_distance: f32,
}

impl Candidate {
    fn better_than(&self, other: &Self) -> bool {
        match (self.exact, other.exact) {
            (true, false) => true,
            (false, true) => false,
            (true, true) => self.depth < other.depth,
            (false, false) => self.screen_distance < other.screen_distance,
        }
    }
}

fn keep_best(best: &mut Option<Candidate>, candidate: Candidate) {
    if best.is_none_or(|b| candidate.better_than(&b)) {
        *best = Some(candidate);
    }
}

/// What a query needs about the frame.
pub struct PickQuery<'a> {
    pub scene: &'a Scene,
    pub accel: &'a PickAccel,
    pub transforms: &'a ViewTransforms,
    pub sizes: Sizes,
    pub filter: PickFilter,
    pub solid_faces: bool,
}

impl PickQuery<'_> {
    /// The element under a point on screen, if any.
    pub fn pick(&self, screen: egui::Pos2) -> Option<ElementRef> {
        let ray = self.transforms.ray(screen);
        if !ray.direction.is_finite() {
            return None;
        }
        let allowed = |kind: ElementKind| match self.filter {
            PickFilter::All => true,
            PickFilter::Only(only) => only == kind,
        };
        // Solid faces hide what is behind them, whichever kind is pickable.
        let face_hit = if allowed(ElementKind::Face) || self.solid_faces {
            self.nearest_face(&ray)
        } else {
            None
        };
        let occluder = if self.solid_faces {
            face_hit.map_or(f32::INFINITY, |(_, t)| {
                t * 1.0005 + self.sizes.vertex_radius
            })
        } else {
            f32::INFINITY
        };
        if allowed(ElementKind::Vertex)
            && let Some(v) = self.nearest_vertex(&ray, occluder)
        {
            return Some(ElementRef::new(ElementKind::Vertex, v.index));
        }
        if allowed(ElementKind::Edge)
            && let Some(e) = self.nearest_edge(&ray, occluder)
        {
            return Some(ElementRef::new(ElementKind::Edge, e.index));
        }
        if allowed(ElementKind::Face) {
            return face_hit.map(|(f, _)| ElementRef::new(ElementKind::Face, f));
        }
        None
    }

    /// World units per point of cursor tolerance at depth `t`.
    fn tolerance_at(&self, t: f32, points: f32) -> f32 {
        self.transforms.world_per_point(t.max(0.0)) * points
    }

    /// Whether a node's box, widened by `radius` plus `points` of screen
    /// tolerance at its far side, meets the ray.
    fn node_near_ray(
        &self,
        ray: &Ray,
        inv: Vec3,
        min: Vec3,
        max: Vec3,
        radius: f32,
        points: f32,
    ) -> bool {
        let center = (min + max) * 0.5;
        let far = (center - ray.origin).length() + (max - min).length() * 0.5;
        let grow = radius + self.tolerance_at(far, points);
        ray_box(ray.origin, inv, min - grow, max + grow).is_some()
    }

    fn nearest_vertex(&self, ray: &Ray, occluder: f32) -> Option<Candidate> {
        let radius = self.sizes.vertex_radius * Sizes::EMPHASIS_VERTEX;
        let inv = ray.direction.recip();
        let mut best = None;
        self.accel.vertices.visit(
            |min, max| self.node_near_ray(ray, inv, min, max, radius, VERTEX_TOLERANCE),
            |v| {
                let p = self.scene.position(v);
                let t = (p - ray.origin).dot(ray.direction);
                if t <= 0.0 || t > occluder {
                    return;
                }
                let miss = ray.at(t).distance(p);
                let points = self.transforms.world_per_point(t);
                let reach = self.sizes.vertex_radius.max(points * VERTEX_TOLERANCE);
                if miss <= reach {
                    keep_best(
                        &mut best,
                        Candidate {
                            index: v,
                            exact: miss <= self.sizes.vertex_radius,
                            depth: t,
                            screen_distance: miss / points.max(1e-30),
                        },
                    );
                }
            },
        );
        best
    }

    fn nearest_edge(&self, ray: &Ray, occluder: f32) -> Option<Candidate> {
        let radius = self.sizes.head_radius * Sizes::EMPHASIS_EDGE;
        let inv = ray.direction.recip();
        let mut best = None;
        self.accel.edges.visit(
            |min, max| self.node_near_ray(ray, inv, min, max, radius, EDGE_TOLERANCE),
            |e| {
                let Some((a, b)) = self.scene.drawn_arrow(e as usize, &self.sizes) else {
                    return;
                };
                let Some((t, miss)) = ray_segment(ray, a, b) else {
                    return;
                };
                if t <= 0.0 || t > occluder {
                    return;
                }
                let points = self.transforms.world_per_point(t);
                let thickness = self.sizes.shaft_radius * 1.5;
                let reach = thickness.max(points * EDGE_TOLERANCE);
                if miss <= reach {
                    keep_best(
                        &mut best,
                        Candidate {
                            index: e,
                            exact: miss <= thickness,
                            depth: t,
                            screen_distance: miss / points.max(1e-30),
                        },
                    );
                }
            },
        );
        best
    }

    /// The nearest face the ray crosses and the distance along the ray.
    fn nearest_face(&self, ray: &Ray) -> Option<(u32, f32)> {
        let inv = ray.direction.recip();
        let mut best: Option<(u32, f32)> = None;
        let best_t = std::cell::Cell::new(f32::INFINITY);
        self.accel.faces.visit(
            |min, max| {
                ray_box(ray.origin, inv, min, max).is_some_and(|(enter, _)| enter <= best_t.get())
            },
            |tri| {
                let Some(&[a, b, c]) = self.scene.triangles.get(tri as usize) else {
                    return;
                };
                let [a, b, c] = [a, b, c].map(|v| self.scene.position(v));
                if let Some(t) = ray_triangle(ray, a, b, c)
                    && t < best_t.get()
                {
                    best_t.set(t);
                    if let Some(&face) = self.scene.triangle_faces.get(tri as usize) {
                        best = Some((face, t));
                    }
                }
            },
        );
        best
    }
}

/// Closest approach of a ray and a segment: the ray parameter there and the
/// distance between them. `None` for a degenerate ray.
pub fn ray_segment(ray: &Ray, a: Vec3, b: Vec3) -> Option<(f32, f32)> {
    let d = ray.direction;
    let e = b - a;
    let w = ray.origin - a;
    let ee = e.dot(e);
    if ee <= 0.0 {
        let t = (a - ray.origin).dot(d);
        return Some((t, ray.at(t).distance(a)));
    }
    let de = d.dot(e);
    let dw = d.dot(w);
    let ew = e.dot(w);
    // Minimise |w + t d - s e| over t (ray) and s in [0, 1] (segment).
    let denominator = ee - de * de; // |d| = 1
    let mut s = if denominator > 1e-12 * ee {
        ((ew - de * dw) / denominator).clamp(0.0, 1.0)
    } else {
        0.0
    };
    let mut t = -dw + s * de;
    if t < 0.0 {
        t = 0.0;
        s = (ew / ee).clamp(0.0, 1.0);
    } else {
        // Re-project onto the segment for the clamped s.
        s = ((ray.at(t) - a).dot(e) / ee).clamp(0.0, 1.0);
        t = (a + e * s - ray.origin).dot(d).max(0.0);
    }
    let distance = ray.at(t).distance(a + e * s);
    Some((t, distance))
}

/// Möller–Trumbore, two-sided: the ray parameter of the hit, if any.
pub fn ray_triangle(ray: &Ray, a: Vec3, b: Vec3, c: Vec3) -> Option<f32> {
    let e1 = b - a;
    let e2 = c - a;
    let p = ray.direction.cross(e2);
    let det = e1.dot(p);
    let scale = e1.length_squared().max(e2.length_squared());
    if det.abs() <= 1e-12 * scale || !det.is_finite() {
        return None;
    }
    let inv = 1.0 / det;
    let s = ray.origin - a;
    let u = s.dot(p) * inv;
    if !(0.0..=1.0).contains(&u) {
        return None;
    }
    let q = s.cross(e1);
    let v = ray.direction.dot(q) * inv;
    if v < 0.0 || u + v > 1.0 {
        return None;
    }
    let t = e2.dot(q) * inv;
    (t > 0.0).then_some(t)
}

#[cfg(test)]
mod tests {
    use egui::{Pos2, Rect, Vec2};

    use super::*;
    use edgewise_pictures::camera::Camera;
    use edgewise_pictures::geometry::{EdgeGeometry, MeshGeometry};

    /// A unit square in the z = 0 plane split into two triangles, with its
    /// five edges (the diagonal included), seen from +Z.
    fn square(half_edges: bool) -> Scene {
        let positions = vec![
            Vec3::new(0.0, 0.0, 0.0),
            Vec3::new(1.0, 0.0, 0.0),
            Vec3::new(1.0, 1.0, 0.0),
            Vec3::new(0.0, 1.0, 0.0),
        ];
        let edges = if half_edges {
            // Face 0 = (0, 1, 2): half-edges 0, 1, 2; face 1 = (0, 2, 3): 3, 4, 5;
            // boundary pairs 6.. for the outside.
            let e = |start, end, face, pair| EdgeGeometry {
                start,
                end,
                face,
                pair: Some(pair),
            };
            vec![
                e(0, 1, Some(0), 6),
                e(1, 2, Some(0), 7),
                e(2, 0, Some(0), 3),
                e(0, 2, Some(1), 2),
                e(2, 3, Some(1), 8),
                e(3, 0, Some(1), 9),
                e(1, 0, None, 0),
                e(2, 1, None, 1),
                e(3, 2, None, 4),
                e(0, 3, None, 5),
            ]
        } else {
            [(0, 1), (1, 2), (2, 0), (2, 3), (3, 0)]
                .into_iter()
                .map(|(start, end)| EdgeGeometry {
                    start,
                    end,
                    face: None,
                    pair: None,
                })
                .collect()
        };
        Scene::new(MeshGeometry {
            positions,
            edges,
            faces: vec![vec![0, 1, 2], vec![0, 2, 3]],
            half_edges,
        })
    }

    fn front_view() -> ViewTransforms {
        let camera = Camera {
            target: [0.5, 0.5, 0.0],
            yaw: 0.0,
            pitch: 0.0,
            distance: 3.0,
        };
        let viewport = Rect::from_min_size(Pos2::ZERO, Vec2::new(600.0, 600.0));
        ViewTransforms::new(camera, viewport, Vec3::new(0.5, 0.5, 0.0), 1.0)
    }

    fn pick_at(scene: &Scene, world: Vec3, filter: PickFilter) -> Option<ElementRef> {
        let transforms = front_view();
        let accel = PickAccel::new(scene);
        let query = PickQuery {
            scene,
            accel: &accel,
            transforms: &transforms,
            sizes: scene.sizes(1.0),
            filter,
            solid_faces: false,
        };
        let (screen, _) = transforms.project(world).unwrap();
        query.pick(screen)
    }

    #[test]
    fn picks_vertices_edges_and_faces() {
        let scene = square(false);
        assert_eq!(
            pick_at(&scene, Vec3::new(1.0, 1.0, 0.0), PickFilter::All),
            Some(ElementRef::new(ElementKind::Vertex, 2))
        );
        assert_eq!(
            pick_at(&scene, Vec3::new(0.5, 0.0, 0.0), PickFilter::All),
            Some(ElementRef::new(ElementKind::Edge, 0))
        );
        assert_eq!(
            pick_at(&scene, Vec3::new(0.0, 0.5, 0.0), PickFilter::All),
            Some(ElementRef::new(ElementKind::Edge, 4))
        );
        assert_eq!(
            pick_at(&scene, Vec3::new(0.8, 0.2, 0.0), PickFilter::All),
            Some(ElementRef::new(ElementKind::Face, 0))
        );
        assert_eq!(
            pick_at(&scene, Vec3::new(0.2, 0.8, 0.0), PickFilter::All),
            Some(ElementRef::new(ElementKind::Face, 1))
        );
        assert_eq!(
            pick_at(&scene, Vec3::new(2.0, 2.0, 0.0), PickFilter::All),
            None
        );
    }

    #[test]
    fn filters_restrict_what_is_picked() {
        let scene = square(false);
        let corner = Vec3::new(1.0, 1.0, 0.0);
        assert_eq!(
            pick_at(
                &scene,
                corner + Vec3::new(-0.05, -0.1, 0.0),
                PickFilter::Only(ElementKind::Face)
            ),
            Some(ElementRef::new(ElementKind::Face, 0))
        );
        assert_eq!(
            pick_at(
                &scene,
                Vec3::new(0.5, 0.0, 0.0),
                PickFilter::Only(ElementKind::Vertex)
            ),
            None
        );
    }

    #[test]
    fn each_half_edge_of_a_pair_is_picked_on_its_side() {
        let scene = square(true);
        // Half-edge 0 (0→1) is inset into face 0 (above the bottom edge); its
        // boundary pair 6 sits below, outside the square.
        let inside = scene.anchor(ElementRef::new(ElementKind::Edge, 0)).unwrap();
        let outside = scene.anchor(ElementRef::new(ElementKind::Edge, 6)).unwrap();
        assert!(inside.y > 0.0 && outside.y < 0.0);
        assert_eq!(
            pick_at(&scene, inside, PickFilter::All),
            Some(ElementRef::new(ElementKind::Edge, 0))
        );
        assert_eq!(
            pick_at(&scene, outside, PickFilter::All),
            Some(ElementRef::new(ElementKind::Edge, 6))
        );
        // The diagonal's two halves go to opposite faces.
        let d0 = scene.anchor(ElementRef::new(ElementKind::Edge, 2)).unwrap();
        let d1 = scene.anchor(ElementRef::new(ElementKind::Edge, 3)).unwrap();
        assert_eq!(
            pick_at(&scene, d0, PickFilter::All),
            Some(ElementRef::new(ElementKind::Edge, 2))
        );
        assert_eq!(
            pick_at(&scene, d1, PickFilter::All),
            Some(ElementRef::new(ElementKind::Edge, 3))
        );
    }

    #[test]
    fn concave_faces_are_picked_inside_only() {
        // An L-shaped face: its notch (upper right) is background.
        let scene = Scene::new(MeshGeometry {
            positions: vec![
                Vec3::new(0.0, 0.0, 0.0),
                Vec3::new(1.0, 0.0, 0.0),
                Vec3::new(1.0, 0.5, 0.0),
                Vec3::new(0.5, 0.5, 0.0),
                Vec3::new(0.5, 1.0, 0.0),
                Vec3::new(0.0, 1.0, 0.0),
            ],
            edges: Vec::new(),
            faces: vec![vec![0, 1, 2, 3, 4, 5]],
            half_edges: false,
        });
        let face = PickFilter::Only(ElementKind::Face);
        assert_eq!(pick_at(&scene, Vec3::new(0.8, 0.8, 0.0), face), None);
        assert_eq!(
            pick_at(&scene, Vec3::new(0.25, 0.8, 0.0), face),
            Some(ElementRef::new(ElementKind::Face, 0))
        );
        assert_eq!(
            pick_at(&scene, Vec3::new(0.8, 0.25, 0.0), face),
            Some(ElementRef::new(ElementKind::Face, 0))
        );
    }

    #[test]
    fn ray_primitives() {
        let ray = Ray {
            origin: Vec3::new(0.0, 0.0, 5.0),
            direction: -Vec3::Z,
        };
        let t = ray_triangle(
            &ray,
            Vec3::new(-1.0, -1.0, 0.0),
            Vec3::new(1.0, -1.0, 0.0),
            Vec3::new(0.0, 1.0, 0.0),
        );
        assert!((t.unwrap() - 5.0).abs() < 1e-5);
        assert_eq!(
            ray_triangle(
                &ray,
                Vec3::new(1.0, 1.0, 0.0),
                Vec3::new(2.0, 1.0, 0.0),
                Vec3::new(1.0, 2.0, 0.0)
            ),
            None
        );
        // Degenerate triangle: never a hit, never a panic.
        assert_eq!(ray_triangle(&ray, Vec3::ZERO, Vec3::ZERO, Vec3::ZERO), None);
        let (t, d) =
            ray_segment(&ray, Vec3::new(-1.0, 0.5, 1.0), Vec3::new(1.0, 0.5, 1.0)).unwrap();
        assert!((t - 4.0).abs() < 1e-5 && (d - 0.5).abs() < 1e-5);
        let (_, d) = ray_segment(&ray, Vec3::new(2.0, 0.0, 1.0), Vec3::new(2.0, 0.0, 1.0)).unwrap();
        assert!((d - 2.0).abs() < 1e-5);
    }

    #[test]
    fn empty_and_degenerate_meshes_pick_nothing() {
        let empty = Scene::new(MeshGeometry {
            positions: vec![],
            edges: vec![],
            faces: vec![],
            half_edges: false,
        });
        assert_eq!(pick_at(&empty, Vec3::ZERO, PickFilter::All), None);
        let coincident = Scene::new(MeshGeometry {
            positions: vec![Vec3::ONE; 3],
            edges: vec![EdgeGeometry {
                start: 0,
                end: 1,
                face: Some(0),
                pair: None,
            }],
            faces: vec![vec![0, 1, 2], vec![7, 8]],
            half_edges: true,
        });
        let _ = pick_at(&coincident, Vec3::ONE, PickFilter::All);
    }
}
