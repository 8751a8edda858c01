//! The built-in functions and a Vector's coordinates: the geometry an
//! edit needs to place a new vertex at a midpoint or a centroid, and the
//! two functions on arrays, and `id`, which turns an element into the
//! number its row has, so an array can hold data per element.

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
    /// `length(a)`: how many items array `a` holds.
    Length,
    /// `append(a, x)`: a statement that adds `x` at the end of array `a`.
    Append,
    /// `id(x)`: the row number of a vertex, edge or face, as an Integer.
    Id,
}

impl Builtin {
    pub const ALL: [Builtin; 6] = [
        Builtin::Vector,
        Builtin::Float,
        Builtin::Sqrt,
        Builtin::Length,
        Builtin::Append,
        Builtin::Id,
    ];
    pub const NAMES: [&'static str; 6] = ["vector", "float", "sqrt", "length", "append", "id"];

    pub fn name(self) -> &'static str {
        match self {
            Builtin::Vector => "vector",
            Builtin::Float => "float",
            Builtin::Sqrt => "sqrt",
            Builtin::Length => "length",
            Builtin::Append => "append",
            Builtin::Id => "id",
        }
    }

    /// Whether it works on an array, which any item type fits: the checker
    /// types these apart, and they compile to array operations.
    pub fn on_arrays(self) -> bool {
        matches!(self, Builtin::Length | Builtin::Append)
    }

    /// Function names ignore case, like keywords.
    pub fn parse(name: &str) -> Option<Builtin> {
        Builtin::ALL
            .into_iter()
            .find(|b| b.name().eq_ignore_ascii_case(name))
    }

    /// The parameters of the functions on numbers; the array functions
    /// (see [`Self::on_arrays`]) list none here.
    pub fn parameters(self) -> &'static [Type] {
        match self {
            Builtin::Vector => &[Type::Float, Type::Float, Type::Float],
            Builtin::Float | Builtin::Sqrt => &[Type::Float],
            Builtin::Length | Builtin::Append | Builtin::Id => &[],
        }
    }

    /// How many arguments it takes.
    pub fn arity(self) -> usize {
        match self {
            Builtin::Length | Builtin::Id => 1,
            Builtin::Append => 2,
            other => other.parameters().len(),
        }
    }

    /// The type of its value; `append` gives none.
    pub fn result(self) -> Option<Type> {
        match self {
            Builtin::Vector => Some(Type::Vector),
            Builtin::Float | Builtin::Sqrt => Some(Type::Float),
            Builtin::Length | Builtin::Id => Some(Type::Integer),
            Builtin::Append => None,
        }
    }

    /// `vector(x : Float, y : Float, z : Float) : Vector`, for messages.
    pub fn signature(self) -> String {
        match self {
            Builtin::Length => return "length(a : Array of …) : Integer".to_owned(),
            Builtin::Append => return "append(a : Array of T; x : T)".to_owned(),
            Builtin::Id => return "id(x : Vertex, Edge or Face) : Integer".to_owned(),
            _ => {}
        }
        let names = ["x", "y", "z"];
        let params: Vec<String> = self
            .parameters()
            .iter()
            .zip(names)
            .map(|(ty, name)| format!("{name} : {ty}"))
            .collect();
        let result = self.result().unwrap_or(Type::Null);
        format!("{}({}) : {result}", self.name(), params.join(", "))
    }

    /// Applies a function on numbers; the checker has made sure the
    /// arguments fit. The array functions run in the VM, on its arrays.
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
            Builtin::Id => match args.first().and_then(|x| x.element()) {
                Some(element) => Value::Integer(i32::try_from(element.id).unwrap_or(i32::MAX)),
                None => return Err("`id` needs a vertex, an edge or a face".to_owned()),
            },
            Builtin::Length | Builtin::Append => {
                return Err(format!("`{}` works on an array", self.name()));
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
