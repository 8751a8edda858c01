//! The stepping virtual machine: runs compiled code on a [`Topology`],
//! producing either a full [`Trace`] or, for speed, just the outcome.

use super::builtin::Builtin;
use super::compiler::{Algorithm, CompareOp, ComputeOp, Instr, MessageItem, Op, Reg, Routine};
use super::diagnostic::Span;
use super::recorder::{OutputRecorder, Recorder};
use super::topology::Topology;
use super::trace::{Outcome, RuntimeError, RuntimeErrorKind, Trace, TraceRecorder};
use super::types::{Type, Value};
use crate::mesh::{Change, EditError, Editor, Mesh, VertexId};
use crate::schema::{Column, ElementKind, ElementRef, LookupError};
use std::fmt;
use std::sync::Arc;

/// Operations run before a trace is cut off, unless configured otherwise:
/// room for a whole-mesh edit such as a subdivision pass over a few thousand
/// triangles, while a runaway loop still stops within a fraction of a second
/// and about 17 MB of trace.
pub const DEFAULT_STEP_LIMIT: usize = 1_000_000;

/// Bytes a run may keep, unless configured otherwise: its trace (steps,
/// snapshots, messages), the variables of the calls in progress, its arrays
/// and the rows and changes it makes. The step limit bounds a run's time;
/// this bounds what a few steps can each take (a call of an algorithm with
/// thousands of variables, a long message), so that no algorithm or link can
/// exhaust a browser tab. Any run of the library uses a few MB.
pub const DEFAULT_MEMORY_LIMIT: usize = 256 << 20;

/// Values the calls of a run may set up, for each step it may take: a call
/// counts as one operation, but sets up every variable and intermediate
/// value of the algorithm it calls, so an algorithm with thousands of
/// variables called in a loop would otherwise take minutes within the step
/// limit. No call of fewer than this many values meets it first.
const VALUES_PER_STEP: usize = 64;

/// The steps between two checks of the memory a run holds; calls and
/// messages, which can take much more than a step, are checked each time.
const MEMORY_CHECK_INTERVAL: usize = 1024;

/// What a row made by `new` is counted as: the largest row, a winged edge's
/// eight references.
const CREATED_ROW_BYTES: usize = 32;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct RunOptions {
    /// The most operations (trace steps) to run. A loop that performs no
    /// operation at all is cut off after this many iterations too.
    pub step_limit: usize,
    /// The most bytes the run may keep (see [`DEFAULT_MEMORY_LIMIT`]).
    pub memory_limit: usize,
}

impl Default for RunOptions {
    fn default() -> Self {
        Self {
            step_limit: DEFAULT_STEP_LIMIT,
            memory_limit: DEFAULT_MEMORY_LIMIT,
        }
    }
}

/// Why an algorithm could not start on the given mesh and inputs.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum InputError {
    WrongStructure {
        algorithm: String,
        needs: String,
        mesh: String,
    },
    Missing {
        name: String,
        ty: Type,
    },
    UnknownParameter {
        name: String,
        algorithm: String,
        parameters: String,
    },
    WrongType {
        name: String,
        expected: Type,
        found: String,
    },
    OutOfRange {
        name: String,
        element: ElementRef,
        count: usize,
    },
    Duplicate {
        name: String,
    },
    Malformed {
        text: String,
    },
}

impl fmt::Display for InputError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            InputError::WrongStructure {
                algorithm,
                needs,
                mesh,
            } => {
                write!(
                    f,
                    "algorithm `{algorithm}` walks a {needs} structure, but the mesh is a {mesh} structure"
                )
            }
            InputError::Missing { name, ty } => {
                write!(f, "no value given for parameter `{name}` ({ty})")
            }
            InputError::UnknownParameter {
                name,
                algorithm,
                parameters,
            } => {
                write!(
                    f,
                    "algorithm `{algorithm}` has no parameter `{name}` (its parameters: {parameters})"
                )
            }
            InputError::WrongType {
                name,
                expected,
                found,
            } => {
                write!(
                    f,
                    "parameter `{name}` is {}, but was given {found}",
                    super::checker::with_article(*expected)
                )
            }
            InputError::OutOfRange {
                name,
                element,
                count,
            } => {
                write!(
                    f,
                    "parameter `{name}`: {element} does not exist (the mesh has {count} {})",
                    element.kind.plural()
                )
            }
            InputError::Duplicate { name } => write!(f, "parameter `{name}` is given twice"),
            InputError::Malformed { text } => {
                write!(
                    f,
                    "`{text}` is not an argument; write NAME=VALUE, such as v=3, n=4 or b=true"
                )
            }
        }
    }
}

impl std::error::Error for InputError {}

impl Algorithm {
    /// Parses a command-line argument such as `v=3` into the parameter's name
    /// and value; the number is read as the parameter's element kind.
    pub fn parse_argument(&self, text: &str) -> Result<(String, Value), InputError> {
        let Some((name, value)) = text.split_once('=') else {
            return Err(InputError::Malformed {
                text: text.to_owned(),
            });
        };
        let (name, value) = (name.trim(), value.trim());
        let Some(param) = self.params().find(|p| p.name == name) else {
            return Err(self.unknown_parameter(name));
        };
        let wrong = || InputError::WrongType {
            name: name.to_owned(),
            expected: param.ty,
            found: format!("`{value}`"),
        };
        let parsed = match param.ty {
            Type::Integer => Value::Integer(value.parse().map_err(|_| wrong())?),
            Type::Float => Value::Float(
                value
                    .parse::<f32>()
                    .ok()
                    .filter(|x| x.is_finite())
                    .ok_or_else(wrong)?,
            ),
            Type::Boolean => Value::Boolean(match value.to_ascii_lowercase().as_str() {
                "true" => true,
                "false" => false,
                _ => return Err(wrong()),
            }),
            ty => {
                let index: u32 = value.parse().map_err(|_| wrong())?;
                match ty.element_kind() {
                    Some(kind) => Value::from(ElementRef::new(kind, index)),
                    None => return Err(wrong()),
                }
            }
        };
        Ok((name.to_owned(), parsed))
    }

    fn unknown_parameter(&self, name: &str) -> InputError {
        let parameters: Vec<String> = self
            .params()
            .map(|p| format!("{} : {}", p.name, p.ty))
            .collect();
        InputError::UnknownParameter {
            name: name.to_owned(),
            algorithm: self.name.clone(),
            parameters: if parameters.is_empty() {
                "none".to_owned()
            } else {
                parameters.join(", ")
            },
        }
    }

