//! Source spans, line/column mapping, and compiler-style error rendering.
//!
//! Every error the language reports points at a byte range of the source, so a
//! student sees the exact token at fault, with a caret under it, the way
//! rustc and starlark render theirs.

use std::fmt;

/// After this many errors reading stops (the lexer, the parser and the
/// checker each): more would bury the first ones, and a hostile file could
/// otherwise make the report grow without end.
pub const MAX_ERRORS: usize = 100;

/// A byte range `start..end` in one source text.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Span {
    pub start: u32,
    pub end: u32,
}

impl Span {
    pub fn new(start: usize, end: usize) -> Self {
        Self {
            start: saturating_u32(start),
            end: saturating_u32(end.max(start)),
        }
    }

    /// The smallest span covering both.
    #[must_use]
    pub fn to(self, other: Span) -> Span {
        Span {
            start: self.start.min(other.start),
            end: self.end.max(other.end),
        }
    }

    /// An empty span at this span's end, for "expected `;` here" messages.
    #[must_use]
    pub fn after(self) -> Span {
        Span {
            start: self.end,
            end: self.end,
        }
    }

    pub fn range(self) -> std::ops::Range<usize> {
        self.start as usize..self.end as usize
    }

    /// The source text under the span, or "" if the span does not fit.
    pub fn text(self, source: &str) -> &str {
        source.get(self.range()).unwrap_or("")
    }
}

fn saturating_u32(n: usize) -> u32 {
    u32::try_from(n).unwrap_or(u32::MAX)
}

/// A 1-based line and column (counted in characters) of a byte offset.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub struct LineColumn {
    pub line: u32,
    pub column: u32,
}

/// Maps byte offsets to lines; built once per source text.
#[derive(Clone, Debug)]
pub struct LineIndex {
    line_starts: Vec<u32>,
}

impl LineIndex {
    pub fn new(source: &str) -> Self {
        let mut line_starts = vec![0];
        for (i, b) in source.bytes().enumerate() {
            if b == b'\n' {
                line_starts.push(saturating_u32(i + 1));
            }
        }
        Self { line_starts }
    }

    /// The 1-based line holding byte `offset`.
    pub fn line(&self, offset: u32) -> u32 {
        let index = self.line_starts.partition_point(|&start| start <= offset);
        saturating_u32(index.max(1))
    }

    pub fn line_column(&self, source: &str, offset: u32) -> LineColumn {
        let line = self.line(offset);
        let start = self.line_start(line);
        let end = (offset as usize).min(source.len());
        let column = source.get(start..end).map_or(0, |s| s.chars().count());
        LineColumn {
            line,
            column: saturating_u32(column + 1),
        }
    }

    fn line_start(&self, line: u32) -> usize {
        self.line_starts
            .get(line.saturating_sub(1) as usize)
            .map_or(0, |&s| s as usize)
    }

    /// The text of a 1-based line, without its line break.
    pub fn line_text<'s>(&self, source: &'s str, line: u32) -> &'s str {
        let start = self.line_start(line).min(source.len());
        let rest = source.get(start..).unwrap_or("");
        let text = rest.split('\n').next().unwrap_or("");
        text.strip_suffix('\r').unwrap_or(text)
    }

    pub fn line_count(&self) -> u32 {
        saturating_u32(self.line_starts.len())
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Severity {
    Error,
    Warning,
}

/// One problem found in a source text.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Diagnostic {
    pub severity: Severity,
    pub span: Span,
    pub message: String,
    /// A suggestion shown under the caret, such as "did you mean `:=`?".
    pub hint: Option<String>,
}

impl Diagnostic {
    pub fn error(span: Span, message: impl Into<String>) -> Self {
        Self {
            severity: Severity::Error,
            span,
            message: message.into(),
            hint: None,
        }
    }

