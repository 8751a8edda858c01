//! The local operations on both structures: every operation on every
//! sample and every element where it applies, checked against the
//! validator and its count formula; each refusal's message; the Euler
//! operators undoing each other; journals reverting; and random sequences of
//! operations (proptest).

use crate::golden;

use std::path::PathBuf;

use edgewise_core::formats;
use edgewise_core::mesh::operations::candidates::{boundary_vertices, edges_at, face_vertices};
use edgewise_core::mesh::operations::{self, Operation, Refusal};
use edgewise_core::mesh::{
    EdgeId, Edit, FaceId, HalfEdgeId, Mesh, MeshStats, Navigation, Polygons, Structure, VertexId,
    WingedEdgeMesh, generate,
};
use edgewise_core::schema::{Column, ElementKind, ElementRef, Records, RecordsMut};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// A sample in both structures: the same vertex and face numbers, and
/// each winged edge's first half-edge (the one running from its start to
/// its end, as the winged edge's left side does).
pub(crate) struct Sample {
    pub(crate) name: String,
    pub(crate) winged: Mesh,
    pub(crate) half: Mesh,
    first_halves: Vec<u32>,
}

impl Sample {
    fn new(name: &str, winged: WingedEdgeMesh) -> Self {
        let (half, correspondence) = winged
            .to_half_edge_with_correspondence()
            .expect("a sample converts");
        let first_halves = (0..winged.edge_count() as u32)
            .map(|e| {
                correspondence
                    .half_edges(EdgeId::new(e))
                    .expect("every edge has half-edges")
                    .0
                    .raw()
            })
            .collect();
        Self {
            name: name.to_owned(),
            winged: Mesh::Winged(winged),
            half: Mesh::Half(half),
            first_halves,
        }
    }

    /// The half-edge mesh's ids for the winged-edge mesh's `ids`.
    pub(crate) fn half_ids(&self, op: Operation, ids: &[u32]) -> Vec<u32> {
        ids.iter()
            .zip(op.arguments())
            .map(|(&id, argument)| match argument.kind {
                ElementKind::Edge => self.first_halves[id as usize],
                _ => id,
            })
            .collect()
    }
}

/// The generated fixtures and the small sample files.
pub(crate) fn samples() -> Vec<Sample> {
    let mut list = Vec::new();
    let generated: [(&str, Polygons); 8] = [
        ("tetrahedron", generate::tetrahedron()),
        ("unit-tetrahedron", generate::unit_tetrahedron()),
        ("regular-tetrahedron", generate::regular_tetrahedron()),
        ("cube", generate::cube()),
        ("cube-zyx", generate::cube_zyx()),
        ("open-square", generate::open_square()),
        ("grid-3x2", generate::grid(3, 2)),
        ("torus-4x3", generate::torus(4, 3)),
    ];
    for (name, polygons) in generated {
        let (mesh, _) = WingedEdgeMesh::build(&polygons).expect("a fixture builds");
        list.push(Sample::new(name, mesh));
    }
    list.push(Sample::new("table-2", generate::table_2()));
    let mut files: Vec<String> = std::fs::read_dir(root().join("meshes"))
        .expect("meshes/")
        .map(|entry| {
            entry
                .expect("entry")
                .file_name()
                .to_string_lossy()
                .into_owned()
        })
        .filter(|name| !name.ends_with(".md") && !name.starts_with("icosphere-20k"))
        .collect();
    files.sort();
    for name in files {
        let bytes = std::fs::read(root().join("meshes").join(&name)).expect("sample");
        let loaded = formats::load(&bytes, &name, Structure::WingedEdge).expect("a sample loads");
        let Mesh::Winged(mesh) = loaded.mesh else {
            panic!("{name} did not load as winged-edge");
        };
        list.push(Sample::new(&name, mesh));
    }
    list
}

fn edge_rows(mesh: &Mesh) -> u32 {
    mesh.count(ElementKind::Edge) as u32
}

/// The faces beside an edge row (the first half's, then the second's),
/// each with its number of edges.
fn sides(mesh: &Mesh, edge: u32) -> [Option<(FaceId, usize)>; 2] {
    match mesh {
        Mesh::Winged(m) => {
            let edge = m.edges()[edge as usize];
            [edge.left_face, edge.right_face].map(|f| f.map(|f| (f, m.around_face(f).count())))
        }
        Mesh::Half(m) => {
            let h = m.half_edges()[edge as usize];
            let pair = m.half_edges()[h.pair_edge.index()];
            [h.face, pair.face].map(|f| f.map(|f| (f, m.around_face(f).count())))
        }
    }
}

fn triangles_beside(mesh: &Mesh, edge: u32) -> i64 {
    sides(mesh, edge)
        .iter()
        .filter(|side| side.is_some_and(|(_, n)| n == 3))
        .count() as i64
}

fn valence(mesh: &Mesh, v: VertexId) -> i64 {
    match mesh {
        Mesh::Winged(m) => m.around_vertex(v).count() as i64,
        Mesh::Half(m) => m.around_vertex(v).count() as i64,
    }
}

/// V, E, F and boundary loops.
fn counts(stats: &MeshStats) -> [i64; 4] {
    [
        stats.vertices as i64,
        stats.edges as i64,
        stats.faces as i64,
        stats.boundary_loops as i64,
    ]
}

/// The change an operation must make to the counts, from the mesh before.
fn expected_delta(mesh: &Mesh, op: Operation, ids: &[u32]) -> [i64; 4] {
    if let Some(delta) = op.delta() {
        return [
            delta.vertices,
            delta.edges,
            delta.faces,
            delta.boundary_loops,
        ];
    }
    match op {
        Operation::SplitEdge => {
            let k = triangles_beside(mesh, ids[0]);
            [1, 1 + k, k, 0]
        }
        Operation::CollapseEdge => {
            let k = triangles_beside(mesh, ids[0]);
            [-1, -1 - k, -k, 0]
        }
        Operation::RemoveVertex => {
            let k = valence(mesh, VertexId::new(ids[0]));
            [-1, -k, 1 - k, 0]
        }
        _ => unreachable!("{op} has a fixed delta"),
    }
}

