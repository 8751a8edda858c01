//! Local operations on either structure: edge flip, edge split, face split,
//! edge collapse, vertex removal and the Euler operators (MEV, KEV, MEF,
//! KEF, KEMR, MEKR), each written once for both structures.
//!
//! Every operation follows the same rules, so that a traced version written
//! in the algorithm language can produce identical tables:
//!
//! - **Preconditions first.** An operation is planned on a working copy
//!   (every read and every change goes through it) and refused, with a
//!   [`Refusal`] naming the elements at fault, before the mesh is touched.
//!   The finished plan is written through an [`Editor`], so every change is
//!   journaled; if a change fails midway, the journal is reverted and the
//!   mesh is as it was.
//! - **Naming.** An edge is named by its edge id in a winged-edge mesh and
//!   by either of its half-edges in a half-edge mesh ([`EdgeRow`]). The
//!   name gives the edge a direction: a half-edge runs to its end vertex, a
//!   winged edge from its start to its end (its left side, which its left
//!   face walks counter-clockwise). "The first half" of an edge below is the
//!   half-edge named, or that left side; "the second half" is its pair, or
//!   the right side.
//! - **Ids.** New rows take the next free id in each table, in the order
//!   each operation's documentation lists; a new edge of a half-edge mesh is
//!   two rows, its first half then its second. Deleted rows stay as gaps
//!   ([`Editor::delete`]) until [`Edit::compact`].
//! - **Writes.** The committed journal holds the new rows, then each changed
//!   cell once with its final value (cells already holding it are skipped),
//!   in the order the operation's steps first change them, then the
//!   deletions. A step "`x` → `y`" makes `y` follow `x` counter-clockwise
//!   around its face: a half-edge's successor edge, or in a winged-edge mesh
//!   `x`'s predecessor wing and `y`'s successor wing on their sides.
//! - **Incident edges** change only where the old one is deleted or no
//!   longer touches its element, to the edge each operation names.
//!
//! The Euler operators keep V − E + F = 2 − 2g − b for every component
//! (b is the number of boundary loops). A face is one cycle; an edge may
//! have the same face on both sides (a dangling edge, or a bridge from a
//! face's outer cycle to an inner one), and a boundary loop is a cycle of
//! half-edges without a face (winged-edge sides without a face).

pub mod candidates;
mod collapse_edge;
mod euler;
mod flip_edge;
mod patch;
mod refusal;
mod remove_vertex;
mod split_edge;
mod split_face;

use std::fmt;

pub use candidates::candidates;
pub use collapse_edge::collapse_edge;
pub use euler::{kef, kemr, kev, mef, mekr, mev};
pub use flip_edge::flip_edge;
pub use refusal::{Action, EdgeName, Refusal};
pub use remove_vertex::remove_vertex;
pub use split_edge::split_edge;
pub use split_face::split_face;

use super::edit::{Change, Edit, Editor};
use super::ids::{EdgeId, FaceId, HalfEdgeId, VertexId};
use super::structure::Mesh;
use crate::schema::{ElementKind, ElementRef};
use patch::Patch;

/// An edge as the operations take it: a row of the edge table, so a winged
/// edge's id, or the id of either half-edge of an edge (which gives the
/// edge the direction of that half-edge).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct EdgeRow(pub u32);

impl From<EdgeId> for EdgeRow {
    fn from(e: EdgeId) -> Self {
        Self(e.raw())
    }
}

impl From<HalfEdgeId> for EdgeRow {
    fn from(h: HalfEdgeId) -> Self {
        Self(h.raw())
    }
}

/// What an applied operation did.
#[derive(Clone, Debug, PartialEq)]
pub struct Applied {
    /// Every primitive change, oldest first; reverting them newest first
    /// restores the mesh exactly.
    pub journal: Vec<Change>,
    /// The rows made, in order (both halves of a new half-edge pair).
    pub made: Vec<ElementRef>,
    /// The rows deleted, in order (both halves of a half-edge pair).
    pub deleted: Vec<ElementRef>,
}

/// The local operations, by their command-line names.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Operation {
    FlipEdge,
    SplitEdge,
    SplitFace,
    CollapseEdge,
    RemoveVertex,
    Mev,
    Mef,
    Kev,
    Kef,
    Kemr,
    Mekr,
}

/// One id an operation takes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Argument {
    /// The table the id is a row of.
    pub kind: ElementKind,
    /// What it names, for help text ("vertex on a boundary loop").
    pub role: &'static str,
    /// Whether it may be left out (only at the end).
    pub optional: bool,
}

impl fmt::Display for Argument {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.optional {
            write!(f, "[{}]", self.role)
        } else {
            f.write_str(self.role)
        }
    }
}

const fn required(kind: ElementKind, role: &'static str) -> Argument {
    Argument {
        kind,
        role,
        optional: false,
    }
}

