//! CFF-flavoured OpenType fonts (`CFF ` version 1) rewritten.
//!
//! When no glyph is rewritten the `CFF ` table is copied. Otherwise, as fontTools'
//! `removeOverlaps` leaves it, the table is rebuilt:
//!
//! * a rewritten glyph's charstring is its contours (`rmoveto`, `rlineto`, `rrcurveto`,
//!   `endchar`, integer operands), with the original's width operand copied in front;
//! * every charstring is **desubroutinized** (each `callsubr`/`callgsubr` replaced by the
//!   subroutine's operators), so that no subroutine is left unused: the Global Subr INDEX and
//!   every Private DICT's `Subrs` are dropped. A glyph draws the same and keeps its width; a
//!   charstring that calls no subroutine (and keeps its hints) keeps its bytes;
//! * unless `keep_hinting`, the hints of every glyph are removed (`hstem`, `vstem`,
//!   `hstemhm`, `vstemhm`, `hintmask`, `cntrmask` with their operands, the width kept) and the
//!   Private DICTs lose their hinting values (`BlueValues` … `ExpansionFactor`), as fontTools'
//!   `remove_hints` does; with `keep_hinting` a rewritten glyph still has no hints;
//! * the header, Name INDEX, String INDEX, charset, Encoding and FDSelect are copied; the Top
//!   DICT and the Font DICTs keep every entry, with their offsets rewritten (as 5-byte
//!   integers).
//!
//! Why by hand: `write-fonts` writes no CFF, and `read-fonts` reads DICTs by value, dropping
//! what it does not know; the rebuild copies every byte it does not need to change. Charstrings
//! computing a subroutine number with the arithmetic operators (Type 2 `12 x`, unused in
//! OpenType fonts) are refused naming the glyph.
//!
//! Outside `CFF `, `head`'s box grows to contain the rewritten glyphs' control points when
//! they reach beyond it; `hmtx` and `hhea` are copied (fontTools' `removeOverlaps` leaves them).

use super::sfnt::{Tables, assemble, i16_at, u16_at};
use super::{GridContour, Written};
use crate::error::{Error, Result};

fn fail(message: String) -> Error {
    Error::InvalidArgument { message }
}

/// Nesting of subroutine calls the Type 2 format allows.
const MAX_SUBR_DEPTH: usize = 10;

/// Largest desubroutinized charstring written (bytes).
const MAX_CHARSTRING: usize = 1 << 20;

/// An INDEX: its items and where it ends.
struct Index<'a> {
    items: Vec<&'a [u8]>,
    end: usize,
}

fn read_index<'a>(cff: &'a [u8], at: usize, what: &str) -> Result<Index<'a>> {
    let bad = || fail(format!("CFF: {what} INDEX at byte {at} runs past the end of the table"));
    let count = u16_at(cff.get(at..at + 2).ok_or_else(bad)?, 0) as usize;
    if count == 0 {
        return Ok(Index { items: vec![], end: at + 2 });
    }
    let off_size = *cff.get(at + 2).ok_or_else(bad)? as usize;
    if !(1..=4).contains(&off_size) {
        return Err(fail(format!("CFF: {what} INDEX at byte {at}: offset size {off_size}")));
    }
    let offsets_at = at + 3;
    let data_at = offsets_at + (count + 1) * off_size - 1;
    let offset = |k: usize| -> Result<usize> {
        let b = cff.get(offsets_at + k * off_size..offsets_at + (k + 1) * off_size).ok_or_else(bad)?;
        Ok(b.iter().fold(0usize, |v, &x| (v << 8) | x as usize))
    };
    let mut items = Vec::with_capacity(count);
    let mut prev = offset(0)?;
    for k in 1..=count {
        let next = offset(k)?;
        if next < prev {
            return Err(fail(format!("CFF: {what} INDEX at byte {at}: offsets out of order")));
        }
        items.push(cff.get(data_at + prev..data_at + next).ok_or_else(bad)?);
        prev = next;
    }
    Ok(Index { items, end: data_at + prev })
}

