//! A recorded run, built for stepping: forward, back, to any step, to the
//! next step on a breakpoint line, over or out of a call, or to the end,
//! all without re-running.
//!
//! Each step is stored as 16 bytes: the instruction's index and up to three
//! 32-bit value codes (the register types in the compiled code say how to
//! read them). Calls are stored beside the steps, not in them: a frame
//! record per call (its algorithm, caller and depth), and a segment list
//! that says which frame each run of consecutive steps belongs to, found by
//! binary search; a run without calls has one segment.
//!
//! A frame starts from its algorithm's initial variables, and only those
//! that start otherwise (its parameters and arrays) are stored for it, so a
//! call of an algorithm with hundreds of variables costs a few bytes, not
//! hundreds of values. Its variables are then snapshotted every
//! [`SNAPSHOT_INTERVAL`] of its own steps, or every as many steps as it has
//! variables if that is more, so snapshots never cost more than one value a
//! step; its state after any step is one snapshot plus at most that many of
//! its assignments replayed.
//! Arrays are logged the same way as the mesh: each array's changes (an
//! append, or an item replaced with the old item kept) with the step that
//! made them, so its items at any step are its changes up to that step
//! replayed, forwards and backwards alike. Marks and highlights are kept in
//! logs ordered by step, so the marked set at any step is a prefix found by
//! binary search.

use super::builtin::Builtin;
use super::compiler::{Algorithm, CompareOp, ComputeOp, Op, Routine, VariableInfo};
use super::diagnostic::Span;
use super::recorder::{Held, Recorder, extend_counted, push_counted};
use super::types::{Type, Value, show_items};
use crate::mesh::{Change, Edit, EditError};
use crate::schema::{Column, ElementRef};
use glam::Vec3;
use std::fmt;
use std::sync::Arc;

/// A frame's own steps between two snapshots of its variables, at least.
pub const SNAPSHOT_INTERVAL: usize = 256;

/// The own steps after which a frame with `count` variables is snapshotted
/// again: a snapshot's values never outnumber the steps between two.
fn snapshot_interval(count: usize) -> usize {
    count.max(SNAPSHOT_INTERVAL)
}

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
    /// The run would have needed more memory than its budget.
    MemoryLimit,
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
    /// A call of another algorithm of the file; `frame` (see
    /// [`Trace::frames_at`]) runs it from the next step, one level deeper.
    Invoke {
        algorithm: &'t str,
        frame: usize,
    },
    /// Back to the caller, from `return` or the algorithm's `end`, with the
    /// value returned if there is one. The started algorithm's `return`
    /// goes on to its `done`.
    Return {
        value: Option<Value>,
    },
    /// `array[index]` gave `result`.
    Index {
        array: Value,
        index: i32,
        result: Value,
    },
    /// `array[index] := new`, replacing `old`.
    Store {
        array: Value,
        index: i32,
        old: Value,
        new: Value,
    },
    /// `append(array, value)`; the array now has `length` items.
    Append {
        array: Value,
        value: Value,
        length: i32,
    },
    Done,
}

impl StepKind<'_> {
    /// The value the step produced: what a lookup, comparison or
    /// computation gave, what was assigned, marked, written or made. `None`
    /// for a message, a call's start, a bare return and the end.
    pub fn outcome(&self) -> Option<Value> {
        match *self {
            StepKind::Lookup { result, .. }
            | StepKind::Compute { result, .. }
            | StepKind::Call { result, .. }
            | StepKind::Index { result, .. } => Some(result),
            StepKind::Assign { value, .. } | StepKind::Append { value, .. } => Some(value),
            StepKind::Compare { result, .. } => Some(Value::Boolean(result)),
            StepKind::Mark { element }
            | StepKind::Highlight { element }
            | StepKind::New { element }
            | StepKind::Delete { element } => Some(element),
            StepKind::Write { new, .. } | StepKind::Store { new, .. } => Some(new),
            StepKind::Return { value } => value,
            StepKind::Message { .. } | StepKind::Invoke { .. } | StepKind::Done => None,
        }
    }
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

/// One frame of the call stack at a step: the started algorithm or a call.
#[derive(Clone, Debug)]
pub struct FrameView<'t> {
    /// The algorithm it runs.
    pub name: &'t str,
    pub routine: &'t Routine,
    /// 0 for the started algorithm, 1 for what it calls, and so on.
    pub depth: usize,
    /// The caller's step that made the call, and its line; `None` for the
    /// started algorithm.
    pub call_step: Option<usize>,
    pub call_line: Option<u32>,
    /// Its variables (parameters first) right after the step.
    pub variables: Vec<(&'t VariableInfo, Value)>,
}

