//! What the VM needs from a mesh: its structure, its table sizes, and the
//! lookups. Keeping this a trait lets the VM run on the winged-edge and
//! half-edge structures (through their [`Records`]) and on anything else with
//! tables, such as the tests' hand-written meshes.

use glam::Vec3;

use crate::mesh::{self, HalfEdgeMesh, VertexId, WingedEdgeMesh};
use crate::schema::{Column, ElementKind, ElementRef, LookupError, Records, Structure};

/// A mesh the VM can walk.
pub trait Topology {
    fn structure(&self) -> Structure;

    /// The number of rows in one table (half-edges, for a half-edge Edge).
    fn count(&self, kind: ElementKind) -> usize;

    /// One lookup. `Ok(None)` is a legitimately missing reference: the face
    /// beyond a boundary edge, or the incident edge of an isolated vertex.
    fn lookup(
        &self,
        element: ElementRef,
        column: Column,
    ) -> Result<Option<ElementRef>, LookupError>;

    /// A vertex's position, for `v.position`; `None` if the vertex does not
    /// exist or the mesh has no geometry.
    fn position(&self, _vertex: VertexId) -> Option<Vec3> {
        None
    }
}

impl<T: Topology + ?Sized> Topology for &T {
    fn structure(&self) -> Structure {
        (**self).structure()
    }

    fn count(&self, kind: ElementKind) -> usize {
        (**self).count(kind)
    }

    #[inline]
    fn lookup(
        &self,
        element: ElementRef,
        column: Column,
    ) -> Result<Option<ElementRef>, LookupError> {
        (**self).lookup(element, column)
    }

    fn position(&self, vertex: VertexId) -> Option<Vec3> {
        (**self).position(vertex)
    }
}

/// Implements [`Topology`] for a mesh by reading its records.
macro_rules! topology_from_records {
    ($($mesh:ty),*) => {$(
        impl Topology for $mesh {
            fn structure(&self) -> Structure {
                Records::structure(self)
            }

            fn count(&self, kind: ElementKind) -> usize {
                Records::count(self, kind)
            }

            #[inline]
            fn lookup(
                &self,
                element: ElementRef,
                column: Column,
            ) -> Result<Option<ElementRef>, LookupError> {
                self.reference(element, column)
            }

            fn position(&self, vertex: VertexId) -> Option<Vec3> {
                if !self.contains(vertex.into()) {
                    return None;
                }
                Records::position(self, vertex)
            }
        }
    )*};
}

topology_from_records!(WingedEdgeMesh, HalfEdgeMesh, mesh::Mesh);
