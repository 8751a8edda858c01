//! Exercises made from a library algorithm's recorded trace.
//!
//! - **Walk**: the student clicks, in order (or in any order, for a set),
//!   the elements the algorithm marks. A wrong click in a sequence is
//!   corrected, the right element taken as done, so the walk goes on.
//! - **Predict**: before each lookup runs, the student says what it gives
//!   (an element, or null).
//!
//! Either way each answer is checked against the trace at once, and the
//! score counts the steps right the first time (TRAKLA2's measure).

use std::collections::BTreeMap;
use std::sync::Arc;

use edgewise_core::lang::{self, Algorithm, RunOptions, StepKind, Type, Value};
use edgewise_core::mesh::operations::candidates;
use edgewise_core::mesh::{Mesh, Structure, VertexId};
use edgewise_core::schema::{ElementKind, ElementRef, Records};
use serde::Deserialize;
use toml::Spanned;

use super::error::{ExerciseError, Located};
use super::seed::Seeded;
use crate::algorithm::library::AlgorithmLibrary;

/// A walk's inputs by name, and what its trace holds to judge.
pub(super) type Drawn = (Vec<(String, ElementRef)>, Expected);

/// At most this many inputs are tried before a draw gives up.
const MAX_TRIES: usize = 500;

/// The fewest elements a drawn walk marks: fewer teaches little.
const LEAST_MARKS: usize = 3;

/// Whether the marks must be clicked in the walk's order.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Order {
    Sequence,
    Set,
}

/// `[walk]` as written.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct WalkFile {
    algorithm: Spanned<String>,
    #[serde(default)]
    args: Option<Spanned<BTreeMap<String, u32>>>,
    #[serde(default)]
    order: Option<Spanned<String>>,
    #[serde(default)]
    lines: Option<Spanned<Vec<u32>>>,
    #[serde(default)]
    visit: Option<Spanned<String>>,
}

/// What a walk follows: the algorithm's marks, or the elements one of its
/// variables holds in turn.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Visit {
    Marks,
    /// The variable's number in the algorithm (parameters first) and name.
    Variable(usize, String),
}

/// What is judged of the trace.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Judged {
    /// Its marks, in this order.
    Marks(Order),
    /// Its lookups (on these lines, or all).
    Lookups(Option<Vec<u32>>),
}

/// One lookup to predict: where it runs, what it asks, what it gives.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Prediction {
    pub line: u32,
    /// `e.successorEdge, where e is half-edge 3`.
    pub question: String,
    pub answer: Option<ElementRef>,
}

/// What the trace holds to judge against.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Expected {
    Marks(Vec<ElementRef>),
    Lookups(Vec<Prediction>),
}

impl Expected {
    fn len(&self) -> usize {
        match self {
            Self::Marks(marks) => marks.len(),
            Self::Lookups(lookups) => lookups.len(),
        }
    }
}

/// The most lookups one instance asks: a long walk is predicted in part.
const MOST_LOOKUPS: usize = 12;

/// A traced task: the library algorithm, the lecturer's own inputs (seed
/// 0) if given, and what of the trace is judged.
#[derive(Clone, Debug)]
pub struct Walk {
    pub algorithm: Arc<Algorithm>,
    pub args: Option<Vec<(String, u32)>>,
    pub judged: Judged,
    pub visit: Visit,
}

