//! What the builder refuses (each refusal with its exact message), what it
//! keeps or splits with a warning, and what `validate()` says about broken
//! tables.

use edgewise_core::mesh::half_edge;
use edgewise_core::mesh::winged_edge;
use edgewise_core::mesh::{
    BuildError, BuildWarning, ConvertError, EdgeId, Element, FaceId, HalfEdgeId, HalfEdgeMesh,
    Issue, Navigation, Polygons, VertexId, WingedEdgeMesh, generate,
};
use edgewise_core::schema::Column;
use glam::Vec3;

/// Faces read from "lines" 10, 11, 12, ... of a file.
fn from_file(vertices: usize, faces: &[&[u32]]) -> Polygons {
    let mut polygons = Polygons::new();
    for i in 0..vertices {
        polygons.push_vertex(Vec3::new(i as f32, (i * i % 7) as f32, (i % 3) as f32));
    }
    for (i, face) in faces.iter().enumerate() {
        polygons.push_face_from_line(face, 10 + i);
    }
    polygons
}

/// Both builders refuse with the same error; returns its message.
fn refusal(polygons: &Polygons) -> (BuildError, String) {
    let half = HalfEdgeMesh::build(polygons).expect_err("half-edge build must refuse");
    let winged = WingedEdgeMesh::build(polygons).expect_err("winged-edge build must refuse");
    assert_eq!(half, winged);
    let message = half.to_string();
    (half, message)
}

#[test]
fn refuses_a_face_with_fewer_than_three_vertices() {
    let (error, message) = refusal(&from_file(3, &[&[0, 1, 2], &[0, 1]]));
    assert!(matches!(error, BuildError::TooFewVertices { count: 2, .. }));
    assert_eq!(
        message,
        "face 1 (line 11) has 2 vertices; a face needs at least 3"
    );
    let (_, message) = refusal(&from_file(3, &[&[]]));
    assert_eq!(
        message,
        "face 0 (line 10) has 0 vertices; a face needs at least 3"
    );
}

#[test]
fn refuses_a_repeated_vertex() {
    let (error, message) = refusal(&from_file(4, &[&[0, 1, 2], &[0, 2, 3, 2]]));
    assert!(
        matches!(error, BuildError::RepeatedVertex { vertex, .. } if vertex == VertexId::new(2))
    );
    assert_eq!(
        message,
        "face 1 (line 11) lists vertex 2 more than once; a face needs distinct vertices"
    );
    // Fewer than three distinct vertices: [1, 1, 2].
    let (_, message) = refusal(&Polygons::from_triangles(vec![Vec3::ZERO; 3], &[[1, 1, 2]]));
    assert_eq!(
        message,
        "face 0 lists vertex 1 more than once; a face needs distinct vertices"
    );
    // A large face takes the other path through the check.
    let mut big: Vec<u32> = (0..40).collect();
    big.push(17);
    let (_, message) = refusal(&Polygons::from_faces(vec![Vec3::ZERO; 40], [big]));
    assert_eq!(
        message,
        "face 0 lists vertex 17 more than once; a face needs distinct vertices"
    );
}

#[test]
fn refuses_an_index_out_of_range() {
    let (error, message) = refusal(&from_file(4, &[&[0, 1, 2], &[0, 2, 7]]));
    assert!(matches!(
        error,
        BuildError::IndexOutOfRange {
            index: 7,
            vertex_count: 4,
            ..
        }
    ));
    assert_eq!(
        message,
        "face 1 (line 11) refers to vertex 7, but the mesh has only 4 vertices (0 to 3)"
    );
    let (_, message) = refusal(&Polygons::from_triangles(Vec::new(), &[[0, 1, u32::MAX]]));
    assert_eq!(
        message,
        "face 0 refers to vertex 0, but the mesh has no vertices"
    );
}

#[test]
fn refuses_a_non_manifold_edge() {
    // Three fins on the edge 0–1.
    let (error, message) = refusal(&from_file(5, &[&[0, 1, 2], &[1, 0, 3], &[0, 1, 4]]));
    assert!(matches!(error, BuildError::NonManifoldEdge { ref faces, .. } if faces.len() == 3));
    assert_eq!(
        message,
        "the edge between vertex 0 and vertex 1 is used by 3 faces (face 0 (line 10), face 1 (line 11), \
         face 2 (line 12)); an edge can border at most two faces (non-manifold edge)"
    );
}

