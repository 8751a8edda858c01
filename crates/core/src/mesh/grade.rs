//! Grading an operation a student carried out by hand, one cell at a time.
//!
//! An operation leaves choices open: which ids new rows get, which of two
//! rows survives a merge, which half-edge a vertex or face keeps as its
//! incident one, which way a new winged edge points. So an answer is graded
//! by what must hold, not by exact ids ([`grade_edit`]):
//!
//! 1. its tables validate;
//! 2. it has the counts of the library operation's result, and the same
//!    faces by size;
//! 3. it is that result up to those choices: one mapping of its darts (the
//!    sides of its edges) onto the result's keeps every successor, pair and
//!    face, and every vertex where it is (within a small tolerance, so a typed
//!    midpoint counts);
//! 4. the rows the operation has no need to touch are unchanged, and keep
//!    their order (a saved file renumbers rows past a deleted one, and
//!    nothing else).
//!
//! The first failure is reported in the tables' own words, naming the
//! answer's rows, never the result's, which the student cannot see.

mod darts;
mod matching;
mod places;

use std::collections::HashSet;
use std::fmt;

use glam::Vec3;

use super::edit::Edit;
use super::ids::{FaceId, VertexId};
use super::operations::{self, Operation, Refusal};
use super::structure::Mesh;
use super::validate::Element;
use crate::schema::{Column, ElementKind, ElementRef, Records, Storage, Structure};
use darts::{Darts, NONE};
use places::Places;

/// What a grade found wrong: the first difference, and the answer's row it
/// is about, for the app to point at.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Difference {
    pub element: Option<ElementRef>,
    pub message: String,
}

impl fmt::Display for Difference {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.message)
    }
}

/// The grade of one answer.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Grade {
    /// `None` when the answer is the operation's result.
    pub difference: Option<Difference>,
    /// The writes the library's operation makes (new rows, cells, deletions):
    /// the fewest an answer needs.
    pub fewest_writes: usize,
}

impl Grade {
    pub fn passed(&self) -> bool {
        self.difference.is_none()
    }
}

/// Grades `answer` as the result of `operation` on `ids` applied to
/// `before`; refuses, as the operation does, an operation that does not
/// apply there.
///
/// ```
/// use edgewise_core::mesh::grade::grade_edit;
/// use edgewise_core::mesh::operations::{self, Operation};
/// use edgewise_core::mesh::{generate, Mesh, Structure};
/// use edgewise_core::schema::{Column, ElementKind, ElementRef, RecordsMut};
///
/// let (before, _) = Mesh::build(&generate::open_square(), Structure::HalfEdge)?;
/// let mut answer = before.clone();
/// operations::apply(&mut answer, Operation::FlipEdge, &[2])?;
/// assert!(grade_edit(&before, Operation::FlipEdge, &[2], &answer)?.passed());
///
/// // One wrong cell: half-edge 0's successor no longer closes its triangle.
/// let h0 = ElementRef::new(ElementKind::Edge, 0);
/// answer.set_reference(h0, Column::SuccessorEdge, Some(ElementRef::new(ElementKind::Edge, 1)))?;
/// let grade = grade_edit(&before, Operation::FlipEdge, &[2], &answer)?;
/// assert!(!grade.passed());
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn grade_edit(
    before: &Mesh,
    operation: Operation,
    ids: &[u32],
    answer: &Mesh,
) -> Result<Grade, Refusal> {
    let mut result = before.clone();
    let applied = operations::apply(&mut result, operation, ids)?;
    let touched: HashSet<ElementRef> = applied
        .journal
        .iter()
        .map(super::edit::Change::element)
        .collect();
    let task = Task { operation, ids };
    let difference = Comparison::new(&task, &result, &touched, answer).first_difference();
    Ok(Grade {
        difference,
        fewest_writes: applied.journal.len(),
    })
}

/// The operation as messages name it: "flip-edge 7".
struct Task<'a> {
    operation: Operation,
    ids: &'a [u32],
}