impl Walk {
    /// `predict` reads `[predict]` (lookups, on `lines`) instead of
    /// `[walk]` (marks, in `order`).
    pub(super) fn parse(
        at: &Located<'_>,
        file: WalkFile,
        structure: Structure,
        predict: bool,
    ) -> Result<Self, ExerciseError> {
        let algorithm = AlgorithmLibrary::shipped()
            .find_or_explain(file.algorithm.get_ref(), structure)
            .map_err(|message| at.error(Some(file.algorithm.span()), message))?;
        if let Some(param) = algorithm.params().find(|p| element_kind(&p.ty).is_none()) {
            return Err(at.error(
                Some(file.algorithm.span()),
                format!(
                    "`{}` takes `{}`, which is not an element; a walk draws its inputs as \
                     elements",
                    algorithm.name, param.name
                ),
            ));
        }
        let args = match file.args {
            None => None,
            Some(args) => {
                let names: Vec<&str> = algorithm.params().map(|p| p.name.as_str()).collect();
                for name in args.get_ref().keys() {
                    if !names.contains(&name.as_str()) {
                        return Err(at.error(
                            Some(args.span()),
                            format!(
                                "`{}` has no input `{name}`; its inputs are {}",
                                algorithm.name,
                                names.join(", ")
                            ),
                        ));
                    }
                }
                if let Some(missing) = names.iter().find(|n| !args.get_ref().contains_key(**n)) {
                    return Err(at.error(
                        Some(args.span()),
                        format!("`args` leaves out the input `{missing}`"),
                    ));
                }
                Some(args.into_inner().into_iter().collect())
            }
        };
        let order = match file.order.as_ref().map(|o| o.get_ref().as_str()) {
            None | Some("sequence") => Order::Sequence,
            Some("set") => Order::Set,
            Some(other) => {
                return Err(at.error(
                    file.order.as_ref().map(Spanned::span),
                    format!("order `{other}` is not one of sequence, set"),
                ));
            }
        };
        let judged = match (predict, file.lines) {
            (false, None) => Judged::Marks(order),
            (true, lines) => {
                if let Some(order) = &file.order {
                    return Err(at.error(
                        Some(order.span()),
                        "a predict exercise asks its lookups in the run's order; `order` is for \
                         walks",
                    ));
                }
                Judged::Lookups(lines.map(Spanned::into_inner))
            }
            (false, Some(lines)) => {
                return Err(at.error(
                    Some(lines.span()),
                    "`lines` chooses a predict exercise's lookups; a walk judges marks",
                ));
            }
        };
        let visit = match file
            .visit
            .as_ref()
            .map(|v| (v.get_ref().as_str(), v.span()))
        {
            None | Some(("marks", _)) => Visit::Marks,
            Some((_, span)) if predict => {
                return Err(at.error(
                    Some(span),
                    "`visit` is for walks; a prediction asks lookups",
                ));
            }
            Some((text, span)) => {
                let name = text
                    .strip_prefix("variable ")
                    .map(str::trim)
                    .unwrap_or_default();
                let found = algorithm
                    .variables
                    .iter()
                    .position(|v| v.name == name && element_kind(&v.ty).is_some());
                match found {
                    Some(index) => Visit::Variable(index, name.to_owned()),
                    None => {
                        return Err(at.error(
                            Some(span),
                            format!(
                                "visit `{text}` is not `marks` or `variable NAME` naming one of \
                                 `{}`'s element variables",
                                algorithm.name
                            ),
                        ));
                    }
                }
            }
        };
        Ok(Self {
            algorithm,
            args,
            judged,
            visit,
        })
    }

    /// The inputs and what the walk marks, for `seed`: the lecturer's own
    /// inputs for seed 0 where given, else drawn.
    pub(super) fn draw(&self, mesh: &Mesh, seed: u64) -> Result<Drawn, String> {
        let kinds: Vec<(String, ElementKind)> = self
            .algorithm
            .params()
            .filter_map(|p| Some((p.name.clone(), element_kind(&p.ty)?)))
            .collect();
        if let (Some(args), 0) = (&self.args, seed) {
            let inputs: Vec<(String, ElementRef)> = kinds
                .iter()
                .map(|(name, kind)| {
                    let id = args
                        .iter()
                        .find(|(n, _)| n == name)
                        .map_or(0, |(_, id)| *id);
                    (name.clone(), ElementRef::new(*kind, id))
                })
                .collect();
            let expected = self.expected(mesh, &inputs)?;
            if expected.len() == 0 {
                return Err(format!(
                    "{} {} nothing from these inputs",
                    self.algorithm.name,
                    self.verb()
                ));
            }
            return Ok((inputs, expected));
        }
        let mut random = Seeded::new(seed);
        let choices: Vec<Vec<u32>> = kinds
            .iter()
            .map(|(_, kind)| starts(mesh, *kind, &mut random))
            .collect();
        if choices.iter().any(Vec::is_empty) {
            return Err(format!(
                "{} has nowhere to start on this mesh",
                self.algorithm.name
            ));
        }
        for attempt in 0..MAX_TRIES {
            let inputs: Vec<(String, ElementRef)> = kinds
                .iter()
                .zip(&choices)
                .map(|((name, kind), list)| {
                    (
                        name.clone(),
                        ElementRef::new(*kind, list[attempt % list.len()]),
                    )
                })
                .collect();
            if let Ok(expected) = self.expected(mesh, &inputs)
                && expected.len() >= LEAST_MARKS
            {
                return Ok((inputs, expected));
            }
        }
        Err(format!(
            "{} {} fewer than {LEAST_MARKS} elements from every input tried; pick another mesh",
            self.algorithm.name,
            self.verb()
        ))
    }

