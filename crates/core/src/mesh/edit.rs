//! Edits one record at a time: what the language's `:=` on a record, `new`
//! and `delete` do, and what every local operation is made of.
//!
//! [`Edit`] is the small set of primitive changes a structure supports.
//! [`Editor`] applies them and keeps a journal of [`Change`]s, each with the
//! value it replaced, so a trace can step an edit backwards and forwards and
//! an undo can take it back exactly. Between changes the tables may break
//! the structure's rules; `validate` says where.

use std::fmt;

use glam::Vec3;

use super::deleted::Deleted;
use super::half_edge::HalfEdgeMesh;
use super::ids::VertexId;
use super::winged_edge::WingedEdgeMesh;
use crate::schema::{
    Column, EditHooks, ElementKind, ElementRef, LookupError, Record, Records, RecordsMut, Rows,
    RowsMut, Structure, WriteError,
};

/// The most rows one table may grow to by edits: far above any mesh the app
/// draws, and low enough that a runaway `new` loop stops long before memory
/// runs out.
pub const MAX_ROWS: usize = 1 << 24;

/// Why a primitive change was refused.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum EditError {
    Write(WriteError),
    /// The table is at [`MAX_ROWS`].
    TableFull(ElementKind),
    /// Deleting a row that is already deleted, or one that never existed.
    NoSuchElement(ElementRef),
    /// A position with an infinite or NaN coordinate.
    NotFinite(VertexId),
}

impl From<WriteError> for EditError {
    fn from(error: WriteError) -> Self {
        Self::Write(error)
    }
}

impl fmt::Display for EditError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Write(error) => error.fmt(f),
            Self::TableFull(kind) => write!(
                f,
                "the {} table already has {MAX_ROWS} rows, the most an edit may make",
                kind.prose()
            ),
            Self::NoSuchElement(element) => {
                write!(f, "{element} does not exist in this mesh (or was deleted)")
            }
            Self::NotFinite(vertex) => {
                write!(f, "the position of {vertex} must be a finite point")
            }
        }
    }
}

impl std::error::Error for EditError {}

/// One primitive change, with what it replaced.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Change {
    /// `column` of `element`'s row went from `old` to `new`.
    Reference {
        element: ElementRef,
        column: Column,
        old: Option<ElementRef>,
        new: Option<ElementRef>,
    },
    /// A vertex moved.
    Position {
        vertex: VertexId,
        old: Vec3,
        new: Vec3,
    },
    /// A row was appended, with its required references unset.
    Create(ElementRef),
    /// A row was marked deleted; it keeps its number and contents.
    Delete(ElementRef),
}

impl Change {
    /// The row the change is about.
    pub fn element(&self) -> ElementRef {
        match *self {
            Self::Reference { element, .. } | Self::Create(element) | Self::Delete(element) => {
                element
            }
            Self::Position { vertex, .. } => vertex.into(),
        }
    }

    /// Makes the change again, after [`Self::revert`].
    pub fn apply<M: Edit + ?Sized>(&self, mesh: &mut M) -> Result<(), EditError> {
        match *self {
            Self::Reference {
                element,
                column,
                new: Some(new),
                ..
            } => Ok(mesh.set_reference(element, column, Some(new))?),
            Self::Reference {
                element,
                column,
                new: None,
                ..
            } => Ok(mesh.unset_reference(element, column)?),
            Self::Position { vertex, new, .. } => mesh.set_position(vertex, new).map(drop),
            Self::Create(element) => mesh.push_row(element.kind).map(drop),
            Self::Delete(element) => mesh.set_deleted(element, true),
        }
    }

    /// Takes the change back. Changes are reverted newest first, so a
    /// created row is always the last of its table.
    pub fn revert<M: Edit + ?Sized>(&self, mesh: &mut M) -> Result<(), EditError> {
        match *self {
            Self::Reference {
                element,
                column,
                old: Some(old),
                ..
            } => Ok(mesh.set_reference(element, column, Some(old))?),
            Self::Reference {
                element,
                column,
                old: None,
                ..
            } => Ok(mesh.unset_reference(element, column)?),
            Self::Position { vertex, old, .. } => mesh.set_position(vertex, old).map(drop),
            Self::Create(element) => mesh.pop_row(element.kind),
            Self::Delete(element) => mesh.set_deleted(element, false),
        }
    }
}