/// Every component with faces keeps V − E + F = 2 − 2g − b with g ≥ 0.
fn assert_euler(stats: &MeshStats, context: &str) {
    for c in &stats.components {
        let twice_genus = 2 - c.euler_characteristic - c.boundary_loops as i64;
        assert!(
            c.faces == 0 || (twice_genus >= 0 && twice_genus % 2 == 0),
            "{context}: component from {} has χ {} and {} boundary loops",
            c.first_vertex,
            c.euler_characteristic,
            c.boundary_loops
        );
    }
}

/// Applies `op` to a copy of `mesh`. Accepted: the result validates before
/// and after compacting, the counts change by the formula, the Euler
/// relation holds, and reverting the journal restores `mesh` exactly.
/// Refused: the copy is untouched. Returns the compacted result.
fn check(name: &str, mesh: &Mesh, op: Operation, ids: &[u32]) -> Result<Mesh, Refusal> {
    let context = format!("{name}: {op} {ids:?}");
    let mut edited = mesh.clone();
    let applied = match operations::apply(&mut edited, op, ids) {
        Ok(applied) => applied,
        Err(refusal) => {
            assert!(
                &edited == mesh,
                "{context}: refused ({refusal}) but changed the mesh"
            );
            return Err(refusal);
        }
    };
    let issues = edited.validate();
    assert!(
        issues.is_empty(),
        "{context}: before compacting: {issues:#?}"
    );
    let mut reverted = edited.clone();
    for change in applied.journal.iter().rev() {
        change.revert(&mut reverted).expect("a change reverts");
    }
    assert!(&reverted == mesh, "{context}: the journal does not revert");
    let mut compacted = edited;
    compacted.compact();
    let issues = compacted.validate();
    assert!(
        issues.is_empty(),
        "{context}: after compacting: {issues:#?}"
    );
    let (before, after) = (mesh.stats(), compacted.stats());
    let change: Vec<i64> = counts(&before)
        .iter()
        .zip(counts(&after))
        .map(|(b, a)| a - b)
        .collect();
    assert_eq!(
        change,
        expected_delta(mesh, op, ids),
        "{context}: V, E, F, loops"
    );
    assert_euler(&after, &context);
    Ok(compacted)
}

/// Every `step`-th item, so the large samples are sampled, not exhausted.
fn every<T>(items: Vec<T>, step: usize) -> impl Iterator<Item = T> {
    items.into_iter().step_by(step.max(1))
}

/// Every argument list `op` takes on `mesh`, thinned to about `budget`.
pub(crate) fn arguments(mesh: &Mesh, op: Operation, budget: usize) -> Vec<Vec<u32>> {
    let all = operations::candidates(mesh, op);
    let step = all.len().div_ceil(budget.max(1));
    every(all, step).collect()
}

/// The faces as vertex lists, each turned to start at its least rotation,
/// in order, with the positions: what two structures' meshes share. The
/// face numbers may differ, as operations keep the face an incident edge is
/// on and the structures pick incident edges differently.
fn shape(mesh: &Mesh) -> (Vec<Vec<u32>>, Vec<[u32; 3]>) {
    let mut faces: Vec<Vec<u32>> = (0..mesh.face_count() as u32)
        .map(|f| {
            let corners = face_vertices(mesh, FaceId::new(f));
            (0..corners.len())
                .map(|turn| {
                    let mut turned = corners.clone();
                    turned.rotate_left(turn);
                    turned
                })
                .min()
                .unwrap_or_default()
        })
        .collect();
    faces.sort();
    let positions = mesh
        .positions()
        .iter()
        .map(|p| p.to_array().map(f32::to_bits))
        .collect();
    (faces, positions)
}

#[test]
fn every_operation_on_every_sample_validates_and_keeps_its_formula() {
    let mut accepted = vec![0usize; Operation::ALL.len()];
    let mut refused = vec![0usize; Operation::ALL.len()];
    for sample in samples() {
        let name = &sample.name;
        assert_eq!(sample.winged.validate(), vec![], "{name}");
        let small = sample.winged.edge_count() <= 100;
        for (i, op) in Operation::ALL.into_iter().enumerate() {
            let budget = if small { 300 } else { 40 };
            for ids in arguments(&sample.winged, op, budget) {
                let winged = check(&format!("{name} (winged)"), &sample.winged, op, &ids);
                let half_ids = sample.half_ids(op, &ids);
                let half = check(&format!("{name} (half)"), &sample.half, op, &half_ids);
                match (winged, half) {
                    (Ok(winged), Ok(half)) => {
                        assert!(
                            shape(&winged) == shape(&half),
                            "{name}: {op} {ids:?} makes different meshes in the two structures"
                        );
                        accepted[i] += 1;
                    }
                    (Err(_), Err(_)) => refused[i] += 1,
                    (winged, half) => panic!(
                        "{name}: {op} {ids:?}: winged-edge {:?}, half-edge {:?}",
                        winged.map(drop),
                        half.map(drop)
                    ),
                }
            }
            // A half-edge mesh also names each edge by its second half,
            // which runs the other way.
            if op.arguments() == Operation::FlipEdge.arguments() {
                let seconds: Vec<u32> = sample
                    .first_halves
                    .iter()
                    .map(|&h| {
                        sample
                            .half
                            .reference(ElementRef::new(ElementKind::Edge, h), Column::PairEdge)
                    })
                    .map(|pair| pair.expect("exists").expect("paired").id)
                    .collect();
                let step = seconds.len().div_ceil(budget);
                for second in every(seconds, step) {
                    let _ = check(&format!("{name} (half)"), &sample.half, op, &[second]);
                }
            }
        }
    }
    for (i, op) in Operation::ALL.into_iter().enumerate() {
        eprintln!("{op}: {} accepted, {} refused", accepted[i], refused[i]);
        // KEMR needs a bridge, which no sample has (see the MEKR tests).
        if op != Operation::Kemr {
            assert!(accepted[i] > 0, "{op} was never accepted");
        }
    }
}

// ------------------------------------------------------------ Euler pairs

/// Small samples in both structures.
fn small_meshes() -> Vec<(String, Mesh)> {
    let mut list = Vec::new();
    for sample in samples() {
        if sample.winged.edge_count() <= 40 {
            list.push((format!("{} (winged)", sample.name), sample.winged));
            list.push((format!("{} (half)", sample.name), sample.half));
        }
    }
    list
}

