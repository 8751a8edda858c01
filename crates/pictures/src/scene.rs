//! What the view derives from a mesh once, when it is set: bounds, face
//! centroids and normals, the triangulation, where each arrow is drawn and
//! the element sizes. Everything else (GPU buffers, picking, labels) reads
//! this.

use glam::Vec3;

use crate::camera::Camera;
use crate::geometry::MeshGeometry;
use edgewise_core::schema::{ElementKind, ElementRef};

/// How far a half-edge arrow is pulled from its edge towards its face's
/// centroid, as a fraction of each end's distance to that centroid.
pub const HALF_EDGE_INSET: f32 = 0.14;

/// The mesh with everything derived from it.
pub struct Scene {
    pub geometry: MeshGeometry,
    /// Corners of the box holding every vertex.
    pub bounds: (Vec3, Vec3),
    /// Center and radius of a sphere holding every vertex.
    pub center: Vec3,
    pub radius: f32,
    /// The mean edge length: the unit that vertex and arrow sizes scale with.
    pub unit: f32,
    pub face_centroids: Vec<Vec3>,
    /// Unit normals by Newell's method (zero for a degenerate face).
    pub face_normals: Vec<Vec3>,
    /// Where each arrow starts and ends before the ends are pulled back from
    /// the vertex spheres: on the edge for a winged edge, inset into its face
    /// for a half-edge.
    pub arrow_starts: Vec<Vec3>,
    pub arrow_ends: Vec<Vec3>,
    /// Fan triangulation: vertex ids of each triangle and its face.
    pub triangles: Vec<[u32; 3]>,
    pub triangle_faces: Vec<u32>,
    /// Face `f` owns triangles `face_triangle_start[f]..face_triangle_start[f + 1]`.
    pub face_triangle_start: Vec<u32>,
    /// Radius of each face's orientation mark (0 where it has no room).
    pub orientation_radius: Vec<f32>,
}

/// Sizes in world units for one frame (they follow the mesh scale).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sizes {
    pub vertex_radius: f32,
    pub shaft_radius: f32,
    pub head_radius: f32,
    pub head_length: f32,
}

impl Sizes {
    /// Extra thickness of highlighted elements.
    pub const EMPHASIS_VERTEX: f32 = 1.35;
    pub const EMPHASIS_EDGE: f32 = 1.5;
}

impl Scene {
    /// Points `camera` at the whole mesh in a view of `aspect`, with room
    /// for the vertex spheres and the labels above them.
    pub fn frame(&self, camera: &mut Camera, aspect: f32) {
        let (min, max) = self.bounds;
        let room = Vec3::splat(self.unit * 0.12);
        camera.frame_box(min - room, max + room, aspect);
    }

