//! Either structure behind one type, for code (tables, views, loaders) that
//! works with whichever the user picked.

use glam::Vec3;

use super::convert::ConvertError;
use super::error::{BuildError, BuildWarning};
use super::half_edge::HalfEdgeMesh;
use super::ids::VertexId;
use super::polygons::Polygons;
use super::stats::MeshStats;
use super::validate::Issue;
use super::winged_edge::WingedEdgeMesh;
use crate::schema::Structure;

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

/// Writes a structure's table accessors inside its `impl`: the rows differ
/// between the structures (each module's `Vertex` and `Face`, then the
/// half-edge or edge rows), the way to read them does not. The structure
/// needs `vertices`, `faces`, `$edges` and `deleted` fields, and its vertex
/// rows a `position`. A deleted row is not there for the accessors.
macro_rules! tables {
    ($vertex:ty, $face:ty, $edges:ident: $edge:ty, $what:literal, $row:ident($id:ty), $count:ident) => {
        /// Gives the tables back, for editing.
        pub fn into_raw_parts(self) -> (Vec<$vertex>, Vec<$face>, Vec<$edge>) {
            (self.vertices, self.faces, self.$edges)
        }

        /// The vertex table.
        pub fn vertices(&self) -> &[$vertex] {
            &self.vertices
        }

        /// The face table.
        pub fn faces(&self) -> &[$face] {
            &self.faces
        }

        #[doc = concat!("The ", $what, " table.")]
        pub fn $edges(&self) -> &[$edge] {
            &self.$edges
        }

        /// Number of vertices.
        pub fn vertex_count(&self) -> usize {
            self.vertices.len()
        }

        /// Number of faces.
        pub fn face_count(&self) -> usize {
            self.faces.len()
        }

        #[doc = concat!("Number of ", $what, "s (rows of the ", $what, " table).")]
        pub fn $count(&self) -> usize {
            self.$edges.len()
        }

        /// A vertex row.
        #[inline]
        pub fn vertex(&self, v: $crate::mesh::VertexId) -> Option<&$vertex> {
            self.vertices
                .get(v.index())
                .filter(|_| !self.deleted.contains(v.into()))
        }

        /// A face row.
        #[inline]
        pub fn face(&self, f: $crate::mesh::FaceId) -> Option<&$face> {
            self.faces
                .get(f.index())
                .filter(|_| !self.deleted.contains(f.into()))
        }

        #[doc = concat!("The ", $what, " row with this id.")]
        #[inline]
        pub fn $row(&self, id: $id) -> Option<&$edge> {
            self.$edges
                .get(id.index())
                .filter(|_| !self.deleted.contains(id.into()))
        }

        /// Rows an edit deleted and the ids have not been compacted since.
        pub fn deleted(&self) -> &$crate::mesh::deleted::Deleted {
            &self.deleted
        }

        /// The position of a vertex.
        #[inline]
        pub fn position(&self, v: $crate::mesh::VertexId) -> Option<::glam::Vec3> {
            self.vertex(v).map(|vertex| vertex.position)
        }
    };
}
pub(crate) use tables;
