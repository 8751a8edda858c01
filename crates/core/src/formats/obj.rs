//! Wavefront OBJ: `v` and `f` make the mesh; every polygon is kept as it is
//! (no triangulation), all `o` and `g` groups are merged into one mesh, and
//! texture coordinates, normals, materials and smoothing groups are ignored.
//!
//! Our own reader rather than tobj: tobj's errors carry no line number, and a
//! student's hand-edited OBJ needs `cube.obj:12:7: …` to be fixable. It is
//! also faster on the 200k-face benchmark torus (88 ms against 121 ms,
//! `benches/formats.rs`).

use std::fmt::Write as _;

use glam::Vec3;

use super::error::{FormatError, Location, Problem, shown};
use super::rows::is_decimal;
use crate::mesh::Polygons;

/// Statements that carry no surface geometry and are skipped silently.
const IGNORED: [&str; 8] = ["vt", "vn", "vp", "o", "g", "s", "usemtl", "mtllib"];

/// Statements of the OBJ specification (curves, surfaces, display
/// attributes) that a polygon mesh cannot use; each is skipped with one
/// warning.
const UNSUPPORTED: [&str; 27] = [
    "l",
    "p",
    "cstype",
    "deg",
    "bmat",
    "step",
    "curv",
    "curv2",
    "surf",
    "parm",
    "trim",
    "hole",
    "scrv",
    "sp",
    "end",
    "con",
    "mg",
    "lod",
    "maplib",
    "usemap",
    "bevel",
    "c_interp",
    "d_interp",
    "trace_obj",
    "shadow_obj",
    "ctech",
    "stech",
];

/// A forward reference to a vertex defined later, checked at the end.
struct Pending {
    index: u64,
    at: Location,
}

/// The 1-based column of byte `offset` in `line`, counting characters.
fn column(line: &[u8], offset: usize) -> usize {
    1 + line
        .get(..offset)
        .unwrap_or(line)
        .iter()
        .filter(|&&b| b & 0xC0 != 0x80)
        .count()
}

/// Splits a line into words with their byte offsets.
fn words(line: &[u8]) -> impl Iterator<Item = (usize, &[u8])> + '_ {
    let mut offset = 0;
    line.split(u8::is_ascii_whitespace).filter_map(move |word| {
        let start = offset;
        offset += word.len() + 1;
        (!word.is_empty()).then_some((start, word))
    })
}

/// A line without its comment.
fn content(line: &[u8]) -> &[u8] {
    match line.iter().position(|&b| b == b'#') {
        Some(hash) => line.get(..hash).unwrap_or(line),
        None => line,
    }
}

/// Calls `each` with every logical line (joining lines that end in `\`) and
/// its 1-based number.
fn for_each_line(
    bytes: &[u8],
    mut each: impl FnMut(&[u8], usize) -> Result<(), FormatError>,
) -> Result<(), FormatError> {
    let mut joined: Vec<u8> = Vec::new();
    let mut joined_from = 0;
    for (index, raw) in bytes.split(|&b| b == b'\n').enumerate() {
        let line = raw.strip_suffix(b"\r").unwrap_or(raw);
        if let Some(head) = line.strip_suffix(b"\\") {
            if joined.is_empty() {
                joined_from = index + 1;
            }
            joined.extend_from_slice(head);
            joined.push(b' ');
            continue;
        }
        if joined.is_empty() {
            each(line, index + 1)?;
        } else {
            joined.extend_from_slice(line);
            each(&joined, joined_from)?;
            joined.clear();
        }
    }
    if !joined.is_empty() {
        each(&joined, joined_from)?;
    }
    Ok(())
}

pub(super) fn read(bytes: &[u8]) -> Result<(Polygons, Vec<Problem>), FormatError> {
    let mut reader = Reader::default();
    for_each_line(bytes, |line, number| {
        reader.statement(content(line), number)
    })?;
    reader.finish()
}

/// What the statements read so far make; one method per statement.
#[derive(Default)]
struct Reader {
    positions: Vec<Vec3>,
    /// Every face's vertex indices, one after another.
    faces: Vec<u32>,
    /// Where each face starts in `faces`, and its line.
    face_starts: Vec<(usize, usize)>,
    pending: Vec<Pending>,
    /// The unsupported statements warned about, each once.
    warned: Vec<&'static str>,
    warnings: Vec<Problem>,
}

