//! What the VM needs from a mesh: its structure, its table sizes, and the
//! lookups. Keeping this a trait lets the VM run on the winged-edge and
//! half-edge structures (implemented below) and on anything else with tables.

use super::types::{Element, ElementKind, Field, Structure};
use crate::mesh::{self, EdgeId, FaceId, HalfEdgeId, HalfEdgeMesh, VertexId, WingedEdgeMesh};
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

impl From<mesh::Structure> for Structure {
    fn from(structure: mesh::Structure) -> Structure {
        match structure {
            mesh::Structure::WingedEdge => Structure::WingedEdge,
            mesh::Structure::HalfEdge => Structure::HalfEdge,
        }
    }
}

impl From<Structure> for mesh::Structure {
    fn from(structure: Structure) -> mesh::Structure {
        match structure {
            Structure::WingedEdge => mesh::Structure::WingedEdge,
            Structure::HalfEdge => mesh::Structure::HalfEdge,
        }
    }
}

fn vertex(id: VertexId) -> Element {
    Element::Vertex(id.raw())
}

fn face(id: FaceId) -> Element {
    Element::Face(id.raw())
}

impl Topology for WingedEdgeMesh {
    fn structure(&self) -> Structure {
        Structure::WingedEdge
    }

    fn count(&self, kind: ElementKind) -> usize {
        match kind {
            ElementKind::Vertex => self.vertex_count(),
            ElementKind::Edge => self.edge_count(),
            ElementKind::Face => self.face_count(),
        }
    }

    #[inline]
    fn lookup(&self, element: Element, field: Field) -> Result<Option<Element>, LookupError> {
        let missing = || LookupError::NoSuchElement(element);
        let edge_of = |e: EdgeId| Some(Element::Edge(e.raw()));
        match (element, field) {
            (Element::Vertex(v), Field::IncidentEdge) => {
                let row = self.vertex(VertexId::new(v)).ok_or_else(missing)?;
                Ok(row.incident_edge.and_then(edge_of))
            }
            (Element::Face(f), Field::IncidentEdge) => {
                let row = self.face(FaceId::new(f)).ok_or_else(missing)?;
                Ok(edge_of(row.incident_edge))
            }
            (Element::Edge(e), _) => {
                let row = self.edge(EdgeId::new(e)).ok_or_else(missing)?;
                Ok(match field {
                    Field::StartVertex => Some(vertex(row.start_vertex)),
                    Field::EndVertex => Some(vertex(row.end_vertex)),
                    Field::LeftFace => row.left_face.map(face),
                    Field::RightFace => row.right_face.map(face),
                    Field::LeftPredecessor => edge_of(row.left_predecessor),
                    Field::LeftSuccessor => edge_of(row.left_successor),
                    Field::RightPredecessor => edge_of(row.right_predecessor),
                    Field::RightSuccessor => edge_of(row.right_successor),
                    _ => return Err(LookupError::NotApplicable { element, field }),
                })
            }
            _ => Err(LookupError::NotApplicable { element, field }),
        }
    }
}

impl Topology for HalfEdgeMesh {
    fn structure(&self) -> Structure {
        Structure::HalfEdge
    }

    fn count(&self, kind: ElementKind) -> usize {
        match kind {
            ElementKind::Vertex => self.vertex_count(),
            ElementKind::Edge => self.half_edge_count(),
            ElementKind::Face => self.face_count(),
        }
    }

    #[inline]
    fn lookup(&self, element: Element, field: Field) -> Result<Option<Element>, LookupError> {
        let missing = || LookupError::NoSuchElement(element);
        let edge_of = |h: HalfEdgeId| Some(Element::Edge(h.raw()));
        match (element, field) {
            (Element::Vertex(v), Field::IncidentEdge) => {
                let row = self.vertex(VertexId::new(v)).ok_or_else(missing)?;
                Ok(row.incident_edge.and_then(edge_of))
            }
            (Element::Face(f), Field::IncidentEdge) => {
                let row = self.face(FaceId::new(f)).ok_or_else(missing)?;
                Ok(edge_of(row.incident_edge))
            }
            (Element::Edge(e), _) => {
                let id = HalfEdgeId::new(e);
                let row = self.half_edge(id).ok_or_else(missing)?;
                Ok(match field {
                    Field::EndVertex => Some(vertex(row.end_vertex)),
                    Field::StartVertex => Some(vertex(self.start_vertex(id).ok_or_else(missing)?)),
                    Field::AdjacentFace => row.face.map(face),
                    Field::PairEdge => edge_of(row.pair_edge),
                    Field::SuccessorEdge => edge_of(row.successor_edge),
                    Field::PredecessorEdge => self.predecessor_edge(id).and_then(edge_of),
                    _ => return Err(LookupError::NotApplicable { element, field }),
                })
            }
            _ => Err(LookupError::NotApplicable { element, field }),
        }
    }
}

/// Either structure, as loaded: the VM runs on whichever the mesh holds.
impl Topology for mesh::Mesh {
    fn structure(&self) -> Structure {
        mesh::Mesh::structure(self).into()
    }

    fn count(&self, kind: ElementKind) -> usize {
        match self {
            mesh::Mesh::Winged(m) => m.count(kind),
            mesh::Mesh::Half(m) => m.count(kind),
        }
    }

    #[inline]
    fn lookup(&self, element: Element, field: Field) -> Result<Option<Element>, LookupError> {
        match self {
            mesh::Mesh::Winged(m) => m.lookup(element, field),
            mesh::Mesh::Half(m) => m.lookup(element, field),
        }
    }
}
