//! Hand-checked small meshes: the journal paper's tetrahedron (Table 2), a
//! cube, an open square of two triangles, a quad strip and a torus.

use edgewise_core::mesh::half_edge::{self, HalfEdge};
use edgewise_core::mesh::winged_edge;
use edgewise_core::mesh::{
    EdgeId, FaceId, HalfEdgeId, HalfEdgeMesh, Mesh, Navigation, Polygons, Side, Structure,
    VertexId, WingedEdge, WingedEdgeMesh, generate,
};
use glam::Vec3;

fn v(i: u32) -> VertexId {
    VertexId::new(i)
}
fn e(i: u32) -> EdgeId {
    EdgeId::new(i)
}
fn f(i: u32) -> FaceId {
    FaceId::new(i)
}
fn h(i: u32) -> HalfEdgeId {
    HalfEdgeId::new(i)
}

/// The numbers of some ids, to compare with literals.
fn ids<I: Into<usize>>(ids: impl Iterator<Item = I>) -> Vec<usize> {
    ids.map(Into::into).collect()
}

fn build_both(polygons: &Polygons) -> (HalfEdgeMesh, WingedEdgeMesh) {
    let (he, warnings) = HalfEdgeMesh::build(polygons).expect("half-edge build");
    assert!(warnings.is_empty(), "{warnings:?}");
    let (we, warnings) = WingedEdgeMesh::build(polygons).expect("winged-edge build");
    assert!(warnings.is_empty(), "{warnings:?}");
    assert_eq!(he.validate(), vec![], "half-edge issues");
    assert_eq!(we.validate(), vec![], "winged-edge issues");
    (he, we)
}

/// Both conversions and both polygon exports agree with the builds.
fn assert_round_trips(polygons: &Polygons, he: &HalfEdgeMesh, we: &WingedEdgeMesh) {
    assert_eq!(&he.to_polygons(), polygons);
    assert_eq!(&he.to_winged_edge().expect("he → we"), we);
    assert_eq!(
        &we.to_half_edge()
            .expect("we → he")
            .to_winged_edge()
            .expect("he → we"),
        we
    );
    assert_eq!(
        &WingedEdgeMesh::build(&we.to_polygons()).expect("rebuild").0,
        we
    );
}

// ---------------------------------------------------------------- tetrahedron

fn edge_named(name: char) -> EdgeId {
    e(name as u32 - 'a' as u32)
}

#[test]
fn tetrahedron_reproduces_table_2() {
    let (_, we) = build_both(&generate::tetrahedron());
    assert_eq!(we.edge_count(), 6);
    // Each edge against its row of Table 2 as printed.
    let mut reversed = Vec::new();
    for (row, &expected) in generate::table_2().edges().iter().enumerate() {
        let name = (b'a' + row as u8) as char;
        let actual = *we.edge(edge_named(name)).expect("edge exists");
        if actual.start_vertex == expected.start_vertex {
            assert_eq!(actual, expected, "row {name}");
        } else {
            // The build points each edge the way it first appears; the paper's
            // row describes the same edge from the other end, which swaps the
            // two sides and nothing else.
            reversed.push(name);
            let flipped = WingedEdge {
                start_vertex: expected.end_vertex,
                end_vertex: expected.start_vertex,
                left_face: expected.right_face,
                right_face: expected.left_face,
                left_predecessor: expected.right_predecessor,
                left_successor: expected.right_successor,
                right_predecessor: expected.left_predecessor,
                right_successor: expected.left_successor,
            };
            assert_eq!(actual, flipped, "row {name} (reversed)");
        }
    }
    // No face order makes every edge point as in Table 2 (faces 1 → 2 → 3 → 1
    // would each have to come first); this listing reverses only a and f.
    assert_eq!(reversed, ['a', 'f']);
    // Vertex table (b): A a, B b, C d as in the paper; D gets a, its
    // lowest-numbered edge, where the paper picked e.
    let incident: Vec<_> = we
        .vertices()
        .iter()
        .map(|vertex| vertex.incident_edge)
        .collect();
    assert_eq!(incident, [Some(e(0)), Some(e(1)), Some(e(3)), Some(e(0))]);
    // Face table (c): 1 a, 2 c, 3 a, 4 b, exactly as in the paper.
    let incident: Vec<_> = we.faces().iter().map(|face| face.incident_edge).collect();
    assert_eq!(incident, [e(0), e(2), e(0), e(1)]);
}