    pub fn new(geometry: MeshGeometry) -> Self {
        let position = |v: u32| -> Vec3 {
            geometry
                .positions
                .get(v as usize)
                .copied()
                .filter(|p| p.is_finite())
                .unwrap_or(Vec3::ZERO)
        };

        // Bounds.
        let mut bounds = (Vec3::ZERO, Vec3::ZERO);
        let (center, radius) = if geometry.positions.is_empty() {
            (Vec3::ZERO, 1.0)
        } else {
            let (mut min, mut max) = (Vec3::splat(f32::INFINITY), Vec3::splat(f32::NEG_INFINITY));
            for p in geometry.positions.iter().filter(|p| p.is_finite()) {
                min = min.min(*p);
                max = max.max(*p);
            }
            if min.is_finite() && max.is_finite() {
                bounds = (min, max);
                let center = (min + max) * 0.5;
                let radius = geometry
                    .positions
                    .iter()
                    .filter(|p| p.is_finite())
                    .map(|p| p.distance(center))
                    .fold(0.0_f32, f32::max);
                (center, if radius > 1e-12 { radius } else { 1.0 })
            } else {
                (Vec3::ZERO, 1.0)
            }
        };

        // Faces: centroid, normal, fan triangulation, room for a mark.
        let face_count = geometry.faces.len();
        let mut face_centroids = Vec::with_capacity(face_count);
        let mut face_normals = Vec::with_capacity(face_count);
        let mut orientation_radius = Vec::with_capacity(face_count);
        let mut triangles = Vec::new();
        let mut triangle_faces = Vec::new();
        let mut face_triangle_start = Vec::with_capacity(face_count + 1);
        face_triangle_start.push(0_u32);
        let mut corners: Vec<Vec3> = Vec::new();
        for (f, face) in geometry.faces.iter().enumerate() {
            corners.clear();
            corners.extend(face.iter().map(|&v| position(v)));
            let centroid = if corners.is_empty() {
                Vec3::ZERO
            } else {
                corners.iter().copied().sum::<Vec3>() / corners.len() as f32
            };
            let mut newell = Vec3::ZERO;
            for (i, a) in corners.iter().enumerate() {
                let b = corners[(i + 1) % corners.len()];
                newell += (*a - centroid).cross(b - centroid);
            }
            let normal = newell.normalize_or_zero();
            face_centroids.push(centroid);
            face_normals.push(normal);
            let room = (0..corners.len())
                .map(|i| {
                    point_segment_distance(centroid, corners[i], corners[(i + 1) % corners.len()])
                })
                .fold(f32::INFINITY, f32::min);
            orientation_radius.push(if normal == Vec3::ZERO || !room.is_finite() {
                0.0
            } else {
                room * 0.42
            });
            if face.len() >= 3 {
                let face_id = u32::try_from(f).unwrap_or(u32::MAX);
                triangulate(&corners, normal, |[a, b, c]| {
                    triangles.push([face[a], face[b], face[c]]);
                    triangle_faces.push(face_id);
                });
            }
            face_triangle_start.push(u32::try_from(triangles.len()).unwrap_or(u32::MAX));
        }

        // Arrows.
        let mut arrow_starts = Vec::with_capacity(geometry.edges.len());
        let mut arrow_ends = Vec::with_capacity(geometry.edges.len());
        let mut length_sum = 0.0_f64;
        for edge in &geometry.edges {
            let (a, b) = (position(edge.start), position(edge.end));
            length_sum += f64::from(a.distance(b));
            let (start, end) = if geometry.half_edges {
                let own = edge.face.and_then(|f| face_centroids.get(f as usize));
                let pair_face = edge
                    .pair
                    .and_then(|p| geometry.edges.get(p as usize))
                    .and_then(|p| p.face)
                    .and_then(|f| face_centroids.get(f as usize));
                match (own, pair_face) {
                    (Some(c), _) => (
                        a + (*c - a) * HALF_EDGE_INSET,
                        b + (*c - b) * HALF_EDGE_INSET,
                    ),
                    // A boundary half-edge sits outside, mirrored from its pair.
                    (None, Some(c)) => (
                        a - (*c - a) * HALF_EDGE_INSET,
                        b - (*c - b) * HALF_EDGE_INSET,
                    ),
                    (None, None) => (a, b),
                }
            } else {
                (a, b)
            };
            arrow_starts.push(start);
            arrow_ends.push(end);
        }
        let mut unit = if geometry.edges.is_empty() {
            0.0
        } else {
            (length_sum / geometry.edges.len() as f64) as f32
        };
        if !(unit.is_finite() && unit > radius * 1e-5) {
            unit = radius * 0.2;
        }

        Self {
            geometry,
            bounds,
            center,
            radius,
            unit,
            face_centroids,
            face_normals,
            arrow_starts,
            arrow_ends,
            triangles,
            triangle_faces,
            face_triangle_start,
            orientation_radius,
        }
    }

    /// Vertex position, or the origin for an id out of range.
    pub fn position(&self, v: u32) -> Vec3 {
        self.geometry
            .positions
            .get(v as usize)
            .copied()
            .filter(|p| p.is_finite())
            .unwrap_or(Vec3::ZERO)
    }

    /// Element sizes at a mesh scale.
    pub fn sizes(&self, mesh_scale: f32) -> Sizes {
        let scale = if mesh_scale.is_finite() {
            mesh_scale.clamp(0.05, 20.0)
        } else {
            1.0
        } * self.unit;
        Sizes {
            vertex_radius: 0.085 * scale,
            shaft_radius: 0.016 * scale,
            head_radius: 0.042 * scale,
            head_length: 0.15 * scale,
        }
    }

    /// Fraction of the vertex radius by which arrow ends are pulled back: a
    /// winged edge runs between the spheres' surfaces; a half-edge is already
    /// inset, so only a little.
    pub fn arrow_gap(&self) -> f32 {
        if self.geometry.half_edges { 0.3 } else { 1.0 }
    }

    /// The drawn arrow of edge `e` after its ends are pulled back, as the
    /// shader does it.
    pub fn drawn_arrow(&self, e: usize, sizes: &Sizes) -> Option<(Vec3, Vec3)> {
        let (a, b) = (*self.arrow_starts.get(e)?, *self.arrow_ends.get(e)?);
        let length = a.distance(b);
        if length <= 0.0 {
            return Some((a, b));
        }
        let dir = (b - a) / length;
        let gap = (sizes.vertex_radius * self.arrow_gap()).min(0.3 * length);
        Some((a + dir * gap, b - dir * gap))
    }

    /// Where an element's label and pointer attach, in world space.
    pub fn anchor(&self, pick: ElementRef) -> Option<Vec3> {
        match pick.kind {
            ElementKind::Vertex => {
                self.geometry.positions.get(pick.id as usize)?;
                Some(self.position(pick.id))
            }
            ElementKind::Edge => {
                let (a, b) = (
                    *self.arrow_starts.get(pick.id as usize)?,
                    *self.arrow_ends.get(pick.id as usize)?,
                );
                // Half-edge labels sit towards the end vertex so both labels of
                // a pair show.
                let t = if self.geometry.half_edges { 0.64 } else { 0.5 };
                Some(a.lerp(b, t))
            }
            ElementKind::Face => self.face_centroids.get(pick.id as usize).copied(),
        }
    }

    pub fn vertex_count(&self) -> usize {
        self.geometry.positions.len()
    }