    pub fn warning(span: Span, message: impl Into<String>) -> Self {
        Self {
            severity: Severity::Warning,
            span,
            message: message.into(),
            hint: None,
        }
    }

    #[must_use]
    pub fn with_hint(mut self, hint: impl Into<String>) -> Self {
        self.hint = Some(hint.into());
        self
    }

    pub fn is_error(&self) -> bool {
        self.severity == Severity::Error
    }

    /// Renders `file:line:column: error: message`, the source line, a caret
    /// line under the span, and the hint if there is one.
    pub fn render(&self, source: &str, file: Option<&str>) -> String {
        self.render_with(&LineIndex::new(source), source, file)
    }

    pub fn render_with(&self, index: &LineIndex, source: &str, file: Option<&str>) -> String {
        let start = index.line_column(source, self.span.start);
        let line_text = index.line_text(source, start.line);
        let severity = match self.severity {
            Severity::Error => "error",
            Severity::Warning => "warning",
        };
        let mut out = String::new();
        if let Some(file) = file {
            out.push_str(file);
            out.push(':');
        }
        out.push_str(&format!(
            "{}:{}: {severity}: {}\n",
            start.line, start.column, self.message
        ));
        let gutter = start.line.to_string();
        let pad = " ".repeat(gutter.len());
        let (shown, caret_from, caret_len) =
            clip_long_line(caret_layout(line_text, start.column, self.span, source));
        out.push_str(&format!("{pad} |\n{gutter} | {shown}\n"));
        out.push_str(&format!(
            "{pad} | {}{}\n",
            " ".repeat(caret_from),
            "^".repeat(caret_len)
        ));
        if let Some(hint) = &self.hint {
            out.push_str(&format!("{pad} = hint: {hint}\n"));
        }
        out
    }
}

/// Expands tabs (so the caret lines up in any terminal) and works out where
/// the caret goes and how long it is; a span running past the line is cut at
/// the line's end, an empty span gets one caret.
fn caret_layout(line: &str, column: u32, span: Span, source: &str) -> (String, usize, usize) {
    let mut shown = String::new();
    let mut display_col = Vec::with_capacity(line.len() + 1);
    let mut width = 0;
    for ch in line.chars() {
        display_col.push(width);
        if ch == '\t' {
            shown.push_str("    ");
            width += 4;
        } else {
            // Other control characters (a NUL in a pasted file) as their
            // visible pictures, one column wide: ␀ ␁ … ␟.
            shown.push(if ch < ' ' {
                char::from_u32(0x2400 + u32::from(ch)).unwrap_or('?')
            } else {
                ch
            });
            width += 1;
        }
    }
    let line_width = width;
    display_col.push(line_width);
    let first = (column as usize).saturating_sub(1);
    let span_chars = span
        .text(source)
        .split('\n')
        .next()
        .unwrap_or("")
        .chars()
        .count();
    let last = (first + span_chars).min(display_col.len() - 1);
    let from = display_col.get(first).copied().unwrap_or(line_width);
    let to = display_col.get(last).copied().unwrap_or(line_width);
    (shown, from, to.saturating_sub(from).max(1))
}

/// `text` cut to `max` characters with `…`, for quoting user text in a message.
pub fn shorten(text: &str, max: usize) -> std::borrow::Cow<'_, str> {
    match text.char_indices().nth(max) {
        Some((cut, _)) => format!("{}…", &text[..cut]).into(),
        None => text.into(),
    }
}

/// The widest source line shown under a message, in characters.
const MAX_SHOWN_LINE: usize = 120;

