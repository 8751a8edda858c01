//! Linked selection: the selected element and every element it references,
//! each with the role it plays, as in the journal's Figures 4 and 5
//! ("7: Selected Edge", "3: Left Predecessor", "Start Vertex", "Right Face").

use edgewise_core::mesh::Mesh;
use edgewise_core::schema::{Column, ElementKind, ElementRef, Records, Storage};

/// The part an element plays relative to the selected one: the selection
/// itself, or the column of the selected record that refers to it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Role {
    Selected,
    Column(Column),
}

impl Role {
    /// Every role: the selection, then each reference column in table order.
    pub fn all() -> impl Iterator<Item = Role> {
        std::iter::once(Role::Selected).chain(
            Column::ALL
                .into_iter()
                .filter(|column| column.target().is_some())
                .map(Role::Column),
        )
    }

    /// The role's name in settings and links: 'selected', 'leftPredecessor'.
    pub fn setting_key(self) -> String {
        match self {
            Self::Selected => "selected".to_owned(),
            Self::Column(column) => column.setting_key(),
        }
    }

    /// Parses [`Self::setting_key`].
    pub fn from_setting_key(key: &str) -> Option<Self> {
        Self::all().find(|role| role.setting_key() == key)
    }

    /// The label shown in the 3D view after the element's id.
    pub fn title(self, selected_kind: ElementKind) -> String {
        match self {
            Self::Selected => format!("Selected {}", selected_kind.title()),
            Self::Column(column) => column.title().to_owned(),
        }
    }

    /// The role's name in `window.edgewise.state()`: 'selected', 'left predecessor'.
    pub fn key(self) -> String {
        match self {
            Self::Selected => "selected".to_owned(),
            Self::Column(column) => column.key(),
        }
    }

    /// Whether the reference is derived rather than stored in the record:
    /// a half-edge stores neither its start vertex nor its predecessor.
    pub fn is_derived(self, structure: edgewise_core::mesh::Structure) -> bool {
        matches!(self, Self::Column(column) if column.storage(structure) == Some(Storage::Derived))
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
    if !mesh.contains(selected) {
        return Vec::new();
    }
    let mut out = vec![Highlight {
        element: selected,
        role: Role::Selected,
    }];
    for entry in Column::table(mesh.structure(), selected.kind) {
        if let Ok(Some(element)) = mesh.reference(selected, entry.column) {
            out.push(Highlight {
                element,
                role: Role::Column(entry.column),
            });
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

/// Reads `vertex 3`, `v3`, `edge 5`, `e 5`, `half-edge 5`, `h5`, `face 1`
/// or `f1` (any case).
pub fn parse_element(text: &str) -> Result<ElementRef, String> {
    let text = text.trim().to_ascii_lowercase();
    let split = text
        .find(|c: char| c.is_ascii_digit())
        .unwrap_or(text.len());
    let (word, number) = text.split_at(split);
    let kind = match word.trim() {
        "v" | "vertex" => Some(ElementKind::Vertex),
        "e" | "h" | "edge" | "half-edge" | "halfedge" => Some(ElementKind::Edge),
        "f" | "face" => Some(ElementKind::Face),
        _ => None,
    };
    let id = number.trim().parse::<u32>().ok();
    match (kind, id) {
        (Some(kind), Some(id)) => Ok(ElementRef::new(kind, id)),
        _ => Err(format!(
            "`{}`: type an element as vertex, edge or face and its id, such as e 3 or vertex 1",
            text.chars().take(40).collect::<String>()
        )),
    }
}

#[cfg(test)]
mod tests {
    use edgewise_core::mesh::{EdgeId, FaceId, HalfEdgeId, Structure, VertexId, generate};

    use super::*;

    /// The journal's tetrahedron (Table 2).
    fn tetrahedron(structure: Structure) -> Mesh {
        Mesh::build(&generate::tetrahedron(), structure)
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
                Role::Column(Column::StartVertex),
                Role::Column(Column::EndVertex),
                Role::Column(Column::LeftFace),
                Role::Column(Column::RightFace),
                Role::Column(Column::LeftPredecessor),
                Role::Column(Column::LeftSuccessor),
                Role::Column(Column::RightPredecessor),
                Role::Column(Column::RightSuccessor),
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
        assert!(Role::Column(Column::PredecessorEdge).is_derived(Structure::HalfEdge));
        assert!(!Role::Column(Column::StartVertex).is_derived(Structure::WingedEdge));
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
                assert_eq!(hl[1].role, Role::Column(Column::IncidentEdge));
                assert_eq!(hl[1].element.kind, ElementKind::Edge);
            }
        }
    }

    #[test]
    fn roles_have_camel_case_setting_keys() {
        assert_eq!(
            Role::Column(Column::LeftPredecessor).setting_key(),
            "leftPredecessor"
        );
        assert_eq!(Role::Selected.setting_key(), "selected");
        for role in Role::all() {
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

    #[test]
    fn elements_are_read_in_long_and_short_forms() {
        let cases = [
            ("vertex 3", ElementRef::new(ElementKind::Vertex, 3)),
            ("v3", ElementRef::new(ElementKind::Vertex, 3)),
            (" E 12 ", ElementRef::new(ElementKind::Edge, 12)),
            ("half-edge 5", ElementRef::new(ElementKind::Edge, 5)),
            ("h5", ElementRef::new(ElementKind::Edge, 5)),
            ("face1", ElementRef::new(ElementKind::Face, 1)),
        ];
        for (text, element) in cases {
            assert_eq!(parse_element(text), Ok(element), "{text}");
        }
        for text in ["3", "edge", "x 3", "edge -1", "edge 99999999999"] {
            assert!(parse_element(text).is_err(), "{text}");
        }
        assert_eq!(
            parse_element("q 1"),
            Err("`q 1`: type an element as vertex, edge or face and its id, such as e 3 or vertex 1".to_owned())
        );
    }
}
