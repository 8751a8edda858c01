//! The reading and writing the two table formats share: `.wtb` and `.htb`
//! hold a vertex, a face and an edge (or half-edge) section whose columns are
//! the structure's stored columns ([`Column::file_columns`]), so one reader
//! and one writer serve both, and each format only says what differs.

use glam::Vec3;

use super::error::{FormatError, Problem};
use super::rows::{self, Problems, RowPlaces, Rows as Lines, Section};
use crate::mesh::{Element, Issue, Mesh};
use crate::schema::{
    Column, ElementKind, ElementRef, Record, RecordsMut, Rows, Storage, Structure,
};

/// A structure a table file holds.
pub(super) trait TableFile: Rows + Sized {
    /// The header word (`wtb`), and the other format's.
    const MAGIC: &'static str;
    const OTHER: &'static str;
    /// The comment lines written before the header.
    const PREAMBLE: &'static str;
    /// The edge section.
    const EDGES: Section;

    /// The tables as written, unchecked.
    fn from_tables(
        vertices: Vec<(Vec3, Self::Vertex)>,
        faces: Vec<Self::Face>,
        edges: Vec<Self::Edge>,
    ) -> Self;

    /// Whether `element` is a row of this structure's edge table (an edge,
    /// or a half-edge), to place validation issues.
    fn is_edge_row(element: Element) -> bool;

    fn into_mesh(self) -> Mesh;

    fn validate(&self) -> Vec<Issue>;
}

/// Implements [`TableFile`] for a structure: its mesh type, its `Mesh`
/// variant, its validation element for edge rows, its vertex record, the
/// header words, the preamble and the edge section.
macro_rules! table_file {
    (
        $mesh:ident, $variant:ident, $edge_element:ident, $vertex:ident,
        magic: $magic:literal, other: $other:literal, preamble: $preamble:expr,
        edges: $section:literal of $element:literal in $structure:expr $(,)?
    ) => {
        impl $crate::formats::tables::TableFile for $mesh {
            const MAGIC: &'static str = $magic;
            const OTHER: &'static str = $other;
            const PREAMBLE: &'static str = $preamble;
            const EDGES: $crate::formats::rows::Section = $crate::formats::rows::Section {
                name: $section,
                element: $element,
                table: ($structure, $crate::schema::ElementKind::Edge),
            };

            fn from_tables(
                vertices: Vec<(glam::Vec3, $vertex)>,
                faces: Vec<Self::Face>,
                edges: Vec<Self::Edge>,
            ) -> Self {
                let vertices = vertices
                    .into_iter()
                    .map(|(position, vertex)| $vertex { position, ..vertex })
                    .collect();
                Self::from_raw_parts(vertices, faces, edges)
            }

            fn is_edge_row(element: $crate::mesh::Element) -> bool {
                matches!(element, $crate::mesh::Element::$edge_element(_))
            }

            fn into_mesh(self) -> $crate::mesh::Mesh {
                $crate::mesh::Mesh::$variant(self)
            }

            fn validate(&self) -> Vec<$crate::mesh::Issue> {
                $mesh::validate(self)
            }
        }
    };
}

pub(super) use table_file;

/// The vertex section of `structure`'s file.
fn vertex_section(structure: Structure) -> Section {
    Section {
        name: "vertices",
        element: "vertex",
        table: (structure, ElementKind::Vertex),
    }
}

/// The face section of `structure`'s file.
fn face_section(structure: Structure) -> Section {
    Section {
        name: "faces",
        element: "face",
        table: (structure, ElementKind::Face),
    }
}

/// Reads one section into records, `prefix` reading what comes before the
/// references (a vertex's coordinates).
fn read_section<R: Record, T>(
    lines: &mut Lines<'_>,
    problems: &mut Problems,
    section: &Section,
    mut prefix: impl FnMut(&[rows::Token<'_>], usize, &mut Problems) -> T,
) -> Result<(Vec<(T, R)>, RowPlaces), FormatError> {
    let mut records = Vec::new();
    let places = rows::section(lines, section, problems, |fields, line, problems| {
        let before = prefix(fields, line, problems);
        let mut record = R::default();
        rows::fill(&mut record, fields, section, line, problems);
        records.push((before, record));
    })?;
    Ok((records, places))
}

/// A table file's tables as written, before any rule is checked, with
/// where each row was, to place problems.
struct Read<'t, M> {
    mesh: M,
    text: &'t str,
    vertex_places: RowPlaces,
    face_places: RowPlaces,
    edge_places: RowPlaces,
}

impl<M: TableFile> Read<'_, M> {
    /// `issues` at the line and column of each field.
    fn place(&self, issues: Vec<Issue>) -> FormatError {
        rows::place_issues(issues, self.text, |element| match element {
            Element::Vertex(_) => Some(&self.vertex_places),
            Element::Face(_) => Some(&self.face_places),
            edge if M::is_edge_row(edge) => Some(&self.edge_places),
            _ => None,
        })
    }
}