/// The first edge row an operation made.
fn made_edge(applied: &operations::Applied) -> u32 {
    applied
        .made
        .iter()
        .find(|row| row.kind == ElementKind::Edge)
        .expect("the operation made an edge")
        .id
}

/// Applies `op` and then `inverse` on the edge it made: once compacted, the
/// tables are the ones it started from. Returns how many pairs it checked.
fn assert_undone(name: &str, mesh: &Mesh, op: Operation, inverse: Operation) -> usize {
    let mut checked = 0;
    for ids in arguments(mesh, op, 200) {
        let mut edited = mesh.clone();
        let Ok(applied) = operations::apply(&mut edited, op, &ids) else {
            continue;
        };
        let edge = made_edge(&applied);
        if let Err(refusal) = operations::apply(&mut edited, inverse, &[edge]) {
            panic!("{name}: {inverse} {edge} after {op} {ids:?} was refused: {refusal}");
        }
        edited.compact();
        assert!(
            &edited == mesh,
            "{name}: {inverse} {edge} does not undo {op} {ids:?}"
        );
        checked += 1;
    }
    checked
}

#[test]
fn mev_then_kev_restores_the_tables() {
    let checked: usize = small_meshes()
        .iter()
        .map(|(name, mesh)| assert_undone(name, mesh, Operation::Mev, Operation::Kev))
        .sum();
    assert!(checked > 500, "{checked}");
}

#[test]
fn mef_then_kef_restores_the_tables() {
    let checked: usize = small_meshes()
        .iter()
        .map(|(name, mesh)| assert_undone(name, mesh, Operation::Mef, Operation::Kef))
        .sum();
    assert!(checked > 100, "{checked}");
}

#[test]
fn mekr_then_kemr_restores_the_tables_and_kemr_then_mekr_too() {
    let mut checked = 0;
    for (name, mesh) in small_meshes() {
        checked += assert_undone(&name, &mesh, Operation::Mekr, Operation::Kemr);
        for ids in arguments(&mesh, Operation::Mekr, 40) {
            let mut bridged = mesh.clone();
            let Ok(applied) = operations::apply(&mut bridged, Operation::Mekr, &ids) else {
                continue;
            };
            bridged.compact();
            // KEMR on the bridge, then MEKR with the same face and ends.
            let bridge = made_edge(&applied);
            let mut edited = bridged.clone();
            operations::apply(&mut edited, Operation::Kemr, &[bridge]).expect("a bridge");
            operations::apply(&mut edited, Operation::Mekr, &ids).expect("the ring is back");
            edited.compact();
            assert!(
                edited == bridged,
                "{name}: MEKR {ids:?} does not undo KEMR {bridge}"
            );
            checked += 1;
        }
    }
    assert!(checked > 50, "{checked}");
}

#[test]
fn kemr_turns_the_inner_cycle_into_a_boundary_loop() {
    // A 5 × 5 grid without its middle square: face 0 is bridged from its
    // corner 7 to vertex 14, a corner of the hole.
    let grid = generate::grid(5, 5);
    let faces: Vec<Vec<u32>> = grid
        .faces()
        .enumerate()
        .filter(|&(f, _)| f != 12)
        .map(|(_, face)| face.to_vec())
        .collect();
    let polygons = Polygons::from_faces(grid.positions().to_vec(), faces);
    for structure in Structure::ALL {
        let (mut mesh, _) = Mesh::build(&polygons, structure).expect("a grid with a hole");
        let before = mesh.stats();
        assert_eq!(before.boundary_loops, 2);
        let applied = operations::apply(&mut mesh, Operation::Mekr, &[0, 7, 14]).expect("joins");
        assert_eq!(mesh.validate(), vec![]);
        assert_eq!(mesh.stats().boundary_loops, 1);
        // The face walks out along the bridge, round the hole and back.
        let mut corners = face_vertices(&mesh, FaceId::new(0));
        let at = corners.iter().position(|&v| v == 0).expect("corner 0");
        corners.rotate_left(at);
        assert_eq!(
            corners,
            [0, 1, 7, 14, 15, 21, 20, 14, 7, 6],
            "{structure:?}"
        );
        let bridge = made_edge(&applied);
        let killed = operations::apply(&mut mesh, Operation::Kemr, &[bridge]).expect("a bridge");
        assert_eq!(mesh.validate(), vec![]);
        assert_eq!(
            killed.deleted.len(),
            killed
                .journal
                .iter()
                .filter(|c| matches!(c, edgewise_core::mesh::Change::Delete(_)))
                .count()
        );
        mesh.compact();
        assert_eq!(mesh.stats(), before);
    }
}

// ------------------------------------------------------------ refusals

fn build(polygons: &Polygons, structure: Structure) -> Mesh {
    Mesh::build(polygons, structure).expect("builds").0
}

fn corners(count: usize) -> Vec<glam::Vec3> {
    (0..count)
        .map(|i| glam::Vec3::new(i as f32, (i * i % 5) as f32, (i % 3) as f32))
        .collect()
}

/// Two triangles on the same three vertices, glued along every edge.
fn dihedron() -> Polygons {
    Polygons::from_triangles(corners(3), &[[0, 1, 2], [1, 0, 2]])
}

/// A quad on one side, two triangles on the other, meeting along 0–2.
fn quad_pillow() -> Polygons {
    Polygons::from_faces(corners(4), [vec![0, 1, 2, 3], vec![0, 3, 2], vec![0, 2, 1]])
}

/// Two tetrahedra glued along triangle 2 3 4, which is not a face: 0 is the
/// top, 1 the bottom.
fn bipyramid() -> Polygons {
    Polygons::from_triangles(
        corners(5),
        &[
            [0, 2, 3],
            [0, 3, 4],
            [0, 4, 2],
            [1, 3, 2],
            [1, 4, 3],
            [1, 2, 4],
        ],
    )
}

/// The 5 × 5 grid without its middle square (face 12).
fn grid_with_hole() -> Polygons {
    let grid = generate::grid(5, 5);
    let faces: Vec<Vec<u32>> = grid
        .faces()
        .enumerate()
        .filter(|&(f, _)| f != 12)
        .map(|(_, face)| face.to_vec())
        .collect();
    Polygons::from_faces(grid.positions().to_vec(), faces)
}

