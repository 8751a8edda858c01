//! Stanford PLY: ASCII, binary little-endian and binary big-endian.
//!
//! The `vertex` element gives x, y and z (of any numeric type); the `face`
//! element gives a list named `vertex_indices` or `vertex_index` (any count
//! and integer index types). Other properties (normals, colours) and other
//! elements are skipped.
//!
//! Our own reader rather than ply-rs-bw: reading the 200k-face benchmark
//! torus into polygons it took 14 ms against 25 ms for binary and 65 ms
//! against 159 ms for ASCII (`benches/formats.rs`; ply-rs-bw through its typed
//! fast path), it needs no dependency (ply-rs-bw brings peg, indexmap and
//! byteorder), and its errors carry a line or byte offset. Binary vertex rows
//! of fixed size and faces whose only property is the index list take a fast
//! path with one bounds check per row; anything else takes the general path.
//!
//! Before reading any data it checks that the counts in the header fit in
//! the bytes that follow, so a 200-byte file claiming four billion vertices
//! is refused instead of reserving gigabytes.

use std::fmt::Write as _;

use glam::Vec3;

use super::error::{FormatError, Location, Problem, SaveError, shown};
use super::rows::is_decimal;
use crate::mesh::Polygons;

/// How a PLY file stores its data.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum PlyEncoding {
    /// Text, one element per line.
    #[default]
    Ascii,
    /// Binary, least significant byte first.
    BinaryLittleEndian,
    /// Binary, most significant byte first.
    BinaryBigEndian,
}

impl PlyEncoding {
    fn header_name(self) -> &'static str {
        match self {
            Self::Ascii => "ascii",
            Self::BinaryLittleEndian => "binary_little_endian",
            Self::BinaryBigEndian => "binary_big_endian",
        }
    }
}

/// A PLY scalar type.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Scalar {
    I8,
    U8,
    I16,
    U16,
    I32,
    U32,
    F32,
    F64,
}

impl Scalar {
    fn parse(name: &str) -> Option<Self> {
        Some(match name {
            "char" | "int8" => Self::I8,
            "uchar" | "uint8" => Self::U8,
            "short" | "int16" => Self::I16,
            "ushort" | "uint16" => Self::U16,
            "int" | "int32" => Self::I32,
            "uint" | "uint32" => Self::U32,
            "float" | "float32" => Self::F32,
            "double" | "float64" => Self::F64,
            _ => return None,
        })
    }

    fn size(self) -> usize {
        match self {
            Self::I8 | Self::U8 => 1,
            Self::I16 | Self::U16 => 2,
            Self::I32 | Self::U32 | Self::F32 => 4,
            Self::F64 => 8,
        }
    }

    fn is_integer(self) -> bool {
        !matches!(self, Self::F32 | Self::F64)
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    Scalar(Scalar),
    List { count: Scalar, item: Scalar },
}

#[derive(Debug)]
struct Property {
    name: String,
    kind: Kind,
}

#[derive(Debug)]
struct Element {
    name: String,
    count: usize,
    properties: Vec<Property>,
    line: usize,
}

impl Element {
    /// The fewest bytes one row can take: binary scalars and list counts, or
    /// for ASCII one character and one separator per value.
    fn min_row_bytes(&self, encoding: PlyEncoding) -> usize {
        match encoding {
            PlyEncoding::Ascii => 2 * self.properties.len().max(1),
            _ => self
                .properties
                .iter()
                .map(|p| match p.kind {
                    Kind::Scalar(s) => s.size(),
                    Kind::List { count, .. } => count.size(),
                })
                .sum::<usize>()
                .max(1),
        }
    }

