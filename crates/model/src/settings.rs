//! The user's configuration: theme, the algorithm view's font size and the
//! trace colours. It is kept in the browser's local storage and goes into a
//! shared link only where it differs from the defaults.

use edgewise_pictures::palette::to_hex;
use std::collections::BTreeMap;

use ecolor::Color32;
use serde::{Deserialize, Serialize};

use crate::{selection::Role, theme::Theme, trace_role::TraceRole};

/// The colour key of boundary half-edges, beside the trace and selection
/// roles' keys.
pub const BOUNDARY: &str = "boundary";

/// The algorithm view's default code size, in points.
pub const DEFAULT_CODE_SIZE: f32 = 14.0;
/// The range offered for the code size.
pub const CODE_SIZES: std::ops::RangeInclusive<f32> = 10.0..=32.0;

/// What the user configured.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct Settings {
    pub dark: bool,
    pub code_size: f32,
    /// Trace role key ('lookup', 'marked', …) or selection role key
    /// ('selected', 'leftPredecessor', …) to `#rrggbb`, only for roles the
    /// user changed.
    pub colours: BTreeMap<String, String>,
    /// The first-visit hint shows until it is dismissed.
    pub welcome: bool,
}

impl Default for Settings {
    fn default() -> Self {
        Self {
            dark: false,
            code_size: DEFAULT_CODE_SIZE,
            colours: BTreeMap::new(),
            welcome: true,
        }
    }
}

impl Settings {
    /// Reads stored settings; anything unreadable falls back to defaults,
    /// with a message saying what was ignored.
    pub fn from_json(json: &str) -> (Self, Option<String>) {
        match serde_json::from_str::<Self>(json) {
            Ok(settings) => settings.sanitized(),
            Err(err) => (
                Self::default(),
                Some(format!(
                    "the saved settings could not be read ({err}); the defaults are used"
                )),
            ),
        }
    }

    pub fn to_json(&self) -> String {
        serde_json::to_string(self).unwrap_or_default()
    }

    /// Drops unknown roles and malformed colours, and clamps the code size.
    pub fn sanitized(mut self) -> (Self, Option<String>) {
        let mut ignored = Vec::new();
        self.colours.retain(|role, colour| {
            let known = TraceRole::parse(role).is_some()
                || Role::from_setting_key(role).is_some()
                || role == BOUNDARY;
            let fine = known && parse_hex(colour).is_some();
            if !fine {
                ignored.push(format!("{role}:{colour}"));
            }
            fine
        });
        if !self.code_size.is_finite() {
            self.code_size = DEFAULT_CODE_SIZE;
        }
        self.code_size = self.code_size.clamp(*CODE_SIZES.start(), *CODE_SIZES.end());
        let message = (!ignored.is_empty()).then(|| {
            format!(
                "ignored colours: {} (a colour is a role and six hex digits, such as lookup:22aa44)",
                ignored.join(", ")
            )
        });
        (self, message)
    }

    /// The theme these settings describe.
    pub fn theme(&self) -> Theme {
        Theme {
            dark: self.dark,
            trace_overrides: self
                .colours
                .iter()
                .filter_map(|(role, hex)| Some((TraceRole::parse(role)?, parse_hex(hex)?)))
                .collect(),
            role_overrides: self
                .colours
                .iter()
                .filter_map(|(role, hex)| Some((Role::from_setting_key(role)?, parse_hex(hex)?)))
                .collect(),
            boundary_override: self.colours.get(BOUNDARY).and_then(|hex| parse_hex(hex)),
        }
    }

    /// Sets (or, with the view's own colour, clears) the colour of
    /// boundary half-edges.
    pub fn set_boundary_colour(&mut self, colour: Color32) {
        let default = edgewise_pictures::palette::Palette::new(self.dark).boundary;
        self.set_key_colour(BOUNDARY, colour, default);
    }

    /// Sets (or, with the journal's own colour, clears) a trace role's colour.
    pub fn set_colour(&mut self, role: TraceRole, colour: Color32) {
        let default = Theme {
            dark: self.dark,
            ..Theme::default()
        }
        .journal_trace_colour(role);
        self.set_key_colour(role.key(), colour, default);
    }

    /// Sets (or, with the default, clears) a selection role's colour.
    pub fn set_role_colour(&mut self, role: Role, colour: Color32) {
        let default = Theme {
            dark: self.dark,
            ..Theme::default()
        }
        .default_role_colour(role);
        self.set_key_colour(&role.setting_key(), colour, default);
    }

    fn set_key_colour(&mut self, key: &str, colour: Color32, default: Color32) {
        if colour == default {
            self.colours.remove(key);
        } else {
            self.colours.insert(key.to_owned(), to_hex(colour));
        }
    }

    /// Back to the journal's scheme (Table 3).
    pub fn reset_colours(&mut self) {
        self.colours.clear();
    }
}

/// `#rrggbb` or `rrggbb`.
pub fn parse_hex(text: &str) -> Option<Color32> {
    let hex = text.strip_prefix('#').unwrap_or(text);
    if hex.len() != 6 || !hex.bytes().all(|b| b.is_ascii_hexdigit()) {
        return None;
    }
    let value = u32::from_str_radix(hex, 16).ok()?;
    let [_, r, g, b] = value.to_be_bytes();
    Some(Color32::from_rgb(r, g, b))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn colours_round_trip_and_the_journal_colour_clears_an_override() {
        let mut settings = Settings::default();
        settings.set_colour(TraceRole::Lookup, Color32::from_rgb(0x12, 0x34, 0x56));
        assert_eq!(settings.colours["lookup"], "#123456");
        let theme = settings.theme();
        assert_eq!(
            theme.trace_colour(TraceRole::Lookup),
            Color32::from_rgb(0x12, 0x34, 0x56)
        );
        let (back, message) = Settings::from_json(&settings.to_json());
        assert_eq!(back, settings);
        assert!(message.is_none());
        let journal = Theme::light().journal_trace_colour(TraceRole::Lookup);
        settings.set_colour(TraceRole::Lookup, journal);
        assert!(settings.colours.is_empty());
    }

    #[test]
    fn bad_stored_values_fall_back_with_a_message() {
        let (settings, message) = Settings::from_json(
            r##"{"dark": true, "code_size": 900, "colours": {"lookup": "zz0000", "nope": "#ffffff", "marked": "#0000ff"}}"##,
        );
        assert!(settings.dark);
        assert_eq!(settings.code_size, 32.0);
        assert_eq!(settings.colours.len(), 1);
        let message = message.expect("a message");
        assert!(message.contains("lookup:zz0000"), "{message}");
        assert!(message.contains("nope:#ffffff"), "{message}");
        let (settings, message) = Settings::from_json("not json");
        assert_eq!(settings, Settings::default());
        assert!(message.is_some_and(|m| m.contains("defaults are used")));
    }

    #[test]
    fn hex_colours_parse_strictly() {
        assert_eq!(parse_hex("#ff8000"), Some(Color32::from_rgb(255, 128, 0)));
        assert_eq!(parse_hex("ff8000"), Some(Color32::from_rgb(255, 128, 0)));
        assert_eq!(parse_hex("#ff800"), None);
        assert_eq!(parse_hex("#gg8000"), None);
        assert_eq!(to_hex(Color32::from_rgb(1, 2, 3)), "#010203");
    }
}
