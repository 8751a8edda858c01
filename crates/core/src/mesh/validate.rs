//! `validate()`: every rule the tables must satisfy, each violation reported
//! with the element, the field (table column) it concerns and a one-line
//! explanation. File loaders map the element and field to a line and column.
//!
//! Every check is linear in the table sizes and stops walking a cycle once it
//! is longer than it can be, so broken tables cannot make it loop.

use std::fmt;

use super::deleted::Deleted;
use super::half_edge::{HalfEdge, HalfEdgeMesh};
use super::ids::{EdgeId, FaceId, HalfEdgeId, VertexId};
use super::winged_edge::{Side, WingedEdge, WingedEdgeMesh};
use crate::schema::{Column, ElementKind, ElementRef, Structure};

/// The table row an issue is about.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Element {
    /// A vertex row.
    Vertex(VertexId),
    /// A winged-edge row.
    Edge(EdgeId),
    /// A half-edge row.
    HalfEdge(HalfEdgeId),
    /// A face row.
    Face(FaceId),
}

impl Element {
    /// A row of `structure`'s tables, as messages name it: an edge row is a
    /// half-edge in a half-edge mesh.
    pub fn of(structure: Structure, row: ElementRef) -> Self {
        match (row.kind, structure) {
            (ElementKind::Vertex, _) => Self::Vertex(VertexId::new(row.id)),
            (ElementKind::Face, _) => Self::Face(FaceId::new(row.id)),
            (ElementKind::Edge, Structure::WingedEdge) => Self::Edge(EdgeId::new(row.id)),
            (ElementKind::Edge, Structure::HalfEdge) => Self::HalfEdge(HalfEdgeId::new(row.id)),
        }
    }
}

impl fmt::Display for Element {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Vertex(id) => id.fmt(f),
            Self::Edge(id) => id.fmt(f),
            Self::HalfEdge(id) => id.fmt(f),
            Self::Face(id) => id.fmt(f),
        }
    }
}

impl From<Element> for ElementRef {
    fn from(element: Element) -> Self {
        match element {
            Element::Vertex(id) => id.into(),
            Element::Edge(id) => id.into(),
            Element::HalfEdge(id) => id.into(),
            Element::Face(id) => id.into(),
        }
    }
}

/// One violated rule.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Issue {
    /// The row.
    pub element: Element,
    /// The column.
    pub field: Column,
    /// What is wrong, in one line.
    pub message: String,
}

impl Issue {
    /// The issue with its field as the algorithm language names it
    /// ("edge 3 successorEdge: …"), for the app, where students read the
    /// language; [`fmt::Display`] names the field as the files do.
    pub fn in_language(&self) -> String {
        format!(
            "{} {}: {}",
            self.element,
            self.field.lookup_name(),
            self.message
        )
    }
}

impl fmt::Display for Issue {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{} {}: {}",
            self.element,
            self.field.record_name(),
            self.message
        )
    }
}

fn describe_face(face: Option<FaceId>) -> String {
    face.map_or_else(|| "the boundary".to_owned(), |f| f.to_string())
}

fn side_name(side: Side) -> &'static str {
    match side {
        Side::Left => "left",
        Side::Right => "right",
    }
}

/// Why a reference leads to no row: it was never set, its row was deleted,
/// or it is past the end of the table.
fn missing_row<I>(deleted: &Deleted, target: I, count: usize, plural: &str) -> String
where
    I: Copy + fmt::Display + Into<ElementRef>,
{
    let element: ElementRef = target.into();
    if element.id == u32::MAX - 1 {
        "it is not set".to_owned()
    } else if deleted.contains(element) {
        format!("{target} was deleted")
    } else {
        format!("{target} does not exist (there are {count} {plural})")
    }
}

/// Both structures name missing rows the same way.
macro_rules! missing {
    ($($mesh:ty),*) => {$(
        impl $mesh {
            fn missing<I>(&self, target: I, count: usize, plural: &str) -> String
            where
                I: Copy + fmt::Display + Into<ElementRef>,
            {
                missing_row(&self.deleted, target, count, plural)
            }
        }
    )*};
}

missing!(HalfEdgeMesh, WingedEdgeMesh);

struct Issues(Vec<Issue>);

