//! Shared by the language's integration tests: sample meshes built from
//! positions and counter-clockwise polygons (with the tetrahedron, cube and
//! grid of `mesh::generate`), and brute-force answers computed
//! by scanning whole tables, the "conventional" way the papers contrast with
//! walking the structure.

#![allow(dead_code)]

use edgewise_core::lang::Topology;
use edgewise_core::mesh::{HalfEdgeMesh, Polygons, WingedEdgeMesh, generate};
use edgewise_core::schema::{Column, ElementKind, ElementRef, Structure};
use glam::Vec3;
use std::collections::BTreeSet;

/// The faces of the convex hull of points in convex position, each listed
/// counter-clockwise seen from outside.
pub fn convex_polyhedron(points: &[[f64; 3]]) -> Polygons {
    let sub = |a: [f64; 3], b: [f64; 3]| [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
    let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    let cross = |a: [f64; 3], b: [f64; 3]| {
        [
            a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0],
        ]
    };
    let n = points.len();
    let mut seen = BTreeSet::new();
    let mut faces: Vec<Vec<u32>> = Vec::new();
    for i in 0..n {
        for j in i + 1..n {
            for k in j + 1..n {
                let mut normal = cross(sub(points[j], points[i]), sub(points[k], points[i]));
                let length = dot(normal, normal).sqrt();
                if length < 1e-9 {
                    continue;
                }
                normal = normal.map(|c| c / length);
                let side: Vec<f64> = points
                    .iter()
                    .map(|&p| dot(normal, sub(p, points[i])))
                    .collect();
                let outside = side.iter().filter(|&&d| d > 1e-6).count();
                let inside = side.iter().filter(|&&d| d < -1e-6).count();
                if outside > 0 && inside > 0 {
                    continue;
                }
                if outside > 0 {
                    normal = normal.map(|c| -c);
                }
                let on: Vec<usize> = (0..n).filter(|&m| side[m].abs() <= 1e-6).collect();
                if !seen.insert(on.clone()) {
                    continue;
                }
                let mut centre = [0.0; 3];
                for &m in &on {
                    centre = [
                        centre[0] + points[m][0],
                        centre[1] + points[m][1],
                        centre[2] + points[m][2],
                    ];
                }
                centre = centre.map(|c| c / on.len() as f64);
                let u = sub(points[on[0]], centre);
                let w = cross(normal, u);
                let mut ordered: Vec<(f64, usize)> = on
                    .iter()
                    .map(|&m| {
                        let d = sub(points[m], centre);
                        (dot(d, w).atan2(dot(d, u)), m)
                    })
                    .collect();
                ordered.sort_by(|a, b| a.0.total_cmp(&b.0));
                faces.push(ordered.iter().map(|&(_, m)| m as u32).collect());
            }
        }
    }
    faces.sort_by_key(|f| {
        let mut key = f.clone();
        key.sort_unstable();
        key
    });
    let positions = points
        .iter()
        .map(|p| Vec3::new(p[0] as f32, p[1] as f32, p[2] as f32))
        .collect();
    Polygons::from_faces(positions, faces)
}

const PHI: f64 = 1.618_033_988_749_895;

