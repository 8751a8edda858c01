//! The pictures: what a view of a mesh shows, as plain data, and the SVG
//! and PDF files made of it. A camera, the mesh's geometry, each element's
//! style and the view options describe a view; [`vector`] turns one into
//! flat shapes, and [`svg`] and [`pdf`] write them beside the tables.
//!
//! It knows meshes (from core) and small value types (glam's vectors,
//! emath's points and ecolor's colours); no window, GPU or UI. The GPU
//! renderer draws the same description, and `edgewise render` writes
//! pictures without either.

pub mod camera;
pub mod geometry;
pub mod options;
pub mod palette;
pub mod pdf;
pub mod scene;
pub mod styles;
pub mod svg;
pub mod text_table;
pub mod vector;