impl fmt::Display for Change {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let show = |r: Option<ElementRef>| r.map_or_else(|| "null".to_owned(), |r| r.to_string());
        match *self {
            Self::Reference {
                element,
                column,
                old,
                new,
            } => write!(
                f,
                "{element} {}: {} → {}",
                column.key(),
                show(old),
                show(new)
            ),
            Self::Position { vertex, old, new } => write!(
                f,
                "{vertex} position: ({}, {}, {}) → ({}, {}, {})",
                old.x, old.y, old.z, new.x, new.y, new.z
            ),
            Self::Create(element) => write!(f, "new {element}"),
            Self::Delete(element) => write!(f, "deleted {element}"),
        }
    }
}

/// Old ids to new ones after [`Edit::compact`]: `None` for a deleted row.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Renumbering {
    pub vertices: Vec<Option<u32>>,
    pub edges: Vec<Option<u32>>,
    pub faces: Vec<Option<u32>>,
}

impl Renumbering {
    fn table(&self, kind: ElementKind) -> &[Option<u32>] {
        match kind {
            ElementKind::Vertex => &self.vertices,
            ElementKind::Edge => &self.edges,
            ElementKind::Face => &self.faces,
        }
    }

    /// The new id of an old element, or `None` if it was deleted.
    pub fn get(&self, element: ElementRef) -> Option<ElementRef> {
        let id = self
            .table(element.kind)
            .get(element.id as usize)
            .copied()??;
        Some(ElementRef::new(element.kind, id))
    }

    /// The ids of `kind` that changed, in order, each with its new id
    /// (`None`: the row was deleted and is gone).
    pub fn changes(&self, kind: ElementKind) -> impl Iterator<Item = (u32, Option<u32>)> + '_ {
        (0u32..)
            .zip(self.table(kind))
            .filter(|&(old, new)| *new != Some(old))
            .map(|(old, new)| (old, *new))
    }

    /// Whether no id changed.
    pub fn is_identity(&self) -> bool {
        ElementKind::ALL.into_iter().all(|kind| {
            (0u32..)
                .zip(self.table(kind))
                .all(|(old, new)| *new == Some(old))
        })
    }

    fn for_table(deleted: &Deleted, kind: ElementKind, len: usize) -> Vec<Option<u32>> {
        let mut next = 0u32;
        (0..len)
            .map(|index| {
                if deleted.row(kind, index) {
                    None
                } else {
                    next += 1;
                    Some(next - 1)
                }
            })
            .collect()
    }

    fn new(deleted: &Deleted, counts: [usize; 3]) -> Self {
        let [v, e, f] = counts;
        Self {
            vertices: Self::for_table(deleted, ElementKind::Vertex, v),
            edges: Self::for_table(deleted, ElementKind::Edge, e),
            faces: Self::for_table(deleted, ElementKind::Face, f),
        }
    }
}

/// The primitive changes of a structure's tables. Every edit, traced or
/// native, is a sequence of these; [`Editor`] journals them.
pub trait Edit: RecordsMut {
    /// Appends a row of `kind` with its required references unset (and, for
    /// a vertex, at the origin). Refused at [`MAX_ROWS`].
    fn push_row(&mut self, kind: ElementKind) -> Result<ElementRef, EditError>;

    /// Removes the last row of `kind`: the inverse of [`Self::push_row`].
    fn pop_row(&mut self, kind: ElementKind) -> Result<(), EditError>;

    /// Marks a row deleted, or not.
    fn set_deleted(&mut self, element: ElementRef, deleted: bool) -> Result<(), EditError>;

    /// Moves a vertex; returns where it was.
    fn set_position(&mut self, vertex: VertexId, position: Vec3) -> Result<Vec3, EditError>;

    /// Drops the deleted rows and renumbers the rest in order, rewriting
    /// every reference; a reference to a deleted row becomes empty (or unset,
    /// where the column needs one).
    fn compact(&mut self) -> Renumbering;

    /// Rows an edit deleted.
    fn deleted_rows(&self) -> &Deleted;
}

fn full(kind: ElementKind, len: usize) -> Result<(), EditError> {
    if len >= MAX_ROWS {
        Err(EditError::TableFull(kind))
    } else {
        Ok(())
    }
}

/// Marks or unmarks a row; refuses rows that do not exist and changes that
/// change nothing, so a journal never holds a no-op.
fn mark_deleted(
    deleted: &mut Deleted,
    count: usize,
    element: ElementRef,
    delete: bool,
) -> Result<(), EditError> {
    let changed = (element.id as usize) < count
        && if delete {
            deleted.insert(element)
        } else {
            deleted.remove(element)
        };
    if changed {
        Ok(())
    } else {
        Err(EditError::NoSuchElement(element))
    }
}