    pub fn edge_count(&self) -> usize {
        self.geometry.edges.len()
    }

    /// Half-edge `e` has no face: it runs along the boundary.
    pub fn is_boundary_half_edge(&self, e: usize) -> bool {
        self.geometry.half_edges && self.geometry.edges.get(e).is_some_and(|g| g.face.is_none())
    }

    pub fn face_count(&self) -> usize {
        self.geometry.faces.len()
    }
}

/// Splits a polygon into triangles (corner indices): a fan when it is convex
/// (the usual case, and any face too large to clip), otherwise by ear
/// clipping in the plane of `normal`, so concave faces fill correctly.
pub fn triangulate(corners: &[Vec3], normal: Vec3, mut emit: impl FnMut([usize; 3])) {
    let n = corners.len();
    if n < 3 {
        return;
    }
    let turn = |a: Vec3, b: Vec3, c: Vec3| (b - a).cross(c - b).dot(normal);
    let convex = normal == Vec3::ZERO
        || n == 3
        || n > 256
        || (0..n).all(|i| turn(corners[i], corners[(i + 1) % n], corners[(i + 2) % n]) >= 0.0);
    if convex {
        for i in 1..n - 1 {
            emit([0, i, i + 1]);
        }
        return;
    }
    let mut remaining: Vec<usize> = (0..n).collect();
    let mut misses = 0;
    let mut i = 0;
    while remaining.len() > 3 {
        let m = remaining.len();
        let (ia, ib, ic) = (
            remaining[(i + m - 1) % m],
            remaining[i % m],
            remaining[(i + 1) % m],
        );
        let (a, b, c) = (corners[ia], corners[ib], corners[ic]);
        let is_ear = turn(a, b, c) > 0.0
            && remaining.iter().all(|&j| {
                j == ia || j == ib || j == ic || !inside_triangle(corners[j], a, b, c, normal)
            });
        if is_ear {
            emit([ia, ib, ic]);
            remaining.remove(i % m);
            misses = 0;
        } else {
            i += 1;
            misses += 1;
            if misses > m {
                // Degenerate or self-intersecting: fan the rest.
                for k in 1..remaining.len() - 1 {
                    emit([remaining[0], remaining[k], remaining[k + 1]]);
                }
                return;
            }
        }
    }
    emit([remaining[0], remaining[1], remaining[2]]);
}

fn inside_triangle(p: Vec3, a: Vec3, b: Vec3, c: Vec3, normal: Vec3) -> bool {
    let side = |u: Vec3, v: Vec3| (v - u).cross(p - u).dot(normal) >= 0.0;
    side(a, b) && side(b, c) && side(c, a)
}

/// Distance from `p` to the segment `a`–`b`.
pub fn point_segment_distance(p: Vec3, a: Vec3, b: Vec3) -> f32 {
    let ab = b - a;
    let length_squared = ab.length_squared();
    let t = if length_squared > 0.0 {
        ((p - a).dot(ab) / length_squared).clamp(0.0, 1.0)
    } else {
        0.0
    };
    p.distance(a + ab * t)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn triangles_of(corners: &[Vec3]) -> Vec<[usize; 3]> {
        let mut out = Vec::new();
        let mut newell = Vec3::ZERO;
        for i in 0..corners.len() {
            newell += corners[i].cross(corners[(i + 1) % corners.len()]);
        }
        triangulate(corners, newell.normalize_or_zero(), |t| out.push(t));
        out
    }

    fn area(corners: &[Vec3], triangles: &[[usize; 3]]) -> f32 {
        triangles
            .iter()
            .map(|&[a, b, c]| {
                (corners[b] - corners[a])
                    .cross(corners[c] - corners[a])
                    .length()
                    * 0.5
            })
            .sum()
    }

    #[test]
    fn convex_faces_are_fanned() {
        let square = [Vec3::ZERO, Vec3::X, Vec3::new(1.0, 1.0, 0.0), Vec3::Y];
        assert_eq!(triangles_of(&square), vec![[0, 1, 2], [0, 2, 3]]);
    }

    #[test]
    fn concave_faces_are_clipped_without_spilling() {
        // An L shape of area 3.
        let l = [
            Vec3::new(0.0, 0.0, 0.0),
            Vec3::new(2.0, 0.0, 0.0),
            Vec3::new(2.0, 1.0, 0.0),
            Vec3::new(1.0, 1.0, 0.0),
            Vec3::new(1.0, 2.0, 0.0),
            Vec3::new(0.0, 2.0, 0.0),
        ];
        let triangles = triangles_of(&l);
        assert_eq!(triangles.len(), 4);
        assert!((area(&l, &triangles) - 3.0).abs() < 1e-5);
    }

    #[test]
    fn degenerate_faces_do_not_panic() {
        let _ = triangles_of(&[Vec3::ONE; 5]);
        let _ = triangles_of(&[Vec3::ZERO, Vec3::X]);
        let bow_tie = [Vec3::ZERO, Vec3::new(1.0, 1.0, 0.0), Vec3::X, Vec3::Y];
        assert_eq!(triangles_of(&bow_tie).len(), 2);
    }
}
