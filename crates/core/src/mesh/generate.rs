//! Generated meshes: the benchmark torus, also used as a sample mesh, and the
//! small meshes that tests, examples and the sample library share, so each
//! one's numbering (which tests and golden files pin) is written down once.

use std::collections::HashMap;
use std::f32::consts::TAU;

use glam::{DVec3, Vec3};

use super::ids::{EdgeId, FaceId, VertexId};
use super::polygons::Polygons;
use super::winged_edge::{Face, Vertex, WingedEdge, WingedEdgeMesh};

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

/// The golden ratio, for the icosahedron's corners.
const PHI: f64 = 1.618_033_988_749_895;

/// The regular icosahedron's 20 faces, counter-clockwise from outside, each
/// from its lowest vertex, in the order the sample files list them.
const ICOSAHEDRON_FACES: [[u32; 3]; 20] = [
    [0, 1, 2],
    [0, 7, 1],
    [0, 2, 6],
    [0, 6, 5],
    [0, 5, 7],
    [1, 8, 2],
    [1, 7, 3],
    [1, 3, 8],
    [2, 4, 6],
    [2, 8, 4],
    [3, 7, 11],
    [3, 9, 8],
    [3, 11, 9],
    [4, 10, 6],
    [4, 8, 9],
    [4, 9, 10],
    [5, 6, 10],
    [5, 11, 7],
    [5, 10, 11],
    [9, 11, 10],
];

/// A regular icosahedron on the unit sphere with each triangle split in four
/// `levels` times, the new vertices pushed out onto the sphere: `20·4^levels`
/// triangles. Level 0 is meshes/icosahedron.ply and level 5 is
/// meshes/icosphere-20k.ply, exactly: the app generates that sample rather
/// than ship it. Computed in f64 and rounded once, as the files were.
/// Levels above 9 (over 5M triangles) give an empty list.
///
/// ```
/// let sphere = edgewise_core::mesh::generate::icosphere(1);
/// assert_eq!((sphere.vertex_count(), sphere.face_count()), (42, 80));
/// ```
pub fn icosphere(levels: u32) -> Polygons {
    if levels > 9 {
        return Polygons::new();
    }
    let mut points = Vec::with_capacity(10 * (1 << (2 * levels)) + 2);
    for a in [-1.0, 1.0] {
        for b in [-PHI, PHI] {
            points.push(DVec3::new(0.0, a, b).normalize());
            points.push(DVec3::new(a, b, 0.0).normalize());
            points.push(DVec3::new(b, 0.0, a).normalize());
        }
    }
    let mut faces = ICOSAHEDRON_FACES.to_vec();
    for _ in 0..levels {
        // Each edge is split once, by whichever of its faces comes first.
        let mut middle: HashMap<(u32, u32), u32> = HashMap::with_capacity(faces.len() * 3 / 2);
        let mut split = |a: u32, b: u32, points: &mut Vec<DVec3>| {
            *middle.entry((a.min(b), a.max(b))).or_insert_with(|| {
                points.push(((points[a as usize] + points[b as usize]) / 2.0).normalize());
                points.len() as u32 - 1
            })
        };
        let mut finer = Vec::with_capacity(faces.len() * 4);
        for &[a, b, c] in &faces {
            let ab = split(a, b, &mut points);
            let bc = split(b, c, &mut points);
            let ca = split(c, a, &mut points);
            finer.extend([[a, ab, ca], [ab, b, bc], [ca, bc, c], [ab, bc, ca]]);
        }
        faces = finer;
    }
    let positions = points.iter().map(|p| p.as_vec3()).collect();
    Polygons::from_triangles(positions, &faces)
}

/// The journal paper's tetrahedron (Fig. 2): vertices A, B, C, D are 0–3 and
/// faces 1 = ABD, 2 = BCD, 3 = ACD, 4 = ABC are 0–3, counter-clockwise seen
/// from outside. Each face starts where the winged-edge build then numbers
/// the edges a–f as Table 2 does (it points only a and f the other way; see
/// [`table_2`]).
///
/// ```
/// let tetrahedron = edgewise_core::mesh::generate::tetrahedron();
/// assert_eq!(tetrahedron.face(0), Some(&[3, 0, 1][..])); // face 1 = D, A, B
/// ```
pub fn tetrahedron() -> Polygons {
    let positions = vec![
        Vec3::new(0.0, 0.0, 0.0),
        Vec3::new(1.0, 0.0, 0.0),
        Vec3::new(0.5, 0.0, -0.9),
        Vec3::new(0.5, 0.8, -0.3),
    ];
    Polygons::from_triangles(positions, &[[3, 0, 1], [1, 2, 3], [0, 3, 2], [0, 2, 1]])
}

