//! The language's types and values, and the lookups each structure offers.

use std::fmt;

/// Which data structure an algorithm walks.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Structure {
    WingedEdge,
    HalfEdge,
}

impl Structure {
    pub fn name(self) -> &'static str {
        match self {
            Structure::WingedEdge => "WingedEdge",
            Structure::HalfEdge => "HalfEdge",
        }
    }

    /// Lower-case prose name, as in "a winged-edge lookup".
    pub fn prose(self) -> &'static str {
        match self {
            Structure::WingedEdge => "winged-edge",
            Structure::HalfEdge => "half-edge",
        }
    }

    pub fn parse(word: &str) -> Option<Structure> {
        [Structure::WingedEdge, Structure::HalfEdge]
            .into_iter()
            .find(|s| s.name().eq_ignore_ascii_case(word))
    }
}

impl fmt::Display for Structure {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// The three kinds of mesh element.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum ElementKind {
    Vertex,
    Edge,
    Face,
}

impl ElementKind {
    /// "vertices", "edges", "faces".
    pub fn plural(self) -> &'static str {
        match self {
            ElementKind::Vertex => "vertices",
            ElementKind::Edge => "edges",
            ElementKind::Face => "faces",
        }
    }

    /// Lower-case, as elements are shown in traces: "vertex 3".
    pub fn prose(self) -> &'static str {
        match self {
            ElementKind::Vertex => "vertex",
            ElementKind::Edge => "edge",
            ElementKind::Face => "face",
        }
    }
}

/// One mesh element: its kind and its number in that kind's table. In a
/// half-edge structure an Edge is a half-edge.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Element {
    Vertex(u32),
    Edge(u32),
    Face(u32),
}

impl Element {
    pub fn kind(self) -> ElementKind {
        match self {
            Element::Vertex(_) => ElementKind::Vertex,
            Element::Edge(_) => ElementKind::Edge,
            Element::Face(_) => ElementKind::Face,
        }
    }

    pub fn index(self) -> u32 {
        match self {
            Element::Vertex(i) | Element::Edge(i) | Element::Face(i) => i,
        }
    }

    pub fn new(kind: ElementKind, index: u32) -> Element {
        match kind {
            ElementKind::Vertex => Element::Vertex(index),
            ElementKind::Edge => Element::Edge(index),
            ElementKind::Face => Element::Face(index),
        }
    }
}

impl fmt::Display for Element {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} {}", self.kind().prose(), self.index())
    }
}

/// A static type. `Null` is the type of the literal `null` only; every
/// element type also admits the null value (a missing face at a boundary).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Type {
    Vertex,
    Edge,
    Face,
    Integer,
    Boolean,
    Null,
}

impl Type {
    pub const DECLARABLE: [Type; 5] = [
        Type::Vertex,
        Type::Edge,
        Type::Face,
        Type::Integer,
        Type::Boolean,
    ];

    pub fn name(self) -> &'static str {
        match self {
            Type::Vertex => "Vertex",
            Type::Edge => "Edge",
            Type::Face => "Face",
            Type::Integer => "Integer",
            Type::Boolean => "Boolean",
            Type::Null => "null",
        }
    }

    pub fn parse(word: &str) -> Option<Type> {
        Type::DECLARABLE
            .into_iter()
            .find(|t| t.name().eq_ignore_ascii_case(word))
    }

    pub fn element_kind(self) -> Option<ElementKind> {
        match self {
            Type::Vertex => Some(ElementKind::Vertex),
            Type::Edge => Some(ElementKind::Edge),
            Type::Face => Some(ElementKind::Face),
            _ => None,
        }
    }

    pub fn of_kind(kind: ElementKind) -> Type {
        match kind {
            ElementKind::Vertex => Type::Vertex,
            ElementKind::Edge => Type::Edge,
            ElementKind::Face => Type::Face,
        }
    }

    /// Whether a value of type `value` may be stored in a variable of this type.
    pub fn accepts(self, value: Type) -> bool {
        self == value || (value == Type::Null && self.element_kind().is_some())
    }

    /// The initial value of a variable of this type.
    pub fn default_value(self) -> Value {
        match self {
            Type::Integer => Value::Integer(0),
            Type::Boolean => Value::Boolean(false),
            _ => Value::Null,
        }
    }

    /// Packs a value of this type into 32 bits, for compact trace steps.
    pub fn encode(self, value: Value) -> u32 {
        value.code()
    }

    /// The inverse of [`Type::encode`].
    pub fn decode(self, code: u32) -> Value {
        match self {
            Type::Integer => Value::Integer(code.cast_signed()),
            Type::Boolean => Value::Boolean(code != 0),
            Type::Null => Value::Null,
            _ if code == NULL_CODE => Value::Null,
            Type::Vertex => Value::Vertex(code),
            Type::Edge => Value::Edge(code),
            Type::Face => Value::Face(code),
        }
    }
}