fn move_vertex(position: Option<&mut Vec3>, vertex: VertexId, to: Vec3) -> Result<Vec3, EditError> {
    if !to.is_finite() {
        return Err(EditError::NotFinite(vertex));
    }
    let slot = position.ok_or(EditError::NoSuchElement(vertex.into()))?;
    Ok(std::mem::replace(slot, to))
}

/// Keeps the rows `keep` says, in order.
fn retain_rows<T>(rows: &mut Vec<T>, keep: &[Option<u32>]) {
    let mut index = 0;
    rows.retain(|_| {
        index += 1;
        keep.get(index - 1).is_some_and(Option::is_some)
    });
}

/// A structure's three tables as growable vectors, and its deleted rows.
pub(crate) struct TablesMut<'m, V, F, E> {
    vertices: &'m mut Vec<V>,
    faces: &'m mut Vec<F>,
    edges: &'m mut Vec<E>,
    deleted: &'m mut Deleted,
}

/// What the generic [`Edit`] needs of a structure besides the schema's
/// column-by-column access to rows.
pub(crate) trait Tables: RowsMut + EditHooks {
    fn tables(&mut self) -> TablesMut<'_, Self::Vertex, Self::Face, Self::Edge>;

    fn position_mut(&mut self, vertex: VertexId) -> Option<&mut Vec3>;
}

macro_rules! tables {
    ($($mesh:ty: $edges:ident),*) => {$(
        impl Tables for $mesh {
            fn tables(&mut self) -> TablesMut<'_, Self::Vertex, Self::Face, Self::Edge> {
                TablesMut {
                    vertices: &mut self.vertices,
                    faces: &mut self.faces,
                    edges: &mut self.$edges,
                    deleted: &mut self.deleted,
                }
            }

            fn position_mut(&mut self, vertex: VertexId) -> Option<&mut Vec3> {
                if self.deleted.contains(vertex.into()) {
                    return None;
                }
                self.vertices.get_mut(vertex.index()).map(|v| &mut v.position)
            }
        }
    )*};
}

tables!(WingedEdgeMesh: edges, HalfEdgeMesh: half_edges);

/// A new row: required references unset, optional ones empty.
fn new_row<R: Record>(structure: Structure, kind: ElementKind) -> R {
    let mut row = R::default();
    for entry in Column::table(structure, kind) {
        row.set(entry.column, None);
    }
    row
}

/// Rewrites every stored reference of `rows` through `map`.
fn renumber<R: Record>(rows: &mut [R], structure: Structure, kind: ElementKind, map: &Renumbering) {
    let columns = Column::table(structure, kind);
    for row in rows {
        for entry in columns {
            let (Some(Some(id)), Some(target)) = (row.get(entry.column), entry.column.target())
            else {
                continue;
            };
            let mapped = map.get(ElementRef::new(target, id)).map(|r| r.id);
            row.set(entry.column, mapped);
        }
    }
}

impl<T: Tables> Edit for T {
    fn push_row(&mut self, kind: ElementKind) -> Result<ElementRef, EditError> {
        let len = self.count(kind);
        full(kind, len)?;
        let structure = Rows::structure(self);
        let tables = self.tables();
        match kind {
            ElementKind::Vertex => tables.vertices.push(new_row(structure, kind)),
            ElementKind::Face => tables.faces.push(new_row(structure, kind)),
            ElementKind::Edge => tables.edges.push(new_row(structure, kind)),
        }
        if kind == ElementKind::Edge {
            self.written(Column::SuccessorEdge);
        }
        Ok(ElementRef::new(kind, len as u32))
    }

    fn pop_row(&mut self, kind: ElementKind) -> Result<(), EditError> {
        let last = ElementRef::new(kind, self.count(kind).saturating_sub(1) as u32);
        let tables = self.tables();
        let popped = match kind {
            ElementKind::Vertex => tables.vertices.pop().is_some(),
            ElementKind::Face => tables.faces.pop().is_some(),
            ElementKind::Edge => tables.edges.pop().is_some(),
        };
        tables.deleted.remove(last);
        if kind == ElementKind::Edge {
            self.written(Column::SuccessorEdge);
        }
        popped.then_some(()).ok_or(EditError::NoSuchElement(last))
    }

    fn set_deleted(&mut self, element: ElementRef, deleted: bool) -> Result<(), EditError> {
        let count = self.count(element.kind);
        mark_deleted(self.tables().deleted, count, element, deleted)?;
        if element.kind == ElementKind::Edge {
            self.written(Column::SuccessorEdge);
        }
        Ok(())
    }

    fn set_position(&mut self, vertex: VertexId, position: Vec3) -> Result<Vec3, EditError> {
        move_vertex(self.position_mut(vertex), vertex, position)
    }

