//! Every column of every table, with every name it goes by: the record field
//! and file column (`left_predecessor`), the role label ("Left Predecessor"),
//! the table header ("left pred"), the language's lookup names
//! (`leftPredecessor`), and the colour its role is shown in. Reading a column
//! from a mesh ([`Records::reference`]) lives here too, so that adding a
//! column means editing this file and no other.

use std::fmt;

use glam::Vec3;

use super::ids::VertexId;
use super::{Deleted, ElementKind, ElementRef, Structure};

/// One column of a vertex, edge (or half-edge) or face table.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Column {
    /// A vertex's position (x, y, z): the one column that is not a reference.
    Position,
    /// A vertex's or face's incident edge.
    IncidentEdge,
    /// An edge's start vertex (derived in a half-edge structure).
    StartVertex,
    /// An edge's or half-edge's end vertex.
    EndVertex,
    /// A winged edge's left face.
    LeftFace,
    /// A winged edge's right face.
    RightFace,
    /// A winged edge's left predecessor.
    LeftPredecessor,
    /// A winged edge's left successor.
    LeftSuccessor,
    /// A winged edge's right predecessor.
    RightPredecessor,
    /// A winged edge's right successor.
    RightSuccessor,
    /// A half-edge's adjacent face.
    Face,
    /// A half-edge's pair edge.
    PairEdge,
    /// A half-edge's successor edge.
    SuccessorEdge,
    /// A half-edge's predecessor edge, derived from the successor cycle.
    PredecessorEdge,
}

/// The colours of a column's role, as sRGB for the light and dark themes.
/// Left-side wings are greens and right-side wings purples, so a student can
/// tell the two faces' traversals apart at a glance.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Palette {
    pub light: [u8; 3],
    pub dark: [u8; 3],
}

/// Whether a structure keeps a column in its records or computes it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Storage {
    /// Kept in the record and written to table files.
    Stored,
    /// Computed from stored columns (a half-edge's start vertex and
    /// predecessor); shown dimmed in the tables, never written.
    Derived,
}

/// A column as one structure's table lays it out.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct TableColumn {
    pub column: Column,
    /// The table header in the app and in `edgewise tables`.
    pub header: &'static str,
    /// The header where the table is narrow, shortened as the journal's
    /// Table 1 shortens it ("L pred." for the left traversal's predecessor).
    pub short: &'static str,
    pub storage: Storage,
}

/// The names a column goes by, one row per column.
struct Names {
    /// The record field, file column and `validate` name.
    record: &'static str,
    /// The role label in the 3D view.
    title: &'static str,
    palette: Palette,
}

const fn names(record: &'static str, title: &'static str, light: u32, dark: u32) -> Names {
    const fn rgb(hex: u32) -> [u8; 3] {
        [(hex >> 16) as u8, (hex >> 8) as u8, hex as u8]
    }
    Names {
        record,
        title,
        palette: Palette {
            light: rgb(light),
            dark: rgb(dark),
        },
    }
}

impl Column {
    /// Every column, in table order.
    pub const ALL: [Column; 14] = [
        Column::Position,
        Column::IncidentEdge,
        Column::StartVertex,
        Column::EndVertex,
        Column::LeftFace,
        Column::RightFace,
        Column::LeftPredecessor,
        Column::LeftSuccessor,
        Column::RightPredecessor,
        Column::RightSuccessor,
        Column::Face,
        Column::PairEdge,
        Column::SuccessorEdge,
        Column::PredecessorEdge,
    ];

