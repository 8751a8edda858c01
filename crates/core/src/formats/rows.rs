//! The parts `.wtb` and `.htb` share: splitting lines into fields with their
//! columns, the header and section lines, row ids, numbers and references,
//! mapping `validate()` issues back to the line and column of their field,
//! and writing aligned tables.
//!
//! A `#` starts a comment that runs to the end of the line; blank lines are
//! ignored. Fields are separated by spaces or tabs.

use std::fmt::Write as _;

use super::error::{FormatError, Location, Problem, shown};
use crate::mesh::VertexId;
use crate::mesh::{Element, Issue};
use crate::schema::{Column, ElementKind, ElementRef, Record, Records, Storage, Structure};

/// The most syntax problems reported before a table file is refused; past
/// that, more of the same helps nobody.
const MAX_PROBLEMS: usize = 50;

/// One field of a row and where it starts.
#[derive(Clone, Copy, Debug)]
pub(super) struct Token<'a> {
    pub text: &'a str,
    /// 1-based, in characters.
    pub column: usize,
}

/// Splits `line` into fields, stopping at a `#`.
pub(super) fn tokenize<'a>(line: &'a str, out: &mut Vec<Token<'a>>) {
    out.clear();
    let content = line.split_once('#').map_or(line, |(before, _)| before);
    let mut start = None;
    let mut column = 0;
    let mut start_column = 0;
    for (offset, ch) in content.char_indices() {
        column += 1;
        if ch == ' ' || ch == '\t' || ch == '\r' {
            if let Some(from) = start.take() {
                out.push(Token {
                    text: &content[from..offset],
                    column: start_column,
                });
            }
        } else if start.is_none() {
            start = Some(offset);
            start_column = column;
        }
    }
    if let Some(from) = start {
        out.push(Token {
            text: &content[from..],
            column: start_column,
        });
    }
}

/// The fields of the table rows, one per line, with their line numbers.
pub(super) struct Rows<'a> {
    text: &'a str,
    lines: std::str::Split<'a, char>,
    /// Line number of the last row returned.
    pub line: usize,
    /// Byte offset of the start of the last row returned.
    pub offset: usize,
    next_offset: usize,
    next_line: usize,
    pub tokens: Vec<Token<'a>>,
}

impl<'a> Rows<'a> {
    pub fn new(text: &'a str) -> Self {
        Self {
            text,
            lines: text.split('\n'),
            line: 0,
            offset: 0,
            next_offset: 0,
            next_line: 1,
            tokens: Vec::with_capacity(12),
        }
    }

    /// Moves to the next line holding fields; false at the end of the text.
    pub fn advance(&mut self) -> bool {
        for line in self.lines.by_ref() {
            let (number, offset) = (self.next_line, self.next_offset);
            self.next_line += 1;
            self.next_offset += line.len() + 1;
            tokenize(line, &mut self.tokens);
            if !self.tokens.is_empty() {
                self.line = number;
                self.offset = offset;
                return true;
            }
        }
        self.line = self.next_line.saturating_sub(1).max(1);
        self.tokens.clear();
        false
    }

    /// The remaining bytes, to bound preallocation by what can follow.
    pub fn remaining(&self) -> usize {
        self.text.len().saturating_sub(self.next_offset)
    }

    /// The location of field `index` of the current row (or of the line).
    pub fn at(&self, index: usize) -> Location {
        match self.tokens.get(index) {
            Some(token) => Location::at(self.line, token.column),
            None => Location::line(self.line),
        }
    }

    /// The current row as it reads, shortened for messages.
    pub fn quoted(&self) -> String {
        let words: Vec<String> = self
            .tokens
            .iter()
            .take(4)
            .map(|t| shown(t.text.as_bytes()))
            .collect();
        let mut text = words.join(" ");
        if self.tokens.len() > 4 {
            text.push_str(" …");
        }
        format!("\"{text}\"")
    }
}

/// Reads `magic 1`, the first line that holds fields.
pub(super) fn header(rows: &mut Rows<'_>, magic: &str, other: &str) -> Result<(), FormatError> {
    let expected = format!("the header \"{magic} 1\"");
    if !rows.advance() {
        return Err(FormatError::new(
            Location::line(rows.line),
            format!("the file ends before the header; expected {expected}"),
        ));
    }
    let first = rows.tokens.first().map_or("", |t| t.text);
    if first == other {
        let what = if other == "wtb" {
            "winged-edge tables (wtb)"
        } else {
            "half-edge tables (htb)"
        };
        return Err(FormatError::new(
            rows.at(0),
            format!("this file holds {what}; expected {expected} (check the file's extension)"),
        ));
    }
    if first != magic {
        return Err(FormatError::new(
            rows.at(0),
            format!("expected {expected}, found {}", rows.quoted()),
        ));
    }
    match rows.tokens.get(1).map(|t| t.text) {
        Some("1") if rows.tokens.len() == 2 => Ok(()),
        Some("1") => Err(FormatError::new(
            rows.at(2),
            format!("expected only {expected} on this line"),
        )),
        Some(version) => Err(FormatError::new(
            rows.at(1),
            format!("version {version} is not supported; this reader reads {magic} 1"),
        )),
        None => Err(FormatError::new(
            Location::line(rows.line),
            format!("expected {expected}: the version number is missing"),
        )),
    }
}

