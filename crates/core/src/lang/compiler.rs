//! Compiles a checked algorithm to linear code, as the papers' system did:
//! jumps, lookups, assignments, comparisons, marks and so on, each carrying
//! the source span of the expression it executes so the view can highlight
//! exactly that piece of the line (the journal's Fig. 7).

use super::ast::*;
use super::builtin::{Axis, Builtin};
use super::checker::{Scope, Signatures};
use super::diagnostic::{Diagnostic, LineIndex, Span};
use super::types::{Item, Type, Value};
use crate::schema::{Column, ElementKind, Structure};
use std::fmt;
use std::ops::Deref;
use std::sync::Arc;

/// A register number. Registers hold the variables (parameters first), then
/// one register per intermediate value, then the constants.
pub type Reg = u16;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CompareOp {
    Eq,
    NotEq,
    Lt,
    Le,
    Gt,
    Ge,
}

impl CompareOp {
    pub fn symbol(self) -> &'static str {
        match self {
            CompareOp::Eq => "=",
            CompareOp::NotEq => "<>",
            CompareOp::Lt => "<",
            CompareOp::Le => "<=",
            CompareOp::Gt => ">",
            CompareOp::Ge => ">=",
        }
    }
}

/// Arithmetic on Integers, Floats and Vectors, and `not`. The unary ones
/// (`Neg`, `Not`, a coordinate) use only the left operand.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ComputeOp {
    Add,
    Sub,
    Mul,
    /// `/`: Float division.
    Divide,
    Div,
    Mod,
    Neg,
    Not,
    /// A Vector's coordinate: `p.x`.
    Coordinate(Axis),
}

impl ComputeOp {
    pub fn symbol(self) -> &'static str {
        match self {
            ComputeOp::Add => "+",
            ComputeOp::Sub | ComputeOp::Neg => "-",
            ComputeOp::Mul => "*",
            ComputeOp::Divide => "/",
            ComputeOp::Div => "div",
            ComputeOp::Mod => "mod",
            ComputeOp::Not => "not",
            ComputeOp::Coordinate(axis) => axis.name(),
        }
    }

    pub fn is_unary(self) -> bool {
        matches!(
            self,
            ComputeOp::Neg | ComputeOp::Not | ComputeOp::Coordinate(_)
        )
    }
}

/// One instruction. Every instruction but Move and the jumps (bookkeeping)
/// produces one trace step.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Op {
    /// `base.field := src`: a write into a record (or a vertex's position).
    Write {
        base: Reg,
        field: Column,
        src: Reg,
    },
    /// `new Vertex`: a row with the next free id.
    New {
        dst: Reg,
        kind: ElementKind,
    },
    /// `delete x`.
    Delete {
        element: Reg,
    },
    /// A built-in function on numbers; `args` holds `argc` registers.
    Call {
        dst: Reg,
        builtin: Builtin,
        args: [Reg; 3],
        argc: u8,
    },
    /// Calls algorithm number `routine` of the file: its parameters take
    /// the values of the registers listed from `args` in
    /// [`Routine::arguments`], and its result lands in `dst`.
    Invoke {
        dst: Reg,
        routine: u16,
        args: u32,
    },
    /// Back to the caller, with `src`'s value if `value` is set.
    Return {
        src: Reg,
        value: bool,
    },
    /// `dst := array[index]`.
    Index {
        dst: Reg,
        array: Reg,
        index: Reg,
    },
    /// `array[index] := src`.
    Store {
        array: Reg,
        index: Reg,
        src: Reg,
    },
    /// `append(array, src)`.
    Append {
        array: Reg,
        src: Reg,
    },
    /// `dst := length(array)`.
    Length {
        dst: Reg,
        array: Reg,
    },
    Lookup {
        dst: Reg,
        base: Reg,
        field: Column,
    },
    Assign {
        var: Reg,
        src: Reg,
    },
    Compare {
        dst: Reg,
        op: CompareOp,
        left: Reg,
        right: Reg,
    },
    Compute {
        dst: Reg,
        op: ComputeOp,
        left: Reg,
        right: Reg,
    },
    Move {
        dst: Reg,
        src: Reg,
    },
    Mark {
        element: Reg,
    },
    Highlight {
        element: Reg,
    },
    Message {
        index: u32,
    },
    /// Stops the run with message `index` as the reason.
    Refuse {
        index: u32,
    },
    Jump {
        target: u32,
    },
    JumpIf {
        cond: Reg,
        when: bool,
        target: u32,
    },
    Done,
}

