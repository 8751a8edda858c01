//! What the VM needs from a mesh: its structure, its table sizes, and the
//! lookups. Keeping this a trait lets the language be tested on hand-written
//! tables and run on the real winged-edge and half-edge structures alike.

use super::types::{Element, ElementKind, Field, Structure};
use std::fmt;

/// A mesh the VM can walk.
pub trait Topology {
    fn structure(&self) -> Structure;

    /// The number of rows in one table (half-edges, for a half-edge Edge).
    fn count(&self, kind: ElementKind) -> usize;

    /// One lookup. `Ok(None)` is a legitimately missing reference: the face
    /// beyond a boundary edge, or the incident edge of an isolated vertex.
    fn lookup(&self, element: Element, field: Field) -> Result<Option<Element>, LookupError>;
}

/// A lookup the mesh could not answer. The checker rules out the second kind
/// for compiled code, so either one means a bad input or a broken mesh.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum LookupError {
    NoSuchElement(Element),
    NotApplicable { element: Element, field: Field },
}

impl fmt::Display for LookupError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            LookupError::NoSuchElement(element) => {
                write!(f, "{element} does not exist in this mesh")
            }
            LookupError::NotApplicable { element, field } => write!(f, "{element} has no {field}"),
        }
    }
}

impl std::error::Error for LookupError {}

impl<T: Topology + ?Sized> Topology for &T {
    fn structure(&self) -> Structure {
        (**self).structure()
    }

    fn count(&self, kind: ElementKind) -> usize {
        (**self).count(kind)
    }

    #[inline]
    fn lookup(&self, element: Element, field: Field) -> Result<Option<Element>, LookupError> {
        (**self).lookup(element, field)
    }
}
