//! What the 3D view and the tables colour, label and point at. A selection
//! and a trace step each produce one [`Paint`]; both views draw from it, so
//! they can never disagree.

use edgewise_core::schema::{ElementKind, ElementRef};
use std::collections::HashMap;

use ecolor::Color32;

use crate::{
    selection::{self, Highlight, Role},
    theme::Theme,
    trace_role::TraceRole,
};
use edgewise_core::mesh::{Change, Issue, Mesh};
use edgewise_pictures::styles::{Pointer, SceneStyles};

/// The most records marked at once as broken, deleted or changed: a runaway
/// edit can make hundreds of thousands, and every marked one is outlined,
/// labelled and looked up while drawing. The panel says how many there are.
pub const MOST_MARKED: usize = 1_000;

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
    /// The names of the variables that refer to each element ("e, se"):
    /// a screen reader hears "variable e" where the view shows a colour.
    pub variable_names: HashMap<ElementRef, String>,
    /// Whether everything not painted fades into the background.
    pub fade_others: bool,
    /// The old value of each cell the current step wrote, shown struck
    /// through before the new one.
    pub struck: HashMap<(ElementRef, Role), String>,
    /// The rules each broken record breaks, one line each.
    pub broken: HashMap<ElementRef, Vec<String>>,
    /// The selected element, or the current operation's first: its row in
    /// the tables is shown selected.
    pub focus: Option<ElementRef>,
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
        paint.focus = Some(selected.element);
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

    /// Marks every record that breaks a rule: red in both views, its
    /// offending cell tinted, and the rule kept for the tables' tooltip.
    /// They rank below the current step's colours but above the rest.
    pub fn add_broken(&mut self, issues: &[Issue], theme: &Theme) {
        let colour = theme.trace_colour(TraceRole::Broken);
        let mut marked = Vec::new();
        for issue in issues {
            let element = ElementRef::from(issue.element);
            if self.broken.len() >= MOST_MARKED && !self.broken.contains_key(&element) {
                break;
            }
            self.cells
                .insert((element, Role::Column(issue.field)), colour);
            let rules = self.broken.entry(element).or_default();
            if rules.is_empty() {
                marked.push(Painted {
                    element,
                    colour,
                    role: TraceRole::Broken.key().to_owned(),
                });
            }
            rules.push(format!("{}: {}", issue.field.key(), issue.message));
        }
        // After the current operation's entries, which come first.
        let at = self
            .painted
            .iter()
            .position(|p| p.role == TraceRole::Variable.key() || p.role == TraceRole::Output.key())
            .unwrap_or(self.painted.len());
        self.painted.splice(at..at, marked);
        self.fade_others = true;
    }

    /// Greys out deleted rows; they stay in the tables as gaps.
    pub fn add_deleted(&mut self, deleted: impl IntoIterator<Item = ElementRef>, theme: &Theme) {
        let colour = theme.trace_colour(TraceRole::Deleted);
        for element in deleted.into_iter().take(MOST_MARKED) {
            self.painted.push(Painted {
                element,
                colour,
                role: TraceRole::Deleted.key().to_owned(),
            });
            self.labels.insert(element, "deleted".to_owned());
        }
    }

    /// What an applied operation changed, until something else is chosen:
    /// each written cell tinted with its old value struck through, written
    /// rows and new rows in their trace colours.
    pub fn add_changes(&mut self, journal: &[Change], theme: &Theme) {
        let mut seen: std::collections::HashSet<ElementRef> =
            self.painted.iter().map(|p| p.element).collect();
        let mut push = |element: ElementRef, role: TraceRole| {
            if seen.insert(element) {
                self.painted.push(Painted {
                    element,
                    colour: theme.trace_colour(role),
                    role: role.key().to_owned(),
                });
            }
        };
        let mut struck = Vec::new();
        for change in journal.iter().take(MOST_MARKED) {
            match *change {
                Change::Create(element) => push(element, TraceRole::Created),
                Change::Reference {
                    element,
                    column,
                    old,
                    ..
                } => {
                    push(element, TraceRole::Written);
                    let old = old.map_or_else(|| "∅".to_owned(), |e| e.id.to_string());
                    struck.push(((element, Role::Column(column)), old));
                }
                Change::Position { vertex, .. } => push(vertex.into(), TraceRole::Written),
                Change::Delete(_) => {}
            }
        }
        let colour = theme.trace_colour(TraceRole::Written);
        for (cell, old) in struck {
            self.cells.insert(cell, colour);
            // The value before the operation: the first write's old value.
            self.struck.entry(cell).or_insert(old);
        }
        self.fade_others = true;
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

/// Per-element styles for `mesh` from a paint: an entry for each painted or
/// labelled element the mesh has, in time proportional to the paint.
pub fn scene_styles(mesh: &Mesh, paint: &Paint, generation: u64) -> SceneStyles {
    let mut styles = SceneStyles {
        generation,
        fade_others: paint.fade_others && !paint.is_empty(),
        elements: std::collections::BTreeMap::new(),
        pointers: paint
            .pointers
            .iter()
            .map(|&(element, colour)| Pointer {
                target: element,
                colour,
            })
            .collect(),
    };
    let exists = |element: ElementRef| {
        let count = match element.kind {
            ElementKind::Vertex => mesh.vertex_count(),
            ElementKind::Edge => mesh.edge_row_count(),
            ElementKind::Face => mesh.face_count(),
        };
        (element.id as usize) < count
    };
    // An element's first entry gives its colour: paint in reverse.
    for p in paint.painted.iter().rev().filter(|p| exists(p.element)) {
        let style = styles.elements.entry(p.element).or_default();
        style.colour = Some(p.colour);
    }
    for (&element, label) in paint.labels.iter().filter(|(e, _)| exists(**e)) {
        let style = styles.elements.entry(element).or_default();
        style.label = Some(format!("{}: {label}", element.id));
    }
    styles
}