    fn compact(&mut self) -> Renumbering {
        let structure = Rows::structure(self);
        let t = self.tables();
        let map = Renumbering::new(t.deleted, [t.vertices.len(), t.edges.len(), t.faces.len()]);
        retain_rows(t.vertices, &map.vertices);
        retain_rows(t.edges, &map.edges);
        retain_rows(t.faces, &map.faces);
        renumber(t.vertices, structure, ElementKind::Vertex, &map);
        renumber(t.edges, structure, ElementKind::Edge, &map);
        renumber(t.faces, structure, ElementKind::Face, &map);
        t.deleted.clear();
        self.written(Column::SuccessorEdge);
        map
    }

    fn deleted_rows(&self) -> &Deleted {
        Rows::deleted(self)
    }
}

/// Applies primitive changes to a mesh and journals them.
///
/// `new Edge` in a half-edge mesh makes two rows whose pair edges name each
/// other; `delete` of a half-edge deletes its pair too, so the language's
/// Edge is the same unit in both structures.
#[derive(Debug)]
pub struct Editor<'m, M: Edit + ?Sized> {
    mesh: &'m mut M,
    journal: Vec<Change>,
}

impl<'m, M: Edit + ?Sized> Editor<'m, M> {
    pub fn new(mesh: &'m mut M) -> Self {
        Self {
            mesh,
            journal: Vec::new(),
        }
    }

    /// The mesh as the changes so far left it.
    pub fn mesh(&self) -> &M {
        self.mesh
    }

    /// Every change so far, oldest first.
    pub fn journal(&self) -> &[Change] {
        &self.journal
    }

    pub fn into_journal(self) -> Vec<Change> {
        self.journal
    }

    /// Stores a reference in a record.
    pub fn set(
        &mut self,
        element: ElementRef,
        column: Column,
        target: Option<ElementRef>,
    ) -> Result<(), EditError> {
        let old = self
            .mesh
            .reference(element, column)
            .map_err(|error| match error {
                LookupError::NoSuchElement(element) => WriteError::NoSuchElement(element),
                LookupError::Deleted(element) => WriteError::Deleted(element),
                LookupError::NotApplicable { element, column } => {
                    WriteError::NotStored { element, column }
                }
            })?;
        self.mesh.set_reference(element, column, target)?;
        self.journal.push(Change::Reference {
            element,
            column,
            old,
            new: target,
        });
        Ok(())
    }

    /// Moves a vertex.
    pub fn set_position(&mut self, vertex: VertexId, position: Vec3) -> Result<(), EditError> {
        let old = self.mesh.set_position(vertex, position)?;
        self.journal.push(Change::Position {
            vertex,
            old,
            new: position,
        });
        Ok(())
    }

    /// A new row of `kind`, with the next free id. In a half-edge mesh an
    /// Edge is a pair of half-edges; the first is returned.
    pub fn create(&mut self, kind: ElementKind) -> Result<ElementRef, EditError> {
        let first = self.push(kind)?;
        if kind == ElementKind::Edge && self.mesh.structure() == Structure::HalfEdge {
            let second = match self.push(kind) {
                Ok(second) => second,
                Err(error) => {
                    self.undo_last()?;
                    return Err(error);
                }
            };
            self.set(first, Column::PairEdge, Some(second))?;
            self.set(second, Column::PairEdge, Some(first))?;
        }
        Ok(first)
    }

    fn push(&mut self, kind: ElementKind) -> Result<ElementRef, EditError> {
        let element = self.mesh.push_row(kind)?;
        self.journal.push(Change::Create(element));
        Ok(element)
    }

    /// Deletes a row (a half-edge with its pair), keeping its number as a
    /// gap until [`Edit::compact`].
    pub fn delete(&mut self, element: ElementRef) -> Result<(), EditError> {
        let pair = (element.kind == ElementKind::Edge
            && self.mesh.structure() == Structure::HalfEdge)
            .then(|| {
                self.mesh
                    .reference(element, Column::PairEdge)
                    .ok()
                    .flatten()
            })
            .flatten()
            .filter(|pair| *pair != element);
        self.mesh.set_deleted(element, true)?;
        self.journal.push(Change::Delete(element));
        if let Some(pair) = pair
            && self.mesh.set_deleted(pair, true).is_ok()
        {
            self.journal.push(Change::Delete(pair));
        }
        Ok(())
    }

