//! The record vocabulary: which structures there are, which kinds of element
//! their tables hold, and every column of every table, with all the names a
//! column goes by. The tables, selection roles, trace frames, file readers and
//! writers, the listing, `validate` and the language's lookups all take their
//! columns from here, so a column is named in this module and nowhere else.
//!
//! - [`Structure`]: winged-edge or half-edge, with its names in code, prose
//!   and links.
//! - [`ElementKind`] and [`ElementRef`]: a vertex, edge or face row. In a
//!   half-edge structure an edge row is a half-edge.
//! - [`Column`]: one table column, its names, whether the structure stores or
//!   derives it, [`Records::reference`] to read it from a mesh and
//!   [`RecordsMut::set_reference`] to write it, one pointer at a time.

mod column;
pub mod deleted;
mod element;
pub mod ids;
mod structure;

pub use column::{
    Column, EditHooks, LookupError, NameError, Palette, Record, Records, RecordsMut, Rows, RowsMut,
    Storage, TableColumn, WriteError,
};
pub use deleted::Deleted;
pub(crate) use element::article;
pub use element::{ElementKind, ElementRef};
pub use structure::Structure;
