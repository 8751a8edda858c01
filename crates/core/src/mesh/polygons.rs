//! The builder's input: positions and polygon faces of any size, as a loader
//! produces them.
//!
//! Faces are stored flat (one index array plus offsets) rather than as a
//! `Vec` per face, so a million-triangle mesh is three allocations instead of
//! a million.

use glam::Vec3;

use super::ids::{FaceId, VertexId};

/// An indexed polygon list: vertex positions and faces that list vertex
/// numbers counter-clockwise seen from outside (the OBJ convention).
///
/// Nothing is checked here; [`HalfEdgeMesh::build`](super::HalfEdgeMesh::build)
/// and [`WingedEdgeMesh::build`](super::WingedEdgeMesh::build) refuse bad input
/// with an error naming the face and, when known, its source line.
#[derive(Clone, Debug, PartialEq)]
pub struct Polygons {
    positions: Vec<Vec3>,
    indices: Vec<u32>,
    /// `offsets[f]..offsets[f + 1]` is face `f` in `indices`; always starts with 0.
    offsets: Vec<usize>,
    /// Source line of each face (0 = unknown); empty when no face has one.
    lines: Vec<usize>,
}

impl Default for Polygons {
    fn default() -> Self {
        Self::new()
    }
}

impl Polygons {
    /// An empty polygon list.
    pub fn new() -> Self {
        Self::with_capacity(0, 0, 0)
    }

    /// An empty list with room for `vertices` positions, `faces` faces and
    /// `corners` vertex references in total.
    pub fn with_capacity(vertices: usize, faces: usize, corners: usize) -> Self {
        let mut offsets = Vec::with_capacity(faces + 1);
        offsets.push(0);
        Self {
            positions: Vec::with_capacity(vertices),
            indices: Vec::with_capacity(corners),
            offsets,
            lines: Vec::new(),
        }
    }

    /// Positions and faces given as slices of vertex numbers.
    pub fn from_faces<F: AsRef<[u32]>>(
        positions: Vec<Vec3>,
        faces: impl IntoIterator<Item = F>,
    ) -> Self {
        let mut polygons = Self {
            positions,
            ..Self::new()
        };
        for face in faces {
            polygons.push_face(face.as_ref());
        }
        polygons
    }

    /// Positions and triangles.
    pub fn from_triangles(positions: Vec<Vec3>, triangles: &[[u32; 3]]) -> Self {
        let mut polygons = Self::with_capacity(0, triangles.len(), triangles.len() * 3);
        polygons.positions = positions;
        for triangle in triangles {
            polygons.push_face(triangle);
        }
        polygons
    }

    /// Adds a vertex and returns its id (saturating at `u32::MAX`, which the
    /// builder then refuses as too large).
    pub fn push_vertex(&mut self, position: Vec3) -> VertexId {
        let id = VertexId::from_index(self.positions.len()).unwrap_or(VertexId::new(u32::MAX));
        self.positions.push(position);
        id
    }

    /// Adds a face listing vertex numbers counter-clockwise.
    pub fn push_face(&mut self, vertices: &[u32]) -> FaceId {
        self.push_face_inner(vertices, 0)
    }

    /// Adds a face that was read from `line` (1-based) of a file, so build
    /// errors can point at it.
    pub fn push_face_from_line(&mut self, vertices: &[u32], line: usize) -> FaceId {
        self.push_face_inner(vertices, line)
    }

    fn push_face_inner(&mut self, vertices: &[u32], line: usize) -> FaceId {
        let face = self.face_count();
        if line != 0 || !self.lines.is_empty() {
            self.lines.resize(face, 0);
            self.lines.push(line);
        }
        self.indices.extend_from_slice(vertices);
        self.offsets.push(self.indices.len());
        FaceId::from_index(face).unwrap_or(FaceId::new(u32::MAX))
    }

    /// The vertex positions.
    pub fn positions(&self) -> &[Vec3] {
        &self.positions
    }

    /// The vertex positions, for moving vertices without changing faces.
    pub fn positions_mut(&mut self) -> &mut [Vec3] {
        &mut self.positions
    }

    /// Number of vertices.
    pub fn vertex_count(&self) -> usize {
        self.positions.len()
    }

    /// Number of faces.
    pub fn face_count(&self) -> usize {
        self.offsets.len().saturating_sub(1)
    }

    /// Total number of vertex references over all faces (the number of
    /// interior half-edges a build creates).
    pub fn corner_count(&self) -> usize {
        self.indices.len()
    }

    /// The vertex numbers of face `face`, if it exists.
    pub fn face(&self, face: usize) -> Option<&[u32]> {
        let start = *self.offsets.get(face)?;
        let end = *self.offsets.get(face + 1)?;
        self.indices.get(start..end)
    }

    /// All faces in order.
    pub fn faces(&self) -> impl ExactSizeIterator<Item = &[u32]> + '_ {
        self.offsets.windows(2).map(|w| match w {
            [start, end] => self.indices.get(*start..*end).unwrap_or(&[]),
            _ => &[],
        })
    }

    /// The first face that lists a vertex twice, and that vertex: such a
    /// face cannot be built, nor written so that it reads back.
    pub fn repeated_corner(&self) -> Option<(FaceId, VertexId)> {
        let mut seen = Vec::new();
        for (f, face) in (0u32..).zip(self.faces()) {
            seen.clear();
            seen.extend_from_slice(face);
            seen.sort_unstable();
            if let Some(pair) = seen.windows(2).find(|pair| pair[0] == pair[1]) {
                return Some((FaceId::new(f), VertexId::new(pair[0])));
            }
        }
        None
    }

    /// The source line face `face` was read from, if known.
    pub fn line(&self, face: usize) -> Option<usize> {
        self.lines.get(face).copied().filter(|&line| line != 0)
    }

    /// All vertex numbers, face after face.
    pub(crate) fn indices(&self) -> &[u32] {
        &self.indices
    }

    /// All vertex numbers, for renumbering corners without changing faces.
    pub(crate) fn indices_mut(&mut self) -> &mut [u32] {
        &mut self.indices
    }

    /// Face start offsets into [`Self::indices`], with a final end offset.
    pub(crate) fn offsets(&self) -> &[usize] {
        &self.offsets
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn faces_are_stored_flat_with_lines() {
        let mut p = Polygons::new();
        for _ in 0..4 {
            p.push_vertex(Vec3::ZERO);
        }
        p.push_face(&[0, 1, 2]);
        p.push_face_from_line(&[0, 2, 3, 1], 7);
        assert_eq!(p.face_count(), 2);
        assert_eq!(p.face(1), Some(&[0, 2, 3, 1][..]));
        assert_eq!(p.face(2), None);
        assert_eq!(p.line(0), None);
        assert_eq!(p.line(1), Some(7));
        assert_eq!(p.faces().count(), 2);
    }
}