impl Op {
    /// Whether executing this instruction records a trace step.
    pub fn is_step(self) -> bool {
        !matches!(self, Op::Move { .. } | Op::Jump { .. } | Op::JumpIf { .. })
    }

    /// Whether it changes the mesh.
    pub fn is_edit(self) -> bool {
        matches!(self, Op::Write { .. } | Op::New { .. } | Op::Delete { .. })
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Instr {
    pub op: Op,
    /// The expression or statement executed.
    pub span: Span,
    /// The 1-based line of the span's start.
    pub line: u32,
}

/// One item of a `message` statement: fixed text or a value's register.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum MessageItem {
    Text(String),
    Value(Reg),
}

/// `message "text", value, …`: shown with the items separated by spaces.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct MessageTemplate {
    pub items: Vec<MessageItem>,
}

/// A parameter or variable of a compiled algorithm; its register is its index.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct VariableInfo {
    pub name: String,
    pub ty: Type,
    pub is_param: bool,
}

/// One compiled algorithm of a file. [`Algorithm`] is how the rest of the
/// program holds one: it keeps the whole file's routines, which its calls
/// name by number.
#[derive(Clone, Debug)]
pub struct Routine {
    pub name: String,
    pub description: Option<String>,
    pub structure: Structure,
    /// Parameters first, then declared variables.
    pub variables: Vec<VariableInfo>,
    /// The static type of every register, so trace steps can be stored as
    /// bare 32-bit codes and decoded on demand.
    pub registers: Vec<Type>,
    pub constants: Vec<(Reg, Value)>,
    pub messages: Vec<MessageTemplate>,
    pub code: Vec<Instr>,
    /// The type of the value it returns (`returns Boolean`), if any.
    pub result: Option<Type>,
    /// The argument registers of its calls ([`Op::Invoke`]), each call's
    /// in a run as long as the callee's parameters.
    pub arguments: Vec<Reg>,
    /// The register file a run starts from: each type's initial value and
    /// the constants, copied in one go at each call.
    pub(crate) initial: Vec<Value>,
    /// The array variables, which each run or call gives new arrays.
    pub(crate) array_variables: Vec<(Reg, Item)>,
    /// The whole file's text, shared by the algorithms compiled from it.
    pub source: Arc<str>,
    /// `algorithm` through the closing `end`.
    pub span: Span,
    pub first_line: u32,
    pub last_line: u32,
}

/// The compiled algorithms of one file.
#[derive(Debug)]
pub struct Unit {
    pub routines: Vec<Routine>,
}

/// A compiled algorithm, ready to run on any mesh of its structure, with
/// the algorithms of its file that it may call. It reads as its
/// [`Routine`] (`algorithm.name`, `algorithm.code`).
#[derive(Clone)]
pub struct Algorithm {
    unit: Arc<Unit>,
    /// Its number in `unit`, always in range.
    index: usize,
}

impl Deref for Algorithm {
    type Target = Routine;

    fn deref(&self) -> &Routine {
        &self.unit.routines[self.index]
    }
}

impl fmt::Debug for Algorithm {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Debug::fmt(&**self, f)
    }
}

impl Algorithm {
    /// Every algorithm of its file, in file order; calls name them by
    /// their index here.
    pub fn routines(&self) -> &[Routine] {
        &self.unit.routines
    }

    /// Its own index in [`Self::routines`].
    pub fn index(&self) -> usize {
        self.index
    }