    /// Takes back the newest change.
    pub fn undo_last(&mut self) -> Result<(), EditError> {
        match self.journal.pop() {
            Some(change) => change.revert(self.mesh),
            None => Ok(()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::{Mesh, generate};

    #[test]
    fn a_journal_reverts_to_the_tables_it_started_from() {
        let mut mesh = Mesh::Half(HalfEdgeMesh::build(&generate::tetrahedron()).unwrap().0);
        let before = mesh.clone();
        let mut editor = Editor::new(&mut mesh);
        let h = editor.create(ElementKind::Edge).unwrap();
        let v = editor.create(ElementKind::Vertex).unwrap();
        editor.set(h, Column::EndVertex, Some(v)).unwrap();
        editor
            .set_position(VertexId::new(v.id), Vec3::new(1.0, 2.0, 3.0))
            .unwrap();
        editor
            .delete(ElementRef::new(ElementKind::Edge, 0))
            .unwrap();
        let journal = editor.into_journal();
        assert_eq!(journal.len(), 9, "{journal:#?}");
        let after = mesh.clone();
        assert!(!after.contains(ElementRef::new(ElementKind::Edge, 0)));
        for change in journal.iter().rev() {
            change.revert(&mut mesh).unwrap();
        }
        assert_eq!(mesh, before);
        for change in &journal {
            change.apply(&mut mesh).unwrap();
        }
        assert_eq!(mesh, after);
    }

    #[test]
    fn new_rows_read_as_unset_and_refuse_what_does_not_fit() {
        let mut mesh = WingedEdgeMesh::build(&generate::tetrahedron()).unwrap().0;
        let mut editor = Editor::new(&mut mesh);
        let e = editor.create(ElementKind::Edge).unwrap();
        assert_eq!(editor.mesh().reference(e, Column::LeftSuccessor), Ok(None));
        let face = ElementRef::new(ElementKind::Face, 0);
        assert_eq!(
            editor
                .set(e, Column::LeftSuccessor, Some(face))
                .unwrap_err()
                .to_string(),
            "the left successor column holds edges, not face 0"
        );
        assert_eq!(
            editor
                .set_position(VertexId::new(0), Vec3::new(f32::NAN, 0.0, 0.0))
                .unwrap_err()
                .to_string(),
            "the position of vertex 0 must be a finite point"
        );
        editor.delete(e).unwrap();
        assert_eq!(
            editor.delete(e).unwrap_err().to_string(),
            "edge 6 does not exist in this mesh (or was deleted)"
        );
        assert_eq!(
            editor
                .set(e, Column::LeftSuccessor, None)
                .unwrap_err()
                .to_string(),
            "edge 6 was deleted; its row cannot be written"
        );
    }

    #[test]
    fn compacting_maps_every_reference() {
        let mut mesh = HalfEdgeMesh::build(&generate::tetrahedron()).unwrap().0;
        let mut editor = Editor::new(&mut mesh);
        let v = editor.create(ElementKind::Vertex).unwrap();
        let h = editor.create(ElementKind::Edge).unwrap();
        editor.set(h, Column::EndVertex, Some(v)).unwrap();
        editor
            .delete(ElementRef::new(ElementKind::Vertex, 1))
            .unwrap();
        let map = mesh.compact();
        assert_eq!(map.get(ElementRef::new(ElementKind::Vertex, 1)), None);
        assert_eq!(map.get(v), Some(ElementRef::new(ElementKind::Vertex, 3)));
        assert!(!map.is_identity());
        assert_eq!(mesh.vertex_count(), 4);
        assert!(mesh.deleted().is_empty());
        assert_eq!(
            mesh.reference(h, Column::EndVertex),
            Ok(Some(ElementRef::new(ElementKind::Vertex, 3)))
        );
        // Half-edges that ended at the deleted vertex are left unset.
        assert!(mesh.half_edges().iter().any(|h| h.end_vertex.is_unset()));
    }

    #[test]
    fn validation_names_unset_and_deleted_references() {
        let mut mesh = WingedEdgeMesh::build(&generate::tetrahedron()).unwrap().0;
        let mut editor = Editor::new(&mut mesh);
        editor.create(ElementKind::Face).unwrap();
        editor
            .delete(ElementRef::new(ElementKind::Edge, 2))
            .unwrap();
        let issues: Vec<String> = mesh.validate().iter().map(ToString::to_string).collect();
        assert!(
            issues.contains(&"face 4 incident_edge: it is not set".to_owned()),
            "{issues:#?}"
        );
        assert!(
            issues
                .iter()
                .any(|issue| issue.contains("edge 2 was deleted")),
            "{issues:#?}"
        );
        assert!(
            !issues.iter().any(|issue| issue.starts_with("edge 2 ")),
            "{issues:#?}"
        );
    }
}