/// Table 2 of the journal paper exactly as printed, on the positions of
/// [`tetrahedron`]: edges a–f are 0–5, vertices A–D 0–3, faces 1–4 0–3. The
/// builder cannot produce it (it orients each edge the way it first meets
/// it), so the sample file and the paper's traces are entered as tables.
///
/// ```
/// use edgewise_core::mesh::{EdgeId, generate};
/// let table = generate::table_2();
/// assert_eq!(table.validate(), vec![]);
/// // Vertex D's incident edge is e, as the paper picked.
/// assert_eq!(table.vertices()[3].incident_edge, Some(EdgeId::new(4)));
/// ```
pub fn table_2() -> WingedEdgeMesh {
    let v = |c: char| VertexId::new(c as u32 - 'A' as u32);
    let e = |c: char| EdgeId::new(c as u32 - 'a' as u32);
    let f = |n: u32| Some(FaceId::new(n - 1));
    // Start, end, left face, right face, left pred, left succ, right pred, right succ.
    let rows = [
        ('A', 'D', 3, 1, 'e', 'f', 'b', 'c'),
        ('A', 'B', 1, 4, 'c', 'a', 'f', 'd'),
        ('B', 'D', 1, 2, 'a', 'b', 'd', 'e'),
        ('B', 'C', 2, 4, 'e', 'c', 'b', 'f'),
        ('C', 'D', 2, 3, 'c', 'd', 'f', 'a'),
        ('A', 'C', 4, 3, 'd', 'b', 'a', 'e'),
    ];
    let edges = rows
        .iter()
        .map(|&(start, end, left, right, lp, ls, rp, rs)| WingedEdge {
            start_vertex: v(start),
            end_vertex: v(end),
            left_face: f(left),
            right_face: f(right),
            left_predecessor: e(lp),
            left_successor: e(ls),
            right_predecessor: e(rp),
            right_successor: e(rs),
        })
        .collect();
    let vertices = tetrahedron()
        .positions()
        .iter()
        .zip(['a', 'b', 'd', 'e'])
        .map(|(&position, edge)| Vertex {
            position,
            incident_edge: Some(e(edge)),
        })
        .collect();
    let faces = ['a', 'c', 'a', 'b']
        .iter()
        .map(|&edge| Face {
            incident_edge: e(edge),
        })
        .collect();
    WingedEdgeMesh::from_raw_parts(vertices, faces, edges)
}

/// The corner of the unit cube: vertex 0 at the origin and 1, 2, 3 on the x,
/// y and z axes; faces 0 2 1 (the xy side), 0 1 3, 1 2 3, 0 3 2. The
/// refusal tests corrupt its tables row by row, so its numbering is fixed.
///
/// ```
/// let corner = edgewise_core::mesh::generate::unit_tetrahedron();
/// assert_eq!(corner.face(3), Some(&[0, 3, 2][..]));
/// ```
pub fn unit_tetrahedron() -> Polygons {
    let positions = vec![Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::Z];
    Polygons::from_triangles(positions, &[[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]])
}

/// A regular tetrahedron on alternate corners of the cube (±1, ±1, ±1),
/// numbered as the language's golden traces were recorded: vertices
/// (1, 1, 1), (1, −1, −1), (−1, 1, −1), (−1, −1, 1).
///
/// ```
/// let tetrahedron = edgewise_core::mesh::generate::regular_tetrahedron();
/// assert_eq!(tetrahedron.face(0), Some(&[2, 0, 1][..]));
/// ```
pub fn regular_tetrahedron() -> Polygons {
    let positions = vec![
        Vec3::new(1.0, 1.0, 1.0),
        Vec3::new(1.0, -1.0, -1.0),
        Vec3::new(-1.0, 1.0, -1.0),
        Vec3::new(-1.0, -1.0, 1.0),
    ];
    Polygons::from_triangles(positions, &[[2, 0, 1], [1, 0, 3], [3, 0, 2], [2, 1, 3]])
}

/// The cube (±1, ±1, ±1) of six squares, as in the sample library: vertex
/// `i` has x from bit 0, y from bit 1 and z from bit 2 (0 is −1, 1 is +1);
/// faces −z, −y, −x, +x, +y, +z, each from its lowest vertex.
///
/// ```
/// let cube = edgewise_core::mesh::generate::cube();
/// assert_eq!(cube.face(0), Some(&[0, 2, 3, 1][..])); // z = −1
/// ```
pub fn cube() -> Polygons {
    cube_with(
        |i| [i & 1, (i >> 1) & 1, (i >> 2) & 1],
        [
            [0, 2, 3, 1],
            [0, 1, 5, 4],
            [0, 4, 6, 2],
            [1, 3, 7, 5],
            [2, 6, 7, 3],
            [4, 5, 7, 6],
        ],
    )
}

