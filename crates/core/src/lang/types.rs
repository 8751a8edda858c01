//! The language's types and values. Lookups are table columns
//! ([`crate::schema::Column`]).

use std::fmt;

use crate::schema::{ElementKind, ElementRef};

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
    pub fn element(self) -> Option<ElementRef> {
        match self {
            Value::Vertex(i) => Some(ElementRef::new(ElementKind::Vertex, i)),
            Value::Edge(i) => Some(ElementRef::new(ElementKind::Edge, i)),
            Value::Face(i) => Some(ElementRef::new(ElementKind::Face, i)),
            _ => None,
        }
    }
}

impl From<ElementRef> for Value {
    fn from(element: ElementRef) -> Value {
        match element.kind {
            ElementKind::Vertex => Value::Vertex(element.id),
            ElementKind::Edge => Value::Edge(element.id),
            ElementKind::Face => Value::Face(element.id),
        }
    }
}

impl From<Option<ElementRef>> for Value {
    fn from(element: Option<ElementRef>) -> Value {
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

#[cfg(test)]
mod tests {
    use super::*;

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
