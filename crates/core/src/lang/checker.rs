//! Name resolution and type checking.
//!
//! The checker reports every problem it can find in one pass; an expression
//! whose type is unknown because of an earlier error is typed `None`, which
//! silences follow-on messages about it.

use std::collections::{HashMap, HashSet};

use super::ast::*;
use super::builtin::{Axis, Builtin};
use super::diagnostic::{Diagnostic, MAX_ERRORS, Span, nearest};
use super::types::Type;
use crate::schema::{Column, ElementKind, NameError, Storage, Structure};

/// A parameter or declared variable. Parameters come first, in order.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Variable {
    pub name: String,
    /// `None` only when the declared type was not understood (reported).
    pub ty: Option<Type>,
    pub is_param: bool,
    pub span: Span,
}

/// The variables of one algorithm, in register order.
#[derive(Clone, Debug, Default)]
pub struct Scope {
    pub variables: Vec<Variable>,
    /// Register of each name, so that looking a name up does not grow with
    /// the number of variables (a pasted file may declare thousands).
    by_name: HashMap<String, usize>,
}

impl Scope {
    pub fn find(&self, name: &str) -> Option<(usize, &Variable)> {
        let index = *self.by_name.get(name)?;
        Some((index, self.variables.get(index)?))
    }

    fn push(&mut self, variable: Variable) {
        self.by_name
            .insert(variable.name.clone(), self.variables.len());
        self.variables.push(variable);
    }
}

/// What a call needs to know of an algorithm of the file.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Signature {
    pub name: String,
    /// Each parameter's name and type (`None`: not understood, reported).
    pub params: Vec<(String, Option<Type>)>,
    pub structure: Option<Structure>,
    /// `None` when it returns nothing; `Some(None)` when its result type was
    /// not understood (reported).
    pub returns: Option<Option<Type>>,
}

impl Signature {
    /// `isTriangle(f : Face) : HalfEdge returns Boolean`, for messages.
    pub fn text(&self) -> String {
        let params: Vec<String> = self
            .params
            .iter()
            .map(|(name, ty)| format!("{name} : {}", ty.map_or("?", Type::name)))
            .collect();
        let mut text = format!("{}({})", self.name, params.join("; "));
        if let Some(structure) = self.structure {
            text.push_str(&format!(" : {structure}"));
        }
        if let Some(result) = self.returns {
            text.push_str(&format!(" returns {}", result.map_or("?", Type::name)));
        }
        text
    }
}

/// Every algorithm of a file, as calls see them, found by name.
#[derive(Clone, Debug, Default)]
pub struct Signatures {
    pub list: Vec<Signature>,
    by_name: HashMap<String, usize>,
}

impl Signatures {
    pub fn of(file: &SourceFile) -> Self {
        let mut signatures = Signatures::default();
        for decl in &file.algorithms {
            let index = signatures.list.len();
            signatures
                .by_name
                .entry(decl.name.name.clone())
                .or_insert(index);
            signatures.list.push(Signature {
                name: decl.name.name.clone(),
                params: decl
                    .params
                    .iter()
                    .map(|p| (p.name.name.clone(), p.ty))
                    .collect(),
                structure: decl.structure.map(|(s, _)| s),
                returns: decl.returns.map(|(ty, _)| ty),
            });
        }
        signatures
    }

    /// The algorithm a call names: the first of that name, else the only
    /// one whose name differs in case alone (names of algorithms, like
    /// keywords, ignore case where that is not ambiguous).
    pub fn find(&self, name: &str) -> Option<(usize, &Signature)> {
        let index = match self.by_name.get(name) {
            Some(&index) => index,
            None => {
                let mut matches =
                    (0..self.list.len()).filter(|&i| self.list[i].name.eq_ignore_ascii_case(name));
                let first = matches.next()?;
                if matches.any(|i| self.list[i].name != self.list[first].name) {
                    return None;
                }
                first
            }
        };
        Some((index, self.list.get(index)?))
    }
}

/// "an Edge", "a Vertex": for messages.
pub fn with_article(ty: Type) -> String {
    match ty {
        Type::Edge | Type::Integer | Type::Array(_) => format!("an {ty}"),
        Type::Vector => "a Vector".to_owned(),
        Type::Null => "null".to_owned(),
        _ => format!("a {ty}"),
    }
}

/// Checks a whole file: every algorithm, and that no two share a name.
/// Returns each algorithm's scope, in file order.
pub fn check_file(
    file: &SourceFile,
    source: &str,
    diagnostics: &mut Vec<Diagnostic>,
) -> Vec<Scope> {
    let mut scopes = Vec::with_capacity(file.algorithms.len());
    let mut names = HashSet::new();
    let signatures = Signatures::of(file);
    for algorithm in &file.algorithms {
        let name = algorithm.name.name.as_str();
        if !name.is_empty() && !names.insert(name) {
            diagnostics.push(Diagnostic::error(
                algorithm.name.span,
                format!("an algorithm named `{name}` is already defined in this file"),
            ));
        } else if let Some(builtin) = Builtin::parse(name) {
            diagnostics.push(
                Diagnostic::error(
                    algorithm.name.span,
                    format!("`{name}` is a built-in function; an algorithm cannot have its name"),
                )
                .with_hint(format!(
                    "a call `{}(…)` would mean the built-in",
                    builtin.name()
                )),
            );
        }
        scopes.push(check_algorithm(algorithm, &signatures, source, diagnostics));
    }
    scopes
}