    /// Whether it calls another algorithm, so stepping over and out of
    /// calls means something.
    pub fn calls_others(&self) -> bool {
        self.code
            .iter()
            .any(|instr| matches!(instr.op, Op::Invoke { .. }))
    }

    /// Whether another algorithm of its file calls it: a helper, which the
    /// app lists apart from the algorithms meant to be started.
    pub fn is_helper(&self) -> bool {
        self.routines().iter().enumerate().any(|(index, routine)| {
            index != self.index
                && routine.code.iter().any(|instr| {
                    matches!(instr.op, Op::Invoke { routine, .. } if usize::from(routine) == self.index)
                })
        })
    }

    /// Whether running it changes the mesh: it, or an algorithm it calls
    /// (directly or not), writes a record, or makes or deletes an element.
    pub fn edits(&self) -> bool {
        let routines = self.routines();
        let mut seen = vec![false; routines.len()];
        let mut stack = vec![self.index];
        while let Some(index) = stack.pop() {
            let Some(routine) = routines.get(index) else {
                continue;
            };
            if std::mem::replace(&mut seen[index], true) {
                continue;
            }
            if routine.writes() {
                return true;
            }
            stack.extend(routine.code.iter().filter_map(|instr| match instr.op {
                Op::Invoke { routine, .. } => Some(usize::from(routine)),
                _ => None,
            }));
        }
        false
    }
}

impl Routine {
    pub fn params(&self) -> impl Iterator<Item = &VariableInfo> {
        self.variables.iter().take_while(|v| v.is_param)
    }

    /// Whether its own code changes the mesh; [`Algorithm::edits`] also
    /// asks the algorithms it calls.
    pub fn writes(&self) -> bool {
        self.code.iter().any(|instr| instr.op.is_edit())
    }

    pub fn param_count(&self) -> usize {
        self.variables.iter().take_while(|v| v.is_param).count()
    }

    /// The algorithm's own source text, from `algorithm` to `end`.
    pub fn text(&self) -> &str {
        self.span.text(&self.source)
    }

    /// The source under `span` with runs of whitespace collapsed, for traces
    /// and messages.
    pub fn snippet(&self, span: Span) -> String {
        span.text(&self.source)
            .split_whitespace()
            .collect::<Vec<_>>()
            .join(" ")
    }

    pub fn register_type(&self, reg: Reg) -> Type {
        self.registers
            .get(usize::from(reg))
            .copied()
            .unwrap_or(Type::Null)
    }

    /// A register's name in the disassembly: the variable's, `t5` for an
    /// intermediate value, or the constant itself.
    pub fn register_name(&self, reg: Reg) -> String {
        if let Some(variable) = self.variables.get(usize::from(reg)) {
            return variable.name.clone();
        }
        if let Some((_, value)) = self.constants.iter().find(|(r, _)| *r == reg) {
            return value.to_string();
        }
        format!("t{reg}")
    }

    /// The header as written in the Neperud dialect, e.g.
    /// `vertexAdjacentEdge(v : Vertex) : WingedEdge`, or
    /// `isTriangle(f : Face) : HalfEdge returns Boolean`.
    pub fn signature(&self) -> String {
        let params: Vec<String> = self
            .params()
            .map(|p| format!("{} : {}", p.name, p.ty))
            .collect();
        let mut text = format!("{}({}) : {}", self.name, params.join("; "), self.structure);
        if let Some(result) = self.result {
            text.push_str(&format!(" returns {result}"));
        }
        text
    }

    /// The argument registers of the call whose [`Op::Invoke`] has `args`,
    /// `count` of them.
    pub fn call_arguments(&self, args: u32, count: usize) -> &[Reg] {
        let start = args as usize;
        self.arguments
            .get(start..start.saturating_add(count))
            .unwrap_or(&[])
    }
}

