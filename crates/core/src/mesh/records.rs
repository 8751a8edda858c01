//! The schema's record traits implemented for the two structures: which
//! field of each row holds which [`Column`], and the tables each structure
//! reads and writes through [`Rows`] and [`RowsMut`]. The traits are the
//! schema's; what the meshes store is theirs, so the impls live here.

use glam::Vec3;

use super::ids::{EdgeId, FaceId, HalfEdgeId, VertexId};
use super::{
    Deleted, HalfEdge, HalfEdgeMesh, Mesh, Side, WingedEdge, WingedEdgeMesh, half_edge, winged_edge,
};
use crate::schema::{
    Column, EditHooks, ElementKind, ElementRef, LookupError, Record, Records, RecordsMut, Rows,
    RowsMut, Structure, WriteError,
};

/// A record field that holds a row number, or an optional one.
trait Cell {
    fn read(&self) -> Option<u32>;
    fn write(value: Option<u32>) -> Self;
}

macro_rules! id_cells {
    ($($id:ty),*) => {$(
        /// A required reference reads as empty until it is set.
        impl Cell for $id {
            fn read(&self) -> Option<u32> {
                (!self.is_unset()).then(|| self.raw())
            }
            fn write(value: Option<u32>) -> Self {
                value.map_or(<$id>::UNSET, <$id>::new)
            }
        }

        impl Cell for Option<$id> {
            fn read(&self) -> Option<u32> {
                self.map(<$id>::raw)
            }
            fn write(value: Option<u32>) -> Self {
                value.map(<$id>::new)
            }
        }
    )*};
}

id_cells!(VertexId, EdgeId, FaceId, HalfEdgeId);

/// Implements [`Record`] for a row type from its stored columns and the
/// fields that hold them.
macro_rules! record {
    ($row:ty: $($column:ident => $field:ident),* $(,)?) => {
        impl Record for $row {
            fn get(&self, column: Column) -> Option<Option<u32>> {
                match column {
                    $(Column::$column => Some(Cell::read(&self.$field)),)*
                    _ => None,
                }
            }

            fn set(&mut self, column: Column, value: Option<u32>) {
                match column {
                    $(Column::$column => self.$field = Cell::write(value),)*
                    _ => {}
                }
            }
        }
    };
}

record!(winged_edge::Vertex: IncidentEdge => incident_edge);
record!(winged_edge::Face: IncidentEdge => incident_edge);
record!(WingedEdge:
    StartVertex => start_vertex,
    EndVertex => end_vertex,
    LeftFace => left_face,
    RightFace => right_face,
    LeftPredecessor => left_predecessor,
    LeftSuccessor => left_successor,
    RightPredecessor => right_predecessor,
    RightSuccessor => right_successor,
);
record!(half_edge::Vertex: IncidentEdge => incident_edge);
record!(half_edge::Face: IncidentEdge => incident_edge);
record!(HalfEdge:
    EndVertex => end_vertex,
    Face => face,
    PairEdge => pair_edge,
    SuccessorEdge => successor_edge,
);

/// Implements [`Rows`] and [`RowsMut`] for a structure from its row types,
/// its edge table, and any derived columns.
macro_rules! rows {
    ($mesh:ty: $structure:expr, $vertex:ty, $face:ty, $edge:ty, $edges:ident $(, $derived:item)?) => {
        impl RowsMut for $mesh {
            fn vertex_rows_mut(&mut self) -> &mut [$vertex] {
                &mut self.vertices
            }

            fn face_rows_mut(&mut self) -> &mut [$face] {
                &mut self.faces
            }

            fn edge_rows_mut(&mut self) -> &mut [$edge] {
                &mut self.$edges
            }
        }

        impl Rows for $mesh {
            type Vertex = $vertex;
            type Face = $face;
            type Edge = $edge;

            fn structure(&self) -> Structure {
                $structure
            }

            fn vertex_rows(&self) -> &[$vertex] {
                self.vertices()
            }

            fn face_rows(&self) -> &[$face] {
                self.faces()
            }

            fn edge_rows(&self) -> &[$edge] {
                self.$edges()
            }

            fn position(&self, vertex: VertexId) -> Option<Vec3> {
                <$mesh>::position(self, vertex)
            }

            fn deleted(&self) -> &Deleted {
                &self.deleted
            }

            $($derived)?
        }
    };
}

rows!(WingedEdgeMesh: Structure::WingedEdge, winged_edge::Vertex, winged_edge::Face, WingedEdge, edges);
rows!(
    HalfEdgeMesh: Structure::HalfEdge,
    half_edge::Vertex,
    half_edge::Face,
    HalfEdge,
    half_edges,
    fn derived(&self, edge: u32, column: Column) -> Option<Option<ElementRef>> {
        let id = HalfEdgeId::new(edge);
        match column {
            Column::StartVertex => Some(self.start_vertex(id).map(ElementRef::vertex)),
            Column::PredecessorEdge => Some(self.predecessor_edge(id).map(ElementRef::half_edge)),
            _ => None,
        }
    }
);

impl EditHooks for WingedEdgeMesh {}

impl EditHooks for HalfEdgeMesh {
    fn written(&mut self, column: Column) {
        if column == Column::SuccessorEdge {
            self.forget_predecessors();
        }
    }
}

impl RecordsMut for Mesh {
    fn set_reference(
        &mut self,
        element: ElementRef,
        column: Column,
        target: Option<ElementRef>,
    ) -> Result<(), WriteError> {
        match self {
            Mesh::Winged(mesh) => mesh.set_reference(element, column, target),
            Mesh::Half(mesh) => mesh.set_reference(element, column, target),
        }
    }

    fn unset_reference(&mut self, element: ElementRef, column: Column) -> Result<(), WriteError> {
        match self {
            Mesh::Winged(mesh) => mesh.unset_reference(element, column),
            Mesh::Half(mesh) => mesh.unset_reference(element, column),
        }
    }
}

/// Either structure, as loaded.
impl Records for Mesh {
    fn structure(&self) -> Structure {
        Mesh::structure(self)
    }

    fn count(&self, kind: ElementKind) -> usize {
        match self {
            Mesh::Winged(mesh) => mesh.count(kind),
            Mesh::Half(mesh) => mesh.count(kind),
        }
    }

    fn position(&self, vertex: VertexId) -> Option<Vec3> {
        Mesh::position(self, vertex)
    }

    fn contains(&self, element: ElementRef) -> bool {
        match self {
            Mesh::Winged(mesh) => mesh.contains(element),
            Mesh::Half(mesh) => mesh.contains(element),
        }
    }

    #[inline]
    fn reference(
        &self,
        element: ElementRef,
        column: Column,
    ) -> Result<Option<ElementRef>, LookupError> {
        match self {
            Mesh::Winged(mesh) => mesh.reference(element, column),
            Mesh::Half(mesh) => mesh.reference(element, column),
        }
    }
}

/// The winged-edge columns of one side of an edge.
impl Column {
    /// A winged edge's face on `side`.
    pub fn face_of(side: Side) -> Self {
        match side {
            Side::Left => Self::LeftFace,
            Side::Right => Self::RightFace,
        }
    }

    /// A winged edge's predecessor on `side`.
    pub fn predecessor_of(side: Side) -> Self {
        match side {
            Side::Left => Self::LeftPredecessor,
            Side::Right => Self::RightPredecessor,
        }
    }

    /// A winged edge's successor on `side`.
    pub fn successor_of(side: Side) -> Self {
        match side {
            Side::Left => Self::LeftSuccessor,
            Side::Right => Self::RightSuccessor,
        }
    }
}
