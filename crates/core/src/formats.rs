//! Readers and writers for the four mesh file formats: the project's own
//! table files (`.wtb` for winged-edge, `.htb` for half-edge, see
//! `docs/formats.md`), PLY and OBJ.
//!
//! Everything works on bytes in memory so the browser and the CLI share it;
//! nothing here touches the filesystem.
//!
//! - PLY and OBJ hold polygons: they are built into the structure the caller
//!   asks for through the mesh builder, which refuses non-manifold or
//!   inconsistently oriented input with the offending face's line.
//! - Table files are taken as written and checked with `validate()`; every
//!   violated rule is reported at the line and column of its field.
//! - No reader panics, and none allocates in proportion to a count it has not
//!   seen backed by data: a header's counts are checked against the bytes
//!   that follow before anything is reserved.
//!
//! ```
//! use edgewise_core::formats::{self, Format, SaveOptions};
//! use edgewise_core::mesh::Structure;
//!
//! let obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
//! let loaded = formats::load(obj.as_bytes(), "triangle.obj", Structure::HalfEdge)?;
//! assert_eq!(loaded.format, Format::Obj);
//! assert_eq!(loaded.mesh.face_count(), 1);
//! let wtb = formats::save(&loaded.mesh, Format::Wtb, &SaveOptions::default())?;
//! assert!(String::from_utf8_lossy(&wtb).contains("wtb 1"));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

pub mod compact;
mod error;
mod htb;
mod listing;
mod obj;
mod ply;
mod rows;
mod tables;
mod wtb;

use std::fmt;

pub use error::{FormatError, Location, Problem, SaveError};
pub use listing::listing;
pub use ply::PlyEncoding;

use crate::mesh::{HalfEdgeMesh, Mesh, Polygons, Structure, WingedEdgeMesh};

/// The largest file any reader accepts: 256 MiB, about six million
/// triangles as binary PLY. Larger inputs are refused before parsing, so a
/// browser tab is never asked for gigabytes.
pub const MAX_FILE_BYTES: usize = 256 * 1024 * 1024;

/// A mesh file format.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Format {
    /// Winged-edge tables (`.wtb`).
    Wtb,
    /// Half-edge tables (`.htb`).
    Htb,
    /// Stanford PLY (`.ply`), ASCII or binary.
    Ply,
    /// Wavefront OBJ (`.obj`).
    Obj,
}

impl Format {
    /// Every format, in the order menus list them.
    pub const ALL: [Format; 4] = [Format::Obj, Format::Ply, Format::Wtb, Format::Htb];

    /// The usual file extension, without the dot.
    pub fn extension(self) -> &'static str {
        match self {
            Self::Wtb => "wtb",
            Self::Htb => "htb",
            Self::Ply => "ply",
            Self::Obj => "obj",
        }
    }

    /// A readable name: "winged-edge tables (.wtb)".
    pub fn description(self) -> &'static str {
        match self {
            Self::Wtb => "winged-edge tables (.wtb)",
            Self::Htb => "half-edge tables (.htb)",
            Self::Ply => "PLY (.ply)",
            Self::Obj => "OBJ (.obj)",
        }
    }

    /// The structure a table format stores (`None` for PLY and OBJ, which
    /// store polygons and are built into whichever structure is asked for).
    pub fn native_structure(self) -> Option<Structure> {
        match self {
            Self::Wtb => Some(Structure::WingedEdge),
            Self::Htb => Some(Structure::HalfEdge),
            Self::Ply | Self::Obj => None,
        }
    }

    /// The format named by a file name's extension, or by a bare extension
    /// (`"cube.OBJ"`, `"obj"` and `".obj"` all give OBJ). `None` when the
    /// name has no extension this module knows.
    pub fn from_name(name: &str) -> Option<Self> {
        let extension = name.rsplit_once('.').map_or(name, |(_, ext)| ext);
        Self::ALL
            .into_iter()
            .find(|format| format.extension().eq_ignore_ascii_case(extension))
    }

    /// Guesses the format of text or bytes with no file name (pasted text):
    /// a `wtb 1` or `htb 1` header (after comments) or the `ply` magic word,
    /// otherwise OBJ.
    pub fn sniff(bytes: &[u8]) -> Self {
        if bytes.starts_with(b"ply\n") || bytes.starts_with(b"ply\r\n") {
            return Self::Ply;
        }
        let text = bytes.get(..bytes.len().min(4096)).unwrap_or(bytes);
        for line in text.split(|&b| b == b'\n') {
            let line = line.trim_ascii();
            if line.is_empty() || line.starts_with(b"#") {
                continue;
            }
            let mut words = line
                .split(u8::is_ascii_whitespace)
                .filter(|w| !w.is_empty());
            return match words.next() {
                Some(b"wtb") => Self::Wtb,
                Some(b"htb") => Self::Htb,
                _ => Self::Obj,
            };
        }
        Self::Obj
    }

    /// The format of a file: by the extension of `name` if it has one (or if
    /// `name` is a bare extension such as `"obj"`), by content if `name` is
    /// empty or has no extension. An extension no reader knows is an error
    /// rather than a guess.
    pub fn detect(bytes: &[u8], name: &str) -> Result<Self, FormatError> {
        let base = name.rsplit(['/', '\\']).next().unwrap_or(name);
        match base.rsplit_once('.') {
            None => Ok(Self::from_name(base).unwrap_or_else(|| Self::sniff(bytes))),
            Some((_, extension)) => Self::from_name(extension).ok_or_else(|| {
                FormatError::new(
                    Location::File,
                    format!(
                        "cannot read .{extension} files; Edgewise reads .obj, .ply, .wtb and .htb \
                         (or, with no extension, guesses from the content)"
                    ),
                )
            }),
        }
    }
}

