//! The orbit camera and the transforms between world, view, clip and screen.
//!
//! Naming follows `a_from_b`: a matrix that takes coordinates in space `b`
//! to space `a`, so `clip_from_world = clip_from_view * view_from_world`.
//! The world is right-handed with +Y up (the usual OBJ convention).

use emath::{Pos2, Rect, Vec2};
use glam::{Mat4, Vec3, Vec4Swizzles as _};
use serde::{Deserialize, Serialize};

/// Vertical field of view.
pub const FOV_Y: f32 = 40.0 * std::f32::consts::PI / 180.0;

/// Highest pitch (just short of straight down or up, where the orbit would
/// lose its "up").
const MAX_PITCH: f32 = 89.0 * std::f32::consts::PI / 180.0;

/// An orbit camera as plain data: it looks at `target` from `distance` away,
/// turned `yaw` radians around +Y and raised `pitch` radians above the
/// horizon.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Camera {
    pub target: [f32; 3],
    pub yaw: f32,
    pub pitch: f32,
    pub distance: f32,
}

impl Default for Camera {
    fn default() -> Self {
        Self {
            target: [0.0; 3],
            yaw: 0.55,
            pitch: 0.4,
            distance: 5.0,
        }
    }
}

impl Camera {
    /// The same camera with any non-finite or out-of-range field replaced, so
    /// a camera from outside (the JavaScript API) can never break the view.
    pub fn sanitized(self) -> Self {
        let default = Self::default();
        let finite = |x: f32, fallback: f32| if x.is_finite() { x } else { fallback };
        Self {
            target: [
                finite(self.target[0], 0.0),
                finite(self.target[1], 0.0),
                finite(self.target[2], 0.0),
            ],
            yaw: finite(self.yaw, default.yaw).rem_euclid(std::f32::consts::TAU),
            pitch: finite(self.pitch, default.pitch).clamp(-MAX_PITCH, MAX_PITCH),
            distance: if self.distance.is_finite() && self.distance > 0.0 {
                self.distance.clamp(1e-6, 1e9)
            } else {
                default.distance
            },
        }
    }

    pub fn target(&self) -> Vec3 {
        Vec3::from(self.target)
    }

    /// Unit vector from the target towards the eye.
    pub fn backward(&self) -> Vec3 {
        let (sin_yaw, cos_yaw) = self.yaw.sin_cos();
        let (sin_pitch, cos_pitch) = self.pitch.sin_cos();
        Vec3::new(cos_pitch * sin_yaw, sin_pitch, cos_pitch * cos_yaw)
    }

    /// Where the eye is, in world space.
    pub fn eye(&self) -> Vec3 {
        self.target() + self.backward() * self.distance
    }

    pub fn view_from_world(&self) -> Mat4 {
        glam::camera::rh::view::look_at_mat4(self.eye(), self.target(), Vec3::Y)
    }

    pub fn world_from_view(&self) -> Mat4 {
        self.view_from_world().inverse()
    }

    /// Turns the camera around the target by a drag of `delta` points.
    pub fn orbit(&mut self, delta: Vec2) {
        self.yaw = (self.yaw - delta.x * 0.008).rem_euclid(std::f32::consts::TAU);
        self.pitch = (self.pitch + delta.y * 0.008).clamp(-MAX_PITCH, MAX_PITCH);
    }

    /// Moves the target so the content follows a drag of `delta` points in a
    /// viewport `viewport_height` points tall.
    pub fn pan(&mut self, delta: Vec2, viewport_height: f32) {
        let world_from_view = self.world_from_view();
        let right = world_from_view.x_axis.xyz();
        let up = world_from_view.y_axis.xyz();
        let world_per_point = world_per_point(self.distance, viewport_height);
        let target =
            self.target() - right * delta.x * world_per_point + up * delta.y * world_per_point;
        if target.is_finite() {
            self.target = target.to_array();
        }
    }

    /// Zooms in (`factor > 1`) or out (`factor < 1`) towards the target.
    pub fn zoom(&mut self, factor: f32) {
        if factor.is_finite() && factor > 0.0 {
            self.distance = (self.distance / factor).clamp(1e-6, 1e9);
        }
    }