/// Compiles every algorithm of a file that passed the checker. Fails only
/// for limits the checker does not know about (more than 65,535 registers
/// in an algorithm, or algorithms in a file).
pub fn compile_file(
    file: &SourceFile,
    scopes: &[Scope],
    source: &Arc<str>,
    lines: &LineIndex,
) -> Result<Vec<Arc<Algorithm>>, Vec<Diagnostic>> {
    let signatures = Signatures::of(file);
    let mut routines = Vec::with_capacity(file.algorithms.len());
    let mut diagnostics = Vec::new();
    if u16::try_from(file.algorithms.len()).is_err() {
        let span = file
            .algorithms
            .last()
            .map_or(Span::default(), |a| a.name.span);
        return Err(vec![Diagnostic::error(
            span,
            "this file holds too many algorithms to compile (over 65,535)",
        )]);
    }
    for (decl, scope) in file.algorithms.iter().zip(scopes) {
        match compile_algorithm(decl, scope, &signatures, source, lines) {
            Ok(routine) => routines.push(routine),
            Err(diagnostic) => diagnostics.push(diagnostic),
        }
    }
    if !diagnostics.is_empty() {
        return Err(diagnostics);
    }
    let unit = Arc::new(Unit { routines });
    Ok((0..unit.routines.len())
        .map(|index| {
            Arc::new(Algorithm {
                unit: Arc::clone(&unit),
                index,
            })
        })
        .collect())
}

/// Compiles one algorithm that passed the checker; its calls are resolved
/// against the file's `signatures`.
fn compile_algorithm(
    decl: &AlgorithmDecl,
    scope: &Scope,
    signatures: &Signatures,
    source: &Arc<str>,
    lines: &LineIndex,
) -> Result<Routine, Diagnostic> {
    let structure = decl.structure.map_or(Structure::WingedEdge, |(s, _)| s);
    let variables: Vec<VariableInfo> = scope
        .variables
        .iter()
        .map(|v| VariableInfo {
            name: v.name.clone(),
            ty: v.ty.unwrap_or(Type::Null),
            is_param: v.is_param,
        })
        .collect();
    let mut compiler = Compiler {
        scope,
        signatures,
        arguments: Vec::new(),
        structure,
        lines,
        registers: variables.iter().map(|v| v.ty).collect(),
        constants: Vec::new(),
        messages: Vec::new(),
        code: Vec::new(),
        labels: Vec::new(),
        loops: Vec::new(),
        overflow: false,
    };
    compiler.statements(&decl.body);
    compiler.emit(Op::Done, decl.end_span);
    if compiler.overflow {
        return Err(Diagnostic::error(
            decl.name.span,
            "this algorithm is too large to compile (over 65,535 values)",
        ));
    }
    compiler.patch_jumps();
    let mut initial: Vec<Value> = compiler
        .registers
        .iter()
        .map(|ty| ty.default_value())
        .collect();
    for &(reg, value) in &compiler.constants {
        if let Some(slot) = initial.get_mut(usize::from(reg)) {
            *slot = value;
        }
    }
    let array_variables = (0..)
        .zip(&variables)
        .filter_map(|(reg, v)| match v.ty {
            Type::Array(item) => Some((reg, item)),
            _ => None,
        })
        .collect();
    Ok(Routine {
        name: decl.name.name.clone(),
        description: decl.description.clone(),
        structure,
        variables,
        registers: compiler.registers,
        constants: compiler.constants,
        messages: compiler.messages,
        code: compiler.code,
        result: decl.returns.and_then(|(ty, _)| ty),
        arguments: compiler.arguments,
        initial,
        array_variables,
        source: Arc::clone(source),
        span: decl.span,
        first_line: lines.line(decl.span.start),
        last_line: lines.line(decl.end_span.start),
    })
}

type Label = u32;

struct Loop {
    break_to: Label,
    continue_to: Label,
}