fn write_index<T: AsRef<[u8]>>(items: &[T]) -> Vec<u8> {
    let mut out = (items.len() as u16).to_be_bytes().to_vec();
    if items.is_empty() {
        return out;
    }
    let last = 1 + items.iter().map(|i| i.as_ref().len()).sum::<usize>();
    let off_size = match last {
        0..=0xff => 1,
        0x100..=0xffff => 2,
        0x1_0000..=0xff_ffff => 3,
        _ => 4,
    };
    out.push(off_size as u8);
    let mut offset = 1usize;
    out.extend(&(offset as u32).to_be_bytes()[4 - off_size..]);
    for item in items {
        offset += item.as_ref().len();
        out.extend(&(offset as u32).to_be_bytes()[4 - off_size..]);
    }
    for item in items {
        out.extend(item.as_ref());
    }
    out
}

/// A DICT entry: its operands' bytes, their integer values (`None` for reals) and its
/// operator (`12 x` as `1200 + x`).
#[derive(Clone)]
struct Entry {
    operands: Vec<u8>,
    values: Vec<Option<i64>>,
    op: u16,
}

const CHARSET: u16 = 15;
const ENCODING: u16 = 16;
const CHARSTRINGS: u16 = 17;
const PRIVATE: u16 = 18;
const SUBRS: u16 = 19;
const FD_ARRAY: u16 = 1236;
const FD_SELECT: u16 = 1237;
/// The Private DICT's hinting values fontTools' `remove_hints` drops.
const HINT_KEYS: [u16; 14] = [6, 7, 8, 9, 10, 11, 1209, 1210, 1211, 1212, 1213, 1214, 1217, 1218];

fn read_dict(d: &[u8], what: &str) -> Result<Vec<Entry>> {
    let bad = || fail(format!("CFF: {what} DICT truncated"));
    let (mut entries, mut operands, mut values) = (vec![], vec![], vec![]);
    let mut i = 0;
    while i < d.len() {
        let b0 = d[i];
        let (len, value) = match b0 {
            28 => (3, Some(i16_at(d.get(i..i + 3).ok_or_else(bad)?, 1) as i64)),
            29 => {
                let b = d.get(i + 1..i + 5).ok_or_else(bad)?;
                (5, Some(i32::from_be_bytes([b[0], b[1], b[2], b[3]]) as i64))
            }
            30 => {
                let mut k = i + 1;
                loop {
                    let b = *d.get(k).ok_or_else(bad)?;
                    k += 1;
                    if b >> 4 == 0xf || b & 0xf == 0xf {
                        break;
                    }
                }
                (k - i, None)
            }
            32..=246 => (1, Some(b0 as i64 - 139)),
            247..=250 => (2, Some((b0 as i64 - 247) * 256 + *d.get(i + 1).ok_or_else(bad)? as i64 + 108)),
            251..=254 => (2, Some(-(b0 as i64 - 251) * 256 - *d.get(i + 1).ok_or_else(bad)? as i64 - 108)),
            12 => {
                let op = 1200 + *d.get(i + 1).ok_or_else(bad)? as u16;
                entries.push(Entry {
                    operands: std::mem::take(&mut operands),
                    values: std::mem::take(&mut values),
                    op,
                });
                i += 2;
                continue;
            }
            0..=21 => {
                entries.push(Entry {
                    operands: std::mem::take(&mut operands),
                    values: std::mem::take(&mut values),
                    op: b0 as u16,
                });
                i += 1;
                continue;
            }
            _ => return Err(fail(format!("CFF: {what} DICT: reserved byte {b0}"))),
        };
        operands.extend(&d[i..i + len]);
        values.push(value);
        i += len;
    }
    Ok(entries)
}