impl Reader {
    /// One logical line, without its comment.
    fn statement(&mut self, line: &[u8], number: usize) -> Result<(), FormatError> {
        let mut words = words(line);
        let Some((_, keyword)) = words.next() else {
            return Ok(());
        };
        let at = |offset: usize| Location::at(number, column(line, offset));
        match keyword {
            b"v" => {
                let position = vertex(words, at, number)?;
                self.positions.push(position);
                Ok(())
            }
            b"f" | b"fo" => {
                self.face_starts.push((self.faces.len(), number));
                for (offset, word) in words {
                    let index = self.corner(word, || at(offset))?;
                    self.faces.push(index);
                }
                Ok(())
            }
            _ => self.other(keyword, number, at(0)),
        }
    }

    /// One corner of an `f` line, `v`, `v/vt`, `v//vn` or `v/vt/vn`: the
    /// 0-based index of its vertex. A vertex defined further down the file
    /// is checked at the end. `at` counts the line's characters up to the
    /// corner, so it is called only for a message: a face of a million
    /// corners would otherwise take a million times a million steps.
    fn corner(&mut self, word: &[u8], at: impl Fn() -> Location) -> Result<u32, FormatError> {
        let bad = || {
            FormatError::new(
                at(),
                format!(
                    "expected a vertex number (v, v/vt, v//vn or v/vt/vn), found \"{}\"",
                    shown(word)
                ),
            )
        };
        let extra_ok = word
            .split(|&b| b == b'/')
            .skip(1)
            .all(|part| part.is_empty() || parse_int(part).is_some());
        if word.split(|&b| b == b'/').count() > 3 || !extra_ok {
            return Err(bad());
        }
        let index_text = word.split(|&b| b == b'/').next().unwrap_or(word);
        let Some(index) = parse_int(index_text) else {
            return Err(bad());
        };
        let count = self.positions.len() as i64;
        let resolved = match index {
            0 => {
                return Err(FormatError::new(
                    at(),
                    "vertex number 0 does not exist: OBJ numbers vertices from 1 \
                     (and counts back from -1)",
                ));
            }
            i if i < 0 && -i > count => {
                return Err(FormatError::new(
                    at(),
                    format!(
                        "vertex number {i} counts back past the first vertex: only \
                         {count} vertices come before this line"
                    ),
                ));
            }
            i if i < 0 => count + i,
            i => {
                if i > count {
                    self.pending.push(Pending {
                        index: i as u64,
                        at: at(),
                    });
                }
                i - 1
            }
        };
        u32::try_from(resolved)
            .map_err(|_| FormatError::new(at(), format!("vertex number {index} is too large")))
    }

    /// Any statement but `v` and `f`: skipped, with one warning per kind
    /// that a polygon mesh cannot use, or refused if OBJ has no such
    /// statement.
    fn other(&mut self, keyword: &[u8], number: usize, at: Location) -> Result<(), FormatError> {
        if IGNORED.iter().any(|k| k.as_bytes() == keyword) {
            return Ok(());
        }
        let Some(&name) = UNSUPPORTED.iter().find(|k| k.as_bytes() == keyword) else {
            return Err(FormatError::new(
                at,
                format!(
                    "unknown statement \"{}\"; expected v, f, vt, vn, o, g, s, usemtl, \
                     mtllib or a # comment",
                    shown(keyword)
                ),
            ));
        };
        if !self.warned.contains(&name) {
            self.warned.push(name);
            self.warnings.push(Problem::new(
                Location::line(number),
                format!("\"{name}\" statements are ignored: only faces (f) make the mesh"),
            ));
        }
        Ok(())
    }