pub fn octahedron() -> Polygons {
    convex_polyhedron(&[
        [1.0, 0.0, 0.0],
        [-1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [0.0, -1.0, 0.0],
        [0.0, 0.0, 1.0],
        [0.0, 0.0, -1.0],
    ])
}

pub fn icosahedron() -> Polygons {
    let mut points = Vec::new();
    for a in [-1.0, 1.0] {
        for b in [-PHI, PHI] {
            points.push([0.0, a, b]);
            points.push([a, b, 0.0]);
            points.push([b, 0.0, a]);
        }
    }
    convex_polyhedron(&points)
}

pub fn dodecahedron() -> Polygons {
    let mut points = Vec::new();
    for x in [-1.0, 1.0] {
        for y in [-1.0, 1.0] {
            for z in [-1.0, 1.0] {
                points.push([x, y, z]);
            }
        }
    }
    for a in [-1.0 / PHI, 1.0 / PHI] {
        for b in [-PHI, PHI] {
            points.push([0.0, a, b]);
            points.push([a, b, 0.0]);
            points.push([b, 0.0, a]);
        }
    }
    convex_polyhedron(&points)
}

/// A prism over a regular `n`-gon.
pub fn prism(n: usize) -> Polygons {
    let mut points = Vec::new();
    for z in [-1.0, 1.0] {
        for i in 0..n {
            let angle = std::f64::consts::TAU * i as f64 / n as f64;
            points.push([angle.cos(), angle.sin(), z]);
        }
    }
    convex_polyhedron(&points)
}

/// A pyramid over a regular `n`-gon.
pub fn pyramid(n: usize) -> Polygons {
    let mut points = vec![[0.0, 0.0, 1.5]];
    for i in 0..n {
        let angle = std::f64::consts::TAU * i as f64 / n as f64;
        points.push([angle.cos(), angle.sin(), 0.0]);
    }
    convex_polyhedron(&points)
}

/// A torus of `nu × nv` quads, numbered like the benchmark torus.
pub fn quad_torus(nu: u32, nv: u32) -> Polygons {
    let triangles = generate::torus(nu, nv);
    let index = |i: u32, j: u32| (j % nv) * nu + (i % nu);
    let mut faces = Vec::new();
    for j in 0..nv {
        for i in 0..nu {
            faces.push(vec![
                index(i, j),
                index(i + 1, j),
                index(i + 1, j + 1),
                index(i, j + 1),
            ]);
        }
    }
    Polygons::from_faces(triangles.positions().to_vec(), faces)
}

/// The same mesh without some faces (which must leave it manifold).
pub fn without_faces(polygons: &Polygons, removed: &[usize]) -> Polygons {
    let faces: Vec<Vec<u32>> = polygons
        .faces()
        .enumerate()
        .filter(|(i, _)| !removed.contains(i))
        .map(|(_, f)| f.to_vec())
        .collect();
    Polygons::from_faces(polygons.positions().to_vec(), faces)
}

/// Every closed sample mesh, by name.
pub fn closed_samples() -> Vec<(&'static str, Polygons)> {
    vec![
        ("tetrahedron", generate::regular_tetrahedron()),
        ("cube", generate::cube_zyx()),
        ("octahedron", octahedron()),
        ("icosahedron", icosahedron()),
        ("dodecahedron", dodecahedron()),
        ("triangular prism", prism(3)),
        ("pentagonal prism", prism(5)),
        ("square pyramid", pyramid(4)),
        ("triangle torus 6×4", generate::torus(6, 4)),
        ("quad torus 5×4", quad_torus(5, 4)),
    ]
}

/// Open sample meshes: each has at least one boundary loop.
pub fn open_samples() -> Vec<(&'static str, Polygons)> {
    vec![
        ("quad grid 3×2", generate::grid(3, 2)),
        (
            "cube without a face",
            without_faces(&generate::cube_zyx(), &[0]),
        ),
        (
            "icosahedron without a face",
            without_faces(&icosahedron(), &[3]),
        ),
        (
            "triangle torus without a face",
            without_faces(&generate::torus(6, 4), &[5]),
        ),
        (
            "quad torus without two faces",
            without_faces(&quad_torus(5, 4), &[0, 12]),
        ),
    ]
}

pub fn winged(polygons: &Polygons) -> WingedEdgeMesh {
    WingedEdgeMesh::build(polygons)
        .expect("sample mesh builds")
        .0
}

pub fn half(polygons: &Polygons) -> HalfEdgeMesh {
    HalfEdgeMesh::build(polygons).expect("sample mesh builds").0
}

/// One row of an edge table, read through the lookups.
#[derive(Clone, Copy, Debug)]
pub struct Row {
    pub edge: u32,
    pub start: u32,
    pub end: u32,
    /// Winged-edge: left face; half-edge: the half-edge's face.
    pub left: Option<u32>,
    /// Winged-edge: right face; half-edge: the pair's face.
    pub right: Option<u32>,
}

fn get(topology: &dyn Topology, element: ElementRef, field: Column) -> Option<ElementRef> {
    topology
        .lookup(element, field)
        .expect("lookup on a valid mesh")
}

/// Scans the whole edge (or half-edge) table.
pub fn rows(topology: &dyn Topology) -> Vec<Row> {
    let index = |e: Option<ElementRef>| e.map(|e: ElementRef| e.id);
    (0..topology.count(ElementKind::Edge) as u32)
        .map(|edge| {
            let e = ElementRef::new(ElementKind::Edge, edge);
            let start =
                get(topology, e, Column::StartVertex).map_or(u32::MAX, |e: ElementRef| e.id);
            let end = get(topology, e, Column::EndVertex).map_or(u32::MAX, |e: ElementRef| e.id);
            let (left, right) = match topology.structure() {
                Structure::WingedEdge => (
                    index(get(topology, e, Column::LeftFace)),
                    index(get(topology, e, Column::RightFace)),
                ),
                Structure::HalfEdge => {
                    let pair =
                        get(topology, e, Column::PairEdge).expect("every half-edge has a pair");
                    (
                        index(get(topology, e, Column::Face)),
                        index(get(topology, pair, Column::Face)),
                    )
                }
            };
            Row {
                edge,
                start,
                end,
                left,
                right,
            }
        })
        .collect()
}

/// What a library algorithm must produce, found without walking the mesh.
pub struct Expected {
    pub marked: Vec<ElementRef>,
    /// For vertexValence: the final value of `n`.
    pub valence: Option<i32>,
}

fn sorted(mut elements: Vec<ElementRef>) -> Vec<ElementRef> {
    elements.sort();
    elements
}

/// The brute-force answer of library algorithm `name` for `input`, or
/// `None` for an algorithm this function does not know.
pub fn brute_force(
    name: &str,
    topology: &dyn Topology,
    polygons: &Polygons,
    input: ElementRef,
) -> Option<Expected> {
    let structure = topology.structure();
    let rows = rows(topology);
    let faces: Vec<Vec<u32>> = polygons.faces().map(<[u32]>::to_vec).collect();
    let face_of = |f: u32| ElementRef::new(ElementKind::Face, f);
    let vertex_of = |v: u32| ElementRef::new(ElementKind::Vertex, v);
    let edge_of = |e: u32| ElementRef::new(ElementKind::Edge, e);
    let i = input.id;

    // The edges (half-edges) a walk around vertex v meets, one per edge.
    let around_vertex = |v: u32| -> Vec<&Row> {
        rows.iter()
            .filter(|r| match structure {
                Structure::WingedEdge => r.start == v || r.end == v,
                Structure::HalfEdge => r.end == v,
            })
            .collect()
    };
    let faces_at = |v: u32| -> Vec<u32> {
        (0..faces.len() as u32)
            .filter(|&f| faces[f as usize].contains(&v))
            .collect()
    };
    let neighbours = |v: u32| -> Vec<u32> {
        around_vertex(v)
            .iter()
            .map(|r| if r.start == v { r.end } else { r.start })
            .collect()
    };
    // The rows bounding face f: winged-edge edges with f on either side, or
    // half-edges whose own face is f.
    let face_rows = |f: u32| -> Vec<&Row> {
        rows.iter()
            .filter(|r| match structure {
                Structure::WingedEdge => r.left == Some(f) || r.right == Some(f),
                Structure::HalfEdge => r.left == Some(f),
            })
            .collect()
    };
    let across = |r: &Row, f: u32| -> Option<u32> {
        match structure {
            Structure::WingedEdge => {
                if r.left == Some(f) {
                    r.right
                } else {
                    r.left
                }
            }
            Structure::HalfEdge => r.right,
        }
    };
    let link = |v: u32| -> Vec<ElementRef> {
        let mut marked = Vec::new();
        let mut vertices = BTreeSet::new();
        for f in faces_at(v) {
            vertices.extend(faces[f as usize].iter().copied().filter(|&x| x != v));
            marked.extend(
                face_rows(f)
                    .iter()
                    .filter(|r| r.start != v && r.end != v)
                    .map(|r| edge_of(r.edge)),
            );
        }
        marked.extend(vertices.into_iter().map(vertex_of));
        marked
    };

    let marked: Vec<ElementRef> = match name {
        "vertexAdjacentEdge" => around_vertex(i).iter().map(|r| edge_of(r.edge)).collect(),
        "vertexAdjacentFace" | "vertexAdjacentFaceOpen" => {
            faces_at(i).into_iter().map(face_of).collect()
        }
        "vertexAdjacentVertex" => neighbours(i).into_iter().map(vertex_of).collect(),
        "vertexValence" => {
            return Some(Expected {
                marked: Vec::new(),
                valence: Some(around_vertex(i).len() as i32),
            });
        }
        "isExtraordinary" => {
            if around_vertex(i).len() == 4 {
                Vec::new()
            } else {
                vec![input]
            }
        }
        "vertexStar" | "vertexStarOpen" => {
            let mut marked = vec![input];
            marked.extend(around_vertex(i).iter().map(|r| edge_of(r.edge)));
            marked.extend(faces_at(i).into_iter().map(face_of));
            marked
        }
        "vertexLink" | "vertexLinkOpen" => link(i),
        "faceAdjacentVertex" => faces
            .get(i as usize)?
            .iter()
            .copied()
            .map(vertex_of)
            .collect(),
        "faceAdjacentEdge" => face_rows(i).iter().map(|r| edge_of(r.edge)).collect(),
        "faceAdjacentFace" | "faceAdjacentFaceOpen" => face_rows(i)
            .iter()
            .filter_map(|r| across(r, i))
            .map(face_of)
            .collect(),
        "edgeAdjacentFace" | "edgeAdjacentFaceOpen" => {
            let row = rows.get(i as usize)?;
            [row.left, row.right]
                .into_iter()
                .flatten()
                .map(face_of)
                .collect()
        }
        "vertexOppositeFace" => (0..faces.len() as u32)
            .filter(|&f| !faces[f as usize].contains(&i))
            .map(face_of)
            .collect(),
        "faceOppositeFace" => {
            let own = faces.get(i as usize)?;
            (0..faces.len() as u32)
                .filter(|&f| faces[f as usize].iter().all(|x| !own.contains(x)))
                .map(face_of)
                .collect()
        }
        "vertexOppositeVertex" => {
            let near = neighbours(i);
            (0..polygons.vertex_count() as u32)
                .filter(|&x| x != i && !near.contains(&x))
                .map(vertex_of)
                .collect()
        }
        "edgeOppositeEdges" | "edgeOppositeEdgesOpen" => {
            // In each face beside the edge, the row sharing no vertex with it.
            let row = rows.get(i as usize)?;
            [row.left, row.right]
                .into_iter()
                .flatten()
                .flat_map(|f| {
                    face_rows(f)
                        .into_iter()
                        .filter(|r| {
                            ![row.start, row.end].contains(&r.start)
                                && ![row.start, row.end].contains(&r.end)
                        })
                        .map(|r| edge_of(r.edge))
                        .collect::<Vec<_>>()
                })
                .collect()
        }
        "boundaryLoop" => {
            // The boundary rows connected to this one through shared vertices.
            let row = rows.get(i as usize)?;
            if row.left.is_some() && row.right.is_some() {
                Vec::new()
            } else {
                let boundary: Vec<&Row> = rows
                    .iter()
                    .filter(|r| match structure {
                        Structure::WingedEdge => r.left.is_none() || r.right.is_none(),
                        Structure::HalfEdge => r.left.is_none(),
                    })
                    .collect();
                let mut reached = BTreeSet::from([row.start, row.end]);
                let mut members = BTreeSet::new();
                loop {
                    let before = members.len();
                    for r in &boundary {
                        if reached.contains(&r.start) || reached.contains(&r.end) {
                            members.insert(r.edge);
                            reached.insert(r.start);
                            reached.insert(r.end);
                        }
                    }
                    if members.len() == before {
                        break;
                    }
                }
                members.into_iter().map(edge_of).collect()
            }
        }
        _ => return None,
    };
    Some(Expected {
        marked: sorted(marked),
        valence: None,
    })
}

/// Each library algorithm's parameter kind and whether it is defined on
/// open meshes (at boundary elements too).
pub fn applies_on_open_meshes(name: &str) -> bool {
    matches!(
        name,
        "vertexAdjacentEdge"
            | "vertexAdjacentFaceOpen"
            | "vertexAdjacentVertex"
            | "vertexValence"
            | "isExtraordinary"
            | "vertexStarOpen"
            | "vertexLinkOpen"
            | "faceAdjacentVertex"
            | "faceAdjacentEdge"
            | "faceAdjacentFaceOpen"
            | "edgeAdjacentFaceOpen"
            | "boundaryLoop"
    )
}

/// The exercises, which only make sense on particular meshes.
pub fn is_exercise(name: &str) -> bool {
    matches!(
        name,
        "vertexOppositeFace"
            | "faceOppositeFace"
            | "edgeOppositeEdges"
            | "edgeOppositeEdgesOpen"
            | "vertexOppositeVertex"
    )
}

pub fn sorted_marked(marked: impl IntoIterator<Item = ElementRef>) -> Vec<ElementRef> {
    sorted(marked.into_iter().collect())
}
