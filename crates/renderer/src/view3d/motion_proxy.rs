//! The motion proxy: a large mesh's coarse lines and faces, simplified by
//! vertex clustering, drawn in their place while the camera moves.
//!
//! A software renderer (`SwiftShader`) pays for every primitive, however
//! small on screen: torus-200k's 300k lines and 200k triangles take about
//! 200 ms a frame to draw, so a turn of the camera followed the pointer at
//! four frames a second. The camera is turned to see the shape, which a
//! few thousand primitives show as well; once it rests, the mesh's own
//! lines and faces are drawn again (`View3d`'s `MOTION_SETTLE`), and
//! highlighted elements are always drawn in full over the proxy.
//!
//! Vertex clustering (Rossignac and Borrel): a grid of cubes is laid over
//! the mesh, each cube's vertices merge into one at their mean, and a line
//! or triangle survives when its corners fall in different cubes (once, if
//! several fall in the same cubes). It needs no connectivity, so it takes
//! whatever the coarse view draws, broken meshes included.

use glam::Vec3;

use super::coarse::CoarseGeometry;

/// Meshes of more than this many coarse lines and triangles get a proxy:
/// below it, drawing the mesh itself keeps up with the pointer.
pub const PROXY_ABOVE: usize = 100_000;

/// About how many lines and triangles a proxy has. Under `SwiftShader` at
/// 1280×800 the app's frame around the view costs 60 to 70 ms, and 20k
/// primitives about 12 more, keeping a moving camera above ten frames a
/// second.
pub const PROXY_PRIMITIVES: usize = 20_000;

/// Grid cells per axis are numbered in 21 bits, so that a cell's three
/// numbers pack into one sort key.
const CELL_BITS: u32 = 21;
const CELL_MAX: u32 = (1 << CELL_BITS) - 1;

/// Grids tried before the last is kept, however many primitives it gives.
const ATTEMPTS: usize = 8;

/// A vertex that is in no cluster (its position is not finite).
const NONE: u32 = u32::MAX;

/// The proxy of `coarse`, whose finite positions lie in `bounds` (the
/// scene's), or `None` when it has at most [`PROXY_ABOVE`] lines and
/// triangles.
pub fn proxy(coarse: &CoarseGeometry, bounds: (Vec3, Vec3)) -> Option<CoarseGeometry> {
    (primitive_count(coarse) > PROXY_ABOVE).then(|| simplify(coarse, bounds, PROXY_PRIMITIVES))
}

fn primitive_count(geometry: &CoarseGeometry) -> usize {
    geometry.lines.len() / 2 + geometry.triangles.len() / 3
}

/// `coarse`, whose finite positions lie in `bounds`, clustered on the
/// finest grid that leaves at most about `target` lines and triangles.
pub fn simplify(coarse: &CoarseGeometry, bounds: (Vec3, Vec3), target: usize) -> CoarseGeometry {
    let target = target.max(1);
    let min = bounds.0.to_array().map(f64::from);
    let extent = f64::from((bounds.1 - bounds.0).max_element());
    // No grid finer than the cell numbers can span.
    let finest = extent / f64::from(CELL_MAX) * 1.01;
    let mut cell = first_cell(coarse, target).max(finest);
    let mut proxy = CoarseGeometry::default();
    for _ in 0..ATTEMPTS {
        if !(cell.is_finite() && cell > 0.0) {
            // A mesh of one point, or of points all in one place.
            cell = 1.0;
        }
        proxy = cluster(coarse, min, cell);
        let count = primitive_count(&proxy);
        if count <= target {
            break;
        }
        // Primitives on a surface go as the inverse square of the cell.
        cell *= (count as f64 / target as f64).sqrt().max(1.1);
    }
    proxy
}

/// A first guess at the cell: a surface of area A crosses about 1.3 A / h²
/// cubes of side h (more than A / h², as it crosses them at a slant), and a
/// closed triangle mesh has about five lines and triangles a vertex; a mesh
/// of lines only, about one a cube along its length.
fn first_cell(coarse: &CoarseGeometry, target: usize) -> f64 {
    let corner = |i: u32| {
        coarse
            .positions
            .get(i as usize)
            .filter(|p| p.iter().all(|c| c.is_finite()))
            .map(|p| glam::DVec3::from(p.map(f64::from)))
    };
    let area: f64 = coarse
        .triangles
        .chunks_exact(3)
        .filter_map(|t| Some((corner(t[0])?, corner(t[1])?, corner(t[2])?)))
        .map(|(a, b, c)| (b - a).cross(c - a).length() / 2.0)
        .sum();
    if area > 0.0 && area.is_finite() {
        return (area * 1.3 * 5.0 / target as f64).sqrt();
    }
    let length: f64 = coarse
        .lines
        .chunks_exact(2)
        .filter_map(|l| Some((corner(l[0])?, corner(l[1])?)))
        .map(|(a, b)| (b - a).length())
        .sum();
    length / target as f64
}

