//! The colours things are drawn in: a calm light and dark theme, the
//! journal's trace colours and the colour of each selection role, with the
//! user's own in their place.

use ecolor::Color32;

use crate::{selection::Role, trace_role::TraceRole};

/// The app's visual theme.
#[derive(Clone, Debug, Default, PartialEq, Eq, Hash)]
pub struct Theme {
    pub dark: bool,
    /// The user's own trace colours, replacing the journal's (Table 3).
    pub trace_overrides: Vec<(TraceRole, Color32)>,
    /// The user's own selection role colours.
    pub role_overrides: Vec<(Role, Color32)>,
    /// The user's own colour of boundary half-edges.
    pub boundary_override: Option<Color32>,
}

impl Theme {
    pub fn light() -> Self {
        Self::default()
    }

    pub fn dark() -> Self {
        Self {
            dark: true,
            ..Self::default()
        }
    }

    /// A number that changes whenever anything drawn from the theme does,
    /// for caches of derived colours.
    pub fn key(&self) -> u64 {
        use std::hash::{Hash as _, Hasher as _};
        let mut hasher = std::collections::hash_map::DefaultHasher::new();
        self.hash(&mut hasher);
        hasher.finish()
    }

    /// The colour of a selection role in the 3D view and the tables (each
    /// column's [`edgewise_core::schema::Palette`] unless overridden).
    pub fn role_colour(&self, role: Role) -> Color32 {
        if let Some(&(_, colour)) = self.role_overrides.iter().find(|(r, _)| *r == role) {
            return colour;
        }
        self.default_role_colour(role)
    }

    /// The app's own colour of a selection role in this theme.
    pub fn default_role_colour(&self, role: Role) -> Color32 {
        let (light, dark) = match role {
            Role::Selected => ((0xd9, 0x48, 0x0f), (0xff, 0x87, 0x4d)),
            Role::Column(column) => {
                let palette = column.palette();
                (palette.light.into(), palette.dark.into())
            }
        };
        let (r, g, b) = if self.dark { dark } else { light };
        Color32::from_rgb(r, g, b)
    }

    /// The journal's default trace colours (Table 3): blue output, green
    /// lookup, yellow highlight, purple variables, light blue comparison.
    /// Yellow is deepened to amber on the light theme to stay readable.
    pub fn trace_colour(&self, role: TraceRole) -> Color32 {
        if let Some(&(_, colour)) = self.trace_overrides.iter().find(|(r, _)| *r == role) {
            return colour;
        }
        self.journal_trace_colour(role)
    }

    /// The journal's default colour of a trace role in this theme.
    pub fn journal_trace_colour(&self, role: TraceRole) -> Color32 {
        let (light, dark) = match role {
            TraceRole::Output => ((0x1d, 0x5b, 0xd8), (0x5c, 0x9d, 0xff)),
            TraceRole::Lookup => ((0x23, 0x9b, 0x3c), (0x5f, 0xd8, 0x74)),
            TraceRole::Highlighted => ((0xd4, 0x9a, 0x00), (0xff, 0xd4, 0x3b)),
            TraceRole::Variable => ((0x8a, 0x3f, 0xcf), (0xc4, 0x8e, 0xf5)),
            TraceRole::Compared => ((0x0f, 0xa5, 0xc4), (0x66, 0xd9, 0xef)),
            TraceRole::Written => ((0xe0, 0x6c, 0x00), (0xff, 0x9f, 0x43)),
            TraceRole::Created => ((0x00, 0x8f, 0x7a), (0x3e, 0xe0, 0xc6)),
            TraceRole::Deleted => ((0x8c, 0x8c, 0x8c), (0x6a, 0x6a, 0x6a)),
            TraceRole::Broken => ((0xd0, 0x1f, 0x3c), (0xff, 0x5c, 0x6c)),
        };
        let (r, g, b) = if self.dark { dark } else { light };
        Color32::from_rgb(r, g, b)
    }
}