#[test]
fn tetrahedron_half_edges_follow_face_order() {
    let polygons = generate::tetrahedron();
    let (he, we) = build_both(&polygons);
    assert_eq!(he.half_edge_count(), 12);
    // Face [D, A, B] gives D→A, A→B, B→D.
    let ends: Vec<u32> = he
        .half_edges()
        .iter()
        .map(|half| half.end_vertex.raw())
        .collect();
    assert_eq!(ends, [0, 1, 3, 2, 3, 1, 3, 2, 0, 2, 1, 0]);
    let starts: Vec<u32> = (0..12)
        .map(|i| he.start_vertex(h(i)).expect("start").raw())
        .collect();
    assert_eq!(starts, [3, 0, 1, 1, 2, 3, 0, 3, 2, 0, 2, 1]);
    for i in 0..12 {
        let half = he.half_edge(h(i)).expect("half-edge");
        assert_eq!(half.face, Some(f(i / 3)));
        assert_eq!(he.predecessor_edge(half.successor_edge), Some(h(i)));
        assert_eq!(he.half_edge(half.pair_edge).expect("pair").pair_edge, h(i));
    }
    // Incident edges: lowest half-edge ending at the vertex; first of the face.
    let incident: Vec<_> = he
        .vertices()
        .iter()
        .map(|vertex| vertex.incident_edge)
        .collect();
    assert_eq!(incident, [Some(h(0)), Some(h(1)), Some(h(3)), Some(h(2))]);
    let incident: Vec<_> = he
        .faces()
        .iter()
        .map(|face| face.incident_edge.raw())
        .collect();
    assert_eq!(incident, [0, 3, 6, 9]);
    // The paper's loop around D visits each half-edge ending at D once.
    let around_d = ids(he.around_vertex(v(3)));
    assert_eq!(around_d, [2, 6, 4]);
    assert_round_trips(&polygons, &he, &we);
    let stats = he.stats();
    assert_eq!(
        (stats.vertices, stats.edges, stats.faces, stats.half_edges),
        (4, 6, 4, 12)
    );
    assert_eq!((stats.euler_characteristic, stats.boundary_loops), (2, 0));
    assert_eq!(stats.components.len(), 1);
    assert_eq!(stats.components[0].genus, Some(0));
    assert_eq!(we.stats(), stats);
}

// ----------------------------------------------------------------------- cube

#[test]
fn cube_of_quads() {
    let polygons = generate::cube();
    let (he, we) = build_both(&polygons);
    let stats = we.stats();
    assert_eq!(
        (stats.vertices, stats.edges, stats.faces, stats.half_edges),
        (8, 12, 6, 24)
    );
    assert_eq!((stats.euler_characteristic, stats.boundary_loops), (2, 0));
    assert_eq!(stats.components[0].genus, Some(0));
    assert_eq!(he.stats(), stats);
    for i in 0..8 {
        assert_eq!(we.around_vertex(v(i)).count(), 3);
        assert_eq!(he.vertex_faces(v(i)).count(), 3);
    }
    for i in 0..6 {
        assert_eq!(we.around_face(f(i)).count(), 4);
        assert_eq!(he.face_neighbours(f(i)).count(), 4);
        let listed = ids(he.face_vertices(f(i)));
        let face = polygons.face(i as usize).expect("face");
        assert_eq!(listed, ids(face.iter().map(|&x| x as usize)));
    }
    // Neighbours of vertex 0 turn clockwise seen from outside (-x, -y, -z corner).
    let around = ids(he.vertex_neighbours(v(0)));
    assert_eq!(around, [1, 2, 4]);
    // The same turn, from the lowest-numbered edge (0→2) instead.
    let around = ids(we.vertex_neighbours(v(0)));
    assert_eq!(around, [2, 4, 1]);
    assert_round_trips(&polygons, &he, &we);
}

// -------------------------------------------------------------- open square

#[test]
fn open_square_half_edge_tables() {
    let (he, _) = build_both(&generate::open_square());
    let row = |end, face: Option<u32>, pair, successor| HalfEdge {
        end_vertex: v(end),
        face: face.map(f),
        pair_edge: h(pair),
        successor_edge: h(successor),
    };
    // Interior half-edges face by face, then boundary ones in the order of
    // their interior pair (0, 1, 4, 5), linked along the boundary loop.
    let expected = [
        row(1, Some(0), 6, 1),
        row(2, Some(0), 7, 2),
        row(0, Some(0), 3, 0),
        row(2, Some(1), 2, 4),
        row(3, Some(1), 8, 5),
        row(0, Some(1), 9, 3),
        row(0, None, 0, 9),
        row(1, None, 1, 6),
        row(2, None, 4, 7),
        row(3, None, 5, 8),
    ];
    assert_eq!(he.half_edges(), expected);
    let predecessors: Vec<u32> = (0..10)
        .map(|i| he.predecessor_edge(h(i)).expect("predecessor").raw())
        .collect();
    assert_eq!(predecessors, [2, 0, 1, 5, 3, 4, 7, 8, 9, 6]);
    let incident: Vec<_> = he
        .vertices()
        .iter()
        .map(|vertex| vertex.incident_edge)
        .collect();
    assert_eq!(incident, [Some(h(2)), Some(h(0)), Some(h(1)), Some(h(4))]);
    assert_eq!(
        he.faces(),
        [
            half_edge::Face {
                incident_edge: h(0)
            },
            half_edge::Face {
                incident_edge: h(3)
            }
        ]
    );
    assert!(he.is_boundary(h(6)) && !he.is_boundary(h(5)));
    // Around vertex 0 the loop passes through the boundary gap: 2 (face 0),
    // 6 (boundary), 5 (face 1).
    let around = ids(he.around_vertex(v(0)));
    assert_eq!(around, [2, 6, 5]);
    let faces = ids(he.vertex_faces(v(0)));
    assert_eq!(faces, [0, 1]);
}