impl fmt::Display for Task<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.operation.name())?;
        for id in self.ids {
            write!(f, " {id}")?;
        }
        Ok(())
    }
}

type Checked = Result<(), Difference>;

fn differ(element: Option<ElementRef>, message: String) -> Checked {
    Err(Difference { element, message })
}

/// The library's result beside the answer, and the mapping between them as
/// it is found.
struct Comparison<'a> {
    task: &'a Task<'a>,
    result: &'a Mesh,
    answer: &'a Mesh,
    touched: &'a HashSet<ElementRef>,
    expected: Darts,
    given: Darts,
    /// How far apart two positions may be and still be one vertex.
    tolerance: f32,
    /// Where the result's vertices are, and the answer's.
    expected_places: Places,
    given_places: Places,
    /// The result's dart → the answer's, and back.
    forward: Vec<u32>,
    backward: Vec<u32>,
}

impl<'a> Comparison<'a> {
    fn new(
        task: &'a Task<'a>,
        result: &'a Mesh,
        touched: &'a HashSet<ElementRef>,
        answer: &'a Mesh,
    ) -> Self {
        let expected = Darts::of(result);
        let given = Darts::of(answer);
        let extent = expected
            .positions
            .iter()
            .flatten()
            .map(|p| p.abs().max_element())
            .fold(1.0_f32, f32::max);
        let tolerance = extent * 1e-4;
        let expected_places = Places::new(&expected.positions, tolerance);
        let given_places = Places::new(&given.positions, tolerance);
        let (forward, backward) = (vec![NONE; expected.len()], vec![NONE; given.len()]);
        Self {
            task,
            result,
            answer,
            touched,
            expected,
            given,
            tolerance,
            expected_places,
            given_places,
            forward,
            backward,
        }
    }

    fn first_difference(mut self) -> Option<Difference> {
        self.check_structure()
            .and_then(|()| self.check_valid())
            .and_then(|()| self.check_counts())
            .and_then(|()| self.check_positions())
            .and_then(|()| self.check_face_sizes())
            .and_then(|()| self.match_darts())
            .and_then(|()| self.check_untouched())
            .err()
    }

    fn check_structure(&self) -> Checked {
        let (want, got) = (self.result.structure(), self.answer.structure());
        if want == got {
            Ok(())
        } else {
            differ(
                None,
                format!(
                    "the answer is a {} mesh; the exercise is in the {} structure",
                    got.prose(),
                    want.prose()
                ),
            )
        }
    }

    fn check_valid(&self) -> Checked {
        match self.answer.validate().into_iter().next() {
            None => Ok(()),
            Some(issue) => differ(
                Some(issue.element.into()),
                format!("the tables do not hold together: {issue}"),
            ),
        }
    }

    fn check_counts(&self) -> Checked {
        for kind in ElementKind::ALL {
            let (want, got) = (live_count(self.result, kind), live_count(self.answer, kind));
            if want != got {
                let noun = self.plural(kind);
                return differ(
                    None,
                    format!(
                        "the tables hold {got} {noun}; after {} the mesh has {want}",
                        self.task
                    ),
                );
            }
        }
        Ok(())
    }

    /// Every vertex of the result has one of the answer's where it is; a
    /// vertex typed in the wrong place is named with where it should be.
    fn check_positions(&self) -> Checked {
        let expected = &self.expected.positions;
        let Some(missing) = (0..expected.len())
            .filter_map(|v| expected[v])
            .find(|&p| self.near(Some(p)).is_empty())
        else {
            return Ok(());
        };
        let given = &self.given.positions;
        let stray = (0..given.len() as u32).find(|&w| {
            given[w as usize].is_some_and(|q| self.expected_places.near(expected, q).is_empty())
        });
        match stray {
            Some(w) => differ(
                Some(ElementRef::new(ElementKind::Vertex, w)),
                format!(
                    "{} is at {}, where the result of {} has no vertex; the result has one at \
                     {} and the answer has none there",
                    VertexId::new(w),
                    coordinates(given[w as usize].unwrap_or_default()),
                    self.task,
                    coordinates(missing)
                ),
            ),
            None => differ(
                None,
                format!(
                    "after {} a vertex is at {}; the answer has none there",
                    self.task,
                    coordinates(missing)
                ),
            ),
        }
    }