    /// The fixed size of a binary row, if it has no list.
    fn fixed_row_bytes(&self) -> Option<usize> {
        self.properties
            .iter()
            .map(|p| match p.kind {
                Kind::Scalar(s) => Some(s.size()),
                Kind::List { .. } => None,
            })
            .sum()
    }
}

struct Header {
    encoding: PlyEncoding,
    elements: Vec<Element>,
    /// Byte offset of the first data byte.
    data_start: usize,
    /// Line number of `end_header`.
    end_line: usize,
}

fn header_error(line: usize, message: impl Into<String>) -> FormatError {
    FormatError::new(Location::line(line), message)
}

fn parse_header(bytes: &[u8]) -> Result<Header, FormatError> {
    if !(bytes.starts_with(b"ply\n") || bytes.starts_with(b"ply\r\n")) {
        return Err(header_error(
            1,
            "expected the magic word \"ply\" alone on the first line",
        ));
    }
    let mut encoding = None;
    let mut elements: Vec<Element> = Vec::new();
    let mut offset = 0;
    for (index, raw) in bytes.split(|&b| b == b'\n').enumerate() {
        let number = index + 1;
        offset += raw.len() + 1;
        if index == 0 {
            continue;
        }
        let line = std::str::from_utf8(raw.strip_suffix(b"\r").unwrap_or(raw))
            .map_err(|_| header_error(number, "the header holds a byte that is not text"))?;
        let words: Vec<&str> = line.split_ascii_whitespace().collect();
        match words.as_slice() {
            [] | ["comment" | "obj_info", ..] => {}
            ["format", name, version] => {
                encoding = Some(match *name {
                    "ascii" => PlyEncoding::Ascii,
                    "binary_little_endian" => PlyEncoding::BinaryLittleEndian,
                    "binary_big_endian" => PlyEncoding::BinaryBigEndian,
                    other => {
                        return Err(header_error(
                            number,
                            format!(
                                "unknown format \"{other}\"; expected ascii, binary_little_endian \
                                 or binary_big_endian"
                            ),
                        ));
                    }
                });
                if *version != "1.0" && *version != "1" {
                    return Err(header_error(
                        number,
                        format!("PLY version {version} is not supported; expected 1.0"),
                    ));
                }
            }
            ["element", name, count] => {
                let count = count.parse::<u32>().map_err(|_| {
                    header_error(
                        number,
                        format!(
                            "expected the number of {name} rows (0 to {}), found \"{}\"",
                            u32::MAX,
                            shown(count.as_bytes())
                        ),
                    )
                })?;
                elements.push(Element {
                    name: (*name).to_owned(),
                    count: count as usize,
                    properties: Vec::new(),
                    line: number,
                });
            }
            ["property", rest @ ..] => {
                let Some(element) = elements.last_mut() else {
                    return Err(header_error(
                        number,
                        "a property before any element; expected \"element <name> <count>\" first",
                    ));
                };
                let scalar = |name: &str| {
                    Scalar::parse(name).ok_or_else(|| {
                        header_error(
                            number,
                            format!(
                                "unknown type \"{name}\"; expected char, uchar, short, ushort, \
                                 int, uint, float or double (or int8 … float64)"
                            ),
                        )
                    })
                };
                let (kind, name) = match rest {
                    ["list", count, item, name] => {
                        let count = scalar(count)?;
                        if !count.is_integer() {
                            return Err(header_error(
                                number,
                                format!("the count type of list {name} must be an integer type"),
                            ));
                        }
                        (
                            Kind::List {
                                count,
                                item: scalar(item)?,
                            },
                            name,
                        )
                    }
                    [ty, name] => (Kind::Scalar(scalar(ty)?), name),
                    _ => {
                        return Err(header_error(
                            number,
                            format!(
                                "expected \"property <type> <name>\" or \"property list <count type> \
                                 <item type> <name>\", found \"{}\"",
                                shown(line.as_bytes())
                            ),
                        ));
                    }
                };
                element.properties.push(Property {
                    name: (*name).to_owned(),
                    kind,
                });
            }
            ["end_header"] => {
                let encoding = encoding.ok_or_else(|| {
                    header_error(
                        number,
                        "the header has no \"format\" line before end_header",
                    )
                })?;
                return Ok(Header {
                    encoding,
                    elements,
                    data_start: offset.min(bytes.len()),
                    end_line: number,
                });
            }
            _ => {
                return Err(header_error(
                    number,
                    format!(
                        "unexpected header line \"{}\"; expected format, comment, element, \
                         property or end_header",
                        line.chars().take(60).collect::<String>()
                    ),
                ));
            }
        }
        if number > 10_000 {
            break;
        }
    }
    Err(header_error(
        1,
        "the header never ends: expected an \"end_header\" line",
    ))
}

/// Which properties the mesh uses.
struct Roles {
    vertex: usize,
    /// Property index of x, y and z in the vertex element.
    xyz: [usize; 3],
    face: usize,
    /// Property index of the index list in the face element.
    indices: usize,
}

fn roles(header: &Header) -> Result<Roles, FormatError> {
    let find = |name: &str| header.elements.iter().position(|e| e.name == name);
    let vertex = find("vertex").ok_or_else(|| {
        header_error(
            header.end_line,
            "the header declares no \"vertex\" element; expected \"element vertex <count>\"",
        )
    })?;
    let face = find("face").ok_or_else(|| {
        header_error(
            header.end_line,
            "the header declares no \"face\" element; a mesh needs faces \
             (\"element face <count>\" with a vertex_indices list)",
        )
    })?;
    let mut xyz = [0; 3];
    let vertex_element = header.elements.get(vertex);
    for (slot, axis) in xyz.iter_mut().zip(["x", "y", "z"]) {
        let found = vertex_element.and_then(|e| {
            e.properties
                .iter()
                .position(|p| p.name == axis && matches!(p.kind, Kind::Scalar(_)))
        });
        *slot = found.ok_or_else(|| {
            header_error(
                vertex_element.map_or(header.end_line, |e| e.line),
                format!("the vertex element has no scalar property \"{axis}\""),
            )
        })?;
    }
    let face_element = header.elements.get(face);
    let indices = face_element
        .and_then(|e| {
            e.properties.iter().position(|p| {
                (p.name == "vertex_indices" || p.name == "vertex_index")
                    && matches!(p.kind, Kind::List { .. })
            })
        })
        .ok_or_else(|| {
            header_error(
                face_element.map_or(header.end_line, |e| e.line),
                "the face element has no list property \"vertex_indices\" or \"vertex_index\"",
            )
        })?;
    if let Some(Property {
        kind: Kind::List { item, .. },
        name,
    }) = face_element.and_then(|e| e.properties.get(indices))
        && !item.is_integer()
    {
        return Err(header_error(
            face_element.map_or(header.end_line, |e| e.line),
            format!(
                "the face list \"{name}\" holds floating-point numbers; expected an integer type"
            ),
        ));
    }
    Ok(Roles {
        vertex,
        xyz,
        face,
        indices,
    })
}

/// Refuses counts the data cannot hold, before anything is reserved.
fn check_counts(header: &Header, available: usize) -> Result<(), FormatError> {
    let mut needed: u128 = 0;
    for element in &header.elements {
        let row = element.min_row_bytes(header.encoding);
        let bytes = element.count as u128 * row as u128;
        needed += bytes;
        if needed > available as u128 {
            let unit = match header.encoding {
                PlyEncoding::Ascii => "characters",
                _ => "bytes",
            };
            return Err(header_error(
                element.line,
                format!(
                    "the header announces {} {} rows of at least {row} {unit} each, but only \
                     {available} bytes of data follow the header",
                    element.count, element.name
                ),
            ));
        }
    }
    Ok(())
}

/// The elements read so far: positions and faces.
struct Mesh {
    polygons: Polygons,
    /// The face being read.
    face: Vec<u32>,
}

pub(super) fn read(bytes: &[u8]) -> Result<(Polygons, Vec<Problem>), FormatError> {
    let header = parse_header(bytes)?;
    let roles = roles(&header)?;
    let data = bytes.get(header.data_start..).unwrap_or(&[]);
    check_counts(&header, data.len())?;
    let mut warnings = Vec::new();
    for (i, element) in header.elements.iter().enumerate() {
        if i != roles.vertex && i != roles.face && element.count > 0 {
            warnings.push(Problem::new(
                Location::line(element.line),
                format!(
                    "the {} rows of element \"{}\" are skipped; only vertex and face make the mesh",
                    element.count, element.name
                ),
            ));
        }
    }
    let vertex_count = header.elements.get(roles.vertex).map_or(0, |e| e.count);
    let face_count = header.elements.get(roles.face).map_or(0, |e| e.count);
    if face_count == 0 {
        return Err(header_error(
            header
                .elements
                .get(roles.face)
                .map_or(header.end_line, |e| e.line),
            "the file has no faces (element face 0); a mesh needs at least one face",
        ));
    }
    // Counts are backed by data (checked above), so these reservations are
    // bounded by the file size.
    let mut mesh = Mesh {
        polygons: Polygons::with_capacity(vertex_count, face_count, face_count * 3),
        face: Vec::new(),
    };
    match header.encoding {
        PlyEncoding::Ascii => read_ascii(bytes, &header, &roles, &mut mesh)?,
        encoding => {
            let big = encoding == PlyEncoding::BinaryBigEndian;
            let mut reader = Binary {
                bytes,
                offset: header.data_start,
                big,
            };
            read_binary(&mut reader, &header, &roles, &mut mesh)?;
        }
    }
    // Vertex numbers out of range are left to the builder, which names the
    // face (and, for ASCII, its line).
    Ok((mesh.polygons, warnings))
}

/// A cursor over binary data.
struct Binary<'a> {
    bytes: &'a [u8],
    offset: usize,
    big: bool,
}

