//! The do-it grader proven in both directions: for every operation, on every
//! sample in both structures and on meshes that random operations made,
//!
//! - the library's result with the choices an operation leaves open taken
//!   differently (touched and new rows renumbered, rows compacted as a saved
//!   file is, touched winged edges reversed, touched incident edges moved to
//!   other valid ones) grades **pass**;
//! - every single-cell corruption of the result grades **fail** with a
//!   message, except a touched row's incident edge set to another valid one,
//!   which is such a choice and must pass.

use std::collections::{BTreeSet, HashSet};

use edgewise_core::mesh::grade::grade_edit;
use edgewise_core::mesh::operations::{self, Operation};
use edgewise_core::mesh::{Edit, Mesh, Structure, VertexId};
use edgewise_core::schema::{Column, ElementKind, ElementRef, Records, RecordsMut, Storage};

use super::mesh_operations::{arguments, chain, pick, samples};

/// A small deterministic generator, so a failure names its seed.
struct Lcg(u64);

impl Lcg {
    fn next(&mut self) -> u64 {
        self.0 = self
            .0
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        self.0 >> 33
    }

    fn below(&mut self, n: usize) -> usize {
        (self.next() % n.max(1) as u64) as usize
    }
}

fn stored_columns(structure: Structure, kind: ElementKind) -> Vec<Column> {
    Column::table(structure, kind)
        .iter()
        .filter(|entry| entry.storage == Storage::Stored && entry.column != Column::Position)
        .map(|entry| entry.column)
        .collect()
}

/// The rows the operation's journal touches, made and deleted ones too.
fn touched(applied: &operations::Applied) -> HashSet<ElementRef> {
    applied
        .journal
        .iter()
        .map(edgewise_core::mesh::Change::element)
        .collect()
}

/// `mesh` with its rows renumbered by `order` (a permutation of each
/// table), every stored cell rewritten to match.
fn renumbered(mesh: &Mesh, order: &[Vec<u32>; 3]) -> Mesh {
    let structure = mesh.structure();
    let index = |kind: ElementKind| {
        ElementKind::ALL
            .iter()
            .position(|&k| k == kind)
            .unwrap_or(0)
    };
    let map = |r: ElementRef| ElementRef::new(r.kind, order[index(r.kind)][r.id as usize]);
    let mut out = mesh.clone();
    for kind in ElementKind::ALL {
        for id in 0..mesh.count(kind) as u32 {
            let row = ElementRef::new(kind, id);
            let to = map(row);
            if kind == ElementKind::Vertex {
                let position = mesh.position(VertexId::new(id)).expect("live vertex");
                out.set_position(VertexId::new(to.id), position)
                    .expect("finite");
            }
            for column in stored_columns(structure, kind) {
                let target = mesh.reference(row, column).expect("stored").map(map);
                out.set_reference(to, column, target).expect("writes");
            }
        }
    }
    out
}

/// The result with the open choices taken another way, as a saved file has
/// it: compacted, touched rows shuffled among themselves, touched winged
/// edges reversed and touched incident edges moved.
fn another_way(result: &Mesh, touched: &HashSet<ElementRef>, rng: &mut Lcg) -> Mesh {
    let mut compacted = result.clone();
    let renumbering = compacted.compact();
    let touched: BTreeSet<ElementRef> = touched
        .iter()
        .filter_map(|&row| renumbering.get(row))
        .collect();
    let order = ElementKind::ALL.map(|kind| {
        let mut order: Vec<u32> = (0..compacted.count(kind) as u32).collect();
        let mut ids: Vec<u32> = touched
            .iter()
            .filter(|r| r.kind == kind)
            .map(|r| r.id)
            .collect();
        let slots = ids.clone();
        for i in (1..ids.len()).rev() {
            ids.swap(i, rng.below(i + 1));
        }
        for (slot, id) in slots.into_iter().zip(ids) {
            order[slot as usize] = id;
        }
        order
    });
    let mut answer = renumbered(&compacted, &order);
    let touched: BTreeSet<ElementRef> = touched
        .iter()
        .map(|r| {
            let k = ElementKind::ALL
                .iter()
                .position(|&k| k == r.kind)
                .unwrap_or(0);
            ElementRef::new(r.kind, order[k][r.id as usize])
        })
        .collect();
    if answer.structure() == Structure::WingedEdge {
        for &row in touched.iter().filter(|r| r.kind == ElementKind::Edge) {
            if rng.below(2) == 0 {
                reverse_winged_edge(&mut answer, row);
            }
        }
    }
    for &row in touched.iter().filter(|r| r.kind != ElementKind::Edge) {
        let choices = incident_choices(&answer, row);
        if !choices.is_empty() {
            let pick = choices[rng.below(choices.len())];
            answer
                .set_reference(row, Column::IncidentEdge, Some(pick))
                .expect("writes");
        }
    }
    answer
}