pub fn check_algorithm(
    decl: &AlgorithmDecl,
    signatures: &Signatures,
    source: &str,
    diagnostics: &mut Vec<Diagnostic>,
) -> Scope {
    let mut scope = Scope::default();
    let declared = decl
        .params
        .iter()
        .map(|p| (p, true))
        .chain(decl.vars.iter().map(|v| (v, false)));
    for (var, is_param) in declared {
        if var.name.name.is_empty() {
            continue;
        }
        if let Some((_, first)) = scope.find(&var.name.name) {
            let what = if first.is_param {
                "a parameter"
            } else {
                "a variable"
            };
            diagnostics.push(Diagnostic::error(
                var.name.span,
                format!(
                    "`{}` is already declared as {what} of this algorithm",
                    var.name.name
                ),
            ));
            continue;
        }
        scope.push(Variable {
            name: var.name.name.clone(),
            ty: var.ty,
            is_param,
            span: var.name.span,
        });
    }
    let mut checker = Checker {
        scope: &scope,
        signatures,
        structure: decl.structure.map(|(s, _)| s),
        algorithm: &decl.name.name,
        returns: decl.returns.map(|(ty, _)| ty),
        source,
        diagnostics,
        loop_depth: 0,
    };
    checker.statements(&decl.body);
    if let Some(Some(result)) = checker.returns
        && !leaves(&decl.body)
    {
        checker.error_with_hint(
            decl.end_span,
            format!(
                "`{}` returns {}, but can reach its `end` without `return`",
                decl.name.name,
                with_article(result)
            ),
            "end every way through it with `return` and a value".to_owned(),
        );
    }
    scope
}

/// Whether control never runs off the end of `statements`: every way
/// through them returns, refuses, or loops for ever. Conservative, like
/// Java's rule: a `while` may run no times, and a `break` leaves its loop.
/// Recurses as deep as the statements nest, which the parser bounds.
pub fn leaves(statements: &[Stmt]) -> bool {
    statements.iter().any(|statement| match &statement.kind {
        StmtKind::Return { .. } | StmtKind::Refuse { .. } => true,
        StmtKind::Block(body) => leaves(body),
        StmtKind::If {
            arms,
            otherwise: Some(otherwise),
        } => arms.iter().all(|(_, body)| leaves(body)) && leaves(otherwise),
        StmtKind::Loop { body }
        | StmtKind::While {
            cond:
                Expr {
                    kind: ExprKind::Boolean(true),
                    ..
                },
            body,
        } => !breaks(body),
        StmtKind::DoWhile { body, .. } => leaves(body) && !breaks(body) && !continues(body),
        _ => false,
    })
}

/// Whether a `break` in `statements` leaves the loop they are the body of.
fn breaks(statements: &[Stmt]) -> bool {
    jumps(statements, &|kind| matches!(kind, StmtKind::Break))
}

fn continues(statements: &[Stmt]) -> bool {
    jumps(statements, &|kind| matches!(kind, StmtKind::Continue))
}

/// Whether `statements` hold a jump that `is_jump` picks, outside any inner
/// loop (whose own jumps stay inside it).
fn jumps(statements: &[Stmt], is_jump: &dyn Fn(&StmtKind) -> bool) -> bool {
    statements.iter().any(|statement| match &statement.kind {
        kind if is_jump(kind) => true,
        StmtKind::Block(body) => jumps(body, is_jump),
        StmtKind::If { arms, otherwise } => {
            arms.iter().any(|(_, body)| jumps(body, is_jump))
                || otherwise.as_ref().is_some_and(|body| jumps(body, is_jump))
        }
        _ => false,
    })
}

/// How a call is used: its value in an expression, or on its own.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Use {
    Value,
    Statement,
}

struct Checker<'a> {
    scope: &'a Scope,
    signatures: &'a Signatures,
    structure: Option<Structure>,
    algorithm: &'a str,
    /// The declared result: `None` for none, `Some(None)` if not understood.
    returns: Option<Option<Type>>,
    source: &'a str,
    diagnostics: &'a mut Vec<Diagnostic>,
    loop_depth: u32,
}

