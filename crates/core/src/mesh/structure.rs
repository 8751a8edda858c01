//! Either structure behind one type, for code (tables, views, loaders) that
//! works with whichever the user picked.

use glam::Vec3;

use super::convert::ConvertError;
use super::deleted::Deleted;
use super::edit::{Edit, EditError, Renumbering};
use super::error::{BuildError, BuildWarning};
use super::half_edge::HalfEdgeMesh;
use super::ids::VertexId;
use super::polygons::Polygons;
use super::stats::MeshStats;
use super::validate::Issue;
use super::winged_edge::WingedEdgeMesh;
use crate::schema::{ElementKind, ElementRef, Structure};

/// A mesh in one of the two structures.
#[derive(Clone, Debug, PartialEq)]
pub enum Mesh {
    /// Stored as winged-edge.
    Winged(WingedEdgeMesh),
    /// Stored as half-edge.
    Half(HalfEdgeMesh),
}

impl From<WingedEdgeMesh> for Mesh {
    fn from(mesh: WingedEdgeMesh) -> Self {
        Self::Winged(mesh)
    }
}

impl From<HalfEdgeMesh> for Mesh {
    fn from(mesh: HalfEdgeMesh) -> Self {
        Self::Half(mesh)
    }
}

impl Mesh {
    /// Builds `structure` from polygons; see [`HalfEdgeMesh::build`] and
    /// [`WingedEdgeMesh::build`].
    ///
    /// ```
    /// use edgewise_core::mesh::{generate, Mesh, Structure};
    ///
    /// let (mesh, _) = Mesh::build(&generate::torus(8, 6), Structure::WingedEdge)?;
    /// let stats = mesh.stats();
    /// assert_eq!((stats.vertices, stats.edges, stats.faces), (48, 144, 96));
    /// assert_eq!(stats.components[0].genus, Some(1));
    /// # Ok::<(), edgewise_core::mesh::BuildError>(())
    /// ```
    pub fn build(
        polygons: &Polygons,
        structure: Structure,
    ) -> Result<(Self, Vec<BuildWarning>), BuildError> {
        Ok(match structure {
            Structure::WingedEdge => {
                let (mesh, warnings) = WingedEdgeMesh::build(polygons)?;
                (Self::Winged(mesh), warnings)
            }
            Structure::HalfEdge => {
                let (mesh, warnings) = HalfEdgeMesh::build(polygons)?;
                (Self::Half(mesh), warnings)
            }
        })
    }

    /// Which structure this is.
    pub fn structure(&self) -> Structure {
        match self {
            Self::Winged(_) => Structure::WingedEdge,
            Self::Half(_) => Structure::HalfEdge,
        }
    }

    /// Number of vertices.
    pub fn vertex_count(&self) -> usize {
        match self {
            Self::Winged(mesh) => mesh.vertex_count(),
            Self::Half(mesh) => mesh.vertex_count(),
        }
    }

    /// Number of edges (half-edge pairs for a half-edge mesh).
    pub fn edge_count(&self) -> usize {
        match self {
            Self::Winged(mesh) => mesh.edge_count(),
            Self::Half(mesh) => mesh.edge_count(),
        }
    }

    /// Number of faces.
    pub fn face_count(&self) -> usize {
        match self {
            Self::Winged(mesh) => mesh.face_count(),
            Self::Half(mesh) => mesh.face_count(),
        }
    }

    /// Number of rows in the edge table (edges, or half-edges).
    pub fn edge_row_count(&self) -> usize {
        match self {
            Self::Winged(mesh) => mesh.edge_count(),
            Self::Half(mesh) => mesh.half_edge_count(),
        }
    }

    /// The position of a vertex.
    pub fn position(&self, v: VertexId) -> Option<Vec3> {
        match self {
            Self::Winged(mesh) => mesh.position(v),
            Self::Half(mesh) => mesh.position(v),
        }
    }