/// The edge row running from `a` to `b`: the half-edge, or the winged edge
/// joining them.
fn edge_between(mesh: &Mesh, a: u32, b: u32) -> u32 {
    match mesh {
        Mesh::Winged(m) => m
            .edges()
            .iter()
            .position(|e| {
                let ends = [e.start_vertex.raw(), e.end_vertex.raw()];
                ends == [a, b] || ends == [b, a]
            })
            .expect("an edge joins them") as u32,
        Mesh::Half(m) => m
            .half_edges()
            .iter()
            .enumerate()
            .position(|(h, half)| {
                half.end_vertex.raw() == b
                    && m.start_vertex(HalfEdgeId::new(h as u32)) == Some(VertexId::new(a))
            })
            .expect("a half-edge runs from a to b") as u32,
    }
}

/// `mesh` after an operation that must be accepted, and what it made.
fn after(mesh: &Mesh, op: Operation, ids: &[u32]) -> (Mesh, u32) {
    let mut edited = mesh.clone();
    let applied = operations::apply(&mut edited, op, ids).expect("the set-up is accepted");
    let made = applied
        .made
        .iter()
        .find(|row| row.kind == ElementKind::Edge)
        .map_or(0, |row| row.id);
    (edited, made)
}

/// `mesh` with a dangling edge from vertex 0 into the face after its
/// incident edge's dart; returns it, the dangling edge and that face.
fn with_dangling_edge(mesh: &Mesh) -> (Mesh, u32, u32) {
    let first = edges_at(mesh, VertexId::new(0))[0];
    let (mesh, edge) = after(mesh, Operation::Mev, &[0, first]);
    let face = sides(&mesh, edge)[0].expect("in a face").0.raw();
    (mesh, edge, face)
}

/// The variant's name, for the golden file; the match is exhaustive so a
/// new variant must be added here and to [`VARIANTS`].
fn variant(refusal: &Refusal) -> &'static str {
    match refusal {
        Refusal::Arguments { .. } => "Arguments",
        Refusal::NoSuchElement(_) => "NoSuchElement",
        Refusal::Deleted(_) => "Deleted",
        Refusal::Broken { .. } => "Broken",
        Refusal::OnBoundary { .. } => "OnBoundary",
        Refusal::SameFaceOnBothSides { .. } => "SameFaceOnBothSides",
        Refusal::NotTriangle { .. } => "NotTriangle",
        Refusal::SharedCorner { .. } => "SharedCorner",
        Refusal::EdgeExists { .. } => "EdgeExists",
        Refusal::LinkCondition { .. } => "LinkCondition",
        Refusal::BoundaryPinch { .. } => "BoundaryPinch",
        Refusal::MergedEdge { .. } => "MergedEdge",
        Refusal::TooSmall { .. } => "TooSmall",
        Refusal::FaceTooSmall { .. } => "FaceTooSmall",
        Refusal::NoFaceEither { .. } => "NoFaceEither",
        Refusal::OnlyDangling { .. } => "OnlyDangling",
        Refusal::PinchesVertex { .. } => "PinchesVertex",
        Refusal::NotOnFace { .. } => "NotOnFace",
        Refusal::PassesTwice { .. } => "PassesTwice",
        Refusal::SameVertex { .. } => "SameVertex",
        Refusal::AdjacentOnFace { .. } => "AdjacentOnFace",
        Refusal::BoundaryVertex { .. } => "BoundaryVertex",
        Refusal::IsolatedVertex { .. } => "IsolatedVertex",
        Refusal::NotSimple { .. } => "NotSimple",
        Refusal::NotAtVertex { .. } => "NotAtVertex",
        Refusal::CornerOnBoundary { .. } => "CornerOnBoundary",
        Refusal::BothCornersOnBoundary { .. } => "BothCornersOnBoundary",
        Refusal::NotBridge { .. } => "NotBridge",
        Refusal::Dangling { .. } => "Dangling",
        Refusal::NotOnBoundary { .. } => "NotOnBoundary",
        Refusal::SeveralBoundaries { .. } => "SeveralBoundaries",
        Refusal::EditFailed(_) => "EditFailed",
        Refusal::Numbering { .. } => "Numbering",
    }
}

const VARIANTS: [&str; 33] = [
    "Arguments",
    "NoSuchElement",
    "Deleted",
    "Broken",
    "OnBoundary",
    "SameFaceOnBothSides",
    "NotTriangle",
    "SharedCorner",
    "EdgeExists",
    "LinkCondition",
    "BoundaryPinch",
    "MergedEdge",
    "TooSmall",
    "FaceTooSmall",
    "NoFaceEither",
    "OnlyDangling",
    "PinchesVertex",
    "NotOnFace",
    "PassesTwice",
    "SameVertex",
    "AdjacentOnFace",
    "BoundaryVertex",
    "IsolatedVertex",
    "NotSimple",
    "NotAtVertex",
    "CornerOnBoundary",
    "BothCornersOnBoundary",
    "NotBridge",
    "Dangling",
    "NotOnBoundary",
    "SeveralBoundaries",
    "EditFailed",
    "Numbering",
];

