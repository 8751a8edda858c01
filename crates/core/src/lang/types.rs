//! The language's types and values. Lookups are table columns
//! ([`crate::schema::Column`]).

use std::fmt;
use std::hash::{Hash, Hasher};

use glam::Vec3;

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
    /// A 32-bit floating-point number.
    Float,
    /// A point or direction in space: three Floats.
    Vector,
    Null,
    /// `Array of Edge`: a list, 0-based, that grows by `append`.
    Array(Item),
}

/// What an array holds: any declarable type but an array, so that `Type`
/// stays a small `Copy` value and no type nests without end.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Item {
    Vertex,
    Edge,
    Face,
    Integer,
    Boolean,
    Float,
    Vector,
}

impl Item {
    pub const ALL: [Item; 7] = [
        Item::Vertex,
        Item::Edge,
        Item::Face,
        Item::Integer,
        Item::Boolean,
        Item::Float,
        Item::Vector,
    ];

    /// The items' type.
    pub fn ty(self) -> Type {
        match self {
            Item::Vertex => Type::Vertex,
            Item::Edge => Type::Edge,
            Item::Face => Type::Face,
            Item::Integer => Type::Integer,
            Item::Boolean => Type::Boolean,
            Item::Float => Type::Float,
            Item::Vector => Type::Vector,
        }
    }

    /// The item kind of `ty`, if an array can hold it.
    pub fn of(ty: Type) -> Option<Item> {
        Item::ALL.into_iter().find(|item| item.ty() == ty)
    }
}

impl Type {
    pub const DECLARABLE: [Type; 7] = [
        Type::Vertex,
        Type::Edge,
        Type::Face,
        Type::Integer,
        Type::Boolean,
        Type::Float,
        Type::Vector,
    ];