/// A section of a table file: `name <count>` followed by `count` rows.
pub(super) struct Section {
    /// The section keyword (`vertices`).
    pub name: &'static str,
    /// The element in messages (`vertex`).
    pub element: &'static str,
    /// The table whose stored columns the rows hold.
    pub table: (Structure, ElementKind),
}

impl Section {
    /// The column names after the id.
    pub fn columns(&self) -> Vec<&'static str> {
        let (structure, kind) = self.table;
        Column::file_columns(structure, kind)
    }

    fn column_list(&self) -> String {
        let mut list = String::from("id");
        for column in self.columns() {
            list.push(' ');
            list.push_str(column);
        }
        list
    }
}

/// Where each row of a table is, to place its issues.
#[derive(Debug, Default)]
pub(super) struct RowPlaces {
    /// Line number and byte offset of each row's line.
    rows: Vec<(usize, usize)>,
}

impl RowPlaces {
    fn line(&self, row: usize) -> Option<(usize, usize)> {
        self.rows.get(row).copied()
    }
}

/// Collects syntax problems across rows, up to [`MAX_PROBLEMS`].
pub(super) struct Problems(Vec<Problem>);

impl Problems {
    pub fn new() -> Self {
        Self(Vec::new())
    }

    pub fn push(&mut self, location: Location, message: String) {
        if self.0.len() < MAX_PROBLEMS {
            self.0.push(Problem::new(location, message));
        }
    }

    pub fn finish(self) -> Result<(), FormatError> {
        if self.0.is_empty() {
            Ok(())
        } else {
            Err(FormatError::from_problems(self.0))
        }
    }
}