/// Swaps a winged edge's ends, and so its sides.
fn reverse_winged_edge(mesh: &mut Mesh, row: ElementRef) {
    let swaps = [
        (Column::StartVertex, Column::EndVertex),
        (Column::LeftFace, Column::RightFace),
        (Column::LeftPredecessor, Column::RightPredecessor),
        (Column::LeftSuccessor, Column::RightSuccessor),
    ];
    for (a, b) in swaps {
        let (x, y) = (
            mesh.reference(row, a).expect("stored"),
            mesh.reference(row, b).expect("stored"),
        );
        mesh.set_reference(row, a, y).expect("writes");
        mesh.set_reference(row, b, x).expect("writes");
    }
}

/// Every edge row a vertex or face may keep as its incident edge.
fn incident_choices(mesh: &Mesh, row: ElementRef) -> Vec<ElementRef> {
    let columns: &[Column] = match (mesh.structure(), row.kind) {
        (Structure::HalfEdge, ElementKind::Vertex) => &[Column::EndVertex],
        (Structure::HalfEdge, _) => &[Column::Face],
        (Structure::WingedEdge, ElementKind::Vertex) => &[Column::StartVertex, Column::EndVertex],
        (Structure::WingedEdge, _) => &[Column::LeftFace, Column::RightFace],
    };
    (0..mesh.count(ElementKind::Edge) as u32)
        .map(|e| ElementRef::new(ElementKind::Edge, e))
        .filter(|&e| mesh.contains(e))
        .filter(|&e| {
            columns
                .iter()
                .any(|&c| mesh.reference(e, c).ok().flatten() == Some(row))
        })
        .collect()
}

/// The one corruption of each stored cell of each live row: a reference
/// moved to the next row of its table (or set where it was empty), a
/// position moved by one unit.
fn corruptions(mesh: &Mesh) -> Vec<(ElementRef, Column, Mesh)> {
    let mut out = Vec::new();
    for kind in ElementKind::ALL {
        for id in 0..mesh.count(kind) as u32 {
            let row = ElementRef::new(kind, id);
            if !mesh.contains(row) {
                continue;
            }
            if kind == ElementKind::Vertex {
                let mut bad = mesh.clone();
                let v = VertexId::new(id);
                let p = mesh.position(v).expect("live");
                bad.set_position(v, p + glam::Vec3::ONE).expect("finite");
                out.push((row, Column::Position, bad));
            }
            for column in stored_columns(mesh.structure(), kind) {
                let Some(target) = column.target() else {
                    continue;
                };
                let count = mesh.count(target) as u32;
                let new = match mesh.reference(row, column).expect("stored") {
                    Some(current) if count > 1 => (current.id + 1) % count,
                    None if count > 0 => 0,
                    Some(_) | None => continue,
                };
                let mut bad = mesh.clone();
                if bad
                    .set_reference(row, column, Some(ElementRef::new(target, new)))
                    .is_ok()
                {
                    out.push((row, column, bad));
                }
            }
        }
    }
    out
}

#[derive(Default)]
struct Counts {
    instances: usize,
    passes: usize,
    failures: usize,
    choices: usize,
}

/// Grades the result taken another way (must pass) and, where `corrupt`,
/// every single-cell corruption of it.
fn prove(
    name: &str,
    before: &Mesh,
    op: Operation,
    ids: &[u32],
    corrupt: bool,
    counts: &mut Counts,
) {
    let mut result = before.clone();
    let Ok(applied) = operations::apply(&mut result, op, ids) else {
        return;
    };
    counts.instances += 1;
    let context = format!("{name}: {op} {ids:?}");
    let touched = touched(&applied);
    let grade = |answer: &Mesh| grade_edit(before, op, ids, answer).expect("the operation applies");
    let native = grade(&result);
    assert!(
        native.passed(),
        "{context}: the native result fails: {:?}",
        native.difference
    );
    assert_eq!(native.fewest_writes, applied.journal.len());
    assert!(
        !grade(before).passed(),
        "{context}: the mesh as it was before passes"
    );
    counts.failures += 1;
    let mut rng = Lcg(ids.iter().fold(op as u64, |s, &id| s * 31 + u64::from(id)));
    for _ in 0..2 {
        let answer = another_way(&result, &touched, &mut rng);
        assert_eq!(
            answer.validate(),
            vec![],
            "{context}: the renumbered answer is broken"
        );
        let grade = grade(&answer);
        assert!(
            grade.passed(),
            "{context}: taken another way, it fails: {:?}",
            grade.difference
        );
        counts.passes += 1;
    }
    if !corrupt {
        return;
    }
    for (row, column, bad) in corruptions(&result) {
        let choice =
            column == Column::IncidentEdge && touched.contains(&row) && bad.validate().is_empty();
        let grade = grade(&bad);
        if choice {
            assert!(
                grade.passed(),
                "{context}: {row} {column:?} is a free choice: {:?}",
                grade.difference
            );
            counts.choices += 1;
        } else {
            let difference = grade.difference.unwrap_or_else(|| {
                panic!("{context}: {row}'s {column:?} corrupted, and it passes")
            });
            assert!(!difference.message.is_empty());
            counts.failures += 1;
        }
    }
}