const EDGE: &[Argument] = &[required(ElementKind::Edge, "edge")];
const VERTEX: &[Argument] = &[required(ElementKind::Vertex, "vertex")];
const VERTEX_SPLIT: &[Argument] = &[
    required(ElementKind::Vertex, "vertex"),
    required(ElementKind::Edge, "edge"),
    Argument {
        kind: ElementKind::Edge,
        role: "edge",
        optional: true,
    },
];
const BRIDGE: &[Argument] = &[
    required(ElementKind::Face, "face"),
    required(ElementKind::Vertex, "vertex on the face"),
    required(ElementKind::Vertex, "vertex on a boundary loop"),
];
const FACE_CUT: &[Argument] = &[
    required(ElementKind::Face, "face"),
    required(ElementKind::Vertex, "vertex"),
    required(ElementKind::Vertex, "vertex"),
];

/// How an operation changes the counts, where that is fixed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Delta {
    pub vertices: i64,
    pub edges: i64,
    pub faces: i64,
    pub boundary_loops: i64,
}

const fn delta(vertices: i64, edges: i64, faces: i64, boundary_loops: i64) -> Delta {
    Delta {
        vertices,
        edges,
        faces,
        boundary_loops,
    }
}

/// An operation name that is not one of [`Operation::ALL`].
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct UnknownOperation(pub String);

impl fmt::Display for UnknownOperation {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let names: Vec<&str> = Operation::ALL.iter().map(|op| op.name()).collect();
        write!(
            f,
            "no operation is named `{}`; the operations are {}",
            self.0,
            names.join(", ")
        )
    }
}

impl std::error::Error for UnknownOperation {}

impl Operation {
    /// Every operation, the modelling ones first, then the Euler operators
    /// with each inverse after its operator.
    pub const ALL: [Operation; 11] = [
        Self::FlipEdge,
        Self::SplitEdge,
        Self::SplitFace,
        Self::CollapseEdge,
        Self::RemoveVertex,
        Self::Mev,
        Self::Kev,
        Self::Mef,
        Self::Kef,
        Self::Kemr,
        Self::Mekr,
    ];