impl Checker<'_> {
    /// After [`MAX_ERRORS`] errors one more says so and the rest are
    /// dropped (their hints not searched for), so a hostile file can make
    /// checking neither slow nor its report long.
    fn full(&self) -> bool {
        self.diagnostics.len() >= MAX_ERRORS
    }

    fn report(&mut self, diagnostic: Diagnostic) {
        match self.diagnostics.len() {
            n if n < MAX_ERRORS => self.diagnostics.push(diagnostic),
            MAX_ERRORS => self.diagnostics.push(Diagnostic::error(
                diagnostic.span,
                format!("more than {MAX_ERRORS} errors; the rest of the file was not checked"),
            )),
            _ => {}
        }
    }

    fn error(&mut self, span: Span, message: String) {
        self.report(Diagnostic::error(span, message));
    }

    fn error_with_hint(&mut self, span: Span, message: String, hint: String) {
        self.report(Diagnostic::error(span, message).with_hint(hint));
    }

    fn text(&self, span: Span) -> String {
        span.text(self.source)
            .split_whitespace()
            .collect::<Vec<_>>()
            .join(" ")
    }

    fn statements(&mut self, statements: &[Stmt]) {
        for statement in statements {
            self.statement(statement);
        }
    }

    fn in_loop(&mut self, body: &[Stmt]) {
        self.loop_depth += 1;
        self.statements(body);
        self.loop_depth -= 1;
    }

    fn statement(&mut self, statement: &Stmt) {
        match &statement.kind {
            StmtKind::Assign { target, value } => self.assignment(target, value),
            StmtKind::Write { base, field, value } => self.write(base, field, value),
            StmtKind::Store {
                array,
                index,
                value,
            } => self.store(array, index, value),
            StmtKind::Call { name, args } => {
                self.call(name, args, Use::Statement);
            }
            StmtKind::Return { value } => self.return_statement(statement.span, value.as_ref()),
            StmtKind::Delete { target } => match self.expr(target) {
                None | Some(Type::Vertex | Type::Edge | Type::Face) => {}
                Some(ty) => {
                    let text = self.text(target.span);
                    self.error(
                        target.span,
                        format!(
                            "only vertices, edges and faces can be deleted; `{text}` is {}",
                            describe_value(ty)
                        ),
                    );
                }
            },
            StmtKind::If { arms, otherwise } => {
                for (cond, body) in arms {
                    self.condition(cond);
                    self.statements(body);
                }
                if let Some(body) = otherwise {
                    self.statements(body);
                }
            }
            StmtKind::While { cond, body } => {
                self.condition(cond);
                self.in_loop(body);
            }
            StmtKind::DoWhile { body, cond } => {
                self.in_loop(body);
                self.condition(cond);
            }
            StmtKind::Loop { body } => self.in_loop(body),
            StmtKind::Block(body) => self.statements(body),
            StmtKind::Break | StmtKind::Continue => {
                if self.loop_depth == 0 {
                    let word = if matches!(statement.kind, StmtKind::Break) {
                        "break"
                    } else {
                        "continue"
                    };
                    self.error(
                        statement.span,
                        format!("`{word}` can only be used inside a loop"),
                    );
                }
            }
            StmtKind::Action { action, target } => self.action(*action, target),
            StmtKind::Message { parts } | StmtKind::Refuse { parts } => {
                for part in parts {
                    if let MessagePart::Value(value) = part {
                        self.expr(value);
                    }
                }
            }
            StmtKind::Error => {}
        }
    }

    fn assignment(&mut self, target: &Ident, value: &Expr) {
        let value_type = self.expr(value);
        let Some(target_type) = self.variable(&target.name, target.span) else {
            return;
        };
        let Some(value_type) = value_type else { return };
        if !target_type.accepts(value_type) {
            self.error(
                value.span,
                format!(
                    "cannot assign {} to `{}`, which is {}",
                    describe_value(value_type),
                    target.name,
                    with_article(target_type)
                ),
            );
        }
    }

    /// `base.field := value`: the field must be stored (not derived) in
    /// this structure, and the value must fit the column.
    fn write(&mut self, base: &Expr, field: &Ident, value: &Expr) {
        let value_type = self.expr(value);
        let column = self.column(base, field);
        let (Some((column, kind)), Some(value_type)) = (column, value_type) else {
            return;
        };
        let Some(structure) = self.structure else {
            return;
        };
        let target = self.text(base.span);
        if column.storage(structure) == Some(Storage::Derived) {
            self.error_with_hint(
                field.span,
                format!(
                    "`{}` is worked out from other columns in a {structure} structure, so it cannot be written",
                    field.name
                ),
                derived_hint(column).to_owned(),
            );
            return;
        }
        let wanted = column.target().map_or(Type::Vector, Type::of_kind);
        if value_type == Type::Null && !column.nullable_in(kind) {
            self.error(value.span, {
                let key = column.key();
                let article = crate::schema::article(&key);
                format!(
                    "`{target}.{}` cannot be null: every {} has {article} {key}",
                    field.name,
                    kind.prose(),
                )
            });
        } else if !wanted.accepts(value_type) {
            self.error(
                value.span,
                format!(
                    "`{target}.{}` holds {}, not {}",
                    field.name,
                    with_article(wanted),
                    describe_value(value_type)
                ),
            );
        }
    }

    /// `a[i] := value`: the value must fit the array's items.
    fn store(&mut self, array: &Expr, index: &Expr, value: &Expr) {
        let value_type = self.expr(value);
        let (Some(item), Some(value_type)) = (self.index(array, index), value_type) else {
            return;
        };
        if !item.accepts(value_type) {
            let text = self.text(array.span);
            self.error(
                value.span,
                format!(
                    "the items of `{text}` are {}, not {}",
                    plural(item),
                    describe_value(value_type)
                ),
            );
        }
    }

    /// `a[i]`: the type of the item, reporting an index that is not an
    /// Integer or a base that is not an array.
    fn index(&mut self, array: &Expr, index: &Expr) -> Option<Type> {
        let array_type = self.expr(array);
        let index_type = self.expr(index);
        if let Some(ty) = index_type
            && ty != Type::Integer
        {
            let text = self.text(index.span);
            let message = format!(
                "an array index is an Integer, but `{text}` is {}",
                describe_value(ty)
            );
            if ty == Type::Float {
                self.error_with_hint(
                    index.span,
                    message,
                    "Integers divide into an Integer with `div`".to_owned(),
                );
            } else {
                self.error(index.span, message);
            }
        }
        let array_type = array_type?;
        let Some(item) = array_type.item() else {
            let text = self.text(array.span);
            self.error_with_hint(
                array.span,
                format!(
                    "`{text}` is {}; only arrays have items to index",
                    describe_value(array_type)
                ),
                "declare an array with `var a : Array of Edge;`".to_owned(),
            );
            return None;
        };
        index_type?;
        Some(item)
    }

    fn return_statement(&mut self, span: Span, value: Option<&Expr>) {
        let value_type = value.and_then(|v| self.expr(v));
        match (self.returns, value) {
            (None, None) | (Some(None), _) => {}
            (None, Some(value)) => self.error_with_hint(
                value.span,
                format!("`{}` returns no value", self.algorithm),
                format!(
                    "write `return` alone, or declare its result after the parameters: \
                     `returns {}`",
                    value_type.map_or("Integer", Type::name)
                ),
            ),
            (Some(Some(result)), None) => self.error_with_hint(
                span,
                format!(
                    "`{}` returns {}, but this `return` gives no value",
                    self.algorithm,
                    with_article(result)
                ),
                format!("write `return` and {}", with_article(result)),
            ),
            (Some(Some(result)), Some(value)) => {
                if let Some(ty) = value_type
                    && !result.accepts(ty)
                {
                    self.error(
                        value.span,
                        format!(
                            "`{}` returns {}, not {}",
                            self.algorithm,
                            with_article(result),
                            describe_value(ty)
                        ),
                    );
                }
            }
        }
    }

    fn condition(&mut self, cond: &Expr) {
        match self.expr(cond) {
            Some(Type::Boolean) | None => {}
            Some(ty) => {
                let text = self.text(cond.span);
                let message = format!(
                    "a condition must be Boolean, but `{text}` is {}",
                    with_article(ty)
                );
                if ty.element_kind().is_some() {
                    self.error_with_hint(
                        cond.span,
                        message,
                        format!("to test for a missing element, write `{text} <> null`"),
                    );
                } else {
                    self.error(cond.span, message);
                }
            }
        }
    }

    fn action(&mut self, action: Action, target: &Expr) {
        let word = match action {
            Action::Mark => "mark",
            Action::Highlight => "highlight",
        };
        match self.expr(target) {
            None | Some(Type::Vertex | Type::Edge | Type::Face) => {}
            Some(Type::Null) => self.error(target.span, format!("cannot {word} null")),
            Some(ty) => {
                let text = self.text(target.span);
                self.error_with_hint(
                    target.span,
                    format!(
                        "only vertices, edges and faces can be {word}ed; `{text}` is {}",
                        with_article(ty)
                    ),
                    format!("to show a value, write `message \"…\", {text}`"),
                );
            }
        }
    }

    /// The type of a variable, reporting an unknown name.
    fn variable(&mut self, name: &str, span: Span) -> Option<Type> {
        if let Some((_, variable)) = self.scope.find(name) {
            return variable.ty;
        }
        let message = format!("unknown variable `{name}`");
        if self.full() {
            self.error(span, message);
            return None;
        }
        let names = self.scope.variables.iter().map(|v| v.name.as_str());
        if let Some(near) = nearest(name, names) {
            self.error_with_hint(span, message, format!("did you mean `{near}`?"));
        } else if Column::all_language_names().any(|f| f.eq_ignore_ascii_case(name)) {
            self.error_with_hint(
                span,
                message,
                format!("`{name}` is a lookup: write it after an element, as in `e.{name}`"),
            );
        } else {
            self.error_with_hint(
                span,
                message,
                "declare it with `var` before `begin`".to_owned(),
            );
        }
        None
    }

    fn expr(&mut self, expr: &Expr) -> Option<Type> {
        match &expr.kind {
            ExprKind::Name(name) => self.variable(name, expr.span),
            ExprKind::Integer(_) => Some(Type::Integer),
            ExprKind::Float(_) => Some(Type::Float),
            ExprKind::New(kind) => Some(Type::of_kind(*kind)),
            ExprKind::Call { name, args } => self.call(name, args, Use::Value),
            ExprKind::Index { array, index } => self.index(array, index),
            ExprKind::Boolean(_) => Some(Type::Boolean),
            ExprKind::Null => Some(Type::Null),
            ExprKind::Error => None,
            ExprKind::Lookup { base, field } => self.lookup(base, field),
            ExprKind::Unary { op, operand } => {
                let ty = self.expr(operand)?;
                let fits = match op {
                    UnaryOp::Neg => ty.is_number() || ty == Type::Vector,
                    UnaryOp::Not => ty == Type::Boolean,
                };
                if !fits {
                    let (wanted, word) = match op {
                        UnaryOp::Neg => ("a number or a Vector", "-"),
                        UnaryOp::Not => ("a Boolean", "not"),
                    };
                    let text = self.text(operand.span);
                    self.error(
                        operand.span,
                        format!(
                            "`{word}` needs {wanted}, but `{text}` is {}",
                            with_article(ty)
                        ),
                    );
                    return None;
                }
                Some(ty)
            }
            ExprKind::Binary { op, left, right } => {
                let left_type = self.expr(left);
                let right_type = self.expr(right);
                self.binary(*op, expr.span, (left, left_type?), (right, right_type?))
            }
        }
    }

    fn binary(
        &mut self,
        op: BinaryOp,
        span: Span,
        left: (&Expr, Type),
        right: (&Expr, Type),
    ) -> Option<Type> {
        let symbol = op.symbol();
        let operand = match op {
            BinaryOp::Eq | BinaryOp::NotEq => {
                let (l, r) = (left.1, right.1);
                if l.item().is_some() || r.item().is_some() {
                    self.error_with_hint(
                        span,
                        "arrays cannot be compared".to_owned(),
                        "compare their lengths or their items".to_owned(),
                    );
                    return None;
                }
                let comparable = l == r
                    || (l.is_number() && r.is_number())
                    || (l == Type::Null && (r.element_kind().is_some() || r == Type::Null))
                    || (r == Type::Null && l.element_kind().is_some());
                if !comparable {
                    let hint = match (l.element_kind(), r.element_kind()) {
                        (Some(_), Some(_)) => {
                            "elements of different kinds are never equal; look up the matching kind first"
                        }
                        _ => "both sides must have the same type",
                    };
                    self.error_with_hint(
                        span,
                        format!(
                            "cannot compare {} with {}",
                            with_article(l),
                            with_article(r)
                        ),
                        hint.to_owned(),
                    );
                    return None;
                }
                return Some(Type::Boolean);
            }
            BinaryOp::Add | BinaryOp::Sub | BinaryOp::Mul | BinaryOp::Divide => {
                if let Some(ty) = arithmetic(op, left.1, right.1) {
                    return Some(ty);
                }
                let (l, r) = (left.1, right.1);
                let (side, ty) = if l.is_number() || (l == Type::Vector && op != BinaryOp::Divide) {
                    (right.0, r)
                } else {
                    (left.0, l)
                };
                let text = self.text(side.span);
                let mut message = format!(
                    "`{symbol}` needs numbers or Vectors, but `{text}` is {}",
                    with_article(ty)
                );
                if l == Type::Vector
                    && r == Type::Vector
                    && matches!(op, BinaryOp::Mul | BinaryOp::Divide)
                {
                    message = format!(
                        "`{symbol}` cannot combine two Vectors; scale a Vector by a number"
                    );
                }
                self.error(side.span, message);
                return None;
            }
            BinaryOp::Lt | BinaryOp::Le | BinaryOp::Gt | BinaryOp::Ge => {
                for (side, ty) in [left, right] {
                    if !ty.is_number() {
                        let text = self.text(side.span);
                        let mut message = format!(
                            "`{symbol}` needs numbers, but `{text}` is {}",
                            with_article(ty)
                        );
                        if ty.element_kind().is_some() {
                            message.push_str("; elements can only be compared with `=` and `<>`");
                        }
                        self.error(side.span, message);
                        return None;
                    }
                }
                return Some(Type::Boolean);
            }
            BinaryOp::Div | BinaryOp::Mod => Type::Integer,
            BinaryOp::And | BinaryOp::Or => Type::Boolean,
        };
        for (side, ty) in [left, right] {
            if ty != operand {
                let text = self.text(side.span);
                let mut message = format!(
                    "`{symbol}` needs {} operands, but `{text}` is {}",
                    operand,
                    with_article(ty)
                );
                if ty == Type::Float && operand == Type::Integer {
                    message.push_str("; Floats divide with `/`");
                }
                self.error(side.span, message);
                return None;
            }
        }
        Some(operand)
    }

    /// A call: of a built-in function, or of another algorithm of the file.
    fn call(&mut self, name: &Ident, args: &[Expr], used: Use) -> Option<Type> {
        let types: Vec<Option<Type>> = args.iter().map(|arg| self.expr(arg)).collect();
        if let Some(builtin) = Builtin::parse(&name.name) {
            let result = self.builtin(builtin, name, args, &types)?;
            return self.used(name, args, used, builtin.result(), result);
        }
        let Some((_, callee)) = self.signatures.find(&name.name) else {
            self.unknown_function(name);
            return None;
        };
        if let (Some(ours), Some(theirs)) = (self.structure, callee.structure)
            && ours != theirs
        {
            self.error_with_hint(
                name.span,
                format!(
                    "`{}` walks a {theirs} structure, but `{}` walks a {ours} structure",
                    callee.name, self.algorithm
                ),
                "an algorithm can call only algorithms of its own structure".to_owned(),
            );
            return None;
        }
        if args.len() != callee.params.len() {
            self.error(
                name.span,
                format!(
                    "`{}` takes {} ({}), but was given {}",
                    callee.name,
                    count(callee.params.len(), "argument"),
                    callee.text(),
                    args.len()
                ),
            );
            return None;
        }
        let mut fits = true;
        for ((arg, ty), (param, want)) in args.iter().zip(&types).zip(&callee.params) {
            let (Some(ty), Some(want)) = (*ty, *want) else {
                fits = false;
                continue;
            };
            if !want.accepts(ty) {
                let text = self.text(arg.span);
                self.error(
                    arg.span,
                    format!(
                        "`{}` needs {} for `{param}`, but `{text}` is {}",
                        callee.name,
                        with_article(want),
                        describe_value(ty)
                    ),
                );
                fits = false;
            }
        }
        if !fits {
            return None;
        }
        match (used, callee.returns) {
            (Use::Value, None) => {
                self.error_with_hint(
                    name.span,
                    format!(
                        "`{}` returns no value, so it cannot be used in an expression",
                        callee.name
                    ),
                    format!(
                        "call it on its own: `{}(…);`, or declare its result after its \
                         parameters with `returns`",
                        callee.name
                    ),
                );
                None
            }
            (_, returns) => returns.flatten(),
        }
    }

    /// Checks how a built-in's value is used: `append` has none to use, and
    /// the others have nothing to do but give one.
    fn used(
        &mut self,
        name: &Ident,
        args: &[Expr],
        used: Use,
        declared: Option<Type>,
        result: Type,
    ) -> Option<Type> {
        let text = match (args.first(), args.last()) {
            (Some(first), Some(last)) => format!(
                "{}({})",
                name.name,
                self.text(Span {
                    start: first.span.start,
                    end: last.span.end,
                })
            ),
            _ => format!("{}()", name.name),
        };
        match (used, declared) {
            (Use::Value, None) => {
                self.error_with_hint(
                    name.span,
                    format!("`{}` changes an array and gives no value", name.name),
                    format!("write it as a statement of its own: `{text};`"),
                );
                None
            }
            (Use::Statement, Some(_)) => {
                self.error_with_hint(
                    name.span,
                    format!("the value of `{text}` is not used"),
                    format!("store it in a variable: `x := {text};`"),
                );
                None
            }
            _ => Some(result),
        }
    }

    fn unknown_function(&mut self, name: &Ident) {
        let message = format!("unknown function `{}`", name.name);
        if self.full() {
            self.error(name.span, message);
            return;
        }
        let candidates = Builtin::NAMES
            .into_iter()
            .chain(self.signatures.list.iter().map(|s| s.name.as_str()));
        let hint = match nearest(&name.name, candidates) {
            Some(near) => format!("did you mean `{near}`?"),
            None => format!(
                "the built-in functions are {}; other algorithms of this file are called by \
                 their names",
                Builtin::NAMES.join(", ")
            ),
        };
        self.error_with_hint(name.span, message, hint);
    }

    /// `vector(x, y, z)`, `float(n)`, `sqrt(x)`, `length(a)`, `append(a, x)`,
    /// `id(x)`;
    /// the type of the value (Null for `append`).
    fn builtin(
        &mut self,
        builtin: Builtin,
        name: &Ident,
        args: &[Expr],
        types: &[Option<Type>],
    ) -> Option<Type> {
        let arity = builtin.arity();
        if args.len() != arity {
            self.error(
                name.span,
                format!(
                    "`{}` takes {} ({}), but was given {}",
                    builtin.name(),
                    count(arity, "argument"),
                    builtin.signature(),
                    args.len()
                ),
            );
            return None;
        }
        if builtin.on_arrays() {
            return self.array_builtin(builtin, args, types);
        }
        if builtin == Builtin::Id {
            let (arg, ty) = (args.first()?, (*types.first()?)?);
            if ty.element_kind().is_none() {
                let text = self.text(arg.span);
                self.error(
                    arg.span,
                    format!(
                        "`id` needs a vertex, an edge or a face, but `{text}` is {}",
                        describe_value(ty)
                    ),
                );
                return None;
            }
            return builtin.result();
        }
        for ((arg, ty), want) in args.iter().zip(types).zip(builtin.parameters()) {
            let ty = (*ty)?;
            if !want.accepts(ty) {
                let text = self.text(arg.span);
                self.error(
                    arg.span,
                    format!(
                        "`{}` needs {} here, but `{text}` is {}",
                        builtin.name(),
                        with_article(*want),
                        describe_value(ty)
                    ),
                );
                return None;
            }
        }
        builtin.result()
    }

    /// `length(a)` and `append(a, x)`: `a` must be an array, and `x` fit
    /// its items.
    fn array_builtin(
        &mut self,
        builtin: Builtin,
        args: &[Expr],
        types: &[Option<Type>],
    ) -> Option<Type> {
        let (array, ty) = (args.first()?, (*types.first()?)?);
        let Some(item) = ty.item() else {
            let text = self.text(array.span);
            self.error(
                array.span,
                format!(
                    "`{}` needs an array, but `{text}` is {}",
                    builtin.name(),
                    describe_value(ty)
                ),
            );
            return None;
        };
        if builtin == Builtin::Append
            && let (Some(value), Some(Some(value_type))) = (args.get(1), types.get(1))
            && !item.accepts(*value_type)
        {
            let text = self.text(array.span);
            self.error(
                value.span,
                format!(
                    "the items of `{text}` are {}, not {}",
                    plural(item),
                    describe_value(*value_type)
                ),
            );
            return None;
        }
        Some(builtin.result().unwrap_or(Type::Null))
    }

    /// The column `base.field` names, with the kind of element it is on,
    /// reporting what is wrong with it.
    fn column(&mut self, base: &Expr, field: &Ident) -> Option<(Column, ElementKind)> {
        let base_type = self.expr(base)?;
        self.resolve(base, base_type, field, "fields to write")
    }

    /// The column `field` names on `base`, of type `base_type`; `what` says
    /// what only elements have (`lookups`, `fields to write`) when `base`
    /// is not one.
    fn resolve(
        &mut self,
        base: &Expr,
        base_type: Type,
        field: &Ident,
        what: &str,
    ) -> Option<(Column, ElementKind)> {
        let Some(kind) = base_type.element_kind() else {
            let text = self.text(base.span);
            self.error(
                field.span,
                format!(
                    "`{text}` is {}; only vertices, edges and faces have {what}",
                    with_article(base_type)
                ),
            );
            return None;
        };
        let structure = self.structure?;
        match Column::resolve(structure, kind, &field.name) {
            Ok(column) => Some((column, kind)),
            Err(error) => {
                self.lookup_error(structure, kind, field, &error);
                None
            }
        }
    }

    fn lookup(&mut self, base: &Expr, field: &Ident) -> Option<Type> {
        let base_type = self.expr(base)?;
        let name = field.name.as_str();
        if name.eq_ignore_ascii_case("mark") || name.eq_ignore_ascii_case("highlight") {
            self.error(
                field.span,
                format!("`.{name}` is a statement of its own, not a value"),
            );
            return None;
        }
        if base_type == Type::Vector {
            if Axis::parse(name).is_some() {
                return Some(Type::Float);
            }
            self.error_with_hint(
                field.span,
                format!("a Vector has no `{name}`"),
                "its coordinates are `.x`, `.y` and `.z`".to_owned(),
            );
            return None;
        }
        let (column, _) = self.resolve(base, base_type, field, "lookups")?;
        Some(column.target().map_or(Type::Vector, Type::of_kind))
    }

    fn lookup_error(
        &mut self,
        structure: Structure,
        kind: ElementKind,
        field: &Ident,
        error: &NameError,
    ) {
        let name = field.name.as_str();
        let kind_name = Type::of_kind(kind);
        let available: Vec<&str> = Column::language_names_for(structure, kind).collect();
        let listing = format!(
            "{kind_name} lookups in a {structure} structure: {}",
            Column::canonical_names_for(structure, kind).join(", ")
        );
        match error {
            NameError::Unknown => {
                let hint = nearest(name, available.iter().copied())
                    .map_or(listing, |near| format!("did you mean `{near}`?"));
                self.error_with_hint(
                    field.span,
                    format!("unknown lookup `{name}` on {kind_name}"),
                    hint,
                );
            }
            NameError::OtherStructure(other) => {
                self.error_with_hint(
                    field.span,
                    format!(
                        "`{name}` is a {} lookup, but `{}` walks a {structure} structure",
                        other.prose(),
                        self.algorithm
                    ),
                    listing,
                );
            }
            NameError::WrongElement(owner) => {
                self.error_with_hint(
                    field.span,
                    format!(
                        "{kind_name} has no lookup `{name}`; it is a lookup on {}",
                        Type::of_kind(*owner)
                    ),
                    listing,
                );
            }
        }
    }
}

