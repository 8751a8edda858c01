//! Compact polygons: a lossless binary form of a polygon list, small enough
//! for a course link (the app deflates it and writes it in base64url as
//! `#poly=`). The app uses it only when building from these polygons gives
//! back the mesh's tables exactly, so every id survives.
//!
//! Layout, all integers LEB128 varints:
//!
//! - the magic bytes `EWP1`, the vertex count, the face count;
//! - the positions as little-endian `f32`, stored in twelve byte planes
//!   (every vertex's byte 0 of x, then byte 1 of x, …, byte 3 of z), which
//!   deflate compresses far better than interleaved floats;
//! - per face: its corner count, then each corner as the zigzag-coded
//!   difference from the corner before it (across faces), so neighbouring
//!   ids cost a byte.
//!
//! Decoding trusts nothing: each count is checked against the bytes left
//! before anything is reserved, and each index against the vertex count.

use std::fmt;

use glam::Vec3;

use crate::mesh::Polygons;

/// The first four bytes.
pub const MAGIC: &[u8; 4] = b"EWP1";

/// Why bytes are not compact polygons: the byte offset and what was wrong.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CompactError {
    pub at: usize,
    pub problem: String,
}

impl fmt::Display for CompactError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "byte {}: {}", self.at, self.problem)
    }
}

impl std::error::Error for CompactError {}

/// The compact form of `polygons`.
///
/// ```
/// use edgewise_core::{formats::compact, mesh::generate};
/// let cube = generate::cube();
/// let bytes = compact::encode(&cube);
/// assert_eq!(compact::decode(&bytes)?, cube);
/// # Ok::<(), compact::CompactError>(())
/// ```
pub fn encode(polygons: &Polygons) -> Vec<u8> {
    let positions = polygons.positions();
    let mut out = Vec::with_capacity(16 + positions.len() * 12 + polygons.face_count() * 5);
    out.extend_from_slice(MAGIC);
    write_varint(&mut out, positions.len() as u64);
    write_varint(&mut out, polygons.face_count() as u64);
    for component in 0..3 {
        for byte in 0..4 {
            out.extend(
                positions
                    .iter()
                    .map(|p| p.to_array()[component].to_le_bytes()[byte]),
            );
        }
    }
    let mut previous = 0_i64;
    for face in polygons.faces() {
        write_varint(&mut out, face.len() as u64);
        for &corner in face {
            let delta = i64::from(corner) - previous;
            write_varint(&mut out, zigzag(delta));
            previous = i64::from(corner);
        }
    }
    out
}

/// Reads [`encode`]'s output back, refusing anything else with the place.
pub fn decode(bytes: &[u8]) -> Result<Polygons, CompactError> {
    let mut reader = Reader { bytes, at: 0 };
    if bytes.get(..4) != Some(MAGIC.as_slice()) {
        return Err(reader.error("not compact polygons (they start with EWP1)"));
    }
    reader.at = 4;
    let vertices = reader.count("the vertex count", 12)?;
    let faces = reader.count("the face count", 4)?;
    if reader.left() < vertices * 12 {
        return Err(reader.error(format!(
            "{vertices} vertices need {} of positions, and {} are left",
            byte_count(vertices * 12),
            byte_count(reader.left())
        )));
    }
    let planes = &bytes[reader.at..reader.at + vertices * 12];
    reader.at += vertices * 12;
    let mut polygons = Polygons::with_capacity(vertices, faces, faces * 3);
    for v in 0..vertices {
        let component = |c: usize| {
            let byte = |b: usize| planes[(c * 4 + b) * vertices + v];
            f32::from_le_bytes([byte(0), byte(1), byte(2), byte(3)])
        };
        polygons.push_vertex(Vec3::new(component(0), component(1), component(2)));
    }
    let mut previous = 0_i64;
    let mut corners = Vec::new();
    for face in 0..faces {
        let start = reader.at;
        let count = reader.count("a face's corner count", 1)?;
        corners.clear();
        for _ in 0..count {
            let at = reader.at;
            let delta = unzigzag(reader.varint("a corner")?);
            let corner = previous
                .checked_add(delta)
                .filter(|c| (0..vertices as i64).contains(c));
            let Some(corner) = corner else {
                return Err(CompactError {
                    at,
                    problem: format!("face {face} has a corner outside the {vertices} vertices"),
                });
            };
            previous = corner;
            corners.push(corner as u32);
        }
        if count < 3 {
            return Err(CompactError {
                at: start,
                problem: format!("face {face} has {count} corners; a face needs at least 3"),
            });
        }
        polygons.push_face(&corners);
    }
    if reader.left() > 0 {
        return Err(reader.error(format!(
            "{} more after the last face",
            byte_count(reader.left())
        )));
    }
    Ok(polygons)
}

struct Reader<'a> {
    bytes: &'a [u8],
    at: usize,
}