/// Reads the rows of a table file of structure `M`; a malformed row is
/// refused at its line and column.
fn read_rows<M: TableFile>(bytes: &[u8]) -> Result<Read<'_, M>, FormatError> {
    let text = super::text(bytes)?;
    let mut lines = Lines::new(text);
    rows::header(&mut lines, M::MAGIC, M::OTHER)?;
    let structure = M::EDGES.table.0;
    let mut problems = Problems::new();
    let coordinates = |fields: &[rows::Token<'_>], line, problems: &mut Problems| {
        let [x, y, z] = Column::COORDINATES;
        let mut axis = |index: usize, name| {
            fields
                .get(index)
                .map_or(0.0, |token| rows::coordinate(token, name, line, problems))
        };
        Vec3::new(axis(0, x), axis(1, y), axis(2, z))
    };
    let (vertices, vertex_places) = read_section(
        &mut lines,
        &mut problems,
        &vertex_section(structure),
        coordinates,
    )?;
    let (faces, face_places) = read_section(
        &mut lines,
        &mut problems,
        &face_section(structure),
        |_, _, _| (),
    )?;
    let (edges, edge_places) = read_section(&mut lines, &mut problems, &M::EDGES, |_, _, _| ())?;
    rows::end(&mut lines, &M::EDGES, edges.len())?;
    problems.finish()?;
    Ok(Read {
        mesh: M::from_tables(
            vertices,
            faces.into_iter().map(|((), face)| face).collect(),
            edges.into_iter().map(|((), edge)| edge).collect(),
        ),
        text,
        vertex_places,
        face_places,
        edge_places,
    })
}

/// Reads a table file of structure `M`, placing every problem, and every
/// rule the tables break, at its line and column.
pub(super) fn read<M: TableFile>(bytes: &[u8]) -> Result<Mesh, FormatError> {
    let read = read_rows::<M>(bytes)?;
    let issues = read.mesh.validate();
    if issues.is_empty() {
        return Ok(read.mesh.into_mesh());
    }
    Err(read.place(issues))
}

/// Reads a table file of structure `M` for diagnosis: tables that break the
/// structure's rules are kept, for a student to find and fix what is wrong.
/// A malformed row is still refused. A reference to a row past the end of
/// its table is read as unset, so that nothing downstream follows it; each
/// such reference is returned as a problem at its field.
pub(super) fn read_for_diagnosis<M: TableFile + RecordsMut>(
    bytes: &[u8],
) -> Result<(Mesh, Vec<Problem>), FormatError> {
    let mut read = read_rows::<M>(bytes)?;
    let structure = M::EDGES.table.0;
    let mut unset = Vec::new();
    for kind in ElementKind::ALL {
        let stored = Column::table(structure, kind)
            .iter()
            .filter(|entry| entry.storage == Storage::Stored);
        for entry in stored {
            for id in 0..read.mesh.count(kind) as u32 {
                let row = ElementRef::new(kind, id);
                let Ok(Some(target)) = read.mesh.reference(row, entry.column) else {
                    continue;
                };
                let rows = read.mesh.count(target.kind);
                if (target.id as usize) < rows {
                    continue;
                }
                if read.mesh.unset_reference(row, entry.column).is_ok() {
                    unset.push(Issue {
                        element: Element::of(structure, row),
                        field: entry.column,
                        message: format!(
                            "{} does not exist (there are {rows}); read as unset",
                            Element::of(structure, target)
                        ),
                    });
                }
            }
        }
    }
    let problems = if unset.is_empty() {
        Vec::new()
    } else {
        read.place(unset).problems().to_vec()
    };
    Ok((read.mesh.into_mesh(), problems))
}

/// Writes `mesh`'s tables as its structure's table file.
pub(super) fn write<M: TableFile>(mesh: &M) -> String {
    let structure = M::EDGES.table.0;
    let mut out = format!("{}{} 1\n", M::PREAMBLE, M::MAGIC);
    rows::write_section(&mut out, mesh, &vertex_section(structure));
    rows::write_section(&mut out, mesh, &face_section(structure));
    rows::write_section(&mut out, mesh, &M::EDGES);
    out
}
