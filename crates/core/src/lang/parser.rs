//! The recursive-descent parser. Each function parses one rule of the
//! grammar (see the module documentation of `lang`) and is named after it.
//!
//! The parser never stops at the first error: a missing token is reported and
//! assumed, a broken expression becomes [`ExprKind::Error`], and a statement
//! that cannot be understood is skipped up to the next `;`, so one run reports
//! every independent mistake in a file.

use super::ast::*;
use super::diagnostic::{Diagnostic, LineIndex, MAX_ERRORS, Span, shorten};
use super::lexer::{SKIPPED_REST, tokenize};
use super::token::{Token, TokenKind as T};
use super::types::{Item, Type};
use crate::schema::Structure;

/// Parses a whole file. The tree is usable (with error nodes) even when
/// diagnostics were reported.
pub fn parse(source: &str) -> (SourceFile, Vec<Diagnostic>) {
    let (tokens, diagnostics) = tokenize(source);
    let lexer_gave_up = diagnostics
        .last()
        .is_some_and(|d| d.message.ends_with(SKIPPED_REST));
    let mut parser = Parser {
        source,
        lines: LineIndex::new(source),
        tokens,
        pos: 0,
        diagnostics,
        depth: 0,
        gave_up: lexer_gave_up,
    };
    let file = parser.file();
    (file, parser.diagnostics)
}

struct Parser<'s> {
    source: &'s str,
    lines: LineIndex,
    tokens: Vec<Token>,
    pos: usize,
    diagnostics: Vec<Diagnostic>,
    /// Current nesting of statements and expressions, plus the operators
    /// and lookups of the chain being read, bounded so that no later pass over
    /// the tree can exhaust the stack.
    depth: u32,
    /// Set once the rest of the file is skipped; later errors are echoes.
    gave_up: bool,
}

/// Deeper nesting than this is refused rather than recursed into. Each
/// operator or lookup in a chain (`a + b + c`, `e.pair.face`) counts as a
/// level too, since it nests the tree one level deeper; every pass over the
/// tree then recurses at most twice this deep.
pub const MAX_NESTING: u32 = 100;

/// Tokens that may begin a statement, used to decide whether a missing `;`
/// can simply be assumed.
const STATEMENT_STARTS: &[T] = &[
    T::Ident,
    T::If,
    T::While,
    T::Do,
    T::Begin,
    T::Break,
    T::Continue,
    T::Mark,
    T::Highlight,
    T::Message,
    T::Return,
];