    /// Points at the bounding sphere (`center`, `radius`) from far enough
    /// away that it fits in a viewport of the given aspect ratio, keeping the
    /// direction.
    pub fn frame(&mut self, center: Vec3, radius: f32, aspect: f32) {
        let radius = if radius.is_finite() && radius > 0.0 {
            radius
        } else {
            1.0
        };
        let aspect = if aspect.is_finite() && aspect > 0.0 {
            aspect
        } else {
            1.5
        };
        let half_y = FOV_Y * 0.5;
        let half_x = (half_y.tan() * aspect).atan();
        let half = half_y.min(half_x);
        self.target = center.to_array();
        self.distance = (radius * 1.08 / half.sin()).clamp(1e-6, 1e9);
    }
}

/// The corners of a box about the origin with half-sides of 1: a box's
/// corners are its centre plus its half-sides times each.
const CORNER_SIGNS: [Vec3; 8] = [
    Vec3::new(-1.0, -1.0, -1.0),
    Vec3::new(1.0, -1.0, -1.0),
    Vec3::new(-1.0, 1.0, -1.0),
    Vec3::new(1.0, 1.0, -1.0),
    Vec3::new(-1.0, -1.0, 1.0),
    Vec3::new(1.0, -1.0, 1.0),
    Vec3::new(-1.0, 1.0, 1.0),
    Vec3::new(1.0, 1.0, 1.0),
];

impl Camera {
    /// Points at the box `min`–`max` from just far enough away that its
    /// corners fit in a viewport of the given aspect ratio, keeping the
    /// direction. Tighter than a bounding sphere for flat or long meshes.
    pub fn frame_box(&mut self, min: Vec3, max: Vec3, aspect: f32) {
        let aspect = if aspect.is_finite() && aspect > 0.0 {
            aspect
        } else {
            1.5
        };
        let center = (min + max) * 0.5;
        let half = (max - min) * 0.5;
        if !(center.is_finite() && half.is_finite()) || half.max_element() <= 0.0 {
            self.frame(
                if center.is_finite() {
                    center
                } else {
                    Vec3::ZERO
                },
                1.0,
                aspect,
            );
            return;
        }
        let back = self.backward();
        let right = Vec3::Y.cross(back).normalize_or(Vec3::X);
        let up = back.cross(right);
        // A margin of about 8% on each side.
        let tan_y = (FOV_Y * 0.5).tan() / 1.08;
        let tan_x = tan_y * aspect;
        let mut distance = 0.0_f32;
        for sign in CORNER_SIGNS {
            let c = half * sign;
            let (x, y, z) = (c.dot(right), c.dot(up), c.dot(back));
            distance = distance.max(z + x.abs() / tan_x).max(z + y.abs() / tan_y);
        }
        self.target = center.to_array();
        self.distance = if distance.is_finite() && distance > 0.0 {
            distance.clamp(1e-6, 1e9)
        } else {
            half.length().max(1e-6) * 3.0
        };
    }
}

/// World units covered by one point at `distance` in front of the eye.
pub fn world_per_point(distance: f32, viewport_height: f32) -> f32 {
    2.0 * distance * (FOV_Y * 0.5).tan() / viewport_height.max(1.0)
}

/// A ray in world space; `direction` is unit length.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ray {
    pub origin: Vec3,
    pub direction: Vec3,
}

impl Ray {
    pub fn at(&self, t: f32) -> Vec3 {
        self.origin + self.direction * t
    }
}

/// Everything needed to go between the world and the view's rectangle on
/// screen for one frame.
#[derive(Clone, Copy, Debug)]
pub struct ViewTransforms {
    pub camera: Camera,
    /// The view's rectangle in egui points.
    pub viewport: Rect,
    pub view_from_world: Mat4,
    pub world_from_view: Mat4,
    pub clip_from_view: Mat4,
    pub clip_from_world: Mat4,
    pub eye: Vec3,
}