    /// The names of the coordinates that make up [`Column::Position`], as
    /// file columns and table headers.
    pub const COORDINATES: [&'static str; 3] = ["x", "y", "z"];

    fn names(self) -> Names {
        match self {
            Self::Position => names("position", "Position", 0x495057, 0xadb5bd),
            Self::IncidentEdge => names("incident_edge", "Incident Edge", 0x1c6dd0, 0x5ca8ff),
            Self::StartVertex => names("start_vertex", "Start Vertex", 0x0b7a75, 0x3fc1b8),
            Self::EndVertex => names("end_vertex", "End Vertex", 0x1c4fa0, 0x749cf0),
            Self::LeftFace => names("left_face", "Left Face", 0x2b8a3e, 0x69db7c),
            Self::RightFace => names("right_face", "Right Face", 0x862e9c, 0xcc8be8),
            Self::LeftPredecessor => {
                names("left_predecessor", "Left Predecessor", 0x5c940d, 0xa9e34b)
            }
            Self::LeftSuccessor => names("left_successor", "Left Successor", 0x087f5b, 0x38d9a9),
            Self::RightPredecessor => {
                names("right_predecessor", "Right Predecessor", 0xae3ec9, 0xe599f7)
            }
            Self::RightSuccessor => names("right_successor", "Right Successor", 0x6741d9, 0xb197fc),
            Self::Face => names("face", "Face", 0x2b8a3e, 0x69db7c),
            Self::PairEdge => names("pair_edge", "Pair Edge", 0xc2255c, 0xf783ac),
            Self::SuccessorEdge => names("successor_edge", "Successor Edge", 0x087f5b, 0x38d9a9),
            Self::PredecessorEdge => {
                names("predecessor_edge", "Predecessor Edge", 0x5c940d, 0xa9e34b)
            }
        }
    }

    /// The record field's name, as table files and `validate` spell it
    /// (`left_predecessor`).
    pub fn record_name(self) -> &'static str {
        self.names().record
    }

    /// The role label: "Left Predecessor".
    pub fn title(self) -> &'static str {
        self.names().title
    }

    /// The role's name in `window.edgewise.state()`: "left predecessor".
    pub fn key(self) -> String {
        self.title().to_lowercase()
    }

    /// The role's name in settings and links: "leftPredecessor".
    pub fn setting_key(self) -> String {
        let mut words = self.title().split(' ');
        let mut key = words.next().unwrap_or_default().to_lowercase();
        key.extend(words);
        key
    }

    /// The colours of the column's role.
    pub fn palette(self) -> Palette {
        self.names().palette
    }

    /// The kind of element the column refers to; `None` for the position.
    pub fn target(self) -> Option<ElementKind> {
        match self {
            Self::Position => None,
            Self::StartVertex | Self::EndVertex => Some(ElementKind::Vertex),
            Self::LeftFace | Self::RightFace | Self::Face => Some(ElementKind::Face),
            _ => Some(ElementKind::Edge),
        }
    }

    /// The kind of element whose record holds the column (the vertex, for
    /// an incident edge, which faces have too).
    pub fn owner(self) -> ElementKind {
        match self {
            Self::Position | Self::IncidentEdge => ElementKind::Vertex,
            _ => ElementKind::Edge,
        }
    }

    /// Whether elements of `kind` have this column.
    pub fn applies_to(self, kind: ElementKind) -> bool {
        match self {
            Self::IncidentEdge => kind != ElementKind::Edge,
            other => other.owner() == kind,
        }
    }

    /// Whether a row of `kind` may hold no reference in this column (`-` in
    /// table files): a boundary face, or an isolated vertex's incident edge.
    pub fn nullable_in(self, kind: ElementKind) -> bool {
        match self {
            Self::LeftFace | Self::RightFace | Self::Face => true,
            Self::IncidentEdge => kind == ElementKind::Vertex,
            _ => false,
        }
    }
}

/// The tables of each structure, column by column.
mod layout {
    use super::Column::*;
    use super::Storage::{Derived, Stored};
    use super::TableColumn;

    const fn col(column: super::Column, header: &'static str, short: &'static str) -> TableColumn {
        TableColumn {
            column,
            header,
            short,
            storage: Stored,
        }
    }

    const fn derived(
        column: super::Column,
        header: &'static str,
        short: &'static str,
    ) -> TableColumn {
        TableColumn {
            storage: Derived,
            ..col(column, header, short)
        }
    }

