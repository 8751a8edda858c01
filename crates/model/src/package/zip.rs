//! A zip archive written in memory: what an LMS takes as a SCORM package.
//!
//! Only what a package needs: DEFLATE or stored entries, no directories, no
//! zip64 (a package is a few megabytes), and one fixed timestamp so the same
//! input always gives the same bytes. Hand-written because the browser
//! builds packages too, and the `zip` crate would add reading, encryption and
//! zip64 to the download for nothing.

/// 1980-01-01 00:00, the earliest MS-DOS date: a fixed time keeps packages
/// reproducible.
const DOS_TIME: u16 = 0;
const DOS_DATE: u16 = (1 << 5) | 1;

/// The most entries and bytes a zip without zip64 holds.
const MAX_ENTRIES: usize = u16::MAX as usize;
const MAX_BYTES: u64 = u32::MAX as u64;

/// How hard DEFLATE tries (miniz's 0–10): 9 packs the wasm within 1% of
/// gzip -9, which the 3 MB goal for a package needs.
const LEVEL: u8 = 9;

/// An archive being written.
#[derive(Default)]
pub struct ZipWriter {
    out: Vec<u8>,
    central: Vec<u8>,
    entries: usize,
}

impl ZipWriter {
    /// Adds a file; `name` uses `/` between folders. Data that does not
    /// shrink is stored as it is.
    pub fn add(&mut self, name: &str, data: &[u8]) -> Result<(), String> {
        if self.entries == MAX_ENTRIES || data.len() as u64 > MAX_BYTES {
            return Err(format!(
                "{name}: a package holds at most 4 GB in 65,535 files"
            ));
        }
        let packed = miniz_oxide::deflate::compress_to_vec(data, LEVEL);
        let (method, body): (u16, &[u8]) = if packed.len() < data.len() {
            (8, &packed)
        } else {
            (0, data)
        };
        let offset = self.out.len();
        if (offset + body.len() + name.len()) as u64 + 30 > MAX_BYTES {
            return Err(format!("{name}: the package would pass 4 GB"));
        }
        let crc = crc32fast::hash(data);
        let common = |to: &mut Vec<u8>| {
            put16(to, 20); // version needed: 2.0 (DEFLATE)
            put16(to, 1 << 11); // names are UTF-8
            put16(to, method);
            put16(to, DOS_TIME);
            put16(to, DOS_DATE);
            put32(to, crc);
            put32(to, body.len() as u32);
            put32(to, data.len() as u32);
            put16(to, name.len() as u16);
            put16(to, 0); // extra field
        };
        put32(&mut self.out, 0x0403_4b50);
        common(&mut self.out);
        self.out.extend_from_slice(name.as_bytes());
        self.out.extend_from_slice(body);

        put32(&mut self.central, 0x0201_4b50);
        put16(&mut self.central, 20); // made by: 2.0, MS-DOS attributes
        common(&mut self.central);
        put16(&mut self.central, 0); // comment
        put16(&mut self.central, 0); // disk
        put16(&mut self.central, 0); // internal attributes
        put32(&mut self.central, 0); // external attributes
        put32(&mut self.central, offset as u32);
        self.central.extend_from_slice(name.as_bytes());
        self.entries += 1;
        Ok(())
    }

    /// The archive's bytes.
    pub fn finish(mut self) -> Vec<u8> {
        let start = self.out.len() as u32;
        let size = self.central.len() as u32;
        self.out.append(&mut self.central);
        put32(&mut self.out, 0x0605_4b50);
        put16(&mut self.out, 0); // this disk
        put16(&mut self.out, 0); // the central directory's disk
        put16(&mut self.out, self.entries as u16);
        put16(&mut self.out, self.entries as u16);
        put32(&mut self.out, size);
        put32(&mut self.out, start);
        put16(&mut self.out, 0); // comment
        self.out
    }
}

fn put16(to: &mut Vec<u8>, value: u16) {
    to.extend_from_slice(&value.to_le_bytes());
}

fn put32(to: &mut Vec<u8>, value: u32) {
    to.extend_from_slice(&value.to_le_bytes());
}
