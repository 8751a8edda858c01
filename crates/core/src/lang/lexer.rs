//! The hand-written lexer: source text to tokens, with `//` comments skipped.

use super::diagnostic::{Diagnostic, MAX_ERRORS, Span, shorten};

/// Longer names are refused: they would only make every message quoting them
/// unreadable, and no algorithm needs one.
pub const MAX_NAME_CHARS: usize = 256;

/// Ends the message of an error after which the lexer or parser stopped.
pub const SKIPPED_REST: &str = "; the rest of the file was not read";
use super::token::{Token, TokenKind};

/// Splits `source` into tokens, ending with [`TokenKind::Eof`]. Bad characters
/// and unterminated strings are reported and skipped, so parsing can go on and
/// find further errors.
pub fn tokenize(source: &str) -> (Vec<Token>, Vec<Diagnostic>) {
    let mut lexer = Lexer {
        source,
        bytes: source.as_bytes(),
        pos: 0,
        tokens: Vec::new(),
        diagnostics: Vec::new(),
    };
    lexer.run();
    (lexer.tokens, lexer.diagnostics)
}

struct Lexer<'s> {
    source: &'s str,
    bytes: &'s [u8],
    pos: usize,
    tokens: Vec<Token>,
    diagnostics: Vec<Diagnostic>,
}