/// Calls deeper than this are indented no further in a rendered trace
/// (their depth is written instead), so a deep recursion stays readable.
const MAX_INDENT: usize = 16;

/// Frames' `parent` and `call_step` where there is none.
const NONE: u32 = u32::MAX;

/// One run of an algorithm: the started one (frame 0) or a call.
#[derive(Clone, Debug, Default)]
struct FrameRecord {
    routine: u32,
    parent: u32,
    depth: u32,
    call_step: u32,
    /// The index of its first step.
    first: u32,
    /// The variables it started with other values than its algorithm's
    /// initial ones: `entry_len` of the entries from `entry` on.
    entry: u32,
    entry_len: u32,
    /// How many variables it has.
    count: u32,
    /// Later snapshots: the step each was taken before, and where its
    /// values are.
    snapshots: Vec<(u32, u32)>,
}

/// Every frame: the started algorithm's (0) apart, so that a run without
/// calls allocates nothing for frames, then the calls, numbered from 1.
#[derive(Clone, Debug, Default)]
struct Frames {
    root: FrameRecord,
    calls: Vec<FrameRecord>,
}

impl Frames {
    fn get(&self, id: usize) -> Option<&FrameRecord> {
        match id.checked_sub(1) {
            None => Some(&self.root),
            Some(call) => self.calls.get(call),
        }
    }

    fn get_mut(&mut self, id: usize) -> Option<&mut FrameRecord> {
        match id.checked_sub(1) {
            None => Some(&mut self.root),
            Some(call) => self.calls.get_mut(call),
        }
    }

    fn len(&self) -> usize {
        self.calls.len() + 1
    }
}

/// From step `start` on, until the next segment, the steps are `frame`'s.
#[derive(Clone, Copy, Debug)]
struct Segment {
    start: u32,
    frame: u32,
}

/// The segments of a run without calls, which keeps none.
const ROOT_ONLY: [Segment; 1] = [Segment { start: 0, frame: 0 }];

/// One array's history: its item type and every change, in step order.
#[derive(Clone, Debug)]
struct ArrayLog {
    item: Type,
    changes: Vec<ArrayChange>,
}

/// Item `index` became `new` at `step` (codes of the item type), replacing
/// `old`, or was appended.
#[derive(Clone, Copy, Debug)]
struct ArrayChange {
    step: u32,
    index: u32,
    old: u32,
    new: u32,
    appended: bool,
}

/// Everything a run did, step by step.
#[derive(Clone, Debug)]
pub struct Trace {
    algorithm: Arc<Algorithm>,
    steps: Vec<Step>,
    frames: Frames,
    /// Empty when the run made no call: every step is frame 0's.
    segments: Vec<Segment>,
    /// The values of every frame's snapshots.
    values: Vec<Value>,
    /// The variables every frame started with that differ from its
    /// algorithm's initial ones.
    entries: Vec<(u32, Value)>,
    arrays: Vec<ArrayLog>,
    marks: Vec<(u32, ElementRef)>,
    highlights: Vec<(u32, ElementRef)>,
    messages: Vec<String>,
    /// Vector values of steps (their code is an index here).
    vectors: Vec<Vec3>,
    /// Every change to the mesh, with the step that made it, in order.
    changes: Vec<(u32, Change)>,
    final_variables: Vec<Value>,
    result: Option<Value>,
    outcome: Outcome,
}

#[derive(Default)]
pub(crate) struct TraceRecorder {
    steps: Vec<Step>,
    frames: Frames,
    /// Whether the started algorithm's frame has begun.
    started: bool,
    segments: Vec<Segment>,
    values: Vec<Value>,
    entries: Vec<(u32, Value)>,
    arrays: Vec<ArrayLog>,
    marks: Vec<(u32, ElementRef)>,
    highlights: Vec<(u32, ElementRef)>,
    messages: Vec<String>,
    vectors: Vec<Vec3>,
    /// The callers of the running frame, outermost first, each with how
    /// many of its own steps remain until its next snapshot.
    callers: Vec<(u32, usize)>,
    /// The running frame, its number of variables, and the step before
    /// which it is snapshotted next.
    frame: u32,
    count: usize,
    due: usize,
    /// Bytes held by every buffer above but `steps`, counted as they grow,
    /// and by the messages' texts.
    held: usize,
    message_bytes: usize,
}

fn index_u32(n: usize) -> u32 {
    u32::try_from(n).unwrap_or(u32::MAX)
}

