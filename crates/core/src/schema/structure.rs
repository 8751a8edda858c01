//! The two structures and the names each goes by.

use std::fmt;

/// Which data structure stores a mesh, or which one an algorithm walks.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Structure {
    /// Winged-edge (edge, vertex and face tables; `.wtb` files).
    WingedEdge,
    /// Half-edge (half-edge, vertex and face tables; `.htb` files).
    HalfEdge,
}

impl Structure {
    /// Both structures, winged-edge first as in the papers.
    pub const ALL: [Structure; 2] = [Structure::WingedEdge, Structure::HalfEdge];

    /// The name in the language (`structuretype WingedEdge`).
    pub fn name(self) -> &'static str {
        match self {
            Structure::WingedEdge => "WingedEdge",
            Structure::HalfEdge => "HalfEdge",
        }
    }

    /// Lower-case prose name, as in "a winged-edge lookup".
    pub fn prose(self) -> &'static str {
        match self {
            Structure::WingedEdge => "winged-edge",
            Structure::HalfEdge => "half-edge",
        }
    }

    /// The short name in course links and the JavaScript API.
    pub fn link_name(self) -> &'static str {
        match self {
            Structure::WingedEdge => "winged",
            Structure::HalfEdge => "half",
        }
    }

    /// The extension of the structure's table files.
    pub fn table_extension(self) -> &'static str {
        match self {
            Structure::WingedEdge => "wtb",
            Structure::HalfEdge => "htb",
        }
    }

    /// Parses the language's name, ignoring case.
    pub fn parse(word: &str) -> Option<Structure> {
        Self::ALL
            .into_iter()
            .find(|s| s.name().eq_ignore_ascii_case(word))
    }

    /// Parses a link's or the JavaScript API's name: the short name, the
    /// prose name or the table extension.
    pub fn parse_link_name(word: &str) -> Option<Structure> {
        Self::ALL
            .into_iter()
            .find(|s| [s.link_name(), s.prose(), s.table_extension()].contains(&word))
    }

    /// The other structure.
    pub fn other(self) -> Structure {
        match self {
            Structure::WingedEdge => Structure::HalfEdge,
            Structure::HalfEdge => Structure::WingedEdge,
        }
    }
}

impl fmt::Display for Structure {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}