fn int5(out: &mut Vec<u8>, v: usize) {
    out.push(29);
    out.extend((v as i32).to_be_bytes());
}

fn push_op(out: &mut Vec<u8>, op: u16) {
    if op >= 1200 {
        out.extend([12, (op - 1200) as u8]);
    } else {
        out.push(op as u8);
    }
}

/// The entry's only (or `k`-th) integer operand.
fn value(e: &Entry, k: usize, what: &str) -> Result<usize> {
    e.values
        .get(k)
        .copied()
        .flatten()
        .and_then(|v| usize::try_from(v).ok())
        .ok_or_else(|| fail(format!("CFF: {what}: operator {} needs a non-negative integer operand", e.op)))
}

fn find(entries: &[Entry], op: u16) -> Option<&Entry> {
    entries.iter().find(|e| e.op == op)
}

/// A charstring after desubroutinizing: its bytes and its width operand, if it has one.
struct Flat {
    bytes: Vec<u8>,
    width: Option<Vec<u8>>,
}

struct Flattener<'a> {
    gsubrs: &'a [&'a [u8]],
    lsubrs: &'a [&'a [u8]],
    keep_hints: bool,
    gid: u32,
    out: Vec<u8>,
    /// The operands since the last operator: where each starts in `out`, its integer value.
    args: Vec<(usize, Option<i64>)>,
    stems: usize,
    cleared: bool,
    width: Option<Vec<u8>>,
    done: bool,
}

fn bias(count: usize) -> i64 {
    if count < 1240 {
        107
    } else if count < 33900 {
        1131
    } else {
        32768
    }
}

impl Flattener<'_> {
    fn fail(&self, what: &str) -> Error {
        fail(format!("glyph {}: charstring: {what}", self.gid))
    }

    /// At the first stack-clearing operator: an extra leading operand is the width.
    fn first_clear(&mut self, has_width: bool) {
        if !self.cleared {
            self.cleared = true;
            if has_width && !self.args.is_empty() {
                let end = self.args.get(1).map_or(self.out.len(), |a| a.0);
                self.width = Some(self.out[self.args[0].0..end].to_vec());
                self.args.remove(0);
            }
        }
    }

    fn run(&mut self, cs: &[u8], depth: usize) -> Result<()> {
        if depth > MAX_SUBR_DEPTH {
            return Err(self.fail("subroutines nested deeper than 10"));
        }
        let mut i = 0;
        while i < cs.len() && !self.done {
            if self.out.len() > MAX_CHARSTRING {
                return Err(self.fail("longer than 1 MiB without subroutines"));
            }
            let b0 = cs[i];
            let operand = match b0 {
                28 => Some((3, cs.get(i..i + 3).map(|b| i16_at(b, 1) as i64))),
                32..=246 => Some((1, Some(b0 as i64 - 139))),
                247..=250 => Some((2, cs.get(i + 1).map(|&b| (b0 as i64 - 247) * 256 + b as i64 + 108))),
                251..=254 => Some((2, cs.get(i + 1).map(|&b| -(b0 as i64 - 251) * 256 - b as i64 - 108))),
                255 => Some((5, cs.get(i + 1..i + 5).map(|b| i32::from_be_bytes([b[0], b[1], b[2], b[3]]) as i64))),
                _ => None,
            };
            if let Some((len, v)) = operand {
                let v = v.ok_or_else(|| self.fail("truncated operand"))?;
                // a 16.16 operand is an integer only when its fraction is zero
                let v = if b0 == 255 { (v & 0xffff == 0).then_some(v >> 16) } else { Some(v) };
                self.args.push((self.out.len(), v));
                self.out.extend(&cs[i..i + len]);
                i += len;
                continue;
            }
            match b0 {
                10 | 29 => {
                    let (at, v) = self.args.pop().ok_or_else(|| self.fail("subroutine call without a number"))?;
                    let v = v.ok_or_else(|| self.fail("subroutine number is not an integer"))?;
                    self.out.truncate(at);
                    let subrs = if b0 == 10 { self.lsubrs } else { self.gsubrs };
                    let k = usize::try_from(v + bias(subrs.len()))
                        .ok()
                        .filter(|k| *k < subrs.len())
                        .ok_or_else(|| self.fail(&format!("no subroutine {v}")))?;
                    self.run(subrs[k], depth + 1)?;
                    i += 1;
                }
                11 => return Ok(()),
                14 => {
                    let n = self.args.len();
                    self.first_clear(n == 1 || n == 5);
                    self.out.push(14);
                    self.args.clear();
                    self.done = true;
                }
                1 | 3 | 18 | 23 | 19 | 20 => {
                    self.first_clear(self.args.len() % 2 == 1);
                    self.stems += self.args.len() / 2;
                    let mut op_len = 1;
                    if b0 == 19 || b0 == 20 {
                        op_len += self.stems.div_ceil(8);
                        if i + op_len > cs.len() {
                            return Err(self.fail("truncated hint mask"));
                        }
                    }
                    if self.keep_hints {
                        self.out.extend(&cs[i..i + op_len]);
                    } else {
                        // the operands go; a width before them stays, for the next operator
                        let from = self.args.first().map_or(self.out.len(), |a| a.0);
                        self.out.truncate(from);
                    }
                    self.args.clear();
                    i += op_len;
                }
                12 => {
                    let b1 = *cs.get(i + 1).ok_or_else(|| self.fail("truncated operator"))?;
                    if !(34..=37).contains(&b1) && b1 != 0 {
                        return Err(self.fail(&format!("operator 12 {b1} (arithmetic) is not supported")));
                    }
                    self.out.extend(&cs[i..i + 2]);
                    self.args.clear();
                    i += 2;
                }
                _ => {
                    match b0 {
                        21 => self.first_clear(self.args.len() == 3),
                        4 | 22 => self.first_clear(self.args.len() == 2),
                        _ => self.cleared = true,
                    }
                    self.out.push(b0);
                    self.args.clear();
                    i += 1;
                }
            }
        }
        Ok(())
    }
}

