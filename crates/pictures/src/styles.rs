//! How each element looks: the few elements that have a colour or a label
//! of their own, whether the rest fade, and the comparison pointers.

use std::borrow::Cow;
use std::collections::BTreeMap;

use ecolor::Color32;
use edgewise_core::schema::ElementRef;

/// Per-element look: the few elements that have a look of their own, and
/// whether every other element is faded. Sparse, so that a selection or a
/// trace step costs what it changes rather than what the mesh holds: the
/// view patches the styles of the elements whose entries changed.
/// `generation` increases on every change so the view looks only then.
#[derive(Clone, Debug, Default)]
pub struct SceneStyles {
    pub generation: u64,
    /// Every element without an entry is drawn faded (a selection or a
    /// trace with "fade the rest" on).
    pub fade_others: bool,
    pub elements: BTreeMap<ElementRef, ElementStyle>,
    pub pointers: Vec<Pointer>,
}

impl SceneStyles {
    /// The look of `element`: its own entry, or the base look.
    pub fn get(&self, element: ElementRef) -> Cow<'_, ElementStyle> {
        match self.elements.get(&element) {
            Some(style) => Cow::Borrowed(style),
            None => Cow::Owned(self.base()),
        }
    }

    /// The look of an element without an entry.
    pub fn base(&self) -> ElementStyle {
        ElementStyle {
            faded: self.fade_others,
            ..ElementStyle::default()
        }
    }

    /// The element's label, if it has one.
    pub fn label(&self, element: ElementRef) -> Option<&str> {
        self.elements.get(&element)?.label.as_deref()
    }

    /// Whether the element is drawn with neither a colour nor a label.
    pub fn is_plain(&self, element: ElementRef) -> bool {
        self.elements
            .get(&element)
            .is_none_or(|style| !is_highlighted(style))
    }
}

/// How one element looks.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ElementStyle {
    /// None = base colour.
    pub colour: Option<Color32>,
    pub faded: bool,
    /// E.g. "3: Left Predecessor"; None = just the id.
    pub label: Option<String>,
}

/// A comparison arrow pointing at an element (the journal draws one per
/// side; the same element twice gets two).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pointer {
    pub target: ElementRef,
    pub colour: Color32,
}

/// Whether an element gets a label in the Highlighted mode: it is coloured
/// or carries a label.
pub fn is_highlighted(style: &ElementStyle) -> bool {
    style.colour.is_some() || style.label.is_some()
}