impl TraceRecorder {
    /// A value's 32-bit code; a Vector is stored aside.
    fn encode(&mut self, value: Value) -> u32 {
        match value {
            Value::Vector(v) => {
                push_counted(&mut self.vectors, v, &mut self.held);
                index_u32(self.vectors.len() - 1)
            }
            other => other.code(),
        }
    }

    fn current_step(&self) -> u32 {
        index_u32(self.steps.len().saturating_sub(1))
    }

    /// Snapshots the running frame's variables before the next step; the
    /// next one is due [`snapshot_interval`] of its own steps later.
    #[cold]
    fn snapshot(&mut self, variables: &[Value]) {
        let offset = index_u32(self.values.len());
        extend_counted(&mut self.values, variables, &mut self.held);
        let step = index_u32(self.steps.len());
        if let Some(frame) = self.frames.get_mut(self.frame as usize) {
            push_counted(&mut frame.snapshots, (step, offset), &mut self.held);
        }
        self.due = self.steps.len() + snapshot_interval(self.count);
    }

    /// Starts a segment of the running frame's steps at the next step.
    fn segment(&mut self) {
        let start = index_u32(self.steps.len());
        let frame = self.frame;
        if self.segments.is_empty() {
            extend_counted(&mut self.segments, &ROOT_ONLY, &mut self.held);
        }
        match self.segments.last_mut() {
            // A frame that made no step owns none.
            Some(last) if last.start == start => last.frame = frame,
            _ => push_counted(&mut self.segments, Segment { start, frame }, &mut self.held),
        }
    }

    pub(crate) fn finish(
        self,
        algorithm: Arc<Algorithm>,
        final_variables: Vec<Value>,
        changes: Vec<(u32, Change)>,
        result: Option<Value>,
        outcome: Outcome,
    ) -> Trace {
        let mut recorder = self;
        // Growth by doubling can leave half the step buffer unused.
        recorder.steps.shrink_to_fit();
        recorder.values.shrink_to_fit();
        recorder.marks.shrink_to_fit();
        recorder.highlights.shrink_to_fit();
        recorder.frames.calls.shrink_to_fit();
        recorder.segments.shrink_to_fit();
        recorder.entries.shrink_to_fit();
        let recorder = recorder;
        Trace {
            algorithm,
            steps: recorder.steps,
            frames: recorder.frames,
            segments: recorder.segments,
            values: recorder.values,
            entries: recorder.entries,
            arrays: recorder.arrays,
            marks: recorder.marks,
            highlights: recorder.highlights,
            messages: recorder.messages,
            vectors: recorder.vectors,
            changes,
            final_variables,
            result,
            outcome,
        }
    }
}

impl Recorder for TraceRecorder {
    #[inline(always)]
    fn step(&mut self, pc: u32, a: Value, b: Value, r: Value, variables: &[Value]) {
        if self.steps.len() == self.due {
            self.snapshot(variables);
        }
        let (a, b, r) = (self.encode(a), self.encode(b), self.encode(r));
        self.steps.push(Step { pc, a, b, r });
    }

    fn enter(&mut self, routine: u32, variables: &[Value], initial: &[Value]) {
        let root = !self.started;
        let (parent, call_step) = if root {
            (NONE, NONE)
        } else {
            let left = self.due.saturating_sub(self.steps.len());
            push_counted(&mut self.callers, (self.frame, left), &mut self.held);
            (self.frame, self.current_step())
        };
        let entry = index_u32(self.entries.len());
        for (number, (&value, initial)) in variables.iter().zip(initial).enumerate() {
            if value != *initial {
                push_counted(
                    &mut self.entries,
                    (index_u32(number), value),
                    &mut self.held,
                );
            }
        }
        let record = FrameRecord {
            routine,
            parent,
            depth: index_u32(self.callers.len()),
            call_step,
            first: index_u32(self.steps.len()),
            entry,
            entry_len: index_u32(self.entries.len()) - entry,
            count: index_u32(variables.len()),
            snapshots: Vec::new(),
        };
        self.count = variables.len();
        self.due = self.steps.len() + snapshot_interval(self.count);
        if root {
            self.started = true;
            self.frames.root = record;
            self.frame = 0;
        } else {
            push_counted(&mut self.frames.calls, record, &mut self.held);
            self.frame = index_u32(self.frames.calls.len());
            self.segment();
        }
    }

    fn leave(&mut self) {
        if let Some((frame, left)) = self.callers.pop() {
            self.frame = frame;
            self.count = self
                .frames
                .get(frame as usize)
                .map_or(0, |f| f.count as usize);
            self.due = self.steps.len() + left;
            self.segment();
        }
    }

