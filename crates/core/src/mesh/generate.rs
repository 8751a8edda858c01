//! Generated meshes: the benchmark torus, also used as a sample mesh.

use std::f32::consts::TAU;

use glam::Vec3;

use super::polygons::Polygons;

/// Major radius of [`torus`].
pub const TORUS_MAJOR_RADIUS: f32 = 2.0;
/// Minor radius of [`torus`].
pub const TORUS_MINOR_RADIUS: f32 = 0.6;
/// The largest grid [`torus`] generates: its 6 corners per vertex stay within
/// the builder's limit of 2³¹ − 2 half-edges.
pub const TORUS_MAX_VERTICES: u64 = (1 << 28) - 1;

/// A triangulated torus grid of `nu × nv` vertices and `2·nu·nv` triangles,
/// the benchmark mesh (so figures compare with other libraries):
///
/// - vertex (i, j) is number `j·nu + i`, at angle 2πi/nu around the major
///   circle (radius 2) and 2πj/nv around the minor circle (radius 0.6);
/// - cell (i, j) with corners a = (i, j), b = (i+1, j), c = (i+1, j+1),
///   d = (i, j+1), taken mod nu and nv, gives triangles (a, b, c), (a, c, d).
///
/// Needs `nu, nv ≥ 3` to be a manifold; smaller grids give polygons the
/// builder refuses. Grids of more than [`TORUS_MAX_VERTICES`] vertices (whose
/// half-edges could not be numbered) give an empty list.
///
/// ```
/// let torus = edgewise_core::mesh::generate::torus(100, 50);
/// assert_eq!((torus.vertex_count(), torus.face_count()), (5_000, 10_000));
/// ```
pub fn torus(nu: u32, nv: u32) -> Polygons {
    if u64::from(nu) * u64::from(nv) > TORUS_MAX_VERTICES {
        return Polygons::new();
    }
    let (count_u, count_v) = (nu as usize, nv as usize);
    let mut polygons = Polygons::with_capacity(
        count_u * count_v,
        2 * count_u * count_v,
        6 * count_u * count_v,
    );
    for j in 0..nv {
        let (sin_v, cos_v) = (TAU * j as f32 / nv as f32).sin_cos();
        for i in 0..nu {
            let (sin_u, cos_u) = (TAU * i as f32 / nu as f32).sin_cos();
            let ring = TORUS_MAJOR_RADIUS + TORUS_MINOR_RADIUS * cos_v;
            polygons.push_vertex(Vec3::new(
                ring * cos_u,
                ring * sin_u,
                TORUS_MINOR_RADIUS * sin_v,
            ));
        }
    }
    let index = |i: u32, j: u32| (j % nv.max(1)) * nu + (i % nu.max(1));
    for j in 0..nv {
        for i in 0..nu {
            let (a, b, c, d) = (
                index(i, j),
                index(i + 1, j),
                index(i + 1, j + 1),
                index(i, j + 1),
            );
            polygons.push_face(&[a, b, c]);
            polygons.push_face(&[a, c, d]);
        }
    }
    polygons
}
