//! Why a polygon list cannot become a mesh, and what a build kept but noticed.

use std::fmt;

use super::ids::{FaceId, VertexId};

/// A face named in a message, with the file line it came from when known.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct FaceRef {
    /// The face number in the polygon list.
    pub face: FaceId,
    /// The 1-based source line, when the face was read from a file.
    pub line: Option<usize>,
}

impl fmt::Display for FaceRef {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.line {
            Some(line) => write!(f, "{} (line {line})", self.face),
            None => write!(f, "{}", self.face),
        }
    }
}

/// A polygon list the builder refuses. Each variant names the elements
/// involved so the message can be acted on.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum BuildError {
    /// A face lists fewer than three vertices.
    TooFewVertices {
        /// The face.
        face: FaceRef,
        /// How many vertices it lists.
        count: usize,
    },
    /// A face lists the same vertex twice, so it has fewer distinct vertices
    /// than corners.
    RepeatedVertex {
        /// The face.
        face: FaceRef,
        /// The vertex it repeats.
        vertex: VertexId,
    },
    /// A face refers to a vertex number that does not exist.
    IndexOutOfRange {
        /// The face.
        face: FaceRef,
        /// The vertex number it uses.
        index: u32,
        /// How many vertices there are.
        vertex_count: usize,
    },
    /// An edge is shared by more than two faces.
    NonManifoldEdge {
        /// The lower-numbered end of the edge.
        start: VertexId,
        /// The other end.
        end: VertexId,
        /// Every face using the edge, in face order.
        faces: Vec<FaceRef>,
    },
    /// Two faces traverse a shared edge in the same direction, so their
    /// orientations disagree.
    InconsistentOrientation {
        /// Where both faces' traversal of the edge starts.
        start: VertexId,
        /// Where it ends.
        end: VertexId,
        /// The lower-numbered face.
        first: FaceRef,
        /// The other face.
        second: FaceRef,
    },
    /// The faces around a vertex form more than one fan (for example two cones
    /// touching at their tips). The builds split such a vertex instead (see
    /// [`BuildWarning::SplitVertex`]), so this reaches callers only if the
    /// split could not be made.
    NonManifoldVertex {
        /// The vertex.
        vertex: VertexId,
        /// A face of one fan.
        first: FaceRef,
        /// A face of another fan.
        second: FaceRef,
    },
    /// More elements than the `u32` ids (and the builder's tag bit) allow.
    TooLarge {
        /// What there are too many of.
        element: &'static str,
        /// How many there are.
        count: usize,
        /// The most supported.
        limit: usize,
    },
}

impl fmt::Display for BuildError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        self.write_numbered(f, 0)
    }
}

impl BuildError {
    /// The message with vertices numbered from `first`, as the input
    /// numbers them: OBJ from 1, so that `f 6 7 3 2` is about vertices 6
    /// and 7, not the tables' ids 5 and 6.
    pub fn numbered_from(&self, first: u32) -> impl fmt::Display + '_ {
        Numbered(move |f: &mut fmt::Formatter<'_>| self.write_numbered(f, first))
    }

    fn write_numbered(&self, f: &mut fmt::Formatter<'_>, base: u32) -> fmt::Result {
        let vertex = |v: &VertexId| InputVertex(*v, base);
        match self {
            Self::TooFewVertices { face, count } => {
                write!(f, "{face} has {count} vertices; a face needs at least 3")
            }
            Self::RepeatedVertex { face, vertex: v } => {
                write!(
                    f,
                    "{face} lists {} more than once; a face needs distinct vertices",
                    vertex(v)
                )
            }
            Self::IndexOutOfRange {
                face,
                index,
                vertex_count: 0,
            } => {
                write!(
                    f,
                    "{face} refers to vertex {index}, but the mesh has no vertices"
                )
            }
            Self::IndexOutOfRange {
                face,
                index,
                vertex_count,
            } => write!(
                f,
                "{face} refers to vertex {index}, but the mesh has only {vertex_count} vertices (0 to {})",
                vertex_count - 1
            ),
            Self::NonManifoldEdge { start, end, faces } => {
                write!(
                    f,
                    "the edge between {} and {} is used by {} faces (",
                    vertex(start),
                    vertex(end),
                    faces.len()
                )?;
                for (i, face) in faces.iter().enumerate() {
                    if i > 0 {
                        f.write_str(", ")?;
                    }
                    write!(f, "{face}")?;
                }
                f.write_str("); an edge can border at most two faces (non-manifold edge)")
            }
            Self::InconsistentOrientation {
                start,
                end,
                first,
                second,
            } => write!(
                f,
                "{first} and {second} both go from {} to {}; faces sharing an edge must \
                 traverse it in opposite directions (inconsistent orientation: reverse one of them)",
                vertex(start),
                vertex(end)
            ),
            Self::NonManifoldVertex {
                vertex: v,
                first: one,
                second,
            } => write!(
                f,
                "{} joins separate fans of faces ({one} and {second} are not connected \
                 around it); the faces around a vertex must form one fan (non-manifold vertex)",
                vertex(v)
            ),
            Self::TooLarge {
                element,
                count,
                limit,
            } => {
                write!(
                    f,
                    "the mesh has {count} {element}; at most {limit} are supported"
                )
            }
        }
    }
}

impl std::error::Error for BuildError {}

/// A vertex as its input numbers it: the id plus the input's first number.
struct InputVertex(VertexId, u32);

impl fmt::Display for InputVertex {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.1 == 0 || self.0.is_unset() {
            return self.0.fmt(f);
        }
        write!(f, "vertex {}", u64::from(self.0.raw()) + u64::from(self.1))
    }
}

/// A message written by a closure (a message in the input's numbering).
struct Numbered<F>(F);

impl<F: Fn(&mut fmt::Formatter<'_>) -> fmt::Result> fmt::Display for Numbered<F> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        (self.0)(f)
    }
}

/// Something a build noticed but kept.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum BuildWarning {
    /// A vertex no face uses; it stays in the mesh as an isolated vertex.
    UnusedVertex {
        /// The vertex.
        vertex: VertexId,
    },
    /// Separate fans of faces met at a vertex (two holes touching at a corner,
    /// two cones sharing a tip). It was split into one vertex per fan at the
    /// same position, so the structures stay manifold: the fan with the
    /// vertex's first corner kept it, the others use the copies.
    SplitVertex {
        /// The vertex as numbered in the input.
        vertex: VertexId,
        /// The new vertices, numbered after the input's, one per extra fan.
        copies: Vec<VertexId>,
    },
}

impl BuildWarning {
    /// The input vertex the warning is about (for finding its source line).
    pub fn vertex(&self) -> VertexId {
        match self {
            Self::UnusedVertex { vertex } | Self::SplitVertex { vertex, .. } => *vertex,
        }
    }
}

impl fmt::Display for BuildWarning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::UnusedVertex { vertex } => {
                write!(
                    f,
                    "{vertex} is not used by any face; it is kept as an isolated vertex"
                )
            }
            Self::SplitVertex { vertex, copies } => {
                write!(
                    f,
                    "{vertex} joined {} fans of faces; split into {}",
                    copies.len() + 1,
                    vertex.raw()
                )?;
                for (i, copy) in copies.iter().enumerate() {
                    let separator = if i + 1 == copies.len() { " and " } else { ", " };
                    write!(f, "{separator}{}", copy.raw())?;
                }
                Ok(())
            }
        }
    }
}
