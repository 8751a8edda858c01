//! The renderer: the 3D view of a mesh, drawn with wgpu through egui paint
//! callbacks, and the cache that copies unchanged parts of the UI from
//! textures. It knows meshes (from core), egui's layout types and wgpu; it
//! knows nothing of the app's documents, tables or algorithms, which hand it
//! geometry, styles and options.

mod texture_copy;
pub mod ui_cache;
pub mod view3d;