impl fmt::Display for Format {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Self::Wtb => "wtb",
            Self::Htb => "htb",
            Self::Ply => "PLY",
            Self::Obj => "OBJ",
        })
    }
}

/// A file read into a mesh.
#[derive(Clone, Debug, PartialEq)]
pub struct Loaded {
    /// The mesh, in the structure that was asked for.
    pub mesh: Mesh,
    /// The format the file was read as.
    pub format: Format,
    /// The structure the file itself stored when it was converted to give
    /// the requested one (a `.wtb` loaded as half-edge), else `None`.
    pub converted_from: Option<Structure>,
    /// What the reader kept but noticed: unused and split vertices, ignored
    /// OBJ statements, skipped PLY elements.
    pub warnings: Vec<Problem>,
}

/// Reads a mesh file of any format into `structure`.
///
/// `name` is a file name or a bare extension and decides the format (see
/// [`Format::detect`]). PLY and OBJ are built into `structure`; a table file
/// is checked as written and, if it stores the other structure, converted.
///
/// Files above [`MAX_FILE_BYTES`] are refused before reading.
pub fn load(bytes: &[u8], name: &str, structure: Structure) -> Result<Loaded, FormatError> {
    let format = Format::detect(bytes, name)?;
    load_as(bytes, format, structure)
}

/// [`load`] with the format already known.
pub fn load_as(bytes: &[u8], format: Format, structure: Structure) -> Result<Loaded, FormatError> {
    check_size(bytes)?;
    let (polygons, mut warnings) = match format {
        Format::Wtb => {
            return tables_loaded(tables::read::<WingedEdgeMesh>(bytes)?, format, structure);
        }
        Format::Htb => {
            return tables_loaded(tables::read::<HalfEdgeMesh>(bytes)?, format, structure);
        }
        Format::Ply => ply::read(bytes)?,
        Format::Obj => obj::read(bytes)?,
    };
    // OBJ numbers vertices from 1, PLY from 0: messages follow the file.
    let first_vertex = u32::from(format == Format::Obj);
    let (mesh, build_warnings) = Mesh::build(&polygons, structure)
        .map_err(|error| FormatError::from_build(&error, first_vertex))?;
    warnings.extend(build_warnings.iter().map(|warning| {
        // Vertex lines are only looked up here, for the rare warning.
        let line = match format {
            Format::Obj => obj::vertex_line(bytes, warning.vertex().index()),
            _ => None,
        };
        Problem::new(
            line.map_or(Location::File, Location::line),
            warning.to_string(),
        )
    }));
    Ok(Loaded {
        mesh,
        format,
        converted_from: None,
        warnings,
    })
}

/// Reads a mesh file for diagnosis: a `.wtb` or `.htb` file whose tables
/// break the structure's rules is kept as written, in the structure it
/// stores, instead of refused, so that a student can see every broken
/// record and fix it. Rows that cannot be read are still refused. A
/// reference past the end of its table is read as unset and listed in
/// [`Loaded::warnings`] at its field. PLY and OBJ hold polygons, not
/// tables, and load as [`load`] loads them, into `structure`.
pub fn load_for_diagnosis(
    bytes: &[u8],
    name: &str,
    structure: Structure,
) -> Result<Loaded, FormatError> {
    let format = Format::detect(bytes, name)?;
    check_size(bytes)?;
    let (mesh, warnings) = match format {
        Format::Wtb => tables::read_for_diagnosis::<WingedEdgeMesh>(bytes)?,
        Format::Htb => tables::read_for_diagnosis::<HalfEdgeMesh>(bytes)?,
        Format::Ply | Format::Obj => return load_as(bytes, format, structure),
    };
    Ok(Loaded {
        mesh,
        format,
        converted_from: None,
        warnings,
    })
}

fn tables_loaded(mesh: Mesh, format: Format, structure: Structure) -> Result<Loaded, FormatError> {
    if mesh.structure() == structure {
        return Ok(Loaded {
            mesh,
            format,
            converted_from: None,
            warnings: Vec::new(),
        });
    }
    let stored = mesh.structure();
    let converted = mesh
        .convert_to(structure)
        .map_err(|error| FormatError::new(Location::File, error.to_string()))?;
    Ok(Loaded {
        mesh: converted,
        format,
        converted_from: Some(stored),
        warnings: Vec::new(),
    })
}

