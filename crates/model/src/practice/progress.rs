//! A saved attempt: enough to bring a student back to the same instance
//! and the same progress after the page closes (an LMS's `suspend_data`).
//!
//! It is text of a few characters an LMS stores safely (letters, digits and
//! `: , . = + - @ ;`):
//!
//! ```text
//! 1:<seed>:<attempt>:<writes>:<flags>:<body>
//! ```
//!
//! `flags` holds `c` (the tables were graded), `f` (the attempt is over)
//! and `m` (the model answer was shown). A walk's or a prediction's body is
//! its answers in order (`h7,v3,-` with `-` for null); a do-it's is the
//! fewest writes that turn the instance's tables into the student's:
//! `+h` (a new row), `h7.next=3` or `h7.next=-` (a reference), `v3@0.5;1;0`
//! (a position), `-f2` (a deleted row). Writes are stored rather than the
//! history of the attempt, so undo and redo need nothing of their own.

use std::fmt;

use edgewise_core::mesh::{Edit, Mesh, VertexId};
use edgewise_core::schema::{Column, ElementKind, ElementRef, Records, RecordsMut, Storage};
use glam::Vec3;

use super::exercise::{Exercise, ExerciseError};
use super::instance::Task;
use super::session::Session;

/// The most answers or writes a saved attempt may hold: far more than any
/// exercise needs, and a bound on hostile text.
pub const MAX_ITEMS: usize = 10_000;

/// A saved attempt.
#[derive(Clone, Debug, PartialEq)]
pub struct Progress {
    pub seed: u64,
    pub attempt: u32,
    pub writes: usize,
    pub graded: bool,
    pub finished: bool,
    pub model_answer_shown: bool,
    pub body: Body,
}

/// What the student gave.
#[derive(Clone, Debug, PartialEq)]
pub enum Body {
    Answers(Vec<Option<ElementRef>>),
    Writes(Vec<Write>),
}

/// One write by hand to the tables.
#[derive(Clone, Debug, PartialEq)]
pub enum Write {
    AddRow(ElementKind),
    Reference {
        element: ElementRef,
        column: Column,
        target: Option<u32>,
    },
    Position {
        vertex: u32,
        position: [f32; 3],
    },
    DeleteRow(ElementRef),
}

impl Session {
    /// This attempt, saved; `tables` are the student's tables now (a do-it
    /// exercise's answer).
    pub fn progress(&self, tables: &Mesh) -> Progress {
        let body = match self.instance.task {
            Task::DoIt { .. } => Body::Writes(writes_between(&self.instance.mesh, tables)),
            Task::Walk { .. } | Task::Predict { .. } => Body::Answers(self.answers.clone()),
        };
        Progress {
            seed: self.base_seed(),
            attempt: self.attempt,
            writes: self.writes,
            graded: self.last.is_some(),
            finished: self.finished,
            model_answer_shown: self.model_answer_shown,
            body,
        }
    }

    /// Brings a saved attempt back: the session, and the tables to show
    /// (the instance's, with the student's writes made again).
    pub fn resume(exercise: Exercise, progress: &Progress) -> Result<(Self, Mesh), ExerciseError> {
        let mut session = Self::start(exercise, progress.seed)?;
        let fail = |session: &Self, what: String| {
            Err(session.error(&format!("the saved attempt cannot be resumed: {what}")))
        };
        if progress.attempt == 0
            || (session.exercise.attempts != 0 && progress.attempt > session.exercise.attempts)
        {
            return fail(
                &session,
                format!("attempt {} is not allowed", progress.attempt),
            );
        }
        session.go_to_attempt(progress.attempt)?;
        let mut tables = session.instance.mesh.clone();
        match (&session.instance.task, &progress.body) {
            (Task::DoIt { .. }, Body::Writes(writes)) => {
                for (n, write) in writes.iter().enumerate() {
                    if let Err(why) = write.apply(&mut tables) {
                        return fail(&session, format!("write {} ({write}): {why}", n + 1));
                    }
                }
                session.writes = progress.writes.max(writes.len());
                if progress.graded && !progress.model_answer_shown {
                    let outcome = session.exercise.grade(&session.instance, &tables)?;
                    session.graded_tables(outcome.passed);
                    session.last = Some(outcome);
                }
                session.finished = progress.finished;
            }
            (Task::Walk { .. } | Task::Predict { .. }, Body::Answers(answers)) => {
                for (n, &given) in answers.iter().enumerate() {
                    if session.answer(given).is_none() {
                        return fail(&session, format!("answer {} is not one it takes", n + 1));
                    }
                }
                if progress.finished && !session.finished && !progress.model_answer_shown {
                    session.check(&tables)?;
                }
            }
            _ => return fail(&session, "it is of another kind of exercise".to_owned()),
        }
        if progress.model_answer_shown {
            session.model_answer()?;
        }
        Ok((session, tables))
    }
}