    fn array_created(&mut self, item: Type) {
        let log = ArrayLog {
            item,
            changes: Vec::new(),
        };
        push_counted(&mut self.arrays, log, &mut self.held);
    }

    // The VM records the step just before calling this, as for marks.
    fn array_changed(&mut self, array: u32, index: u32, old: Option<Value>, new: Value) {
        let step = self.current_step();
        let appended = old.is_none();
        let old = old.map_or(0, |old| self.encode(old));
        let new = self.encode(new);
        if let Some(log) = self.arrays.get_mut(array as usize) {
            let change = ArrayChange {
                step,
                index,
                old,
                new,
                appended,
            };
            push_counted(&mut log.changes, change, &mut self.held);
        }
    }

    fn mark(&mut self, element: ElementRef) {
        let step = self.current_step();
        push_counted(&mut self.marks, (step, element), &mut self.held);
    }

    fn highlight(&mut self, element: ElementRef) {
        let step = self.current_step();
        push_counted(&mut self.highlights, (step, element), &mut self.held);
    }

    fn message(&mut self, text: String) -> u32 {
        self.message_bytes += text.capacity();
        push_counted(&mut self.messages, text, &mut self.held);
        index_u32(self.messages.len() - 1)
    }

    fn bytes(&self) -> Held {
        Held {
            messages: self.message_bytes,
            other: self.held + self.steps.capacity() * size_of::<Step>(),
        }
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

    /// What the started algorithm returned, if it returned a value.
    pub fn result(&self) -> Option<Value> {
        self.result
    }

    fn decoder(&self, ty: Type) -> Decoder<'_> {
        Decoder {
            ty,
            vectors: &self.vectors,
        }
    }

    /// The frame step `index` belongs to.
    fn frame_of(&self, index: usize) -> usize {
        let after = self.segments.partition_point(|s| s.start as usize <= index);
        after
            .checked_sub(1)
            .and_then(|i| self.segments.get(i))
            .map_or(0, |s| s.frame as usize)
    }

    /// The segments, with the one a run without calls leaves implicit.
    fn segments(&self) -> &[Segment] {
        if self.segments.is_empty() {
            &ROOT_ONLY
        } else {
            &self.segments
        }
    }

    fn routine_of(&self, frame: usize) -> Option<&Routine> {
        let record = self.frames.get(frame)?;
        self.algorithm.routines().get(record.routine as usize)
    }

    /// The frame a call step started.
    fn called_frame(&self, index: usize) -> Option<usize> {
        let calls = &self.frames.calls;
        let at = calls.partition_point(|f| (f.call_step as usize) < index);
        calls
            .get(at)
            .filter(|f| f.call_step as usize == index)
            .map(|_| at + 1)
    }

    /// The algorithm step `index` ran in, with the step and its instruction.
    fn located(&self, index: usize) -> Option<(&Routine, Step, &super::compiler::Instr)> {
        let step = *self.steps.get(index)?;
        let routine = self.routine_of(self.frame_of(index))?;
        let instr = routine.code.get(step.pc as usize)?;
        Some((routine, step, instr))
    }

    /// How deep in calls step `index` ran: 0 in the started algorithm.
    pub fn depth(&self, index: usize) -> Option<usize> {
        if index >= self.steps.len() {
            return None;
        }
        let frame = self.frames.get(self.frame_of(index))?;
        Some(frame.depth as usize)
    }

    /// The algorithm step `index` ran in.
    pub fn routine_at(&self, index: usize) -> Option<&Routine> {
        self.located(index).map(|(routine, _, _)| routine)
    }