    fn verb(&self) -> &'static str {
        match self.judged {
            Judged::Marks(_) => "marks",
            Judged::Lookups(_) => "looks up",
        }
    }

    /// What the trace from `inputs` holds to judge: the marks in order, or
    /// the lookups that give an element or null (at most
    /// [`MOST_LOOKUPS`]).
    fn expected(&self, mesh: &Mesh, inputs: &[(String, ElementRef)]) -> Result<Expected, String> {
        let values: Vec<(&str, Value)> = inputs
            .iter()
            .map(|(name, element)| (name.as_str(), Value::from(*element)))
            .collect();
        let trace = lang::run(&self.algorithm, mesh, &values, RunOptions::default())
            .map_err(|err| err.to_string())?;
        if let Some(error) = trace.outcome().error() {
            return Err(error.to_string());
        }
        let lines = match (&self.judged, &self.visit) {
            (Judged::Marks(_), Visit::Marks) => {
                return Ok(Expected::Marks(trace.marked().collect()));
            }
            (Judged::Marks(_), Visit::Variable(variable, _)) => {
                return Ok(Expected::Marks(held(&trace, *variable)));
            }
            (Judged::Lookups(lines), _) => lines,
        };
        let structure = mesh.structure();
        let lookups = (0..trace.len())
            .filter_map(|index| trace.step(index))
            .filter(|step| {
                lines
                    .as_ref()
                    .is_none_or(|lines| lines.contains(&step.line))
            })
            .filter_map(|step| match step.kind {
                StepKind::Lookup {
                    base,
                    field,
                    result,
                } if result == Value::Null || result.element().is_some() => {
                    let base = base.element()?;
                    Some(Prediction {
                        line: step.line,
                        question: format!(
                            "{}.{}",
                            edgewise_core::mesh::Element::of(structure, base),
                            field.lookup_name()
                        ),
                        answer: result.element(),
                    })
                }
                _ => None,
            })
            .take(MOST_LOOKUPS)
            .collect();
        Ok(Expected::Lookups(lookups))
    }
}

/// The elements variable number `variable` of the started algorithm holds
/// in turn (a value assigned again in a row counts once).
fn held(trace: &lang::Trace, variable: usize) -> Vec<ElementRef> {
    let mut held: Vec<ElementRef> = Vec::new();
    for index in 0..trace.len() {
        if trace.depth(index) != Some(0) {
            continue;
        }
        let Some(step) = trace.step(index) else {
            continue;
        };
        if let StepKind::Assign { variable: v, value } = step.kind
            && v == variable
            && let Some(element) = value.element()
            && held.last() != Some(&element)
        {
            held.push(element);
        }
    }
    held
}

/// The table an input of type `ty` names, if it is an element.
fn element_kind(ty: &Type) -> Option<ElementKind> {
    match ty {
        Type::Vertex => Some(ElementKind::Vertex),
        Type::Edge => Some(ElementKind::Edge),
        Type::Face => Some(ElementKind::Face),
        _ => None,
    }
}