    /// Checks named inputs against the parameters and the mesh and returns
    /// the initial register file's variable part.
    pub fn bind_inputs<T: Topology + ?Sized>(
        &self,
        topology: &T,
        inputs: &[(&str, Value)],
    ) -> Result<Vec<Value>, InputError> {
        if topology.structure() != self.structure {
            return Err(InputError::WrongStructure {
                algorithm: self.name.clone(),
                needs: self.structure.to_string(),
                mesh: topology.structure().to_string(),
            });
        }
        for (i, (name, _)) in inputs.iter().enumerate() {
            if !self.params().any(|p| p.name == *name) {
                return Err(self.unknown_parameter(name));
            }
            if inputs
                .get(..i)
                .is_some_and(|earlier| earlier.iter().any(|(n, _)| n == name))
            {
                return Err(InputError::Duplicate {
                    name: (*name).to_owned(),
                });
            }
        }
        let mut values = Vec::with_capacity(self.variables.len());
        for variable in &self.variables {
            if !variable.is_param {
                values.push(variable.ty.default_value());
                continue;
            }
            let name = variable.name.clone();
            let given = inputs.iter().find(|(n, _)| *n == variable.name);
            if let Type::Array(_) = variable.ty {
                // An array parameter of the algorithm started begins empty.
                match given {
                    Some(&(_, value)) if value != Value::Null => {
                        return Err(InputError::WrongType {
                            name,
                            expected: variable.ty,
                            found: value.to_string(),
                        });
                    }
                    _ => values.push(Value::Null),
                }
                continue;
            }
            let Some(&(_, value)) = given else {
                return Err(InputError::Missing {
                    name,
                    ty: variable.ty,
                });
            };
            let value = match (variable.ty, value) {
                (Type::Float, Value::Integer(n)) => Value::Float(n as f32),
                _ => value,
            };
            let fits = match (variable.ty, value) {
                (Type::Integer, Value::Integer(_))
                | (Type::Boolean, Value::Boolean(_))
                | (Type::Float, Value::Float(_))
                | (Type::Vector, Value::Vector(_)) => true,
                (ty, value) => value
                    .element()
                    .is_some_and(|e| Some(e.kind) == ty.element_kind()),
            };
            if !fits {
                return Err(InputError::WrongType {
                    name,
                    expected: variable.ty,
                    found: value.to_string(),
                });
            }
            if let Some(element) = value.element() {
                let count = topology.count(element.kind);
                let deleted = matches!(
                    topology.lookup(element, Column::IncidentEdge),
                    Err(LookupError::Deleted(_))
                );
                if element.id as usize >= count || deleted {
                    return Err(InputError::OutOfRange {
                        name,
                        element,
                        count,
                    });
                }
            }
            values.push(value);
        }
        Ok(values)
    }
}

/// Runs an algorithm and records every step, for stepping back and forth.
/// The mesh is only read; an algorithm that edits stops at its first edit
/// (use [`run_editing`]).
pub fn run<T: Topology + ?Sized>(
    algorithm: &Arc<Algorithm>,
    topology: &T,
    inputs: &[(&str, Value)],
    options: RunOptions,
) -> Result<Trace, InputError> {
    let variables = algorithm.bind_inputs(topology, inputs)?;
    Ok(record(algorithm, Reading(topology), &variables, options))
}

/// Runs an algorithm that may change the mesh, recording every step and
/// every change ([`Trace::changes`]). `mesh` is left as the run left it,
/// even if it stopped on an error; reverting the trace's changes newest
/// first restores it.
pub fn run_editing(
    algorithm: &Arc<Algorithm>,
    mesh: &mut Mesh,
    inputs: &[(&str, Value)],
    options: RunOptions,
) -> Result<Trace, InputError> {
    let variables = algorithm.bind_inputs(&*mesh, inputs)?;
    Ok(record(algorithm, Editing::new(mesh), &variables, options))
}

/// Runs on `store`, recording every step.
fn record<S: Store>(
    algorithm: &Arc<Algorithm>,
    store: S,
    variables: &[Value],
    options: RunOptions,
) -> Trace {
    let recorder = TraceRecorder::default();
    Machine::new(algorithm, store, variables, recorder, options).trace(algorithm)
}

/// Runs on `store`, keeping only the output.
fn output<S: Store>(
    algorithm: &Algorithm,
    store: S,
    variables: &[Value],
    options: RunOptions,
) -> Execution {
    let recorder = OutputRecorder::default();
    Machine::new(algorithm, store, variables, recorder, options).execution()
}

/// The result of [`execute`]: what a run produced, without its steps.
#[derive(Clone, Debug, PartialEq)]
pub struct Execution {
    pub marked: Vec<ElementRef>,
    pub highlighted: Vec<ElementRef>,
    pub messages: Vec<String>,
    /// The variables' final values, in declaration order (parameters first).
    pub variables: Vec<Value>,
    /// Every array the run made, with its final items, numbered as the
    /// [`Value::Array`]s in `variables` number them.
    pub arrays: Vec<Vec<Value>>,
    /// What the algorithm returned, if it returned a value.
    pub result: Option<Value>,
    /// The number of operations performed.
    pub steps: usize,
    /// What an editing run changed, oldest first ([`execute_editing`]).
    pub changes: Vec<Change>,
    pub outcome: Outcome,
}

impl Execution {
    /// The final value of a variable, by name.
    pub fn variable(&self, algorithm: &Algorithm, name: &str) -> Option<Value> {
        let index = algorithm.variables.iter().position(|v| v.name == name)?;
        self.variables.get(index).copied()
    }

    /// The final items of an array value; `None` for other values.
    pub fn items(&self, array: Value) -> Option<&[Value]> {
        match array {
            Value::Array(number) => self.arrays.get(number as usize).map(Vec::as_slice),
            _ => None,
        }
    }
}

/// Runs an algorithm keeping only its output: the fast path for tests,
/// benchmarks, and answering a query without animating it.
pub fn execute<T: Topology + ?Sized>(
    algorithm: &Algorithm,
    topology: &T,
    inputs: &[(&str, Value)],
    options: RunOptions,
) -> Result<Execution, InputError> {
    let variables = algorithm.bind_inputs(topology, inputs)?;
    Ok(output(algorithm, Reading(topology), &variables, options))
}

