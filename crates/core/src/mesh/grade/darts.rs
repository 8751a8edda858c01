//! Both structures as one combinatorial map, so the grader compares meshes
//! once: a dart is one side of an edge (a half-edge row, or a winged edge's
//! left or right side) with the vertex its face's counter-clockwise walk
//! leaves from, the dart after it on that walk, the other side of its edge,
//! and its face.

use glam::Vec3;

use crate::mesh::ids::{EdgeId, FaceId, VertexId};
use crate::mesh::winged_edge::Side;
use crate::mesh::{HalfEdgeMesh, Mesh, WingedEdgeMesh};
use crate::schema::{Column, ElementKind, ElementRef, Records, Structure};

/// No dart, vertex or face.
pub(super) const NONE: u32 = u32::MAX;

/// The darts of a mesh, indexed by dart number: a half-edge's row, or
/// twice a winged edge's row plus 0 for its left side and 1 for its right.
/// Deleted rows are darts whose origin is [`NONE`].
pub(super) struct Darts {
    pub structure: Structure,
    pub origin: Vec<u32>,
    pub next: Vec<u32>,
    pub twin: Vec<u32>,
    pub face: Vec<u32>,
    /// Each vertex's position; `None` for a deleted row.
    pub positions: Vec<Option<Vec3>>,
}

impl Darts {
    /// The darts of a mesh that validates (a broken reference becomes
    /// [`NONE`], which the matching reports rather than follows).
    pub fn of(mesh: &Mesh) -> Self {
        let positions = (0..mesh.count(ElementKind::Vertex) as u32)
            .map(|v| mesh.position(VertexId::new(v)))
            .collect();
        match mesh {
            Mesh::Half(m) => Self::of_half_edges(m, positions),
            Mesh::Winged(m) => Self::of_winged_edges(m, positions),
        }
    }

    fn of_half_edges(mesh: &HalfEdgeMesh, positions: Vec<Option<Vec3>>) -> Self {
        let count = mesh.half_edge_count();
        let mut darts = Self::empty(Structure::HalfEdge, count, positions);
        for (h, row) in mesh.half_edges().iter().enumerate() {
            if mesh
                .half_edge(crate::mesh::HalfEdgeId::new(h as u32))
                .is_none()
            {
                continue;
            }
            darts.origin[h] = mesh
                .half_edge(row.pair_edge)
                .map_or(NONE, |pair| pair.end_vertex.raw());
            darts.next[h] = row.successor_edge.raw();
            darts.twin[h] = row.pair_edge.raw();
            darts.face[h] = row.face.map_or(NONE, FaceId::raw);
        }
        darts
    }

    fn of_winged_edges(mesh: &WingedEdgeMesh, positions: Vec<Option<Vec3>>) -> Self {
        let count = mesh.edge_count() * 2;
        let mut darts = Self::empty(Structure::WingedEdge, count, positions);
        for (e, row) in mesh.edges().iter().enumerate() {
            if mesh.edge(EdgeId::new(e as u32)).is_none() {
                continue;
            }
            for side in [Side::Left, Side::Right] {
                let d = dart(e as u32, side) as usize;
                let face = row.face(side);
                darts.origin[d] = row.ccw_start(side).raw();
                darts.twin[d] = dart(e as u32, side.opposite());
                darts.face[d] = face.map_or(NONE, FaceId::raw);
                let after = row.predecessor(side);
                darts.next[d] = mesh
                    .edge(after)
                    .and_then(|next| next.side_entered_at(face, row.ccw_end(side)))
                    .map_or(NONE, |next_side| dart(after.raw(), next_side));
            }
        }
        darts
    }

    fn empty(structure: Structure, count: usize, positions: Vec<Option<Vec3>>) -> Self {
        Self {
            structure,
            origin: vec![NONE; count],
            next: vec![NONE; count],
            twin: vec![NONE; count],
            face: vec![NONE; count],
            positions,
        }
    }

    pub fn len(&self) -> usize {
        self.origin.len()
    }

    pub fn is_live(&self, d: u32) -> bool {
        self.origin.get(d as usize).is_some_and(|&o| o != NONE)
    }

    /// Where the dart's walk arrives: its twin's origin.
    pub fn end(&self, d: u32) -> u32 {
        self.twin
            .get(d as usize)
            .and_then(|&t| self.origin.get(t as usize))
            .copied()
            .unwrap_or(NONE)
    }

    pub fn position(&self, v: u32) -> Option<Vec3> {
        self.positions.get(v as usize).copied().flatten()
    }

    /// The edge-table row the dart is a side of, and which side for a
    /// winged edge.
    pub fn row(&self, d: u32) -> (u32, Option<Side>) {
        match self.structure {
            Structure::HalfEdge => (d, None),
            Structure::WingedEdge => (
                d / 2,
                Some(if d.is_multiple_of(2) {
                    Side::Left
                } else {
                    Side::Right
                }),
            ),
        }
    }

    /// The column holding the dart after `d` on its face's walk.
    pub fn next_column(&self, d: u32) -> Column {
        match self.row(d).1 {
            None => Column::SuccessorEdge,
            Some(side) => Column::predecessor_of(side),
        }
    }

    /// The column holding the dart's face.
    pub fn face_column(&self, d: u32) -> Column {
        match self.row(d).1 {
            None => Column::Face,
            Some(side) => Column::face_of(side),
        }
    }

    /// The dart as a message names it: "half-edge 9 (vertex 3 → vertex 5)",
    /// "edge 4 (vertex 3 → vertex 5, its left side)".
    pub fn describe(&self, d: u32) -> String {
        let ends = format!(
            "{} → {}",
            VertexId::new(self.origin[d as usize]),
            VertexId::new(self.end(d))
        );
        match self.row(d) {
            (row, None) => format!("{} ({ends})", crate::mesh::HalfEdgeId::new(row)),
            (row, Some(side)) => format!(
                "{} ({ends}, its {} side)",
                EdgeId::new(row),
                match side {
                    Side::Left => "left",
                    Side::Right => "right",
                }
            ),
        }
    }

    /// The edge-table row of a dart, as an element.
    pub fn element(&self, d: u32) -> ElementRef {
        ElementRef::new(ElementKind::Edge, self.row(d).0)
    }
}

/// A winged edge's side as a dart number.
fn dart(edge: u32, side: Side) -> u32 {
    edge * 2 + u32::from(side == Side::Right)
}