    pub(super) const VERTEX: &[TableColumn] = &[
        col(Position, "position", "position"),
        col(IncidentEdge, "incident edge", "inc. edge"),
    ];
    pub(super) const FACE: &[TableColumn] = &[col(IncidentEdge, "incident edge", "inc. edge")];
    pub(super) const WINGED_EDGE: &[TableColumn] = &[
        col(StartVertex, "start", "start"),
        col(EndVertex, "end", "end"),
        col(LeftFace, "left face", "L face"),
        col(RightFace, "right face", "R face"),
        col(LeftPredecessor, "left pred", "L pred."),
        col(LeftSuccessor, "left succ", "L succ."),
        col(RightPredecessor, "right pred", "R pred."),
        col(RightSuccessor, "right succ", "R succ."),
    ];
    pub(super) const HALF_EDGE: &[TableColumn] = &[
        col(EndVertex, "end vertex", "end"),
        col(Face, "face", "face"),
        col(PairEdge, "pair", "pair"),
        col(SuccessorEdge, "successor", "succ."),
        derived(StartVertex, "start vertex", "start"),
        derived(PredecessorEdge, "predecessor", "pred."),
    ];
}

impl Column {
    /// The columns of one table of `structure`, in order: the stored ones,
    /// then the derived ones.
    pub fn table(structure: Structure, kind: ElementKind) -> &'static [TableColumn] {
        match (structure, kind) {
            (_, ElementKind::Vertex) => layout::VERTEX,
            (_, ElementKind::Face) => layout::FACE,
            (Structure::WingedEdge, ElementKind::Edge) => layout::WINGED_EDGE,
            (Structure::HalfEdge, ElementKind::Edge) => layout::HALF_EDGE,
        }
    }

    /// The column names of a table file's section, after the id: the
    /// coordinates, then every stored reference.
    pub fn file_columns(structure: Structure, kind: ElementKind) -> Vec<&'static str> {
        let mut names = Vec::new();
        for entry in Self::table(structure, kind) {
            match (entry.column, entry.storage) {
                (Self::Position, _) => names.extend(Self::COORDINATES),
                (column, Storage::Stored) => names.push(column.record_name()),
                (_, Storage::Derived) => {}
            }
        }
        names
    }

    /// Where the column is in `structure`'s tables, if it is.
    pub fn storage(self, structure: Structure) -> Option<Storage> {
        ElementKind::ALL.into_iter().find_map(|kind| {
            Self::table(structure, kind)
                .iter()
                .find(|entry| entry.column == self)
                .map(|entry| entry.storage)
        })
    }
}

/// Lookup names and the columns they read.
type LookupNames = &'static [(&'static str, Column)];

/// Every name the language accepts for a lookup, by the structure it is
/// limited to (`None`: both), the canonical name of each column first.
/// Names ignore case.
const LANGUAGE_NAMES: &[(Option<Structure>, LookupNames)] = &[
    (
        None,
        &[
            ("incidentEdge", Column::IncidentEdge),
            ("startVertex", Column::StartVertex),
            ("endVertex", Column::EndVertex),
            ("position", Column::Position),
        ],
    ),
    (
        Some(Structure::WingedEdge),
        &[
            ("leftFace", Column::LeftFace),
            ("rightFace", Column::RightFace),
            ("leftPredecessor", Column::LeftPredecessor),
            ("leftSuccessor", Column::LeftSuccessor),
            ("rightPredecessor", Column::RightPredecessor),
            ("rightSuccessor", Column::RightSuccessor),
        ],
    ),
    (
        Some(Structure::HalfEdge),
        &[
            ("adjacentFace", Column::Face),
            ("face", Column::Face),
            ("vertex", Column::EndVertex),
            ("pairEdge", Column::PairEdge),
            ("pair", Column::PairEdge),
            ("twin", Column::PairEdge),
            ("successorEdge", Column::SuccessorEdge),
            ("successor", Column::SuccessorEdge),
            ("next", Column::SuccessorEdge),
            ("predecessorEdge", Column::PredecessorEdge),
            ("predecessor", Column::PredecessorEdge),
            ("prev", Column::PredecessorEdge),
        ],
    ),
];

/// [`LANGUAGE_NAMES`] one name at a time: (name, column, limited to).
fn language_names() -> impl Iterator<Item = (&'static str, Column, Option<Structure>)> {
    LANGUAGE_NAMES.iter().flat_map(|&(only_in, names)| {
        names
            .iter()
            .map(move |&(name, column)| (name, column, only_in))
    })
}