    /// All vertex positions in order.
    pub fn positions(&self) -> Vec<Vec3> {
        match self {
            Self::Winged(mesh) => mesh.vertices().iter().map(|v| v.position).collect(),
            Self::Half(mesh) => mesh.vertices().iter().map(|v| v.position).collect(),
        }
    }

    /// Counts and invariants; see [`MeshStats`].
    pub fn stats(&self) -> MeshStats {
        match self {
            Self::Winged(mesh) => mesh.stats(),
            Self::Half(mesh) => mesh.stats(),
        }
    }

    /// Every violated rule; empty for a sound mesh.
    pub fn validate(&self) -> Vec<Issue> {
        match self {
            Self::Winged(mesh) => mesh.validate(),
            Self::Half(mesh) => mesh.validate(),
        }
    }

    /// The faces as a polygon list.
    pub fn to_polygons(&self) -> Polygons {
        match self {
            Self::Winged(mesh) => mesh.to_polygons(),
            Self::Half(mesh) => mesh.to_polygons(),
        }
    }

    /// The same mesh in `structure` (a copy if it already is).
    pub fn convert_to(&self, structure: Structure) -> Result<Self, ConvertError> {
        Ok(match (self, structure) {
            (Self::Winged(mesh), Structure::HalfEdge) => Self::Half(mesh.to_half_edge()?),
            (Self::Half(mesh), Structure::WingedEdge) => Self::Winged(mesh.to_winged_edge()?),
            (same, _) => same.clone(),
        })
    }

    /// The winged-edge mesh, if that is the structure.
    pub fn as_winged_edge(&self) -> Option<&WingedEdgeMesh> {
        match self {
            Self::Winged(mesh) => Some(mesh),
            Self::Half(_) => None,
        }
    }

    /// The half-edge mesh, if that is the structure.
    pub fn as_half_edge(&self) -> Option<&HalfEdgeMesh> {
        match self {
            Self::Half(mesh) => Some(mesh),
            Self::Winged(_) => None,
        }
    }
}

impl Edit for Mesh {
    fn push_row(&mut self, kind: ElementKind) -> Result<ElementRef, EditError> {
        match self {
            Mesh::Winged(mesh) => mesh.push_row(kind),
            Mesh::Half(mesh) => mesh.push_row(kind),
        }
    }

    fn pop_row(&mut self, kind: ElementKind) -> Result<(), EditError> {
        match self {
            Mesh::Winged(mesh) => mesh.pop_row(kind),
            Mesh::Half(mesh) => mesh.pop_row(kind),
        }
    }

    fn set_deleted(&mut self, element: ElementRef, deleted: bool) -> Result<(), EditError> {
        match self {
            Mesh::Winged(mesh) => mesh.set_deleted(element, deleted),
            Mesh::Half(mesh) => mesh.set_deleted(element, deleted),
        }
    }

    fn set_position(&mut self, vertex: VertexId, position: Vec3) -> Result<Vec3, EditError> {
        match self {
            Mesh::Winged(mesh) => mesh.set_position(vertex, position),
            Mesh::Half(mesh) => mesh.set_position(vertex, position),
        }
    }

    fn compact(&mut self) -> Renumbering {
        match self {
            Mesh::Winged(mesh) => mesh.compact(),
            Mesh::Half(mesh) => mesh.compact(),
        }
    }

    fn deleted_rows(&self) -> &Deleted {
        match self {
            Mesh::Winged(mesh) => mesh.deleted_rows(),
            Mesh::Half(mesh) => mesh.deleted_rows(),
        }
    }
}

impl Mesh {
    /// [`Mesh::stats`] of the rows that are not deleted: the counts a
    /// student expects mid-edit, before the ids are compacted.
    pub fn live_stats(&self) -> MeshStats {
        if self.deleted_rows().is_empty() {
            return self.stats();
        }
        let mut live = self.clone();
        live.compact();
        live.stats()
    }
}