fn check_size(bytes: &[u8]) -> Result<(), FormatError> {
    if bytes.len() > MAX_FILE_BYTES {
        return Err(FormatError::new(
            Location::File,
            format!(
                "the file is {} bytes; Edgewise reads files of at most {} bytes (256 MiB)",
                bytes.len(),
                MAX_FILE_BYTES
            ),
        ));
    }
    Ok(())
}

/// How to write a file.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct SaveOptions {
    /// The PLY encoding (ignored by the other formats).
    pub ply_encoding: PlyEncoding,
}

/// Writes `mesh` in `format`, converting it first if the format stores the
/// other structure (`.wtb` is winged-edge, `.htb` half-edge). PLY and OBJ
/// store each face counter-clockwise seen from outside, with 0-based PLY and
/// 1-based OBJ vertex numbers. Rows an edit deleted are left out and the
/// ids compacted: files never hold gaps.
pub fn save(mesh: &Mesh, format: Format, options: &SaveOptions) -> Result<Vec<u8>, SaveError> {
    if !crate::mesh::Edit::deleted_rows(mesh).is_empty() {
        let mut compacted = mesh.clone();
        crate::mesh::Edit::compact(&mut compacted);
        return save(&compacted, format, options);
    }
    match format {
        Format::Wtb => match mesh.convert_to(Structure::WingedEdge)? {
            Mesh::Winged(winged) => Ok(tables::write(&winged).into_bytes()),
            Mesh::Half(_) => Err(SaveError::Unsupported(
                "the mesh did not convert to winged-edge".to_owned(),
            )),
        },
        Format::Htb => match mesh.convert_to(Structure::HalfEdge)? {
            Mesh::Half(half) => Ok(tables::write(&half).into_bytes()),
            Mesh::Winged(_) => Err(SaveError::Unsupported(
                "the mesh did not convert to half-edge".to_owned(),
            )),
        },
        Format::Ply | Format::Obj => {
            let polygons = mesh.to_polygons();
            check_polygon_faces(&polygons, format)?;
            let bytes = match format {
                Format::Ply => ply::write(&polygons, options.ply_encoding)?,
                _ => obj::write(&polygons).into_bytes(),
            };
            check_reads_back(mesh, &bytes, format)?;
            Ok(bytes)
        }
    }
}

/// A polygon file lists each face's corners once: a face that passes a
/// vertex twice (along a dangling edge and back, or pinched at a vertex)
/// cannot be written so that it reads back.
fn check_polygon_faces(polygons: &Polygons, format: Format) -> Result<(), SaveError> {
    match polygons.repeated_corner() {
        None => Ok(()),
        Some((face, vertex)) => Err(SaveError::Unsupported(format!(
            "{face} passes {vertex} twice (along a dangling edge and back, or pinched there); \
             {} lists each face's corners once and cannot hold it: save as .wtb or .htb, \
             which keep the tables as they are",
            format.description()
        ))),
    }
}

/// Reads `bytes` back and refuses them unless they give the same counts as
/// `mesh`: a command must never write a file Edgewise cannot read back.
fn check_reads_back(mesh: &Mesh, bytes: &[u8], format: Format) -> Result<(), SaveError> {
    let wrote = mesh.stats();
    let refused = |why: String| {
        SaveError::Unsupported(format!(
            "the mesh cannot be written as {} so that it reads back ({why}): save as .wtb or \
             .htb, which keep the tables as they are",
            format.description()
        ))
    };
    let loaded =
        load_as(bytes, format, mesh.structure()).map_err(|error| refused(error.to_string()))?;
    let read = loaded.mesh.stats();
    if (read.vertices, read.edges, read.faces) != (wrote.vertices, wrote.edges, wrote.faces) {
        return Err(refused(format!(
            "it would read back as {} vertices, {} edges and {} faces instead of {}, {} and {}",
            read.vertices, read.edges, read.faces, wrote.vertices, wrote.edges, wrote.faces
        )));
    }
    Ok(())
}

/// Reads a PLY or OBJ file into a polygon list without building a
/// structure, for tools that want the raw faces (and for benchmarks). Table
/// files are refused: they hold tables, not polygons.
pub fn read_polygons(bytes: &[u8], format: Format) -> Result<Polygons, FormatError> {
    check_size(bytes)?;
    match format {
        Format::Ply => ply::read(bytes).map(|(polygons, _)| polygons),
        Format::Obj => obj::read(bytes).map(|(polygons, _)| polygons),
        Format::Wtb | Format::Htb => Err(FormatError::new(
            Location::File,
            "table files hold tables, not polygons; load them with formats::load",
        )),
    }
}

/// The text of a file as UTF-8, or an error at the line of the first byte
/// that is not.
pub(crate) fn text(bytes: &[u8]) -> Result<&str, FormatError> {
    std::str::from_utf8(bytes).map_err(|error| {
        let valid = bytes.get(..error.valid_up_to()).unwrap_or(&[]);
        let line = 1 + valid.iter().filter(|&&b| b == b'\n').count();
        FormatError::new(
            Location::line(line),
            format!(
                "byte {} is not UTF-8 text; a text file was expected here",
                error.valid_up_to()
            ),
        )
    })
}
