//! What went wrong while reading a file, and where: every problem carries a
//! place (line and column for text, byte offset for binary data) so the CLI
//! and the app can print compiler-style `file:line:column: message` lines.

use std::fmt;

use crate::mesh::{BuildError, ConvertError, FaceRef};

/// Text from a file as a message quotes it: control characters escaped (a NUL
/// shows as `\0`), bytes that are not UTF-8 as `\xFF`, and cut at 40
/// characters, so that no file can make a message unreadable or huge.
pub(super) fn shown(text: &[u8]) -> String {
    const MAX_CHARS: usize = 40;
    let mut shown = String::new();
    let mut chars = 0;
    for chunk in text.utf8_chunks() {
        for ch in chunk.valid().chars() {
            if chars == MAX_CHARS {
                shown.push('…');
                return shown;
            }
            shown.extend(ch.escape_debug());
            chars += 1;
        }
        for byte in chunk.invalid() {
            if chars == MAX_CHARS {
                shown.push('…');
                return shown;
            }
            shown.push_str(&format!("\\x{byte:02X}"));
            chars += 1;
        }
    }
    shown
}

/// Where in a file a problem is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Location {
    /// The file as a whole (its size, or a mesh-wide property).
    File,
    /// A 1-based line and, when one field is at fault, its 1-based column.
    Line {
        /// The line.
        line: usize,
        /// The column of the field, in characters.
        column: Option<usize>,
    },
    /// A 0-based byte offset into binary data.
    Byte(u64),
}

impl Location {
    /// A whole line.
    pub fn line(line: usize) -> Self {
        Self::Line { line, column: None }
    }

    /// One field of a line.
    pub fn at(line: usize, column: usize) -> Self {
        Self::Line {
            line,
            column: Some(column),
        }
    }

    /// The line, if this is a place in text.
    pub fn line_number(self) -> Option<usize> {
        match self {
            Self::Line { line, .. } => Some(line),
            Self::File | Self::Byte(_) => None,
        }
    }
}

/// One problem (or, in [`super::Loaded::warnings`], one remark) at one place.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Problem {
    /// Where it is.
    pub location: Location,
    /// What is wrong and what was expected, in one line.
    pub message: String,
}

impl Problem {
    /// A problem at `location`.
    pub fn new(location: Location, message: impl Into<String>) -> Self {
        Self {
            location,
            message: message.into(),
        }
    }

    /// The compiler-style line: `file:line:column: message`,
    /// `file:line: message`, `file: byte N: message` or `file: message`.
    pub fn render(&self, file: &str) -> String {
        match self.location {
            Location::File => format!("{file}: {}", self.message),
            Location::Line { line, column: None } => format!("{file}:{line}: {}", self.message),
            Location::Line {
                line,
                column: Some(column),
            } => format!("{file}:{line}:{column}: {}", self.message),
            Location::Byte(offset) => format!("{file}: byte {offset}: {}", self.message),
        }
    }
}

impl fmt::Display for Problem {
    /// Like [`Problem::render`] without a file name: `12:5: message`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.location {
            Location::File => f.write_str(&self.message),
            Location::Line { line, column: None } => write!(f, "{line}: {}", self.message),
            Location::Line {
                line,
                column: Some(column),
            } => write!(f, "{line}:{column}: {}", self.message),
            Location::Byte(offset) => write!(f, "byte {offset}: {}", self.message),
        }
    }
}

/// A file that was refused, with every problem found. A table file lists
/// every violated rule; the other readers stop at the first problem, since
/// what follows a syntax error is rarely meaningful.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct FormatError {
    problems: Vec<Problem>,
}

impl FormatError {
    /// A refusal for one problem.
    pub fn new(location: Location, message: impl Into<String>) -> Self {
        Self {
            problems: vec![Problem::new(location, message)],
        }
    }

    /// A refusal for several problems, in file order. `problems` must not be
    /// empty; an empty list becomes a refusal with no place.
    pub fn from_problems(mut problems: Vec<Problem>) -> Self {
        if problems.is_empty() {
            problems.push(Problem::new(Location::File, "the file was refused"));
        }
        Self { problems }
    }

    /// Every problem, in file order (at least one).
    pub fn problems(&self) -> &[Problem] {
        &self.problems
    }

    /// The first problem.
    pub fn first(&self) -> &Problem {
        // `problems` is never empty (see the constructors), but stay panic-free.
        static NONE: Problem = Problem {
            location: Location::File,
            message: String::new(),
        };
        self.problems.first().unwrap_or(&NONE)
    }

    /// Every problem rendered as `file:line:column: message`, one per line,
    /// each ending in a newline.
    pub fn render(&self, file: &str) -> String {
        let mut out = String::new();
        for problem in &self.problems {
            out.push_str(&problem.render(file));
            out.push('\n');
        }
        out
    }

    /// A builder refusal, placed at the source line of the face that shows
    /// the problem (the later face when two are involved), its vertices
    /// numbered from `first_vertex` as the file numbers them.
    pub(crate) fn from_build(error: &BuildError, first_vertex: u32) -> Self {
        let face: Option<FaceRef> = match error {
            BuildError::TooFewVertices { face, .. }
            | BuildError::RepeatedVertex { face, .. }
            | BuildError::IndexOutOfRange { face, .. } => Some(*face),
            BuildError::NonManifoldEdge { faces, .. } => faces.iter().max().copied(),
            BuildError::InconsistentOrientation { second, .. }
            | BuildError::NonManifoldVertex { second, .. } => Some(*second),
            BuildError::TooLarge { .. } => None,
        };
        let location = face
            .and_then(|face| face.line)
            .map_or(Location::File, Location::line);
        Self::new(location, error.numbered_from(first_vertex).to_string())
    }
}

impl fmt::Display for FormatError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for (i, problem) in self.problems.iter().enumerate() {
            if i > 0 {
                f.write_str("\n")?;
            }
            write!(f, "{problem}")?;
        }
        Ok(())
    }
}

impl std::error::Error for FormatError {}

/// Why a mesh could not be saved in the requested format.
#[derive(Clone, Debug, PartialEq)]
pub enum SaveError {
    /// Converting to the format's structure failed (the mesh is broken).
    Convert(ConvertError),
    /// The mesh does not fit the format (for example a face too large for
    /// the PLY list count type).
    Unsupported(String),
}

impl fmt::Display for SaveError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Convert(error) => error.fmt(f),
            Self::Unsupported(message) => f.write_str(message),
        }
    }
}

impl std::error::Error for SaveError {}

impl From<ConvertError> for SaveError {
    fn from(error: ConvertError) -> Self {
        Self::Convert(error)
    }
}