impl Issues {
    fn push(&mut self, element: Element, field: Column, message: String) {
        self.0.push(Issue {
            element,
            field,
            message,
        });
    }
}

fn check_position(issues: &mut Issues, v: VertexId, position: glam::Vec3) {
    if !position.is_finite() {
        issues.push(
            Element::Vertex(v),
            Column::Position,
            format!(
                "position ({}, {}, {}) is not a finite point",
                position.x, position.y, position.z
            ),
        );
    }
}

impl HalfEdgeMesh {
    /// Lists every violated rule, or nothing for a sound mesh: pair(pair(h))
    /// = h and the halves end at different vertices; each successor lies in
    /// the same face, starts where its half-edge ends and has exactly one
    /// predecessor; each face's successor cycle from its incident edge closes
    /// and covers the face; each vertex's incident edge ends at it and the loop
    /// (successor, then pair) from it reaches every half-edge ending there.
    pub fn validate(&self) -> Vec<Issue> {
        let mut issues = Issues(Vec::new());
        let (incoming, face_size) = self.check_half_edges(&mut issues);
        self.check_faces(&mut issues, &face_size);
        self.check_vertices(&mut issues, &incoming);
        issues.0
    }

    /// Checks each half-edge's references, and counts the half-edges that
    /// end at each vertex and lie in each face, which the face and vertex
    /// checks compare their cycles with.
    fn check_half_edges(&self, issues: &mut Issues) -> (Vec<u32>, Vec<u32>) {
        let (nv, nf) = (self.vertices.len(), self.faces.len());
        let mut incoming = vec![0u32; nv];
        let mut face_size = vec![0u32; nf];
        for (id, h) in (0u32..).map(HalfEdgeId::new).zip(&self.half_edges) {
            if self.deleted.contains(id.into()) {
                continue;
            }
            let element = Element::HalfEdge(id);
            match incoming
                .get_mut(h.end_vertex.index())
                .filter(|_| self.vertex(h.end_vertex).is_some())
            {
                Some(count) => *count += 1,
                None => issues.push(
                    element,
                    Column::EndVertex,
                    self.missing(h.end_vertex, nv, "vertices"),
                ),
            }
            if let Some(f) = h.face {
                match face_size
                    .get_mut(f.index())
                    .filter(|_| self.face(f).is_some())
                {
                    Some(count) => *count += 1,
                    None => issues.push(element, Column::Face, self.missing(f, nf, "faces")),
                }
            }
            self.check_pair(issues, id, h);
            self.check_successor(issues, id, h);
        }
        (incoming, face_size)
    }

    /// pair(pair(h)) = h, the halves end at different vertices, and an
    /// edge has a face on at least one side.
    fn check_pair(&self, issues: &mut Issues, id: HalfEdgeId, h: &HalfEdge) {
        let element = Element::HalfEdge(id);
        let nh = self.half_edges.len();
        match self.half_edge(h.pair_edge) {
            None => issues.push(
                element,
                Column::PairEdge,
                self.missing(h.pair_edge, nh, "half-edges"),
            ),
            Some(_) if h.pair_edge == id => {
                issues.push(element, Column::PairEdge, "the half-edge is its own pair edge".to_owned());
            }
            Some(pair) if pair.pair_edge != id => issues.push(
                element,
                Column::PairEdge,
                format!(
                    "its pair edge {} has {} as pair edge, not this half-edge (pair(pair(h)) must be h)",
                    h.pair_edge, pair.pair_edge
                ),
            ),
            Some(pair) => {
                if pair.end_vertex == h.end_vertex {
                    issues.push(
                        element,
                        Column::PairEdge,
                        format!(
                            "it and its pair edge {} both end at {}; the halves of an edge end at its two different vertices",
                            h.pair_edge, h.end_vertex
                        ),
                    );
                }
                if h.face.is_none() && pair.face.is_none() && id < h.pair_edge {
                    issues.push(
                        element,
                        Column::Face,
                        format!(
                            "neither it nor its pair edge {} has a face; an edge needs a face on at least one side",
                            h.pair_edge
                        ),
                    );
                }
            }
        }
    }

