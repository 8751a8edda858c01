//! Why an operation was refused, naming the elements at fault. Every
//! refusal is found before the first change, so a refused operation leaves
//! the mesh untouched.

use std::fmt;

use super::Operation;
use crate::mesh::edit::EditError;
use crate::mesh::ids::{FaceId, VertexId};
use crate::mesh::validate::Element;
use crate::schema::{Column, ElementRef};

/// An edge as a message names it: a winged edge by its id, a half-edge
/// pair by the half-edge it was named by ("the edge of half-edge 7").
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct EdgeName(pub Element);

impl fmt::Display for EdgeName {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.0 {
            Element::HalfEdge(h) => write!(f, "the edge of {h}"),
            other => other.fmt(f),
        }
    }
}

/// What was being done, as a refusal's message opens: "collapsing edge 3
/// would …".
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Action {
    Flipping(EdgeName),
    Splitting(EdgeName),
    SplittingFace(FaceId),
    Collapsing(EdgeName),
    Removing(VertexId),
    /// KEV.
    Contracting(EdgeName),
    /// KEF and KEMR.
    RemovingEdge(EdgeName),
    /// MEKR: a face joined to the boundary loop through a vertex.
    Joining {
        face: FaceId,
        boundary: VertexId,
    },
}

impl fmt::Display for Action {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Flipping(edge) => write!(f, "flipping {edge}"),
            Self::Splitting(edge) => write!(f, "splitting {edge}"),
            Self::SplittingFace(face) => write!(f, "splitting {face}"),
            Self::Collapsing(edge) => write!(f, "collapsing {edge}"),
            Self::Removing(vertex) => write!(f, "removing {vertex}"),
            Self::Contracting(edge) => write!(f, "contracting {edge}"),
            Self::RemovingEdge(edge) => write!(f, "removing {edge}"),
            Self::Joining { face, boundary } => {
                write!(f, "joining {face} to the boundary loop at {boundary}")
            }
        }
    }
}

/// Why an operation did not happen.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Refusal {
    /// The wrong number of ids for the operation.
    Arguments {
        operation: Operation,
        given: usize,
    },
    /// An id past the end of its table.
    NoSuchElement(Element),
    /// An id whose row an edit deleted.
    Deleted(Element),
    /// A reference a valid mesh has is missing or leads nowhere.
    Broken {
        element: Element,
        column: Column,
    },
    /// The operation needs a face where the boundary is.
    OnBoundary {
        operation: Operation,
        edge: EdgeName,
    },
    /// The operation needs two different faces on the edge's sides.
    SameFaceOnBothSides {
        operation: Operation,
        edge: EdgeName,
        face: FaceId,
    },
    /// A flip needs two triangles.
    NotTriangle {
        operation: Operation,
        face: FaceId,
        edges: usize,
    },
    /// The two triangles of an edge have the same third corner.
    SharedCorner {
        action: Action,
        vertex: VertexId,
    },
    /// The new edge would join two vertices an edge joins already.
    EdgeExists {
        action: Action,
        a: VertexId,
        b: VertexId,
        existing: EdgeName,
    },
    /// The two ends of an edge share a neighbour that the faces beside the
    /// edge do not account for.
    LinkCondition {
        action: Action,
        edge: EdgeName,
        a: VertexId,
        b: VertexId,
        shared: VertexId,
    },
    /// An interior edge between two boundary vertices.
    BoundaryPinch {
        action: Action,
        edge: EdgeName,
        a: VertexId,
        b: VertexId,
    },
    /// Two edges merged into one would have the same face (or none) on
    /// both sides.
    MergedEdge {
        action: Action,
        a: VertexId,
        b: VertexId,
        face: Option<FaceId>,
    },
    /// Only two faces would be left, glued to each other along every edge.
    TooSmall {
        action: Action,
        faces: [FaceId; 2],
    },
    /// A face would be left with fewer than three edges.
    FaceTooSmall {
        action: Action,
        face: FaceId,
        edges: usize,
    },
    /// An edge would be left with no face on either side.
    NoFaceEither {
        action: Action,
        edge: EdgeName,
    },
    /// The boundary would pass a vertex twice.
    PinchesVertex {
        action: Action,
        vertex: VertexId,
    },
    /// A face would be left walking only edges it has on both sides.
    OnlyDangling {
        action: Action,
        face: FaceId,
    },
    NotOnFace {
        face: FaceId,
        vertex: VertexId,
    },
    /// A face that passes a vertex twice has two corners there.
    PassesTwice {
        face: FaceId,
        vertex: VertexId,
    },
    SameVertex {
        vertex: VertexId,
    },
    /// Two vertices that follow each other around the face.
    AdjacentOnFace {
        face: FaceId,
        a: VertexId,
        b: VertexId,
    },
    BoundaryVertex {
        vertex: VertexId,
    },
    IsolatedVertex {
        vertex: VertexId,
    },
    /// The face the operation makes would pass a vertex twice.
    NotSimple {
        action: Action,
        vertex: VertexId,
    },
    NotAtVertex {
        edge: EdgeName,
        vertex: VertexId,
    },
    /// A dangling edge would go into a boundary gap.
    CornerOnBoundary {
        vertex: VertexId,
        edge: EdgeName,
    },
    BothCornersOnBoundary {
        vertex: VertexId,
    },
    /// KEMR needs the same face on both sides.
    NotBridge {
        edge: EdgeName,
        faces: [Option<FaceId>; 2],
    },
    /// One end of the edge has no other edge.
    Dangling {
        edge: EdgeName,
        vertex: VertexId,
    },
    NotOnBoundary {
        vertex: VertexId,
    },
    /// A vertex where the boundary passes more than once.
    SeveralBoundaries {
        vertex: VertexId,
        count: usize,
    },
    /// A change failed while the plan was written; every change made was
    /// taken back.
    EditFailed(EditError),
    /// A new row did not get the id the plan gave it; every change made
    /// was taken back.
    Numbering {
        planned: ElementRef,
        made: ElementRef,
    },
}