#[test]
fn refuses_inconsistent_orientation() {
    let (error, message) = refusal(&from_file(4, &[&[0, 1, 2], &[3, 2, 1], &[1, 3, 0]]));
    assert!(matches!(
        error,
        BuildError::InconsistentOrientation { first, second, .. }
            if first.face == FaceId::new(0) && second.face == FaceId::new(2)
    ));
    assert_eq!(
        message,
        "face 0 (line 10) and face 2 (line 12) both go from vertex 0 to vertex 1; faces sharing an edge must \
         traverse it in opposite directions (inconsistent orientation: reverse one of them)"
    );
}

/// Both builders accept with the same warnings; the meshes validate, and
/// convert into each other.
fn accepted(polygons: &Polygons) -> (HalfEdgeMesh, Vec<BuildWarning>) {
    let (half, warnings) = HalfEdgeMesh::build(polygons).expect("half-edge build");
    let (winged, winged_warnings) = WingedEdgeMesh::build(polygons).expect("winged-edge build");
    assert_eq!(warnings, winged_warnings);
    assert_eq!(half.validate(), vec![]);
    assert_eq!(winged.validate(), vec![]);
    assert_eq!(half.to_winged_edge().expect("he → we"), winged);
    let back = winged.to_half_edge().expect("we → he");
    assert_eq!(back.to_winged_edge().expect("he → we"), winged);
    (half, warnings)
}

fn split(vertex: u32, copies: &[u32]) -> BuildWarning {
    BuildWarning::SplitVertex {
        vertex: VertexId::new(vertex),
        copies: copies.iter().copied().map(VertexId::new).collect(),
    }
}

#[test]
fn splits_a_vertex_joining_two_fans() {
    // Two triangles touching at vertex 0 only (two open fans).
    let polygons = from_file(5, &[&[0, 1, 2], &[0, 3, 4]]);
    let (mesh, warnings) = accepted(&polygons);
    assert_eq!(warnings, [split(0, &[5])]);
    assert_eq!(
        warnings[0].to_string(),
        "vertex 0 joined 2 fans of faces; split into 0 and 5"
    );
    assert_eq!(mesh.vertex_count(), 6);
    assert_eq!(
        mesh.position(VertexId::new(5)),
        mesh.position(VertexId::new(0))
    );
    let faces: Vec<Vec<u32>> = mesh.to_polygons().faces().map(<[u32]>::to_vec).collect();
    assert_eq!(faces, [vec![0, 1, 2], vec![5, 3, 4]]);
    assert_eq!(mesh.stats().connected_components(), 2);
    // The split mesh is manifold: building it again changes nothing.
    let (again, warnings) = accepted(&mesh.to_polygons());
    assert!(warnings.is_empty());
    assert_eq!(again, mesh);

    // Two closed tetrahedra sharing their apex (two closed fans): two spheres.
    let tetrahedron = generate::unit_tetrahedron();
    let mut faces: Vec<Vec<u32>> = tetrahedron.faces().map(<[u32]>::to_vec).collect();
    faces.extend(tetrahedron.faces().map(|face| {
        face.iter()
            .map(|&x| if x == 0 { 0 } else { x + 3 })
            .collect()
    }));
    let (mesh, warnings) = accepted(&Polygons::from_faces(vec![Vec3::ZERO; 7], faces));
    assert_eq!(warnings, [split(0, &[7])]);
    let stats = mesh.stats();
    assert_eq!((stats.vertices, stats.edges, stats.faces), (8, 12, 8));
    assert!(stats.components.iter().all(|c| c.genus == Some(0)));
}