#[test]
fn open_square_winged_edge_tables() {
    let polygons = generate::open_square();
    let (he, we) = build_both(&polygons);
    let row = |start, end, left, right: Option<u32>, lp, ls, rp, rs| WingedEdge {
        start_vertex: v(start),
        end_vertex: v(end),
        left_face: Some(f(left)),
        right_face: right.map(f),
        left_predecessor: e(lp),
        left_successor: e(ls),
        right_predecessor: e(rp),
        right_successor: e(rs),
    };
    let expected = [
        row(0, 1, 0, None, 1, 2, 4, 1),
        row(1, 2, 0, None, 2, 0, 0, 3),
        row(2, 0, 0, Some(1), 0, 1, 3, 4),
        row(2, 3, 1, None, 4, 2, 1, 4),
        row(3, 0, 1, None, 2, 3, 3, 0),
    ];
    assert_eq!(we.edges(), expected);
    let incident: Vec<_> = we
        .vertices()
        .iter()
        .map(|vertex| vertex.incident_edge)
        .collect();
    assert_eq!(incident, [Some(e(0)), Some(e(0)), Some(e(1)), Some(e(3))]);
    assert_eq!(
        we.faces(),
        [
            winged_edge::Face {
                incident_edge: e(0)
            },
            winged_edge::Face {
                incident_edge: e(2)
            }
        ]
    );
    let stats = we.stats();
    assert_eq!(
        (
            stats.vertices,
            stats.edges,
            stats.faces,
            stats.boundary_loops
        ),
        (4, 5, 2, 1)
    );
    assert_eq!(stats.euler_characteristic, 1);
    assert_eq!(stats.components[0].genus, None);
    assert_eq!(he.stats(), stats);
    let around = ids(we.around_vertex(v(0)));
    assert_eq!(around, [0, 4, 2]);
    let sides: Vec<(u32, Side)> = we
        .around_face(f(1))
        .map(|(x, side)| (x.raw(), side))
        .collect();
    assert_eq!(sides, [(2, Side::Right), (3, Side::Left), (4, Side::Left)]);
    assert_round_trips(&polygons, &he, &we);
    let (_, correspondence) = he.to_winged_edge_with_correspondence().expect("convert");
    assert_eq!(correspondence.half_edges(e(2)), Some((h(2), h(3))));
    assert_eq!(correspondence.edge(h(9)), Some(e(4)));
}

// ---------------------------------------------------------------- quad strip

#[test]
fn quad_strip() {
    let polygons = generate::grid(3, 1);
    let (he, we) = build_both(&polygons);
    let stats = he.stats();
    assert_eq!(
        (stats.vertices, stats.edges, stats.faces, stats.half_edges),
        (8, 10, 3, 20)
    );
    assert_eq!((stats.boundary_loops, stats.euler_characteristic), (1, 1));
    assert_eq!(we.stats(), stats);
    // The single boundary loop has 8 half-edges.
    let boundary: Vec<_> = he
        .half_edges()
        .iter()
        .filter(|half| half.face.is_none())
        .collect();
    assert_eq!(boundary.len(), 8);
    let mut walk = h(12);
    for _ in 0..8 {
        walk = he.half_edge(walk).expect("boundary").successor_edge;
        assert!(he.is_boundary(walk));
    }
    assert_eq!(walk, h(12));
    let neighbours = ids(we.face_neighbours(f(1)));
    assert_eq!(neighbours.len(), 2);
    assert!(neighbours.contains(&0) && neighbours.contains(&2));
    assert_round_trips(&polygons, &he, &we);
}

// --------------------------------------------------------------------- torus

