//! Drawing an instance: the task with its ids, from a seed. Every drawn
//! instance applies (the library's operation accepts it) and is worth
//! doing (a flip or split of an edge with a face on each side, a face cut
//! between corners that are not neighbours, a vertex split with three
//! edges or more), so trial and error on one instance gains nothing on
//! the next.

use edgewise_core::mesh::operations::{self, Operation, Refusal, candidates};
use edgewise_core::mesh::{Mesh, Structure, VertexId};
use edgewise_core::schema::{ElementKind, ElementRef};

use super::exercise::{Exercise, ExerciseError, TaskSpec};
use super::seed::Seeded;
use super::walk::{Expected, Judged, Order, Prediction, Visit};

/// At most this many candidates are tried before a draw gives up: enough
/// for every shipped mesh, and bounded on a hostile one.
const MAX_TRIES: usize = 2_000;

/// What the student is asked to do.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Task {
    /// Carry out `operation` on `ids`, as `edgewise edit` names them.
    DoIt { operation: Operation, ids: Vec<u32> },
    /// Click what `algorithm` marks from `args`: `expected`, in order or
    /// as a set.
    Walk {
        algorithm: String,
        args: Vec<(String, ElementRef)>,
        expected: Vec<ElementRef>,
        order: Order,
        /// The variable whose values are walked; `None`: the marks.
        variable: Option<String>,
    },
    /// Say what each of `lookups` gives, in the run's order.
    Predict {
        algorithm: String,
        args: Vec<(String, ElementRef)>,
        lookups: Vec<Prediction>,
    },
}

impl Task {
    /// The task in words, naming rows as `structure`'s tables do.
    pub fn describe(&self, structure: Structure) -> String {
        let (operation, ids) = match self {
            Self::DoIt { operation, ids } => (operation, ids),
            Self::Walk {
                algorithm,
                args,
                order,
                variable,
                ..
            } => {
                let what = variable.as_ref().map_or_else(
                    || "element it marks".to_owned(),
                    |name| format!("element its variable {name} holds"),
                );
                let how = match order {
                    Order::Sequence => format!("in order, each {what}"),
                    Order::Set => format!("in any order, every {what}"),
                };
                return format!(
                    "Walk {algorithm} from {}: click, {how}.",
                    inputs(args, structure)
                );
            }
            Self::Predict {
                algorithm, args, ..
            } => {
                return format!(
                    "Predict {algorithm} from {}: before each lookup runs, click the element it \
                     gives, or answer null.",
                    inputs(args, structure)
                );
            }
        };
        let edge = |id: u32| match structure {
            Structure::HalfEdge => format!("the edge of half-edge {id}"),
            Structure::WingedEdge => format!("edge {id}"),
        };
        let id = |i: usize| ids.get(i).copied().unwrap_or_default();
        match operation {
            Operation::FlipEdge => format!("Flip {}.", edge(id(0))),
            Operation::SplitEdge => format!("Split {} at its midpoint.", edge(id(0))),
            Operation::SplitFace => format!(
                "Split face {} between vertices {} and {}.",
                id(0),
                id(1),
                id(2)
            ),
            Operation::CollapseEdge => format!(
                "Collapse {}: its end merges into its start, at the midpoint.",
                edge(id(0))
            ),
            Operation::RemoveVertex => format!("Remove vertex {}.", id(0)),
            Operation::Mev if ids.len() == 3 => format!(
                "MEV: split vertex {} between {} and {}, making a new vertex and edge.",
                id(0),
                edge(id(1)),
                edge(id(2))
            ),
            Operation::Mev => format!(
                "MEV: hang a new edge and vertex from vertex {}, beside {}.",
                id(0),
                edge(id(1))
            ),
            Operation::Mef => format!(
                "MEF: make an edge from vertex {} to vertex {} across face {}, and a new face.",
                id(1),
                id(2),
                id(0)
            ),
            Operation::Kev => format!(
                "KEV: kill {} and its end vertex, which merges into its start.",
                edge(id(0))
            ),
            Operation::Kef => format!(
                "KEF: kill {} and merge the two faces beside it.",
                edge(id(0))
            ),
            Operation::Kemr => format!(
                "KEMR: kill the bridge {}, leaving its inner cycle as a ring.",
                edge(id(0))
            ),
            Operation::Mekr => format!(
                "MEKR: bridge face {} at vertex {} to the boundary loop at vertex {}.",
                id(0),
                id(1),
                id(2)
            ),
        }
    }
}

/// One instance of an exercise: its seed, its start mesh and its task.
#[derive(Clone, Debug)]
pub struct Instance {
    pub seed: u64,
    pub mesh: Mesh,
    pub task: Task,
}