/// The fewest writes that turn `from` into `to`: new rows, then references
/// and positions, then deletions (a deleted row takes no writes).
pub fn writes_between(from: &Mesh, to: &Mesh) -> Vec<Write> {
    let structure = to.structure();
    let mut writes = Vec::new();
    for kind in ElementKind::ALL {
        for _ in from.count(kind)..to.count(kind) {
            writes.push(Write::AddRow(kind));
        }
    }
    for kind in ElementKind::ALL {
        let columns: Vec<Column> = Column::table(structure, kind)
            .iter()
            .filter(|entry| entry.storage == Storage::Stored && entry.column != Column::Position)
            .map(|entry| entry.column)
            .collect();
        for id in 0..to.count(kind) as u32 {
            let element = ElementRef::new(kind, id);
            if !to.contains(element) {
                continue;
            }
            let existed = from.contains(element);
            if kind == ElementKind::Vertex {
                let vertex = VertexId::new(id);
                let now = to.position(vertex).unwrap_or_default();
                let before = if existed {
                    from.position(vertex)
                } else {
                    Some(Vec3::ZERO)
                };
                if before != Some(now) {
                    writes.push(Write::Position {
                        vertex: id,
                        position: now.to_array(),
                    });
                }
            }
            for &column in &columns {
                let now = to.reference(element, column).ok().flatten().map(|e| e.id);
                let before = if existed {
                    from.reference(element, column).ok().flatten().map(|e| e.id)
                } else {
                    None
                };
                if now != before {
                    writes.push(Write::Reference {
                        element,
                        column,
                        target: now,
                    });
                }
            }
        }
    }
    // A row deleted from the instance, or added and deleted in the same
    // attempt (one the instance had deleted already takes no write).
    for kind in ElementKind::ALL {
        for id in 0..to.count(kind) as u32 {
            let element = ElementRef::new(kind, id);
            let new = id as usize >= from.count(kind);
            if !to.contains(element) && (new || from.contains(element)) {
                writes.push(Write::DeleteRow(element));
            }
        }
    }
    writes
}

impl Write {
    fn apply(&self, mesh: &mut Mesh) -> Result<(), String> {
        match *self {
            Self::AddRow(kind) => mesh.push_row(kind).map(drop).map_err(|e| e.to_string()),
            Self::Reference {
                element,
                column,
                target,
            } => {
                let kind = column.target().ok_or("the column holds no reference")?;
                let target = target.map(|id| ElementRef::new(kind, id));
                if let Some(target) = target
                    && !mesh.contains(target)
                {
                    return Err(format!("{target} is not in the tables"));
                }
                match target {
                    Some(_) => mesh.set_reference(element, column, target),
                    None => mesh.unset_reference(element, column),
                }
                .map_err(|e| e.to_string())
            }
            Self::Position { vertex, position } => {
                let position = Vec3::from_array(position);
                if !position.is_finite() {
                    return Err("the position is not finite".to_owned());
                }
                if !mesh.contains(ElementRef::new(ElementKind::Vertex, vertex)) {
                    return Err(format!("vertex {vertex} is not in the tables"));
                }
                mesh.set_position(VertexId::new(vertex), position)
                    .map(drop)
                    .map_err(|e| e.to_string())
            }
            Self::DeleteRow(element) => {
                if !mesh.contains(element) {
                    return Err(format!("{element} is not in the tables"));
                }
                mesh.set_deleted(element, true).map_err(|e| e.to_string())
            }
        }
    }
}

fn letter(kind: ElementKind) -> char {
    match kind {
        ElementKind::Vertex => 'v',
        ElementKind::Edge => 'e',
        ElementKind::Face => 'f',
    }
}

fn kind_of(letter: char) -> Option<ElementKind> {
    match letter {
        'v' => Some(ElementKind::Vertex),
        'e' => Some(ElementKind::Edge),
        'f' => Some(ElementKind::Face),
        _ => None,
    }
}

struct Short(ElementRef);

impl fmt::Display for Short {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}{}", letter(self.0.kind), self.0.id)
    }
}

fn parse_element(text: &str) -> Option<ElementRef> {
    let mut chars = text.chars();
    let kind = kind_of(chars.next()?)?;
    let id = chars.as_str();
    if id.is_empty() || !id.bytes().all(|b| b.is_ascii_digit()) {
        return None;
    }
    Some(ElementRef::new(kind, id.parse().ok()?))
}

fn column_name(column: Column) -> &'static str {
    column
        .language_name()
        .unwrap_or_else(|| column.record_name())
}

fn parse_column(kind: ElementKind, name: &str) -> Option<Column> {
    Column::ALL
        .into_iter()
        .find(|&c| c.applies_to(kind) && c.target().is_some() && column_name(c) == name)
}

impl fmt::Display for Write {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Self::AddRow(kind) => write!(f, "+{}", letter(kind)),
            Self::Reference {
                element,
                column,
                target,
            } => {
                write!(f, "{}.{}=", Short(element), column_name(column))?;
                match target {
                    Some(id) => write!(f, "{id}"),
                    None => f.write_str("-"),
                }
            }
            Self::Position {
                vertex,
                position: [x, y, z],
            } => write!(f, "v{vertex}@{x};{y};{z}"),
            Self::DeleteRow(element) => write!(f, "-{}", Short(element)),
        }
    }
}

