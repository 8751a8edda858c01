//! Linked selection: the selected element and every element it references,
//! each with the role it plays, as in the journal's Figures 4 and 5
//! ("7: Selected Edge", "3: Left Predecessor", "Start Vertex", "Right Face").

use edgewise_core::mesh::{EdgeId, FaceId, HalfEdgeId, Mesh, VertexId};
use serde::Serialize;

/// The three kinds of rows. In a half-edge mesh an "edge" is a half-edge.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum ElementKind {
    Vertex,
    Edge,
    Face,
}

impl ElementKind {
    /// Parses the JavaScript API's kind names.
    pub fn parse(name: &str) -> Option<Self> {
        match name {
            "vertex" => Some(Self::Vertex),
            "edge" | "halfedge" | "half-edge" => Some(Self::Edge),
            "face" => Some(Self::Face),
            _ => None,
        }
    }

    /// "Vertex", "Edge" or "Face", as in role labels.
    pub fn title(self) -> &'static str {
        match self {
            Self::Vertex => "Vertex",
            Self::Edge => "Edge",
            Self::Face => "Face",
        }
    }
}

/// One row of one table.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
pub struct ElementRef {
    pub kind: ElementKind,
    pub id: u32,
}

impl ElementRef {
    pub fn vertex(v: VertexId) -> Self {
        Self {
            kind: ElementKind::Vertex,
            id: v.index() as u32,
        }
    }

    pub fn edge(e: EdgeId) -> Self {
        Self {
            kind: ElementKind::Edge,
            id: e.index() as u32,
        }
    }

    pub fn half_edge(h: HalfEdgeId) -> Self {
        Self {
            kind: ElementKind::Edge,
            id: h.index() as u32,
        }
    }

    pub fn face(f: FaceId) -> Self {
        Self {
            kind: ElementKind::Face,
            id: f.index() as u32,
        }
    }

    /// Whether the row exists in `mesh`.
    pub fn exists_in(self, mesh: &Mesh) -> bool {
        let count = match self.kind {
            ElementKind::Vertex => mesh.vertex_count(),
            ElementKind::Edge => mesh.edge_row_count(),
            ElementKind::Face => mesh.face_count(),
        };
        (self.id as usize) < count
    }
}

/// The part an element plays relative to the selected one. Each role but
/// `Selected` is also the name of the table column that holds the reference.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Role {
    Selected,
    IncidentEdge,
    StartVertex,
    EndVertex,
    LeftFace,
    RightFace,
    LeftPredecessor,
    LeftSuccessor,
    RightPredecessor,
    RightSuccessor,
    /// A half-edge's adjacent face.
    Face,
    PairEdge,
    SuccessorEdge,
    /// Derived from the successor cycle; shown dimmed in the table.
    PredecessorEdge,
}

impl Role {
    pub const ALL: [Role; 14] = [
        Role::Selected,
        Role::IncidentEdge,
        Role::StartVertex,
        Role::EndVertex,
        Role::LeftFace,
        Role::RightFace,
        Role::LeftPredecessor,
        Role::LeftSuccessor,
        Role::RightPredecessor,
        Role::RightSuccessor,
        Role::Face,
        Role::PairEdge,
        Role::SuccessorEdge,
        Role::PredecessorEdge,
    ];

    /// The role's name in settings and links: 'selected', 'leftPredecessor'.
    pub fn setting_key(self) -> String {
        let mut words = self.words_title().split(' ');
        let mut key = words.next().unwrap_or_default().to_lowercase();
        key.extend(words);
        key
    }

    /// Parses [`Self::setting_key`].
    pub fn from_setting_key(key: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|role| role.setting_key() == key)
    }

    /// The label shown in the 3D view after the element's id.
    pub fn title(self, selected_kind: ElementKind) -> String {
        match self {
            Self::Selected => format!("Selected {}", selected_kind.title()),
            other => other.words_title().to_owned(),
        }
    }

    fn words_title(self) -> &'static str {
        match self {
            Self::Selected => "Selected",
            Self::IncidentEdge => "Incident Edge",
            Self::StartVertex => "Start Vertex",
            Self::EndVertex => "End Vertex",
            Self::LeftFace => "Left Face",
            Self::RightFace => "Right Face",
            Self::LeftPredecessor => "Left Predecessor",
            Self::LeftSuccessor => "Left Successor",
            Self::RightPredecessor => "Right Predecessor",
            Self::RightSuccessor => "Right Successor",
            Self::Face => "Face",
            Self::PairEdge => "Pair Edge",
            Self::SuccessorEdge => "Successor Edge",
            Self::PredecessorEdge => "Predecessor Edge",
        }
    }

    /// The role's name in `window.edgewise.state()`: 'selected', 'left predecessor'.
    pub fn key(self) -> String {
        self.words_title().to_lowercase()
    }

    /// Whether the reference is derived rather than stored in the record:
    /// a half-edge stores neither its start vertex nor its predecessor.
    pub fn is_derived(self, half_edge: bool) -> bool {
        half_edge && matches!(self, Self::StartVertex | Self::PredecessorEdge)
    }
}