/// Why a lookup name was refused, for the checker's message.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum NameError {
    /// No structure has a lookup of this name.
    Unknown,
    /// The other structure has it.
    OtherStructure(Structure),
    /// The structure has it, on another kind of element.
    WrongElement(ElementKind),
}

impl Column {
    /// The canonical lookup name in the language (`leftPredecessor`,
    /// `position`).
    pub fn language_name(self) -> Option<&'static str> {
        language_names()
            .find(|&(_, column, _)| column == self)
            .map(|(name, _, _)| name)
    }

    /// The name an algorithm reads the column by, or the record's where the
    /// language has none: what the app and traces say to students.
    pub fn lookup_name(self) -> &'static str {
        self.language_name().unwrap_or(self.record_name())
    }

    /// Resolves a lookup name (any case, any alias) on an element of `kind`
    /// in `structure`.
    pub fn resolve(structure: Structure, kind: ElementKind, name: &str) -> Result<Self, NameError> {
        let mut found_elsewhere = None;
        for (candidate, column, only_in) in language_names() {
            if !candidate.eq_ignore_ascii_case(name) {
                continue;
            }
            match only_in {
                Some(other) if other != structure => {
                    found_elsewhere = Some(NameError::OtherStructure(other));
                }
                _ if !column.applies_to(kind) => {
                    found_elsewhere = Some(NameError::WrongElement(column.owner()));
                }
                _ => return Ok(column),
            }
        }
        Err(found_elsewhere.unwrap_or(NameError::Unknown))
    }

    /// The lookup names (aliases included) valid on `kind` in `structure`.
    pub fn language_names_for(
        structure: Structure,
        kind: ElementKind,
    ) -> impl Iterator<Item = &'static str> {
        language_names()
            .filter(move |&(_, column, only_in)| {
                only_in.is_none_or(|s| s == structure) && column.applies_to(kind)
            })
            .map(|(name, _, _)| name)
    }

    /// The canonical (non-alias) lookup names valid on `kind` in
    /// `structure`, for hints.
    pub fn canonical_names_for(structure: Structure, kind: ElementKind) -> Vec<&'static str> {
        Self::language_names_for(structure, kind)
            .filter(|&name| {
                Self::resolve(structure, kind, name)
                    .is_ok_and(|column| column.language_name() == Some(name))
            })
            .collect()
    }

    /// Every lookup name of either structure.
    pub fn all_language_names() -> impl Iterator<Item = &'static str> {
        language_names().map(|(name, _, _)| name)
    }
}

/// A table row whose columns can be read and written by [`Column`]: the file
/// readers fill rows this way, and [`Records::reference`] reads them.
pub trait Record: Default {
    /// The row number `column` holds (`Some(None)` for an empty reference),
    /// or `None` if this record does not store `column`.
    fn get(&self, column: Column) -> Option<Option<u32>>;

    /// Stores `value` (a row number, or none) in `column`. Columns the
    /// record does not store are ignored.
    fn set(&mut self, column: Column, value: Option<u32>);
}

/// A reference a mesh could not give: the row does not exist, or its table
/// has no such column.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum LookupError {
    NoSuchElement(ElementRef),
    /// An edit deleted the row.
    Deleted(ElementRef),
    NotApplicable {
        element: ElementRef,
        column: Column,
    },
}

impl fmt::Display for LookupError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::NoSuchElement(element) => write!(f, "{element} does not exist in this mesh"),
            Self::Deleted(element) => write!(f, "{element} was deleted"),
            Self::NotApplicable { element, column } => {
                write!(f, "{element} has no {}", column.lookup_name())
            }
        }
    }
}

impl std::error::Error for LookupError {}

/// A mesh's tables, read column by column.
pub trait Records {
    /// The structure whose tables these are.
    fn structure(&self) -> Structure;

    /// The number of rows in one table (half-edges, for a half-edge mesh's
    /// edge table).
    fn count(&self, kind: ElementKind) -> usize;

