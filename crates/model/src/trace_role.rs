//! What a trace step's colours mean, kept apart from the algorithm views so
//! that the theme can colour them without depending on those views.

/// The journal's colour meanings (Table 3); the base colour is the view's
/// own gray.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum TraceRole {
    /// Blue: marked, the algorithm's output.
    Output,
    /// Green: the base and the result of the current lookup.
    Lookup,
    /// Yellow: highlighted by the algorithm.
    Highlighted,
    /// Purple: the value of some variable.
    Variable,
    /// Light blue: a side of the current comparison.
    Compared,
    /// Orange: the record (and the reference) the current step writes.
    Written,
    /// Teal: the element the current step creates.
    Created,
    /// Gray: a deleted row, kept as a gap until the ids are compacted.
    Deleted,
    /// Red: a record that breaks one of the structure's rules.
    Broken,
}

impl TraceRole {
    pub const ALL: [TraceRole; 9] = [
        TraceRole::Output,
        TraceRole::Lookup,
        TraceRole::Highlighted,
        TraceRole::Variable,
        TraceRole::Compared,
        TraceRole::Written,
        TraceRole::Created,
        TraceRole::Deleted,
        TraceRole::Broken,
    ];

    /// The name in `state().highlights` and in the colour settings.
    pub fn key(self) -> &'static str {
        match self {
            TraceRole::Output => "marked",
            TraceRole::Lookup => "lookup",
            TraceRole::Highlighted => "highlighted",
            TraceRole::Variable => "variable",
            TraceRole::Compared => "compared",
            TraceRole::Written => "written",
            TraceRole::Created => "created",
            TraceRole::Deleted => "deleted",
            TraceRole::Broken => "broken",
        }
    }

    /// Parses [`Self::key`].
    pub fn parse(key: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|role| role.key() == key)
    }

    /// The role's mark in labels, a cue besides colour (for readers who
    /// cannot tell the colours apart, and for print in gray); a variable's
    /// cue is its name.
    pub fn glyph(self) -> Option<&'static str> {
        match self {
            TraceRole::Output => Some("✓"),
            TraceRole::Lookup => Some("→"),
            TraceRole::Highlighted => Some("★"),
            TraceRole::Variable => None,
            TraceRole::Compared => Some("?"),
            TraceRole::Written => Some("✎"),
            TraceRole::Created => Some("+"),
            TraceRole::Deleted => Some("×"),
            TraceRole::Broken => Some("!"),
        }
    }

    /// The legend's wording.
    pub fn meaning(self) -> &'static str {
        match self {
            TraceRole::Output => "algorithm output (marked)",
            TraceRole::Lookup => "in a lookup",
            TraceRole::Highlighted => "highlighted",
            TraceRole::Variable => "a variable refers to it",
            TraceRole::Compared => "in a comparison",
            TraceRole::Written => "a record written (old value struck through)",
            TraceRole::Created => "just created",
            TraceRole::Deleted => "deleted (a gap until compacted)",
            TraceRole::Broken => "breaks a rule of the structure",
        }
    }
}
