//! Winged-edge and half-edge mesh structures, built from polygons, checked and
//! navigable, following the conventions of the papers the product teaches
//! (Neperud and Shene for winged-edge, Neperud section 2.2 for half-edge).
//!
//! - [`Polygons`] is the builder input every loader produces.
//! - [`HalfEdgeMesh::build`] and [`WingedEdgeMesh::build`] refuse bad input
//!   with a [`BuildError`] and report kept oddities as [`BuildWarning`]s; a
//!   vertex where separate fans of faces meet is split, one vertex per fan.
//! - [`HalfEdgeMesh::from_raw_parts`] / [`WingedEdgeMesh::from_raw_parts`] take
//!   tables as written; `validate()` lists each [`Issue`] by element and field.
//! - `stats()`, the conversions and the walks of [`Navigation`] (one
//!   [`Circulator`] over each structure's [`Ring`]s) work on both.

mod builder;
pub mod circulator;
pub mod convert;
pub use crate::schema::deleted;
pub mod edit;
pub mod error;
pub mod generate;
pub mod grade;
pub mod half_edge;
pub use crate::schema::ids;
pub mod navigation;
pub mod operations;
pub mod polygons;
mod records;
pub mod stats;
pub mod structure;
mod tables;
mod traversal;
pub mod validate;
pub mod winged_edge;

pub use crate::schema::Structure;
pub use circulator::{Circulator, Ring};
pub use convert::{ConvertError, EdgeCorrespondence};
pub use deleted::Deleted;
pub use edit::{Change, Edit, EditError, Editor, Renumbering};
pub use error::{BuildError, BuildWarning, FaceRef};
pub use half_edge::{HalfEdge, HalfEdgeMesh};
pub use ids::{EdgeId, FaceId, HalfEdgeId, VertexId};
pub use navigation::{AroundFace, AroundVertex, Navigation};
pub use operations::{Applied, EdgeRow, Operation, Refusal};
pub use polygons::Polygons;
pub use stats::{ComponentStats, MeshStats};
pub use structure::Mesh;
pub use validate::{Element, Issue};
pub use winged_edge::{Side, WingedEdge, WingedEdgeMesh};