/// An element to highlight, and why.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Highlight {
    pub element: ElementRef,
    pub role: Role,
}

/// The selected element followed by every element its record references, in
/// the order of the table's columns. Missing (boundary) faces are skipped.
pub fn highlights(mesh: &Mesh, selected: ElementRef) -> Vec<Highlight> {
    if !selected.exists_in(mesh) {
        return Vec::new();
    }
    let mut out = vec![Highlight {
        element: selected,
        role: Role::Selected,
    }];
    let mut push = |element: Option<ElementRef>, role: Role| {
        if let Some(element) = element {
            out.push(Highlight { element, role });
        }
    };
    let index = selected.id as usize;
    match (mesh, selected.kind) {
        (Mesh::Winged(m), ElementKind::Vertex) => {
            let incident = m.vertices().get(index).and_then(|v| v.incident_edge);
            push(incident.map(ElementRef::edge), Role::IncidentEdge);
        }
        (Mesh::Winged(m), ElementKind::Face) => {
            let incident = m.faces().get(index).map(|f| f.incident_edge);
            push(incident.map(ElementRef::edge), Role::IncidentEdge);
        }
        (Mesh::Winged(m), ElementKind::Edge) => {
            if let Some(e) = m.edges().get(index) {
                push(Some(ElementRef::vertex(e.start_vertex)), Role::StartVertex);
                push(Some(ElementRef::vertex(e.end_vertex)), Role::EndVertex);
                push(e.left_face.map(ElementRef::face), Role::LeftFace);
                push(e.right_face.map(ElementRef::face), Role::RightFace);
                push(
                    Some(ElementRef::edge(e.left_predecessor)),
                    Role::LeftPredecessor,
                );
                push(
                    Some(ElementRef::edge(e.left_successor)),
                    Role::LeftSuccessor,
                );
                push(
                    Some(ElementRef::edge(e.right_predecessor)),
                    Role::RightPredecessor,
                );
                push(
                    Some(ElementRef::edge(e.right_successor)),
                    Role::RightSuccessor,
                );
            }
        }
        (Mesh::Half(m), ElementKind::Vertex) => {
            let incident = m.vertices().get(index).and_then(|v| v.incident_edge);
            push(incident.map(ElementRef::half_edge), Role::IncidentEdge);
        }
        (Mesh::Half(m), ElementKind::Face) => {
            let incident = m.faces().get(index).map(|f| f.incident_edge);
            push(incident.map(ElementRef::half_edge), Role::IncidentEdge);
        }
        (Mesh::Half(m), ElementKind::Edge) => {
            if let Some(h) = m.half_edges().get(index) {
                let id = HalfEdgeId::new(selected.id);
                push(Some(ElementRef::vertex(h.end_vertex)), Role::EndVertex);
                push(h.face.map(ElementRef::face), Role::Face);
                push(Some(ElementRef::half_edge(h.pair_edge)), Role::PairEdge);
                push(
                    Some(ElementRef::half_edge(h.successor_edge)),
                    Role::SuccessorEdge,
                );
                push(
                    m.start_vertex(id).map(ElementRef::vertex),
                    Role::StartVertex,
                );
                push(
                    m.predecessor_edge(id).map(ElementRef::half_edge),
                    Role::PredecessorEdge,
                );
            }
        }
    }
    out
}

/// The label of `element` in the 3D view: its id and every role it plays,
/// e.g. "7: Selected Edge" or "3: Left Predecessor, Right Successor".
pub fn role_label(highlights: &[Highlight], element: ElementRef) -> Option<String> {
    role_titles(highlights, element).map(|titles| format!("{}: {titles}", element.id))
}

/// Every role `element` plays, e.g. "Left Predecessor, Right Successor".
pub fn role_titles(highlights: &[Highlight], element: ElementRef) -> Option<String> {
    let selected_kind = highlights.first()?.element.kind;
    let roles: Vec<String> = highlights
        .iter()
        .filter(|h| h.element == element)
        .map(|h| h.role.title(selected_kind))
        .collect();
    (!roles.is_empty()).then(|| roles.join(", "))
}