/// Element numbers are below `u32::MAX`, which stands for null.
const NULL_CODE: u32 = u32::MAX;

impl fmt::Display for Type {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// A run-time value: 8 bytes, copied freely.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Value {
    Null,
    Vertex(u32),
    Edge(u32),
    Face(u32),
    Integer(i32),
    Boolean(bool),
}

impl Value {
    /// The 32-bit code of a trace step; the register's static type tells
    /// how to read it back ([`Type::decode`]).
    #[inline]
    pub fn code(self) -> u32 {
        match self {
            Value::Null => NULL_CODE,
            Value::Vertex(i) | Value::Edge(i) | Value::Face(i) => i,
            Value::Integer(n) => n.cast_unsigned(),
            Value::Boolean(b) => u32::from(b),
        }
    }

    #[inline]
    pub fn element(self) -> Option<Element> {
        match self {
            Value::Vertex(i) => Some(Element::Vertex(i)),
            Value::Edge(i) => Some(Element::Edge(i)),
            Value::Face(i) => Some(Element::Face(i)),
            _ => None,
        }
    }
}

impl From<Element> for Value {
    fn from(element: Element) -> Value {
        match element {
            Element::Vertex(i) => Value::Vertex(i),
            Element::Edge(i) => Value::Edge(i),
            Element::Face(i) => Value::Face(i),
        }
    }
}

impl From<Option<Element>> for Value {
    fn from(element: Option<Element>) -> Value {
        element.map_or(Value::Null, Value::from)
    }
}

impl fmt::Display for Value {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Value::Null => f.write_str("null"),
            Value::Integer(n) => write!(f, "{n}"),
            Value::Boolean(b) => write!(f, "{b}"),
            _ => match self.element() {
                Some(element) => element.fmt(f),
                None => Ok(()),
            },
        }
    }
}

/// A lookup: one reference stored in (or derived from) a table entry.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Field {
    /// Vertex and face tables, both structures.
    IncidentEdge,
    StartVertex,
    EndVertex,
    // Winged-edge edge table.
    LeftFace,
    RightFace,
    LeftPredecessor,
    LeftSuccessor,
    RightPredecessor,
    RightSuccessor,
    // Half-edge table.
    AdjacentFace,
    PairEdge,
    SuccessorEdge,
    PredecessorEdge,
}

/// Every spelling of every lookup: (name, field, structure it exists in, or
/// `None` for both).
const FIELD_NAMES: &[(&str, Field, Option<Structure>)] = &[
    ("incidentEdge", Field::IncidentEdge, None),
    ("startVertex", Field::StartVertex, None),
    ("endVertex", Field::EndVertex, None),
    ("leftFace", Field::LeftFace, Some(Structure::WingedEdge)),
    ("rightFace", Field::RightFace, Some(Structure::WingedEdge)),
    (
        "leftPredecessor",
        Field::LeftPredecessor,
        Some(Structure::WingedEdge),
    ),
    (
        "leftSuccessor",
        Field::LeftSuccessor,
        Some(Structure::WingedEdge),
    ),
    (
        "rightPredecessor",
        Field::RightPredecessor,
        Some(Structure::WingedEdge),
    ),
    (
        "rightSuccessor",
        Field::RightSuccessor,
        Some(Structure::WingedEdge),
    ),
    (
        "adjacentFace",
        Field::AdjacentFace,
        Some(Structure::HalfEdge),
    ),
    ("face", Field::AdjacentFace, Some(Structure::HalfEdge)),
    ("vertex", Field::EndVertex, Some(Structure::HalfEdge)),
    ("pairEdge", Field::PairEdge, Some(Structure::HalfEdge)),
    ("pair", Field::PairEdge, Some(Structure::HalfEdge)),
    ("twin", Field::PairEdge, Some(Structure::HalfEdge)),
    (
        "successorEdge",
        Field::SuccessorEdge,
        Some(Structure::HalfEdge),
    ),
    ("successor", Field::SuccessorEdge, Some(Structure::HalfEdge)),
    ("next", Field::SuccessorEdge, Some(Structure::HalfEdge)),
    (
        "predecessorEdge",
        Field::PredecessorEdge,
        Some(Structure::HalfEdge),
    ),
    (
        "predecessor",
        Field::PredecessorEdge,
        Some(Structure::HalfEdge),
    ),
    ("prev", Field::PredecessorEdge, Some(Structure::HalfEdge)),
];