impl Reader<'_> {
    fn left(&self) -> usize {
        self.bytes.len() - self.at
    }

    fn error(&self, problem: impl Into<String>) -> CompactError {
        CompactError {
            at: self.at,
            problem: problem.into(),
        }
    }

    fn varint(&mut self, what: &str) -> Result<u64, CompactError> {
        let start = self.at;
        let mut value = 0_u64;
        for shift in (0..64).step_by(7) {
            let Some(&byte) = self.bytes.get(self.at) else {
                return Err(CompactError {
                    at: start,
                    problem: format!("the data ends inside {what}"),
                });
            };
            self.at += 1;
            value |= u64::from(byte & 0x7f) << shift;
            if byte & 0x80 == 0 {
                return Ok(value);
            }
        }
        Err(CompactError {
            at: start,
            problem: format!("{what} is longer than 64 bits"),
        })
    }

    /// A count each of whose items takes at least `bytes_each` of what is
    /// left: larger ones cannot be true, and are refused before any
    /// allocation.
    fn count(&mut self, what: &str, bytes_each: usize) -> Result<usize, CompactError> {
        let start = self.at;
        let value = self.varint(what)?;
        let most = self.left() / bytes_each;
        usize::try_from(value)
            .ok()
            .filter(|&n| n <= most)
            .ok_or_else(|| CompactError {
                at: start,
                problem: format!(
                    "{what} {value} is more than the {} left can hold",
                    byte_count(self.left())
                ),
            })
    }
}

/// "1 byte", "6 bytes".
fn byte_count(n: usize) -> String {
    if n == 1 {
        "1 byte".to_owned()
    } else {
        format!("{n} bytes")
    }
}

fn write_varint(out: &mut Vec<u8>, mut value: u64) {
    while value >= 0x80 {
        out.push((value as u8) | 0x80);
        value >>= 7;
    }
    out.push(value as u8);
}

fn zigzag(value: i64) -> u64 {
    ((value << 1) ^ (value >> 63)) as u64
}

fn unzigzag(value: u64) -> i64 {
    ((value >> 1) as i64) ^ -((value & 1) as i64)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::generate;

    #[test]
    fn polygons_come_back_to_the_bit() {
        for polygons in [
            generate::cube(),
            generate::torus(12, 8),
            generate::icosphere(2),
            generate::grid(3, 2),
            Polygons::new(),
        ] {
            let back = decode(&encode(&polygons)).expect("decodes");
            assert_eq!(back, polygons);
        }
        // Every float, even a NaN's payload and a negative zero.
        let mut odd = Polygons::new();
        for x in [
            f32::from_bits(0x7fc0_1234),
            -0.0,
            f32::MIN_POSITIVE,
            f32::MAX,
        ] {
            odd.push_vertex(Vec3::new(x, -x, 1.0));
        }
        odd.push_face(&[0, 3, 1, 2]);
        let back = decode(&encode(&odd)).expect("decodes");
        let bits = |p: &Polygons| -> Vec<u32> {
            p.positions()
                .iter()
                .flat_map(|v| v.to_array().map(f32::to_bits))
                .collect()
        };
        assert_eq!(bits(&back), bits(&odd));
    }

    #[test]
    fn bad_bytes_are_refused_with_the_place() {
        let good = encode(&generate::cube());
        let refusal = |bytes: &[u8]| decode(bytes).expect_err("refused").to_string();
        assert_eq!(
            refusal(b"EWP2"),
            "byte 0: not compact polygons (they start with EWP1)"
        );
        // A vertex count that the bytes cannot back is refused at once.
        assert_eq!(
            refusal(b"EWP1\xff\xff\xff\xff\x0f\x00"),
            "byte 4: the vertex count 4294967295 is more than the 1 byte left can hold"
        );
        // Cut short: the last face's count promises more than is left.
        let cut = &good[..good.len() - 1];
        assert_eq!(
            refusal(cut),
            format!(
                "byte {}: a face's corner count 4 is more than the 3 bytes left can hold",
                cut.len() - 4
            )
        );
        assert_eq!(
            refusal(&[*MAGIC, [0x80; 4]].concat()),
            "byte 4: the data ends inside the vertex count"
        );
        let mut extra = good.clone();
        extra.push(0);
        assert!(refusal(&extra).ends_with("1 byte more after the last face"));
        // Face 0's first corner pointing past the 8 vertices.
        let mut wild = good.clone();
        let first_corner = 4 + 1 + 1 + 8 * 12 + 1;
        wild[first_corner] = 0x7e;
        assert_eq!(
            refusal(&wild),
            format!("byte {first_corner}: face 0 has a corner outside the 8 vertices")
        );
        let mut two = encode(&generate::cube());
        two[4 + 1 + 1 + 8 * 12] = 2;
        assert!(
            refusal(&two).contains("face 0 has 2 corners"),
            "{}",
            refusal(&two)
        );
    }
}
