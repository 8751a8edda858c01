//! The table accessors both structures share, written into each one's
//! `impl` by a macro: the row types differ, the way to read them does not.

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