#[test]
fn splits_a_vertex_joining_three_fans_and_numbers_copies_by_vertex() {
    // Vertex 2 joins three fans (faces 0 and 3 share the edge 2–3, so they
    // are one), vertex 1 two; vertex 0 is unused. Vertex 1's copy comes
    // first (lower vertex), then vertex 2's two, in order of each fan's
    // first corner.
    let polygons = from_file(
        12,
        &[
            &[2, 3, 4],
            &[5, 2, 7],
            &[1, 8, 9],
            &[3, 2, 6],
            &[10, 11, 2],
            &[1, 11, 10],
        ],
    );
    let (mesh, warnings) = accepted(&polygons);
    assert_eq!(
        warnings,
        [
            split(1, &[12]),
            split(2, &[13, 14]),
            BuildWarning::UnusedVertex {
                vertex: VertexId::new(0)
            }
        ]
    );
    assert_eq!(
        warnings[1].to_string(),
        "vertex 2 joined 3 fans of faces; split into 2, 13 and 14"
    );
    assert_eq!(mesh.vertex_count(), 15);
    let faces: Vec<Vec<u32>> = mesh.to_polygons().faces().map(<[u32]>::to_vec).collect();
    assert_eq!(
        faces,
        [
            vec![2, 3, 4],
            vec![5, 13, 7],
            vec![1, 8, 9],
            vec![3, 2, 6],
            vec![10, 11, 14],
            vec![12, 11, 10]
        ]
    );
}

#[test]
fn a_vertex_split_does_not_hide_edge_refusals() {
    // Vertex 0 joins two fans, and the edge 3–4 has three faces, or the
    // faces on edge 3–4 disagree: the edge is refused as without the pinch.
    let (error, _) = refusal(&from_file(
        7,
        &[&[0, 1, 2], &[0, 3, 4], &[4, 3, 5], &[3, 4, 6]],
    ));
    assert!(matches!(error, BuildError::NonManifoldEdge { ref faces, .. } if faces.len() == 3));
    let (error, message) = refusal(&from_file(6, &[&[0, 1, 2], &[0, 3, 4], &[3, 4, 5]]));
    assert!(matches!(error, BuildError::InconsistentOrientation { .. }));
    assert_eq!(
        message,
        "face 1 (line 11) and face 2 (line 12) both go from vertex 3 to vertex 4; faces sharing an edge must \
         traverse it in opposite directions (inconsistent orientation: reverse one of them)"
    );
}

#[test]
fn keeps_unused_vertices_with_a_warning() {
    let polygons = from_file(5, &[&[0, 1, 3]]);
    let (mesh, warnings) = HalfEdgeMesh::build(&polygons).expect("build");
    assert_eq!(
        warnings,
        [
            BuildWarning::UnusedVertex {
                vertex: VertexId::new(2)
            },
            BuildWarning::UnusedVertex {
                vertex: VertexId::new(4)
            }
        ]
    );
    assert_eq!(
        warnings[1].to_string(),
        "vertex 4 is not used by any face; it is kept as an isolated vertex"
    );
    assert_eq!(mesh.vertex_count(), 5);
    assert_eq!(
        mesh.vertex(VertexId::new(4)).and_then(|v| v.incident_edge),
        None
    );
    assert_eq!(mesh.validate(), vec![]);
    let (winged, warnings_too) = WingedEdgeMesh::build(&polygons).expect("build");
    assert_eq!(warnings_too, warnings);
    assert_eq!(winged.stats().connected_components(), 3);
}

#[test]
fn empty_input_builds_an_empty_mesh() {
    let (mesh, warnings) = HalfEdgeMesh::build(&Polygons::new()).expect("build");
    assert!(warnings.is_empty());
    assert_eq!(
        (
            mesh.vertex_count(),
            mesh.half_edge_count(),
            mesh.face_count()
        ),
        (0, 0, 0)
    );
    assert_eq!(mesh.stats().euler_characteristic, 0);
    let (mesh, _) = WingedEdgeMesh::build(&Polygons::new()).expect("build");
    assert_eq!(mesh.to_half_edge().expect("convert").half_edge_count(), 0);
}

#[test]
fn tiny_tori_are_refused_not_panicked_on() {
    for (nu, nv) in [(1, 1), (1, 3), (2, 3), (3, 2), (0, 4)] {
        let polygons = generate::torus(nu, nv);
        let built = HalfEdgeMesh::build(&polygons);
        assert_eq!(
            built.is_ok(),
            polygons.face_count() == 0,
            "{nu}×{nv}: {built:?}"
        );
    }
}

// --------------------------------------------------------------- validate()

fn has(issues: &[Issue], element: Element, field: Column, text: &str) -> bool {
    issues.iter().any(|issue| {
        issue.element == element && issue.field == field && issue.message.contains(text)
    })
}