fn flatten(cs: &[u8], gsubrs: &[&[u8]], lsubrs: &[&[u8]], keep_hints: bool, gid: u32) -> Result<Flat> {
    let mut f = Flattener {
        gsubrs,
        lsubrs,
        keep_hints,
        gid,
        out: Vec::with_capacity(cs.len()),
        args: vec![],
        stems: 0,
        cleared: false,
        width: None,
        done: false,
    };
    f.run(cs, 0)?;
    Ok(Flat { bytes: f.out, width: f.width })
}

/// A Type 2 integer operand in its shortest encoding.
fn push_int(out: &mut Vec<u8>, v: i32, gid: u32) -> Result<()> {
    match v {
        -107..=107 => out.push((v + 139) as u8),
        108..=1131 => {
            let w = v - 108;
            out.extend([(247 + (w >> 8)) as u8, (w & 0xff) as u8]);
        }
        -1131..=-108 => {
            let w = -v - 108;
            out.extend([(251 + (w >> 8)) as u8, (w & 0xff) as u8]);
        }
        _ => {
            let w = i16::try_from(v)
                .map_err(|_| fail(format!("glyph {gid}: a step of {v} units does not fit a charstring operand")))?;
            out.push(28);
            out.extend(w.to_be_bytes());
        }
    }
    Ok(())
}