/// Where a derived column's value is written instead.
fn derived_hint(column: Column) -> &'static str {
    match column {
        Column::StartVertex => {
            "a half-edge's start vertex is its pair's end vertex: write `h.pair.vertex`"
        }
        Column::PredecessorEdge => {
            "a half-edge's predecessor is the half-edge whose successor it is: write that one's `successor`"
        }
        _ => "write the columns it is worked out from",
    }
}

/// The type of `left op right` for `+ - * /`, if the operands fit.
fn arithmetic(op: BinaryOp, left: Type, right: Type) -> Option<Type> {
    use Type::{Float, Integer, Vector};
    match (op, left, right) {
        (BinaryOp::Divide, l, r) if l.is_number() && r.is_number() => Some(Float),
        (_, Integer, Integer) => Some(Integer),
        (_, l, r) if l.is_number() && r.is_number() => Some(Float),
        (BinaryOp::Add | BinaryOp::Sub, Vector, Vector) => Some(Vector),
        (BinaryOp::Mul, Vector, n) | (BinaryOp::Mul, n, Vector) if n.is_number() => Some(Vector),
        (BinaryOp::Divide, Vector, n) if n.is_number() => Some(Vector),
        _ => None,
    }
}

/// "2 arguments", "1 argument".
fn count(n: usize, what: &str) -> String {
    if n == 1 {
        format!("1 {what}")
    } else {
        format!("{n} {what}s")
    }
}