impl Lexer<'_> {
    fn peek(&self, ahead: usize) -> u8 {
        self.bytes.get(self.pos + ahead).copied().unwrap_or(0)
    }

    fn push(&mut self, kind: TokenKind, start: usize) {
        self.tokens.push(Token {
            kind,
            span: Span::new(start, self.pos),
        });
    }

    fn run(&mut self) {
        while self.pos < self.bytes.len() {
            let start = self.pos;
            let c = self.peek(0);
            match c {
                b' ' | b'\t' | b'\r' | b'\n' => self.pos += 1,
                b'/' if self.peek(1) == b'/' => {
                    while self.pos < self.bytes.len() && self.peek(0) != b'\n' {
                        self.pos += 1;
                    }
                }
                b'a'..=b'z' | b'A'..=b'Z' | b'_' => {
                    while matches!(self.peek(0), b'a'..=b'z' | b'A'..=b'Z' | b'0'..=b'9' | b'_') {
                        self.pos += 1;
                    }
                    let word = Span::new(start, self.pos).text(self.source);
                    if word.len() > MAX_NAME_CHARS {
                        self.give_up(
                            Span::new(start, self.pos),
                            &format!(
                                "this name is {} characters long; names may have at most \
                                 {MAX_NAME_CHARS}",
                                word.len()
                            ),
                        );
                        break;
                    }
                    let kind = TokenKind::keyword(word).unwrap_or(TokenKind::Ident);
                    self.push(kind, start);
                }
                b'0'..=b'9' => self.number(start),
                b'"' => self.string(start),
                _ => self.operator(start, c),
            }
        }
        self.tokens.push(Token {
            kind: TokenKind::Eof,
            span: Span::new(self.pos, self.pos),
        });
    }

    /// An Integer (`42`) or a Float (`0.5`, `2.0`): a point counts only
    /// with a digit after it, so `1.x` stays a lookup on `1`.
    fn number(&mut self, start: usize) {
        while self.peek(0).is_ascii_digit() {
            self.pos += 1;
        }
        if self.peek(0) == b'.' && self.peek(1).is_ascii_digit() {
            self.pos += 1;
            while self.peek(0).is_ascii_digit() {
                self.pos += 1;
            }
            let span = Span::new(start, self.pos);
            let finite = span
                .text(self.source)
                .parse::<f32>()
                .is_ok_and(f32::is_finite);
            if !finite {
                self.report(Diagnostic::error(
                    span,
                    format!(
                        "the number {} is too large for a Float",
                        shorten(span.text(self.source), 20)
                    ),
                ));
            }
            self.push(TokenKind::Float, start);
            return;
        }
        let span = Span::new(start, self.pos);
        if span.text(self.source).parse::<i32>().is_err() {
            self.report(Diagnostic::error(
                span,
                format!(
                    "the number {} is too large (Integer holds up to {})",
                    shorten(span.text(self.source), 20),
                    i32::MAX
                ),
            ));
        }
        self.push(TokenKind::Integer, start);
    }

    /// Records an error; past [`MAX_ERRORS`] it stops reading instead, so a
    /// file of binary garbage gives a short report, not one error per byte.
    fn report(&mut self, diagnostic: Diagnostic) {
        if self.diagnostics.len() < MAX_ERRORS {
            self.diagnostics.push(diagnostic);
        } else {
            self.give_up(diagnostic.span, &format!("more than {MAX_ERRORS} errors"));
        }
    }

    /// Reports `why` and skips the rest of the text.
    fn give_up(&mut self, span: Span, why: &str) {
        self.diagnostics
            .push(Diagnostic::error(span, format!("{why}{SKIPPED_REST}")));
        self.pos = self.bytes.len();
    }

    fn string(&mut self, start: usize) {
        self.pos += 1;
        loop {
            match self.bytes.get(self.pos) {
                Some(b'"') => {
                    self.pos += 1;
                    self.push(TokenKind::String, start);
                    return;
                }
                None | Some(b'\n') => {
                    self.report(
                        Diagnostic::error(
                            Span::new(start, self.pos),
                            "this string has no closing `\"`",
                        )
                        .with_hint("strings end on the line they start on"),
                    );
                    self.push(TokenKind::String, start);
                    return;
                }
                Some(_) => self.pos += 1,
            }
        }
    }

    fn operator(&mut self, start: usize, c: u8) {
        use TokenKind as T;
        let next = self.peek(1);
        let (kind, len) = match (c, next) {
            (b':', b'=') => (T::Assign, 2),
            (b':', _) => (T::Colon, 1),
            (b';', _) => (T::Semicolon, 1),
            (b',', _) => (T::Comma, 1),
            (b'.', _) => (T::Dot, 1),
            (b'(', _) => (T::LParen, 1),
            (b')', _) => (T::RParen, 1),
            (b'[', _) => (T::LBracket, 1),
            (b']', _) => (T::RBracket, 1),
            (b'=', b'=') => (T::EqEq, 2),
            (b'=', _) => (T::Eq, 1),
            (b'<', b'>') => (T::NotEq, 2),
            (b'<', b'=') => (T::Le, 2),
            (b'<', _) => (T::Lt, 1),
            (b'>', b'=') => (T::Ge, 2),
            (b'>', _) => (T::Gt, 1),
            (b'!', b'=') => (T::BangEq, 2),
            (b'+', _) => (T::Plus, 1),
            (b'-', _) => (T::Minus, 1),
            (b'*', _) => (T::Star, 1),
            (b'/', _) => (T::Slash, 1),
            _ => {
                // Skip one whole character, which may be several bytes.
                let ch = self
                    .source
                    .get(start..)
                    .and_then(|s| s.chars().next())
                    .unwrap_or('?');
                self.pos += ch.len_utf8();
                let span = Span::new(start, self.pos);
                let diagnostic = Diagnostic::error(
                    span,
                    format!("unexpected character `{}`", ch.escape_debug()),
                );
                self.report(match ch {
                    '{' | '}' => diagnostic.with_hint("blocks are written `begin … end`"),
                    '%' => diagnostic.with_hint("the remainder operator is `mod`"),
                    '&' => diagnostic.with_hint("use `and`"),
                    '|' => diagnostic.with_hint("use `or`"),
                    '!' => diagnostic.with_hint("use `not`"),
                    '\'' => diagnostic.with_hint("strings use double quotes"),
                    _ => diagnostic,
                });
                return;
            }
        };
        self.pos += len;
        self.push(kind, start);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn kinds(src: &str) -> Vec<TokenKind> {
        let (tokens, diagnostics) = tokenize(src);
        assert!(diagnostics.is_empty(), "{diagnostics:?}");
        tokens.iter().map(|t| t.kind).collect()
    }

    #[test]
    fn keywords_ignore_case_and_comments_are_skipped() {
        use TokenKind as T;
        assert_eq!(
            kinds("BEGIN e := v.incidentEdge; // x := y\nEnd"),
            vec![
                T::Begin,
                T::Ident,
                T::Assign,
                T::Ident,
                T::Dot,
                T::Ident,
                T::Semicolon,
                T::End,
                T::Eof
            ]
        );
        assert_eq!(
            kinds("= == <> <= >= < > !="),
            vec![
                T::Eq,
                T::EqEq,
                T::NotEq,
                T::Le,
                T::Ge,
                T::Lt,
                T::Gt,
                T::BangEq,
                T::Eof
            ]
        );
    }

    #[test]
    fn bad_characters_are_reported_and_skipped() {
        let (tokens, diagnostics) = tokenize("x { é \"open");
        assert_eq!(diagnostics.len(), 3);
        assert_eq!(tokens.last().map(|t| t.kind), Some(TokenKind::Eof));
        assert_eq!(
            diagnostics[0].hint.as_deref(),
            Some("blocks are written `begin … end`")
        );
    }
}