impl Exercise {
    /// The instance `seed` draws. Seed 0 is the file's own ids where it
    /// gives them; an exercise that draws no fresh instances gives the same
    /// one for every seed.
    pub fn instance(&self, seed: u64) -> Result<Instance, ExerciseError> {
        let seed_used = if self.fresh_instance { seed } else { 0 };
        let do_it = match &self.task {
            TaskSpec::DoIt(do_it) => do_it,
            TaskSpec::Walk(walk) => {
                let (args, expected) =
                    walk.draw(self.start(), seed_used)
                        .map_err(|message| ExerciseError {
                            source: self.name.clone(),
                            at: None,
                            message: format!("[{}]: {message}", self.kind.name()),
                        })?;
                let algorithm = walk.algorithm.name.clone();
                let task = match (expected, &walk.judged) {
                    (Expected::Lookups(lookups), _) => Task::Predict {
                        algorithm,
                        args,
                        lookups,
                    },
                    (Expected::Marks(expected), judged) => Task::Walk {
                        algorithm,
                        args,
                        expected,
                        variable: match &walk.visit {
                            Visit::Marks => None,
                            Visit::Variable(_, name) => Some(name.clone()),
                        },
                        order: match judged {
                            Judged::Marks(order) => *order,
                            Judged::Lookups(_) => Order::Sequence,
                        },
                    },
                };
                return Ok(Instance {
                    seed,
                    mesh: self.start().clone(),
                    task,
                });
            }
        };
        let operation = do_it.operation;
        let ids = match (&do_it.ids, seed_used) {
            (Some(ids), 0) => {
                let mut tried = self.start().clone();
                operations::apply(&mut tried, operation, ids)
                    .map_err(|refusal| self.refused(operation, ids, &refusal))?;
                ids.clone()
            }
            _ => self.draw(operation, seed_used)?,
        };
        Ok(Instance {
            seed,
            mesh: self.start().clone(),
            task: Task::DoIt { operation, ids },
        })
    }

    fn draw(&self, operation: Operation, seed: u64) -> Result<Vec<u32>, ExerciseError> {
        let mesh = self.start();
        let mut all: Vec<Vec<u32>> = candidates(mesh, operation)
            .into_iter()
            .filter(|ids| worth_doing(mesh, operation, ids))
            .collect();
        Seeded::new(seed).shuffle(&mut all);
        all.into_iter()
            .take(MAX_TRIES)
            .find(|ids| operations::apply(&mut mesh.clone(), operation, ids).is_ok())
            .ok_or_else(|| ExerciseError {
                source: self.name.clone(),
                at: None,
                message: format!(
                    "{operation} applies nowhere worth practising on this mesh; pick another mesh"
                ),
            })
    }

    fn refused(&self, operation: Operation, ids: &[u32], refusal: &Refusal) -> ExerciseError {
        let ids: Vec<String> = ids.iter().map(ToString::to_string).collect();
        ExerciseError {
            source: self.name.clone(),
            at: None,
            message: format!(
                "[do-it] ids: {} {} is refused on this mesh: {refusal}",
                operation,
                ids.join(" ")
            ),
        }
    }
}

/// Whether an instance teaches something: see the module notes.
fn worth_doing(mesh: &Mesh, operation: Operation, ids: &[u32]) -> bool {
    let edge = ElementRef::new(ElementKind::Edge, ids.first().copied().unwrap_or_default());
    match operation {
        Operation::FlipEdge | Operation::SplitEdge | Operation::CollapseEdge | Operation::Kef => {
            candidates::interior(mesh, edge)
        }
        Operation::SplitFace | Operation::Mef => match ids {
            [f, u, w] => u != w && !neighbours(mesh, *f, *u, *w),
            _ => false,
        },
        Operation::Mev => match ids {
            [v, x, y] => x != y && valence(mesh, *v) >= 3,
            _ => false,
        },
        Operation::Kev | Operation::RemoveVertex | Operation::Kemr | Operation::Mekr => true,
    }
}

/// Whether `u` and `w` are consecutive corners of face `f`.
fn neighbours(mesh: &Mesh, f: u32, u: u32, w: u32) -> bool {
    let corners = candidates::face_vertices(mesh, edgewise_core::mesh::FaceId::new(f));
    let n = corners.len();
    (0..n).any(|i| {
        let (a, b) = (corners[i], corners[(i + 1) % n]);
        (a, b) == (u, w) || (a, b) == (w, u)
    })
}

fn valence(mesh: &Mesh, v: u32) -> usize {
    candidates::edges_at(mesh, VertexId::new(v)).len()
}

/// A walk's inputs as a sentence names them: `v = vertex 3`.
fn inputs(args: &[(String, ElementRef)], structure: Structure) -> String {
    args.iter()
        .map(|(name, element)| {
            format!(
                "{name} = {}",
                edgewise_core::mesh::Element::of(structure, *element)
            )
        })
        .collect::<Vec<_>>()
        .join(", ")
}