    /// The successor lies in the same face, starts where the half-edge
    /// ends, and has no other predecessor.
    fn check_successor(&self, issues: &mut Issues, id: HalfEdgeId, h: &HalfEdge) {
        let element = Element::HalfEdge(id);
        let nh = self.half_edges.len();
        match self.half_edge(h.successor_edge) {
            None => issues.push(
                element,
                Column::SuccessorEdge,
                self.missing(h.successor_edge, nh, "half-edges"),
            ),
            Some(successor) => {
                if successor.face != h.face {
                    issues.push(
                        element,
                        Column::SuccessorEdge,
                        format!(
                            "its successor {} lies in {}, but this half-edge lies in {}",
                            h.successor_edge,
                            describe_face(successor.face),
                            describe_face(h.face)
                        ),
                    );
                }
                if let Some(start) = self.start_vertex(h.successor_edge)
                    && start != h.end_vertex
                {
                    issues.push(
                        element,
                        Column::SuccessorEdge,
                        format!(
                            "its successor {} starts at {start}, but this half-edge ends at {}",
                            h.successor_edge, h.end_vertex
                        ),
                    );
                }
                if let Some(first) = self.predecessor_edge(h.successor_edge)
                    && first != id
                {
                    issues.push(
                        element,
                        Column::SuccessorEdge,
                        format!(
                            "{} is already the successor of {first}; every half-edge has exactly one predecessor",
                            h.successor_edge
                        ),
                    );
                }
            }
        }
    }

    /// Each face's successor cycle from its incident edge closes, covers the
    /// face and has at least three half-edges.
    fn check_faces(&self, issues: &mut Issues, face_size: &[u32]) {
        let nh = self.half_edges.len();
        for ((id, face), &size) in (0u32..).map(FaceId::new).zip(&self.faces).zip(face_size) {
            if self.deleted.contains(id.into()) {
                continue;
            }
            let start = face.incident_edge;
            let message = match self.half_edge(start) {
                None => self.missing(start, nh, "half-edges"),
                Some(h) if h.face != Some(id) => {
                    format!(
                        "its incident edge {start} lies in {}, not in this face",
                        describe_face(h.face)
                    )
                }
                Some(_) => {
                    let (length, closed) = cycle(start, size, |h| {
                        let next = self.half_edge(h)?.successor_edge;
                        (self.half_edge(next)?.face == Some(id)).then_some(next)
                    });
                    if !closed {
                        format!(
                            "the successor links from its incident edge {start} do not come back to it"
                        )
                    } else if length != size {
                        format!(
                            "the successor cycle from its incident edge {start} has {length} half-edges, but {size} half-edges lie in this face; a face is a single cycle"
                        )
                    } else if length < 3 {
                        format!("it has only {length} edges; a face needs at least 3")
                    } else {
                        continue;
                    }
                }
            };
            issues.push(Element::Face(id), Column::IncidentEdge, message);
        }
    }

    /// Each vertex's position is a point, and its incident edge ends at it
    /// and starts a loop that reaches every half-edge ending there.
    fn check_vertices(&self, issues: &mut Issues, incoming: &[u32]) {
        let nh = self.half_edges.len();
        for ((id, vertex), &count) in (0u32..)
            .map(VertexId::new)
            .zip(&self.vertices)
            .zip(incoming)
        {
            if self.deleted.contains(id.into()) {
                continue;
            }
            check_position(issues, id, vertex.position);
            let message = match vertex.incident_edge {
                None if count == 0 => continue,
                None => format!("it has no incident edge, but {count} half-edges end here"),
                Some(start) => match self.half_edge(start) {
                    None => self.missing(start, nh, "half-edges"),
                    Some(h) if h.end_vertex != id => format!(
                        "its incident edge {start} ends at {}; a vertex's incident edge is a half-edge ending at it",
                        h.end_vertex
                    ),
                    Some(_) => {
                        let (reached, closed) = cycle(start, count, |h| {
                            let successor = self.half_edge(h)?.successor_edge;
                            let next = self.half_edge(successor)?.pair_edge;
                            (self.half_edge(next)?.end_vertex == id).then_some(next)
                        });
                        if closed && reached == count {
                            continue;
                        } else if closed {
                            format!(
                                "the loop around it from {start} (successor, then pair) reaches {reached} of the {count} half-edges ending here; the vertex joins separate fans"
                            )
                        } else {
                            format!(
                                "the loop around it from {start} (successor, then pair) does not come back to it"
                            )
                        }
                    }
                },
            };
            issues.push(Element::Vertex(id), Column::IncidentEdge, message);
        }
    }
}