/// Why a lookup name was refused, for the checker's message.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum FieldError {
    /// No structure has a lookup of this name.
    Unknown,
    /// The other structure has it.
    OtherStructure(Structure),
    /// The structure has it, on another kind of element.
    WrongElement(ElementKind),
}

impl Field {
    /// The canonical name, as the tables' column headings spell it.
    pub fn name(self) -> &'static str {
        FIELD_NAMES
            .iter()
            .find(|&&(_, f, _)| f == self)
            .map_or("?", |&(name, _, _)| name)
    }

    /// The element kind a lookup applies to.
    pub fn base(self) -> ElementKind {
        match self {
            Field::IncidentEdge => ElementKind::Vertex,
            _ => ElementKind::Edge,
        }
    }

    /// The kind of element a lookup yields.
    pub fn result(self) -> ElementKind {
        match self {
            Field::StartVertex | Field::EndVertex => ElementKind::Vertex,
            Field::LeftFace | Field::RightFace | Field::AdjacentFace => ElementKind::Face,
            _ => ElementKind::Edge,
        }
    }

    /// Whether this lookup applies to elements of `kind`.
    pub fn applies_to(self, kind: ElementKind) -> bool {
        match self {
            Field::IncidentEdge => kind != ElementKind::Edge,
            _ => kind == ElementKind::Edge,
        }
    }

    /// Whether the lookup can yield null in a valid mesh: a missing face at a
    /// boundary, or the incident edge of an isolated vertex.
    pub fn may_be_null(self) -> bool {
        matches!(
            self,
            Field::LeftFace | Field::RightFace | Field::AdjacentFace | Field::IncidentEdge
        )
    }

    /// Resolves a lookup name (any case, any alias) on an element of `kind` in
    /// `structure`.
    pub fn resolve(
        structure: Structure,
        kind: ElementKind,
        name: &str,
    ) -> Result<Field, FieldError> {
        let mut found_elsewhere = None;
        let mut known = false;
        for &(candidate, field, only_in) in FIELD_NAMES {
            if !candidate.eq_ignore_ascii_case(name) {
                continue;
            }
            known = true;
            match only_in {
                Some(other) if other != structure => {
                    found_elsewhere = Some(FieldError::OtherStructure(other));
                }
                _ if !field.applies_to(kind) => {
                    found_elsewhere = Some(FieldError::WrongElement(field.base()));
                }
                _ => return Ok(field),
            }
        }
        if known {
            Err(found_elsewhere.unwrap_or(FieldError::Unknown))
        } else {
            Err(FieldError::Unknown)
        }
    }

    /// The lookup names (aliases included) valid on `kind` in `structure`.
    pub fn names_for(
        structure: Structure,
        kind: ElementKind,
    ) -> impl Iterator<Item = &'static str> {
        FIELD_NAMES
            .iter()
            .filter(move |&&(_, field, only_in)| {
                only_in.is_none_or(|s| s == structure) && field.applies_to(kind)
            })
            .map(|&(name, _, _)| name)
    }

    /// Every lookup name of either structure.
    pub fn all_names() -> impl Iterator<Item = &'static str> {
        FIELD_NAMES.iter().map(|&(name, _, _)| name)
    }
}

impl fmt::Display for Field {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lookups_resolve_by_structure_and_element() {
        use ElementKind as K;
        use Structure::{HalfEdge, WingedEdge};
        assert_eq!(
            Field::resolve(HalfEdge, K::Edge, "TWIN"),
            Ok(Field::PairEdge)
        );
        assert_eq!(
            Field::resolve(WingedEdge, K::Face, "incidentEdge"),
            Ok(Field::IncidentEdge)
        );
        assert_eq!(
            Field::resolve(HalfEdge, K::Edge, "leftFace"),
            Err(FieldError::OtherStructure(WingedEdge))
        );
        assert_eq!(
            Field::resolve(WingedEdge, K::Vertex, "startVertex"),
            Err(FieldError::WrongElement(K::Edge))
        );
        assert_eq!(
            Field::resolve(WingedEdge, K::Edge, "sideways"),
            Err(FieldError::Unknown)
        );
    }

    #[test]
    fn values_round_trip_through_their_encoding() {
        for (ty, value) in [
            (Type::Edge, Value::Edge(7)),
            (Type::Face, Value::Null),
            (Type::Integer, Value::Integer(-3)),
            (Type::Boolean, Value::Boolean(true)),
            (Type::Null, Value::Null),
        ] {
            assert_eq!(ty.decode(ty.encode(value)), value);
        }
    }
}
