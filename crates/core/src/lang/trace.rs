//! A recorded run, built for stepping: forward, back, to any step, to the
//! next step on a breakpoint line, or to the end, all without re-running.
//!
//! Each step is stored as 16 bytes: the instruction's index and up to three
//! 32-bit value codes (the register types in the compiled code say how to
//! read them). The variables are snapshotted every [`SNAPSHOT_INTERVAL`]
//! steps, so the state after any step is one snapshot plus at most that many
//! assignments replayed. Marks and highlights are kept in logs ordered by
//! step, so the marked set at any step is a prefix found by binary search.

use super::builtin::Builtin;
use super::compiler::{Algorithm, CompareOp, ComputeOp, Op};
use super::diagnostic::Span;
use super::types::{Type, Value};
use super::vm::Recorder;
use crate::mesh::{Change, Edit, EditError};
use crate::schema::{Column, ElementRef};
use glam::Vec3;
use std::fmt;
use std::sync::Arc;

/// Steps between two variable snapshots.
pub const SNAPSHOT_INTERVAL: usize = 256;

/// One recorded step, as stored.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Step {
    pub pc: u32,
    pub a: u32,
    pub b: u32,
    pub r: u32,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RuntimeErrorKind {
    /// A null lookup, a null mark, a division by zero, an overflow.
    Fault,
    /// The step limit stopped a run that may never end.
    StepLimit,
    /// The algorithm refused (`refuse`): a precondition does not hold.
    Refused,
}

/// An error that stopped a run; the trace keeps every step before it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct RuntimeError {
    pub kind: RuntimeErrorKind,
    pub span: Span,
    pub line: u32,
    pub message: String,
}

impl fmt::Display for RuntimeError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "line {}: {}", self.line, self.message)
    }
}

impl std::error::Error for RuntimeError {}

#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Outcome {
    Finished,
    Error(RuntimeError),
}

impl Outcome {
    pub fn error(&self) -> Option<&RuntimeError> {
        match self {
            Outcome::Finished => None,
            Outcome::Error(error) => Some(error),
        }
    }
}

/// One step as the papers display it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum StepKind<'t> {
    /// A data structure lookup: `base.field` gave `result`.
    Lookup {
        base: Value,
        field: Column,
        result: Value,
    },
    /// Variable number `variable` now refers to `value`.
    Assign {
        variable: usize,
        value: Value,
    },
    Compare {
        op: CompareOp,
        left: Value,
        right: Value,
        result: bool,
    },
    /// Integer or Boolean arithmetic; `right` is `None` for `-` and `not`.
    Compute {
        op: ComputeOp,
        left: Value,
        right: Option<Value>,
        result: Value,
    },
    Mark {
        element: Value,
    },
    Highlight {
        element: Value,
    },
    Message {
        text: &'t str,
    },
    /// `element.field` went from `old` to `new` (a reference, or a
    /// position).
    Write {
        element: Value,
        field: Column,
        old: Value,
        new: Value,
    },
    /// `new Vertex` made `element`.
    New {
        element: Value,
    },
    Delete {
        element: Value,
    },
    /// A built-in function gave `result`.
    Call {
        builtin: Builtin,
        result: Value,
    },
    Done,
}

/// A decoded step with where it happened.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct StepView<'t> {
    /// 0-based; traces print it 1-based.
    pub index: usize,
    pub kind: StepKind<'t>,
    /// The expression or statement that ran, for sub-line highlighting.
    pub span: Span,
    pub line: u32,
}

/// Everything a run did, step by step.
#[derive(Clone, Debug)]
pub struct Trace {
    algorithm: Arc<Algorithm>,
    initial: Vec<Value>,
    steps: Vec<Step>,
    snapshots: Vec<Value>,
    marks: Vec<(u32, ElementRef)>,
    highlights: Vec<(u32, ElementRef)>,
    messages: Vec<String>,
    /// Vector values of steps (their code is an index here).
    vectors: Vec<Vec3>,
    /// Every change to the mesh, with the step that made it, in order.
    changes: Vec<(u32, Change)>,
    final_variables: Vec<Value>,
    outcome: Outcome,
}

pub(crate) struct TraceRecorder {
    variable_count: usize,
    steps: Vec<Step>,
    snapshots: Vec<Value>,
    marks: Vec<(u32, ElementRef)>,
    highlights: Vec<(u32, ElementRef)>,
    messages: Vec<String>,
    vectors: Vec<Vec3>,
}

impl TraceRecorder {
    pub(crate) fn new(variable_count: usize) -> Self {
        Self {
            variable_count,
            steps: Vec::new(),
            snapshots: Vec::new(),
            marks: Vec::new(),
            highlights: Vec::new(),
            messages: Vec::new(),
            vectors: Vec::new(),
        }
    }

