//! The exercises Edgewise ships (algorithms/exercises/), built in so each
//! is one click, one `?exercise=` or one `edgewise practice show` away.

use super::exercise::{Exercise, ExerciseError};

/// A shipped exercise: its name and its file's text.
pub struct Shipped {
    pub name: &'static str,
    pub text: &'static str,
}

macro_rules! shipped {
    ($($name:literal),* $(,)?) => {
        &[$(Shipped {
            name: $name,
            text: include_str!(concat!("../../../../algorithms/exercises/", $name, ".toml")),
        }),*]
    };
}

/// Every shipped exercise, in menu order.
pub const SHIPPED: &[Shipped] = shipped![
    "collapse-edge-half-edge",
    "collapse-edge-winged-edge",
    "flip-edge-half-edge",
    "flip-edge-winged-edge",
    "kef-half-edge",
    "kef-winged-edge",
    "kev-half-edge",
    "kev-winged-edge",
    "mef-half-edge",
    "mef-winged-edge",
    "mev-half-edge",
    "mev-winged-edge",
    "predict-edge-faces-half-edge",
    "predict-face-loop-half-edge",
    "predict-vertex-edges-half-edge",
    "predict-vertex-edges-winged-edge",
    "split-edge-half-edge",
    "split-edge-winged-edge",
    "split-face-half-edge",
    "split-face-winged-edge",
    "walk-boundary-loop-half-edge",
    "walk-face-loop-half-edge",
    "walk-face-loop-winged-edge",
    "walk-face-vertices-by-variable-half-edge",
    "walk-vertex-edges-half-edge",
    "walk-vertex-edges-winged-edge",
    "walk-vertex-neighbours-winged-edge",
];

/// The shipped exercise called `name`, read.
pub fn find(name: &str) -> Option<Result<Exercise, ExerciseError>> {
    SHIPPED
        .iter()
        .find(|shipped| shipped.name == name)
        .map(|shipped| Exercise::parse(shipped.name, shipped.text))
}

/// Every shipped name, for messages that list them.
pub fn names() -> Vec<&'static str> {
    SHIPPED.iter().map(|shipped| shipped.name).collect()
}