/// Shows only a window of a very long line, around the caret and marked `…`
/// where cut, so that a message about a 1 MB line stays readable.
fn clip_long_line((shown, from, len): (String, usize, usize)) -> (String, usize, usize) {
    let chars: Vec<char> = shown.chars().collect();
    if chars.len() <= MAX_SHOWN_LINE {
        return (shown, from, len);
    }
    let start = from
        .saturating_sub(MAX_SHOWN_LINE / 3)
        .min(chars.len() - MAX_SHOWN_LINE);
    let end = start + MAX_SHOWN_LINE;
    let mut clipped = String::new();
    let mut caret = from.saturating_sub(start);
    if start > 0 {
        clipped.push('…');
        caret += 1;
    }
    clipped.extend(chars.get(start..end).unwrap_or(&[]));
    if end < chars.len() {
        clipped.push('…');
    }
    (clipped, caret, len.min(end.saturating_sub(from)).max(1))
}

impl fmt::Display for Diagnostic {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.message)
    }
}

/// Renders every diagnostic, in source order, separated by blank lines.
pub fn render_all(diagnostics: &[Diagnostic], source: &str, file: Option<&str>) -> String {
    let index = LineIndex::new(source);
    let mut sorted: Vec<&Diagnostic> = diagnostics.iter().collect();
    sorted.sort_by_key(|d| (d.span.start, d.span.end));
    let rendered: Vec<String> = sorted
        .iter()
        .map(|d| d.render_with(&index, source, file))
        .collect();
    rendered.join("\n")
}

/// Levenshtein distance, ignoring ASCII case, for "did you mean" hints.
pub fn edit_distance(a: &str, b: &str) -> usize {
    let a: Vec<char> = a.chars().map(|c| c.to_ascii_lowercase()).collect();
    let b: Vec<char> = b.chars().map(|c| c.to_ascii_lowercase()).collect();
    let mut previous: Vec<usize> = (0..=b.len()).collect();
    let mut current = vec![0; b.len() + 1];
    for (i, ca) in a.iter().enumerate() {
        current[0] = i + 1;
        for (j, cb) in b.iter().enumerate() {
            let substitution = previous[j] + usize::from(ca != cb);
            current[j + 1] = substitution.min(previous[j + 1] + 1).min(current[j] + 1);
        }
        std::mem::swap(&mut previous, &mut current);
    }
    previous[b.len()]
}

/// The candidate nearest to `word`, if it is near enough to be a likely typo.
pub fn nearest<'a>(word: &str, candidates: impl IntoIterator<Item = &'a str>) -> Option<&'a str> {
    let length = word.chars().count();
    let limit = (length / 3).max(2);
    candidates
        .into_iter()
        // The distance is at least the difference in length: skipping those
        // keeps a very long name from costing its length squared.
        .filter(|c| c.chars().count().abs_diff(length) <= limit)
        .map(|c| (edit_distance(word, c), c))
        .filter(|&(d, _)| d <= limit)
        .min_by_key(|&(d, _)| d)
        .map(|(_, c)| c)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn line_and_column_count_characters() {
        let src = "ab\ncé d\n";
        let index = LineIndex::new(src);
        let offset = src.find('d').unwrap() as u32;
        assert_eq!(
            index.line_column(src, offset),
            LineColumn { line: 2, column: 4 }
        );
        assert_eq!(index.line_text(src, 2), "cé d");
    }

    #[test]
    fn render_puts_caret_under_span() {
        let src = "begin\n\tx = 1\nend";
        let start = src.find('=').unwrap();
        let d =
            Diagnostic::error(Span::new(start, start + 1), "bad").with_hint("did you mean `:=`?");
        assert_eq!(
            d.render(src, Some("a.alg")),
            "a.alg:2:4: error: bad\n  |\n2 |     x = 1\n  |       ^\n  = hint: did you mean `:=`?\n"
        );
    }

    #[test]
    fn nearest_finds_typos_only() {
        let names = ["startVertex", "endVertex", "leftFace"];
        assert_eq!(nearest("startVertx", names), Some("startVertex"));
        assert_eq!(nearest("StartVertex", names), Some("startVertex"));
        assert_eq!(nearest("banana", names), None);
        assert_eq!(edit_distance("kitten", "sitting"), 3);
    }
}