/// Where a walk may start, those worth starting from first (a vertex with
/// three edges or more, an edge with a face on each side), each group
/// shuffled: a walk along a boundary finds its boundary edges after the
/// interior ones mark nothing.
fn starts(mesh: &Mesh, kind: ElementKind, random: &mut Seeded) -> Vec<u32> {
    let (mut good, mut rest): (Vec<u32>, Vec<u32>) = (0..mesh.count(kind) as u32)
        .filter(|&id| mesh.contains(ElementRef::new(kind, id)))
        .partition(|&id| match kind {
            ElementKind::Vertex => candidates::edges_at(mesh, VertexId::new(id)).len() >= 3,
            ElementKind::Edge => candidates::interior(mesh, ElementRef::new(kind, id)),
            ElementKind::Face => true,
        });
    random.shuffle(&mut good);
    random.shuffle(&mut rest);
    good.extend(rest);
    good
}

/// One click graded: whether it was right, and what to say.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Click {
    pub right: bool,
    pub feedback: String,
}

/// The clicks of a walk so far.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Clicks {
    /// The elements taken as found, in order (a wrong click in a sequence
    /// adds the right one).
    pub found: Vec<ElementRef>,
    /// Clicks right the first time.
    pub right: usize,
    /// Clicks that were wrong.
    pub wrong: usize,
}

impl Clicks {
    /// Grades one click against what the walk marks; `None` once every
    /// element is found.
    pub fn click(
        &mut self,
        expected: &[ElementRef],
        order: Order,
        element: ElementRef,
        structure: Structure,
    ) -> Option<Click> {
        let name = |e: ElementRef| edgewise_core::mesh::Element::of(structure, e).to_string();
        let total = expected.len();
        match order {
            Order::Sequence => {
                let &wanted = expected.get(self.found.len())?;
                self.found.push(wanted);
                let place = format!("({} of {total})", self.found.len());
                Some(if element == wanted {
                    self.right += 1;
                    Click {
                        right: true,
                        feedback: format!("Right: {} is marked next {place}.", name(element)),
                    }
                } else {
                    self.wrong += 1;
                    Click {
                        right: false,
                        feedback: format!(
                            "Not {}: the walk marks {} next; it is marked for you {place}.",
                            name(element),
                            name(wanted)
                        ),
                    }
                })
            }
            Order::Set => {
                if self.found.len() == total {
                    return None;
                }
                Some(if self.found.contains(&element) {
                    self.wrong += 1;
                    Click {
                        right: false,
                        feedback: format!("{} is found already.", name(element)),
                    }
                } else if expected.contains(&element) {
                    self.found.push(element);
                    self.right += 1;
                    Click {
                        right: true,
                        feedback: format!(
                            "Right: the walk marks {} ({} of {total} found).",
                            name(element),
                            self.found.len()
                        ),
                    }
                } else {
                    self.wrong += 1;
                    Click {
                        right: false,
                        feedback: format!("{} is not among what the walk marks.", name(element)),
                    }
                })
            }
        }
    }

    /// Whether every element is found.
    pub fn done(&self, expected: &[ElementRef]) -> bool {
        self.found.len() >= expected.len()
    }

    /// Grades a prediction of the next lookup (`None`: null); `None` once
    /// every lookup is answered. The run goes on with what the lookup
    /// really gives.
    pub fn predict(
        &mut self,
        lookups: &[Prediction],
        given: Option<ElementRef>,
        structure: Structure,
    ) -> Option<Click> {
        let lookup = lookups.get(self.answered())?;
        let name = |e: Option<ElementRef>| {
            e.map_or_else(
                || "null".to_owned(),
                |e| edgewise_core::mesh::Element::of(structure, e).to_string(),
            )
        };
        let place = format!("({} of {})", self.answered() + 1, lookups.len());
        Some(if given == lookup.answer {
            self.right += 1;
            Click {
                right: true,
                feedback: format!("Right: {} is {} {place}.", lookup.question, name(given)),
            }
        } else {
            self.wrong += 1;
            Click {
                right: false,
                feedback: format!(
                    "Not {}: {} is {} {place}.",
                    name(given),
                    lookup.question,
                    name(lookup.answer)
                ),
            }
        })
    }

    /// How many answers (or clicks) were graded.
    pub fn answered(&self) -> usize {
        self.right + self.wrong
    }
}
