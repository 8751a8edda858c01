//! Conversions: half-edge ⇄ winged-edge (same vertex and face numbering, each
//! winged edge ↔ one half-edge pair) and both back to a polygon list.
//!
//! A mesh with deleted rows (mid-edit) is compacted first: the converted
//! mesh has no gaps, and the [`EdgeCorrespondence`] maps the old ids.
//!
//! The conversions are canonical, so the builds and conversions agree:
//! `HalfEdgeMesh::build(p)` converted to winged-edge equals
//! `WingedEdgeMesh::build(p)`, and a winged-edge mesh converted to half-edge
//! and back is unchanged. Winged-edge to polygons starts each face at its
//! lowest-numbered edge that has the face on its left (the edge that first
//! appeared in that face), which keeps the edge numbering when rebuilt.

use std::fmt;

use super::builder::NONE;
use super::edit::{Edit as _, Renumbering};
use super::error::BuildError;
use super::half_edge::HalfEdgeMesh;
use super::ids::{EdgeId, FaceId, HalfEdgeId, VertexId};
use super::navigation::Navigation;
use super::polygons::Polygons;
use super::validate::Issue;
use super::winged_edge::{self, Side, WingedEdge, WingedEdgeMesh};
use crate::schema::{ElementKind, ElementRef};

/// Why a conversion did not happen.
#[derive(Clone, Debug, PartialEq)]
pub enum ConvertError {
    /// The source mesh fails [`validate`](HalfEdgeMesh::validate); these are
    /// its issues.
    Invalid(Vec<Issue>),
    /// The source mesh is consistent but cannot be rebuilt.
    Build(BuildError),
    /// A winged-edge face passes a vertex twice (a dangling edge); the
    /// conversion to half-edge goes through the face list, which cannot.
    PassesTwice { face: FaceId, vertex: VertexId },
}

impl fmt::Display for ConvertError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Invalid(issues) => {
                write!(
                    f,
                    "the mesh has {} problems, so it cannot be converted",
                    issues.len()
                )?;
                if let Some(first) = issues.first() {
                    write!(f, "; the first: {first}")?;
                }
                Ok(())
            }
            Self::Build(error) => write!(f, "the mesh cannot be converted: {error}"),
            Self::PassesTwice { face, vertex } => write!(
                f,
                "{face} passes {vertex} twice (along a dangling edge and back); winged-edge \
                 tables convert to half-edge through their face lists, which need each corner \
                 once: keep this mesh in winged-edge (.wtb), or remove the dangling edge (KEV) \
                 first"
            ),
        }
    }
}

impl std::error::Error for ConvertError {}

/// Which half-edges make up which winged edge, after a conversion, and
/// where the source's vertices and faces went. Every method takes the
/// source mesh's ids.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct EdgeCorrespondence {
    edge_of_half_edge: Vec<EdgeId>,
    half_edges_of_edge: Vec<(HalfEdgeId, HalfEdgeId)>,
    /// How the source was compacted first, if it had deleted rows.
    renumbering: Option<Renumbering>,
}

impl EdgeCorrespondence {
    /// The winged edge a half-edge belongs to.
    pub fn edge(&self, h: HalfEdgeId) -> Option<EdgeId> {
        let h = self.renumbered(ElementKind::Edge, h.raw())?;
        self.edge_of_half_edge.get(h as usize).copied()
    }

    /// The two half-edges of a winged edge: first the one running from its
    /// start to its end (whose face is the left face), then its pair.
    pub fn half_edges(&self, e: EdgeId) -> Option<(HalfEdgeId, HalfEdgeId)> {
        let e = self.renumbered(ElementKind::Edge, e.raw())?;
        self.half_edges_of_edge.get(e as usize).copied()
    }

    /// A source vertex's id in the converted mesh: the same, unless the
    /// source had deleted rows (`None` for a deleted vertex).
    pub fn vertex(&self, v: VertexId) -> Option<VertexId> {
        self.renumbered(ElementKind::Vertex, v.raw())
            .map(VertexId::new)
    }

    /// A source face's id in the converted mesh, as [`Self::vertex`].
    pub fn face(&self, f: FaceId) -> Option<FaceId> {
        self.renumbered(ElementKind::Face, f.raw()).map(FaceId::new)
    }

    fn renumbered(&self, kind: ElementKind, id: u32) -> Option<u32> {
        match &self.renumbering {
            None => Some(id),
            Some(map) => map.get(ElementRef::new(kind, id)).map(|e| e.id),
        }
    }

    fn after(mut self, renumbering: Renumbering) -> Self {
        self.renumbering = Some(renumbering);
        self
    }
}