/// The charstring of grid contours (cubic flavour: two control points between on-curve
/// points), with `width` (an operand's bytes) in front.
pub(super) fn encode_charstring(width: Option<&[u8]>, contours: &[GridContour], gid: u32) -> Result<Vec<u8>> {
    let mut out = width.map(<[u8]>::to_vec).unwrap_or_default();
    let (mut cx, mut cy) = (0i32, 0i32);
    let mut rel = |out: &mut Vec<u8>, x: i32, y: i32| -> Result<()> {
        push_int(out, x - cx, gid)?;
        push_int(out, y - cy, gid)?;
        (cx, cy) = (x, y);
        Ok(())
    };
    for c in contours.iter().filter(|c| !c.points.is_empty()) {
        let p = &c.points;
        rel(&mut out, p[0].x, p[0].y)?;
        out.push(21); // rmoveto
        let mut k = 1;
        while k < p.len() {
            if p[k].on_curve {
                rel(&mut out, p[k].x, p[k].y)?;
                out.push(5); // rlineto
                k += 1;
            } else {
                let end = p.get(k + 2).unwrap_or(&p[0]);
                let c2 = p
                    .get(k + 1)
                    .ok_or_else(|| fail(format!("glyph {gid}: a cubic without its second control point")))?;
                rel(&mut out, p[k].x, p[k].y)?;
                rel(&mut out, c2.x, c2.y)?;
                rel(&mut out, end.x, end.y)?;
                out.push(8); // rrcurveto
                k += 3;
            }
        }
    }
    out.push(14); // endchar
    Ok(out)
}

/// The length of a charset (formats 0, 1, 2) for `n` glyphs.
fn charset_len(cff: &[u8], at: usize, n: usize) -> Result<usize> {
    let bad = || fail("CFF: charset runs past the end of the table".into());
    let format = *cff.get(at).ok_or_else(bad)?;
    let need = n.saturating_sub(1);
    match format {
        0 => Ok(1 + 2 * need),
        1 | 2 => {
            let (mut covered, mut k) = (0usize, at + 1);
            let step = if format == 1 { 3 } else { 4 };
            while covered < need {
                let r = cff.get(k..k + step).ok_or_else(bad)?;
                covered += 1 + if format == 1 { r[2] as usize } else { u16_at(r, 2) as usize };
                k += step;
            }
            Ok(k - at)
        }
        f => Err(fail(format!("CFF: charset format {f}"))),
    }
}

fn encoding_len(cff: &[u8], at: usize) -> Result<usize> {
    let bad = || fail("CFF: Encoding runs past the end of the table".into());
    let format = *cff.get(at).ok_or_else(bad)?;
    let n = *cff.get(at + 1).ok_or_else(bad)? as usize;
    let mut len = match format & 0x7f {
        0 => 2 + n,
        1 => 2 + 2 * n,
        f => return Err(fail(format!("CFF: Encoding format {f}"))),
    };
    if format & 0x80 != 0 {
        len += 1 + 3 * *cff.get(at + len).ok_or_else(bad)? as usize;
    }
    cff.get(at..at + len).ok_or_else(bad)?;
    Ok(len)
}

/// The FDSelect's length and each glyph's Font DICT.
fn fd_select(cff: &[u8], at: usize, n: usize) -> Result<(usize, Vec<usize>)> {
    let bad = || fail("CFF: FDSelect runs past the end of the table".into());
    match *cff.get(at).ok_or_else(bad)? {
        0 => Ok((1 + n, cff.get(at + 1..at + 1 + n).ok_or_else(bad)?.iter().map(|&f| f as usize).collect())),
        3 => {
            let ranges = u16_at(cff.get(at + 1..at + 3).ok_or_else(bad)?, 0) as usize;
            let len = 1 + 2 + 3 * ranges + 2;
            let d = cff.get(at..at + len).ok_or_else(bad)?;
            let mut fds = vec![0; n];
            for r in 0..ranges {
                let first = u16_at(d, 3 + 3 * r) as usize;
                let next = u16_at(d, 3 + 3 * (r + 1)) as usize;
                let fd = d[5 + 3 * r] as usize;
                for g in first..next.min(n) {
                    fds[g] = fd;
                }
            }
            Ok((len, fds))
        }
        f => Err(fail(format!("CFF: FDSelect format {f}"))),
    }
}

