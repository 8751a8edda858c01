//! Rust source as the tidy checks need it: identifiers, string literals and
//! punctuation with their lines; comments, numbers, characters and
//! lifetimes dropped.

#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Token {
    Ident(String),
    /// A string literal's text, escapes left as written.
    Str(String),
    /// `::`
    PathSep,
    Punct(char),
}

/// The tokens of `text`, each with its 1-based line.
pub fn tokens(text: &str) -> Vec<(Token, u32)> {
    let chars: Vec<char> = text.chars().collect();
    let mut out = Vec::new();
    let mut line = 1;
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        let next = chars.get(i + 1).copied();
        match c {
            '\n' => {
                line += 1;
                i += 1;
            }
            _ if c.is_whitespace() => i += 1,
            '/' if next == Some('/') => {
                while i < chars.len() && chars[i] != '\n' {
                    i += 1;
                }
            }
            '/' if next == Some('*') => {
                let mut depth = 0;
                while i < chars.len() {
                    if chars[i] == '/' && chars.get(i + 1) == Some(&'*') {
                        depth += 1;
                        i += 2;
                    } else if chars[i] == '*' && chars.get(i + 1) == Some(&'/') {
                        depth -= 1;
                        i += 2;
                        if depth == 0 {
                            break;
                        }
                    } else {
                        line += u32::from(chars[i] == '\n');
                        i += 1;
                    }
                }
            }
            '"' => {
                let start_line = line;
                let (text, end) = quoted(&chars, i + 1, &mut line);
                out.push((Token::Str(text), start_line));
                i = end;
            }
            'r' | 'b' | 'c' if raw_string_start(&chars, i).is_some() => {
                let (hashes, open) = raw_string_start(&chars, i).unwrap_or((0, i));
                let start_line = line;
                let mut j = open + 1;
                let mut text = String::new();
                while j < chars.len() {
                    if chars[j] == '"' && (0..hashes).all(|k| chars.get(j + 1 + k) == Some(&'#')) {
                        j += 1 + hashes;
                        break;
                    }
                    line += u32::from(chars[j] == '\n');
                    text.push(chars[j]);
                    j += 1;
                }
                out.push((Token::Str(text), start_line));
                i = j;
            }
            '\'' => i = after_quote(&chars, i),
            ':' if next == Some(':') => {
                out.push((Token::PathSep, line));
                i += 2;
            }
            _ if c.is_alphabetic() || c == '_' => {
                let start = i;
                while i < chars.len() && (chars[i].is_alphanumeric() || chars[i] == '_') {
                    i += 1;
                }
                out.push((Token::Ident(chars[start..i].iter().collect()), line));
            }
            _ if c.is_ascii_digit() => {
                while i < chars.len() && (chars[i].is_alphanumeric() || chars[i] == '_') {
                    i += 1;
                }
            }
            _ => {
                out.push((Token::Punct(c), line));
                i += 1;
            }
        }
    }
    out
}

/// The token ranges of the `#[cfg(test)] mod NAME { … }` blocks: code
/// that may spell out what the rest must not, to check it.
pub fn test_modules(tokens: &[(Token, u32)]) -> Vec<std::ops::Range<usize>> {
    let ident =
        |i: usize, word: &str| matches!(tokens.get(i), Some((Token::Ident(w), _)) if w == word);
    let punct = |i: usize, c: char| matches!(tokens.get(i), Some((Token::Punct(p), _)) if *p == c);
    let mut ranges = Vec::new();
    for i in 0..tokens.len() {
        let attribute = punct(i, '#')
            && punct(i + 1, '[')
            && ident(i + 2, "cfg")
            && punct(i + 3, '(')
            && ident(i + 4, "test")
            && punct(i + 5, ')')
            && punct(i + 6, ']');
        if !(attribute && ident(i + 7, "mod") && punct(i + 9, '{')) {
            continue;
        }
        let mut depth = 0usize;
        for (j, (token, _)) in tokens.iter().enumerate().skip(i + 9) {
            match token {
                Token::Punct('{') => depth += 1,
                Token::Punct('}') => {
                    depth -= 1;
                    if depth == 0 {
                        ranges.push(i..j + 1);
                        break;
                    }
                }
                _ => {}
            }
        }
    }
    ranges
}

