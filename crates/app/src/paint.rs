//! What the 3D view and the tables colour, label and point at. A selection
//! and a trace step each produce one [`Paint`]; both views draw from it, so
//! they can never disagree.

use edgewise_core::schema::{ElementKind, ElementRef};
use std::collections::HashMap;

use egui::Color32;

use crate::{
    selection::{self, Highlight, Role},
    theme::Theme,
};

/// One coloured element and why, for the views and `state().highlights`.
#[derive(Clone, Debug, PartialEq)]
pub struct Painted {
    pub element: ElementRef,
    pub colour: Color32,
    /// The role's name in `state().highlights`: 'selected', 'lookup'.
    pub role: String,
}

/// Colours, labels, tinted cells and pointers for one moment.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Paint {
    /// In priority order: an element's first entry gives its colour.
    pub painted: Vec<Painted>,
    /// Label text shown after the element's id ("Left Predecessor", "e, se")
    /// in the 3D view and in the table's labels column.
    pub labels: HashMap<ElementRef, String>,
    /// Reference cells to tint: the row and the column (named by its role).
    pub cells: HashMap<(ElementRef, Role), Color32>,
    /// Arrows pointing at elements (comparisons).
    pub pointers: Vec<(ElementRef, Color32)>,
    /// Whether everything not painted fades into the background.
    pub fade_others: bool,
}

impl Paint {
    /// The linked-selection paint: the selected element and each element it
    /// references in its role's colour, with role labels, and the selected
    /// row's reference cells tinted.
    pub fn from_selection(highlights: &[Highlight], theme: &Theme) -> Self {
        let mut paint = Self {
            fade_others: !highlights.is_empty(),
            ..Self::default()
        };
        let Some(selected) = highlights.first() else {
            return paint;
        };
        for h in highlights {
            let colour = theme.role_colour(h.role);
            paint.painted.push(Painted {
                element: h.element,
                colour,
                role: h.role.key(),
            });
            if h.role != Role::Selected {
                paint.cells.insert((selected.element, h.role), colour);
            }
            paint.labels.entry(h.element).or_insert_with(|| {
                selection::role_titles(highlights, h.element).unwrap_or_default()
            });
        }
        paint
    }

    /// The colour of `element`, if it is painted.
    pub fn colour_of(&self, element: ElementRef) -> Option<Color32> {
        self.painted
            .iter()
            .find(|p| p.element == element)
            .map(|p| p.colour)
    }

    /// The element of `kind` to bring into view in its table: the first
    /// painted one (the selected element, or the current operation's).
    pub fn focus(&self, kind: ElementKind) -> Option<u32> {
        self.painted
            .iter()
            .find(|p| p.element.kind == kind)
            .map(|p| p.element.id)
    }

    /// Whether anything is painted.
    pub fn is_empty(&self) -> bool {
        self.painted.is_empty() && self.labels.is_empty() && self.pointers.is_empty()
    }
}