/// "Edges", "Integers": what an array of `ty` holds, for messages.
fn plural(ty: Type) -> String {
    match ty {
        Type::Vertex => "Vertices".to_owned(),
        other => format!("{other}s"),
    }
}

fn describe_value(ty: Type) -> String {
    match ty {
        Type::Null => "null".to_owned(),
        _ => with_article(ty),
    }
}

#[cfg(test)]
mod tests {
    use super::super::parser::parse;
    use super::*;

    fn errors(source: &str) -> Vec<String> {
        let (file, mut diagnostics) = parse(source);
        assert!(diagnostics.is_empty(), "{diagnostics:#?}");
        check_file(&file, source, &mut diagnostics);
        diagnostics
            .iter()
            .map(|d| {
                format!(
                    "{}{}",
                    d.message,
                    d.hint
                        .as_ref()
                        .map(|h| format!(" ({h})"))
                        .unwrap_or_default()
                )
            })
            .collect()
    }

    #[test]
    fn lookups_name_the_structure_that_has_them() {
        let found = errors(
            "algorithm a(e : Edge) : HalfEdge begin mark e.leftFace; mark e.startVertx; mark e.incidentEdge end",
        );
        assert_eq!(found.len(), 3, "{found:?}");
        assert!(
            found[0].starts_with(
                "`leftFace` is a winged-edge lookup, but `a` walks a HalfEdge structure"
            )
        );
        assert_eq!(
            found[1],
            "unknown lookup `startVertx` on Edge (did you mean `startVertex`?)"
        );
        assert!(
            found[2].starts_with("Edge has no lookup `incidentEdge`; it is a lookup on Vertex")
        );
    }