fn face_or_boundary(face: Option<FaceId>) -> String {
    face.map_or_else(|| "the boundary".to_owned(), |face| face.to_string())
}

impl Refusal {
    /// Why the boundary is in the way, for [`Refusal::OnBoundary`].
    fn boundary_reason(operation: Operation) -> &'static str {
        match operation {
            Operation::FlipEdge => "a flip needs two faces",
            Operation::Kef => "KEF merges the faces on its two sides",
            Operation::Kemr => "KEMR removes an edge with the same face on both sides",
            _ => "the operation needs a face on each side",
        }
    }

    /// Why one face on both sides is in the way, for
    /// [`Refusal::SameFaceOnBothSides`].
    fn same_face_reason(operation: Operation) -> &'static str {
        match operation {
            Operation::FlipEdge => "a flip needs two different triangles",
            Operation::Kef => "KEF merges two different faces (KEMR removes an edge like this)",
            Operation::Kev => {
                "only a dangling edge may have one face around it (KEMR removes a bridge)"
            }
            Operation::CollapseEdge => "a collapse needs two different faces or the boundary",
            _ => "the operation needs two different faces",
        }
    }
}

impl fmt::Display for Refusal {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Arguments { operation, given } => {
                let arguments = operation.arguments();
                let required = arguments.iter().filter(|a| !a.optional).count();
                let count = if required == arguments.len() {
                    required.to_string()
                } else {
                    format!("{required} or {}", arguments.len())
                };
                let plural = if arguments.len() == 1 { "id" } else { "ids" };
                let names: Vec<String> = arguments.iter().map(ToString::to_string).collect();
                write!(
                    f,
                    "{operation} takes {count} {plural} ({}), not {given}",
                    names.join(", ")
                )
            }
            Self::NoSuchElement(element) => {
                let row = ElementRef::from(*element);
                if row.id == u32::MAX {
                    // An unset reference led here: name what is missing.
                    let kind = row.kind.prose();
                    let article = crate::schema::article(kind);
                    write!(f, "{article} {kind} it needs is not set yet")
                } else {
                    write!(f, "{element} does not exist")
                }
            }
            Self::Deleted(element) => write!(f, "{element} was deleted"),
            Self::Broken { element, column } => write!(
                f,
                "{element} {}: the tables are broken here (check the mesh to see why)",
                column.record_name()
            ),
            Self::OnBoundary { operation, edge } => write!(
                f,
                "{edge} is on the boundary; {}",
                Self::boundary_reason(*operation)
            ),
            Self::SameFaceOnBothSides {
                operation,
                edge,
                face,
            } => write!(
                f,
                "{edge} has {face} on both sides; {}",
                Self::same_face_reason(*operation)
            ),
            Self::NotTriangle {
                operation,
                face,
                edges,
            } => {
                write!(f, "{face} is not a triangle (it has {edges} edges); ")?;
                match operation {
                    Operation::FlipEdge => write!(f, "a flip needs two triangles"),
                    other => write!(f, "{other} needs triangles"),
                }
            }
            Self::SharedCorner { action, vertex } => write!(
                f,
                "{action} is refused: both of its triangles have {vertex} as their third corner, so they share all three vertices"
            ),
            Self::EdgeExists {
                action,
                a,
                b,
                existing,
            } => write!(
                f,
                "{action} would join vertices {} and {} a second time ({existing} already joins them)",
                a.raw(),
                b.raw()
            ),
            Self::LinkCondition {
                action,
                edge,
                a,
                b,
                shared,
            } => write!(
                f,
                "{action} would make the mesh non-manifold: vertices {} and {} share neighbour {} outside the faces of {edge} (the link condition)",
                a.raw(),
                b.raw(),
                shared.raw()
            ),
            Self::BoundaryPinch { action, edge, a, b } => write!(
                f,
                "{action} would pinch the surface: vertices {} and {} are both on the boundary but {edge} is not (the link condition)",
                a.raw(),
                b.raw()
            ),
            Self::MergedEdge { action, a, b, face } => match face {
                Some(face) => write!(
                    f,
                    "{action} would leave {face} on both sides of the edge between vertices {} and {}",
                    a.raw(),
                    b.raw()
                ),
                None => write!(
                    f,
                    "{action} would leave the edge between vertices {} and {} with no face on either side",
                    a.raw(),
                    b.raw()
                ),
            },
            Self::TooSmall { action, faces } => write!(
                f,
                "{action} would leave only {} and {}, glued to each other along every edge (the mesh is too small)",
                faces[0], faces[1]
            ),
            Self::FaceTooSmall {
                action,
                face,
                edges,
            } => write!(
                f,
                "{action} would leave {face} with {edges} edges; a face needs at least 3"
            ),
            Self::NoFaceEither { action, edge } => {
                write!(f, "{action} would leave {edge} with no face on either side")
            }
            Self::PinchesVertex { action, vertex } => write!(
                f,
                "{action} would pinch the surface at {vertex}: the boundary passes it already"
            ),
            Self::OnlyDangling { action, face } => write!(
                f,
                "{action} would leave {face} bounded only by dangling edges, which it has on both sides"
            ),
            Self::NotOnFace { face, vertex } => write!(f, "{vertex} is not on {face}"),
            Self::PassesTwice { face, vertex } => write!(
                f,
                "{face} passes {vertex} twice, so which of its corners is meant is ambiguous"
            ),
            Self::SameVertex { vertex } => {
                write!(f, "the two vertices must differ ({vertex} was given twice)")
            }
            Self::AdjacentOnFace { face, a, b } => write!(
                f,
                "vertices {} and {} are neighbours around {face}; an edge between them would make a face of two edges",
                a.raw(),
                b.raw()
            ),
            Self::BoundaryVertex { vertex } => write!(
                f,
                "{vertex} is on the boundary; only an interior vertex can be removed"
            ),
            Self::IsolatedVertex { vertex } => {
                write!(
                    f,
                    "{vertex} has no edges, so there are no faces around it to merge"
                )
            }
            Self::NotSimple { action, vertex } => {
                write!(f, "{action} would make a face that passes {vertex} twice")
            }
            Self::NotAtVertex { edge, vertex } => {
                write!(f, "{edge} does not start or end at {vertex}")
            }
            Self::CornerOnBoundary { vertex, edge } => write!(
                f,
                "the corner after {edge} at {vertex} is on the boundary; a dangling edge must go into a face"
            ),
            Self::BothCornersOnBoundary { vertex } => write!(
                f,
                "both corners at {vertex} are on the boundary; the new edge would have no face on either side"
            ),
            Self::NotBridge { edge, faces } => write!(
                f,
                "{edge} has {} on one side and {} on the other; KEMR removes an edge with the same face on both sides (KEF merges two faces)",
                face_or_boundary(faces[0]),
                face_or_boundary(faces[1])
            ),
            Self::Dangling { edge, vertex } => write!(
                f,
                "{edge} dangles: {vertex} has no other edge; KEMR removes a bridge between two cycles (KEV removes a dangling edge)"
            ),
            Self::NotOnBoundary { vertex } => write!(f, "{vertex} is not on a boundary loop"),
            Self::SeveralBoundaries { vertex, count } => write!(
                f,
                "the boundary passes {vertex} at {count} corners, so which one is meant is ambiguous"
            ),
            Self::EditFailed(error) => {
                write!(
                    f,
                    "the edit failed and every change was taken back: {error}"
                )
            }
            Self::Numbering { planned, made } => write!(
                f,
                "the edit planned to make {planned} but the table made {made}; every change was taken back"
            ),
        }
    }
}

impl std::error::Error for Refusal {}