impl Parser<'_> {
    // ---- token helpers ----

    fn token(&self) -> Token {
        self.token_at(0)
    }

    fn token_at(&self, ahead: usize) -> Token {
        let last = self.tokens.len().saturating_sub(1);
        self.tokens
            .get((self.pos + ahead).min(last))
            .copied()
            .unwrap_or(Token {
                kind: T::Eof,
                span: Span::default(),
            })
    }

    fn peek(&self) -> T {
        self.token().kind
    }

    fn at(&self, kind: T) -> bool {
        self.peek() == kind
    }

    fn bump(&mut self) -> Token {
        let token = self.token();
        if token.kind != T::Eof {
            self.pos += 1;
        }
        token
    }

    fn eat(&mut self, kind: T) -> Option<Token> {
        if self.at(kind) {
            Some(self.bump())
        } else {
            None
        }
    }

    fn previous_span(&self) -> Span {
        self.pos
            .checked_sub(1)
            .and_then(|i| self.tokens.get(i))
            .map_or(Span::default(), |t| t.span)
    }

    fn text(&self, span: Span) -> &str {
        span.text(self.source)
    }

    fn found(&self) -> String {
        let token = self.token();
        match token.kind {
            T::Ident | T::Integer | T::String => {
                format!("`{}`", shorten(self.text(token.span), 40))
            }
            kind => kind.to_string(),
        }
    }

    /// Records an error unless one was already reported at the same place,
    /// which keeps one mistake from producing a cascade of messages.
    fn report(&mut self, diagnostic: Diagnostic) {
        if self.gave_up
            || self
                .diagnostics
                .iter()
                .any(|d| d.span.start == diagnostic.span.start)
        {
            return;
        }
        if self.diagnostics.len() >= MAX_ERRORS {
            self.give_up(diagnostic.span, &format!("more than {MAX_ERRORS} errors"));
            return;
        }
        self.diagnostics.push(diagnostic);
    }

    /// Reports why the rest of the file is skipped and skips it, which ends
    /// every open construct at once.
    fn give_up(&mut self, span: Span, why: &str) {
        if self.gave_up {
            return;
        }
        self.gave_up = true;
        self.diagnostics
            .push(Diagnostic::error(span, format!("{why}{SKIPPED_REST}")));
        self.pos = self.tokens.len().saturating_sub(1);
    }

    fn error_here(&mut self, message: String) {
        let span = self.token().span;
        self.report(Diagnostic::error(span, message));
    }

    /// Consumes `kind` or reports that it was expected (and carries on as if
    /// it had been there).
    fn expect(&mut self, kind: T, context: &str) -> Option<Token> {
        if let Some(token) = self.eat(kind) {
            return Some(token);
        }
        let message = format!("expected {kind} {context}, found {}", self.found());
        self.error_here(message);
        None
    }

    fn line_of(&self, span: Span) -> u32 {
        self.lines.line(span.start)
    }

    /// Skips to just past the next `;`, or to a token that closes a block.
    fn synchronize(&mut self) {
        loop {
            match self.peek() {
                T::Semicolon => {
                    self.bump();
                    return;
                }
                T::End | T::Else | T::Algorithm | T::Eof => return,
                _ => {
                    self.bump();
                }
            }
        }
    }

    // ---- file := algorithm-declaration [ ; ] … ----

    fn file(&mut self) -> SourceFile {
        let mut file = SourceFile::default();
        while !self.at(T::Eof) {
            if self.at(T::Algorithm) {
                file.algorithms.push(self.algorithm_declaration());
            } else {
                let message = format!("expected `algorithm`, found {}", self.found());
                self.error_here(message);
                while !matches!(self.peek(), T::Algorithm | T::Eof) {
                    self.bump();
                }
            }
        }
        file
    }

    // ---- algorithm-declaration ----

    fn algorithm_declaration(&mut self) -> AlgorithmDecl {
        let start = self.bump().span;
        let name = self.identifier("as the algorithm's name");
        self.expect(T::LParen, "after the algorithm's name");
        let params = if self.at(T::RParen) {
            Vec::new()
        } else {
            self.parameter_list()
        };
        self.expect(T::RParen, "after the parameters");

        let mut structure = None;
        // Set once a structure type was written, even a misspelled one, so
        // a typo is not also reported as a missing structure type.
        let mut structure_written = false;
        if self.eat(T::Colon).is_some() {
            structure_written = true;
            structure = self.mesh_type();
        }
        let returns = self.result_type();
        self.eat(T::Semicolon);
        if self.eat(T::StructureType).is_some() {
            structure_written = true;
            let declared = self.mesh_type();
            if let (Some((first, _)), Some((second, span))) = (structure, declared)
                && first != second
            {
                self.report(Diagnostic::error(
                    span,
                    format!("the structure type is given twice, as {first} and as {second}"),
                ));
            }
            structure = structure.or(declared);
            self.eat(T::Semicolon);
        }
        let mut description = None;
        if self.eat(T::Description).is_some() {
            if let Some(token) = self.expect(T::String, "after `description`") {
                description = Some(string_contents(self.text(token.span)));
            }
            self.eat(T::Semicolon);
        }
        let mut vars = Vec::new();
        while self.eat(T::Var).is_some() {
            while self.starts_declaration() {
                vars.extend(self.declaration_group());
                if self.eat(T::Semicolon).is_none() {
                    break;
                }
            }
        }
        if structure.is_none()
            && self.at(T::Ident)
            && Structure::parse(self.text(self.token().span)).is_some()
        {
            // `algorithm f(v : Vertex) HalfEdge;` — a forgotten colon.
            structure_written = true;
            structure = self.mesh_type();
            self.eat(T::Semicolon);
        }
        self.expect(T::Begin, "before the algorithm's statements");
        let body = self.statement_list(false);
        let end_span = match self.eat(T::End) {
            Some(token) => token.span,
            None => {
                let message = format!(
                    "expected `end` to close algorithm `{}` (line {}), found {}",
                    name.name,
                    self.line_of(start),
                    self.found()
                );
                let span = self.token().span;
                self.report(Diagnostic::error(span, message).with_hint(
                    "an `if`, `while`, `do` or `begin` inside it may be missing its own `end`",
                ));
                self.previous_span().after()
            }
        };
        self.eat(T::Semicolon);
        if !structure_written {
            self.report(
                Diagnostic::error(name.span, format!("algorithm `{}` does not say which structure it walks", name.name))
                    .with_hint("add `structuretype WingedEdge` (or HalfEdge) after the header, or `: HalfEdge` after the parameters"),
            );
        }
        AlgorithmDecl {
            name,
            params,
            structure,
            returns,
            description,
            vars,
            body,
            span: start.to(end_span),
            end_span,
        }
    }

    fn identifier(&mut self, context: &str) -> Ident {
        if let Some(token) = self.eat(T::Ident) {
            return Ident {
                name: self.text(token.span).to_owned(),
                span: token.span,
            };
        }
        let token = self.token();
        let message = if token.kind.is_keyword() {
            format!(
                "`{}` is a keyword and cannot be used {context}",
                self.text(token.span)
            )
        } else {
            format!("expected a name {context}, found {}", self.found())
        };
        self.error_here(message);
        if token.kind.is_keyword() {
            self.bump();
        }
        Ident {
            name: String::new(),
            span: token.span,
        }
    }

    /// A declaration group starts with a name (or a keyword misused as one)
    /// followed by `:` or `,`; anything else ends the `var` section.
    fn starts_declaration(&self) -> bool {
        let first = self.peek();
        (first == T::Ident || first.is_keyword())
            && matches!(self.token_at(1).kind, T::Colon | T::Comma)
    }

    fn mesh_type(&mut self) -> Option<(Structure, Span)> {
        let token = self.token();
        if token.kind == T::Ident {
            self.bump();
            let word = self.text(token.span);
            if let Some(structure) = Structure::parse(word) {
                return Some((structure, token.span));
            }
            let hint = if Type::parse(word).is_some() || word.eq_ignore_ascii_case("array") {
                format!(
                    "after `:` comes the structure the algorithm walks; a result is written \
                     `returns {word}` after it"
                )
            } else {
                super::diagnostic::nearest(word, ["WingedEdge", "HalfEdge"]).map_or_else(
                    || "the structure types are WingedEdge and HalfEdge".to_owned(),
                    |n| format!("did you mean `{n}`?"),
                )
            };
            self.report(
                Diagnostic::error(token.span, format!("unknown structure type `{word}`"))
                    .with_hint(hint),
            );
        } else {
            let message = format!(
                "expected a structure type (WingedEdge or HalfEdge), found {}",
                self.found()
            );
            self.error_here(message);
        }
        None
    }

    // ---- parameter-list := identifier-list : type [ ; identifier-list : type ]* ----

    fn parameter_list(&mut self) -> Vec<VarDecl> {
        let mut params = Vec::new();
        loop {
            params.extend(self.declaration_group());
            // The grammar separates groups with `;`; a `,` is accepted too.
            if self.eat(T::Semicolon).is_none() && self.eat(T::Comma).is_none() {
                return params;
            }
        }
    }

    /// identifier-list : type
    fn declaration_group(&mut self) -> Vec<VarDecl> {
        let mut names = vec![self.identifier("in a declaration")];
        while self.eat(T::Comma).is_some() {
            names.push(self.identifier("in a declaration"));
        }
        self.expect(T::Colon, "between the names and their type");
        let (ty, ty_span) = self.type_name();
        names
            .into_iter()
            .map(|name| VarDecl { name, ty, ty_span })
            .collect()
    }

    // result-type := "returns" type
    fn result_type(&mut self) -> Option<(Option<Type>, Span)> {
        self.eat(T::Returns)?;
        let (ty, span) = self.type_name();
        Some((ty, span))
    }

    // type := scalar-type | "Array" "of" scalar-type
    fn type_name(&mut self) -> (Option<Type>, Span) {
        let token = self.token();
        if token.kind == T::Ident && self.text(token.span).eq_ignore_ascii_case("array") {
            return self.array_type();
        }
        self.scalar_type()
    }

    /// `Array of Edge`. The item type is read as a scalar type, without
    /// recursion, so `Array of Array of …` is an error, not a deeper parse.
    fn array_type(&mut self) -> (Option<Type>, Span) {
        let start = self.bump().span;
        if self.eat(T::Of).is_none() {
            let message = format!("expected `of` after `Array`, found {}", self.found());
            let span = self.token().span;
            self.report(
                Diagnostic::error(span, message)
                    .with_hint("an array type names its items: `Array of Edge`"),
            );
            return (None, start);
        }
        let item = self.token();
        if item.kind == T::Ident && self.text(item.span).eq_ignore_ascii_case("array") {
            self.report(
                Diagnostic::error(item.span, "an array cannot hold arrays").with_hint(
                    "its items are vertices, edges, faces, numbers, Booleans or Vectors",
                ),
            );
            // Skip the rest of the type (`Array of … of Edge`) in a loop.
            while self.at(T::Ident) && self.text(self.token().span).eq_ignore_ascii_case("array") {
                self.bump();
                if self.eat(T::Of).is_none() {
                    break;
                }
            }
            let (_, span) = self.scalar_type();
            return (None, start.to(span));
        }
        let (ty, span) = self.scalar_type();
        let span = start.to(span);
        (ty.and_then(Item::of).map(Type::Array), span)
    }

    fn scalar_type(&mut self) -> (Option<Type>, Span) {
        let token = self.token();
        if token.kind != T::Ident {
            let message = format!(
                "expected a type (Vertex, Edge, Face, Integer or Boolean), found {}",
                self.found()
            );
            self.error_here(message);
            return (None, token.span);
        }
        self.bump();
        let word = self.text(token.span);
        if let Some(ty) = Type::parse(word) {
            return (Some(ty), token.span);
        }
        let diagnostic = Diagnostic::error(token.span, format!("unknown type `{word}`"));
        let diagnostic = if Structure::parse(word).is_some() {
            diagnostic.with_hint(format!(
                "{word} is a structure type; its edges have type Edge"
            ))
        } else if let Some(near) =
            super::diagnostic::nearest(word, Type::DECLARABLE.iter().map(|t| t.name()))
        {
            diagnostic.with_hint(format!("did you mean `{near}`?"))
        } else {
            diagnostic.with_hint("the types are Vertex, Edge, Face, Integer and Boolean")
        };
        self.report(diagnostic);
        (None, token.span)
    }

    // ---- statement-list := statement ; [ statement ; ]* ----

    /// Parses statements up to `end`, `else` or (inside a `do` body) the
    /// `while` that closes the loop. The `;` before those is optional.
    fn statement_list(&mut self, in_do_body: bool) -> Vec<Stmt> {
        let mut statements = Vec::new();
        loop {
            while self.eat(T::Semicolon).is_some() {}
            match self.peek() {
                T::End | T::Else | T::Eof | T::Algorithm => return statements,
                T::While if in_do_body && self.while_closes_do() => return statements,
                _ => {}
            }
            let before = self.pos;
            let statement = self.statement();
            if self.pos == before {
                let message = format!("expected a statement, found {}", self.found());
                self.error_here(message);
                self.synchronize();
                continue;
            }
            let failed = matches!(statement.kind, StmtKind::Error);
            let end = statement.span;
            statements.push(statement);
            if failed {
                continue;
            }
            if self.eat(T::Semicolon).is_some() {
                continue;
            }
            match self.peek() {
                T::End | T::Else | T::Eof => {}
                T::While if in_do_body => {}
                kind => {
                    // A bad character in between was reported already.
                    let gap = end.end..self.token().span.start;
                    if !self.diagnostics.iter().any(|d| gap.contains(&d.span.start)) {
                        self.report(Diagnostic::error(
                            end.after(),
                            "expected `;` after this statement",
                        ));
                    }
                    if !STATEMENT_STARTS.contains(&kind) {
                        self.synchronize();
                    }
                }
            }
        }
    }

    /// In a `do` body, tells the `while` that closes the loop from a nested
    /// `while … do` statement: only the latter has a `do` after its condition.
    fn while_closes_do(&self) -> bool {
        let mut ahead = 1;
        loop {
            match self.token_at(ahead).kind {
                T::Do => return false,
                T::Semicolon
                | T::End
                | T::Else
                | T::Begin
                | T::Then
                | T::Eof
                | T::Algorithm
                | T::While => return true,
                _ => ahead += 1,
            }
        }
    }

    fn statement(&mut self) -> Stmt {
        if !self.enter() {
            return Stmt {
                kind: StmtKind::Error,
                span: self.token().span,
            };
        }
        let statement = self.statement_inner();
        self.depth -= 1;
        statement
    }

    fn statement_inner(&mut self) -> Stmt {
        let start = self.token().span;
        let kind = match self.peek() {
            T::If => return self.if_statement(),
            T::While => return self.while_statement(),
            T::Do => return self.do_statement(),
            T::Begin => {
                self.bump();
                let body = self.statement_list(false);
                self.close_with_end("begin", start);
                StmtKind::Block(body)
            }
            T::Break => {
                self.bump();
                StmtKind::Break
            }
            T::Continue => {
                self.bump();
                StmtKind::Continue
            }
            T::Mark | T::Highlight => {
                let action = if self.bump().kind == T::Mark {
                    Action::Mark
                } else {
                    Action::Highlight
                };
                let target = self.expression();
                StmtKind::Action { action, target }
            }
            T::Message | T::Refuse => self.message_statement(),
            T::Return => {
                self.bump();
                let value = starts_expression(self.peek()).then(|| self.expression());
                StmtKind::Return { value }
            }
            T::Delete => {
                self.bump();
                StmtKind::Delete {
                    target: self.expression(),
                }
            }
            T::Ident => return self.identifier_statement(),
            _ => {
                return Stmt {
                    kind: StmtKind::Error,
                    span: start,
                };
            }
        };
        Stmt {
            kind,
            span: start.to(self.previous_span()),
        }
    }

    fn close_with_end(&mut self, construct: &str, opened: Span) {
        if self.eat(T::End).is_none() {
            let message = format!(
                "expected `end` to close the `{construct}` on line {}, found {}",
                self.line_of(opened),
                self.found()
            );
            self.error_here(message);
        }
    }

    /// An assignment, or the half-edge paper's `e.mark;` / `v.highlight;`.
    fn identifier_statement(&mut self) -> Stmt {
        let target = self.postfix_expression();
        let start = target.span;
        let finish = |this: &Self, kind| Stmt {
            kind,
            span: start.to(this.previous_span()),
        };
        match self.peek() {
            T::Assign | T::Eq | T::EqEq => {
                let operator = self.bump();
                if operator.kind != T::Assign {
                    self.report(
                        Diagnostic::error(
                            operator.span,
                            format!(
                                "`{}` compares values; assignment is written `:=`",
                                self.text(operator.span)
                            ),
                        )
                        .with_hint("did you mean `:=`?"),
                    );
                }
                let value = self.expression();
                match target.kind {
                    ExprKind::Name(name) => finish(
                        self,
                        StmtKind::Assign {
                            target: Ident {
                                name,
                                span: target.span,
                            },
                            value,
                        },
                    ),
                    ExprKind::Lookup { base, field } => finish(
                        self,
                        StmtKind::Write {
                            base: *base,
                            field,
                            value,
                        },
                    ),
                    ExprKind::Index { array, index } => finish(
                        self,
                        StmtKind::Store {
                            array: *array,
                            index: *index,
                            value,
                        },
                    ),
                    _ => {
                        self.report(
                            Diagnostic::error(
                                target.span,
                                "only a variable, a record's field or an array's item can be \
                                 assigned to",
                            )
                            .with_hint("write `x := …`, `e.leftSuccessor := …` or `a[i] := …`"),
                        );
                        finish(self, StmtKind::Error)
                    }
                }
            }
            _ => {
                if let ExprKind::Call { name, args } = target.kind {
                    return finish(self, StmtKind::Call { name, args });
                }
                if let ExprKind::Lookup { base, field } = &target.kind {
                    let action = if field.name.eq_ignore_ascii_case("mark") {
                        Some(Action::Mark)
                    } else if field.name.eq_ignore_ascii_case("highlight") {
                        Some(Action::Highlight)
                    } else {
                        None
                    };
                    if let Some(action) = action {
                        return finish(
                            self,
                            StmtKind::Action {
                                action,
                                target: (**base).clone(),
                            },
                        );
                    }
                }
                let text = self.text(target.span).to_owned();
                let hint = match target.kind {
                    ExprKind::Name(_) => format!(
                        "to change `{text}`, write `{text} := …`; to output it, `mark {text}`"
                    ),
                    _ => format!(
                        "a lookup on its own does nothing; to output it, write `mark {text}`"
                    ),
                };
                let message = format!("expected `:=` after `{text}`, found {}", self.found());
                self.report(Diagnostic::error(self.token().span, message).with_hint(hint));
                self.synchronize();
                Stmt {
                    kind: StmtKind::Error,
                    span: start,
                }
            }
        }
    }

    // message-statement := ("message" | "refuse") item { , item },
    // item := string | expr
    fn message_statement(&mut self) -> StmtKind {
        let refuse = self.bump().kind == T::Refuse;
        let mut parts = Vec::new();
        loop {
            if let Some(token) = self.eat(T::String) {
                parts.push(MessagePart::Text(string_contents(self.text(token.span))));
            } else {
                parts.push(MessagePart::Value(self.expression()));
            }
            if self.eat(T::Comma).is_none() {
                return if refuse {
                    StmtKind::Refuse { parts }
                } else {
                    StmtKind::Message { parts }
                };
            }
        }
    }

    // if-statement := if expr then statement-list [ else if expr then statement-list ]* [ else statement-list ] end
    //               | if ( expr ) statement [ else statement ]        (half-edge paper)
    fn if_statement(&mut self) -> Stmt {
        let start = self.bump().span;
        let parenthesized = self.at(T::LParen);
        let cond = self.expression();
        let closed_by_paren = parenthesized
            && self
                .pos
                .checked_sub(1)
                .and_then(|i| self.tokens.get(i))
                .is_some_and(|t| t.kind == T::RParen);
        if self.at(T::Then) || !closed_by_paren {
            self.expect(T::Then, "after the condition");
            let mut arms = vec![(cond, self.statement_list(false))];
            let mut otherwise = None;
            while self.eat(T::Else).is_some() {
                if self.eat(T::If).is_some() {
                    let cond = self.expression();
                    self.expect(T::Then, "after the condition");
                    arms.push((cond, self.statement_list(false)));
                } else {
                    otherwise = Some(self.statement_list(false));
                    break;
                }
            }
            self.close_with_end("if", start);
            return Stmt {
                kind: StmtKind::If { arms, otherwise },
                span: start.to(self.previous_span()),
            };
        }
        let then_branch = self.single_statement();
        if self.at(T::Semicolon) && self.token_at(1).kind == T::Else {
            self.bump();
        }
        let otherwise = if self.eat(T::Else).is_some() {
            Some(vec![self.single_statement()])
        } else {
            None
        };
        Stmt {
            kind: StmtKind::If {
                arms: vec![(cond, vec![then_branch])],
                otherwise,
            },
            span: start.to(self.previous_span()),
        }
    }

    fn single_statement(&mut self) -> Stmt {
        let before = self.pos;
        let statement = self.statement();
        if self.pos == before {
            let message = format!("expected a statement, found {}", self.found());
            self.error_here(message);
        }
        statement
    }

    // while-statement := while expr do statement-list end
    fn while_statement(&mut self) -> Stmt {
        let start = self.bump().span;
        let cond = self.expression();
        self.expect(T::Do, "after the loop's condition");
        let body = self.statement_list(false);
        self.close_with_end("while", start);
        Stmt {
            kind: StmtKind::While { cond, body },
            span: start.to(self.previous_span()),
        }
    }

    // do-while-statement := do statement-list while expr
    // do-statement       := do statement-list end
    // (`do begin … end while (c)` is a do-while whose body is one block.)
    fn do_statement(&mut self) -> Stmt {
        let start = self.bump().span;
        let body = self.statement_list(true);
        let kind = if self.eat(T::While).is_some() {
            let cond = self.expression();
            StmtKind::DoWhile { body, cond }
        } else {
            if self.eat(T::End).is_none() {
                let message = format!(
                    "expected `while` or `end` to close the `do` on line {}, found {}",
                    self.line_of(start),
                    self.found()
                );
                self.error_here(message);
            }
            StmtKind::Loop { body }
        };
        Stmt {
            kind,
            span: start.to(self.previous_span()),
        }
    }

    // ---- expressions, loosest first ----

    fn expression(&mut self) -> Expr {
        if !self.enter() {
            return Expr {
                kind: ExprKind::Error,
                span: self.token().span,
            };
        }
        let expr = self.or_expression();
        self.depth -= 1;
        expr
    }

    /// Counts one level of nesting; past the limit, reports it once and
    /// skips the rest of the file, which ends every open construct.
    fn enter(&mut self) -> bool {
        let span = self.token().span;
        self.deepen(span, || {
            format!("this is nested too deeply (more than {MAX_NESTING} levels)")
        })
    }

    /// Counts one more operator or lookup of a chain (the caller restores
    /// the depth after the chain); past the limit, reports it at `operator`
    /// and skips the rest of the file.
    fn chain(&mut self, operator: Span) -> bool {
        self.deepen(operator, || {
            format!(
                "this expression is too long (more than {MAX_NESTING} operators, lookups and \
                 levels of nesting); split it into steps with variables"
            )
        })
    }

    /// One level deeper, or, past [`MAX_NESTING`], `why` at `span` and the
    /// rest of the file skipped.
    fn deepen(&mut self, span: Span, why: impl FnOnce() -> String) -> bool {
        if self.depth < MAX_NESTING {
            self.depth += 1;
            return true;
        }
        self.give_up(span, &why());
        false
    }

    /// A binary expression's span runs from where its left operand began to
    /// the last token read, so it includes any parentheses around operands.
    fn binary(&self, start: u32, op: BinaryOp, left: Expr, right: Expr) -> Expr {
        let span = Span {
            start,
            end: self.previous_span().end.max(start),
        };
        Expr {
            kind: ExprKind::Binary {
                op,
                left: Box::new(left),
                right: Box::new(right),
            },
            span,
        }
    }

    fn or_expression(&mut self) -> Expr {
        let (start, depth) = (self.token().span.start, self.depth);
        let mut left = self.and_expression();
        while let Some(operator) = self.eat(T::Or) {
            if !self.chain(operator.span) {
                break;
            }
            let right = self.and_expression();
            left = self.binary(start, BinaryOp::Or, left, right);
        }
        self.depth = depth;
        left
    }

    fn and_expression(&mut self) -> Expr {
        let (start, depth) = (self.token().span.start, self.depth);
        let mut left = self.not_expression();
        while let Some(operator) = self.eat(T::And) {
            if !self.chain(operator.span) {
                break;
            }
            let right = self.not_expression();
            left = self.binary(start, BinaryOp::And, left, right);
        }
        self.depth = depth;
        left
    }

    fn not_expression(&mut self) -> Expr {
        if let Some(token) = self.eat(T::Not) {
            if !self.enter() {
                return Expr {
                    kind: ExprKind::Error,
                    span: token.span,
                };
            }
            let operand = self.not_expression();
            self.depth -= 1;
            let span = token.span.to(self.previous_span());
            return Expr {
                kind: ExprKind::Unary {
                    op: UnaryOp::Not,
                    operand: Box::new(operand),
                },
                span,
            };
        }
        self.comparison()
    }

    fn comparison_operator(&mut self) -> Option<BinaryOp> {
        let op = match self.peek() {
            T::Eq | T::EqEq => BinaryOp::Eq,
            T::NotEq => BinaryOp::NotEq,
            T::BangEq => {
                let span = self.token().span;
                self.report(
                    Diagnostic::error(span, "`!=` is not an operator here")
                        .with_hint("did you mean `<>`?"),
                );
                BinaryOp::NotEq
            }
            T::Lt => BinaryOp::Lt,
            T::Le => BinaryOp::Le,
            T::Gt => BinaryOp::Gt,
            T::Ge => BinaryOp::Ge,
            _ => return None,
        };
        self.bump();
        Some(op)
    }

    fn comparison(&mut self) -> Expr {
        let start = self.token().span.start;
        let left = self.additive();
        let Some(op) = self.comparison_operator() else {
            return left;
        };
        let right = self.additive();
        let mut expr = self.binary(start, op, left, right);
        let chained = self.token().span;
        if self.comparison_operator().is_some() {
            self.report(
                Diagnostic::error(chained, "comparisons cannot be chained")
                    .with_hint("compare twice and join them with `and`"),
            );
            let extra = self.additive();
            expr.span = expr.span.to(extra.span);
            expr.kind = ExprKind::Error;
        }
        expr
    }

    fn additive(&mut self) -> Expr {
        let (start, depth) = (self.token().span.start, self.depth);
        let mut left = self.multiplicative();
        loop {
            let op = match self.peek() {
                T::Plus => BinaryOp::Add,
                T::Minus => BinaryOp::Sub,
                _ => break,
            };
            let operator = self.bump();
            if !self.chain(operator.span) {
                break;
            }
            let right = self.multiplicative();
            left = self.binary(start, op, left, right);
        }
        self.depth = depth;
        left
    }

    fn multiplicative(&mut self) -> Expr {
        let (start, depth) = (self.token().span.start, self.depth);
        let mut left = self.unary();
        loop {
            let op = match self.peek() {
                T::Star => BinaryOp::Mul,
                T::Slash => BinaryOp::Divide,
                T::Div => BinaryOp::Div,
                T::Mod => BinaryOp::Mod,
                _ => break,
            };
            let operator = self.bump();
            if !self.chain(operator.span) {
                break;
            }
            let right = self.unary();
            left = self.binary(start, op, left, right);
        }
        self.depth = depth;
        left
    }

    fn unary(&mut self) -> Expr {
        if let Some(token) = self.eat(T::Minus) {
            if !self.enter() {
                return Expr {
                    kind: ExprKind::Error,
                    span: token.span,
                };
            }
            let operand = self.unary();
            self.depth -= 1;
            let span = token.span.to(self.previous_span());
            if let ExprKind::Integer(n) = operand.kind {
                return Expr {
                    kind: ExprKind::Integer(n.wrapping_neg()),
                    span,
                };
            }
            if let ExprKind::Float(x) = operand.kind {
                return Expr {
                    kind: ExprKind::Float(-x),
                    span,
                };
            }
            return Expr {
                kind: ExprKind::Unary {
                    op: UnaryOp::Neg,
                    operand: Box::new(operand),
                },
                span,
            };
        }
        self.postfix_expression()
    }

    // postfix := primary { "." lookup | "[" expr "]" }
    fn postfix_expression(&mut self) -> Expr {
        let depth = self.depth;
        let mut expr = self.primary();
        while matches!(self.peek(), T::Dot | T::LBracket) {
            let operator = self.bump();
            if !self.chain(operator.span) {
                // The rest was skipped: an unfinished chain is no value, so
                // that what holds it reports nothing more.
                self.depth = depth;
                return Expr {
                    kind: ExprKind::Error,
                    span: expr.span,
                };
            }
            if operator.kind == T::LBracket {
                let index = self.expression();
                self.expect(T::RBracket, "to close the index");
                expr = Expr {
                    span: expr.span.to(self.previous_span()),
                    kind: ExprKind::Index {
                        array: Box::new(expr),
                        index: Box::new(index),
                    },
                };
                continue;
            }
            let token = self.token();
            if token.kind == T::Ident || token.kind.is_keyword() {
                self.bump();
                let field = Ident {
                    name: self.text(token.span).to_owned(),
                    span: token.span,
                };
                let span = expr.span.to(token.span);
                expr = Expr {
                    kind: ExprKind::Lookup {
                        base: Box::new(expr),
                        field,
                    },
                    span,
                };
            } else {
                let message = format!("expected a lookup name after `.`, found {}", self.found());
                self.error_here(message);
                self.depth = depth;
                return Expr {
                    kind: ExprKind::Error,
                    span: expr.span,
                };
            }
        }
        self.depth = depth;
        expr
    }

    fn primary(&mut self) -> Expr {
        let token = self.token();
        let kind = match token.kind {
            T::Ident if self.token_at(1).kind == T::LParen => return self.call(),
            T::Ident => ExprKind::Name(self.text(token.span).to_owned()),
            T::Float => ExprKind::Float(self.text(token.span).parse().unwrap_or(0.0)),
            T::New => return self.new_element(),
            // An out-of-range number was reported by the lexer.
            T::Integer => ExprKind::Integer(self.text(token.span).parse().unwrap_or(0)),
            T::True => ExprKind::Boolean(true),
            T::False => ExprKind::Boolean(false),
            T::Null => ExprKind::Null,
            T::LParen => {
                self.bump();
                let inner = self.expression();
                self.expect(T::RParen, "to close the parenthesis");
                return inner;
            }
            _ => {
                let message = format!("expected an expression, found {}", self.found());
                self.error_here(message);
                return Expr {
                    kind: ExprKind::Error,
                    span: token.span,
                };
            }
        };
        self.bump();
        Expr {
            kind,
            span: token.span,
        }
    }
}