/// A quoted string's text from `start` (after the `"`), and the index after
/// its closing quote.
fn quoted(chars: &[char], start: usize, line: &mut u32) -> (String, usize) {
    let mut text = String::new();
    let mut j = start;
    while j < chars.len() {
        match chars[j] {
            '\\' => {
                text.push('\\');
                if let Some(&escaped) = chars.get(j + 1) {
                    *line += u32::from(escaped == '\n');
                    text.push(escaped);
                }
                j += 2;
            }
            '"' => return (text, j + 1),
            c => {
                *line += u32::from(c == '\n');
                text.push(c);
                j += 1;
            }
        }
    }
    (text, j)
}

/// For `r"`, `r#"`, `br"` and `cr#"`: the number of `#`s and the index of
/// the opening quote. A byte string `b"…"` counts as a raw one with no `#`,
/// close enough for these checks.
fn raw_string_start(chars: &[char], i: usize) -> Option<(usize, usize)> {
    if i > 0 && (chars[i - 1].is_alphanumeric() || chars[i - 1] == '_') {
        return None;
    }
    let mut j = i;
    if matches!(chars[j], 'b' | 'c') {
        j += 1;
    }
    if chars.get(j) == Some(&'r') {
        j += 1;
    } else if j == i || chars.get(j) != Some(&'"') {
        return None;
    }
    let mut hashes = 0;
    while chars.get(j) == Some(&'#') {
        hashes += 1;
        j += 1;
    }
    (chars.get(j) == Some(&'"')).then_some((hashes, j))
}

/// The index after a character literal or a lifetime starting at `i`.
fn after_quote(chars: &[char], i: usize) -> usize {
    match (chars.get(i + 1), chars.get(i + 2)) {
        (Some('\\'), _) => {
            let mut j = i + 2;
            while j < chars.len() && chars[j] != '\'' {
                j += 1;
            }
            j + 1
        }
        (Some(_), Some('\'')) => i + 3,
        _ => i + 1,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn kinds(text: &str) -> Vec<Token> {
        tokens(text).into_iter().map(|(token, _)| token).collect()
    }

    #[test]
    fn comments_characters_and_lifetimes_are_skipped() {
        let text = "// crate::a\n/* crate::b /* nested */ */ fn f<'a>(c: char) { '{'; '\\''; }";
        let words: Vec<Token> = kinds(text)
            .into_iter()
            .filter(|token| matches!(token, Token::Ident(_)))
            .collect();
        assert_eq!(
            words,
            ["fn", "f", "a", "c", "char"].map(|w| Token::Ident(w.to_owned()))
        );
        let braces = kinds(text).into_iter().filter(|t| *t == Token::Punct('{'));
        assert_eq!(
            braces.count(),
            1,
            "only the body's brace; the character's is skipped"
        );
    }

    #[test]
    fn test_modules_are_found_whole() {
        let found = tokens("fn a() {}\n#[cfg(test)]\nmod tests { fn b() { \"x\"; } }\nfn c() {}");
        let ranges = test_modules(&found);
        assert_eq!(ranges.len(), 1);
        let inside: Vec<&Token> = found[ranges[0].clone()].iter().map(|(t, _)| t).collect();
        assert!(inside.contains(&&Token::Str("x".to_owned())));
        assert_eq!(inside.last(), Some(&&Token::Punct('}')));
        assert_eq!(found[ranges[0].end].0, Token::Ident("fn".to_owned()));
    }

    #[test]
    fn strings_keep_their_text_and_lines() {
        let found = tokens("let a = \"x \\\" y\";\nlet b = r#\"raw \"q\"\"#; br\"z\"");
        let strings: Vec<(Token, u32)> = found
            .into_iter()
            .filter(|(token, _)| matches!(token, Token::Str(_)))
            .collect();
        assert_eq!(
            strings,
            vec![
                (Token::Str("x \\\" y".to_owned()), 1),
                (Token::Str("raw \"q\"".to_owned()), 2),
                (Token::Str("z".to_owned()), 2),
            ]
        );
    }
}