/// The same cube numbered the other way round, as the language's golden
/// traces were recorded: vertex `i` has x from bit 2, y from bit 1 and z
/// from bit 0; faces −x, −y, −z, +z, +y, +x.
///
/// ```
/// let cube = edgewise_core::mesh::generate::cube_zyx();
/// assert_eq!(cube.face(0), Some(&[2, 0, 1, 3][..])); // x = −1
/// ```
pub fn cube_zyx() -> Polygons {
    cube_with(
        |i| [(i >> 2) & 1, (i >> 1) & 1, i & 1],
        [
            [2, 0, 1, 3],
            [1, 0, 4, 5],
            [4, 0, 2, 6],
            [3, 1, 5, 7],
            [6, 2, 3, 7],
            [5, 4, 6, 7],
        ],
    )
}

/// Eight corners whose (x, y, z) bits `bits` gives, and six squares.
fn cube_with(bits: impl Fn(u32) -> [u32; 3], faces: [[u32; 4]; 6]) -> Polygons {
    let positions = (0..8)
        .map(|i| Vec3::from_array(bits(i).map(|bit| if bit == 0 { -1.0 } else { 1.0 })))
        .collect();
    Polygons::from_faces(positions, faces)
}

/// A unit square in the plane z = 0 cut along its diagonal 0–2 into
/// triangles 0 1 2 and 0 2 3: the smallest mesh with a boundary, small
/// enough to check its tables by hand.
///
/// ```
/// let square = edgewise_core::mesh::generate::open_square();
/// assert_eq!(square.face(1), Some(&[0, 2, 3][..]));
/// ```
pub fn open_square() -> Polygons {
    let positions = vec![Vec3::ZERO, Vec3::X, Vec3::new(1.0, 1.0, 0.0), Vec3::Y];
    Polygons::from_triangles(positions, &[[0, 1, 2], [0, 2, 3]])
}

/// An open grid of `nx × ny` unit squares in the plane z = 0, with one
/// boundary loop: vertex (i, j) is number `j·(nx + 1) + i` at (i, j, 0), and
/// square (i, j) is face `j·nx + i`, listed (i, j), (i + 1, j), (i + 1, j + 1),
/// (i, j + 1), counter-clockwise seen from +z. Grids of more than
/// [`TORUS_MAX_VERTICES`] vertices give an empty list, as for [`torus`].
///
/// ```
/// let grid = edgewise_core::mesh::generate::grid(3, 2);
/// assert_eq!((grid.vertex_count(), grid.face_count()), (12, 6));
/// assert_eq!(grid.face(0), Some(&[0, 1, 5, 4][..]));
/// ```
/// The half-edge explainer's example mesh: six triangles around a centre
/// vertex (3) in the plane, an open hexagon; where its edge-flip
/// walkthrough happens.
pub fn hexagon() -> Polygons {
    let positions = [
        [1.0, 4.0],
        [3.0, 4.0],
        [0.0, 2.0],
        [2.0, 2.0],
        [4.0, 2.0],
        [1.0, 0.0],
        [3.0, 0.0],
    ]
    .map(|[x, y]| Vec3::new(x, y, 0.0))
    .to_vec();
    Polygons::from_triangles(
        positions,
        &[
            [0, 2, 3],
            [0, 3, 1],
            [1, 3, 4],
            [2, 5, 3],
            [3, 5, 6],
            [3, 6, 4],
        ],
    )
}

pub fn grid(nx: u32, ny: u32) -> Polygons {
    let (columns, rows) = (u64::from(nx) + 1, u64::from(ny) + 1);
    if columns * rows > TORUS_MAX_VERTICES {
        return Polygons::new();
    }
    let (count_x, count_y) = (nx as usize, ny as usize);
    let mut polygons = Polygons::with_capacity(
        (count_x + 1) * (count_y + 1),
        count_x * count_y,
        4 * count_x * count_y,
    );
    for j in 0..=ny {
        for i in 0..=nx {
            polygons.push_vertex(Vec3::new(i as f32, j as f32, 0.0));
        }
    }
    let index = |i: u32, j: u32| j * (nx + 1) + i;
    for j in 0..ny {
        for i in 0..nx {
            polygons.push_face(&[
                index(i, j),
                index(i + 1, j),
                index(i + 1, j + 1),
                index(i, j + 1),
            ]);
        }
    }
    polygons
}