#[test]
fn validate_names_the_half_edge_field_at_fault() {
    let (mesh, _) = HalfEdgeMesh::build(&generate::unit_tetrahedron()).expect("build");
    let (vertices, faces, mut half_edges) = mesh.into_raw_parts();
    half_edges[0].pair_edge = HalfEdgeId::new(5);
    half_edges[7].successor_edge = HalfEdgeId::new(40);
    half_edges[9].end_vertex = VertexId::new(9);
    let broken = HalfEdgeMesh::from_raw_parts(vertices, faces, half_edges);
    let issues = broken.validate();
    assert!(
        has(
            &issues,
            Element::HalfEdge(HalfEdgeId::new(0)),
            Column::PairEdge,
            "pair(pair(h)) must be h"
        ),
        "{issues:#?}"
    );
    assert!(has(
        &issues,
        Element::HalfEdge(HalfEdgeId::new(7)),
        Column::SuccessorEdge,
        "half-edge 40 does not exist"
    ));
    assert!(has(
        &issues,
        Element::HalfEdge(HalfEdgeId::new(9)),
        Column::EndVertex,
        "vertex 9 does not exist"
    ));
    assert!(has(
        &issues,
        Element::Face(FaceId::new(2)),
        Column::IncidentEdge,
        "do not come back"
    ));
    assert_eq!(
        issues[0].to_string(),
        "half-edge 0 pair_edge: its pair edge half-edge 5 has half-edge 9 as pair edge, not this half-edge \
         (pair(pair(h)) must be h)"
    );
    // Nothing panics or loops on the broken tables.
    for v in 0..5 {
        assert!(broken.around_vertex(VertexId::new(v)).count() <= 12);
        assert!(broken.vertex_neighbours(VertexId::new(v)).count() <= 12);
    }
    for f in 0..5 {
        assert!(broken.face_vertices(FaceId::new(f)).count() <= 12);
    }
    assert!(broken.to_polygons().face_count() == 4);
    let _ = broken.stats();
    assert!(
        matches!(broken.to_winged_edge(), Err(ConvertError::Invalid(ref list)) if *list == issues)
    );
}

#[test]
fn validate_catches_wrong_incident_edges_and_duplicate_successors() {
    let (mesh, _) = HalfEdgeMesh::build(&generate::unit_tetrahedron()).expect("build");
    let (mut vertices, mut faces, mut half_edges) = mesh.into_raw_parts();
    vertices[1].incident_edge = Some(HalfEdgeId::new(0)); // half-edge 0 ends at vertex 2
    vertices[3].position = Vec3::new(f32::NAN, 0.0, 0.0);
    faces[1].incident_edge = HalfEdgeId::new(0); // lies in face 0
    half_edges[4].successor_edge = HalfEdgeId::new(3); // 3 is already 5's successor
    let issues = HalfEdgeMesh::from_raw_parts(vertices, faces, half_edges).validate();
    assert!(
        has(
            &issues,
            Element::Vertex(VertexId::new(1)),
            Column::IncidentEdge,
            "ends at vertex 2"
        ),
        "{issues:#?}"
    );
    assert!(has(
        &issues,
        Element::Vertex(VertexId::new(3)),
        Column::Position,
        "not a finite point"
    ));
    assert!(has(
        &issues,
        Element::Face(FaceId::new(1)),
        Column::IncidentEdge,
        "lies in face 0"
    ));
    assert!(has(
        &issues,
        Element::HalfEdge(HalfEdgeId::new(5)),
        Column::SuccessorEdge,
        "already the successor"
    ));
}

