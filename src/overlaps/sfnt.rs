//! The OpenType container, read and written by hand: the table directory, table checksums and
//! `head.checkSumAdjustment` (OpenType, "Font file" and "Calculating checksums").
//!
//! Written fonts list their tables in tag order (as the directory must), each table's data
//! 4-byte aligned and zero-padded, in the same order; a table that is not rewritten keeps its
//! bytes.

use crate::error::{Error, Result};

fn fail(message: String) -> Error {
    Error::InvalidArgument { message }
}

/// A font's tables: the sfnt version and each table's tag and bytes, in directory order.
pub(super) struct Tables<'a> {
    /// `0x00010000` (TrueType outlines) or `OTTO` (CFF).
    pub version: u32,
    /// `(tag, data)`.
    pub tables: Vec<([u8; 4], &'a [u8])>,
}

/// A big-endian `u16` at `at` (the caller checked the length).
pub(super) fn u16_at(d: &[u8], at: usize) -> u16 {
    u16::from_be_bytes([d[at], d[at + 1]])
}

/// A big-endian `i16` at `at`.
pub(super) fn i16_at(d: &[u8], at: usize) -> i16 {
    i16::from_be_bytes([d[at], d[at + 1]])
}

/// A big-endian `u32` at `at`.
pub(super) fn u32_at(d: &[u8], at: usize) -> u32 {
    u32::from_be_bytes([d[at], d[at + 1], d[at + 2], d[at + 3]])
}

impl<'a> Tables<'a> {
    /// Reads the table directory of a single font (not a collection, not WOFF).
    pub fn read(data: &'a [u8]) -> Result<Self> {
        if data.len() < 12 {
            return Err(fail("not an OpenType font: shorter than its header".into()));
        }
        let version = u32_at(data, 0);
        match &data[..4] {
            b"ttcf" => {
                return Err(fail("a font collection (.ttc/.otc): remove-overlaps writes single fonts".into()));
            }
            b"wOFF" | b"wOF2" => return Err(fail("a WOFF font: decompress it first".into())),
            [0, 1, 0, 0] | b"OTTO" | b"true" => {}
            _ => return Err(fail("not an OpenType font (unknown sfnt version)".into())),
        }
        let count = u16_at(data, 4) as usize;
        if data.len() < 12 + 16 * count {
            return Err(fail(format!("table directory of {count} tables runs past the end of the file")));
        }
        let mut tables = Vec::with_capacity(count);
        for k in 0..count {
            let r = 12 + 16 * k;
            let tag: [u8; 4] = data[r..r + 4].try_into().expect("four bytes");
            let (offset, length) = (u32_at(data, r + 8) as usize, u32_at(data, r + 12) as usize);
            let table = offset
                .checked_add(length)
                .and_then(|end| data.get(offset..end))
                .ok_or_else(|| fail(format!("table {:?} runs past the end of the file", tag_name(&tag))))?;
            if tables.iter().any(|(t, _)| *t == tag) {
                return Err(fail(format!("table {:?} listed twice", tag_name(&tag))));
            }
            tables.push((tag, table));
        }
        Ok(Tables { version, tables })
    }

    /// The table with this tag.
    pub fn get(&self, tag: &[u8; 4]) -> Option<&'a [u8]> {
        self.tables.iter().find(|(t, _)| t == tag).map(|(_, d)| *d)
    }

    /// The table, or an error naming it.
    pub fn need(&self, tag: &[u8; 4], size: usize) -> Result<&'a [u8]> {
        let t = self.get(tag).ok_or_else(|| fail(format!("no {:?} table", tag_name(tag))))?;
        if t.len() < size {
            return Err(fail(format!("table {:?} is shorter than {size} bytes", tag_name(tag))));
        }
        Ok(t)
    }
}

/// A tag as text.
pub(super) fn tag_name(tag: &[u8; 4]) -> String {
    String::from_utf8_lossy(tag).into_owned()
}

/// The OpenType checksum of a table: the sum of its big-endian `u32` words, the last one
/// zero-padded, modulo 2³².
pub(super) fn checksum(data: &[u8]) -> u32 {
    let mut sum = 0u32;
    for chunk in data.chunks(4) {
        let mut w = [0u8; 4];
        w[..chunk.len()].copy_from_slice(chunk);
        sum = sum.wrapping_add(u32::from_be_bytes(w));
    }
    sum
}

/// The font file of these tables: the directory sorted by tag with the binary-search fields,
/// each table's checksum, the data 4-byte aligned in directory order, and
/// `head.checkSumAdjustment` set so that the whole file sums to `0xB1B0AFBA`.
pub(super) fn assemble(version: u32, mut tables: Vec<([u8; 4], Vec<u8>)>) -> Vec<u8> {
    tables.sort_by_key(|a| a.0);
    let count = tables.len();
    let mut entry_selector = 0u16;
    while (2usize << entry_selector) <= count {
        entry_selector += 1;
    }
    let search_range = if count == 0 { 0 } else { 16u16 << entry_selector };
    let range_shift = (16 * count as u16).saturating_sub(search_range);
    let mut out = Vec::with_capacity(12 + 16 * count + tables.iter().map(|t| t.1.len() + 3).sum::<usize>());
    out.extend(version.to_be_bytes());
    out.extend((count as u16).to_be_bytes());
    out.extend(search_range.to_be_bytes());
    out.extend(entry_selector.to_be_bytes());
    out.extend(range_shift.to_be_bytes());
    let mut offset = 12 + 16 * count;
    let mut head_at = None;
    for (tag, data) in &mut tables {
        if tag == b"head" && data.len() >= 12 {
            data[8..12].copy_from_slice(&[0; 4]);
        }
        out.extend(*tag);
        out.extend(checksum(data).to_be_bytes());
        out.extend((offset as u32).to_be_bytes());
        out.extend((data.len() as u32).to_be_bytes());
        if tag == b"head" && data.len() >= 12 {
            head_at = Some(offset);
        }
        offset += data.len().next_multiple_of(4);
    }
    for (_, data) in &tables {
        out.extend(data.iter());
        out.resize(out.len().next_multiple_of(4), 0);
    }
    if let Some(at) = head_at {
        let adjustment = 0xB1B0_AFBAu32.wrapping_sub(checksum(&out));
        out[at + 8..at + 12].copy_from_slice(&adjustment.to_be_bytes());
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn checksum_pads_the_last_word() {
        assert_eq!(checksum(&[0, 0, 0, 1, 2]), 1 + 0x0200_0000);
    }

    #[test]
    fn assembled_font_sums_to_the_magic_number() {
        let mut head = vec![0u8; 54];
        head[12..16].copy_from_slice(&0x5F0F_3CF5u32.to_be_bytes());
        let font = assemble(0x0001_0000, vec![(*b"zzzz", vec![1, 2, 3]), (*b"head", head)]);
        assert_eq!(checksum(&font), 0xB1B0_AFBA);
        let t = Tables::read(&font).unwrap();
        assert_eq!(t.tables.iter().map(|t| t.0).collect::<Vec<_>>(), [*b"head", *b"zzzz"]);
        assert_eq!(t.get(b"zzzz").unwrap(), [1, 2, 3]);
    }
}
