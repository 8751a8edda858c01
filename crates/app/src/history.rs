//! Undo and redo for one tab. Every change of the tab's mesh (a load, a
//! conversion, an edit, a cell set by hand, compacting the ids) is one
//! entry that keeps the whole document as it was, so an undo puts the
//! tables back byte for byte, selection and name included. The oldest
//! entries go once the kept documents hold more than [`MAX_ROWS_KEPT`]
//! rows in all, or there are more than [`MAX_ENTRIES`].

use edgewise_core::schema::{ElementKind, Records as _};

use edgewise_model::document::Document;

/// The most entries kept on each side.
pub const MAX_ENTRIES: usize = 100;

/// The most table rows the kept documents may hold together: about 200 MB,
/// four copies of the 200k-triangle torus, hundreds of a classroom mesh.
pub const MAX_ROWS_KEPT: usize = 4_000_000;

/// What made an entry: undoing an edit is also "restore the mesh before
/// the edit", which a load is not.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    Load,
    Edit,
}

/// One change, with the document from the other side of it.
struct Entry {
    label: String,
    kind: Kind,
    document: Option<Document>,
}

impl Entry {
    fn rows(&self) -> usize {
        self.document.as_ref().map_or(0, |document| {
            ElementKind::ALL
                .iter()
                .map(|&kind| document.mesh().count(kind))
                .sum()
        })
    }
}

/// The undo and redo stacks of a tab.
#[derive(Default)]
pub struct History {
    undo: Vec<Entry>,
    redo: Vec<Entry>,
}

/// What `state().history` shows: the labels, oldest first.
#[derive(Clone, Debug, Default, PartialEq, Eq, serde::Serialize)]
pub struct HistoryState {
    pub undo: Vec<String>,
    pub redo: Vec<String>,
}

impl History {
    /// Records a change about to be made: `before` is the document as it
    /// is now. Forgets what could be redone. A change labelled like the last
    /// one and `merge`d into it (typing in the OBJ editor) keeps only the
    /// first `before`, so one undo takes back the whole run of keystrokes.
    pub fn record(&mut self, label: String, kind: Kind, before: Option<Document>, merge: bool) {
        self.redo.clear();
        if merge && self.undo.last().is_some_and(|last| last.label == label) {
            return;
        }
        self.undo.push(Entry {
            label,
            kind,
            document: before,
        });
        trim(&mut self.undo);
    }

    /// Takes back the last change: puts the document from before it in
    /// `current`, keeping the one there to redo; gives the change's label,
    /// or `None` if there is nothing to undo.
    pub fn undo(&mut self, current: &mut Option<Document>) -> Option<String> {
        step(&mut self.undo, &mut self.redo, current)
    }

    /// Makes the last undone change again: puts the document from after it
    /// in `current`, keeping the one there to undo.
    pub fn redo(&mut self, current: &mut Option<Document>) -> Option<String> {
        step(&mut self.redo, &mut self.undo, current)
    }

    /// What the next undo would take back, and whether it was an edit.
    pub fn last(&self) -> Option<(&str, Kind)> {
        self.undo
            .last()
            .map(|entry| (entry.label.as_str(), entry.kind))
    }

    /// What the next redo would make again.
    pub fn next(&self) -> Option<&str> {
        self.redo.last().map(|entry| entry.label.as_str())
    }

    pub fn state(&self) -> HistoryState {
        let labels = |entries: &[Entry]| entries.iter().map(|e| e.label.clone()).collect();
        HistoryState {
            undo: labels(&self.undo),
            redo: labels(&self.redo),
        }
    }
}

/// Pops the newest entry of `from` into `current`, and pushes what was in
/// `current` onto `to` under the entry's label.
fn step(
    from: &mut Vec<Entry>,
    to: &mut Vec<Entry>,
    current: &mut Option<Document>,
) -> Option<String> {
    let entry = from.pop()?;
    let now = std::mem::replace(current, entry.document);
    to.push(Entry {
        label: entry.label.clone(),
        kind: entry.kind,
        document: now,
    });
    trim(to);
    Some(entry.label)
}

/// Drops the oldest entries past the limits; the newest always stays.
fn trim(entries: &mut Vec<Entry>) {
    let mut rows: usize = entries.iter().map(Entry::rows).sum();
    let mut drop = 0;
    while entries.len() - drop > 1 && (entries.len() - drop > MAX_ENTRIES || rows > MAX_ROWS_KEPT) {
        rows -= entries[drop].rows();
        drop += 1;
    }
    entries.drain(..drop);
}