impl Binary<'_> {
    fn take<const N: usize>(&mut self, what: &dyn Fn() -> String) -> Result<[u8; N], FormatError> {
        let chunk = self
            .bytes
            .get(self.offset..self.offset + N)
            .and_then(|s| <[u8; N]>::try_from(s).ok());
        match chunk {
            Some(mut chunk) => {
                self.offset += N;
                if self.big == cfg!(target_endian = "little") {
                    chunk.reverse();
                }
                Ok(chunk)
            }
            None => Err(FormatError::new(
                Location::Byte(self.offset as u64),
                format!(
                    "the file ends inside {}: expected {N} more bytes, {} are left",
                    what(),
                    self.bytes.len().saturating_sub(self.offset)
                ),
            )),
        }
    }

    fn number(&mut self, scalar: Scalar, what: &dyn Fn() -> String) -> Result<f64, FormatError> {
        Ok(match scalar {
            Scalar::I8 => f64::from(i8::from_ne_bytes(self.take::<1>(what)?)),
            Scalar::U8 => f64::from(u8::from_ne_bytes(self.take::<1>(what)?)),
            Scalar::I16 => f64::from(i16::from_ne_bytes(self.take::<2>(what)?)),
            Scalar::U16 => f64::from(u16::from_ne_bytes(self.take::<2>(what)?)),
            Scalar::I32 => f64::from(i32::from_ne_bytes(self.take::<4>(what)?)),
            Scalar::U32 => f64::from(u32::from_ne_bytes(self.take::<4>(what)?)),
            Scalar::F32 => f64::from(f32::from_ne_bytes(self.take::<4>(what)?)),
            Scalar::F64 => f64::from_ne_bytes(self.take::<8>(what)?),
        })
    }

    fn integer(&mut self, scalar: Scalar, what: &dyn Fn() -> String) -> Result<i64, FormatError> {
        Ok(match scalar {
            Scalar::I8 => i64::from(i8::from_ne_bytes(self.take::<1>(what)?)),
            Scalar::U8 => i64::from(u8::from_ne_bytes(self.take::<1>(what)?)),
            Scalar::I16 => i64::from(i16::from_ne_bytes(self.take::<2>(what)?)),
            Scalar::U16 => i64::from(u16::from_ne_bytes(self.take::<2>(what)?)),
            Scalar::I32 => i64::from(i32::from_ne_bytes(self.take::<4>(what)?)),
            Scalar::U32 => i64::from(u32::from_ne_bytes(self.take::<4>(what)?)),
            // Refused in the header for index lists and list counts.
            Scalar::F32 | Scalar::F64 => self.number(scalar, what)? as i64,
        })
    }

    fn skip(&mut self, count: usize, what: &dyn Fn() -> String) -> Result<(), FormatError> {
        if self.bytes.len().saturating_sub(self.offset) < count {
            return Err(FormatError::new(
                Location::Byte(self.offset as u64),
                format!(
                    "the file ends inside {}: expected {count} more bytes, {} are left",
                    what(),
                    self.bytes.len().saturating_sub(self.offset)
                ),
            ));
        }
        self.offset += count;
        Ok(())
    }
}