#[test]
fn the_grader_passes_every_way_of_doing_it_and_fails_every_wrong_cell() {
    let mut counts = Counts::default();
    for sample in samples() {
        let small = sample.winged.edge_count() <= 40;
        for op in Operation::ALL {
            let budget = if small { 6 } else { 2 };
            for ids in arguments(&sample.winged, op, budget) {
                let half_ids = sample.half_ids(op, &ids);
                prove(
                    &format!("{} (winged)", sample.name),
                    &sample.winged,
                    op,
                    &ids,
                    small,
                    &mut counts,
                );
                prove(
                    &format!("{} (half)", sample.name),
                    &sample.half,
                    op,
                    &half_ids,
                    small,
                    &mut counts,
                );
            }
        }
    }
    eprintln!(
        "samples: {} instances; {} answers taken another way pass; {} corruptions fail; {} free choices pass",
        counts.instances, counts.passes, counts.failures, counts.choices
    );
    assert!(counts.instances > 200 && counts.failures > 10_000 && counts.choices > 50);
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig { cases: 32, ..proptest::prelude::ProptestConfig::default() })]

    /// Meshes that random operations made (bridges, dangling edges, gaps
    /// left by deleted rows), then one more operation to grade.
    #[test]
    fn the_grader_holds_on_meshes_random_operations_made(
        (mut mesh, steps) in chain(2..10),
    ) {
        let mut counts = Counts::default();
        let (last, rest) = steps.split_last().expect("two steps or more");
        for &(op, picks) in rest {
            let ids = pick(&mesh, op, picks);
            let _ = operations::apply(&mut mesh, op, &ids);
        }
        let (op, picks) = *last;
        let ids = pick(&mesh, op, picks);
        prove("random", &mesh, op, &ids, true, &mut counts);
    }
}

/// The feedback a student reads, word for word.
#[test]
fn feedback_names_the_first_difference_in_the_tables_words() {
    use edgewise_core::mesh::generate;
    let (before, _) = Mesh::build(&generate::open_square(), Structure::HalfEdge).expect("builds");
    let grade = |answer: &Mesh| {
        grade_edit(&before, Operation::FlipEdge, &[2], answer)
            .expect("applies")
            .difference
            .map(|d| d.message)
    };
    let mut flipped = before.clone();
    operations::apply(&mut flipped, Operation::FlipEdge, &[2]).expect("flips");
    assert_eq!(grade(&flipped), None);

    let messages = [
        grade(&before),
        {
            let mut one_wrong = flipped.clone();
            let h0 = ElementRef::new(ElementKind::Edge, 0);
            let face = one_wrong.reference(h0, Column::Face).expect("stored");
            let other = face.map(|f| ElementRef::new(ElementKind::Face, 1 - f.id));
            one_wrong
                .set_reference(h0, Column::Face, other)
                .expect("writes");
            grade(&one_wrong)
        },
        grade(&flipped.convert_to(Structure::WingedEdge).expect("converts")),
        {
            let (rebuilt, _) =
                Mesh::build(&flipped.to_polygons(), Structure::HalfEdge).expect("builds");
            grade(&rebuilt)
        },
    ];
    let expected = [
        "half-edge 0 (vertex 0 → vertex 1)'s successor edge is half-edge 1 (vertex 1 → vertex 2); \
         after flip-edge 2 the next side around face 0 runs from vertex 1 to vertex 3",
        "the tables do not hold together: half-edge 0 successor_edge: its successor half-edge 3 \
         lies in face 1, but this half-edge lies in face 0",
        "the answer is a winged-edge mesh; the exercise is in the half-edge structure",
        "vertex 1's incident edge is half-edge 0; flip-edge 2 need not change it, and it was \
         half-edge 5",
    ]
    .map(|m| Some(m.to_owned()));
    assert_eq!(messages, expected);
}