/// [`execute`] for an algorithm that may change the mesh: `mesh` is left
/// as the run left it, and [`Execution::changes`] says how.
pub fn execute_editing(
    algorithm: &Algorithm,
    mesh: &mut Mesh,
    inputs: &[(&str, Value)],
    options: RunOptions,
) -> Result<Execution, InputError> {
    let variables = algorithm.bind_inputs(&*mesh, inputs)?;
    Ok(output(algorithm, Editing::new(mesh), &variables, options))
}

/// Where the VM reads the mesh and, when it may, changes it.
trait Store {
    type Mesh: Topology + ?Sized;

    fn mesh(&self) -> &Self::Mesh;

    /// Applies an edit, or gives `None` when the run may only read.
    fn edit<R>(
        &mut self,
        edit: impl FnOnce(&mut Editor<'_, Mesh>) -> Result<R, EditError>,
    ) -> Option<Result<R, EditError>>;

    /// The changes made so far.
    fn journal(&self) -> &[Change];
}

/// A run that only reads.
struct Reading<'a, T: ?Sized>(&'a T);

impl<T: Topology + ?Sized> Store for Reading<'_, T> {
    type Mesh = T;

    #[inline(always)]
    fn mesh(&self) -> &T {
        self.0
    }

    fn edit<R>(
        &mut self,
        _edit: impl FnOnce(&mut Editor<'_, Mesh>) -> Result<R, EditError>,
    ) -> Option<Result<R, EditError>> {
        None
    }

    fn journal(&self) -> &[Change] {
        &[]
    }
}

/// A run that may change the mesh, through a journaling editor.
struct Editing<'m> {
    editor: Editor<'m, Mesh>,
}

impl<'m> Editing<'m> {
    fn new(mesh: &'m mut Mesh) -> Self {
        Self {
            editor: Editor::new(mesh),
        }
    }
}

impl Store for Editing<'_> {
    type Mesh = Mesh;

    #[inline(always)]
    fn mesh(&self) -> &Mesh {
        self.editor.mesh()
    }

    fn edit<R>(
        &mut self,
        edit: impl FnOnce(&mut Editor<'_, Mesh>) -> Result<R, EditError>,
    ) -> Option<Result<R, EditError>> {
        Some(edit(&mut self.editor))
    }

    fn journal(&self) -> &[Change] {
        self.editor.journal()
    }
}

/// Where a variable's null came from, to explain a later null lookup.
#[derive(Clone, Copy, Debug)]
enum NullOrigin {
    Unassigned,
    /// Assigned from a lookup that yielded null: the lookup's instruction and
    /// the element it was applied to.
    Lookup {
        pc: usize,
        base: Value,
    },
    Assigned {
        pc: usize,
    },
    /// A parameter given null by the call on `line`.
    Passed {
        line: u32,
    },
}

/// The most algorithms running at once: the one started and the calls in
/// progress. Frames live in a `Vec`, not on the Rust stack; the limit stops
/// a runaway recursion early, with a message, rather than at the step limit.
pub const MAX_CALL_DEPTH: usize = 256;

/// The most array items one run may make, counting each new array as one:
/// enough for any exercise, and a hostile loop stops at 16 MiB of items.
pub const MAX_ARRAY_ITEMS: usize = 1 << 20;

/// A caller waiting for its call to return.
struct Frame<'a> {
    routine: &'a Routine,
    index: u32,
    registers: Vec<Value>,
    null_origins: Vec<NullOrigin>,
    variable_count: usize,
    /// Where the caller goes on, and where the result goes.
    return_pc: usize,
    dst: Reg,
}

/// The arrays a run made: [`Value::Array`] numbers them.
#[derive(Default)]
struct Arrays {
    lists: Vec<Vec<Value>>,
    /// Items and arrays made so far, against [`MAX_ARRAY_ITEMS`].
    made: usize,
}

/// The bytes a call's register file holds.
fn frame_bytes(registers: &Vec<Value>, null_origins: &Vec<NullOrigin>) -> usize {
    registers.capacity() * size_of::<Value>() + null_origins.capacity() * size_of::<NullOrigin>()
}

impl Arrays {
    /// What the arrays hold, counting each item and each array's own record.
    fn bytes(&self) -> usize {
        self.made * size_of::<Value>() + self.lists.len() * size_of::<Vec<Value>>()
    }

    fn reserve(&mut self) -> Result<(), String> {
        if self.made >= MAX_ARRAY_ITEMS {
            return Err(format!(
                "the arrays of this run reached {MAX_ARRAY_ITEMS} items, the most one run may \
                 make (each new array counts as one)"
            ));
        }
        self.made += 1;
        Ok(())
    }

    fn list(&self, array: Value) -> Result<&Vec<Value>, String> {
        match array {
            Value::Array(i) => self
                .lists
                .get(i as usize)
                .ok_or_else(|| format!("{array} does not exist")),
            _ => Err(format!("{array} is not an array")),
        }
    }

    /// The item at `index`, or why there is none: "index 5 is out of range
    /// in a[i] (the array has 3 items, indices 0 to 2)", said of `code`.
    fn checked(
        &self,
        array: Value,
        index: Value,
        code: impl FnOnce() -> String,
    ) -> Result<(usize, &Vec<Value>), String> {
        let list = self.list(array)?;
        let Value::Integer(i) = index else {
            return Err(format!("{index} is not an index"));
        };
        match usize::try_from(i) {
            Ok(i) if i < list.len() => Ok((i, list)),
            _ => {
                let items = match list.len() {
                    0 => "the array is empty".to_owned(),
                    1 => "the array has 1 item, index 0".to_owned(),
                    n => format!("the array has {n} items, indices 0 to {}", n - 1),
                };
                Err(format!("index {i} is out of range in {} ({items})", code()))
            }
        }
    }
}

struct Machine<'a, S, R> {
    /// Every algorithm of the started one's file, which calls name by number.
    routines: &'a [Routine],
    /// The algorithm running now, and its number.
    routine: &'a Routine,
    current: u32,
    store: S,
    /// The step each journal entry was made at.
    change_steps: Vec<u32>,
    /// The running frame's registers: its variables first.
    registers: Vec<Value>,
    variable_count: usize,
    null_origins: Vec<NullOrigin>,
    /// The callers of the running frame, outermost first.
    frames: Vec<Frame<'a>>,
    /// Register files of returned calls, reused by the next calls.
    spare: Vec<(Vec<Value>, Vec<NullOrigin>)>,
    arrays: Arrays,
    /// What the started algorithm returned, if it returned a value.
    result: Option<Value>,
    recorder: R,
    limit: usize,
    steps: usize,
    back_jumps: usize,
    /// The most bytes the run may hold, and the step at which that, or
    /// the step limit, is checked next.
    memory_limit: usize,
    next_check: usize,
    /// Bytes held by the register files of calls in progress and of
    /// returned calls kept for reuse.
    frame_bytes: usize,
    /// Rows made by `new`.
    created_rows: usize,
    /// Values the calls so far have set up, against
    /// [`VALUES_PER_STEP`] times the step limit.
    values_set_up: usize,
}