/// Every refusal, each from a real operation on a real mesh where one can
/// reach it, rendered into tests/golden/operations/refusals.txt
/// (`EDGEWISE_BLESS=1` rewrites it). A refused operation must leave the
/// mesh untouched.
#[test]
fn every_refusal_has_a_golden_message() {
    use Operation as Op;
    use Structure::{HalfEdge as Half, WingedEdge as Winged};
    let tetrahedron = |s| build(&generate::tetrahedron(), s);
    let cube = |s| build(&generate::cube(), s);
    let open_square = |s| build(&generate::open_square(), s);
    let octahedron = |s| {
        let bytes = std::fs::read(root().join("meshes/octahedron.obj")).expect("sample");
        formats::load(&bytes, "octahedron.obj", s)
            .expect("loads")
            .mesh
    };

    let mut cases: Vec<(String, Mesh, Operation, Vec<u32>)> = Vec::new();
    let mut case = |label: &str, mesh: Mesh, op: Operation, ids: &[u32]| {
        let structure = match mesh.structure() {
            Winged => "winged",
            Half => "half",
        };
        cases.push((format!("{label} ({structure})"), mesh, op, ids.to_vec()));
    };

    case("tetrahedron", tetrahedron(Winged), Op::FlipEdge, &[0, 1]);
    case("tetrahedron", tetrahedron(Half), Op::Mev, &[0]);
    case("tetrahedron", tetrahedron(Winged), Op::RemoveVertex, &[12]);
    case("tetrahedron", tetrahedron(Half), Op::Kev, &[30]);
    case(
        "tetrahedron",
        tetrahedron(Winged),
        Op::SplitFace,
        &[9, 0, 1],
    );
    let (collapsed, _) = after(&octahedron(Half), Op::CollapseEdge, &[0]);
    case(
        "octahedron after collapse-edge 0",
        collapsed,
        Op::FlipEdge,
        &[1],
    );
    let mut broken = tetrahedron(Half);
    broken
        .set_reference(
            ElementRef::new(ElementKind::Edge, 1),
            Column::SuccessorEdge,
            Some(ElementRef::new(ElementKind::Edge, 99)),
        )
        .expect("a stored column");
    case(
        "tetrahedron, half-edge 1's successor 99",
        broken,
        Op::FlipEdge,
        &[0],
    );
    case("open square", open_square(Winged), Op::FlipEdge, &[0]);
    case("open square", open_square(Half), Op::Kef, &[0]);
    for structure in [Winged, Half] {
        let (dangling, edge, _) = with_dangling_edge(&cube(structure));
        case(
            "cube with a dangling edge",
            dangling.clone(),
            Op::FlipEdge,
            &[edge],
        );
        case(
            "cube with a dangling edge",
            dangling.clone(),
            Op::Kef,
            &[edge],
        );
        case(
            "cube with a dangling edge",
            dangling.clone(),
            Op::CollapseEdge,
            &[edge],
        );
        case("cube with a dangling edge", dangling, Op::Kemr, &[edge]);
    }
    let (bridged, bridge) = after(&build(&grid_with_hole(), Half), Op::Mekr, &[0, 7, 14]);
    case(
        "holed grid bridged by mekr 0 7 14",
        bridged.clone(),
        Op::Kev,
        &[bridge],
    );
    let along_hole = edge_between(&bridged, 14, 15);
    let (strut_inside, _) = after(&bridged, Op::Mev, &[15, along_hole]);
    case(
        "holed grid bridged, with an edge dangling from 15",
        strut_inside,
        Op::Kemr,
        &[bridge],
    );
    // A path of three dangling edges from vertex 0; removing the first,
    // named from its far end, would leave the face walking only the path.
    let (path, first) = after(&octahedron(Half), Op::Mev, &[0, 0]);
    let (path, second) = after(&path, Op::Mev, &[6, first]);
    let (path, _) = after(&path, Op::Mev, &[7, second]);
    case(
        "octahedron with a dangling path from 0",
        path,
        Op::Kemr,
        &[first + 1],
    );
    // A bridge from hole corner 14 to the outer boundary at 1: named from
    // 1, its inner cycle is face 6, which passes the hole at 14.
    let (bridged, bridge) = after(&build(&grid_with_hole(), Half), Op::Mekr, &[6, 14, 1]);
    case(
        "holed grid bridged by mekr 6 14 1",
        bridged,
        Op::Kemr,
        &[bridge + 1],
    );
    case("cube", cube(Winged), Op::FlipEdge, &[0]);
    case("dihedron", build(&dihedron(), Winged), Op::FlipEdge, &[0]);
    case("dihedron", build(&dihedron(), Half), Op::SplitEdge, &[0]);
    case("tetrahedron", tetrahedron(Winged), Op::FlipEdge, &[0]);
    case("tetrahedron", tetrahedron(Half), Op::FlipEdge, &[0]);
    case(
        "quad pillow",
        build(&quad_pillow(), Half),
        Op::SplitFace,
        &[0, 0, 2],
    );
    case("open square", open_square(Winged), Op::Mekr, &[0, 0, 3]);
    let pyramid = build(&bipyramid(), Winged);
    let equator = edge_between(&pyramid, 2, 3);
    case("bipyramid", pyramid, Op::CollapseEdge, &[equator]);
    let strip = build(&generate::grid(3, 1), Half);
    let rung = edge_between(&strip, 1, 5);
    case("3 × 1 grid", strip, Op::CollapseEdge, &[rung]);
    let strip = build(&generate::grid(3, 1), Winged);
    let rung = edge_between(&strip, 1, 5);
    case("3 × 1 grid", strip, Op::Kev, &[rung]);
    let triangle = Polygons::from_triangles(corners(3), &[[0, 1, 2]]);
    case(
        "one triangle",
        build(&triangle, Winged),
        Op::CollapseEdge,
        &[0],
    );
    case("dihedron", build(&dihedron(), Half), Op::CollapseEdge, &[0]);
    case("tetrahedron", tetrahedron(Winged), Op::CollapseEdge, &[0]);
    case("tetrahedron", tetrahedron(Half), Op::RemoveVertex, &[0]);
    case("tetrahedron", tetrahedron(Winged), Op::Kev, &[0]);
    case("cube", cube(Half), Op::SplitFace, &[0, 0, 7]);
    let (dangling, _, face) = with_dangling_edge(&cube(Winged));
    let far = face_vertices(&dangling, FaceId::new(face))
        .into_iter()
        .find(|&v| v != 0)
        .expect("another corner");
    case(
        "cube with a dangling edge",
        dangling,
        Op::SplitFace,
        &[face, 0, far],
    );
    case("cube", cube(Winged), Op::SplitFace, &[0, 0, 0]);
    case("cube", cube(Half), Op::SplitFace, &[0, 0, 2]);
    case("tetrahedron", tetrahedron(Winged), Op::Mef, &[0, 0, 1]);
    case("open square", open_square(Winged), Op::RemoveVertex, &[0]);
    let mut lonely = Polygons::from_triangles(corners(3), &[[0, 1, 2]]);
    lonely.push_vertex(glam::Vec3::ONE);
    case(
        "a triangle and a lone vertex",
        build(&lonely, Half),
        Op::RemoveVertex,
        &[3],
    );
    let pillow = build(&quad_pillow(), Winged);
    let shared = edge_between(&pillow, 0, 1);
    case("quad pillow", pillow, Op::Kef, &[shared]);
    case("open square", open_square(Half), Op::Mekr, &[0, 1, 3]);
    let far_edge = edge_between(&cube(Winged), 6, 7);
    case("cube", cube(Winged), Op::Mev, &[0, far_edge]);
    let square = open_square(Half);
    let rim = edge_between(&square, 1, 2);
    case("open square", square, Op::Mev, &[1, rim]);
    case("cube", cube(Winged), Op::Kemr, &[0]);
    case(
        "2 × 2 grid",
        build(&generate::grid(2, 2), Winged),
        Op::Mekr,
        &[0, 0, 4],
    );

    let mut lines = vec![
        "# Every refusal of the local operations: the variant, what was asked, and the".to_owned(),
        "# message. Written by crates/core/tests/it/mesh_operations.rs (EDGEWISE_BLESS=1)."
            .to_owned(),
    ];
    let mut seen = std::collections::BTreeSet::new();
    for (label, mesh, op, ids) in cases {
        let mut edited = mesh.clone();
        let Err(refusal) = operations::apply(&mut edited, op, &ids) else {
            panic!("{label}: {op} {ids:?} was accepted");
        };
        assert!(edited == mesh, "{label}: the refusal changed the mesh");
        let ids: Vec<String> = ids.iter().map(ToString::to_string).collect();
        lines.push(format!(
            "{}: {label}: {op} {}: {refusal}",
            variant(&refusal),
            ids.join(" ")
        ));
        seen.insert(variant(&refusal));
    }
    // No operation on a mesh that validates reaches these: a vertex where
    // the boundary passes twice, or a failure while writing.
    let constructed = [
        Refusal::BothCornersOnBoundary {
            vertex: VertexId::new(4),
        },
        Refusal::SeveralBoundaries {
            vertex: VertexId::new(4),
            count: 2,
        },
        Refusal::EditFailed(edgewise_core::mesh::EditError::TableFull(
            ElementKind::Vertex,
        )),
        Refusal::Numbering {
            planned: ElementRef::new(ElementKind::Face, 6),
            made: ElementRef::new(ElementKind::Face, 7),
        },
    ];
    for refusal in constructed {
        lines.push(format!("{}: (constructed): {refusal}", variant(&refusal)));
        seen.insert(variant(&refusal));
    }
    let missing: Vec<&str> = VARIANTS
        .iter()
        .copied()
        .filter(|v| !seen.contains(v))
        .collect();
    assert!(missing.is_empty(), "no golden message for {missing:?}");
    lines.push(String::new());
    golden::assert_matches(
        &root().join("tests/golden/operations/refusals.txt"),
        lines.join("\n"),
    );
}