    pub fn name(self) -> &'static str {
        match self {
            Type::Vertex => "Vertex",
            Type::Edge => "Edge",
            Type::Face => "Face",
            Type::Integer => "Integer",
            Type::Boolean => "Boolean",
            Type::Float => "Float",
            Type::Vector => "Vector",
            Type::Null => "null",
            Type::Array(item) => match item {
                Item::Vertex => "Array of Vertex",
                Item::Edge => "Array of Edge",
                Item::Face => "Array of Face",
                Item::Integer => "Array of Integer",
                Item::Boolean => "Array of Boolean",
                Item::Float => "Array of Float",
                Item::Vector => "Array of Vector",
            },
        }
    }

    /// The type of an array's items; `None` for other types.
    pub fn item(self) -> Option<Type> {
        match self {
            Type::Array(item) => Some(item.ty()),
            _ => None,
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

    /// Whether Integer and Float arithmetic applies.
    pub fn is_number(self) -> bool {
        matches!(self, Type::Integer | Type::Float)
    }

    /// Whether a value of type `value` may be stored in a variable of this
    /// type. An Integer widens to a Float.
    pub fn accepts(self, value: Type) -> bool {
        self == value
            || (value == Type::Null && self.element_kind().is_some())
            || (self == Type::Float && value == Type::Integer)
    }

    /// The initial value of a variable of this type. An array variable
    /// starts as a new empty array, which only a run can make; this gives
    /// `null` for it.
    pub fn default_value(self) -> Value {
        match self {
            Type::Integer => Value::Integer(0),
            Type::Boolean => Value::Boolean(false),
            Type::Float => Value::Float(0.0),
            Type::Vector => Value::Vector(Vec3::ZERO),
            _ => Value::Null,
        }
    }

    /// Packs a value of this type into 32 bits, for compact trace steps.
    /// A Vector does not fit; traces keep Vectors in a table and store the
    /// index.
    pub fn encode(self, value: Value) -> u32 {
        value.code()
    }

    /// The inverse of [`Type::encode`] for every type but Vector.
    pub fn decode(self, code: u32) -> Value {
        match self {
            Type::Integer => Value::Integer(code.cast_signed()),
            Type::Boolean => Value::Boolean(code != 0),
            Type::Float => Value::Float(f32::from_bits(code)),
            Type::Vector => Value::Vector(Vec3::ZERO),
            Type::Null => Value::Null,
            _ if code == NULL_CODE => Value::Null,
            Type::Array(_) => Value::Array(code),
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

/// A run-time value: 16 bytes, copied freely. Floats compare by their bits
/// here (so values can be map keys); the language's `=` compares numbers.
#[derive(Clone, Copy, Debug)]
pub enum Value {
    Null,
    Vertex(u32),
    Edge(u32),
    Face(u32),
    Integer(i32),
    Boolean(bool),
    Float(f32),
    Vector(Vec3),
    /// An array: its number in the run's list of arrays. Assigning or
    /// passing it shares the array (as in Java or Python); the trace and
    /// [`super::Execution`] show its items.
    Array(u32),
}

impl Value {
    /// The bits that identify a value, for equality and hashing.
    fn identity(self) -> (u8, [u32; 3]) {
        match self {
            Value::Null => (0, [0; 3]),
            Value::Vertex(i) => (1, [i, 0, 0]),
            Value::Edge(i) => (2, [i, 0, 0]),
            Value::Face(i) => (3, [i, 0, 0]),
            Value::Integer(n) => (4, [n.cast_unsigned(), 0, 0]),
            Value::Boolean(b) => (5, [u32::from(b), 0, 0]),
            Value::Float(x) => (6, [x.to_bits(), 0, 0]),
            Value::Vector(v) => (7, [v.x.to_bits(), v.y.to_bits(), v.z.to_bits()]),
            Value::Array(i) => (8, [i, 0, 0]),
        }
    }

    /// A Float, or an Integer widened to one.
    pub fn number(self) -> Option<f32> {
        match self {
            Value::Float(x) => Some(x),
            Value::Integer(n) => Some(n as f32),
            _ => None,
        }
    }
}

impl PartialEq for Value {
    /// The same as comparing identities, matched directly: the VM compares
    /// values at every loop test, and building two identities costs more
    /// than the lookup being tested.
    #[inline]
    fn eq(&self, other: &Self) -> bool {
        match (*self, *other) {
            (Value::Null, Value::Null) => true,
            (Value::Vertex(a), Value::Vertex(b))
            | (Value::Edge(a), Value::Edge(b))
            | (Value::Face(a), Value::Face(b))
            | (Value::Array(a), Value::Array(b)) => a == b,
            (Value::Integer(a), Value::Integer(b)) => a == b,
            (Value::Boolean(a), Value::Boolean(b)) => a == b,
            (Value::Float(a), Value::Float(b)) => a.to_bits() == b.to_bits(),
            (Value::Vector(_), Value::Vector(_)) => self.identity() == other.identity(),
            _ => false,
        }
    }
}

impl Eq for Value {}

impl Hash for Value {
    fn hash<H: Hasher>(&self, state: &mut H) {
        self.identity().hash(state);
    }
}

impl Value {
    /// The 32-bit code of a trace step; the register's static type tells
    /// how to read it back ([`Type::decode`]).
    #[inline]
    pub fn code(self) -> u32 {
        match self {
            Value::Null => NULL_CODE,
            Value::Vertex(i) | Value::Edge(i) | Value::Face(i) | Value::Array(i) => i,
            Value::Integer(n) => n.cast_unsigned(),
            Value::Boolean(b) => u32::from(b),
            Value::Float(x) => x.to_bits(),
            Value::Vector(_) => 0,
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
            Value::Float(x) => write_float(f, *x),
            Value::Vector(v) => {
                f.write_str("(")?;
                write_float(f, v.x)?;
                f.write_str(", ")?;
                write_float(f, v.y)?;
                f.write_str(", ")?;
                write_float(f, v.z)?;
                f.write_str(")")
            }
            Value::Array(i) => write!(f, "array {i}"),
            _ => match self.element() {
                Some(element) => element.fmt(f),
                None => Ok(()),
            },
        }
    }
}

/// Array items beyond this many are summed up, so that a message or a
/// trace line about a long array stays readable.
pub const SHOWN_ITEMS: usize = 12;

/// An array's items as messages and traces show them: `[edge 1, edge 4]`,
/// a long one cut to its first [`SHOWN_ITEMS`] and its length.
pub fn show_items(items: &[Value]) -> String {
    let shown: Vec<String> = items
        .iter()
        .take(SHOWN_ITEMS)
        .map(ToString::to_string)
        .collect();
    if items.len() > SHOWN_ITEMS {
        format!("[{}, … {} items in all]", shown.join(", "), items.len())
    } else {
        format!("[{}]", shown.join(", "))
    }
}

/// A Float as a reader expects it: `0.5`, `2.0`, `-1.25`; always with a
/// point so it is not mistaken for an Integer.
fn write_float(f: &mut fmt::Formatter<'_>, x: f32) -> fmt::Result {
    if x.is_finite() && x == x.trunc() && x.abs() < 1e9 {
        write!(f, "{x:.1}")
    } else {
        write!(f, "{x}")
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
            (Type::Float, Value::Float(-0.25)),
            (Type::Null, Value::Null),
        ] {
            assert_eq!(ty.decode(ty.encode(value)), value);
        }
    }

    #[test]
    fn equality_is_identity() {
        let values = [
            Value::Null,
            Value::Vertex(1),
            Value::Edge(1),
            Value::Face(1),
            Value::Array(1),
            Value::Integer(1),
            Value::Boolean(true),
            Value::Float(1.0),
            Value::Float(-0.0),
            Value::Float(0.0),
            Value::Vector(Vec3::ONE),
            Value::Vector(Vec3::ZERO),
        ];
        for a in values {
            for b in values {
                assert_eq!(a == b, a.identity() == b.identity(), "{a:?} {b:?}");
            }
        }
        let array = Type::Array(Item::Edge);
        assert_eq!(array.decode(array.encode(Value::Array(7))), Value::Array(7));
        assert_eq!(array.name(), "Array of Edge");
        assert_eq!(Item::of(Type::Null), None);
    }

    #[test]
    fn floats_and_vectors_show_a_point() {
        assert_eq!(Value::Float(2.0).to_string(), "2.0");
        assert_eq!(Value::Float(-0.125).to_string(), "-0.125");
        assert_eq!(
            Value::Vector(Vec3::new(0.5, 1.0, -2.0)).to_string(),
            "(0.5, 1.0, -2.0)"
        );
    }
}