/// A scalar at the start of `bytes` (which holds at least its size).
#[inline]
fn scalar_at(bytes: &[u8], scalar: Scalar, big: bool) -> f64 {
    fn get<const N: usize>(bytes: &[u8], big: bool) -> [u8; N] {
        let mut chunk = [0; N];
        if let Some(source) = bytes.get(..N) {
            chunk.copy_from_slice(source);
        }
        if big == cfg!(target_endian = "little") {
            chunk.reverse();
        }
        chunk
    }
    match scalar {
        Scalar::I8 => f64::from(i8::from_ne_bytes(get(bytes, big))),
        Scalar::U8 => f64::from(u8::from_ne_bytes(get(bytes, big))),
        Scalar::I16 => f64::from(i16::from_ne_bytes(get(bytes, big))),
        Scalar::U16 => f64::from(u16::from_ne_bytes(get(bytes, big))),
        Scalar::I32 => f64::from(i32::from_ne_bytes(get(bytes, big))),
        Scalar::U32 => f64::from(u32::from_ne_bytes(get(bytes, big))),
        Scalar::F32 => f64::from(f32::from_ne_bytes(get(bytes, big))),
        Scalar::F64 => f64::from_ne_bytes(get(bytes, big)),
    }
}

/// Vertices whose rows have a fixed size (no list property, the usual
/// case): one bounds check per row. Returns false to use the general path.
fn fast_vertices(
    reader: &mut Binary<'_>,
    element: &Element,
    roles: &Roles,
    mesh: &mut Mesh,
) -> Result<bool, FormatError> {
    let Some(row_size) = element.fixed_row_bytes() else {
        return Ok(false);
    };
    let mut axes = [(0, Scalar::F32); 3];
    let mut offset = 0;
    for (p, property) in element.properties.iter().enumerate() {
        let Kind::Scalar(scalar) = property.kind else {
            return Ok(false);
        };
        if let Some(axis) = roles.xyz.iter().position(|&i| i == p)
            && let Some(slot) = axes.get_mut(axis)
        {
            *slot = (offset, scalar);
        }
        offset += scalar.size();
    }
    for row in 0..element.count {
        let start = reader.offset;
        let Some(data) = reader.bytes.get(start..start + row_size) else {
            let what = || format!("vertex {row}");
            reader.skip(row_size, &what)?;
            continue;
        };
        let mut xyz = [0.0f32; 3];
        for ((slot, &(at, scalar)), name) in xyz.iter_mut().zip(&axes).zip(["x", "y", "z"]) {
            let value = scalar_at(data.get(at..).unwrap_or(&[]), scalar, reader.big) as f32;
            if !value.is_finite() {
                return Err(FormatError::new(
                    Location::Byte((start + at) as u64),
                    format!(
                        "vertex {row} has {name} = {value}; coordinates must be finite numbers"
                    ),
                ));
            }
            *slot = value;
        }
        mesh.polygons.push_vertex(Vec3::from(xyz));
        reader.offset += row_size;
    }
    Ok(true)
}