// ------------------------------------------------------------ random sequences

/// The meshes random sequences start from.
fn start(index: usize, structure: Structure) -> Mesh {
    let polygons = match index % 6 {
        0 => generate::tetrahedron(),
        1 => generate::cube(),
        2 => generate::open_square(),
        3 => generate::grid(2, 2),
        4 => grid_with_hole(),
        _ => {
            let bytes = std::fs::read(root().join("meshes/octahedron.obj")).expect("sample");
            formats::read_polygons(&bytes, formats::Format::Obj).expect("reads")
        }
    };
    build(&polygons, structure)
}

/// The live edge rows with one face on both sides: bridges and dangling
/// edges.
fn one_face_edges(mesh: &Mesh) -> Vec<u32> {
    (0..edge_rows(mesh))
        .filter(|&e| mesh.contains(ElementRef::new(ElementKind::Edge, e)))
        .filter(|&e| matches!(sides(mesh, e), [Some((f, _)), Some((g, _))] if f == g))
        .collect()
}

/// Ids for `op` from three random numbers: mostly elements that fit
/// together (corners of the face chosen, edges at the vertex chosen, a
/// boundary vertex for MEKR), sometimes any row, deleted ones included.
pub(crate) fn pick(mesh: &Mesh, op: Operation, picks: [u16; 4]) -> Vec<u32> {
    let any = |kind, pick: u16| u32::from(pick) % (mesh.count(kind).max(1) as u32);
    let choose = |list: &[u32], pick: u16, kind| {
        if list.is_empty() || pick.is_multiple_of(11) {
            any(kind, pick)
        } else {
            list[usize::from(pick) % list.len()]
        }
    };
    let arguments = op.arguments();
    let count = arguments.len()
        - usize::from(picks[3].is_multiple_of(2) && arguments.len() == 3 && arguments[2].optional);
    let mut ids: Vec<u32> = Vec::new();
    for (i, argument) in arguments.iter().take(count).enumerate() {
        let pick = picks[i];
        let id = match (op, i) {
            (Operation::SplitFace | Operation::Mef | Operation::Mekr, 1)
            | (Operation::SplitFace | Operation::Mef, 2) => choose(
                &face_vertices(mesh, FaceId::new(ids[0])),
                pick,
                ElementKind::Vertex,
            ),
            (Operation::Mekr, 2) => choose(&boundary_vertices(mesh), pick, ElementKind::Vertex),
            (Operation::Kemr, 0) => choose(&one_face_edges(mesh), pick, ElementKind::Edge),
            (Operation::Mev, 1 | 2) => choose(
                &edges_at(mesh, VertexId::new(ids[0])),
                pick,
                ElementKind::Edge,
            ),
            _ => any(argument.kind, pick),
        };
        ids.push(id);
    }
    ids
}