/// A Private DICT: its entries and its local subroutines.
struct Private<'a> {
    entries: Vec<Entry>,
    subrs: Vec<&'a [u8]>,
}

fn read_private<'a>(cff: &'a [u8], e: &Entry) -> Result<Private<'a>> {
    let (size, at) = (value(e, 0, "Private")?, value(e, 1, "Private")?);
    let d = at.checked_add(size).and_then(|end| cff.get(at..end));
    let d = d.ok_or_else(|| fail("CFF: Private DICT runs past the end of the table".into()))?;
    let entries = read_dict(d, "Private")?;
    let subrs = match find(&entries, SUBRS) {
        Some(s) => read_index(cff, at + value(s, 0, "Subrs")?, "Subrs")?.items,
        None => vec![],
    };
    Ok(Private { entries, subrs })
}

fn private_bytes(p: &Private<'_>, keep_hints: bool) -> Vec<u8> {
    let mut out = vec![];
    for e in &p.entries {
        if e.op == SUBRS || (!keep_hints && HINT_KEYS.contains(&e.op)) {
            continue;
        }
        out.extend(&e.operands);
        push_op(&mut out, e.op);
    }
    out
}

/// The rebuilt `CFF ` table (see the module documentation).
fn rebuild(cff: &[u8], num_glyphs: usize, written: &Written) -> Result<Vec<u8>> {
    let hdr_size = *cff.get(2).ok_or_else(|| fail("CFF: header truncated".into()))? as usize;
    let names = read_index(cff, hdr_size, "Name")?;
    let top = read_index(cff, names.end, "Top DICT")?;
    if top.items.len() != 1 {
        return Err(fail(format!("CFF: {} fonts in one table (OpenType allows one)", top.items.len())));
    }
    let strings = read_index(cff, top.end, "String")?;
    let gsubrs = read_index(cff, strings.end, "Global Subr")?;
    let top_dict = read_dict(top.items[0], "Top")?;
    let charstrings_entry = find(&top_dict, CHARSTRINGS).ok_or_else(|| fail("CFF: no CharStrings".into()))?;
    let charstrings = read_index(cff, value(charstrings_entry, 0, "CharStrings")?, "CharStrings")?;
    if charstrings.items.len() != num_glyphs {
        return Err(fail(format!("CFF: {} charstrings for {num_glyphs} glyphs", charstrings.items.len())));
    }
    // the pieces copied as they are
    let copied = |op: u16, predefined: usize, len: &dyn Fn(usize) -> Result<usize>| -> Result<Option<&[u8]>> {
        match find(&top_dict, op) {
            Some(e) if value(e, 0, "Top")? > predefined => {
                let at = value(e, 0, "Top")?;
                Ok(Some(&cff[at..at + len(at)?]))
            }
            _ => Ok(None),
        }
    };
    let charset = copied(CHARSET, 2, &|at| charset_len(cff, at, num_glyphs))?;
    let encoding = copied(ENCODING, 1, &|at| encoding_len(cff, at))?;
    let (fd_select_bytes, fds) = match find(&top_dict, FD_SELECT) {
        Some(e) => {
            let at = value(e, 0, "FDSelect")?;
            let (len, fds) = fd_select(cff, at, num_glyphs)?;
            (Some(&cff[at..at + len]), fds)
        }
        None => (None, vec![0; num_glyphs]),
    };
    // the Private DICTs: the Top DICT's, or one per Font DICT
    let font_dicts: Option<Vec<Vec<Entry>>> = match find(&top_dict, FD_ARRAY) {
        Some(e) => Some(
            read_index(cff, value(e, 0, "FDArray")?, "FDArray")?
                .items
                .iter()
                .map(|d| read_dict(d, "Font"))
                .collect::<Result<_>>()?,
        ),
        None => None,
    };
    let privates: Vec<Private<'_>> = match &font_dicts {
        Some(dicts) => dicts
            .iter()
            .map(|d| match find(d, PRIVATE) {
                Some(p) => read_private(cff, p),
                None => Ok(Private { entries: vec![], subrs: vec![] }),
            })
            .collect::<Result<_>>()?,
        None => match find(&top_dict, PRIVATE) {
            Some(p) => vec![read_private(cff, p)?],
            None => vec![Private { entries: vec![], subrs: vec![] }],
        },
    };
    // the charstrings
    let mut new_charstrings: Vec<Vec<u8>> = Vec::with_capacity(num_glyphs);
    for (gid, cs) in charstrings.items.iter().enumerate() {
        let fd = fds[gid];
        let private = privates.get(fd).ok_or_else(|| fail(format!("glyph {gid}: no Font DICT {fd}")))?;
        let flat = flatten(cs, &gsubrs.items, &private.subrs, written.keep_hinting, gid as u32)?;
        let bytes = match written.changed.get(&(gid as u32)) {
            Some(contours) => encode_charstring(flat.width.as_deref(), contours, gid as u32)?,
            // unchanged drawing: its own bytes when flattening changed nothing
            None if cs.starts_with(&flat.bytes) => cs.to_vec(),
            None => flat.bytes,
        };
        new_charstrings.push(bytes);
    }
    let new_charstrings = write_index(&new_charstrings);
    let private_blobs: Vec<Vec<u8>> = privates.iter().map(|p| private_bytes(p, written.keep_hinting)).collect();
    // the layout: header, Name, Top DICT, String, (empty) Global Subr, charset, Encoding,
    // FDSelect, CharStrings, FDArray, Private DICTs
    let top_bytes = |at: &Layout| -> Vec<u8> {
        let mut d = vec![];
        for e in &top_dict {
            match e.op {
                CHARSET if charset.is_some() => int5(&mut d, at.charset),
                ENCODING if encoding.is_some() => int5(&mut d, at.encoding),
                CHARSTRINGS => int5(&mut d, at.charstrings),
                FD_SELECT => int5(&mut d, at.fd_select),
                FD_ARRAY => int5(&mut d, at.fd_array),
                PRIVATE => {
                    int5(&mut d, private_blobs[0].len());
                    int5(&mut d, at.privates[0]);
                }
                _ => d.extend(&e.operands),
            }
            push_op(&mut d, e.op);
        }
        d
    };
    let fd_array_bytes = |at: &Layout| -> Option<Vec<u8>> {
        let dicts = font_dicts.as_ref()?;
        let items: Vec<Vec<u8>> = dicts
            .iter()
            .enumerate()
            .map(|(k, d)| {
                let mut b = vec![];
                for e in d {
                    if e.op == PRIVATE {
                        int5(&mut b, private_blobs[k].len());
                        int5(&mut b, at.privates[k]);
                    } else {
                        b.extend(&e.operands);
                    }
                    push_op(&mut b, e.op);
                }
                b
            })
            .collect();
        Some(write_index(&items))
    };
    let empty_index = write_index::<&[u8]>(&[]);
    let head_len = hdr_size + (names.end - hdr_size);
    let mut at = Layout { privates: vec![0; private_blobs.len()], ..Layout::default() };
    // two passes: the sizes do not depend on the offsets (5-byte integers)
    for _ in 0..2 {
        let mut pos = head_len + write_index(&[top_bytes(&at)]).len();
        pos += strings.end - top.end + empty_index.len();
        at.charset = pos;
        pos += charset.map_or(0, <[u8]>::len);
        at.encoding = pos;
        pos += encoding.map_or(0, <[u8]>::len);
        at.fd_select = pos;
        pos += fd_select_bytes.map_or(0, <[u8]>::len);
        at.charstrings = pos;
        pos += new_charstrings.len();
        at.fd_array = pos;
        pos += fd_array_bytes(&at).map_or(0, |b| b.len());
        for (k, p) in private_blobs.iter().enumerate() {
            at.privates[k] = pos;
            pos += p.len();
        }
    }
    let mut out = cff[..names.end].to_vec();
    out.extend(write_index(&[top_bytes(&at)]));
    out.extend(&cff[top.end..strings.end]);
    out.extend(&empty_index);
    for piece in [charset, encoding, fd_select_bytes].into_iter().flatten() {
        out.extend(piece);
    }
    out.extend(&new_charstrings);
    if let Some(b) = fd_array_bytes(&at) {
        out.extend(b);
    }
    for p in &private_blobs {
        out.extend(p);
    }
    Ok(out)
}