    /// The command-line name: `flip-edge`, `mev`.
    pub fn name(self) -> &'static str {
        self.names().0
    }

    /// The command-line name, and the library algorithm that traces the
    /// operation.
    fn names(self) -> (&'static str, &'static str) {
        match self {
            Self::FlipEdge => ("flip-edge", "flipEdge"),
            Self::SplitEdge => ("split-edge", "splitEdge"),
            Self::SplitFace => ("split-face", "splitFace"),
            Self::CollapseEdge => ("collapse-edge", "collapseEdge"),
            Self::RemoveVertex => ("remove-vertex", "removeVertex"),
            Self::Mev => ("mev", "mev"),
            Self::Mef => ("mef", "mef"),
            Self::Kev => ("kev", "kev"),
            Self::Kef => ("kef", "kef"),
            Self::Kemr => ("kemr", "kemr"),
            Self::Mekr => ("mekr", "mekr"),
        }
    }

    /// Parses a command-line name, ignoring case (`MEV` is `mev`).
    pub fn parse(name: &str) -> Result<Self, UnknownOperation> {
        Self::ALL
            .into_iter()
            .find(|op| op.name().eq_ignore_ascii_case(name))
            .ok_or_else(|| UnknownOperation(name.to_owned()))
    }

    /// What the operation does, in one line.
    pub fn summary(self) -> &'static str {
        match self {
            Self::FlipEdge => "turn the edge between two triangles to join their other corners",
            Self::SplitEdge => {
                "add a vertex at the edge's midpoint, joined to the third corner of each triangle beside it"
            }
            Self::SplitFace => "join two corners of a face by a new edge, making a new face (MEF)",
            Self::CollapseEdge => {
                "merge the edge's end into its start at the midpoint, removing the triangles beside it"
            }
            Self::RemoveVertex => "remove an interior vertex and its edges, merging its faces",
            Self::Mev => {
                "make an edge and a vertex: split a vertex, or hang a dangling edge in a face"
            }
            Self::Kev => "kill an edge and a vertex: merge the edge's end into its start",
            Self::Mef => "make an edge and a face: split a face between two of its corners",
            Self::Kef => "kill an edge and a face: merge the two faces beside an edge",
            Self::Kemr => {
                "kill an edge, make a ring: remove a bridge, leaving its inner cycle as a boundary loop"
            }
            Self::Mekr => {
                "make an edge, kill a ring: bridge a face to a boundary loop, which joins the face"
            }
        }
    }

    /// The library algorithm that traces the operation record by record,
    /// in each structure's edits file (`half-edge-edits.alg`,
    /// `winged-edge-edits.alg`), taking the same ids in the same order
    /// (MEV's one edge given twice). Tests hold the two to identical tables.
    pub fn algorithm(self) -> &'static str {
        self.names().1
    }

    /// The ids the operation takes, in order.
    pub fn arguments(self) -> &'static [Argument] {
        match self {
            Self::FlipEdge
            | Self::SplitEdge
            | Self::CollapseEdge
            | Self::Kev
            | Self::Kef
            | Self::Kemr => EDGE,
            Self::SplitFace | Self::Mef => FACE_CUT,
            Self::RemoveVertex => VERTEX,
            Self::Mev => VERTEX_SPLIT,
            Self::Mekr => BRIDGE,
        }
    }

    /// How V, E, F and the boundary loops change, where that is fixed. A
    /// split or collapse depends on how many triangles are beside the edge,
    /// a vertex removal on the vertex's valence.
    pub fn delta(self) -> Option<Delta> {
        match self {
            Self::FlipEdge => Some(delta(0, 0, 0, 0)),
            Self::SplitFace | Self::Mef => Some(delta(0, 1, 1, 0)),
            Self::Mev => Some(delta(1, 1, 0, 0)),
            Self::Kev => Some(delta(-1, -1, 0, 0)),
            Self::Kef => Some(delta(0, -1, -1, 0)),
            Self::Kemr => Some(delta(0, -1, 0, 1)),
            Self::Mekr => Some(delta(0, 1, 0, -1)),
            Self::SplitEdge | Self::CollapseEdge | Self::RemoveVertex => None,
        }
    }

    /// Applies the operation to the ids, in the order
    /// [`arguments`](Self::arguments) lists.
    pub fn run<M: Edit + ?Sized>(
        self,
        editor: &mut Editor<'_, M>,
        ids: &[u32],
    ) -> Result<Applied, Refusal> {
        let arguments = self.arguments();
        let least = arguments.iter().filter(|a| !a.optional).count();
        if ids.len() < least || ids.len() > arguments.len() {
            return Err(Refusal::Arguments {
                operation: self,
                given: ids.len(),
            });
        }
        let id = |i: usize| ids.get(i).copied().unwrap_or_default();
        let (v, f) = (|i| VertexId::new(id(i)), |i| FaceId::new(id(i)));
        let edge = |i| EdgeRow(id(i));
        match self {
            Self::FlipEdge => flip_edge(editor, edge(0)),
            Self::SplitEdge => split_edge(editor, edge(0)),
            Self::SplitFace => split_face(editor, f(0), v(1), v(2)),
            Self::CollapseEdge => collapse_edge(editor, edge(0)),
            Self::RemoveVertex => remove_vertex(editor, v(0)),
            Self::Mev => mev(editor, v(0), edge(1), ids.get(2).map(|&e| EdgeRow(e))),
            Self::Mef => mef(editor, f(0), v(1), v(2)),
            Self::Kev => kev(editor, edge(0)),
            Self::Kef => kef(editor, edge(0)),
            Self::Kemr => kemr(editor, edge(0)),
            Self::Mekr => mekr(editor, f(0), v(1), v(2)),
        }
    }
}

impl fmt::Display for Operation {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// Applies `operation` to the elements `ids` names (see
/// [`Operation::arguments`]), journaling every change.
///
/// ```
/// use edgewise_core::mesh::operations::{self, Operation};
/// use edgewise_core::mesh::{generate, Mesh, Structure};
///
/// let (mut mesh, _) = Mesh::build(&generate::open_square(), Structure::HalfEdge)?;
/// // Half-edge 2 runs along the diagonal from vertex 2 to vertex 0.
/// let applied = operations::apply(&mut mesh, Operation::SplitEdge, &[2])?;
/// assert_eq!(mesh.validate(), vec![]);
/// assert_eq!(applied.made.len(), 9); // a vertex, three edges (six half-edges), two faces
/// let refused = operations::apply(&mut mesh, Operation::FlipEdge, &[0]);
/// assert_eq!(
///     refused.map(drop).map_err(|r| r.to_string()),
///     Err("the edge of half-edge 0 is on the boundary; a flip needs two faces".to_owned())
/// );
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn apply(mesh: &mut Mesh, operation: Operation, ids: &[u32]) -> Result<Applied, Refusal> {
    let mut editor = Editor::new(mesh);
    operation.run(&mut editor, ids)
}

/// Plans an operation on a working copy of the editor's mesh and commits
/// the plan; a refusal while planning leaves the mesh untouched.
fn run<M: Edit + ?Sized>(
    editor: &mut Editor<'_, M>,
    plan: impl FnOnce(&mut Patch<'_, M>) -> Result<(), Refusal>,
) -> Result<Applied, Refusal> {
    let plan = {
        let mut patch = Patch::new(editor.mesh());
        plan(&mut patch)?;
        patch.finish()
    };
    plan.commit(editor)
}
