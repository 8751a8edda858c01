//! Element kinds and references to rows, shared by the language, the app and
//! the 3D view, so that no layer passes a bare row number.

use std::fmt;

use super::ids::{EdgeId, FaceId, HalfEdgeId, VertexId};

/// The three kinds of mesh element, one table each.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "lowercase"))]
pub enum ElementKind {
    Vertex,
    Edge,
    Face,
}

impl ElementKind {
    /// The three kinds, in the order the papers list the tables.
    pub const ALL: [ElementKind; 3] = [ElementKind::Vertex, ElementKind::Edge, ElementKind::Face];

    /// "vertices", "edges", "faces".
    pub fn plural(self) -> &'static str {
        match self {
            ElementKind::Vertex => "vertices",
            ElementKind::Edge => "edges",
            ElementKind::Face => "faces",
        }
    }

    /// Lower-case, as elements are shown in traces: "vertex 3".
    pub fn prose(self) -> &'static str {
        match self {
            ElementKind::Vertex => "vertex",
            ElementKind::Edge => "edge",
            ElementKind::Face => "face",
        }
    }

    /// "Vertex", "Edge" or "Face", as in role labels.
    pub fn title(self) -> &'static str {
        match self {
            ElementKind::Vertex => "Vertex",
            ElementKind::Edge => "Edge",
            ElementKind::Face => "Face",
        }
    }

    /// Parses the JavaScript API's and links' kind names.
    pub fn parse(name: &str) -> Option<Self> {
        match name {
            "vertex" => Some(Self::Vertex),
            "edge" | "halfedge" | "half-edge" => Some(Self::Edge),
            "face" => Some(Self::Face),
            _ => None,
        }
    }
}

/// One row of one table: its kind and its number in that table. In a
/// half-edge structure an edge row is a half-edge.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct ElementRef {
    pub kind: ElementKind,
    pub id: u32,
}

impl ElementRef {
    pub const fn new(kind: ElementKind, id: u32) -> Self {
        Self { kind, id }
    }

    pub const fn vertex(v: VertexId) -> Self {
        Self::new(ElementKind::Vertex, v.raw())
    }

    pub const fn edge(e: EdgeId) -> Self {
        Self::new(ElementKind::Edge, e.raw())
    }

    pub const fn half_edge(h: HalfEdgeId) -> Self {
        Self::new(ElementKind::Edge, h.raw())
    }

    pub const fn face(f: FaceId) -> Self {
        Self::new(ElementKind::Face, f.raw())
    }
}

/// A typed id is a reference to its row.
macro_rules! from_id {
    ($($id:ty => $make:ident),*) => {$(
        impl From<$id> for ElementRef {
            fn from(id: $id) -> Self {
                Self::$make(id)
            }
        }
    )*};
}

from_id!(VertexId => vertex, EdgeId => edge, HalfEdgeId => half_edge, FaceId => face);

/// "vertex 3", "edge 7", "face 0".
impl fmt::Display for ElementRef {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} {}", self.kind.prose(), self.id)
    }
}

/// "a" or "an" before `word`, for messages that name a kind or a column.
pub(crate) fn article(word: &str) -> &'static str {
    if word.starts_with(['a', 'e', 'i', 'o', 'u']) {
        "an"
    } else {
        "a"
    }
}