/// Faces whose only property is the index list (the usual case): the items
/// of each list are read from one checked slice.
fn fast_faces(
    reader: &mut Binary<'_>,
    element: &Element,
    mesh: &mut Mesh,
) -> Result<bool, FormatError> {
    let Some(Kind::List { count, item }) = element.properties.first().map(|p| p.kind) else {
        return Ok(false);
    };
    for row in 0..element.count {
        let start = reader.offset;
        let what = || format!("face {row}");
        let n = reader.integer(count, &what)?;
        let size = usize::try_from(n)
            .ok()
            .and_then(|n| n.checked_mul(item.size()));
        let data = size.and_then(|size| reader.bytes.get(reader.offset..reader.offset + size));
        let Some(data) = data else {
            return Err(FormatError::new(
                Location::Byte(start as u64),
                format!(
                    "the file ends inside face {row}: its list announces {n} items ({} bytes), but \
                     only {} bytes are left",
                    i128::from(n) * item.size() as i128,
                    reader.bytes.len().saturating_sub(reader.offset)
                ),
            ));
        };
        mesh.face.clear();
        for (k, chunk) in data.chunks_exact(item.size()).enumerate() {
            let index = scalar_at(chunk, item, reader.big);
            if index < 0.0 {
                return Err(FormatError::new(
                    Location::Byte((reader.offset + k * item.size()) as u64),
                    format!("face {row} refers to vertex {index}; vertex numbers start at 0"),
                ));
            }
            mesh.face.push(index as u32);
        }
        mesh.polygons.push_face(&mesh.face);
        reader.offset += data.len();
    }
    Ok(true)
}