    /// A value's 32-bit code; a Vector is stored aside.
    fn encode(&mut self, value: Value) -> u32 {
        match value {
            Value::Vector(v) => {
                self.vectors.push(v);
                u32::try_from(self.vectors.len() - 1).unwrap_or(u32::MAX)
            }
            other => other.code(),
        }
    }

    fn current_step(&self) -> u32 {
        u32::try_from(self.steps.len().saturating_sub(1)).unwrap_or(u32::MAX)
    }

    pub(crate) fn finish(
        self,
        algorithm: Arc<Algorithm>,
        initial: Vec<Value>,
        final_variables: Vec<Value>,
        changes: Vec<(u32, Change)>,
        outcome: Outcome,
    ) -> Trace {
        let mut recorder = self;
        // Growth by doubling can leave half the step buffer unused.
        recorder.steps.shrink_to_fit();
        recorder.snapshots.shrink_to_fit();
        recorder.marks.shrink_to_fit();
        recorder.highlights.shrink_to_fit();
        let recorder = recorder;
        Trace {
            algorithm,
            initial,
            steps: recorder.steps,
            snapshots: recorder.snapshots,
            marks: recorder.marks,
            highlights: recorder.highlights,
            messages: recorder.messages,
            vectors: recorder.vectors,
            changes,
            final_variables,
            outcome,
        }
    }
}

impl Recorder for TraceRecorder {
    #[inline(always)]
    fn step(&mut self, pc: u32, a: Value, b: Value, r: Value, variables: &[Value]) {
        if self.steps.len().is_multiple_of(SNAPSHOT_INTERVAL) {
            self.snapshots.extend_from_slice(variables);
            debug_assert_eq!(variables.len(), self.variable_count);
        }
        let (a, b, r) = (self.encode(a), self.encode(b), self.encode(r));
        self.steps.push(Step { pc, a, b, r });
    }

    // The VM records a mark's step just before calling these.
    fn mark(&mut self, element: ElementRef) {
        let step = self.current_step();
        self.marks.push((step, element));
    }

    fn highlight(&mut self, element: ElementRef) {
        let step = self.current_step();
        self.highlights.push((step, element));
    }

    fn message(&mut self, text: String) -> u32 {
        self.messages.push(text);
        u32::try_from(self.messages.len() - 1).unwrap_or(u32::MAX)
    }
}

/// Reads a step's 32-bit code back as a value of a register's type.
struct Decoder<'t> {
    ty: Type,
    vectors: &'t [Vec3],
}

impl Decoder<'_> {
    fn decode(&self, code: u32) -> Value {
        match self.ty {
            Type::Vector => self
                .vectors
                .get(code as usize)
                .map_or(Value::Null, |&v| Value::Vector(v)),
            ty => ty.decode(code),
        }
    }
}

impl Trace {
    pub fn algorithm(&self) -> &Arc<Algorithm> {
        &self.algorithm
    }

    /// The number of steps recorded.
    pub fn len(&self) -> usize {
        self.steps.len()
    }

    pub fn is_empty(&self) -> bool {
        self.steps.is_empty()
    }

    pub fn outcome(&self) -> &Outcome {
        &self.outcome
    }

