//! Tokens of the algorithm language.

use super::diagnostic::Span;
use std::fmt;

/// A token's kind. Keywords are matched without regard to case; type,
/// structure and lookup names are ordinary identifiers, resolved later, so a
/// misspelling of one of them can be answered with the nearest name.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum TokenKind {
    Ident,
    Integer,
    Float,
    String,
    // Keywords.
    Algorithm,
    StructureType,
    Description,
    Var,
    Begin,
    End,
    If,
    Then,
    Else,
    While,
    Do,
    Break,
    Continue,
    Mark,
    Highlight,
    Message,
    And,
    Or,
    Not,
    Div,
    Mod,
    True,
    False,
    Null,
    New,
    Delete,
    Refuse,
    Return,
    Returns,
    Of,
    // Punctuation and operators.
    /// `:=`
    Assign,
    Colon,
    Semicolon,
    Comma,
    Dot,
    LParen,
    RParen,
    LBracket,
    RBracket,
    /// `=`
    Eq,
    /// `==`, the half-edge paper's spelling of `=`.
    EqEq,
    /// `<>`
    NotEq,
    /// `!=`: not part of the language, lexed so the parser can suggest `<>`.
    BangEq,
    Lt,
    Le,
    Gt,
    Ge,
    Plus,
    Minus,
    Star,
    Slash,
    Eof,
}

/// Keywords with their canonical spelling; lookup is case-insensitive.
pub const KEYWORDS: &[(&str, TokenKind)] = &[
    ("algorithm", TokenKind::Algorithm),
    ("structuretype", TokenKind::StructureType),
    ("description", TokenKind::Description),
    ("var", TokenKind::Var),
    ("begin", TokenKind::Begin),
    ("end", TokenKind::End),
    ("if", TokenKind::If),
    ("then", TokenKind::Then),
    ("else", TokenKind::Else),
    ("while", TokenKind::While),
    ("do", TokenKind::Do),
    ("break", TokenKind::Break),
    ("continue", TokenKind::Continue),
    ("mark", TokenKind::Mark),
    ("highlight", TokenKind::Highlight),
    ("message", TokenKind::Message),
    ("and", TokenKind::And),
    ("or", TokenKind::Or),
    ("not", TokenKind::Not),
    ("div", TokenKind::Div),
    ("mod", TokenKind::Mod),
    ("true", TokenKind::True),
    ("false", TokenKind::False),
    ("null", TokenKind::Null),
    ("new", TokenKind::New),
    ("delete", TokenKind::Delete),
    ("refuse", TokenKind::Refuse),
    ("return", TokenKind::Return),
    ("returns", TokenKind::Returns),
    ("of", TokenKind::Of),
];

impl TokenKind {
    pub fn keyword(word: &str) -> Option<TokenKind> {
        KEYWORDS
            .iter()
            .find(|(k, _)| k.eq_ignore_ascii_case(word))
            .map(|&(_, kind)| kind)
    }

    pub fn is_keyword(self) -> bool {
        KEYWORDS.iter().any(|&(_, k)| k == self)
    }

    /// How the token is named in "expected …, found …" messages.
    pub fn describe(self) -> &'static str {
        use TokenKind as T;
        if let Some((word, _)) = KEYWORDS.iter().find(|&&(_, k)| k == self) {
            return word;
        }
        match self {
            T::Ident => "a name",
            T::Integer => "a number",
            T::Float => "a Float number",
            T::String => "a string",
            T::Assign => ":=",
            T::Colon => ":",
            T::Semicolon => ";",
            T::Comma => ",",
            T::Dot => ".",
            T::LParen => "(",
            T::RParen => ")",
            T::LBracket => "[",
            T::RBracket => "]",
            T::Eq => "=",
            T::EqEq => "==",
            T::NotEq => "<>",
            T::BangEq => "!=",
            T::Lt => "<",
            T::Le => "<=",
            T::Gt => ">",
            T::Ge => ">=",
            T::Plus => "+",
            T::Minus => "-",
            T::Star => "*",
            T::Slash => "/",
            _ => "end of file",
        }
    }
}

impl fmt::Display for TokenKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            TokenKind::Ident
            | TokenKind::Integer
            | TokenKind::Float
            | TokenKind::String
            | TokenKind::Eof => f.write_str(self.describe()),
            _ => write!(f, "`{}`", self.describe()),
        }
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Token {
    pub kind: TokenKind,
    pub span: Span,
}