fn read_binary(
    reader: &mut Binary<'_>,
    header: &Header,
    roles: &Roles,
    mesh: &mut Mesh,
) -> Result<(), FormatError> {
    for (e, element) in header.elements.iter().enumerate() {
        let is_vertex = e == roles.vertex;
        let is_face = e == roles.face;
        if is_vertex && fast_vertices(reader, element, roles, mesh)? {
            continue;
        }
        if is_face && element.properties.len() == 1 && fast_faces(reader, element, mesh)? {
            continue;
        }
        if !is_vertex
            && !is_face
            && let Some(size) = element.fixed_row_bytes()
        {
            let what = || format!("element {}", element.name);
            reader.skip(element.count.saturating_mul(size), &what)?;
            continue;
        }
        for row in 0..element.count {
            let mut xyz = [0.0f32; 3];
            for (p, property) in element.properties.iter().enumerate() {
                let what = || format!("{} {row} (property {})", element.name, property.name);
                match property.kind {
                    Kind::Scalar(scalar) => {
                        let value = reader.number(scalar, &what)?;
                        if is_vertex && let Some(axis) = roles.xyz.iter().position(|&i| i == p) {
                            let start = reader.offset - scalar.size();
                            let value = value as f32;
                            if !value.is_finite() {
                                return Err(FormatError::new(
                                    Location::Byte(start as u64),
                                    format!(
                                        "vertex {row} has {} = {value}; coordinates must be \
                                         finite numbers",
                                        ["x", "y", "z"].get(axis).copied().unwrap_or("x")
                                    ),
                                ));
                            }
                            if let Some(slot) = xyz.get_mut(axis) {
                                *slot = value;
                            }
                        }
                    }
                    Kind::List { count, item } => {
                        let start = reader.offset;
                        let n = reader.integer(count, &what)?;
                        let n = usize::try_from(n).map_err(|_| {
                            FormatError::new(
                                Location::Byte(start as u64),
                                format!("{} {row} has a list of {n} items", element.name),
                            )
                        })?;
                        let size = n.saturating_mul(item.size());
                        if reader.bytes.len().saturating_sub(reader.offset) < size {
                            return Err(FormatError::new(
                                Location::Byte(start as u64),
                                format!(
                                    "the file ends inside {} {row}: its list announces {n} items \
                                     ({size} bytes), but only {} bytes are left",
                                    element.name,
                                    reader.bytes.len().saturating_sub(reader.offset)
                                ),
                            ));
                        }
                        if is_face && p == roles.indices {
                            mesh.face.clear();
                            for _ in 0..n {
                                let at = reader.offset;
                                let index = reader.integer(item, &what)?;
                                let index = u32::try_from(index).map_err(|_| {
                                    FormatError::new(
                                        Location::Byte(at as u64),
                                        format!(
                                            "face {row} refers to vertex {index}; vertex numbers \
                                             start at 0"
                                        ),
                                    )
                                })?;
                                mesh.face.push(index);
                            }
                            mesh.polygons.push_face(&mesh.face);
                        } else {
                            reader.skip(size, &what)?;
                        }
                    }
                }
            }
            if is_vertex {
                mesh.polygons.push_vertex(Vec3::from(xyz));
            }
        }
    }
    let left = reader.bytes.len().saturating_sub(reader.offset);
    if left > 0 {
        return Err(FormatError::new(
            Location::Byte(reader.offset as u64),
            format!(
                "{left} bytes are left after the last element; the counts in the header do not \
                 match the data"
            ),
        ));
    }
    Ok(())
}