impl Parser<'_> {
    // call := ident "(" [ expr { "," expr } ] ")"
    fn call(&mut self) -> Expr {
        let name = self.identifier("as a function name");
        self.bump();
        let mut args = Vec::new();
        if !self.at(T::RParen) {
            loop {
                args.push(self.expression());
                if self.eat(T::Comma).is_none() {
                    break;
                }
            }
        }
        self.expect(T::RParen, "to close the argument list");
        Expr {
            span: name.span.to(self.previous_span()),
            kind: ExprKind::Call { name, args },
        }
    }

    // new-element := "new" ( "Vertex" | "Edge" | "Face" )
    fn new_element(&mut self) -> Expr {
        let start = self.bump().span;
        let (ty, span) = self.type_name();
        let span = start.to(span);
        match ty.and_then(Type::element_kind) {
            Some(kind) => Expr {
                kind: ExprKind::New(kind),
                span,
            },
            None => {
                if ty.is_some() {
                    self.report(Diagnostic::error(
                        span,
                        "`new` makes a Vertex, an Edge or a Face",
                    ));
                }
                Expr {
                    kind: ExprKind::Error,
                    span,
                }
            }
        }
    }
}

/// Whether a token can begin an expression: `return` followed by one
/// returns a value.
fn starts_expression(kind: T) -> bool {
    matches!(
        kind,
        T::Ident
            | T::Integer
            | T::Float
            | T::True
            | T::False
            | T::Null
            | T::New
            | T::LParen
            | T::Minus
            | T::Not
    )
}