/// Reads `section`'s header line and its rows, calling `row` with the fields
/// after the id of each row whose shape is right. Row problems are collected
/// in `problems` (so one bad number does not hide the next); a wrong count or
/// a missing section ends the reading at once.
pub(super) fn section<'a>(
    rows: &mut Rows<'a>,
    section: &Section,
    problems: &mut Problems,
    mut row: impl FnMut(&[Token<'a>], usize, &mut Problems),
) -> Result<RowPlaces, FormatError> {
    let expected = format!("\"{} <count>\"", section.name);
    if !rows.advance() {
        return Err(FormatError::new(
            Location::line(rows.line),
            format!("the file ends here; expected {expected}"),
        ));
    }
    if rows.tokens.first().map(|t| t.text) != Some(section.name) {
        return Err(FormatError::new(
            rows.at(0),
            format!("expected {expected}, found {}", rows.quoted()),
        ));
    }
    let count = match rows.tokens.get(1) {
        None => {
            return Err(FormatError::new(
                Location::line(rows.line),
                format!("expected {expected}: the count is missing"),
            ));
        }
        Some(token) => token.text.parse::<u32>().map_err(|_| {
            FormatError::new(
                rows.at(1),
                format!(
                    "expected the number of {} (0 to {}), found \"{}\"",
                    section.name,
                    u32::MAX,
                    shown(token.text.as_bytes())
                ),
            )
        })?,
    };
    if rows.tokens.len() > 2 {
        return Err(FormatError::new(
            rows.at(2),
            format!("expected only {expected} on this line"),
        ));
    }
    let announced = rows.line;
    let count = count as usize;
    // Every row takes at least two bytes per field, so a count the rest of
    // the file cannot hold is caught before anything is reserved.
    let fields = section.columns().len() + 1;
    let most = rows.remaining() / (2 * fields);
    let mut places = RowPlaces {
        rows: Vec::with_capacity(count.min(most)),
    };
    for index in 0..count {
        if !rows.advance() {
            return Err(FormatError::new(
                Location::line(rows.line),
                format!(
                    "the file ends after {index} of the {count} {} announced on line {announced}",
                    section.name
                ),
            ));
        }
        let first = rows.tokens.first().map_or("", |t| t.text);
        if first.starts_with(|c: char| c.is_ascii_alphabetic()) && first != "-" {
            return Err(FormatError::new(
                rows.at(0),
                format!(
                    "expected {} {index} (line {announced} announces {count} {}), found {}",
                    section.element,
                    section.name,
                    rows.quoted()
                ),
            ));
        }
        places.rows.push((rows.line, rows.offset));
        if rows.tokens.len() != fields {
            problems.push(
                Location::line(rows.line),
                format!(
                    "a {} row has {} fields ({}), found {}",
                    section.element,
                    fields,
                    section.column_list(),
                    rows.tokens.len()
                ),
            );
            continue;
        }
        let id = rows.tokens.first().map_or("", |t| t.text);
        if id.parse::<usize>().ok() != Some(index) {
            problems.push(
                rows.at(0),
                format!(
                    "expected the id {index} here, found \"{}\"; rows are numbered from 0 in order",
                    shown(id.as_bytes())
                ),
            );
            continue;
        }
        row(rows.tokens.get(1..).unwrap_or(&[]), rows.line, problems);
    }
    Ok(places)
}

/// After the last section: anything more is an error.
pub(super) fn end(rows: &mut Rows<'_>, last: &Section, count: usize) -> Result<(), FormatError> {
    if rows.advance() {
        return Err(FormatError::new(
            rows.at(0),
            format!(
                "expected the end of the file after {count} {}, found {}; is a count too small?",
                last.name,
                rows.quoted()
            ),
        ));
    }
    Ok(())
}

/// A coordinate: a finite decimal number.
pub(super) fn coordinate(
    token: &Token<'_>,
    name: &str,
    line: usize,
    problems: &mut Problems,
) -> f32 {
    match token.text.parse::<f32>() {
        Ok(value) if value.is_finite() && is_decimal(token.text) => value,
        Ok(_) | Err(_) => {
            problems.push(
                Location::at(line, token.column),
                format!(
                    "expected a finite number for {name}, found \"{}\"",
                    shown(token.text.as_bytes())
                ),
            );
            0.0
        }
    }
}

/// Whether a number is written in decimal digits (Rust's parser also takes
/// `nan`, `inf` and `infinity`, which are no coordinates).
pub(super) fn is_decimal(text: &str) -> bool {
    text.bytes()
        .all(|b| b.is_ascii_digit() || matches!(b, b'.' | b'-' | b'+' | b'e' | b'E'))
}

/// Reads the stored references of one row into `record`, column by column
/// in file order, after the coordinates if the table has them.
pub(super) fn fill<R: Record>(
    record: &mut R,
    fields: &[Token<'_>],
    section: &Section,
    line: usize,
    problems: &mut Problems,
) {
    let (structure, kind) = section.table;
    let mut tokens = fields.iter();
    for entry in Column::table(structure, kind) {
        if entry.storage == Storage::Derived {
            continue;
        }
        if entry.column == Column::Position {
            tokens.nth(Column::COORDINATES.len() - 1);
            continue;
        }
        let Some(token) = tokens.next() else {
            return;
        };
        let column = entry.column;
        let what = match column.target() {
            Some(ElementKind::Vertex) => "a vertex",
            Some(ElementKind::Face) => "a face",
            _ if structure == Structure::HalfEdge => "a half-edge",
            _ => "an edge",
        };
        let value = reference(
            token,
            column.record_name(),
            what,
            column.nullable_in(kind),
            line,
            problems,
        );
        record.set(column, value);
    }
}

/// A reference to a row: a number, or `-` where the column allows "none".
pub(super) fn reference(
    token: &Token<'_>,
    name: &str,
    what: &str,
    optional: bool,
    line: usize,
    problems: &mut Problems,
) -> Option<u32> {
    if token.text == "-" {
        if !optional {
            problems.push(
                Location::at(line, token.column),
                format!("{name} cannot be \"-\"; expected {what} number"),
            );
        }
        return None;
    }
    match token.text.parse::<u32>() {
        Ok(value) => Some(value),
        Err(_) => {
            let or_none = if optional { " or \"-\"" } else { "" };
            problems.push(
                Location::at(line, token.column),
                format!(
                    "expected {what} number{or_none} for {name}, found \"{}\"",
                    shown(token.text.as_bytes())
                ),
            );
            None
        }
    }
}

/// The position of a column in its file row (the id is field 0).
fn field_index(element: Element, column: Column) -> usize {
    let (structure, kind) = match element {
        Element::Vertex(_) => (Structure::WingedEdge, ElementKind::Vertex),
        Element::Face(_) => (Structure::WingedEdge, ElementKind::Face),
        Element::Edge(_) => (Structure::WingedEdge, ElementKind::Edge),
        Element::HalfEdge(_) => (Structure::HalfEdge, ElementKind::Edge),
    };
    let first = match column {
        Column::Position => Column::COORDINATES[0],
        other => other.record_name(),
    };
    Column::file_columns(structure, kind)
        .iter()
        .position(|&name| name == first)
        .map_or(1, |index| index + 1)
}

/// The validation issues of a table file, placed at the line of the row and
/// the column of the field, in file order.
pub(super) fn place_issues<'p>(
    issues: Vec<Issue>,
    text: &str,
    places: impl Fn(Element) -> Option<&'p RowPlaces>,
) -> FormatError {
    let mut tokens = Vec::new();
    let mut problems: Vec<Problem> = issues
        .into_iter()
        .map(|issue| {
            let index = match issue.element {
                Element::Vertex(id) => id.index(),
                Element::Edge(id) => id.index(),
                Element::HalfEdge(id) => id.index(),
                Element::Face(id) => id.index(),
            };
            let row = places(issue.element).and_then(|rows| rows.line(index));
            let location = match row {
                Some((line, offset)) => {
                    let row = text.get(offset..).unwrap_or("");
                    tokenize(row.split('\n').next().unwrap_or(""), &mut tokens);
                    match tokens.get(field_index(issue.element, issue.field)) {
                        Some(token) => Location::at(line, token.column),
                        None => Location::line(line),
                    }
                }
                None => Location::File,
            };
            Problem::new(location, issue.to_string())
        })
        .collect();
    problems.sort_by_key(|problem| problem.location);
    FormatError::from_problems(problems)
}

/// Writes one section of a table file: its `name <count>` line, then each
/// row's id, coordinates (for vertices) and stored references.
pub(super) fn write_section(out: &mut String, mesh: &impl Records, section: &Section) {
    let (structure, kind) = section.table;
    let stored: Vec<Column> = Column::table(structure, kind)
        .iter()
        .filter(|entry| entry.storage == Storage::Stored)
        .map(|entry| entry.column)
        .collect();
    let rows: Vec<Vec<String>> = (0..mesh.count(kind))
        .map(|index| {
            let id = u32::try_from(index).unwrap_or(u32::MAX);
            let element = ElementRef::new(kind, id);
            let mut row = vec![id.to_string()];
            for &column in &stored {
                if column == Column::Position {
                    let p = mesh.position(VertexId::new(id)).unwrap_or_default();
                    row.extend([p.x, p.y, p.z].map(|c| c.to_string()));
                } else {
                    let target = mesh.reference(element, column).ok().flatten();
                    row.push(cell(target.map(|t| t.id)));
                }
            }
            row
        })
        .collect();
    out.push_str(&format!("\n{} {}\n", section.name, rows.len()));
    let mut columns = vec!["id"];
    columns.extend(section.columns());
    write_table(out, &columns, &rows);
}

/// Writes rows as columns padded to a common width, under a comment line
/// naming the columns.
pub(super) fn write_table(out: &mut String, columns: &[&str], rows: &[Vec<String>]) {
    let mut widths: Vec<usize> = columns.iter().map(|c| c.len()).collect();
    if let Some(first) = widths.first_mut() {
        // The header line starts with "# ", which the first column absorbs.
        *first += 2;
    }
    for row in rows {
        for (width, cell) in widths.iter_mut().zip(row) {
            *width = (*width).max(cell.len());
        }
    }
    let mut line = String::new();
    let mut push_line = |out: &mut String, cells: &mut dyn Iterator<Item = &str>| {
        line.clear();
        for (i, (cell, &width)) in cells.zip(&widths).enumerate() {
            if i > 0 {
                line.push_str("  ");
            }
            let _ = write!(line, "{cell:>width$}");
        }
        out.push_str(line.trim_end());
        out.push('\n');
    };
    let header: Vec<String> = columns
        .iter()
        .enumerate()
        .map(|(i, c)| {
            if i == 0 {
                format!("# {c}")
            } else {
                (*c).to_owned()
            }
        })
        .collect();
    // Left-align the comment marker: pad the first header cell on the right.
    let mut header_cells: Vec<String> = header;
    if let (Some(first), Some(&width)) = (header_cells.first_mut(), widths.first()) {
        *first = format!("{first:<width$}");
    }
    push_line(out, &mut header_cells.iter().map(String::as_str));
    for row in rows {
        push_line(out, &mut row.iter().map(String::as_str));
    }
}

/// A reference cell: the number, or `-` for none.
pub(super) fn cell(value: Option<u32>) -> String {
    value.map_or_else(|| "-".to_owned(), |v| v.to_string())
}
