//! The built-in functions and a Vector's coordinates: the geometry an
//! edit needs to place a new vertex at a midpoint or a centroid.

use super::types::{Type, Value};
use glam::Vec3;

/// A built-in function.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Builtin {
    /// `vector(x, y, z)`.
    Vector,
    /// `float(n)`: a number as a Float.
    Float,
    /// `sqrt(x)`.
    Sqrt,
}

impl Builtin {
    pub const ALL: [Builtin; 3] = [Builtin::Vector, Builtin::Float, Builtin::Sqrt];
    pub const NAMES: [&'static str; 3] = ["vector", "float", "sqrt"];

    pub fn name(self) -> &'static str {
        match self {
            Builtin::Vector => "vector",
            Builtin::Float => "float",
            Builtin::Sqrt => "sqrt",
        }
    }

    /// Function names ignore case, like keywords.
    pub fn parse(name: &str) -> Option<Builtin> {
        Builtin::ALL
            .into_iter()
            .find(|b| b.name().eq_ignore_ascii_case(name))
    }

    pub fn parameters(self) -> &'static [Type] {
        match self {
            Builtin::Vector => &[Type::Float, Type::Float, Type::Float],
            Builtin::Float | Builtin::Sqrt => &[Type::Float],
        }
    }

    pub fn result(self) -> Type {
        match self {
            Builtin::Vector => Type::Vector,
            Builtin::Float | Builtin::Sqrt => Type::Float,
        }
    }

    /// `vector(x : Float, y : Float, z : Float) : Vector`, for messages.
    pub fn signature(self) -> String {
        let names = ["x", "y", "z"];
        let params: Vec<String> = self
            .parameters()
            .iter()
            .zip(names)
            .map(|(ty, name)| format!("{name} : {ty}"))
            .collect();
        format!("{}({}) : {}", self.name(), params.join(", "), self.result())
    }

    /// Applies the function; the checker has made sure the arguments fit.
    pub fn apply(self, args: &[Value]) -> Result<Value, String> {
        let number = |i: usize| args.get(i).and_then(|v| v.number()).unwrap_or(0.0);
        Ok(match self {
            Builtin::Vector => Value::Vector(Vec3::new(number(0), number(1), number(2))),
            Builtin::Float => Value::Float(number(0)),
            Builtin::Sqrt => {
                let x = number(0);
                if x < 0.0 {
                    return Err(format!("sqrt of a negative number ({x})"));
                }
                Value::Float(x.sqrt())
            }
        })
    }
}

/// One coordinate of a Vector: `p.x`, `p.y`, `p.z`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Axis {
    X,
    Y,
    Z,
}

impl Axis {
    pub fn parse(name: &str) -> Option<Axis> {
        match name.to_ascii_lowercase().as_str() {
            "x" => Some(Axis::X),
            "y" => Some(Axis::Y),
            "z" => Some(Axis::Z),
            _ => None,
        }
    }

    pub fn name(self) -> &'static str {
        match self {
            Axis::X => "x",
            Axis::Y => "y",
            Axis::Z => "z",
        }
    }

    pub fn of(self, v: Vec3) -> f32 {
        match self {
            Axis::X => v.x,
            Axis::Y => v.y,
            Axis::Z => v.z,
        }
    }
}