impl ViewTransforms {
    /// The transforms for `camera` looking at a scene inside the bounding
    /// sphere (`scene_center`, `scene_radius`), drawn into `viewport`.
    pub fn new(camera: Camera, viewport: Rect, scene_center: Vec3, scene_radius: f32) -> Self {
        let aspect = (viewport.width() / viewport.height().max(1.0)).max(1e-3);
        let eye = camera.eye();
        let scene_radius = scene_radius.max(1e-6);
        // Near and far planes hug the scene so the 24-bit depth buffer keeps
        // its precision where the mesh is.
        let to_center = (eye - scene_center).length();
        let far = (to_center + scene_radius * 1.5).max(camera.distance * 2.0);
        let near = (to_center - scene_radius * 1.5)
            .max(far * 1e-4)
            .max(camera.distance * 0.005);
        let view_from_world = camera.view_from_world();
        // wgpu's clip space: depth 0..1, y up (the DirectX convention).
        let clip_from_view =
            glam::camera::rh::proj::directx::perspective(FOV_Y, aspect, near, far.max(near * 2.0));
        Self {
            camera,
            viewport,
            view_from_world,
            world_from_view: view_from_world.inverse(),
            clip_from_view,
            clip_from_world: clip_from_view * view_from_world,
            eye,
        }
    }

    /// World units covered by one point at `distance` in front of the eye.
    pub fn world_per_point(&self, distance: f32) -> f32 {
        world_per_point(distance, self.viewport.height())
    }

    /// Where a world point lands on screen (points) and its distance in
    /// front of the eye, or `None` behind the eye.
    pub fn project(&self, world: Vec3) -> Option<(Pos2, f32)> {
        let clip = self.clip_from_world * world.extend(1.0);
        if clip.w <= 1e-9 {
            return None;
        }
        let ndc = clip.xyz() / clip.w;
        let pos = Pos2::new(
            self.viewport.left() + (ndc.x + 1.0) * 0.5 * self.viewport.width(),
            self.viewport.top() + (1.0 - ndc.y) * 0.5 * self.viewport.height(),
        );
        Some((pos, clip.w))
    }

    /// The rectangle on screen (points), within the view, that holds the
    /// projection of the box between `min` and `max`; `None` where a corner
    /// lies behind the eye, whose projection has no bound, or is not finite.
    pub fn screen_rect_of_box(&self, (min, max): (Vec3, Vec3)) -> Option<Rect> {
        let (center, half) = ((min + max) * 0.5, (max - min) * 0.5);
        let mut rect = Rect::NOTHING;
        for sign in CORNER_SIGNS {
            let (pos, _) = self.project(center + half * sign)?;
            // `Rect::extend_with` would skip a NaN rather than spread it.
            if !pos.is_finite() {
                return None;
            }
            rect.extend_with(pos);
        }
        Some(rect.intersect(self.viewport))
    }

    /// The ray from the eye through a point on screen.
    pub fn ray(&self, screen: Pos2) -> Ray {
        let x = (screen.x - self.viewport.left()) / self.viewport.width().max(1.0) * 2.0 - 1.0;
        let y = 1.0 - (screen.y - self.viewport.top()) / self.viewport.height().max(1.0) * 2.0;
        let tan = (FOV_Y * 0.5).tan();
        let aspect = self.viewport.width() / self.viewport.height().max(1.0);
        let in_view = Vec3::new(x * tan * aspect, y * tan, -1.0).normalize();
        let direction = self.world_from_view.transform_vector3(in_view).normalize();
        Ray {
            origin: self.eye,
            direction,
        }
    }

    /// Whether a world box may be inside the view (false only when it is
    /// entirely outside one side of the view frustum).
    pub fn may_see_box(&self, min: Vec3, max: Vec3) -> bool {
        let m = self.clip_from_world;
        let (r0, r1, r2, r3) = (m.row(0), m.row(1), m.row(2), m.row(3));
        // Planes (a, b, c, d) with a·x + b·y + c·z + d >= 0 inside.
        let planes = [r3 + r0, r3 - r0, r3 + r1, r3 - r1, r2, r3 - r2];
        planes.iter().all(|plane| {
            let normal = plane.xyz();
            let farthest = Vec3::select(normal.cmpge(Vec3::ZERO), max, min);
            normal.dot(farthest) + plane.w >= 0.0
        })
    }