/// Follows `next` from `start` for at most `limit + 1` steps; returns how many
/// elements it visited and whether it came back to `start`.
fn cycle<T: PartialEq + Copy>(start: T, limit: u32, next: impl Fn(T) -> Option<T>) -> (u32, bool) {
    let mut current = start;
    let mut length = 0;
    while length <= limit {
        length += 1;
        match next(current) {
            Some(following) if following == start => return (length, true),
            Some(following) => current = following,
            None => break,
        }
    }
    (length, false)
}

impl WingedEdgeMesh {
    /// Lists every violated rule, or nothing for a sound mesh: each edge joins
    /// two different existing vertices and has a face on at least one side;
    /// each wing borders the same face, meets this edge at the right vertex and
    /// names this edge back (the predecessor's successor is this edge); each
    /// face's cycle from its incident edge closes and covers the face; each
    /// vertex's incident edge touches it and the turn around it from there
    /// reaches every edge at the vertex.
    pub fn validate(&self) -> Vec<Issue> {
        let mut issues = Issues(Vec::new());
        let (nv, nf, ne) = (self.vertices.len(), self.faces.len(), self.edges.len());
        let mut degree = vec![0u32; nv];
        let mut face_size = vec![0u32; nf];
        for (id, edge) in (0u32..).map(EdgeId::new).zip(&self.edges) {
            if self.deleted.contains(id.into()) {
                continue;
            }
            let element = Element::Edge(id);
            for (v, field) in [
                (edge.start_vertex, Column::StartVertex),
                (edge.end_vertex, Column::EndVertex),
            ] {
                match degree
                    .get_mut(v.index())
                    .filter(|_| self.vertex(v).is_some())
                {
                    Some(count) => *count += 1,
                    None => issues.push(element, field, self.missing(v, nv, "vertices")),
                }
            }
            if edge.start_vertex == edge.end_vertex {
                issues.push(
                    element,
                    Column::EndVertex,
                    format!(
                        "the edge starts and ends at {}; an edge joins two different vertices",
                        edge.start_vertex
                    ),
                );
            }
            // The same face on both sides is allowed: a dangling edge (MEV)
            // or a bridge to an inner cycle (MEKR) is walked once each way
            // by its face, and the face cycle below checks that walk.
            if edge.left_face.is_none() && edge.right_face.is_none() {
                issues.push(
                    element,
                    Column::LeftFace,
                    "the edge has no face on either side; an edge needs a face on at least one side".to_owned(),
                );
            }
            for side in [Side::Left, Side::Right] {
                self.check_wings(&mut issues, id, edge, side, &mut face_size);
            }
        }

        for ((id, face), &size) in (0u32..).map(FaceId::new).zip(&self.faces).zip(&face_size) {
            if self.deleted.contains(id.into()) {
                continue;
            }
            let start = face.incident_edge;
            let message = match self.edge(start).map(|edge| edge.side_of(Some(id))) {
                None => self.missing(start, ne, "edges"),
                Some(None) => format!("its incident edge {start} does not border this face"),
                Some(Some(side)) => {
                    let (length, closed) = cycle((start, side), size, |(e, side)| {
                        let edge = self.edge(e)?;
                        let next = edge.predecessor(side);
                        let entered = edge.ccw_end(side);
                        Some((next, self.edge(next)?.side_entered_at(Some(id), entered)?))
                    });
                    if !closed {
                        format!(
                            "the wings from its incident edge {start} do not lead back to it around this face"
                        )
                    } else if length != size {
                        format!(
                            "the cycle of wings from its incident edge {start} has {length} edges, but {size} edges border this face; a face is a single cycle"
                        )
                    } else if length < 3 {
                        format!("it has only {length} edges; a face needs at least 3")
                    } else {
                        continue;
                    }
                }
            };
            issues.push(Element::Face(id), Column::IncidentEdge, message);
        }

        for ((id, vertex), &count) in (0u32..).map(VertexId::new).zip(&self.vertices).zip(&degree) {
            if self.deleted.contains(id.into()) {
                continue;
            }
            check_position(&mut issues, id, vertex.position);
            let message = match vertex.incident_edge {
                None if count == 0 => continue,
                None => format!("it has no incident edge, but {count} edges end here"),
                Some(start) => match self.edge(start) {
                    None => self.missing(start, ne, "edges"),
                    Some(edge) if edge.other_vertex(id).is_none() => {
                        format!("its incident edge {start} does not start or end here")
                    }
                    Some(_) => {
                        let (reached, closed) = cycle(start, count, |e| {
                            let next = self.next_around(e, id)?;
                            self.edge(next)?.other_vertex(id).map(|_| next)
                        });
                        if closed && reached == count {
                            continue;
                        } else if closed {
                            format!(
                                "the turn around it from {start} reaches {reached} of the {count} edges here; the vertex joins separate fans"
                            )
                        } else {
                            format!("the turn around it from {start} does not come back to it")
                        }
                    }
                },
            };
            issues.push(Element::Vertex(id), Column::IncidentEdge, message);
        }
        issues.0
    }