#[test]
fn validate_names_the_winged_edge_wing_at_fault() {
    let (mesh, _) = WingedEdgeMesh::build(&generate::unit_tetrahedron()).expect("build");
    let (vertices, faces, mut edges) = mesh.into_raw_parts();
    // Swap edge 0's left wings: the predecessor and successor are now wrong.
    let edge = &mut edges[0];
    std::mem::swap(&mut edge.left_predecessor, &mut edge.left_successor);
    let issues = WingedEdgeMesh::from_raw_parts(vertices.clone(), faces.clone(), edges).validate();
    let zero = Element::Edge(EdgeId::new(0));
    assert!(
        has(
            &issues,
            zero,
            Column::LeftPredecessor,
            "the wings must agree"
        ),
        "{issues:#?}"
    );
    assert!(has(
        &issues,
        zero,
        Column::LeftSuccessor,
        "the wings must agree"
    ));
    assert!(has(
        &issues,
        zero,
        Column::LeftPredecessor,
        "going clockwise around face 0"
    ));

    // A right face that is not the face its wings run around.
    let (_, _, mut edges) = WingedEdgeMesh::build(&generate::unit_tetrahedron())
        .expect("build")
        .0
        .into_raw_parts();
    edges[3].right_face = Some(FaceId::new(7));
    let issues = WingedEdgeMesh::from_raw_parts(vertices.clone(), faces.clone(), edges).validate();
    assert!(
        has(
            &issues,
            Element::Edge(EdgeId::new(3)),
            Column::RightFace,
            "face 7 does not exist"
        ),
        "{issues:#?}"
    );
    assert!(has(
        &issues,
        Element::Edge(EdgeId::new(3)),
        Column::RightPredecessor,
        "does not border face 7"
    ));

    // Incident edges.
    let (mut vertices, mut faces, edges) = WingedEdgeMesh::build(&generate::unit_tetrahedron())
        .expect("build")
        .0
        .into_raw_parts();
    vertices[0].incident_edge = None;
    faces[2] = winged_edge::Face {
        incident_edge: EdgeId::new(99),
    };
    let broken = WingedEdgeMesh::from_raw_parts(vertices, faces, edges);
    let issues = broken.validate();
    assert!(has(
        &issues,
        Element::Vertex(VertexId::new(0)),
        Column::IncidentEdge,
        "no incident edge, but 3 edges"
    ));
    assert!(has(
        &issues,
        Element::Face(FaceId::new(2)),
        Column::IncidentEdge,
        "edge 99 does not exist"
    ));
    assert_eq!(broken.around_face(FaceId::new(2)).count(), 0);
    assert!(matches!(
        broken.to_half_edge(),
        Err(ConvertError::Invalid(_))
    ));
}

#[test]
fn validate_reports_a_pinched_vertex_in_tables() {
    // Two triangles sharing only vertex 0, written as tables by hand: each
    // table is locally fine, but the loop around vertex 0 misses a fan.
    let positions = [Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::NEG_X, Vec3::NEG_Y];
    let mut polygons = Polygons::new();
    for p in positions {
        polygons.push_vertex(p);
    }
    polygons.push_face(&[0, 1, 2]);
    let (first, _) = HalfEdgeMesh::build(&polygons).expect("one triangle");
    let (mut vertices, mut faces, mut half_edges) = first.into_raw_parts();
    // Append a second triangle 0, 3, 4 with its own boundary, offset by 6.
    let offset = |h: HalfEdgeId| HalfEdgeId::new(h.raw() + 6);
    let copy: Vec<half_edge::HalfEdge> = half_edges.clone();
    for h in copy {
        let end = match h.end_vertex.raw() {
            0 => 0,
            v => v + 2,
        };
        half_edges.push(half_edge::HalfEdge {
            end_vertex: VertexId::new(end),
            face: h.face.map(|_| FaceId::new(1)),
            pair_edge: offset(h.pair_edge),
            successor_edge: offset(h.successor_edge),
        });
    }
    faces.push(half_edge::Face {
        incident_edge: HalfEdgeId::new(6),
    });
    vertices[3] = half_edge::Vertex {
        position: positions[3],
        incident_edge: Some(HalfEdgeId::new(6)),
    };
    vertices[4] = half_edge::Vertex {
        position: positions[4],
        incident_edge: Some(HalfEdgeId::new(7)),
    };
    let pinched = HalfEdgeMesh::from_raw_parts(vertices, faces, half_edges);
    let issues = pinched.validate();
    assert_eq!(issues.len(), 1, "{issues:#?}");
    assert_eq!(issues[0].element, Element::Vertex(VertexId::new(0)));
    assert_eq!(issues[0].field, Column::IncidentEdge);
    assert!(
        issues[0]
            .message
            .contains("reaches 2 of the 4 half-edges ending here"),
        "{}",
        issues[0]
    );
    assert!(matches!(
        pinched.to_winged_edge(),
        Err(ConvertError::Invalid(_))
    ));
}