    /// Unit vectors of the screen's right and up directions in world space.
    pub fn screen_axes(&self) -> (Vec3, Vec3) {
        (
            self.world_from_view.x_axis.xyz(),
            self.world_from_view.y_axis.xyz(),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn viewport() -> Rect {
        Rect::from_min_size(Pos2::new(10.0, 20.0), Vec2::new(800.0, 600.0))
    }

    #[test]
    fn target_projects_to_the_viewport_center() {
        let camera = Camera {
            target: [1.0, 2.0, 3.0],
            ..Camera::default()
        };
        let t = ViewTransforms::new(camera, viewport(), Vec3::new(1.0, 2.0, 3.0), 1.0);
        let (pos, depth) = t.project(camera.target()).unwrap();
        assert!((pos - viewport().center()).length() < 1e-3, "{pos:?}");
        assert!((depth - camera.distance).abs() < 1e-3);
    }

    #[test]
    fn ray_through_a_projected_point_passes_through_it() {
        let camera = Camera::default();
        let t = ViewTransforms::new(camera, viewport(), Vec3::ZERO, 2.0);
        let point = Vec3::new(0.7, -0.3, 0.4);
        let (pos, _) = t.project(point).unwrap();
        let ray = t.ray(pos);
        let along = (point - ray.origin).dot(ray.direction);
        let closest = ray.at(along);
        assert!((closest - point).length() < 1e-4, "{closest} vs {point}");
    }

    #[test]
    fn a_box_in_front_projects_into_its_screen_rect() {
        let camera = Camera::default();
        let t = ViewTransforms::new(camera, viewport(), Vec3::ZERO, 2.0);
        let (min, max) = (Vec3::new(-0.5, -0.2, -0.3), Vec3::new(0.6, 0.4, 0.2));
        let rect = t
            .screen_rect_of_box((min, max))
            .expect("in front of the eye");
        assert!(viewport().contains_rect(rect), "{rect:?}");
        assert!(rect.width() > 10.0 && rect.height() > 10.0, "{rect:?}");
        // Points inside the box, the corners among them, land inside it.
        for i in 0..=4 {
            for j in 0..=4 {
                for k in 0..=4 {
                    let at = Vec3::new(i as f32, j as f32, k as f32) / 4.0;
                    let (pos, _) = t.project(min + (max - min) * at).unwrap();
                    assert!(rect.expand(1e-3).contains(pos), "{pos:?} outside {rect:?}");
                }
            }
        }
        // A box larger than the view is cut to it.
        let huge = t.screen_rect_of_box((Vec3::splat(-0.9), Vec3::splat(0.9)));
        assert!(
            huge.is_some_and(|r| viewport().contains_rect(r)),
            "{huge:?}"
        );
    }

    #[test]
    fn a_box_around_the_eye_has_no_screen_rect() {
        let camera = Camera::default();
        let t = ViewTransforms::new(camera, viewport(), Vec3::ZERO, 2.0);
        let around = (t.eye - Vec3::ONE, t.eye + Vec3::ONE);
        assert_eq!(t.screen_rect_of_box(around), None);
        let nan = (Vec3::splat(f32::NAN), Vec3::ONE);
        assert_eq!(t.screen_rect_of_box(nan), None);
    }

    #[test]
    fn yaw_and_pitch_place_the_eye() {
        let camera = Camera {
            target: [0.0; 3],
            yaw: 0.0,
            pitch: 0.0,
            distance: 4.0,
        };
        assert!((camera.eye() - Vec3::new(0.0, 0.0, 4.0)).length() < 1e-6);
        let above = Camera {
            pitch: 1.0,
            ..camera
        };
        assert!(above.eye().y > 0.0);
        let right = Camera {
            yaw: std::f32::consts::FRAC_PI_2,
            ..camera
        };
        assert!((right.eye() - Vec3::new(4.0, 0.0, 0.0)).length() < 1e-5);
    }

    #[test]
    fn framing_fits_the_sphere_in_view() {
        let mut camera = Camera::default();
        camera.frame(Vec3::new(5.0, 0.0, 0.0), 2.0, 800.0 / 600.0);
        assert_eq!(camera.target, [5.0, 0.0, 0.0]);
        let t = ViewTransforms::new(camera, viewport(), Vec3::new(5.0, 0.0, 0.0), 2.0);
        let (right, up) = t.screen_axes();
        for offset in [right, -right, up, -up] {
            let (pos, _) = t.project(camera.target() + offset * 2.0).unwrap();
            assert!(viewport().contains(pos), "{pos:?}");
        }
    }

    #[test]
    fn box_framing_fits_the_corners_tightly() {
        let mut camera = Camera::default();
        let (min, max) = (Vec3::new(0.0, 0.0, 0.0), Vec3::new(4.0, 4.0, 0.0));
        camera.frame_box(min, max, 800.0 / 600.0);
        let t = ViewTransforms::new(camera, viewport(), Vec3::new(2.0, 2.0, 0.0), 2.9);
        let corners = [min, max, Vec3::new(4.0, 0.0, 0.0), Vec3::new(0.0, 4.0, 0.0)];
        let projected: Vec<Pos2> = corners.iter().map(|&c| t.project(c).unwrap().0).collect();
        assert!(
            projected.iter().all(|p| viewport().contains(*p)),
            "{projected:?}"
        );
        // Tight: some corner comes within 10% of an edge of the view.
        let rect = Rect::from_points(&projected);
        assert!(
            rect.width() > viewport().width() * 0.8 || rect.height() > viewport().height() * 0.8,
            "{rect:?}"
        );
        // A single point still gets a sensible camera.
        camera.frame_box(Vec3::ONE, Vec3::ONE, 1.0);
        assert_eq!(camera.target, [1.0; 3]);
        assert!(camera.distance > 0.0 && camera.distance.is_finite());
    }

    #[test]
    fn pan_moves_the_target_with_the_drag() {
        let mut camera = Camera::default();
        let t0 = ViewTransforms::new(camera, viewport(), Vec3::ZERO, 1.0);
        let (before, _) = t0.project(Vec3::ZERO).unwrap();
        camera.pan(Vec2::new(30.0, -20.0), viewport().height());
        let t1 = ViewTransforms::new(camera, viewport(), Vec3::ZERO, 1.0);
        let (after, _) = t1.project(Vec3::ZERO).unwrap();
        let moved = after - before;
        assert!((moved - Vec2::new(30.0, -20.0)).length() < 0.5, "{moved:?}");
    }

    #[test]
    fn frustum_test_keeps_visible_boxes_and_drops_hidden_ones() {
        let camera = Camera::default();
        let t = ViewTransforms::new(camera, viewport(), Vec3::ZERO, 1.0);
        assert!(t.may_see_box(Vec3::splat(-0.1), Vec3::splat(0.1)));
        let behind = camera.eye() + camera.backward() * 5.0;
        assert!(!t.may_see_box(behind - 0.1, behind + 0.1));
        let (right, _) = t.screen_axes();
        let aside = right * 100.0;
        assert!(!t.may_see_box(aside - 0.1, aside + 0.1));
    }

    #[test]
    fn sanitize_repairs_broken_cameras() {
        let camera = Camera {
            target: [f32::NAN, 1.0, f32::INFINITY],
            yaw: f32::NAN,
            pitch: 10.0,
            distance: -1.0,
        }
        .sanitized();
        assert_eq!(camera.target, [0.0, 1.0, 0.0]);
        assert!(camera.yaw.is_finite());
        assert!(camera.pitch <= MAX_PITCH);
        assert!(camera.distance > 0.0);
    }

    #[test]
    fn zoom_and_orbit_stay_in_range() {
        let mut camera = Camera::default();
        camera.zoom(2.0);
        assert!((camera.distance - 2.5).abs() < 1e-6);
        camera.zoom(0.0);
        assert!((camera.distance - 2.5).abs() < 1e-6);
        camera.orbit(Vec2::new(0.0, 1e6));
        assert!(camera.pitch <= MAX_PITCH);
    }
}
