//! The syntax tree, as parsed, before names and types are checked.

use super::diagnostic::Span;
use super::types::Type;
use crate::schema::{ElementKind, Structure};

#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Ident {
    pub name: String,
    pub span: Span,
}

/// A file holds any number of algorithms.
#[derive(Clone, Debug, Default)]
pub struct SourceFile {
    pub algorithms: Vec<AlgorithmDecl>,
}

#[derive(Clone, Debug)]
pub struct AlgorithmDecl {
    pub name: Ident,
    pub params: Vec<VarDecl>,
    /// `None` when neither `: HalfEdge` nor `structuretype …` was given (an error).
    pub structure: Option<(Structure, Span)>,
    /// `returns Boolean`: the type of the value it gives back to a caller,
    /// with its span (`None` in it when the type was not understood).
    pub returns: Option<(Option<Type>, Span)>,
    pub description: Option<String>,
    pub vars: Vec<VarDecl>,
    pub body: Vec<Stmt>,
    /// The `algorithm` keyword through the closing `end`.
    pub span: Span,
    /// The closing `end`, where the trace's last step (done) points.
    pub end_span: Span,
}

#[derive(Clone, Debug)]
pub struct VarDecl {
    pub name: Ident,
    /// `None` when the type name was not understood (already reported).
    pub ty: Option<Type>,
    pub ty_span: Span,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Action {
    Mark,
    Highlight,
}

#[derive(Clone, Debug)]
pub struct Stmt {
    pub kind: StmtKind,
    pub span: Span,
}

#[derive(Clone, Debug)]
pub enum StmtKind {
    Assign {
        target: Ident,
        value: Expr,
    },
    /// `e.leftSuccessor := f`, `v.position := p`: a write into a record.
    /// `target` is the lookup written to.
    Write {
        base: Expr,
        field: Ident,
        value: Expr,
    },
    /// `a[i] := x`: a write into an array's item.
    Store {
        array: Expr,
        index: Expr,
        value: Expr,
    },
    /// `delete x`: the row stays as a gap until the ids are compacted.
    Delete {
        target: Expr,
    },
    /// `name(args)` on its own: a call of another algorithm of the file
    /// (any result is dropped), or of `append`.
    Call {
        name: Ident,
        args: Vec<Expr>,
    },
    /// `return` or `return value`: back to the caller (or, in the algorithm
    /// that was started, to its end).
    Return {
        value: Option<Expr>,
    },
    /// `if c then … else if c then … else … end`, or the half-edge paper's
    /// `if (c) statement else statement`.
    If {
        arms: Vec<(Expr, Vec<Stmt>)>,
        otherwise: Option<Vec<Stmt>>,
    },
    While {
        cond: Expr,
        body: Vec<Stmt>,
    },
    DoWhile {
        body: Vec<Stmt>,
        cond: Expr,
    },
    /// `do … end`: repeats until `break`.
    Loop {
        body: Vec<Stmt>,
    },
    /// `begin … end`.
    Block(Vec<Stmt>),
    Break,
    Continue,
    Action {
        action: Action,
        target: Expr,
    },
    /// `message` items: strings and values, shown separated by spaces.
    Message {
        parts: Vec<MessagePart>,
    },
    /// `refuse "reason", value, …`: stops the run, reporting why an
    /// operation's precondition does not hold.
    Refuse {
        parts: Vec<MessagePart>,
    },
    /// A statement that did not parse (already reported).
    Error,
}

#[derive(Clone, Debug)]
pub enum MessagePart {
    Text(String),
    Value(Expr),
}

#[derive(Clone, Debug)]
pub struct Expr {
    pub kind: ExprKind,
    pub span: Span,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum UnaryOp {
    Neg,
    Not,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BinaryOp {
    Eq,
    NotEq,
    Lt,
    Le,
    Gt,
    Ge,
    Add,
    Sub,
    Mul,
    /// `/`: Float division.
    Divide,
    Div,
    Mod,
    And,
    Or,
}

impl BinaryOp {
    pub fn symbol(self) -> &'static str {
        match self {
            BinaryOp::Eq => "=",
            BinaryOp::NotEq => "<>",
            BinaryOp::Lt => "<",
            BinaryOp::Le => "<=",
            BinaryOp::Gt => ">",
            BinaryOp::Ge => ">=",
            BinaryOp::Add => "+",
            BinaryOp::Sub => "-",
            BinaryOp::Mul => "*",
            BinaryOp::Divide => "/",
            BinaryOp::Div => "div",
            BinaryOp::Mod => "mod",
            BinaryOp::And => "and",
            BinaryOp::Or => "or",
        }
    }

    pub fn is_comparison(self) -> bool {
        matches!(
            self,
            BinaryOp::Eq
                | BinaryOp::NotEq
                | BinaryOp::Lt
                | BinaryOp::Le
                | BinaryOp::Gt
                | BinaryOp::Ge
        )
    }
}

#[derive(Clone, Debug)]
pub enum ExprKind {
    Name(String),
    Lookup {
        base: Box<Expr>,
        field: Ident,
    },
    Integer(i32),
    Float(f32),
    Boolean(bool),
    Null,
    /// `new Vertex`, `new Edge`, `new Face`.
    New(ElementKind),
    /// A built-in function (`vector(x, y, z)`, `length(a)`), or another
    /// algorithm of the file that returns a value.
    Call {
        name: Ident,
        args: Vec<Expr>,
    },
    /// `a[i]`: an array's item.
    Index {
        array: Box<Expr>,
        index: Box<Expr>,
    },
    Unary {
        op: UnaryOp,
        operand: Box<Expr>,
    },
    Binary {
        op: BinaryOp,
        left: Box<Expr>,
        right: Box<Expr>,
    },
    /// An expression that did not parse (already reported).
    Error,
}