/// The text between a string token's quotes.
fn string_contents(token: &str) -> String {
    let inner = token.strip_prefix('"').unwrap_or(token);
    inner.strip_suffix('"').unwrap_or(inner).to_owned()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse_ok(source: &str) -> SourceFile {
        let (file, diagnostics) = parse(source);
        assert!(diagnostics.is_empty(), "{diagnostics:#?}");
        file
    }

    #[test]
    fn journal_listing_parses() {
        let file = parse_ok(
            "algorithm vertexAdjacentEdge(v : Vertex);\nstructuretype WingedEdge\ndescription \"Mark the adjacent edges of a vertex.\"\nvar e, se : Edge;\nbegin\n e := v.incidentEdge;\n se := e;\n do\n mark e;\n if e.startVertex = v then\n e := e.leftSuccessor;\n else\n e := e.rightSuccessor;\n end;\n while e <> se;\nend;\n",
        );
        let algorithm = &file.algorithms[0];
        assert_eq!(algorithm.name.name, "vertexAdjacentEdge");
        assert_eq!(
            algorithm.structure.map(|s| s.0),
            Some(Structure::WingedEdge)
        );
        assert_eq!(algorithm.vars.len(), 2);
        assert_eq!(algorithm.body.len(), 3);
        assert!(matches!(algorithm.body[2].kind, StmtKind::DoWhile { .. }));
    }

    #[test]
    fn half_edge_paper_dialect_parses() {
        let file = parse_ok(
            "ALGORITHM vertexAdjacentEdge( v : Vertex ) : HalfEdge;\n// Marks the adjacent edges of a vertex\nvar e, se : Edge;\nbegin\n v.highlight;\n e := v.incidentEdge;\n se := e;\n do\n begin\n e.mark;\n if( e.startVertex == v ) e := e.successorEdge else e := e.pairEdge\n end while( e <> se )\nend;",
        );
        let body = &file.algorithms[0].body;
        assert!(matches!(
            body[0].kind,
            StmtKind::Action {
                action: Action::Highlight,
                ..
            }
        ));
        let StmtKind::DoWhile { body, .. } = &body[3].kind else {
            panic!("{:?}", body[3])
        };
        assert!(matches!(body[0].kind, StmtKind::Block(_)));
    }

    #[test]
    fn nested_while_inside_do_is_not_the_loop_end() {
        let file = parse_ok(
            "algorithm a(n : Integer) : HalfEdge begin do while n > 0 do n := n - 1 end; n := 3 while n < 0 end",
        );
        let StmtKind::DoWhile { body, .. } = &file.algorithms[0].body[0].kind else {
            panic!()
        };
        assert_eq!(body.len(), 2);
    }

    #[test]
    fn calls_returns_and_arrays_parse_in_both_header_forms() {
        let file = parse_ok(
            "algorithm f(v : Vertex) returns Array of Edge;\nstructuretype WingedEdge\nvar a : Array of Edge;\nbegin append(a, v.incidentEdge); a[0] := a[length(a) - 1]; return a end;\nalgorithm g(v : Vertex) : WingedEdge returns Integer begin if v = null then return 0 end; f(v); return length(f(v)) end",
        );
        let (f, g) = (&file.algorithms[0], &file.algorithms[1]);
        assert_eq!(f.structure.map(|s| s.0), Some(Structure::WingedEdge));
        assert_eq!(f.returns.and_then(|r| r.0), Some(Type::Array(Item::Edge)));
        assert_eq!(g.returns.and_then(|r| r.0), Some(Type::Integer));
        assert!(matches!(f.body[0].kind, StmtKind::Call { .. }));
        assert!(matches!(f.body[1].kind, StmtKind::Store { .. }));
        assert!(matches!(
            f.body[2].kind,
            StmtKind::Return { value: Some(_) }
        ));
        let StmtKind::If { arms, .. } = &g.body[0].kind else {
            panic!("{:?}", g.body[0])
        };
        assert!(matches!(
            arms[0].1[0].kind,
            StmtKind::Return { value: Some(_) }
        ));
        assert!(matches!(g.body[1].kind, StmtKind::Call { .. }));
    }

    #[test]
    fn several_errors_are_reported_in_one_pass() {
        let (_, diagnostics) = parse(
            "algorithm a(v : Vertex) : HalfEdge\nvar e : Edge;\nbegin\n e = v.incidentEdge;\n if e then e := ;\n end;\n x := 1 +;\nend",
        );
        let messages: Vec<&str> = diagnostics.iter().map(|d| d.message.as_str()).collect();
        assert_eq!(messages.len(), 3, "{messages:?}");
        assert_eq!(diagnostics[0].hint.as_deref(), Some("did you mean `:=`?"));
    }
}
