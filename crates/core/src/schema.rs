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
//!   derives it, and [`Records::reference`] to read it from a mesh.

mod column;
mod element;
mod structure;

pub use column::{
    Column, LookupError, NameError, Palette, Record, Records, Rows, Storage, TableColumn,
};
pub use element::{ElementKind, ElementRef};
pub use structure::Structure;
