//! The formats the Save as… menu and `exportMesh` offer: each mesh format,
//! PLY twice (text and binary).

use edgewise_core::formats::{Format, PlyEncoding, SaveOptions};

/// A format the Save as… menu and `exportMesh` offer.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SaveFormat {
    Wtb,
    Htb,
    PlyText,
    PlyBinary,
    Obj,
}

impl SaveFormat {
    pub const ALL: [Self; 5] = [
        Self::Wtb,
        Self::Htb,
        Self::PlyText,
        Self::PlyBinary,
        Self::Obj,
    ];

    /// The menu entry.
    pub fn label(self) -> &'static str {
        match self {
            Self::Wtb => "Winged-edge table (.wtb)",
            Self::Htb => "Half-edge table (.htb)",
            Self::PlyText => "PLY, text (.ply)",
            Self::PlyBinary => "PLY, binary (.ply)",
            Self::Obj => "Wavefront OBJ (.obj)",
        }
    }

    /// The JavaScript API's name: `'wtb'`, `'htb'`, `'ply'`, `'ply-binary'`, `'obj'`.
    pub fn key(self) -> &'static str {
        match self {
            Self::Wtb => "wtb",
            Self::Htb => "htb",
            Self::PlyText => "ply",
            Self::PlyBinary => "ply-binary",
            Self::Obj => "obj",
        }
    }

    /// Parses [`Self::key`].
    pub fn parse(key: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|f| f.key() == key)
    }

    pub fn format(self) -> Format {
        match self {
            Self::Wtb => Format::Wtb,
            Self::Htb => Format::Htb,
            Self::PlyText | Self::PlyBinary => Format::Ply,
            Self::Obj => Format::Obj,
        }
    }

    /// Whether the output is bytes rather than text.
    pub fn is_binary(self) -> bool {
        self == Self::PlyBinary
    }

    pub fn options(self) -> SaveOptions {
        SaveOptions {
            ply_encoding: if self.is_binary() {
                PlyEncoding::BinaryLittleEndian
            } else {
                PlyEncoding::Ascii
            },
        }
    }
}