    /// After the last line: refuses references past the last vertex and a
    /// file without faces, and makes the polygons.
    fn finish(self) -> Result<(Polygons, Vec<Problem>), FormatError> {
        let Self {
            positions,
            faces,
            face_starts,
            pending,
            warnings,
            ..
        } = self;
        let count = positions.len() as u64;
        if let Some(bad) = pending.iter().find(|p| p.index > count) {
            return Err(FormatError::new(
                bad.at,
                format!(
                    "vertex number {} does not exist: the file has {count} vertices (1 to {count})",
                    bad.index
                ),
            ));
        }
        if face_starts.is_empty() {
            let vertices = match count {
                0 => "no vertices (v lines)".to_owned(),
                1 => "1 vertex".to_owned(),
                _ => format!("{count} vertices"),
            };
            return Err(FormatError::new(
                Location::File,
                format!(
                    "the file has {vertices} and no faces (f lines); a mesh needs at least one face"
                ),
            ));
        }
        let mut polygons = Polygons::with_capacity(positions.len(), face_starts.len(), faces.len());
        for position in positions {
            polygons.push_vertex(position);
        }
        let ends = face_starts
            .iter()
            .skip(1)
            .map(|&(start, _)| start)
            .chain(std::iter::once(faces.len()));
        for (&(start, line), end) in face_starts.iter().zip(ends) {
            polygons.push_face_from_line(faces.get(start..end).unwrap_or(&[]), line);
        }
        Ok((polygons, warnings))
    }
}

/// The words of a `v` line after the keyword: x, y and z (and an optional
/// w, which is checked and dropped).
fn vertex<'a>(
    words: impl Iterator<Item = (usize, &'a [u8])>,
    at: impl Fn(usize) -> Location,
    number: usize,
) -> Result<Vec3, FormatError> {
    let mut xyz = [0.0f32; 3];
    let mut count = 0;
    for (offset, word) in words {
        let text = std::str::from_utf8(word).unwrap_or("");
        let value = text.parse::<f32>().ok().filter(|v| v.is_finite());
        match value {
            Some(value) if is_decimal(text) => {
                if let Some(slot) = xyz.get_mut(count) {
                    *slot = value;
                }
            }
            _ => {
                let what = ["x", "y", "z"].get(count).copied().unwrap_or("w");
                return Err(FormatError::new(
                    at(offset),
                    format!(
                        "expected a finite number for {what}, found \"{}\"",
                        shown(word)
                    ),
                ));
            }
        }
        count += 1;
    }
    if count < 3 {
        return Err(FormatError::new(
            Location::line(number),
            format!("a vertex needs x, y and z; this one has {count} numbers"),
        ));
    }
    Ok(Vec3::from(xyz))
}

/// A decimal integer with an optional sign.
fn parse_int(word: &[u8]) -> Option<i64> {
    let (negative, digits) = match word.split_first() {
        Some((b'-', rest)) => (true, rest),
        Some((b'+', rest)) => (false, rest),
        _ => (false, word),
    };
    if digits.is_empty() || digits.len() > 18 {
        return None;
    }
    let mut value: i64 = 0;
    for &b in digits {
        if !b.is_ascii_digit() {
            return None;
        }
        value = value * 10 + i64::from(b - b'0');
    }
    Some(if negative { -value } else { value })
}

/// The line of the `index`-th (0-based) `v` statement, for warnings.
pub(super) fn vertex_line(bytes: &[u8], index: usize) -> Option<usize> {
    let mut seen = 0;
    let mut found = None;
    let _ = for_each_line(bytes, |line, number| {
        if found.is_none() && words(content(line)).next().map(|(_, w)| w) == Some(b"v") {
            if seen == index {
                found = Some(number);
            }
            seen += 1;
        }
        Ok(())
    });
    found
}

pub(super) fn write(polygons: &Polygons) -> String {
    let mut out = String::with_capacity(polygons.vertex_count() * 32 + polygons.corner_count() * 8);
    let _ = writeln!(
        out,
        "# Written by Edgewise: {} vertices, {} faces, each counter-clockwise seen from outside",
        polygons.vertex_count(),
        polygons.face_count()
    );
    for p in polygons.positions() {
        let _ = writeln!(out, "v {} {} {}", p.x, p.y, p.z);
    }
    for face in polygons.faces() {
        out.push('f');
        for &v in face {
            let _ = write!(out, " {}", u64::from(v) + 1);
        }
        out.push('\n');
    }
    out
}