    /// Compares the faces by their number of sides, naming an answer face
    /// of a size the result has fewer of, and the sizes the faces the
    /// operation changed have.
    fn check_face_sizes(&self) -> Checked {
        let (want, got) = (face_sizes(self.result), face_sizes(self.answer));
        let mut want_sorted: Vec<usize> = want.iter().map(|&(_, n)| n).collect();
        let mut got_sorted: Vec<usize> = got.iter().map(|&(_, n)| n).collect();
        want_sorted.sort_unstable();
        got_sorted.sort_unstable();
        if want_sorted == got_sorted {
            return Ok(());
        }
        let count = |sizes: &[usize], n: usize| sizes.iter().filter(|&&s| s == n).count();
        let Some(&(face, n)) = got
            .iter()
            .find(|&&(_, n)| count(&got_sorted, n) > count(&want_sorted, n))
        else {
            return Ok(());
        };
        let mut changed: Vec<String> = want
            .iter()
            .filter(|&&(f, _)| self.touched.contains(&ElementRef::face(f)))
            .map(|&(_, n)| n.to_string())
            .collect();
        changed.sort();
        let sides = self.sides_word();
        let after = match changed.as_slice() {
            [] => format!("after {} no face has {n} {sides}", self.task),
            [one] => format!("after {} the face it changes has {one}", self.task),
            many => format!(
                "after {} the faces it changes have {} {sides}",
                self.task,
                join_and(many)
            ),
        };
        differ(
            Some(ElementRef::face(face)),
            format!("{face}'s cycle has {n} {sides}; {after}"),
        )
    }

    /// The answer's vertices at `position`.
    fn near(&self, position: Option<Vec3>) -> Vec<u32> {
        position.map_or_else(Vec::new, |p| {
            self.given_places.near(&self.given.positions, p)
        })
    }

    /// The answer's vertex at `position` ("vertex 7"), or the coordinates
    /// where it has none.
    fn name_at(&self, position: Option<Vec3>) -> String {
        match self.near(position).first() {
            Some(&v) => VertexId::new(v).to_string(),
            None => coordinates(position.unwrap_or_default()),
        }
    }

    /// Rows the operation need not touch keep their contents (through the
    /// mapping) and their order.
    fn check_untouched(&self) -> Checked {
        let maps = self.element_maps()?;
        let structure = self.result.structure();
        for kind in ElementKind::ALL {
            let mut last: Option<u32> = None;
            for id in 0..self.result.count(kind) as u32 {
                let row = ElementRef::new(kind, id);
                if !self.result.contains(row) || self.touched.contains(&row) {
                    continue;
                }
                let Some(mapped) = maps.apply(row) else {
                    continue;
                };
                let named = |r: ElementRef| Element::of(structure, r);
                if last.is_some_and(|last| mapped.id <= last) {
                    return differ(
                        Some(mapped),
                        format!(
                            "{} holds what {} held, but {} need not renumber it: rows the \
                             operation does not touch keep their numbers (rebuilding the mesh \
                             is not the operation)",
                            named(mapped),
                            named(row),
                            self.task
                        ),
                    );
                }
                last = Some(mapped.id);
                self.check_row(row, mapped, &maps)?;
            }
        }
        Ok(())
    }

    fn check_row(&self, row: ElementRef, mapped: ElementRef, maps: &Maps) -> Checked {
        let structure = self.result.structure();
        for entry in Column::table(structure, row.kind) {
            if entry.storage != Storage::Stored || entry.column == Column::Position {
                continue;
            }
            let column = entry.column;
            let want = self
                .result
                .reference(row, column)
                .ok()
                .flatten()
                .and_then(|r| maps.apply(r));
            let got = self.answer.reference(mapped, column).ok().flatten();
            if want != got {
                let name = |r: Option<ElementRef>| {
                    r.map_or_else(
                        || "empty".to_owned(),
                        |r| Element::of(structure, r).to_string(),
                    )
                };
                return differ(
                    Some(mapped),
                    format!(
                        "{}'s {} is {}; {} need not change it, and it was {}",
                        Element::of(structure, mapped),
                        column.key(),
                        name(got),
                        self.task,
                        name(want)
                    ),
                );
            }
        }
        Ok(())
    }