    #[test]
    fn calls_ignore_case_unless_that_is_ambiguous() {
        let one = "algorithm isTriangle(f : Face) : HalfEdge returns Boolean begin return true end \
                   algorithm a(f : Face) : HalfEdge begin if ISTRIANGLE(f) then mark f end end";
        assert_eq!(errors(one), Vec::<String>::new());
        let two = "algorithm isTriangle(f : Face) : HalfEdge returns Boolean begin return true end \
                   algorithm IsTriangle(f : Face) : HalfEdge returns Boolean begin return false end \
                   algorithm a(f : Face) : HalfEdge begin if ISTRIANGLE(f) then mark f end end";
        assert_eq!(
            errors(two),
            ["unknown function `ISTRIANGLE` (did you mean `isTriangle`?)"]
        );
    }

    #[test]
    fn only_a_way_that_can_run_off_the_end_misses_a_return() {
        let body = |statements: &str| {
            errors(&format!(
                "algorithm a(n : Integer) : HalfEdge returns Integer begin {statements} end"
            ))
        };
        for leaves in [
            "return 1",
            "if n > 0 then return 1 else return 2 end",
            "if n > 0 then return 1 else if n < 0 then return 2 else refuse \"zero\" end",
            "do n := n + 1; if n > 9 then return n end end",
            "while true do n := n + 1 end",
            "do return n while n > 0",
            "begin return n end",
        ] {
            assert_eq!(body(leaves), Vec::<String>::new(), "{leaves}");
        }
        for falls in [
            "n := 1",
            "if n > 0 then return 1 end",
            "while n > 0 do return n end",
            "do if n > 9 then break end; n := n + 1 end",
            "do if n > 0 then continue end; return n while n > 0",
        ] {
            assert_eq!(
                body(falls),
                [
                    "`a` returns an Integer, but can reach its `end` without `return` (end every way through it with `return` and a value)"
                ],
                "{falls}"
            );
        }
    }

    #[test]
    fn types_are_checked() {
        let found = errors(
            "algorithm a(v : Vertex) : WingedEdge var n : Integer; f : Face; begin n := v; f := null; if v.incidentEdge then break end; mark n; n := n + true end",
        );
        assert_eq!(
            found,
            [
                "cannot assign a Vertex to `n`, which is an Integer",
                "a condition must be Boolean, but `v.incidentEdge` is an Edge (to test for a missing element, write `v.incidentEdge <> null`)",
                "`break` can only be used inside a loop",
                "only vertices, edges and faces can be marked; `n` is an Integer (to show a value, write `message \"…\", n`)",
                "`+` needs numbers or Vectors, but `true` is a Boolean",
            ]
        );
    }
}