/// A random chain: a start mesh in a random structure, and operations each
/// with the random numbers [`pick`] turns into ids.
pub(crate) fn chain(
    steps: std::ops::Range<usize>,
) -> impl proptest::strategy::Strategy<Value = (Mesh, Vec<(Operation, [u16; 4])>)> {
    use proptest::prelude::*;
    (
        0usize..6,
        any::<bool>(),
        proptest::collection::vec((0usize..Operation::ALL.len(), any::<[u16; 4]>()), steps),
    )
        .prop_map(|(index, half, steps)| {
            let structure = if half {
                Structure::HalfEdge
            } else {
                Structure::WingedEdge
            };
            let steps = steps
                .into_iter()
                .map(|(op, picks)| (Operation::ALL[op], picks))
                .collect();
            (start(index, structure), steps)
        })
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig { cases: 48, ..proptest::prelude::ProptestConfig::default() })]

    /// Random operations on random elements of small meshes, in both
    /// structures, compacting now and then: every accepted operation leaves
    /// a valid mesh with the counts its formula gives, every refused one
    /// leaves the mesh as it was.
    #[test]
    fn random_operations_keep_the_mesh_valid((mut mesh, steps) in chain(1..16)) {
        for (step, (op, picks)) in steps.into_iter().enumerate() {
            let ids = pick(&mesh, op, picks);
            let context = format!("step {step}: {op} {ids:?}");
            let before = mesh.clone();
            match operations::apply(&mut mesh, op, &ids) {
                Ok(_) => {
                    let issues = mesh.validate();
                    proptest::prop_assert!(issues.is_empty(), "{}: {:#?}", context, issues);
                    let (mut old, mut new) = (before.clone(), mesh.clone());
                    old.compact();
                    new.compact();
                    let issues = new.validate();
                    proptest::prop_assert!(issues.is_empty(), "{} compacted: {:#?}", context, issues);
                    let change: Vec<i64> = counts(&old.stats())
                        .iter()
                        .zip(counts(&new.stats()))
                        .map(|(b, a)| a - b)
                        .collect();
                    proptest::prop_assert_eq!(change, expected_delta(&before, op, &ids).to_vec(), "{}", context);
                    assert_euler(&new.stats(), &context);
                }
                Err(refusal) => {
                    proptest::prop_assert!(mesh == before, "{}: refused ({}) but changed", context, refusal);
                }
            }
            if picks[3].is_multiple_of(5) {
                mesh.compact();
            }
        }
    }
}

/// [`fuzzing::check_saved_faithfully`], as a proptest failure.
fn assert_saved_faithfully(
    mesh: &Mesh,
    context: &str,
) -> Result<(), proptest::test_runner::TestCaseError> {
    edgewise_core::fuzzing::check_saved_faithfully(mesh).map_err(|problem| {
        proptest::test_runner::TestCaseError::fail(format!("{context}: {problem}"))
    })
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig { cases: 32, ..proptest::prelude::ProptestConfig::default() })]

    /// Random edit chains, never compacted: after every accepted edit the
    /// mesh converts and saves in every format to what it is, or a polygon
    /// format refuses with the reason.
    #[test]
    fn random_edit_chains_convert_and_save_faithfully((mut mesh, steps) in chain(1..10)) {
        for (step, (op, picks)) in steps.into_iter().enumerate() {
            let ids = pick(&mesh, op, picks);
            if operations::apply(&mut mesh, op, &ids).is_ok() {
                assert_saved_faithfully(&mesh, &format!("step {step}: {op} {ids:?}"))?;
            }
        }
    }
}

#[test]
fn a_mesh_mid_edit_converts_both_ways() {
    let bytes = std::fs::read(root().join("meshes/octahedron.obj")).expect("sample");
    let polygons = formats::read_polygons(&bytes, formats::Format::Obj).expect("reads");
    for structure in [Structure::HalfEdge, Structure::WingedEdge] {
        for (op, ids) in [(Operation::CollapseEdge, [0]), (Operation::Kef, [0])] {
            let mut mesh = build(&polygons, structure);
            operations::apply(&mut mesh, op, &ids).expect("applies");
            assert!(!mesh.deleted_rows().is_empty(), "{op} leaves deleted rows");
            assert_saved_faithfully(&mesh, &format!("{structure:?} {op}")).expect("faithful");
        }
    }
}

#[test]
fn a_dangling_edge_is_refused_by_obj_and_ply_with_the_reason() {
    let mesh = build(&generate::cube(), Structure::HalfEdge);
    let (mesh, _, _) = with_dangling_edge(&mesh);
    for format in [formats::Format::Obj, formats::Format::Ply] {
        let error = formats::save(&mesh, format, &formats::SaveOptions::default())
            .expect_err("a dangling edge does not fit a polygon list");
        let message = error.to_string();
        assert!(
            message.contains("passes vertex") && message.contains("save as .wtb or .htb"),
            "{message}"
        );
    }
    for format in [formats::Format::Wtb, formats::Format::Htb] {
        let bytes =
            formats::save(&mesh, format, &formats::SaveOptions::default()).expect("tables keep it");
        let loaded = formats::load_as(
            &bytes,
            format,
            format.native_structure().expect("a table format"),
        )
        .expect("reads back");
        assert!(loaded.mesh.validate().is_empty());
    }
}

/// One accepted example of every operation on a small mesh, in both
/// structures, with its journal as the app would animate it: the exact
/// sequence a traced version must reproduce. In
/// tests/golden/operations/journals.txt (`EDGEWISE_BLESS=1` rewrites it).
#[test]
fn journals_match_their_golden_file() {
    use Operation as Op;
    let winged = |polygons: &Polygons| WingedEdgeMesh::build(polygons).expect("builds").0;
    let octahedron = {
        let bytes = std::fs::read(root().join("meshes/octahedron.obj")).expect("sample");
        formats::read_polygons(&bytes, formats::Format::Obj).expect("reads")
    };
    let square = Sample::new("open square", winged(&generate::open_square()));
    let cube = Sample::new("cube", winged(&generate::cube()));
    let octahedron = Sample::new("octahedron", winged(&octahedron));
    let holed = Sample::new("holed grid", winged(&grid_with_hole()));
    let examples: [(&Sample, Operation, Vec<u32>); 11] = [
        (&square, Op::FlipEdge, vec![2]),
        (&square, Op::SplitEdge, vec![2]),
        (&cube, Op::SplitFace, vec![0, 0, 3]),
        (&octahedron, Op::CollapseEdge, vec![0]),
        (&octahedron, Op::RemoveVertex, vec![0]),
        (&cube, Op::Mev, vec![0, 0, 3]),
        (&cube, Op::Mev, vec![0, 0]),
        (&cube, Op::Kev, vec![0]),
        (&cube, Op::Mef, vec![0, 0, 3]),
        (&cube, Op::Kef, vec![0]),
        (&holed, Op::Mekr, vec![0, 7, 14]),
    ];
    let mut text = String::from(
        "# One example of every operation in both structures, with the journal it\n\
         # writes. Written by crates/core/tests/it/mesh_operations.rs (EDGEWISE_BLESS=1).\n",
    );
    let mut show = |name: &str, structure: &str, mesh: &Mesh, op: Operation, ids: &[u32]| {
        let mut edited = mesh.clone();
        let applied = operations::apply(&mut edited, op, ids)
            .unwrap_or_else(|refusal| panic!("{name}: {op} {ids:?}: {refusal}"));
        let listed: Vec<String> = ids.iter().map(ToString::to_string).collect();
        text.push_str(&format!(
            "\n{op} {} on the {name} ({structure})\n",
            listed.join(" ")
        ));
        for change in &applied.journal {
            text.push_str(&format!("  {change}\n"));
        }
    };
    for (sample, op, ids) in examples {
        show(&sample.name, "winged", &sample.winged, op, &ids);
        show(
            &sample.name,
            "half",
            &sample.half,
            op,
            &sample.half_ids(op, &ids),
        );
    }
    // A bridge does not convert between the structures (its face passes
    // vertices twice), so each is made in its own.
    for (structure, mesh) in [("winged", &holed.winged), ("half", &holed.half)] {
        let (mut bridged, bridge) = after(mesh, Op::Mekr, &[0, 7, 14]);
        bridged.compact();
        show(
            "holed grid bridged by mekr 0 7 14",
            structure,
            &bridged,
            Op::Kemr,
            &[bridge],
        );
    }
    golden::assert_matches(&root().join("tests/golden/operations/journals.txt"), text);
}