struct Compiler<'a> {
    scope: &'a Scope,
    signatures: &'a Signatures,
    /// Argument registers of the calls, see [`Routine::arguments`].
    arguments: Vec<Reg>,
    structure: Structure,
    lines: &'a LineIndex,
    registers: Vec<Type>,
    constants: Vec<(Reg, Value)>,
    messages: Vec<MessageTemplate>,
    code: Vec<Instr>,
    /// Each label's instruction index, once placed.
    labels: Vec<Option<u32>>,
    loops: Vec<Loop>,
    overflow: bool,
}

impl Compiler<'_> {
    fn emit(&mut self, op: Op, span: Span) {
        let line = self.lines.line(span.start);
        self.code.push(Instr { op, span, line });
    }

    fn register(&mut self, ty: Type) -> Reg {
        if let Ok(reg) = Reg::try_from(self.registers.len()) {
            self.registers.push(ty);
            reg
        } else {
            self.overflow = true;
            0
        }
    }

    fn constant(&mut self, value: Value, ty: Type) -> Reg {
        if let Some(&(reg, _)) = self
            .constants
            .iter()
            .find(|&&(reg, v)| v == value && self.registers.get(usize::from(reg)) == Some(&ty))
        {
            return reg;
        }
        let reg = self.register(ty);
        self.constants.push((reg, value));
        reg
    }

    fn new_label(&mut self) -> Label {
        self.labels.push(None);
        u32::try_from(self.labels.len() - 1).unwrap_or(u32::MAX)
    }

    fn place(&mut self, label: Label) {
        let here = u32::try_from(self.code.len()).unwrap_or(u32::MAX);
        if let Some(slot) = self.labels.get_mut(label as usize) {
            *slot = Some(here);
        }
    }

    /// Jumps are emitted with label numbers; this turns them into addresses.
    fn patch_jumps(&mut self) {
        let labels = &self.labels;
        let resolve = |label: u32| labels.get(label as usize).copied().flatten().unwrap_or(0);
        for instr in &mut self.code {
            match &mut instr.op {
                Op::Jump { target } | Op::JumpIf { target, .. } => *target = resolve(*target),
                _ => {}
            }
        }
    }

    fn variable(&self, name: &str) -> Reg {
        self.scope
            .find(name)
            .and_then(|(i, _)| Reg::try_from(i).ok())
            .unwrap_or(0)
    }

    fn statements(&mut self, statements: &[Stmt]) {
        for statement in statements {
            self.statement(statement);
        }
    }

    fn statement(&mut self, statement: &Stmt) {
        let span = statement.span;
        match &statement.kind {
            StmtKind::Assign { target, value } => {
                let src = self.expr(value);
                let var = self.variable(&target.name);
                self.emit(Op::Assign { var, src }, span);
            }
            StmtKind::Write { base, field, value } => {
                let src = self.expr(value);
                let base_reg = self.expr(base);
                let kind = self.register_type(base_reg).element_kind();
                if let Some(field) =
                    kind.and_then(|k| Column::resolve(self.structure, k, &field.name).ok())
                {
                    self.emit(
                        Op::Write {
                            base: base_reg,
                            field,
                            src,
                        },
                        span,
                    );
                }
            }
            StmtKind::Store {
                array,
                index,
                value,
            } => {
                let src = self.expr(value);
                let array = self.expr(array);
                let index = self.expr(index);
                self.emit(Op::Store { array, index, src }, span);
            }
            StmtKind::Call { name, args } => {
                if Builtin::parse(&name.name) == Some(Builtin::Append) {
                    if let [array, value] = args.as_slice() {
                        let src = self.expr(value);
                        let array = self.expr(array);
                        self.emit(Op::Append { array, src }, span);
                    }
                } else {
                    self.invoke(name, args, span);
                }
            }
            StmtKind::Return { value } => {
                let op = match value {
                    Some(value) => Op::Return {
                        src: self.expr(value),
                        value: true,
                    },
                    None => Op::Return {
                        src: 0,
                        value: false,
                    },
                };
                self.emit(op, span);
            }
            StmtKind::Delete { target } => {
                let element = self.expr(target);
                self.emit(Op::Delete { element }, span);
            }
            StmtKind::If { arms, otherwise } => {
                let end = self.new_label();
                for (i, (cond, body)) in arms.iter().enumerate() {
                    let next = self.new_label();
                    self.jump_unless(cond, false, next);
                    self.statements(body);
                    if i + 1 < arms.len() || otherwise.is_some() {
                        self.emit(Op::Jump { target: end }, cond.span);
                    }
                    self.place(next);
                }
                if let Some(body) = otherwise {
                    self.statements(body);
                }
                self.place(end);
            }
            StmtKind::While { cond, body } => {
                let (top, end) = (self.new_label(), self.new_label());
                self.place(top);
                self.jump_unless(cond, false, end);
                self.loop_body(body, end, top);
                self.emit(Op::Jump { target: top }, cond.span);
                self.place(end);
            }
            StmtKind::DoWhile { body, cond } => {
                let (top, test, end) = (self.new_label(), self.new_label(), self.new_label());
                self.place(top);
                self.loop_body(body, end, test);
                self.place(test);
                self.jump_unless(cond, true, top);
                self.place(end);
            }
            StmtKind::Loop { body } => {
                let (top, end) = (self.new_label(), self.new_label());
                self.place(top);
                self.loop_body(body, end, top);
                self.emit(Op::Jump { target: top }, span);
                self.place(end);
            }
            StmtKind::Block(body) => self.statements(body),
            StmtKind::Break => {
                if let Some(target) = self.loops.last().map(|l| l.break_to) {
                    self.emit(Op::Jump { target }, span);
                }
            }
            StmtKind::Continue => {
                if let Some(target) = self.loops.last().map(|l| l.continue_to) {
                    self.emit(Op::Jump { target }, span);
                }
            }
            StmtKind::Action { action, target } => {
                let element = self.expr(target);
                let op = match action {
                    Action::Mark => Op::Mark { element },
                    Action::Highlight => Op::Highlight { element },
                };
                self.emit(op, span);
            }
            StmtKind::Message { parts } | StmtKind::Refuse { parts } => {
                let refuse = matches!(statement.kind, StmtKind::Refuse { .. });
                let items = parts
                    .iter()
                    .map(|part| match part {
                        MessagePart::Text(text) => MessageItem::Text(text.clone()),
                        MessagePart::Value(value) => MessageItem::Value(self.expr(value)),
                    })
                    .collect();
                let index = u32::try_from(self.messages.len()).unwrap_or(u32::MAX);
                self.messages.push(MessageTemplate { items });
                if refuse {
                    self.emit(Op::Refuse { index }, span);
                } else {
                    self.emit(Op::Message { index }, span);
                }
            }
            StmtKind::Error => {}
        }
    }

    fn loop_body(&mut self, body: &[Stmt], break_to: Label, continue_to: Label) {
        self.loops.push(Loop {
            break_to,
            continue_to,
        });
        self.statements(body);
        self.loops.pop();
    }

    /// Emits code that jumps to `target` when `cond` evaluates to `when`,
    /// short-circuiting `and`, `or` and `not` into jumps.
    fn jump_unless(&mut self, cond: &Expr, when: bool, target: Label) {
        match &cond.kind {
            ExprKind::Boolean(value) => {
                if *value == when {
                    self.emit(Op::Jump { target }, cond.span);
                }
            }
            ExprKind::Unary {
                op: UnaryOp::Not,
                operand,
            } => self.jump_unless(operand, !when, target),
            ExprKind::Binary {
                op: op @ (BinaryOp::And | BinaryOp::Or),
                left,
                right,
            } => {
                // `a and b` is false as soon as `a` is; `a or b` true as soon as `a` is.
                let decisive = *op == BinaryOp::Or;
                if when == decisive {
                    self.jump_unless(left, when, target);
                    self.jump_unless(right, when, target);
                } else {
                    let skip = self.new_label();
                    self.jump_unless(left, decisive, skip);
                    self.jump_unless(right, when, target);
                    self.place(skip);
                }
            }
            _ => {
                let reg = self.expr(cond);
                self.emit(
                    Op::JumpIf {
                        cond: reg,
                        when,
                        target,
                    },
                    cond.span,
                );
            }
        }
    }

    /// Emits code computing `expr` and returns the register holding it.
    fn expr(&mut self, expr: &Expr) -> Reg {
        let span = expr.span;
        match &expr.kind {
            ExprKind::Name(name) => self.variable(name),
            ExprKind::Integer(n) => self.constant(Value::Integer(*n), Type::Integer),
            ExprKind::Float(x) => self.constant(Value::Float(*x), Type::Float),
            ExprKind::Boolean(b) => self.constant(Value::Boolean(*b), Type::Boolean),
            ExprKind::Null | ExprKind::Error => self.constant(Value::Null, Type::Null),
            ExprKind::New(kind) => {
                let dst = self.register(Type::of_kind(*kind));
                self.emit(Op::New { dst, kind: *kind }, span);
                dst
            }
            ExprKind::Index { array, index } => {
                let array = self.expr(array);
                let index = self.expr(index);
                let item = self.register_type(array).item().unwrap_or(Type::Null);
                let dst = self.register(item);
                self.emit(Op::Index { dst, array, index }, span);
                dst
            }
            ExprKind::Call { name, args } => match Builtin::parse(&name.name) {
                Some(builtin) => self.builtin(builtin, args, span),
                None => self.invoke(name, args, span),
            },
            ExprKind::Lookup { base, field } => self.lookup(base, field, span),
            ExprKind::Unary { op, operand } => {
                let operand = self.expr(operand);
                let (op, ty) = match op {
                    UnaryOp::Neg => (ComputeOp::Neg, self.register_type(operand)),
                    UnaryOp::Not => (ComputeOp::Not, Type::Boolean),
                };
                self.compute(ty, op, operand, operand, span)
            }
            ExprKind::Binary {
                op: op @ (BinaryOp::And | BinaryOp::Or),
                left,
                right,
            } => self.short_circuit(*op == BinaryOp::Or, left, right, span),
            ExprKind::Binary { op, left, right } => self.binary(*op, left, right, span),
        }
    }

    /// A call of a built-in function: `length` of an array, or one of the
    /// others with up to three arguments.
    fn builtin(&mut self, builtin: Builtin, args: &[Expr], span: Span) -> Reg {
        if builtin == Builtin::Length {
            let array = args.first().map_or(0, |array| self.expr(array));
            let dst = self.register(Type::Integer);
            self.emit(Op::Length { dst, array }, span);
            return dst;
        }
        let mut regs = [0; 3];
        for (slot, arg) in regs.iter_mut().zip(args) {
            *slot = self.expr(arg);
        }
        let dst = self.register(builtin.result().unwrap_or(Type::Null));
        self.emit(
            Op::Call {
                dst,
                builtin,
                args: regs,
                argc: args.len().min(3) as u8,
            },
            span,
        );
        dst
    }

    /// `base.field`: a coordinate of a vector, or a column of an element's
    /// record (the paper's lookup). The checker has refused any other field,
    /// so an unknown one only yields `null` here.
    fn lookup(&mut self, base: &Expr, field: &Ident, span: Span) -> Reg {
        let base_reg = self.expr(base);
        let base_type = self.register_type(base_reg);
        if base_type == Type::Vector {
            let Some(axis) = Axis::parse(&field.name) else {
                return self.constant(Value::Null, Type::Null);
            };
            let op = ComputeOp::Coordinate(axis);
            return self.compute(Type::Float, op, base_reg, base_reg, span);
        }
        let kind = base_type.element_kind();
        let resolved = kind.and_then(|k| Column::resolve(self.structure, k, &field.name).ok());
        let Some(field) = resolved else {
            return self.constant(Value::Null, Type::Null);
        };
        let dst = self.register(field.target().map_or(Type::Vector, Type::of_kind));
        self.emit(
            Op::Lookup {
                dst,
                base: base_reg,
                field,
            },
            span,
        );
        dst
    }

    /// `left and right`, `left or right`: the right side runs only when
    /// the left one does not decide (`or` stops on true, `and` on false).
    fn short_circuit(&mut self, or: bool, left: &Expr, right: &Expr, span: Span) -> Reg {
        let dst = self.register(Type::Boolean);
        let left = self.expr(left);
        self.emit(Op::Move { dst, src: left }, span);
        let done = self.new_label();
        self.emit(
            Op::JumpIf {
                cond: dst,
                when: or,
                target: done,
            },
            span,
        );
        let right = self.expr(right);
        self.emit(Op::Move { dst, src: right }, span);
        self.place(done);
        dst
    }

    /// A comparison, or arithmetic typed by [`result_type`].
    fn binary(&mut self, op: BinaryOp, left: &Expr, right: &Expr, span: Span) -> Reg {
        let left = self.expr(left);
        let right = self.expr(right);
        let compare = match op {
            BinaryOp::Eq => Some(CompareOp::Eq),
            BinaryOp::NotEq => Some(CompareOp::NotEq),
            BinaryOp::Lt => Some(CompareOp::Lt),
            BinaryOp::Le => Some(CompareOp::Le),
            BinaryOp::Gt => Some(CompareOp::Gt),
            BinaryOp::Ge => Some(CompareOp::Ge),
            _ => None,
        };
        if let Some(op) = compare {
            let dst = self.register(Type::Boolean);
            self.emit(
                Op::Compare {
                    dst,
                    op,
                    left,
                    right,
                },
                span,
            );
            return dst;
        }
        let ty = result_type(op, self.register_type(left), self.register_type(right));
        let op = match op {
            BinaryOp::Add => ComputeOp::Add,
            BinaryOp::Sub => ComputeOp::Sub,
            BinaryOp::Mul => ComputeOp::Mul,
            BinaryOp::Divide => ComputeOp::Divide,
            BinaryOp::Div => ComputeOp::Div,
            _ => ComputeOp::Mod,
        };
        self.compute(ty, op, left, right, span)
    }

    /// `op` on `left` and `right` (one operand, given twice, for a unary
    /// `op`) into a new register of type `ty`.
    fn compute(&mut self, ty: Type, op: ComputeOp, left: Reg, right: Reg, span: Span) -> Reg {
        let dst = self.register(ty);
        self.emit(
            Op::Compute {
                dst,
                op,
                left,
                right,
            },
            span,
        );
        dst
    }

    /// Emits a call of another algorithm of the file and returns the
    /// register its result lands in (a `null` one when it has none).
    fn invoke(&mut self, name: &Ident, args: &[Expr], span: Span) -> Reg {
        let Some((index, callee)) = self.signatures.find(&name.name) else {
            return self.constant(Value::Null, Type::Null);
        };
        let result = callee.returns.flatten();
        let registers: Vec<Reg> = args.iter().map(|arg| self.expr(arg)).collect();
        let start = u32::try_from(self.arguments.len()).unwrap_or(u32::MAX);
        self.arguments.extend(registers);
        let dst = self.register(result.unwrap_or(Type::Null));
        let Ok(routine) = u16::try_from(index) else {
            self.overflow = true;
            return dst;
        };
        self.emit(
            Op::Invoke {
                dst,
                routine,
                args: start,
            },
            span,
        );
        dst
    }

    fn register_type(&self, reg: Reg) -> Type {
        self.registers
            .get(usize::from(reg))
            .copied()
            .unwrap_or(Type::Null)
    }
}

/// The type `+ - * /` give: Integer only from two Integers, a Vector if
/// either side is one, otherwise Float.
fn result_type(op: BinaryOp, left: Type, right: Type) -> Type {
    if left == Type::Vector || right == Type::Vector {
        Type::Vector
    } else if op == BinaryOp::Divide || left == Type::Float || right == Type::Float {
        Type::Float
    } else {
        Type::Integer
    }
}