fn read_ascii(
    bytes: &[u8],
    header: &Header,
    roles: &Roles,
    mesh: &mut Mesh,
) -> Result<(), FormatError> {
    let data = bytes.get(header.data_start..).unwrap_or(&[]);
    let mut lines = data
        .split(|&b| b == b'\n')
        .enumerate()
        .map(|(i, line)| (header.end_line + 1 + i, line))
        .filter(|(_, line)| !line.trim_ascii().is_empty());
    let mut words: Vec<(usize, &[u8])> = Vec::new();
    for (e, element) in header.elements.iter().enumerate() {
        let is_vertex = e == roles.vertex;
        let is_face = e == roles.face;
        for row in 0..element.count {
            let Some((number, line)) = lines.next() else {
                return Err(FormatError::new(
                    Location::line(header.end_line + 1 + data.split(|&b| b == b'\n').count()),
                    format!(
                        "the file ends after {row} of the {} {} rows announced on line {}",
                        element.count, element.name, element.line
                    ),
                ));
            };
            words.clear();
            let mut offset = 0;
            for word in line.split(u8::is_ascii_whitespace) {
                if !word.is_empty() {
                    words.push((offset, word));
                }
                offset += word.len() + 1;
            }
            let text = AsciiRow {
                number,
                line,
                words: &words,
                row,
                element,
            };
            let mut next = 0;
            let mut xyz = [0.0f32; 3];
            for (p, property) in element.properties.iter().enumerate() {
                if next >= words.len() {
                    return Err(text.missing(property));
                }
                match property.kind {
                    Kind::Scalar(_) => {
                        let axis = roles.xyz.iter().position(|&i| i == p);
                        match axis.filter(|_| is_vertex) {
                            Some(axis) => {
                                let value = text.coordinate(next, property)?;
                                if let Some(slot) = xyz.get_mut(axis) {
                                    *slot = value;
                                }
                            }
                            None => text.number(next, property)?,
                        }
                        next += 1;
                    }
                    Kind::List { .. } => {
                        let n = text.list_count(next, property)?;
                        next += 1;
                        if is_face && p == roles.indices {
                            mesh.face.clear();
                            for k in next..next + n {
                                mesh.face.push(text.vertex_number(k)?);
                            }
                            mesh.polygons.push_face_from_line(&mesh.face, number);
                        }
                        next += n;
                    }
                }
            }
            if next < words.len() {
                return Err(FormatError::new(
                    text.at(next),
                    format!(
                        "{} {row} has {} values, but its properties take {next}; expected one \
                         row per line",
                        element.name,
                        words.len()
                    ),
                ));
            }
            if is_vertex {
                mesh.polygons.push_vertex(Vec3::from(xyz));
            }
        }
    }
    if let Some((number, _)) = lines.next() {
        return Err(FormatError::new(
            Location::line(number),
            "more data follows the last element; the counts in the header do not match the data",
        ));
    }
    Ok(())
}

/// One data row of an ASCII file, split into words with their byte
/// offsets: reads and checks the words of each property.
struct AsciiRow<'a> {
    /// The line's number.
    number: usize,
    line: &'a [u8],
    words: &'a [(usize, &'a [u8])],
    /// The row's number within its element.
    row: usize,
    element: &'a Element,
}