    /// A vertex's position, the one column that is not a reference.
    fn position(&self, vertex: VertexId) -> Option<Vec3>;

    /// The reference `column` of `element`'s row holds (or derives).
    /// `Ok(None)` is a legitimately missing reference: the face beyond a
    /// boundary edge, or the incident edge of an isolated vertex.
    fn reference(
        &self,
        element: ElementRef,
        column: Column,
    ) -> Result<Option<ElementRef>, LookupError>;

    /// Whether the row exists (and was not deleted).
    fn contains(&self, element: ElementRef) -> bool {
        (element.id as usize) < self.count(element.kind)
    }
}

/// The three tables of one structure, as slices of [`Record`]s; every such
/// mesh is [`Records`].
pub trait Rows {
    type Vertex: Record;
    type Face: Record;
    type Edge: Record;

    fn structure(&self) -> Structure;
    fn vertex_rows(&self) -> &[Self::Vertex];
    fn face_rows(&self) -> &[Self::Face];
    /// Edges, or half-edges.
    fn edge_rows(&self) -> &[Self::Edge];
    fn position(&self, vertex: VertexId) -> Option<Vec3>;
    /// Rows an edit deleted.
    fn deleted(&self) -> &Deleted;

    /// A column the structure computes instead of storing (a half-edge's
    /// start vertex and predecessor), or `None` if it has no such column.
    fn derived(&self, _edge: u32, _column: Column) -> Option<Option<ElementRef>> {
        None
    }
}

impl<T: Rows> Records for T {
    fn structure(&self) -> Structure {
        Rows::structure(self)
    }

    fn count(&self, kind: ElementKind) -> usize {
        match kind {
            ElementKind::Vertex => self.vertex_rows().len(),
            ElementKind::Edge => self.edge_rows().len(),
            ElementKind::Face => self.face_rows().len(),
        }
    }

    fn position(&self, vertex: VertexId) -> Option<Vec3> {
        Rows::position(self, vertex)
    }

    fn contains(&self, element: ElementRef) -> bool {
        (element.id as usize) < self.count(element.kind) && !self.deleted().contains(element)
    }

    #[inline]
    fn reference(
        &self,
        element: ElementRef,
        column: Column,
    ) -> Result<Option<ElementRef>, LookupError> {
        if self.deleted().contains(element) {
            return Err(LookupError::Deleted(element));
        }
        let index = element.id as usize;
        let stored = match element.kind {
            ElementKind::Vertex => self.vertex_rows().get(index).map(|row| row.get(column)),
            ElementKind::Face => self.face_rows().get(index).map(|row| row.get(column)),
            ElementKind::Edge => self.edge_rows().get(index).map(|row| row.get(column)),
        };
        let not_applicable = LookupError::NotApplicable { element, column };
        match stored.ok_or(LookupError::NoSuchElement(element))? {
            Some(value) => {
                let target = column.target().ok_or(not_applicable)?;
                Ok(value.map(|id| ElementRef::new(target, id)))
            }
            None if element.kind == ElementKind::Edge => {
                self.derived(element.id, column).ok_or(not_applicable)
            }
            None => Err(not_applicable),
        }
    }
}

/// Why a write into a record was refused.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum WriteError {
    NoSuchElement(ElementRef),
    /// An edit deleted the row.
    Deleted(ElementRef),
    /// The structure does not store this column in this row: it derives it,
    /// or another kind of row holds it.
    NotStored {
        element: ElementRef,
        column: Column,
    },
    /// The column refers to another kind of element.
    WrongKind {
        column: Column,
        found: ElementRef,
    },
    /// The column must refer to something.
    Empty {
        element: ElementRef,
        column: Column,
    },
}

impl fmt::Display for WriteError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Self::NoSuchElement(element) => write!(f, "{element} does not exist in this mesh"),
            Self::Deleted(element) => write!(f, "{element} was deleted; its row cannot be written"),
            Self::NotStored { element, column } => {
                write!(f, "{element} does not store a {}", column.key())
            }
            Self::WrongKind { column, found } => match column.target() {
                Some(kind) => write!(
                    f,
                    "the {} column holds {}, not {found}",
                    column.key(),
                    kind.plural()
                ),
                None => write!(f, "the {} column holds no reference", column.key()),
            },
            Self::Empty { element, column } => {
                write!(f, "the {} of {element} cannot be empty", column.key())
            }
        }
    }
}