fn check(issues: Vec<Issue>) -> Result<(), ConvertError> {
    if issues.is_empty() {
        Ok(())
    } else {
        Err(ConvertError::Invalid(issues))
    }
}

impl HalfEdgeMesh {
    /// The same mesh as a winged-edge structure. Edges are numbered by their
    /// lower-numbered half-edge and point the way it does; incident edges are
    /// the lowest-numbered candidates. Refuses a mesh that fails
    /// [`validate`](Self::validate).
    pub fn to_winged_edge(&self) -> Result<WingedEdgeMesh, ConvertError> {
        self.to_winged_edge_with_correspondence()
            .map(|(mesh, _)| mesh)
    }

    /// [`to_winged_edge`](Self::to_winged_edge), also telling which half-edges
    /// became which edge (for linked selection across the two views).
    pub fn to_winged_edge_with_correspondence(
        &self,
    ) -> Result<(WingedEdgeMesh, EdgeCorrespondence), ConvertError> {
        if !self.deleted().is_empty() {
            let mut compacted = self.clone();
            let renumbering = compacted.compact();
            let (mesh, correspondence) = compacted.to_winged_edge_with_correspondence()?;
            return Ok((mesh, correspondence.after(renumbering)));
        }
        check(self.validate())?;
        let half_edges = &self.half_edges;
        let mut edge_of = vec![NONE; half_edges.len()];
        let mut first_halves = Vec::with_capacity(half_edges.len() / 2);
        for (h, half_edge) in half_edges.iter().enumerate() {
            let pair = half_edge.pair_edge.index();
            edge_of[h] = if pair > h {
                first_halves.push(h as u32);
                first_halves.len() as u32 - 1
            } else {
                edge_of.get(pair).copied().unwrap_or(NONE)
            };
        }
        let edge = |h: Option<HalfEdgeId>| {
            EdgeId::new(
                h.and_then(|h| edge_of.get(h.index()).copied())
                    .unwrap_or(NONE),
            )
        };
        let mut edges = Vec::with_capacity(first_halves.len());
        let mut pairs = Vec::with_capacity(first_halves.len());
        for &h in &first_halves {
            let id = HalfEdgeId::new(h);
            let Some(half) = self.half_edge(id) else {
                continue;
            };
            let Some(pair) = self.half_edge(half.pair_edge) else {
                continue;
            };
            edges.push(WingedEdge {
                start_vertex: pair.end_vertex,
                end_vertex: half.end_vertex,
                left_face: half.face,
                right_face: pair.face,
                left_predecessor: edge(Some(half.successor_edge)),
                left_successor: edge(self.predecessor_edge(id)),
                right_predecessor: edge(Some(pair.successor_edge)),
                right_successor: edge(self.predecessor_edge(half.pair_edge)),
            });
            pairs.push((id, half.pair_edge));
        }
        let mut lowest = vec![NONE; self.faces.len()];
        for (half_edge, &e) in half_edges.iter().zip(&edge_of) {
            if let Some(slot) = half_edge.face.and_then(|f| lowest.get_mut(f.index())) {
                *slot = (*slot).min(e);
            }
        }
        let faces = lowest
            .into_iter()
            .map(|e| winged_edge::Face {
                incident_edge: EdgeId::new(e),
            })
            .collect();
        let vertices = winged_edge::Vertex::rows(
            self.vertices.iter().map(|vertex| vertex.position),
            &lowest_incident(self.vertices.len(), &edges),
        );
        let correspondence = EdgeCorrespondence {
            edge_of_half_edge: edge_of.into_iter().map(EdgeId::new).collect(),
            half_edges_of_edge: pairs,
            renumbering: None,
        };
        Ok((
            WingedEdgeMesh::from_raw_parts(vertices, faces, edges),
            correspondence,
        ))
    }

    /// The faces as a polygon list: each face counter-clockwise from the start
    /// vertex of its incident edge (for a built mesh, exactly as it was
    /// listed). Meant for valid meshes; a broken face gives what its walk
    /// reaches.
    pub fn to_polygons(&self) -> Polygons {
        let mut polygons =
            Polygons::with_capacity(self.vertices.len(), self.faces.len(), self.half_edges.len());
        for vertex in &self.vertices {
            polygons.push_vertex(vertex.position);
        }
        let mut face = Vec::new();
        for f in (0..self.faces.len() as u32).map(FaceId::new) {
            face.clear();
            face.extend(self.face_vertices(f).map(VertexId::raw));
            polygons.push_face(&face);
        }
        polygons
    }
}