/// Runs the traced `name` with `ids` as its arguments, in order (MEV's one
/// edge is given twice, the dangling-edge case).
fn traced(
    program: &edgewise_core::lang::Program,
    name: &str,
    mesh: &mut Mesh,
    ids: &[u32],
) -> edgewise_core::lang::Trace {
    use edgewise_core::lang::{self, RunOptions, Value};
    let algorithm = program
        .algorithm(name)
        .unwrap_or_else(|| panic!("the library has no `{name}`"));
    let mut ids = ids.to_vec();
    if name == "mev" && ids.len() == 2 {
        ids.push(ids[1]);
    }
    let args: Vec<(&str, Value)> = algorithm
        .params()
        .zip(&ids)
        .map(|(param, &id)| {
            let kind = param.ty.element_kind().expect("element parameters");
            (param.name.as_str(), Value::from(ElementRef::new(kind, id)))
        })
        .collect();
    lang::run_editing(algorithm, mesh, &args, RunOptions::default()).expect("inputs fit")
}

/// The traced operations of the library match the native ones table for
/// table: wherever the native operation applies, the traced one leaves the
/// same tables (compared after compacting, which also compares which rows
/// were deleted); wherever it refuses, the traced one refuses before
/// writing anything. On every sample, and on meshes with a dangling edge,
/// a hole and a bridge, which only the Euler operators make.
#[test]
fn traced_library_operations_match_the_native_ones() {
    use Structure::{HalfEdge as Half, WingedEdge as Winged};
    let programs = [
        ("winged-edge-edits.alg", Winged),
        ("half-edge-edits.alg", Half),
    ]
    .map(|(file, structure)| {
        let program = edgewise_core::lang::library::program(file)
            .expect("shipped")
            .expect("the library compiles");
        (structure, program)
    });
    let mut meshes: Vec<(String, Mesh)> = Vec::new();
    for sample in samples() {
        meshes.push((format!("{} (winged)", sample.name), sample.winged));
        meshes.push((format!("{} (half)", sample.name), sample.half));
    }
    for structure in [Winged, Half] {
        let holed = build(&grid_with_hole(), structure);
        // Bridges from several faces to the hole: what KEMR takes away.
        for ids in arguments(&holed, Operation::Mekr, 60) {
            let mut bridged = holed.clone();
            if operations::apply(&mut bridged, Operation::Mekr, &ids).is_ok() {
                meshes.push((
                    format!("holed grid bridged by mekr {ids:?} ({structure})"),
                    bridged,
                ));
            }
        }
        let (dangling, _, _) = with_dangling_edge(&build(&generate::cube(), structure));
        meshes.push((format!("holed grid ({structure})"), holed));
        meshes.push((format!("cube with a dangling edge ({structure})"), dangling));
    }
    let mut compared = [[0usize; 2]; Operation::ALL.len()];
    let mut mismatches = Vec::new();
    for (name, mesh) in &meshes {
        let program = &programs
            .iter()
            .find(|(s, _)| *s == mesh.structure())
            .expect("both structures")
            .1;
        let budget = if mesh.count(ElementKind::Edge) <= 200 {
            200
        } else {
            30
        };
        for (i, op) in Operation::ALL.into_iter().enumerate() {
            let algorithm = op.algorithm();
            for ids in arguments(mesh, op, budget) {
                let mut native = mesh.clone();
                let native_result = operations::apply(&mut native, op, &ids);
                let mut by_trace = mesh.clone();
                let trace = traced(program, algorithm, &mut by_trace, &ids);
                let context = format!("{name}: {op} {ids:?} ({algorithm})");
                match (native_result, trace.outcome().error()) {
                    (Ok(_), None) => {
                        native.compact();
                        by_trace.compact();
                        if native != by_trace {
                            mismatches.push(format!("{context}: the tables differ"));
                        }
                        compared[i][0] += 1;
                    }
                    (Err(_), Some(_)) if trace.changes().len() == 0 => compared[i][1] += 1,
                    (Err(_), Some(error)) => {
                        mismatches.push(format!("{context}: wrote before refusing: {error}"));
                    }
                    (Ok(_), Some(error)) => {
                        mismatches.push(format!("{context}: only the traced one refused: {error}"));
                    }
                    (Err(refusal), None) => {
                        mismatches
                            .push(format!("{context}: only the native one refused: {refusal}"));
                    }
                }
            }
        }
    }
    assert!(
        mismatches.is_empty(),
        "{} mismatches:\n{}",
        mismatches.len(),
        mismatches[..mismatches.len().min(40)].join("\n")
    );
    for (op, [applied, refused]) in Operation::ALL.iter().zip(compared) {
        eprintln!("{op}: {applied} applied alike, {refused} refused alike");
        assert!(
            applied >= 20,
            "{op}: only {applied} applied ({refused} refused)"
        );
    }
}