impl std::error::Error for WriteError {}

/// The tables of [`Rows`], writable.
pub trait RowsMut: Rows {
    fn vertex_rows_mut(&mut self) -> &mut [Self::Vertex];
    fn face_rows_mut(&mut self) -> &mut [Self::Face];
    fn edge_rows_mut(&mut self) -> &mut [Self::Edge];
}

/// A mesh's tables, written column by column: what an edit does one
/// pointer at a time. A write may leave the tables inconsistent (an edit
/// passes through such states); `validate` says where.
pub trait RecordsMut: Records {
    /// Stores `target` (or nothing) in `column` of `element`'s row.
    fn set_reference(
        &mut self,
        element: ElementRef,
        column: Column,
        target: Option<ElementRef>,
    ) -> Result<(), WriteError>;

    /// Empties `column` of `element`'s row even where the column needs a
    /// reference, leaving it unset as in a new row: how a journal takes back
    /// the first write into a new row.
    fn unset_reference(&mut self, element: ElementRef, column: Column) -> Result<(), WriteError>;
}

/// Checks a write against the column's kind and nullability, then stores it.
fn write<R: Record>(
    rows: &mut [R],
    element: ElementRef,
    column: Column,
    target: Option<ElementRef>,
    unset: bool,
) -> Result<(), WriteError> {
    let row = rows
        .get_mut(element.id as usize)
        .ok_or(WriteError::NoSuchElement(element))?;
    if row.get(column).is_none() {
        return Err(WriteError::NotStored { element, column });
    }
    match target {
        Some(found) if Some(found.kind) != column.target() => {
            Err(WriteError::WrongKind { column, found })
        }
        None if !unset && !column.nullable_in(element.kind) => {
            Err(WriteError::Empty { element, column })
        }
        _ => {
            row.set(column, target.map(|t| t.id));
            Ok(())
        }
    }
}

impl<T: RowsMut + EditHooks> RecordsMut for T {
    fn set_reference(
        &mut self,
        element: ElementRef,
        column: Column,
        target: Option<ElementRef>,
    ) -> Result<(), WriteError> {
        write_row(self, element, column, target, false)
    }

    fn unset_reference(&mut self, element: ElementRef, column: Column) -> Result<(), WriteError> {
        write_row(self, element, column, None, true)
    }
}

fn write_row<T: RowsMut + EditHooks>(
    mesh: &mut T,
    element: ElementRef,
    column: Column,
    target: Option<ElementRef>,
    unset: bool,
) -> Result<(), WriteError> {
    if mesh.deleted().contains(element) {
        return Err(WriteError::Deleted(element));
    }
    match element.kind {
        ElementKind::Vertex => write(mesh.vertex_rows_mut(), element, column, target, unset),
        ElementKind::Face => write(mesh.face_rows_mut(), element, column, target, unset),
        ElementKind::Edge => write(mesh.edge_rows_mut(), element, column, target, unset),
    }?;
    mesh.written(column);
    Ok(())
}

/// What a structure keeps derived from its records, dropped after a write.
pub trait EditHooks {
    /// `column` of some row was written.
    fn written(&mut self, _column: Column) {}
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lookups_resolve_by_structure_and_element() {
        use ElementKind as K;
        use Structure::{HalfEdge, WingedEdge};
        assert_eq!(
            Column::resolve(HalfEdge, K::Edge, "TWIN"),
            Ok(Column::PairEdge)
        );
        assert_eq!(
            Column::resolve(WingedEdge, K::Face, "incidentEdge"),
            Ok(Column::IncidentEdge)
        );
        assert_eq!(
            Column::resolve(HalfEdge, K::Edge, "leftFace"),
            Err(NameError::OtherStructure(WingedEdge))
        );
        assert_eq!(
            Column::resolve(WingedEdge, K::Vertex, "startVertex"),
            Err(NameError::WrongElement(K::Edge))
        );
        assert_eq!(
            Column::resolve(WingedEdge, K::Edge, "sideways"),
            Err(NameError::Unknown)
        );
    }