/// The lowest-numbered edge at each vertex.
fn lowest_incident(vertex_count: usize, edges: &[WingedEdge]) -> Vec<u32> {
    let mut incident = vec![NONE; vertex_count];
    for (e, edge) in (0u32..).zip(edges) {
        for v in [edge.start_vertex, edge.end_vertex] {
            if let Some(slot) = incident.get_mut(v.index())
                && *slot == NONE
            {
                *slot = e;
            }
        }
    }
    incident
}

impl WingedEdgeMesh {
    /// The same mesh as a half-edge structure, numbered as
    /// [`HalfEdgeMesh::build`] numbers [`Self::to_polygons`]. Refuses a mesh
    /// that fails [`validate`](Self::validate).
    pub fn to_half_edge(&self) -> Result<HalfEdgeMesh, ConvertError> {
        self.to_half_edge_with_correspondence()
            .map(|(mesh, _)| mesh)
    }

    /// [`to_half_edge`](Self::to_half_edge), also telling which half-edges
    /// each edge became.
    pub fn to_half_edge_with_correspondence(
        &self,
    ) -> Result<(HalfEdgeMesh, EdgeCorrespondence), ConvertError> {
        if !self.deleted().is_empty() {
            let mut compacted = self.clone();
            let renumbering = compacted.compact();
            let (mesh, correspondence) = compacted.to_half_edge_with_correspondence()?;
            return Ok((mesh, correspondence.after(renumbering)));
        }
        check(self.validate())?;
        let (polygons, sides) = self.polygons_and_sides();
        if let Some((face, vertex)) = polygons.repeated_corner() {
            return Err(ConvertError::PassesTwice { face, vertex });
        }
        let (mesh, _) = HalfEdgeMesh::build(&polygons).map_err(ConvertError::Build)?;
        // Interior half-edge h is step h of the face walks; a boundary
        // half-edge belongs to its pair's edge.
        let mut edge_of: Vec<EdgeId> = sides.iter().map(|&(e, _)| e).collect();
        let mut halves = vec![(HalfEdgeId::new(NONE), HalfEdgeId::new(NONE)); self.edges.len()];
        for (h, half_edge) in (0u32..).map(HalfEdgeId::new).zip(mesh.half_edges()) {
            let (e, side) = match sides.get(h.index()) {
                Some(&side) => side,
                None => {
                    let pair = sides
                        .get(half_edge.pair_edge.index())
                        .copied()
                        .unwrap_or((EdgeId::new(NONE), Side::Left));
                    edge_of.push(pair.0);
                    (pair.0, pair.1.opposite())
                }
            };
            if let Some(slot) = halves.get_mut(e.index()) {
                match side {
                    Side::Left => slot.0 = h,
                    Side::Right => slot.1 = h,
                }
            }
        }
        Ok((
            mesh,
            EdgeCorrespondence {
                edge_of_half_edge: edge_of,
                half_edges_of_edge: halves,
                renumbering: None,
            },
        ))
    }

    /// The faces as a polygon list, each counter-clockwise from the start of
    /// its lowest-numbered edge having it on the left (or, failing that, its
    /// lowest-numbered edge), so building the list again reproduces this
    /// mesh's numbering. Meant for valid meshes; a broken face gives what its
    /// walk reaches.
    pub fn to_polygons(&self) -> Polygons {
        self.polygons_and_sides().0
    }

    /// The polygon list and, for every corner, the edge side it walks.
    fn polygons_and_sides(&self) -> (Polygons, Vec<(EdgeId, Side)>) {
        let mut starts: Vec<Option<(EdgeId, Side)>> = vec![None; self.faces.len()];
        for side in [Side::Left, Side::Right] {
            for (e, edge) in (0u32..).map(EdgeId::new).zip(&self.edges) {
                if let Some(slot) = edge.face(side).and_then(|f| starts.get_mut(f.index()))
                    && slot.is_none()
                {
                    *slot = Some((e, side));
                }
            }
        }
        let mut polygons =
            Polygons::with_capacity(self.vertices.len(), self.faces.len(), self.edges.len() * 2);
        for vertex in &self.vertices {
            polygons.push_vertex(vertex.position);
        }
        let mut sides = Vec::with_capacity(self.edges.len() * 2);
        let mut face = Vec::new();
        for (f, &start) in (0u32..).map(FaceId::new).zip(&starts) {
            face.clear();
            for (e, side) in self.face_sides_from(f, start) {
                if let Some(edge) = self.edge(e) {
                    face.push(edge.ccw_start(side).raw());
                    sides.push((e, side));
                }
            }
            polygons.push_face(&face);
        }
        (polygons, sides)
    }
}