impl<'a, S: Store, R: Recorder> Machine<'a, S, R> {
    fn new(
        algorithm: &'a Algorithm,
        store: S,
        variables: &[Value],
        recorder: R,
        options: RunOptions,
    ) -> Self {
        let routine: &'a Routine = algorithm;
        let mut registers = routine.initial.clone();
        for (slot, value) in registers.iter_mut().zip(variables) {
            *slot = *value;
        }
        let variable_count = routine.variables.len().min(registers.len());
        let mut machine = Machine {
            routines: algorithm.routines(),
            routine,
            current: u32::try_from(algorithm.index()).unwrap_or(u32::MAX),
            store,
            change_steps: Vec::new(),
            registers: Vec::new(),
            variable_count,
            null_origins: vec![NullOrigin::Unassigned; variable_count],
            frames: Vec::new(),
            spare: Vec::new(),
            arrays: Arrays::default(),
            result: None,
            recorder,
            limit: options.step_limit,
            steps: 0,
            back_jumps: 0,
            memory_limit: options.memory_limit,
            next_check: options.step_limit.min(MEMORY_CHECK_INTERVAL),
            frame_bytes: 0,
            created_rows: 0,
            values_set_up: 0,
        };
        // A routine has fewer than 65,536 registers, so its arrays fit the
        // budget of a fresh run.
        let _ = machine.new_arrays(routine, &mut registers, 0);
        machine.registers = registers;
        machine
    }

    /// The started algorithm's variables, wherever the run is.
    fn root_variables(&self) -> Vec<Value> {
        let (registers, count) = match self.frames.first() {
            Some(root) => (&root.registers, root.variable_count),
            None => (&self.registers, self.variable_count),
        };
        registers.get(..count).unwrap_or(&[]).to_vec()
    }

    // The two below take the machine by reference: moving it costs more
    // than a short run.
    fn trace(&mut self, algorithm: &Arc<Algorithm>) -> Trace
    where
        R: Into<TraceRecorder> + Default,
    {
        let outcome = self.run();
        let final_variables = self.root_variables();
        let changes: Vec<(u32, Change)> = self
            .change_steps
            .iter()
            .copied()
            .zip(self.store.journal().iter().copied())
            .collect();
        let recorder: TraceRecorder = std::mem::take(&mut self.recorder).into();
        recorder.finish(
            Arc::clone(algorithm),
            final_variables,
            changes,
            self.result,
            outcome,
        )
    }

    fn execution(&mut self) -> Execution
    where
        R: Into<OutputRecorder> + Default,
    {
        let outcome = self.run();
        let variables = self.root_variables();
        let changes = self.store.journal().to_vec();
        let OutputRecorder {
            marked,
            highlighted,
            messages,
            ..
        } = std::mem::take(&mut self.recorder).into();
        Execution {
            marked,
            highlighted,
            messages,
            variables,
            arrays: std::mem::take(&mut self.arrays.lists),
            result: self.result,
            steps: self.steps,
            changes,
            outcome,
        }
    }

    /// Gives every array variable of `routine` from `first` on a new empty
    /// array: the locals of a call, all the variables of the started one.
    fn new_arrays(
        &mut self,
        routine: &Routine,
        registers: &mut [Value],
        first: usize,
    ) -> Result<(), String> {
        for &(variable, item) in &routine.array_variables {
            if usize::from(variable) < first {
                continue;
            }
            self.arrays.reserve()?;
            let number = index_u32(self.arrays.lists.len());
            self.arrays.lists.push(Vec::new());
            self.recorder.array_created(item.ty());
            if let Some(slot) = registers.get_mut(usize::from(variable)) {
                *slot = Value::Array(number);
            }
        }
        Ok(())
    }

    /// Ties the journal entries an edit just made to the step it recorded.
    fn note_changes(&mut self) {
        let step = u32::try_from(self.steps.saturating_sub(1)).unwrap_or(u32::MAX);
        let made = self.store.journal().len() - self.change_steps.len();
        self.change_steps.extend(std::iter::repeat_n(step, made));
    }