    /// Decodes step `index`.
    pub fn step(&self, index: usize) -> Option<StepView<'_>> {
        let step = *self.steps.get(index)?;
        let instr = self.algorithm.code.get(step.pc as usize)?;
        let ty = |reg| Decoder {
            ty: self.algorithm.register_type(reg),
            vectors: &self.vectors,
        };
        let kind = match instr.op {
            Op::Write { base, field, .. } => {
                let column = Decoder {
                    ty: field.target().map_or(Type::Vector, Type::of_kind),
                    vectors: &self.vectors,
                };
                StepKind::Write {
                    element: ty(base).decode(step.a),
                    field,
                    old: column.decode(step.b),
                    new: column.decode(step.r),
                }
            }
            Op::New { dst, .. } => StepKind::New {
                element: ty(dst).decode(step.r),
            },
            Op::Delete { element } => StepKind::Delete {
                element: ty(element).decode(step.a),
            },
            Op::Call { dst, builtin, .. } => StepKind::Call {
                builtin,
                result: ty(dst).decode(step.r),
            },
            Op::Lookup { dst, base, field } => StepKind::Lookup {
                base: ty(base).decode(step.a),
                field,
                result: ty(dst).decode(step.r),
            },
            Op::Assign { var, .. } => StepKind::Assign {
                variable: usize::from(var),
                value: ty(var).decode(step.r),
            },
            Op::Compare {
                op, left, right, ..
            } => StepKind::Compare {
                op,
                left: ty(left).decode(step.a),
                right: ty(right).decode(step.b),
                result: step.r != 0,
            },
            Op::Compute {
                dst,
                op,
                left,
                right,
            } => StepKind::Compute {
                op,
                left: ty(left).decode(step.a),
                right: (!op.is_unary()).then(|| ty(right).decode(step.b)),
                result: ty(dst).decode(step.r),
            },
            Op::Mark { element } => StepKind::Mark {
                element: ty(element).decode(step.a),
            },
            Op::Highlight { element } => StepKind::Highlight {
                element: ty(element).decode(step.a),
            },
            Op::Message { .. } => StepKind::Message {
                text: self
                    .messages
                    .get(step.a as usize)
                    .map_or("", String::as_str),
            },
            Op::Done
            | Op::Refuse { .. }
            | Op::Move { .. }
            | Op::Jump { .. }
            | Op::JumpIf { .. } => StepKind::Done,
        };
        Some(StepView {
            index,
            kind,
            span: instr.span,
            line: instr.line,
        })
    }

    /// The source line of step `index`.
    pub fn line(&self, index: usize) -> Option<u32> {
        let step = self.steps.get(index)?;
        self.algorithm.code.get(step.pc as usize).map(|i| i.line)
    }

    /// Every change the run made to the mesh, oldest first.
    pub fn changes(&self) -> impl ExactSizeIterator<Item = &Change> + '_ {
        self.changes.iter().map(|(_, change)| change)
    }

    /// How many changes were made up to and including step `index`
    /// (`None`: before the first step).
    pub fn changes_through(&self, index: Option<usize>) -> usize {
        match index {
            None => 0,
            Some(index) => self
                .changes
                .partition_point(|&(step, _)| step as usize <= index),
        }
    }

    /// The changes step `index` made.
    pub fn changes_at(&self, index: usize) -> impl Iterator<Item = &Change> + '_ {
        let start = self
            .changes
            .partition_point(|&(step, _)| (step as usize) < index);
        self.changes
            .get(start..)
            .unwrap_or(&[])
            .iter()
            .take_while(move |&&(step, _)| step as usize == index)
            .map(|(_, change)| change)
    }

    /// Moves `mesh` from the state after `from` changes to the state after
    /// `to` changes (counts from [`Self::changes_through`]), applying or
    /// reverting changes in order.
    pub fn seek<M: Edit + ?Sized>(
        &self,
        mesh: &mut M,
        from: usize,
        to: usize,
    ) -> Result<(), EditError> {
        if to >= from {
            for (_, change) in self.changes.get(from..to).unwrap_or(&[]) {
                change.apply(mesh)?;
            }
        } else {
            for (_, change) in self.changes.get(to..from).unwrap_or(&[]).iter().rev() {
                change.revert(mesh)?;
            }
        }
        Ok(())
    }

    /// The variables (parameters first) before the first step.
    pub fn initial_variables(&self) -> &[Value] {
        &self.initial
    }

    /// The variables when the run stopped.
    pub fn final_variables(&self) -> &[Value] {
        &self.final_variables
    }

    /// The variables right after step `index`: one snapshot plus at most
    /// [`SNAPSHOT_INTERVAL`] assignments replayed.
    pub fn variables_at(&self, index: usize) -> Vec<Value> {
        if index >= self.steps.len() {
            return self.final_variables.clone();
        }
        let count = self.initial.len();
        let block = index / SNAPSHOT_INTERVAL;
        let mut state = self
            .snapshots
            .get(block * count..(block + 1) * count)
            .map_or_else(|| self.initial.clone(), <[Value]>::to_vec);
        for step in self
            .steps
            .get(block * SNAPSHOT_INTERVAL..=index)
            .unwrap_or(&[])
        {
            if let Some(Op::Assign { var, .. }) =
                self.algorithm.code.get(step.pc as usize).map(|i| i.op)
                && let Some(slot) = state.get_mut(usize::from(var))
            {
                *slot = Decoder {
                    ty: self.algorithm.register_type(var),
                    vectors: &self.vectors,
                }
                .decode(step.r);
            }
        }
        state
    }

    /// The elements marked up to and including step `index`, in marking order.
    pub fn marked_at(&self, index: usize) -> impl Iterator<Item = ElementRef> + '_ {
        let end = self
            .marks
            .partition_point(|&(step, _)| step as usize <= index);
        self.marks.get(..end).unwrap_or(&[]).iter().map(|&(_, e)| e)
    }

    /// Every element marked in the run, in marking order.
    pub fn marked(&self) -> impl Iterator<Item = ElementRef> + '_ {
        self.marks.iter().map(|&(_, e)| e)
    }

    pub fn highlighted_at(&self, index: usize) -> impl Iterator<Item = ElementRef> + '_ {
        let end = self
            .highlights
            .partition_point(|&(step, _)| step as usize <= index);
        self.highlights
            .get(..end)
            .unwrap_or(&[])
            .iter()
            .map(|&(_, e)| e)
    }

    /// The text of the latest `message` at or before step `index`.
    pub fn message_at(&self, index: usize) -> Option<&str> {
        let last = index.min(self.steps.len().checked_sub(1)?);
        (0..=last).rev().find_map(|i| match self.step(i)?.kind {
            StepKind::Message { text } => Some(text),
            _ => None,
        })
    }

    /// The first step after `from` on source line `line` (a breakpoint),
    /// if any.
    pub fn next_on_line(&self, from: usize, line: u32) -> Option<usize> {
        let code = &self.algorithm.code;
        let start = from.checked_add(1)?;
        let rest = self.steps.get(start..)?;
        rest.iter()
            .position(|s| code.get(s.pc as usize).is_some_and(|i| i.line == line))
            .map(|p| p + start)
    }

    /// The last step before `from` on `line`, for stepping back to a breakpoint.
    pub fn previous_on_line(&self, from: usize, line: u32) -> Option<usize> {
        let code = &self.algorithm.code;
        let before = self.steps.get(..from.min(self.steps.len()))?;
        before
            .iter()
            .rposition(|s| code.get(s.pc as usize).is_some_and(|i| i.line == line))
    }

    /// Bytes held by the trace's step data, snapshots and logs (not counting
    /// message texts), for the memory figure in the documentation.
    pub fn memory_bytes(&self) -> usize {
        use std::mem::size_of;
        self.steps.capacity() * size_of::<Step>()
            + self.snapshots.capacity() * size_of::<Value>()
            + self.vectors.capacity() * size_of::<Vec3>()
            + self.changes.capacity() * size_of::<(u32, Change)>()
            + (self.marks.capacity() + self.highlights.capacity()) * size_of::<(u32, ElementRef)>()
    }

    /// One line per step, as `edgewise trace` prints it:
    /// `step 12  line 10  lookup e.startVertex -> vertex 1`.
    pub fn render_line(&self, index: usize) -> String {
        let Some(view) = self.step(index) else {
            return String::new();
        };
        let step = self.steps.get(index).copied();
        let snippet = step
            .and_then(|s| self.algorithm.code.get(s.pc as usize))
            .map(|i| self.algorithm.snippet(i.span))
            .unwrap_or_default();
        let what = match view.kind {
            StepKind::Lookup { result, .. } => format!("lookup {snippet} -> {result}"),
            StepKind::Assign { variable, value } => {
                let name = self
                    .algorithm
                    .variables
                    .get(variable)
                    .map_or("?", |v| v.name.as_str());
                format!("assign {name} := {value}")
            }
            StepKind::Compare {
                op,
                left,
                right,
                result,
            } => {
                format!(
                    "compare {snippet} ({left} {} {right}) -> {result}",
                    op.symbol()
                )
            }
            StepKind::Compute {
                op,
                left,
                right: Some(right),
                result,
            } => {
                format!(
                    "compute {snippet} ({left} {} {right}) -> {result}",
                    op.symbol()
                )
            }
            StepKind::Compute {
                op,
                left,
                right: None,
                result,
            } => {
                format!("compute {snippet} ({} {left}) -> {result}", op.symbol())
            }
            StepKind::Mark { element } => format!("mark {element}"),
            StepKind::Highlight { element } => format!("highlight {element}"),
            StepKind::Message { text } => format!("message \"{text}\""),
            StepKind::Write {
                element,
                field,
                old,
                new,
            } => {
                let field = field.language_name().unwrap_or(field.record_name());
                format!("write {element}.{field} := {new} (was {old})")
            }
            StepKind::New { element } => format!("new {element}"),
            StepKind::Delete { element } => format!("delete {element}"),
            StepKind::Call { result, .. } => format!("call {snippet} -> {result}"),
            StepKind::Done => "done".to_owned(),
        };
        format!("step {}  line {}  {what}", index + 1, view.line)
    }

    /// `marked: edge 0, edge 5, edge 1`, or `marked:` when nothing was.
    pub fn render_marked(&self) -> String {
        let marked: Vec<String> = self.marked().map(|e| e.to_string()).collect();
        if marked.is_empty() {
            "marked:".to_owned()
        } else {
            format!("marked: {}", marked.join(", "))
        }
    }

    /// The whole trace as `edgewise trace` prints it: every step, the marked
    /// line, and `error: …` if the run stopped on an error.
    pub fn render(&self) -> String {
        let mut out = String::new();
        for index in 0..self.steps.len() {
            out.push_str(&self.render_line(index));
            out.push('\n');
        }
        out.push_str(&self.render_marked());
        out.push('\n');
        if let Some(error) = self.outcome.error() {
            out.push_str(&format!("error: {error}\n"));
        }
        out
    }
}