#[cfg(test)]
mod tests {
    use edgewise_core::mesh::{Polygons, Structure};
    use glam::Vec3;

    use super::*;

    /// The journal's tetrahedron (Table 2): A, B, C, D and CCW faces
    /// 1 = ABD, 2 = BCD, 3 = ACD, 4 = ABC as seen from outside.
    fn tetrahedron(structure: Structure) -> Mesh {
        let positions = vec![
            Vec3::new(0.0, 0.0, 1.0),
            Vec3::new(1.0, 0.0, -0.5),
            Vec3::new(-1.0, 0.0, -0.5),
            Vec3::new(0.0, 1.2, 0.0),
        ];
        let faces: [[u32; 3]; 4] = [[0, 1, 3], [1, 2, 3], [2, 0, 3], [0, 2, 1]];
        let polygons = Polygons::from_faces(positions, faces);
        Mesh::build(&polygons, structure)
            .expect("valid tetrahedron")
            .0
    }

    #[test]
    fn a_winged_edge_highlights_its_nine_pieces() {
        let mesh = tetrahedron(Structure::WingedEdge);
        let Mesh::Winged(m) = &mesh else {
            unreachable!()
        };
        let e = m.edges()[0];
        let hl = highlights(&mesh, ElementRef::edge(EdgeId::new(0)));
        let roles: Vec<Role> = hl.iter().map(|h| h.role).collect();
        assert_eq!(
            roles,
            [
                Role::Selected,
                Role::StartVertex,
                Role::EndVertex,
                Role::LeftFace,
                Role::RightFace,
                Role::LeftPredecessor,
                Role::LeftSuccessor,
                Role::RightPredecessor,
                Role::RightSuccessor,
            ]
        );
        assert_eq!(hl[1].element, ElementRef::vertex(e.start_vertex));
        assert_eq!(hl[5].element, ElementRef::edge(e.left_predecessor));
        assert_eq!(
            role_label(&hl, ElementRef::edge(EdgeId::new(0))).as_deref(),
            Some("0: Selected Edge")
        );
        let pred = ElementRef::edge(e.left_predecessor);
        let label = role_label(&hl, pred).expect("predecessor is labelled");
        assert!(label.starts_with(&format!("{}: ", pred.id)));
        assert!(label.contains("Left Predecessor"), "{label}");
    }

    #[test]
    fn a_half_edge_highlights_stored_and_derived_references() {
        let mesh = tetrahedron(Structure::HalfEdge);
        let Mesh::Half(m) = &mesh else { unreachable!() };
        let h = m.half_edges()[4];
        let hl = highlights(&mesh, ElementRef::half_edge(HalfEdgeId::new(4)));
        let keys: Vec<String> = hl.iter().map(|h| h.role.key()).collect();
        assert_eq!(
            keys,
            [
                "selected",
                "end vertex",
                "face",
                "pair edge",
                "successor edge",
                "start vertex",
                "predecessor edge"
            ]
        );
        assert_eq!(hl[3].element, ElementRef::half_edge(h.pair_edge));
        assert!(Role::PredecessorEdge.is_derived(true));
        assert!(!Role::StartVertex.is_derived(false));
    }

    #[test]
    fn vertices_and_faces_show_their_incident_edge() {
        for structure in [Structure::WingedEdge, Structure::HalfEdge] {
            let mesh = tetrahedron(structure);
            for selected in [
                ElementRef::vertex(VertexId::new(2)),
                ElementRef::face(FaceId::new(3)),
            ] {
                let hl = highlights(&mesh, selected);
                assert_eq!(hl.len(), 2, "{structure:?} {selected:?}");
                assert_eq!(hl[1].role, Role::IncidentEdge);
                assert_eq!(hl[1].element.kind, ElementKind::Edge);
            }
        }
    }

    #[test]
    fn roles_have_camel_case_setting_keys() {
        assert_eq!(Role::LeftPredecessor.setting_key(), "leftPredecessor");
        assert_eq!(Role::Selected.setting_key(), "selected");
        for role in Role::ALL {
            assert_eq!(Role::from_setting_key(&role.setting_key()), Some(role));
        }
    }

    #[test]
    fn a_missing_element_highlights_nothing() {
        let mesh = tetrahedron(Structure::WingedEdge);
        let missing = ElementRef {
            kind: ElementKind::Face,
            id: 99,
        };
        assert!(highlights(&mesh, missing).is_empty());
    }
}