    /// The edge after `e` turning around `v` (the order of the half-edge
    /// paper's loop): the left predecessor if `e` ends at `v`, else the right
    /// predecessor.
    pub(crate) fn next_around(&self, e: EdgeId, v: VertexId) -> Option<EdgeId> {
        let edge = self.edge(e)?;
        if edge.end_vertex == v {
            Some(edge.left_predecessor)
        } else if edge.start_vertex == v {
            Some(edge.right_predecessor)
        } else {
            None
        }
    }

    fn check_wings(
        &self,
        issues: &mut Issues,
        id: EdgeId,
        edge: &WingedEdge,
        side: Side,
        face_size: &mut [u32],
    ) {
        let element = Element::Edge(id);
        let face = edge.face(side);
        let name = side_name(side);
        if let Some(f) = face {
            match face_size
                .get_mut(f.index())
                .filter(|_| self.face(f).is_some())
            {
                Some(count) => *count += 1,
                None => issues.push(
                    element,
                    Column::face_of(side),
                    self.missing(f, self.faces.len(), "faces"),
                ),
            }
        }
        // The clockwise traversal of `face` enters this edge at `enter` and
        // leaves it at `leave`.
        let (enter, leave) = (edge.ccw_end(side), edge.ccw_start(side));
        let ne = self.edges.len();

        let predecessor = edge.predecessor(side);
        let field = Column::predecessor_of(side);
        match self.edge(predecessor) {
            None => issues.push(element, field, self.missing(predecessor, ne, "edges")),
            Some(wing) => match wing.side_entered_at(face, enter) {
                None => issues.push(
                    element,
                    field,
                    format!(
                        "{predecessor} does not border {}, the {name} face of this edge",
                        describe_face(face)
                    ),
                ),
                Some(wing_side) => {
                    if wing.ccw_start(wing_side) != enter {
                        issues.push(
                            element,
                            field,
                            format!(
                                "going clockwise around {}, {predecessor} leads to {}, but this edge is entered at {enter}",
                                describe_face(face),
                                wing.ccw_start(wing_side)
                            ),
                        );
                    }
                    let back = wing.successor(wing_side);
                    if back != id {
                        issues.push(
                            element,
                            field,
                            format!(
                                "{predecessor} has {back} as its {} successor, not this edge; the wings must agree",
                                side_name(wing_side)
                            ),
                        );
                    }
                }
            },
        }

        let successor = edge.successor(side);
        let field = Column::successor_of(side);
        match self.edge(successor) {
            None => issues.push(element, field, self.missing(successor, ne, "edges")),
            Some(wing) => match wing.side_left_at(face, leave) {
                None => issues.push(
                    element,
                    field,
                    format!(
                        "{successor} does not border {}, the {name} face of this edge",
                        describe_face(face)
                    ),
                ),
                Some(wing_side) => {
                    if wing.ccw_end(wing_side) != leave {
                        issues.push(
                            element,
                            field,
                            format!(
                                "going clockwise around {}, this edge leads to {leave}, but {successor} starts from {}",
                                describe_face(face),
                                wing.ccw_end(wing_side)
                            ),
                        );
                    }
                    let back = wing.predecessor(wing_side);
                    if back != id {
                        issues.push(
                            element,
                            field,
                            format!(
                                "{successor} has {back} as its {} predecessor, not this edge; the wings must agree",
                                side_name(wing_side)
                            ),
                        );
                    }
                }
            },
        }
    }
}