impl AsciiRow<'_> {
    /// Where word `index` starts (the line's end past the last word).
    fn at(&self, index: usize) -> Location {
        let offset = self.words.get(index).map_or(self.line.len(), |&(o, _)| o);
        Location::at(self.number, offset + 1)
    }

    /// Word `index` as it is, for messages.
    fn raw(&self, index: usize) -> &[u8] {
        self.words.get(index).map_or(&b""[..], |&(_, w)| w)
    }

    /// Word `index` as text, for parsing; empty when it is not UTF-8.
    fn word(&self, index: usize) -> &str {
        std::str::from_utf8(self.raw(index)).unwrap_or("")
    }

    /// The row ends before `property`.
    fn missing(&self, property: &Property) -> FormatError {
        FormatError::new(
            Location::line(self.number),
            format!(
                "{} {} ends before property {}; expected one row per line",
                self.element.name, self.row, property.name
            ),
        )
    }

    /// Word `index`, a vertex's coordinate: a finite decimal number.
    fn coordinate(&self, index: usize, property: &Property) -> Result<f32, FormatError> {
        let text = self.word(index);
        match text.parse::<f32>().ok().filter(|v| v.is_finite()) {
            Some(value) if is_decimal(text) => Ok(value),
            _ => Err(FormatError::new(
                self.at(index),
                format!(
                    "expected a finite number for {} of vertex {}, found \"{}\"",
                    property.name,
                    self.row,
                    shown(self.raw(index))
                ),
            )),
        }
    }

    /// Word `index`, any other scalar: checked as a number and dropped.
    fn number(&self, index: usize, property: &Property) -> Result<(), FormatError> {
        if self.word(index).parse::<f64>().is_ok() {
            return Ok(());
        }
        Err(FormatError::new(
            self.at(index),
            format!(
                "expected a number for {} of {} {}, found \"{}\"",
                property.name,
                self.element.name,
                self.row,
                shown(self.raw(index))
            ),
        ))
    }

    /// Word `index`, the item count of a list, which as many words must
    /// follow.
    fn list_count(&self, index: usize, property: &Property) -> Result<usize, FormatError> {
        let n = self.word(index).parse::<usize>().map_err(|_| {
            FormatError::new(
                self.at(index),
                format!(
                    "expected the item count of list {}, found \"{}\"",
                    property.name,
                    shown(self.raw(index))
                ),
            )
        })?;
        let left = self.words.len().saturating_sub(index + 1);
        if left < n {
            return Err(FormatError::new(
                self.at(index),
                format!(
                    "the list {} announces {n} items, but only {left} values follow on this line",
                    property.name
                ),
            ));
        }
        Ok(n)
    }

    /// Word `index`, an item of a face's vertex list.
    fn vertex_number(&self, index: usize) -> Result<u32, FormatError> {
        self.word(index).parse::<u32>().map_err(|_| {
            FormatError::new(
                self.at(index),
                format!(
                    "expected a vertex number (0 or more), found \"{}\"",
                    shown(self.raw(index))
                ),
            )
        })
    }
}

pub(super) fn write(polygons: &Polygons, encoding: PlyEncoding) -> Result<Vec<u8>, SaveError> {
    let largest = polygons.faces().map(<[u32]>::len).max().unwrap_or(0);
    let count_type = if largest <= usize::from(u8::MAX) {
        "uchar"
    } else {
        "int"
    };
    let mut header = String::new();
    let _ = write!(
        header,
        "ply\nformat {} 1.0\ncomment Written by Edgewise; faces are counter-clockwise seen from outside\n\
         element vertex {}\nproperty float x\nproperty float y\nproperty float z\n\
         element face {}\nproperty list {count_type} int vertex_indices\nend_header\n",
        encoding.header_name(),
        polygons.vertex_count(),
        polygons.face_count()
    );
    if polygons.vertex_count() > i32::MAX as usize {
        return Err(SaveError::Unsupported(format!(
            "{} vertices do not fit PLY's int vertex numbers",
            polygons.vertex_count()
        )));
    }
    let mut out = header.into_bytes();
    match encoding {
        PlyEncoding::Ascii => {
            let mut text = String::new();
            for p in polygons.positions() {
                let _ = writeln!(text, "{} {} {}", p.x, p.y, p.z);
            }
            for face in polygons.faces() {
                let _ = write!(text, "{}", face.len());
                for &v in face {
                    let _ = write!(text, " {v}");
                }
                text.push('\n');
            }
            out.extend_from_slice(text.as_bytes());
        }
        PlyEncoding::BinaryLittleEndian | PlyEncoding::BinaryBigEndian => {
            let big = encoding == PlyEncoding::BinaryBigEndian;
            out.reserve(polygons.vertex_count() * 12 + polygons.corner_count() * 4);
            let put = |bytes: [u8; 4], out: &mut Vec<u8>| {
                if big {
                    out.extend(bytes.iter().rev());
                } else {
                    out.extend_from_slice(&bytes);
                }
            };
            for p in polygons.positions() {
                for c in [p.x, p.y, p.z] {
                    put(c.to_le_bytes(), &mut out);
                }
            }
            for face in polygons.faces() {
                if count_type == "uchar" {
                    out.push(face.len() as u8);
                } else {
                    put((face.len() as u32).to_le_bytes(), &mut out);
                }
                for &v in face {
                    put(v.to_le_bytes(), &mut out);
                }
            }
        }
    }
    Ok(out)
}