#[derive(Default)]
struct Layout {
    charset: usize,
    encoding: usize,
    fd_select: usize,
    charstrings: usize,
    fd_array: usize,
    privates: Vec<usize>,
}

/// The rewritten CFF font (see the module documentation).
pub(super) fn write(tables: &Tables<'_>, num_glyphs: usize, written: &Written) -> Result<Vec<u8>> {
    let cff = tables.need(b"CFF ", 4)?;
    let new_cff = if written.changed.is_empty() { cff.to_vec() } else { rebuild(cff, num_glyphs, written)? };
    let mut head = tables.need(b"head", 54)?.to_vec();
    let points = written.changed.values().flatten().flat_map(|c| &c.points);
    let mut b = [i16_at(&head, 36), i16_at(&head, 38), i16_at(&head, 40), i16_at(&head, 42)].map(|v| v as i32);
    for p in points {
        b = [b[0].min(p.x), b[1].min(p.y), b[2].max(p.x), b[3].max(p.y)];
    }
    for (k, v) in b.iter().enumerate() {
        let v = (*v).clamp(i16::MIN as i32, i16::MAX as i32) as i16;
        head[36 + 2 * k..38 + 2 * k].copy_from_slice(&v.to_be_bytes());
    }
    let out = tables
        .tables
        .iter()
        .map(|(tag, data)| {
            let new = match tag {
                b"CFF " => new_cff.clone(),
                b"head" => head.clone(),
                _ => data.to_vec(),
            };
            (*tag, new)
        })
        .collect();
    Ok(assemble(tables.version, out))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn subroutines_are_inlined_and_hints_dropped_with_the_width_kept() {
        // width 10 (first operand of hstem), a stem, then a call to local subr 0 (bias 107)
        // holding "0 0 rmoveto", then a line and endchar
        let lsubr: &[u8] = &[139, 139, 21, 11];
        let cs = [149, 139, 189, 1, 32, 10, 189, 139, 5, 14];
        let kept = flatten(&cs, &[], &[lsubr], true, 0).unwrap();
        assert_eq!(kept.width, Some(vec![149]));
        assert_eq!(kept.bytes, [149, 139, 189, 1, 139, 139, 21, 189, 139, 5, 14]);
        let dropped = flatten(&cs, &[], &[lsubr], false, 0).unwrap();
        assert_eq!(dropped.bytes, [149, 139, 139, 21, 189, 139, 5, 14]);
    }

    #[test]
    fn hint_masks_take_their_bytes_by_the_stem_count() {
        // 9 stems (one implicit before the hintmask): a mask of two bytes
        let mut cs = vec![];
        for _ in 0..8 {
            cs.extend([139, 140]);
        }
        cs.push(18); // hstemhm, 8 stems
        cs.extend([139, 140, 19, 0xff, 0x80, 139, 139, 21, 14]);
        let f = flatten(&cs, &[], &[], false, 0).unwrap();
        assert_eq!(f.bytes, [139, 139, 21, 14]);
        assert_eq!(f.width, None);
    }

    #[test]
    fn index_round_trips() {
        let items: Vec<&[u8]> = vec![b"a", b"", b"xyz"];
        let bytes = write_index(&items);
        let back = read_index(&bytes, 0, "test").unwrap();
        assert_eq!(back.items, items);
        assert_eq!(back.end, bytes.len());
    }
}