    /// Decodes step `index`.
    pub fn step(&self, index: usize) -> Option<StepView<'_>> {
        let (routine, step, instr) = self.located(index)?;
        let ty = |reg| self.decoder(routine.register_type(reg));
        let item = |reg| self.decoder(routine.register_type(reg).item().unwrap_or(Type::Null));
        let kind = match instr.op {
            Op::Write { base, field, .. } => {
                let column = self.decoder(field.target().map_or(Type::Vector, Type::of_kind));
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
            Op::Length { .. } => StepKind::Call {
                builtin: Builtin::Length,
                result: Type::Integer.decode(step.r),
            },
            Op::Invoke {
                routine: number, ..
            } => StepKind::Invoke {
                algorithm: self
                    .algorithm
                    .routines()
                    .get(usize::from(number))
                    .map_or("", |r| r.name.as_str()),
                frame: self.called_frame(index).unwrap_or(0),
            },
            Op::Return { value, .. } => StepKind::Return {
                value: value.then(|| {
                    self.decoder(routine.result.unwrap_or(Type::Null))
                        .decode(step.a)
                }),
            },
            Op::Index { dst, array, .. } => StepKind::Index {
                array: ty(array).decode(step.a),
                index: step.b.cast_signed(),
                result: ty(dst).decode(step.r),
            },
            Op::Store { array, .. } => StepKind::Store {
                array: ty(array).decode(step.a),
                index: step.b.cast_signed(),
                old: self
                    .array_change(step.a, index)
                    .map_or(Value::Null, |change| item(array).decode(change.old)),
                new: item(array).decode(step.r),
            },
            Op::Append { array, .. } => StepKind::Append {
                array: ty(array).decode(step.a),
                value: item(array).decode(step.r),
                length: step.b.cast_signed(),
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
            // A call that reaches its `end` returns.
            Op::Done if self.depth(index).unwrap_or(0) > 0 => StepKind::Return { value: None },
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

    /// The change array `array` logged at step `index`.
    fn array_change(&self, array: u32, index: usize) -> Option<&ArrayChange> {
        let changes = &self.arrays.get(array as usize)?.changes;
        let at = changes.partition_point(|c| (c.step as usize) < index);
        changes.get(at).filter(|c| c.step as usize == index)
    }

    /// The source line of step `index`.
    pub fn line(&self, index: usize) -> Option<u32> {
        self.located(index).map(|(_, _, instr)| instr.line)
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

    /// The started algorithm's variables (parameters first) before the
    /// first step.
    pub fn initial_variables(&self) -> Vec<Value> {
        self.routine_of(0)
            .map(|routine| self.entry_variables(&self.frames.root, routine))
            .unwrap_or_default()
    }

    /// The started algorithm's variables when the run stopped.
    pub fn final_variables(&self) -> &[Value] {
        &self.final_variables
    }

    /// The started algorithm's variables right after step `index` (calls
    /// change them only by what they return): one snapshot plus at most
    /// [`SNAPSHOT_INTERVAL`] assignments replayed.
    pub fn variables_at(&self, index: usize) -> Vec<Value> {
        if index >= self.steps.len() {
            return self.final_variables.clone();
        }
        self.frame_variables(0, index)
    }

    /// Frame `frame`'s variables right after step `index`: its latest
    /// snapshot then its own assignments since, skipping the steps of the
    /// calls it made.
    fn frame_variables(&self, frame: usize, index: usize) -> Vec<Value> {
        let Some(record) = self.frames.get(frame) else {
            return Vec::new();
        };
        let Some(routine) = self.routine_of(frame) else {
            return Vec::new();
        };
        let later = record
            .snapshots
            .partition_point(|&(step, _)| step as usize <= index);
        let snapshot = later
            .checked_sub(1)
            .and_then(|i| record.snapshots.get(i))
            .copied();
        let count = record.count as usize;
        let (from, mut state) = match snapshot {
            Some((from, offset)) => {
                let offset = offset as usize;
                let state = self.values.get(offset..offset + count);
                (from, state.map_or_else(Vec::new, <[Value]>::to_vec))
            }
            None => (record.first, self.entry_variables(record, routine)),
        };
        for (range, owner) in self.runs(from as usize..index.saturating_add(1)) {
            if owner != frame {
                continue;
            }
            for step in self.steps.get(range).unwrap_or(&[]) {
                if let Some(Op::Assign { var, .. }) =
                    routine.code.get(step.pc as usize).map(|i| i.op)
                    && let Some(slot) = state.get_mut(usize::from(var))
                {
                    *slot = self.decoder(routine.register_type(var)).decode(step.r);
                }
            }
        }
        state
    }

    /// A frame's variables as it started: its algorithm's initial ones,
    /// with those it started otherwise.
    fn entry_variables(&self, record: &FrameRecord, routine: &Routine) -> Vec<Value> {
        let mut state = routine
            .initial
            .get(..record.count as usize)
            .map_or_else(Vec::new, <[Value]>::to_vec);
        let start = record.entry as usize;
        let entries = self.entries.get(start..start + record.entry_len as usize);
        for &(number, value) in entries.unwrap_or(&[]) {
            if let Some(slot) = state.get_mut(number as usize) {
                *slot = value;
            }
        }
        state
    }

    /// The steps of `range` cut into runs of one frame each, in order, with
    /// the frame.
    fn runs(
        &self,
        range: std::ops::Range<usize>,
    ) -> impl Iterator<Item = (std::ops::Range<usize>, usize)> + '_ {
        let end = range.end.min(self.steps.len());
        let segments = self.segments();
        let first = segments
            .partition_point(|s| s.start as usize <= range.start)
            .saturating_sub(1);
        let segments = segments.get(first..).unwrap_or(&[]);
        segments
            .iter()
            .enumerate()
            .map_while(move |(i, segment)| {
                let next = segments
                    .get(i + 1)
                    .map_or(end, |s| (s.start as usize).min(end));
                let start = (segment.start as usize).max(range.start);
                (start < end).then_some((start..next.max(start), segment.frame as usize))
            })
            .filter(|(run, _)| !run.is_empty())
    }

    /// The call stack right after step `index`, the started algorithm
    /// first and the innermost call last, each frame with its variables.
    /// At or past the end, the stack where the run stopped (an error may
    /// stop it in a call that made no step yet).
    pub fn frames_at(&self, index: usize) -> Vec<FrameView<'_>> {
        let index = index.min(self.steps.len());
        let mut chain = Vec::new();
        let mut frame = self.frame_of(index);
        while let Some(record) = self.frames.get(frame) {
            chain.push(frame);
            if record.parent == NONE || chain.len() > self.frames.len() {
                break;
            }
            frame = record.parent as usize;
        }
        chain
            .into_iter()
            .rev()
            .filter_map(|frame| self.frame_view(frame, index))
            .collect()
    }

    fn frame_view(&self, frame: usize, index: usize) -> Option<FrameView<'_>> {
        let record = self.frames.get(frame)?;
        let routine = self.routine_of(frame)?;
        let call_step = (record.call_step != NONE).then_some(record.call_step as usize);
        Some(FrameView {
            name: &routine.name,
            routine,
            depth: record.depth as usize,
            call_step,
            call_line: call_step.and_then(|step| self.line(step)),
            variables: routine
                .variables
                .iter()
                .zip(self.frame_variables(frame, index))
                .collect(),
        })
    }

    /// The next step after `from` that is not inside a call `from` makes:
    /// over a call, to the step after it returns.
    pub fn step_over(&self, from: usize) -> Option<usize> {
        let depth = self.depth(from)?;
        self.next_where(from, |d| d <= depth)
    }

    /// The next step after the running call returns, in its caller; `None`
    /// in the started algorithm.
    pub fn step_out(&self, from: usize) -> Option<usize> {
        let depth = self.depth(from)?.checked_sub(1)?;
        self.next_where(from, |d| d <= depth)
    }

    /// The last step before `from` that is not inside a call: stepping back
    /// over a call.
    pub fn step_back_over(&self, from: usize) -> Option<usize> {
        let depth = self.depth(from)?;
        let runs: Vec<_> = self.runs(0..from).collect();
        runs.into_iter()
            .rev()
            .find(|(_, frame)| {
                self.frames
                    .get(*frame)
                    .is_some_and(|f| f.depth as usize <= depth)
            })
            .map(|(run, _)| run.end - 1)
    }

    fn next_where(&self, from: usize, keep: impl Fn(usize) -> bool) -> Option<usize> {
        let start = from.checked_add(1)?;
        self.runs(start..self.steps.len())
            .find(|(_, frame)| {
                self.frames
                    .get(*frame)
                    .is_some_and(|f| keep(f.depth as usize))
            })
            .map(|(run, _)| run.start)
    }

    /// The items of an array value right after step `index` (after the
    /// last step, its final items); `None` for other values.
    pub fn items_at(&self, array: Value, index: usize) -> Option<Vec<Value>> {
        let Value::Array(number) = array else {
            return None;
        };
        let log = self.arrays.get(number as usize)?;
        let decoder = self.decoder(log.item);
        let mut items = Vec::new();
        for change in log.changes.iter().take_while(|c| c.step as usize <= index) {
            let value = decoder.decode(change.new);
            if change.appended {
                items.push(value);
            } else if let Some(slot) = items.get_mut(change.index as usize) {
                *slot = value;
            }
        }
        Some(items)
    }

    /// A value as the trace shows it after step `index`: an array as its
    /// items then, `[face 0, face 3]`.
    pub fn show(&self, value: Value, index: usize) -> String {
        match self.items_at(value, index) {
            Some(items) => show_items(&items),
            None => value.to_string(),
        }
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

    /// The `message`s before step `index`: how many there are, and the
    /// texts of the last `most` of them, oldest first. A runaway run can
    /// print a hundred thousand; a view shows the latest.
    pub fn messages_before(&self, index: usize, most: usize) -> (usize, &[String]) {
        let end = index.min(self.steps.len());
        let count = (0..end)
            .rev()
            .find_map(|i| {
                let (_, step, instr) = self.located(i)?;
                matches!(instr.op, Op::Message { .. }).then_some(step.a as usize + 1)
            })
            .unwrap_or(0)
            .min(self.messages.len());
        (count, &self.messages[count.saturating_sub(most)..count])
    }

    /// The text of the latest `message` at or before step `index`.
    pub fn message_at(&self, index: usize) -> Option<&str> {
        let last = index.min(self.steps.len().checked_sub(1)?);
        (0..=last).rev().find_map(|i| match self.step(i)?.kind {
            StepKind::Message { text } => Some(text),
            _ => None,
        })
    }

    /// Whether step `index`, of a run of `frame`'s steps, is on `line`.
    fn on_line(&self, frame: usize, index: usize, line: u32) -> bool {
        let Some(routine) = self.routine_of(frame) else {
            return false;
        };
        self.steps
            .get(index)
            .and_then(|s| routine.code.get(s.pc as usize))
            .is_some_and(|i| i.line == line)
    }

    /// The first step after `from` on source line `line` (a breakpoint),
    /// if any.
    pub fn next_on_line(&self, from: usize, line: u32) -> Option<usize> {
        let start = from.checked_add(1)?;
        self.runs(start..self.steps.len())
            .find_map(|(run, frame)| run.into_iter().find(|&i| self.on_line(frame, i, line)))
    }

    /// The last step before `from` on `line`, for stepping back to a breakpoint.
    pub fn previous_on_line(&self, from: usize, line: u32) -> Option<usize> {
        let runs: Vec<_> = self.runs(0..from.min(self.steps.len())).collect();
        runs.into_iter()
            .rev()
            .find_map(|(run, frame)| run.rev().find(|&i| self.on_line(frame, i, line)))
    }

    /// Bytes held by the trace's step data, frames, snapshots and logs (not
    /// counting message texts), for the memory figure in the documentation.
    pub fn memory_bytes(&self) -> usize {
        use std::mem::size_of;
        let frames: usize = std::iter::once(&self.frames.root)
            .chain(&self.frames.calls)
            .map(|f| f.snapshots.capacity() * size_of::<(u32, u32)>())
            .sum();
        let arrays: usize = self
            .arrays
            .iter()
            .map(|a| a.changes.capacity() * size_of::<ArrayChange>())
            .sum();
        self.steps.capacity() * size_of::<Step>()
            + (self.frames.calls.capacity() + 1) * size_of::<FrameRecord>()
            + frames
            + self.segments.capacity() * size_of::<Segment>()
            + self.values.capacity() * size_of::<Value>()
            + self.entries.capacity() * size_of::<(u32, Value)>()
            + self.arrays.capacity() * size_of::<ArrayLog>()
            + arrays
            + self.vectors.capacity() * size_of::<Vec3>()
            + self.changes.capacity() * size_of::<(u32, Change)>()
            + (self.marks.capacity() + self.highlights.capacity()) * size_of::<(u32, ElementRef)>()
    }

    /// One line per step, as `edgewise trace` prints it:
    /// `step 12  line 10  lookup e.startVertex -> vertex 1`, indented two
    /// spaces for each call it is inside (up to [`MAX_INDENT`]).
    pub fn render_line(&self, index: usize) -> String {
        self.render_line_with(index, &mut |value| self.show(value, index))
    }

    /// Every step's line, first to last, as [`Self::render_line`] gives
    /// them. Arrays are replayed once along the way rather than from the
    /// start for each step that shows one, so a run that grows a long array
    /// prints in time linear in its steps.
    pub fn lines(&self) -> impl Iterator<Item = String> + '_ {
        let mut arrays = ArrayReplay::new(self);
        (0..self.steps.len())
            .map(move |index| self.render_line_with(index, &mut |value| arrays.show(value, index)))
    }

    fn render_line_with(&self, index: usize, show: &mut dyn FnMut(Value) -> String) -> String {
        let Some(view) = self.step(index) else {
            return String::new();
        };
        let depth = self.depth(index).unwrap_or(0);
        let indent = if depth > MAX_INDENT {
            format!("{}[depth {depth}] ", "  ".repeat(MAX_INDENT))
        } else {
            "  ".repeat(depth)
        };
        format!(
            "step {}  line {}  {indent}{}",
            index + 1,
            view.line,
            self.render_operation_with(index, show)
        )
    }

    /// What step `index` did, in the words of [`Self::render_line`] without
    /// its step and line: `lookup e.startVertex -> vertex 1`.
    pub fn render_operation(&self, index: usize) -> String {
        self.render_operation_with(index, &mut |value| self.show(value, index))
    }

    /// [`Self::render_operation`], showing values (arrays as their items)
    /// with `show`.
    fn render_operation_with(&self, index: usize, show: &mut dyn FnMut(Value) -> String) -> String {
        let Some(view) = self.step(index) else {
            return String::new();
        };
        let Some((routine, _, instr)) = self.located(index) else {
            return String::new();
        };
        let snippet = routine.snippet(instr.span);
        let name = |reg| routine.register_name(reg);
        match view.kind {
            StepKind::Lookup { result, .. } => format!("lookup {snippet} -> {result}"),
            StepKind::Assign { variable, value } => {
                let name = routine
                    .variables
                    .get(variable)
                    .map_or("?", |v| v.name.as_str());
                format!("assign {name} := {}", show(value))
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
                let field = field.lookup_name();
                format!("write {element}.{field} := {new} (was {old})")
            }
            StepKind::New { element } => format!("new {element}"),
            StepKind::Delete { element } => format!("delete {element}"),
            StepKind::Call { result, .. } => format!("call {snippet} -> {result}"),
            StepKind::Invoke { algorithm, frame } => {
                let arguments: Vec<String> = self
                    .frames
                    .get(frame)
                    .filter(|_| frame != 0)
                    .and_then(|_| self.frame_view(frame, index))
                    .map(|callee| {
                        callee
                            .variables
                            .iter()
                            .filter(|(v, _)| v.is_param)
                            .map(|(v, value)| format!("{} = {}", v.name, show(*value)))
                            .collect()
                    })
                    .unwrap_or_default();
                format!("call {algorithm}({})", arguments.join(", "))
            }
            StepKind::Return { value: Some(value) } => {
                format!("return {}", show(value))
            }
            StepKind::Return { value: None } => "return".to_owned(),
            StepKind::Index {
                index: at, result, ..
            } => format!("index {snippet} (item {at}) -> {result}"),
            StepKind::Store {
                index: at,
                old,
                new,
                ..
            } => {
                let array = match instr.op {
                    Op::Store { array, .. } => name(array),
                    _ => String::new(),
                };
                format!("store {array}[{at}] := {new} (was {old})")
            }
            StepKind::Append { value, length, .. } => {
                let array = match instr.op {
                    Op::Append { array, .. } => name(array),
                    _ => String::new(),
                };
                let items = if length == 1 { "item" } else { "items" };
                format!("append {value} to {array} (now {length} {items})")
            }
            StepKind::Done => "done".to_owned(),
        }
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
        for line in self.lines() {
            out.push_str(&line);
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

/// Every array's items as the steps go forward, each array brought up to
/// the step that shows it: [`Trace::lines`].
struct ArrayReplay<'t> {
    trace: &'t Trace,
    /// Each array's items so far, and how many of its changes made them.
    arrays: Vec<(Vec<Value>, usize)>,
}

impl<'t> ArrayReplay<'t> {
    fn new(trace: &'t Trace) -> Self {
        Self {
            trace,
            arrays: vec![(Vec::new(), 0); trace.arrays.len()],
        }
    }

    /// `value` as [`Trace::show`] shows it after step `index`, which is no
    /// earlier than any step shown before.
    fn show(&mut self, value: Value, index: usize) -> String {
        let Value::Array(number) = value else {
            return value.to_string();
        };
        let (Some(log), Some((items, applied))) = (
            self.trace.arrays.get(number as usize),
            self.arrays.get_mut(number as usize),
        ) else {
            return value.to_string();
        };
        let decoder = self.trace.decoder(log.item);
        let due = log.changes.get(*applied..).unwrap_or(&[]);
        for change in due.iter().take_while(|c| c.step as usize <= index) {
            let value = decoder.decode(change.new);
            if change.appended {
                items.push(value);
            } else if let Some(slot) = items.get_mut(change.index as usize) {
                *slot = value;
            }
            *applied += 1;
        }
        show_items(items)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::mem::size_of;

    /// The sizes algorithms/README.md gives for a step and a call.
    #[test]
    fn steps_and_calls_stay_small() {
        assert_eq!(size_of::<Step>(), 16);
        assert_eq!(
            size_of::<FrameRecord>() + 2 * size_of::<Segment>(),
            72,
            "a call's record and its two segments"
        );
        assert_eq!(size_of::<Value>(), 16);
    }
}