    #[test]
    fn every_name_of_a_column_comes_from_one_row() {
        let column = Column::LeftPredecessor;
        assert_eq!(column.record_name(), "left_predecessor");
        assert_eq!(column.title(), "Left Predecessor");
        assert_eq!(column.key(), "left predecessor");
        assert_eq!(column.setting_key(), "leftPredecessor");
        assert_eq!(column.language_name(), Some("leftPredecessor"));
        assert_eq!(Column::Face.language_name(), Some("adjacentFace"));
        assert_eq!(Column::Position.language_name(), Some("position"));
    }

    #[test]
    fn a_write_is_read_back_and_a_bad_one_is_refused_with_the_reason() {
        use crate::mesh::{HalfEdgeMesh, Polygons, WingedEdgeMesh, generate};
        let polygons = Polygons::from_triangles(
            vec![Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::ONE],
            &[[0, 1, 2], [2, 1, 3]],
        );
        let (mut winged, _) = WingedEdgeMesh::build(&polygons).expect("two triangles");
        let edge = ElementRef::new(ElementKind::Edge, 0);
        let other = Some(ElementRef::new(ElementKind::Edge, 3));
        winged
            .set_reference(edge, Column::RightSuccessor, other)
            .expect("a stored wing");
        assert_eq!(winged.reference(edge, Column::RightSuccessor), Ok(other));
        assert_eq!(winged.set_reference(edge, Column::LeftFace, None), Ok(()));
        let vertex = Some(ElementRef::new(ElementKind::Vertex, 1));
        let refused = winged.set_reference(edge, Column::LeftSuccessor, vertex);
        assert_eq!(
            refused.map_err(|e| e.to_string()),
            Err("the left successor column holds edges, not vertex 1".to_owned())
        );
        let refused = winged.set_reference(edge, Column::StartVertex, None);
        assert_eq!(
            refused.map_err(|e| e.to_string()),
            Err("the start vertex of edge 0 cannot be empty".to_owned())
        );

        let (mut half, _) = HalfEdgeMesh::build(&generate::grid(2, 1)).expect("a strip");
        let h = ElementRef::new(ElementKind::Edge, 0);
        assert_eq!(
            half.set_reference(h, Column::StartVertex, vertex),
            Err(WriteError::NotStored {
                element: h,
                column: Column::StartVertex
            })
        );
        // The predecessor, derived from the successors, follows the writes:
        // h's old predecessor now loops on itself, and half-edge 5 leads to h.
        let old = half
            .reference(h, Column::PredecessorEdge)
            .expect("exists")
            .expect("h has a predecessor");
        let new = ElementRef::new(ElementKind::Edge, 5);
        assert_ne!(old, new);
        half.set_reference(old, Column::SuccessorEdge, Some(old))
            .expect("a stored link");
        half.set_reference(new, Column::SuccessorEdge, Some(h))
            .expect("a stored link");
        assert_eq!(half.reference(h, Column::PredecessorEdge), Ok(Some(new)));
    }

    #[test]
    fn file_columns_are_the_stored_record_names() {
        assert_eq!(
            Column::file_columns(Structure::HalfEdge, ElementKind::Edge),
            ["end_vertex", "face", "pair_edge", "successor_edge"]
        );
        assert_eq!(
            Column::file_columns(Structure::WingedEdge, ElementKind::Vertex),
            ["x", "y", "z", "incident_edge"]
        );
        assert_eq!(
            Column::PredecessorEdge.storage(Structure::HalfEdge),
            Some(Storage::Derived)
        );
        assert_eq!(Column::PairEdge.storage(Structure::WingedEdge), None);
    }

    #[test]
    fn every_column_is_in_some_table_and_the_language() {
        for column in Column::ALL {
            let in_a_table = Structure::ALL
                .into_iter()
                .any(|structure| column.storage(structure).is_some());
            assert!(in_a_table, "{column:?}");
            assert!(column.language_name().is_some(), "{column:?}");
        }
    }
}