    /// Applies an edit, or explains why it cannot be made.
    fn edit<X>(
        &mut self,
        edit: impl FnOnce(&mut Editor<'_, Mesh>) -> Result<X, EditError>,
    ) -> Result<X, String> {
        match self.store.edit(edit) {
            Some(Ok(done)) => Ok(done),
            Some(Err(error)) => Err(error.to_string()),
            None => Err(
                "this run can only read the mesh; algorithms that change it run as edits"
                    .to_owned(),
            ),
        }
    }

    #[inline(always)]
    fn get(&self, reg: Reg) -> Value {
        self.registers
            .get(usize::from(reg))
            .copied()
            .unwrap_or(Value::Null)
    }

    #[inline(always)]
    fn set(&mut self, reg: Reg, value: Value) {
        if let Some(slot) = self.registers.get_mut(usize::from(reg)) {
            *slot = value;
        }
    }

    #[inline(always)]
    fn record(&mut self, pc: usize, a: Value, b: Value, r: Value) {
        self.steps += 1;
        let variables = self.registers.get(..self.variable_count).unwrap_or(&[]);
        self.recorder.step(pc as u32, a, b, r, variables);
    }

    fn run(&mut self) -> Outcome {
        let variables = self.registers.get(..self.variable_count).unwrap_or(&[]);
        let initial = self.routine.initial.get(..self.variable_count);
        self.recorder
            .enter(self.current, variables, initial.unwrap_or(&[]));
        let mut code: &'a [Instr] = &self.routine.code;
        let mut pc = 0usize;
        loop {
            let Some(instr) = code.get(pc) else {
                return self.fail(
                    pc.saturating_sub(1),
                    "the code ended without `done`".to_owned(),
                );
            };
            let op = instr.op;
            if self.steps >= self.next_check && op.is_step() {
                if self.steps >= self.limit {
                    return self.step_limit(pc);
                }
                if let Some(outcome) = self.memory_check(pc) {
                    return outcome;
                }
                self.next_check = (self.steps + MEMORY_CHECK_INTERVAL).min(self.limit);
            }
            match op {
                Op::Lookup { .. } | Op::Write { .. } | Op::New { .. } | Op::Delete { .. } => {
                    if let Err(message) = self.mesh_op(pc, op) {
                        return self.fail(pc, message);
                    }
                }
                Op::Call { .. } => {
                    if let Err(message) = self.builtin(pc, instr) {
                        return self.fail(pc, message);
                    }
                }
                Op::Invoke { dst, routine, args } => {
                    if let Some(outcome) = self.set_up_check(pc, routine) {
                        return outcome;
                    }
                    if let Err(message) = self.call(pc, dst, routine, args) {
                        return self.fail(pc, message);
                    }
                    if let Some(outcome) = self.memory_check(pc) {
                        return outcome;
                    }
                    code = &self.routine.code;
                    pc = 0;
                    continue;
                }
                Op::Return { src, value } => {
                    let result = value.then(|| widen(self.routine.result, self.get(src)));
                    self.record(pc, result.unwrap_or(Value::Null), Value::Null, Value::Null);
                    if self.frames.is_empty() {
                        // The started algorithm goes on to its `end`.
                        self.result = result;
                        pc = code.len().saturating_sub(1);
                        continue;
                    }
                    pc = self.return_to_caller(result);
                    code = &self.routine.code;
                    continue;
                }
                Op::Index { .. } | Op::Store { .. } | Op::Append { .. } | Op::Length { .. } => {
                    if let Err(message) = self.array(pc, instr) {
                        return self.fail(pc, message);
                    }
                }
                Op::Assign { var, src } => {
                    let value = widen(Some(self.routine.register_type(var)), self.get(src));
                    self.record(pc, Value::Null, Value::Null, value);
                    if value == Value::Null {
                        self.note_null(pc, var, src);
                    }
                    self.set(var, value);
                }
                Op::Compare {
                    dst,
                    op,
                    left,
                    right,
                } => {
                    let (l, r) = (self.get(left), self.get(right));
                    let result = compare(op, l, r);
                    self.record(pc, l, r, Value::Boolean(result));
                    self.set(dst, Value::Boolean(result));
                }
                Op::Compute {
                    dst,
                    op,
                    left,
                    right,
                } => {
                    let (l, r) = (self.get(left), self.get(right));
                    let result = match compute(op, l, r) {
                        Ok(result) => result,
                        Err(problem) => return self.fail(pc, self.in_code(&problem, pc)),
                    };
                    self.record(pc, l, r, result);
                    self.set(dst, result);
                }
                Op::Move { dst, src } => {
                    let value = self.get(src);
                    self.set(dst, value);
                }
                Op::Mark { element } | Op::Highlight { element } => {
                    let mark = matches!(op, Op::Mark { .. });
                    if let Err(message) = self.mark(pc, element, mark) {
                        return self.fail(pc, message);
                    }
                }
                Op::Refuse { index } => {
                    let message = self.format_message(index);
                    return self.error_at(pc, RuntimeErrorKind::Refused, message);
                }
                Op::Message { index } => {
                    let text = self.format_message(index);
                    let number = self.recorder.message(text);
                    self.record(pc, Value::Integer(number as i32), Value::Null, Value::Null);
                    if let Some(outcome) = self.memory_check(pc) {
                        return outcome;
                    }
                }
                Op::Jump { target } => {
                    if let Some(outcome) = self.jump(pc, target) {
                        return outcome;
                    }
                    pc = target as usize;
                    continue;
                }
                Op::JumpIf { cond, when, target } => {
                    if matches!(self.get(cond), Value::Boolean(b) if b == when) {
                        if let Some(outcome) = self.jump(pc, target) {
                            return outcome;
                        }
                        pc = target as usize;
                        continue;
                    }
                }
                Op::Done => {
                    self.record(pc, Value::Null, Value::Null, Value::Null);
                    if self.frames.is_empty() {
                        return Outcome::Finished;
                    }
                    // A call that reached its `end`: the checker has made
                    // sure only one without a result can.
                    let result = self.routine.result.map(Type::default_value);
                    pc = self.return_to_caller(result);
                    code = &self.routine.code;
                    continue;
                }
            }
            pc += 1;
        }
    }

    /// Calls a built-in function and records its step; an `Err` is the
    /// fault's message.
    #[inline]
    fn builtin(&mut self, pc: usize, instr: &Instr) -> Result<(), String> {
        let Op::Call {
            dst,
            builtin,
            args,
            argc,
        } = instr.op
        else {
            return Ok(());
        };
        let mut values = [Value::Null; 3];
        for (slot, &reg) in values.iter_mut().zip(&args).take(usize::from(argc)) {
            *slot = self.get(reg);
        }
        if builtin == Builtin::Id && values[0] == Value::Null {
            return Err(self.cannot_act_message("take the id of", args[0]));
        }
        let result = builtin
            .apply(&values[..usize::from(argc)])
            .map_err(|problem| format!("{problem} in {}", self.routine.snippet(instr.span)))?;
        self.record(pc, values[0], values[1], result);
        self.set(dst, result);
        Ok(())
    }

    /// `mark` (or, if not `mark`, `highlight`) the element in `element`,
    /// and records the step; an `Err` is the fault's message.
    #[inline]
    fn mark(&mut self, pc: usize, element: Reg, mark: bool) -> Result<(), String> {
        let value = self.get(element);
        let word = if mark { "mark" } else { "highlight" };
        let Some(target) = value.element() else {
            return Err(self.cannot_act_message(word, element));
        };
        self.record(pc, value, Value::Null, Value::Null);
        if mark {
            self.recorder.mark(target);
        } else {
            self.recorder.highlight(target);
        }
        Ok(())
    }

    /// Runs an operation that reads or changes the mesh and records its
    /// step; an `Err` is the fault's message.
    #[inline]
    fn mesh_op(&mut self, pc: usize, op: Op) -> Result<(), String> {
        match op {
            Op::Lookup { dst, base, field } => {
                let base_value = self.get(base);
                let Some(element) = base_value.element() else {
                    return Err(self.explain_null(base));
                };
                let result = if field == Column::Position {
                    let position = self.store.mesh().position(VertexId::new(element.id));
                    Value::Vector(position.ok_or_else(|| format!("{element} has no position"))?)
                } else {
                    let reference = self.store.mesh().lookup(element, field);
                    Value::from(reference.map_err(|error| format!("lookup failed: {error}"))?)
                };
                self.record(pc, base_value, Value::Null, result);
                self.set(dst, result);
            }
            Op::Write { base, field, src } => {
                let base_value = self.get(base);
                let Some(element) = base_value.element() else {
                    return Err(format!(
                        "cannot write into null: {}",
                        self.explain_null(base)
                    ));
                };
                let value = self.get(src);
                let old = if field == Column::Position {
                    let position = match value {
                        Value::Vector(v) => v,
                        other => glam::Vec3::splat(other.number().unwrap_or(0.0)),
                    };
                    let vertex = VertexId::new(element.id);
                    let old = self
                        .store
                        .mesh()
                        .position(vertex)
                        .map_or(Value::Null, Value::Vector);
                    self.edit(|editor| editor.set_position(vertex, position))?;
                    old
                } else {
                    let old = self
                        .store
                        .mesh()
                        .lookup(element, field)
                        .map_or(Value::Null, Value::from);
                    let target = value.element();
                    if let Err(error) = self.edit(|editor| editor.set(element, field, target)) {
                        return Err(self.write_refused(error, value, src));
                    }
                    old
                };
                self.record(pc, base_value, old, value);
                self.note_changes();
            }
            Op::New { dst, kind } => {
                let element = self.edit(|editor| editor.create(kind))?;
                let value = Value::from(element);
                self.created_rows += 1;
                self.record(pc, Value::Null, Value::Null, value);
                self.note_changes();
                self.set(dst, value);
            }
            Op::Delete { element } => {
                let value = self.get(element);
                let Some(target) = value.element() else {
                    return Err(self.cannot_act_message("delete", element));
                };
                self.edit(|editor| editor.delete(target))?;
                self.record(pc, value, Value::Null, Value::Null);
                self.note_changes();
            }
            _ => {}
        }
        Ok(())
    }

    /// Runs an array operation and records its step. Kept out of the main
    /// loop, like calls, so that algorithms without them run as fast as
    /// before they existed.
    #[inline(never)]
    fn array(&mut self, pc: usize, instr: &Instr) -> Result<(), String> {
        let code = || self.routine.snippet(instr.span);
        match instr.op {
            Op::Index { dst, array, index } => {
                let (list, at) = (self.get(array), self.get(index));
                let (i, items) = self.arrays.checked(list, at, code)?;
                let item = items.get(i).copied().unwrap_or(Value::Null);
                self.record(pc, list, at, item);
                self.set(dst, item);
            }
            Op::Store { array, index, src } => {
                let (list, at) = (self.get(array), self.get(index));
                let value = widen(self.routine.register_type(array).item(), self.get(src));
                let (i, items) = self.arrays.checked(list, at, code)?;
                let old = items.get(i).copied().unwrap_or(Value::Null);
                if let Some(slot) = self
                    .arrays
                    .lists
                    .get_mut(list.code() as usize)
                    .and_then(|items| items.get_mut(i))
                {
                    *slot = value;
                }
                self.record(pc, list, at, value);
                self.recorder
                    .array_changed(list.code(), index_u32(i), Some(old), value);
            }
            Op::Append { array, src } => {
                let list = self.get(array);
                let value = widen(self.routine.register_type(array).item(), self.get(src));
                let length = self.arrays.list(list)?.len();
                self.arrays.reserve()?;
                if let Some(items) = self.arrays.lists.get_mut(list.code() as usize) {
                    items.push(value);
                }
                let count = Value::Integer(i32::try_from(length + 1).unwrap_or(i32::MAX));
                self.record(pc, list, count, value);
                self.recorder
                    .array_changed(list.code(), index_u32(length), None, value);
            }
            Op::Length { dst, array } => {
                let list = self.get(array);
                let length = self.arrays.list(list)?.len();
                let length = Value::Integer(i32::try_from(length).unwrap_or(i32::MAX));
                self.record(pc, list, Value::Null, length);
                self.set(dst, length);
            }
            _ => {}
        }
        Ok(())
    }

    /// Starts a call: records its step in the caller, then makes the callee
    /// the running frame, its parameters set from the arguments and its
    /// array variables new arrays.
    #[inline(never)]
    fn call(&mut self, pc: usize, dst: Reg, number: u16, args: u32) -> Result<(), String> {
        let Some(callee) = self.routines.get(usize::from(number)) else {
            return Err(format!("there is no algorithm number {number} to call"));
        };
        if self.frames.len() + 1 >= MAX_CALL_DEPTH {
            return Err(format!(
                "calls nest too deep: {MAX_CALL_DEPTH} algorithms are running at once, the most \
                 there may be; does `{}` call itself without end?",
                callee.name
            ));
        }
        let (mut registers, mut null_origins) = self.spare.pop().unwrap_or_default();
        let before = frame_bytes(&registers, &null_origins);
        registers.clear();
        registers.extend_from_slice(&callee.initial);
        let variable_count = callee.variables.len().min(registers.len());
        null_origins.clear();
        null_origins.resize(variable_count, NullOrigin::Unassigned);
        self.frame_bytes += frame_bytes(&registers, &null_origins) - before;
        let params = callee.param_count();
        let line = self.location(pc).1;
        let arguments = self.routine.call_arguments(args, params);
        for (i, (&reg, variable)) in arguments.iter().zip(&callee.variables).enumerate() {
            let value = widen(Some(variable.ty), self.get(reg));
            if let Some(slot) = registers.get_mut(i) {
                *slot = value;
            }
            if value == Value::Null
                && let Some(origin) = null_origins.get_mut(i)
            {
                *origin = NullOrigin::Passed { line };
            }
        }
        self.new_arrays(callee, &mut registers, params)?;
        self.record(pc, Value::Null, Value::Null, Value::Null);
        let caller = Frame {
            routine: self.routine,
            index: self.current,
            registers: std::mem::replace(&mut self.registers, registers),
            null_origins: std::mem::replace(&mut self.null_origins, null_origins),
            variable_count: self.variable_count,
            return_pc: pc + 1,
            dst,
        };
        self.frames.push(caller);
        self.routine = callee;
        self.current = u32::from(number);
        self.variable_count = variable_count;
        let variables = self.registers.get(..variable_count).unwrap_or(&[]);
        let initial = callee.initial.get(..variable_count).unwrap_or(&[]);
        self.recorder.enter(self.current, variables, initial);
        Ok(())
    }

    /// Counts the values a call of routine `number` sets up, and stops the
    /// run when its calls have set up more than [`VALUES_PER_STEP`] for each
    /// step it may take.
    fn set_up_check(&mut self, pc: usize, number: u16) -> Option<Outcome> {
        let callee = self.routines.get(usize::from(number))?;
        let most = self.limit.saturating_mul(VALUES_PER_STEP);
        self.values_set_up += callee.initial.len();
        if self.values_set_up <= most {
            return None;
        }
        Some(self.stopped(
            pc,
            RuntimeErrorKind::StepLimit,
            format_args!(
                "the calls of this run set up more than {most} variables and intermediate \
                 values, the most a run may (each call of `{}` sets up {}); does it call in a \
                 loop that never ends?",
                callee.name,
                callee.initial.len()
            ),
        ))
    }

    /// Stops the run when what it holds has passed its memory budget.
    fn memory_check(&self, pc: usize) -> Option<Outcome> {
        let recorded = self.recorder.bytes();
        let parts = [
            ("the trace of its steps", recorded.other),
            ("the texts of its messages", recorded.messages),
            ("the variables of the calls in progress", self.frame_bytes),
            ("its arrays", self.arrays.bytes()),
            (
                "the rows and changes it made",
                self.created_rows * CREATED_ROW_BYTES
                    + self.store.journal().len() * (size_of::<Change>() + size_of::<u32>()),
            ),
        ];
        let held: usize = parts.iter().map(|(_, bytes)| bytes).sum();
        if held <= self.memory_limit {
            return None;
        }
        let largest = parts
            .iter()
            .max_by_key(|(_, bytes)| *bytes)
            .map_or("", |(part, _)| part);
        Some(self.stopped(
            pc,
            RuntimeErrorKind::MemoryLimit,
            format_args!(
                "the run would need more than {} MB of memory, the most a run may keep for its \
                 trace, variables, arrays and new rows (most of it for {largest})",
                self.memory_limit >> 20
            ),
        ))
    }

    /// Ends the running call: the caller runs again, with `result` in the
    /// call's register. Returns where the caller goes on.
    #[inline(never)]
    fn return_to_caller(&mut self, result: Option<Value>) -> usize {
        let Some(caller) = self.frames.pop() else {
            return self.routine.code.len();
        };
        let registers = std::mem::replace(&mut self.registers, caller.registers);
        let null_origins = std::mem::replace(&mut self.null_origins, caller.null_origins);
        self.spare.push((registers, null_origins));
        self.routine = caller.routine;
        self.current = caller.index;
        self.variable_count = caller.variable_count;
        self.set(caller.dst, result.unwrap_or(Value::Null));
        self.recorder.leave();
        caller.return_pc
    }

    /// Counts backward jumps, so a loop with no operation in it still meets
    /// the limit.
    #[inline(always)]
    fn jump(&mut self, pc: usize, target: u32) -> Option<Outcome> {
        if (target as usize) <= pc {
            self.back_jumps += 1;
            if self.back_jumps > self.limit {
                return Some(self.step_limit(pc));
            }
        }
        None
    }

    fn step_limit(&self, pc: usize) -> Outcome {
        self.stopped(
            pc,
            RuntimeErrorKind::StepLimit,
            format_args!(
                "the step limit was reached (the loop may never end; raise the limit to run \
                 longer)"
            ),
        )
    }

    /// A limit stopped the run at `pc`: "stopped after N operations: why".
    fn stopped(&self, pc: usize, kind: RuntimeErrorKind, why: fmt::Arguments<'_>) -> Outcome {
        self.error_at(
            pc,
            kind,
            format!("stopped after {} operations: {why}", self.steps),
        )
    }

    /// The run ends at `pc` with an error of `kind`.
    fn error_at(&self, pc: usize, kind: RuntimeErrorKind, message: String) -> Outcome {
        let (span, line) = self.location(pc);
        Outcome::Error(RuntimeError {
            kind,
            span,
            line,
            message,
        })
    }

    fn location(&self, pc: usize) -> (Span, u32) {
        self.routine
            .code
            .get(pc)
            .map_or((self.routine.span, self.routine.first_line), |i| {
                (i.span, i.line)
            })
    }

    /// `problem` with the code it happened in: "division by zero (1 div 0)
    /// in n div k".
    fn in_code(&self, problem: &str, pc: usize) -> String {
        format!("{problem} in {}", self.routine.snippet(self.location(pc).0))
    }

    fn fail(&self, pc: usize, message: String) -> Outcome {
        self.error_at(pc, RuntimeErrorKind::Fault, message)
    }

    fn format_message(&self, index: u32) -> String {
        let Some(template) = self.routine.messages.get(index as usize) else {
            return String::new();
        };
        let items: Vec<String> = template
            .items
            .iter()
            .map(|item| match item {
                MessageItem::Text(text) => text.clone(),
                MessageItem::Value(reg) => self.show(self.get(*reg)),
            })
            .filter(|item| !item.is_empty())
            .collect();
        items.join(" ")
    }

    /// A value as a message shows it: an array as its items.
    fn show(&self, value: Value) -> String {
        match self.arrays.list(value) {
            Ok(items) if matches!(value, Value::Array(_)) => super::types::show_items(items),
            _ => value.to_string(),
        }
    }

    fn note_null(&mut self, pc: usize, var: Reg, src: Reg) {
        let origin = if let Some(&origin) = self.null_origins.get(usize::from(src)) {
            origin
        } else if let Some((lookup_pc, base)) = self.writer_lookup(src) {
            NullOrigin::Lookup {
                pc: lookup_pc,
                base: self.get(base),
            }
        } else {
            NullOrigin::Assigned { pc }
        };
        if let Some(slot) = self.null_origins.get_mut(usize::from(var)) {
            *slot = origin;
        }
    }

    /// The lookup instruction that computes intermediate register `reg`, if
    /// one does (each intermediate register has a single writer).
    fn writer_lookup(&self, reg: Reg) -> Option<(usize, Reg)> {
        self.routine
            .code
            .iter()
            .enumerate()
            .find_map(|(pc, instr)| match instr.op {
                Op::Lookup { dst, base, .. } if dst == reg => Some((pc, base)),
                _ => None,
            })
    }

    /// Why a lookup yielded null: "edge 7 is on the boundary".
    fn null_reason(&self, lookup_pc: usize, base: Value) -> String {
        let Some(Op::Lookup { field, .. }) = self.routine.code.get(lookup_pc).map(|i| i.op) else {
            return "it was never set".to_owned();
        };
        match field {
            face if face.target() == Some(ElementKind::Face) => {
                format!("{base} is on the boundary")
            }
            other => format!("{base} has no {}", other.key()),
        }
    }

    /// "`e.leftFace` is null (edge 7 is on the boundary)", or for a variable,
    /// where its null came from.
    fn explain_null(&self, reg: Reg) -> String {
        if let Some(&origin) = self.null_origins.get(usize::from(reg)) {
            let name = self.routine.register_name(reg);
            return match origin {
                NullOrigin::Unassigned => format!("{name} is null (it has not been assigned yet)"),
                NullOrigin::Lookup { pc, base } => {
                    let (span, line) = self.location(pc);
                    format!(
                        "{name} is null (set from {} on line {line}: {})",
                        self.routine.snippet(span),
                        self.null_reason(pc, base)
                    )
                }
                NullOrigin::Assigned { pc } => {
                    let (_, line) = self.location(pc);
                    format!("{name} is null (assigned on line {line})")
                }
                NullOrigin::Passed { line } => {
                    format!("{name} is null (the call on line {line} passed null)")
                }
            };
        }
        if let Some((pc, base)) = self.writer_lookup(reg) {
            let (span, _) = self.location(pc);
            return format!(
                "{} is null ({})",
                self.routine.snippet(span),
                self.null_reason(pc, self.get(base))
            );
        }
        "null has no lookups".to_owned()
    }

    /// Why a write was refused; a null value says where the null came from.
    fn write_refused(&self, error: String, value: Value, src: Reg) -> String {
        if value == Value::Null && error.contains("cannot be empty") {
            return format!("{error}: {}", self.explain_null(src));
        }
        error
    }

    fn cannot_act_message(&self, word: &str, reg: Reg) -> String {
        format!("cannot {word} null: {}", self.explain_null(reg))
    }
}

fn index_u32(n: usize) -> u32 {
    u32::try_from(n).unwrap_or(u32::MAX)
}

/// `value` as a variable or item of type `ty` holds it: an Integer
/// widens to a Float.
#[inline(always)]
fn widen(ty: Option<Type>, value: Value) -> Value {
    match (ty, value) {
        (Some(Type::Float), Value::Integer(n)) => Value::Float(n as f32),
        _ => value,
    }
}

/// `l op r` for numbers of one kind: Integers exactly, Floats as floats.
#[inline]
fn holds<T: PartialOrd + Copy>(op: CompareOp, l: T, r: T) -> bool {
    match op {
        CompareOp::Eq => l == r,
        CompareOp::NotEq => l != r,
        CompareOp::Lt => l < r,
        CompareOp::Le => l <= r,
        CompareOp::Gt => l > r,
        CompareOp::Ge => l >= r,
    }
}

#[inline]
fn compare(op: CompareOp, left: Value, right: Value) -> bool {
    if let (Value::Integer(l), Value::Integer(r)) = (left, right) {
        return holds(op, l, r);
    }
    if let (Some(l), Some(r)) = (left.number(), right.number()) {
        return holds(op, l, r);
    }
    match op {
        CompareOp::Eq => left == right,
        CompareOp::NotEq => left != right,
        _ => false,
    }
}

fn compute(op: ComputeOp, left: Value, right: Value) -> Result<Value, String> {
    match (op, left, right) {
        (ComputeOp::Not, Value::Boolean(b), _) => Ok(Value::Boolean(!b)),
        (ComputeOp::Coordinate(axis), Value::Vector(v), _) => Ok(Value::Float(axis.of(v))),
        (ComputeOp::Neg, Value::Vector(v), _) => Ok(Value::Vector(-v)),
        (ComputeOp::Neg, Value::Float(x), _) => Ok(Value::Float(-x)),
        (_, Value::Integer(l), Value::Integer(r)) if op != ComputeOp::Divide => integer(op, l, r),
        (_, Value::Vector(_), _) | (_, _, Value::Vector(_)) => vector(op, left, right),
        _ => match (left.number(), right.number()) {
            (Some(l), Some(r)) => float(op, l, r),
            _ => Err("not a number".to_owned()),
        },
    }
}

fn integer(op: ComputeOp, l: i32, r: i32) -> Result<Value, String> {
    let result = match op {
        ComputeOp::Add => l.checked_add(r),
        ComputeOp::Sub => l.checked_sub(r),
        ComputeOp::Mul => l.checked_mul(r),
        ComputeOp::Div | ComputeOp::Mod if r == 0 => {
            return Err(format!("division by zero ({l} {} 0)", op.symbol()));
        }
        ComputeOp::Div => l.checked_div(r),
        ComputeOp::Mod => l.checked_rem(r),
        ComputeOp::Neg => l.checked_neg(),
        _ => None,
    };
    result.map(Value::Integer).ok_or_else(|| {
        if op.is_unary() {
            format!("integer overflow ({} {l})", op.symbol())
        } else {
            format!("integer overflow ({l} {} {r})", op.symbol())
        }
    })
}

fn float(op: ComputeOp, l: f32, r: f32) -> Result<Value, String> {
    let result = match op {
        ComputeOp::Add => l + r,
        ComputeOp::Sub => l - r,
        ComputeOp::Mul => l * r,
        ComputeOp::Divide if r == 0.0 => {
            return Err(format!("division by zero ({} / 0)", Value::Float(l)));
        }
        ComputeOp::Divide => l / r,
        _ => return Err("not a Float operation".to_owned()),
    };
    if result.is_finite() {
        Ok(Value::Float(result))
    } else {
        Err(format!(
            "Float overflow ({} {} {})",
            Value::Float(l),
            op.symbol(),
            Value::Float(r)
        ))
    }
}

fn vector(op: ComputeOp, left: Value, right: Value) -> Result<Value, String> {
    let result = match (op, left, right) {
        (ComputeOp::Add, Value::Vector(a), Value::Vector(b)) => a + b,
        (ComputeOp::Sub, Value::Vector(a), Value::Vector(b)) => a - b,
        (ComputeOp::Mul, Value::Vector(a), n) | (ComputeOp::Mul, n, Value::Vector(a)) => {
            a * n.number().ok_or("a Vector is scaled by a number")?
        }
        (ComputeOp::Divide, Value::Vector(a), n) => {
            let n = n.number().ok_or("a Vector is divided by a number")?;
            if n == 0.0 {
                return Err(format!("division by zero ({left} / 0)"));
            }
            a / n
        }
        _ => return Err("not a Vector operation".to_owned()),
    };
    if result.is_finite() {
        Ok(Value::Vector(result))
    } else {
        Err(format!("Float overflow ({left} {} {right})", op.symbol()))
    }
}
