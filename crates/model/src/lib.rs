//! The model: what Edgewise shows, without drawing it. An open mesh with its
//! selection ([`document`]), an algorithm's run and what each of its steps
//! shows ([`algorithm`]), the colours a moment is painted in ([`paint`],
//! [`theme`], [`settings`]), course links ([`course_link`]) and the built-in
//! samples, and the SCORM packages an LMS imports ([`package`]). The app draws these with egui and the renderer; `edgewise
//! render` writes their pictures with no window ([`still`]).

pub mod algorithm;
pub mod course_link;
pub mod document;
pub mod message;
pub mod moment;
pub mod package;
pub mod paint;
pub mod practice;
pub mod samples;
pub mod selection;
pub mod settings;
pub mod still;
pub mod theme;
pub mod trace_role;