/// `coarse` with its vertices merged by cubes of side `cell` from `min`.
fn cluster(coarse: &CoarseGeometry, min: [f64; 3], cell: f64) -> CoarseGeometry {
    let cell_of = |p: &[f32; 3]| -> Option<u64> {
        if !p.iter().all(|c| c.is_finite()) {
            return None;
        }
        let mut key = 0_u64;
        for a in 0..3 {
            // Saturating: a far point joins the grid's last cell.
            let n = ((f64::from(p[a]) - min[a]) / cell)
                .floor()
                .clamp(0.0, f64::from(CELL_MAX));
            key = (key << CELL_BITS) | n as u64;
        }
        Some(key)
    };
    let mut keyed: Vec<(u64, u32)> = (0_u32..)
        .zip(&coarse.positions)
        .filter_map(|(i, p)| Some((cell_of(p)?, i)))
        .collect();
    keyed.sort_unstable();

    let mut cluster_of = vec![NONE; coarse.positions.len()];
    let mut sums: Vec<([f64; 3], u32)> = Vec::new();
    let mut last_key = None;
    for &(key, vertex) in &keyed {
        if last_key != Some(key) {
            last_key = Some(key);
            sums.push(([0.0; 3], 0));
        }
        let cluster = sums.len() - 1;
        let (sum, count) = &mut sums[cluster];
        let p = coarse.positions[vertex as usize];
        for a in 0..3 {
            sum[a] += f64::from(p[a]);
        }
        *count += 1;
        cluster_of[vertex as usize] = cluster as u32;
    }
    let positions = sums
        .iter()
        .map(|(sum, count)| sum.map(|s| (s / f64::from(*count)) as f32))
        .collect();
    let map = |v: u32| cluster_of.get(v as usize).copied().filter(|&c| c != NONE);

    let mut lines: Vec<u64> = coarse
        .lines
        .chunks_exact(2)
        .filter_map(|l| {
            let (a, b) = (map(l[0])?, map(l[1])?);
            (a != b).then(|| (u64::from(a.min(b)) << 32) | u64::from(a.max(b)))
        })
        .collect();
    lines.sort_unstable();
    lines.dedup();

    // Triangles keep their winding; the key, their corners in order, finds
    // those that fall in the same three cubes.
    let mut triangles: Vec<(u128, [u32; 3])> = coarse
        .triangles
        .chunks_exact(3)
        .filter_map(|t| {
            let corners = [map(t[0])?, map(t[1])?, map(t[2])?];
            let [a, b, c] = corners;
            if a == b || b == c || a == c {
                return None;
            }
            let mut sorted = corners;
            sorted.sort_unstable();
            let key = sorted
                .iter()
                .fold(0_u128, |key, &v| (key << 32) | u128::from(v));
            Some((key, corners))
        })
        .collect();
    triangles.sort_unstable_by_key(|(key, _)| *key);
    triangles.dedup_by_key(|(key, _)| *key);

    CoarseGeometry {
        positions,
        lines: lines
            .iter()
            .flat_map(|&l| [(l >> 32) as u32, l as u32])
            .collect(),
        triangles: triangles.iter().flat_map(|(_, t)| *t).collect(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use edgewise_pictures::geometry::MeshGeometry;
    use edgewise_pictures::scene::Scene;

    /// The bounds the scene of `geometry`'s positions finds.
    fn scene_bounds(geometry: &CoarseGeometry) -> (Vec3, Vec3) {
        let positions = geometry.positions.iter().map(|&p| Vec3::from(p)).collect();
        Scene::new(MeshGeometry {
            positions,
            ..MeshGeometry::default()
        })
        .bounds
    }

    /// A grid of `n`×`n` squares in the plane z = 0, each two triangles,
    /// with every square's four sides as lines (shared sides twice, as a
    /// half-edge mesh's pairs are not: duplicates must merge anyway).
    fn grid(n: u32) -> CoarseGeometry {
        let at = |x: u32, y: u32| y * (n + 1) + x;
        let positions = (0..=n)
            .flat_map(|y| (0..=n).map(move |x| [x as f32, y as f32, 0.0]))
            .collect();
        let (mut lines, mut triangles) = (Vec::new(), Vec::new());
        for y in 0..n {
            for x in 0..n {
                let (a, b, c, d) = (at(x, y), at(x + 1, y), at(x + 1, y + 1), at(x, y + 1));
                lines.extend([a, b, b, c, c, d, d, a]);
                triangles.extend([a, b, c, a, c, d]);
            }
        }
        CoarseGeometry {
            positions,
            lines,
            triangles,
        }
    }

    #[test]
    fn a_large_mesh_is_cut_to_about_the_target_and_a_small_one_has_no_proxy() {
        let large = grid(300);
        assert!(primitive_count(&large) > PROXY_ABOVE);
        let proxy = proxy(&large, scene_bounds(&large)).expect("a proxy for 450k primitives");
        let count = primitive_count(&proxy);
        assert!(
            (PROXY_PRIMITIVES / 4..=PROXY_PRIMITIVES).contains(&count),
            "{count} primitives"
        );
        let small = grid(100);
        assert!(super::proxy(&small, scene_bounds(&small)).is_none());
    }

    #[test]
    fn the_proxy_covers_the_mesh_with_valid_triangles_that_keep_their_winding() {
        let mesh = grid(60);
        let proxy = simplify(&mesh, scene_bounds(&mesh), 2_000);
        assert!(primitive_count(&proxy) <= 2_000);
        let count = proxy.positions.len() as u32;
        assert!(
            proxy
                .lines
                .iter()
                .chain(&proxy.triangles)
                .all(|&v| v < count)
        );
        let (min, max) = scene_bounds(&proxy);
        // Cluster means lie inside the mesh and reach near its corners.
        for a in 0..2 {
            assert!(min[a] >= 0.0 && min[a] < 3.0, "{min:?}");
            assert!(max[a] <= 60.0 && max[a] > 57.0, "{max:?}");
        }
        // Every triangle still faces +z, as the grid's do.
        for t in proxy.triangles.chunks_exact(3) {
            let p = |i: u32| Vec3::from(proxy.positions[i as usize]);
            let normal = (p(t[1]) - p(t[0])).cross(p(t[2]) - p(t[0]));
            assert!(normal.z > 0.0, "{t:?} turned over");
        }
        // No line or triangle is degenerate or repeated.
        let mut lines: Vec<_> = proxy.lines.chunks_exact(2).map(|l| (l[0], l[1])).collect();
        assert!(lines.iter().all(|(a, b)| a < b));
        lines.dedup();
        assert_eq!(lines.len(), proxy.lines.len() / 2);
    }

    #[test]
    fn points_that_are_not_finite_and_indices_out_of_range_are_left_out() {
        let mut mesh = grid(4);
        mesh.positions[0] = [f32::NAN, 0.0, 0.0];
        mesh.lines.extend([999, 1]);
        mesh.triangles.extend([1, 2, 999]);
        let proxy = simplify(&mesh, scene_bounds(&mesh), 1_000_000);
        // The finest grid keeps every other vertex apart: one fewer in all.
        assert_eq!(proxy.positions.len(), mesh.positions.len() - 1);
        assert!(
            proxy
                .positions
                .iter()
                .all(|p| p.iter().all(|c| c.is_finite()))
        );
        // The square at vertex 0 loses its two lines there and a triangle.
        assert_eq!(proxy.triangles.len() / 3, 4 * 4 * 2 - 2);
    }

    #[test]
    fn a_mesh_of_one_point_or_none_gives_an_empty_proxy() {
        let one = CoarseGeometry {
            positions: vec![[1.0, 2.0, 3.0]; 3],
            lines: vec![0, 1],
            triangles: vec![0, 1, 2],
        };
        let proxy = simplify(&one, scene_bounds(&one), 10);
        assert_eq!(proxy.positions.len(), 1);
        assert!(proxy.lines.is_empty() && proxy.triangles.is_empty());
        assert_eq!(
            simplify(&CoarseGeometry::default(), (Vec3::ZERO, Vec3::ZERO), 10),
            CoarseGeometry::default()
        );
    }
}