impl Write {
    fn parse(text: &str) -> Option<Self> {
        if let Some(kind) = text.strip_prefix('+') {
            let mut chars = kind.chars();
            let kind = kind_of(chars.next()?)?;
            return chars.as_str().is_empty().then_some(Self::AddRow(kind));
        }
        if let Some(element) = text.strip_prefix('-') {
            return parse_element(element).map(Self::DeleteRow);
        }
        if let Some((vertex, at)) = text.split_once('@') {
            let vertex = parse_element(vertex).filter(|e| e.kind == ElementKind::Vertex)?;
            let mut coordinates = at.split(';').map(|c| c.parse::<f32>().ok());
            let position = [
                coordinates.next()??,
                coordinates.next()??,
                coordinates.next()??,
            ];
            if coordinates.next().is_some() || !position.iter().all(|c| c.is_finite()) {
                return None;
            }
            return Some(Self::Position {
                vertex: vertex.id,
                position,
            });
        }
        let (cell, target) = text.split_once('=')?;
        let (element, column) = cell.split_once('.')?;
        let element = parse_element(element)?;
        let column = parse_column(element.kind, column)?;
        let target = match target {
            "-" => None,
            id if !id.is_empty() && id.bytes().all(|b| b.is_ascii_digit()) => {
                Some(id.parse().ok()?)
            }
            _ => return None,
        };
        Some(Self::Reference {
            element,
            column,
            target,
        })
    }
}

impl fmt::Display for Progress {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let flags: String = [
            (self.graded, 'c'),
            (self.finished, 'f'),
            (self.model_answer_shown, 'm'),
        ]
        .into_iter()
        .filter_map(|(on, c)| on.then_some(c))
        .collect();
        write!(
            f,
            "1:{}:{}:{}:{flags}:",
            self.seed, self.attempt, self.writes
        )?;
        let items: Vec<String> = match &self.body {
            Body::Answers(answers) => answers
                .iter()
                .map(|a| a.map_or_else(|| "-".to_owned(), |e| Short(e).to_string()))
                .collect(),
            Body::Writes(writes) => writes.iter().map(Write::to_string).collect(),
        };
        f.write_str(&items.join(","))
    }
}

/// Why saved text is not an attempt.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ProgressError(pub String);

impl fmt::Display for ProgressError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "the saved attempt is not readable: {}", self.0)
    }
}

impl std::error::Error for ProgressError {}

impl Progress {
    /// Reads saved text; `do_it` says which body to expect.
    pub fn parse(text: &str, do_it: bool) -> Result<Self, ProgressError> {
        let error = |what: &str| Err(ProgressError(what.to_owned()));
        let mut parts = text.splitn(6, ':');
        if parts.next() != Some("1") {
            return error("it does not start with version 1");
        }
        let mut number = |name: &str| -> Result<u64, ProgressError> {
            parts
                .next()
                .and_then(|n| n.parse().ok())
                .ok_or_else(|| ProgressError(format!("its {name} is not a whole number")))
        };
        let seed = number("seed")?;
        let attempt = u32::try_from(number("attempt")?)
            .map_err(|_| ProgressError("its attempt is too large".to_owned()))?;
        let writes = usize::try_from(number("writes")?)
            .map_err(|_| ProgressError("its writes are too many".to_owned()))?;
        let (Some(flags), Some(body)) = (parts.next(), parts.next()) else {
            return error("it ends early");
        };
        if let Some(c) = flags.chars().find(|c| !"cfm".contains(*c)) {
            return Err(ProgressError(format!("`{c}` is not a flag")));
        }
        let items: Vec<&str> = if body.is_empty() {
            Vec::new()
        } else {
            body.split(',').collect()
        };
        if items.len() > MAX_ITEMS {
            return Err(ProgressError(format!(
                "it holds more than {MAX_ITEMS} items"
            )));
        }
        let body = if do_it {
            let mut writes = Vec::with_capacity(items.len());
            for (n, item) in items.iter().enumerate() {
                let write = Write::parse(item).ok_or_else(|| {
                    ProgressError(format!("write {} `{}` is not a write", n + 1, clip(item)))
                })?;
                writes.push(write);
            }
            Body::Writes(writes)
        } else {
            let mut answers = Vec::with_capacity(items.len());
            for (n, item) in items.iter().enumerate() {
                let answer = match *item {
                    "-" => None,
                    _ => Some(parse_element(item).ok_or_else(|| {
                        ProgressError(format!(
                            "answer {} `{}` is not an element",
                            n + 1,
                            clip(item)
                        ))
                    })?),
                };
                answers.push(answer);
            }
            Body::Answers(answers)
        };
        Ok(Self {
            seed,
            attempt,
            writes,
            graded: flags.contains('c'),
            finished: flags.contains('f'),
            model_answer_shown: flags.contains('m'),
            body,
        })
    }
}

/// At most 24 characters of hostile text, for a message.
fn clip(text: &str) -> std::borrow::Cow<'_, str> {
    edgewise_core::lang::diagnostic::shorten(text, 24)
}

#[cfg(test)]
mod tests;