    /// The mapping of vertices, edge rows and faces the darts give.
    fn element_maps(&self) -> Result<Maps, Difference> {
        let mut maps = Maps {
            vertices: vec![NONE; self.expected.positions.len()],
            edges: vec![NONE; self.result.count(ElementKind::Edge)],
            faces: vec![NONE; self.result.count(ElementKind::Face)],
        };
        for e in 0..self.expected.len() as u32 {
            let a = self.forward[e as usize];
            if a == NONE {
                continue;
            }
            // Both sides of a winged edge give the same row, reversed or not.
            maps.edges[self.expected.row(e).0 as usize] = self.given.row(a).0;
            let origin = self.expected.origin[e as usize] as usize;
            let given_origin = self.given.origin[a as usize];
            if maps.vertices[origin] != NONE && maps.vertices[origin] != given_origin {
                return Err(Difference {
                    element: Some(ElementRef::new(ElementKind::Vertex, given_origin)),
                    message: format!(
                        "{} and {} are both at {}, where the result of {} has one vertex",
                        VertexId::new(maps.vertices[origin]),
                        VertexId::new(given_origin),
                        coordinates(self.given.position(given_origin).unwrap_or_default()),
                        self.task
                    ),
                });
            }
            maps.vertices[origin] = given_origin;
            let (face, given_face) = (self.expected.face[e as usize], self.given.face[a as usize]);
            if face != NONE {
                maps.faces[face as usize] = given_face;
            }
        }
        Ok(maps)
    }

    fn plural(&self, kind: ElementKind) -> &'static str {
        match (kind, self.result.structure()) {
            (ElementKind::Edge, Structure::HalfEdge) => "half-edges",
            (kind, _) => kind.plural(),
        }
    }

    fn sides_word(&self) -> &'static str {
        match self.result.structure() {
            Structure::HalfEdge => "half-edges",
            Structure::WingedEdge => "edges",
        }
    }
}

/// Where each of the result's rows is in the answer.
struct Maps {
    vertices: Vec<u32>,
    edges: Vec<u32>,
    faces: Vec<u32>,
}

impl Maps {
    fn apply(&self, row: ElementRef) -> Option<ElementRef> {
        let table = match row.kind {
            ElementKind::Vertex => &self.vertices,
            ElementKind::Edge => &self.edges,
            ElementKind::Face => &self.faces,
        };
        table
            .get(row.id as usize)
            .filter(|&&id| id != NONE)
            .map(|&id| ElementRef::new(row.kind, id))
    }
}

/// The live rows of one table (half-edges for a half-edge mesh's edges).
fn live_count(mesh: &Mesh, kind: ElementKind) -> usize {
    mesh.count(kind) - mesh.deleted_rows().count(kind)
}

/// Each live face with its number of sides.
fn face_sizes(mesh: &Mesh) -> Vec<(FaceId, usize)> {
    use super::navigation::Navigation;
    (0..mesh.count(ElementKind::Face) as u32)
        .map(FaceId::new)
        .filter(|&f| mesh.contains(ElementRef::face(f)))
        .map(|f| {
            let n = match mesh {
                Mesh::Winged(m) => m.around_face(f).count(),
                Mesh::Half(m) => m.around_face(f).count(),
            };
            (f, n)
        })
        .collect()
}

fn coordinates(p: Vec3) -> String {
    format!("({}, {}, {})", p.x, p.y, p.z)
}

fn join_and(items: &[String]) -> String {
    match items {
        [] => String::new(),
        [one] => one.clone(),
        [init @ .., last] => format!("{} and {last}", init.join(", ")),
    }
}