#[test]
fn torus_has_genus_one() {
    let polygons = generate::torus(4, 3);
    let (he, we) = build_both(&polygons);
    let stats = he.stats();
    assert_eq!(
        (stats.vertices, stats.edges, stats.faces, stats.half_edges),
        (12, 36, 24, 72)
    );
    assert_eq!((stats.euler_characteristic, stats.boundary_loops), (0, 0));
    assert_eq!(stats.components[0].genus, Some(1));
    assert_eq!(we.stats(), stats);
    for i in 0..12 {
        assert_eq!(he.vertex_neighbours(v(i)).count(), 6);
        assert_eq!(we.vertex_faces(v(i)).count(), 6);
    }
    assert_round_trips(&polygons, &he, &we);
    let (mesh, _) = Mesh::build(&polygons, Structure::HalfEdge).expect("build");
    let converted = mesh.convert_to(Structure::WingedEdge).expect("convert");
    assert_eq!(converted.structure(), Structure::WingedEdge);
    assert_eq!(converted.as_winged_edge(), Some(&we));
    assert_eq!(converted.positions(), polygons.positions());
}

#[test]
fn two_components_and_an_isolated_vertex() {
    let mut polygons = generate::torus(3, 3);
    let offset = polygons.vertex_count() as u32;
    let corner = generate::unit_tetrahedron();
    for &p in corner.positions().iter().chain(&[Vec3::ONE]) {
        polygons.push_vertex(p);
    }
    for face in corner.faces() {
        let face: Vec<u32> = face.iter().map(|x| x + offset).collect();
        polygons.push_face(&face);
    }
    let (we, warnings) = WingedEdgeMesh::build(&polygons).expect("build");
    assert_eq!(warnings.len(), 1);
    assert_eq!(
        warnings[0].to_string(),
        "vertex 13 is not used by any face; it is kept as an isolated vertex"
    );
    assert_eq!(we.validate(), vec![]);
    assert_eq!(we.vertex(v(13)).expect("kept").incident_edge, None);
    let stats = we.stats();
    assert_eq!(stats.connected_components(), 3);
    let genera: Vec<_> = stats.components.iter().map(|c| c.genus).collect();
    assert_eq!(genera, [Some(1), Some(0), None]);
    assert_eq!(stats.euler_characteristic, 3); // torus 0, sphere 2, point 1
    let he = we.to_half_edge().expect("convert");
    assert_eq!(he.stats(), stats);
    assert_eq!(he.around_vertex(v(13)).count(), 0);
}

// ------------------------------------------------------------ dangling edge

/// A triangle with an edge dangling into it from vertex 0 (what MEV with
/// one edge makes): its face walks the dangling edge out and back, so the
/// edge has face 0 on both sides, and both structures accept that.
#[test]
fn a_dangling_edge_has_its_face_on_both_sides() {
    let positions = [Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::splat(0.3)];
    let vertices = positions
        .iter()
        .zip([2, 0, 1, 6])
        .map(|(&position, incident)| half_edge::Vertex {
            position,
            incident_edge: Some(h(incident)),
        })
        .collect();
    let faces = vec![half_edge::Face {
        incident_edge: h(0),
    }];
    // End vertex, face, pair, successor: 0→1→2→0 with 0→3→0 after 2→0,
    // then the boundary loop 1→0→2→1.
    let rows = [
        (1, Some(0), 3, 1),
        (2, Some(0), 4, 2),
        (0, Some(0), 5, 6),
        (0, None, 0, 5),
        (1, None, 1, 3),
        (2, None, 2, 4),
        (3, Some(0), 7, 7),
        (0, Some(0), 6, 0),
    ];
    let half_edges = rows
        .iter()
        .map(|&(end, face, pair, successor)| HalfEdge {
            end_vertex: v(end),
            face: face.map(f),
            pair_edge: h(pair),
            successor_edge: h(successor),
        })
        .collect();
    let he = HalfEdgeMesh::from_raw_parts(vertices, faces, half_edges);
    assert_eq!(he.validate(), vec![]);
    assert_eq!(ids(he.face_vertices(f(0))), [0, 1, 2, 0, 3]);
    let we = he
        .to_winged_edge()
        .expect("a valid half-edge mesh converts");
    assert_eq!(we.validate(), vec![]);
    let dangling = we.edge(e(3)).expect("the fourth edge");
    assert_eq!(
        (dangling.left_face, dangling.right_face),
        (Some(f(0)), Some(f(0)))
    );
    // The walk tells the two sides of the dangling edge apart by the vertex
    // it arrives at, so it goes out along one and back along the other.
    let sides: Vec<_> = we.around_face(f(0)).collect();
    assert_eq!(
        sides,
        [
            (e(0), Side::Left),
            (e(1), Side::Left),
            (e(2), Side::Left),
            (e(3), Side::Left),
            (e(3), Side::Right)
        ]
    );
    let stats = we.stats();
    assert_eq!((stats.vertices, stats.edges, stats.faces), (4, 4, 1));
    assert_eq!(stats.boundary_loops, 1);
    assert_eq!(he.stats().boundary_loops, 1);
}
