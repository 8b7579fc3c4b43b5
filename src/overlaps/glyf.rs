//! TrueType (`glyf`) fonts rewritten at the byte level.
//!
//! Why by hand and not with `write-fonts`: a glyph that is not rewritten must keep its bytes
//! (the encoder's choice of flag repeats and coordinate sizes, its padding), and only the few
//! tables overlap removal changes are rebuilt, so the writer copies every glyph's `loca` range
//! as it is, encodes the rewritten glyphs itself (a simple glyph: contour ends, no
//! instructions, flags with repeats, short and same-as-previous coordinates), and patches the
//! fields of `head`, `hhea`, `hmtx` and `maxp` that depend on the outlines, as fontTools
//! recomputes them when it saves a font:
//!
//! * `glyf`/`loca`: glyph records in glyph order; `loca` short (offsets/2) when every offset is
//!   even and below 2¹⁷, else long; `head.indexToLocFormat` set to match.
//! * instructions: a rewritten glyph has none; every other glyph considered loses its own
//!   unless `keep_hinting` (fontTools' `removeHinting`: the instruction bytes spliced out, the
//!   composite's `WE_HAVE_INSTRUCTIONS` flags cleared); `fpgm`, `prep`, `cvt ` are copied.
//! * a rewritten glyph's box is that of its points; its `hmtx` left side bearing becomes its
//!   `xMin`. A composite that is not rewritten but uses a rewritten glyph keeps its bytes
//!   except its box, recomputed from its composed points when it changed.
//! * `head`: the union of the boxes of the glyphs with outlines, and bit 1 of `flags` (every
//!   left side bearing is the glyph's `xMin`); `maxp`: `maxPoints`, `maxContours`,
//!   `maxCompositePoints`, `maxCompositeContours`, `maxComponentElements`,
//!   `maxComponentDepth`; `hhea`: `advanceWidthMax`, `minLeftSideBearing`,
//!   `minRightSideBearing`, `xMaxExtent`.

use super::sfnt::{Tables, assemble, i16_at, u16_at, u32_at};
use super::{GridContour, GridPoint, Written};
use crate::error::{Error, Result};
use crate::format::Font;
use std::collections::BTreeMap;

fn fail(message: String) -> Error {
    Error::InvalidArgument { message }
}

const ON_CURVE: u8 = 0x01;
const X_SHORT: u8 = 0x02;
const Y_SHORT: u8 = 0x04;
const REPEAT: u8 = 0x08;
const X_SAME_OR_POSITIVE: u8 = 0x10;
const Y_SAME_OR_POSITIVE: u8 = 0x20;

const ARG_1_AND_2_ARE_WORDS: u16 = 0x0001;
const WE_HAVE_A_SCALE: u16 = 0x0008;
const MORE_COMPONENTS: u16 = 0x0020;
const WE_HAVE_AN_X_AND_Y_SCALE: u16 = 0x0040;
const WE_HAVE_A_TWO_BY_TWO: u16 = 0x0080;
const WE_HAVE_INSTRUCTIONS: u16 = 0x0100;

/// Deepest composite nesting followed when counting `maxp`'s composite values.
const MAX_DEPTH: usize = crate::format::font::MAX_COMPONENT_DEPTH;

/// The box of integer points, `[x_min, y_min, x_max, y_max]`.
fn points_box(points: &[(i16, i16, bool)]) -> Option<[i16; 4]> {
    points.iter().fold(None, |b, &(x, y, _)| {
        Some(match b {
            None => [x, y, x, y],
            Some([a, c, d, e]) => [a.min(x), c.min(y), d.max(x), e.max(y)],
        })
    })
}

/// The `glyf` record of a simple glyph with these contours (no instructions), and its box.
///
/// # Errors
/// A coordinate outside `i16` or more than 65,535 points.
pub(super) fn encode_simple(contours: &[GridContour], gid: u32) -> Result<(Vec<u8>, Option<[i16; 4]>)> {
    let mut points: Vec<(i16, i16, bool)> = vec![];
    let mut ends: Vec<u16> = vec![];
    for c in contours.iter().filter(|c| !c.points.is_empty()) {
        for p in &c.points {
            let (Ok(x), Ok(y)) = (i16::try_from(p.x), i16::try_from(p.y)) else {
                return Err(fail(format!("glyph {gid}: point ({}, {}) outside the 16-bit range of glyf", p.x, p.y)));
            };
            points.push((x, y, p.on_curve));
        }
        let end = u16::try_from(points.len() - 1)
            .map_err(|_| fail(format!("glyph {gid}: more than 65,535 points in one glyph")))?;
        ends.push(end);
    }
    if points.is_empty() {
        return Ok((vec![], None));
    }
    let n_contours = i16::try_from(ends.len()).map_err(|_| fail(format!("glyph {gid}: more than 32,767 contours")))?;
    let bbox = points_box(&points).expect("points");
    let mut out = vec![];
    out.extend(n_contours.to_be_bytes());
    for v in bbox {
        out.extend(v.to_be_bytes());
    }
    for e in &ends {
        out.extend(e.to_be_bytes());
    }
    out.extend([0, 0]); // no instructions
    let (mut flags, mut xs, mut ys) = (vec![], vec![], vec![]);
    let (mut px, mut py) = (0i32, 0i32);
    for &(x, y, on) in &points {
        let mut f = if on { ON_CURVE } else { 0 };
        let (dx, dy) = (x as i32 - px, y as i32 - py);
        (px, py) = (x as i32, y as i32);
        for (d, short, same, bytes) in
            [(dx, X_SHORT, X_SAME_OR_POSITIVE, &mut xs), (dy, Y_SHORT, Y_SAME_OR_POSITIVE, &mut ys)]
        {
            if d == 0 {
                f |= same;
            } else if d.abs() <= 255 {
                f |= short;
                if d > 0 {
                    f |= same;
                }
                bytes.push(d.unsigned_abs() as u8);
            } else {
                // a difference of two i16 fits i16 only when it does: glyf stores it as i16
                let d16 = i16::try_from(d)
                    .map_err(|_| fail(format!("glyph {gid}: a step of {d} units between points does not fit glyf")))?;
                bytes.extend(d16.to_be_bytes());
            }
        }
        flags.push(f);
    }
    // runs of equal flags: the flag with REPEAT and the count of further copies
    let mut k = 0;
    while k < flags.len() {
        let mut run = 1;
        while k + run < flags.len() && flags[k + run] == flags[k] && run < 256 {
            run += 1;
        }
        if run >= 3 {
            out.push(flags[k] | REPEAT);
            out.push((run - 1) as u8);
        } else {
            out.extend(std::iter::repeat_n(flags[k], run));
        }
        k += run;
    }
    out.extend(xs);
    out.extend(ys);
    if out.len() % 2 == 1 {
        out.push(0);
    }
    Ok((out, Some(bbox)))
}

/// A glyph record without its instructions: `None` when it has none (then its bytes stay).
fn without_instructions(g: &[u8], gid: u32) -> Result<Option<Vec<u8>>> {
    let bad = || fail(format!("glyph {gid}: glyf record truncated"));
    if g.len() < 10 {
        return Ok(None);
    }
    let n = i16_at(g, 0);
    if n > 0 {
        let at = 10 + 2 * n as usize;
        let len = u16_at(g.get(at..at + 2).ok_or_else(bad)?, 0) as usize;
        if len == 0 {
            return Ok(None);
        }
        let rest = g.get(at + 2 + len..).ok_or_else(bad)?;
        // the flags and coordinates, without the record's padding (fontTools' `trim`)
        let points = u16_at(g, at - 2) as usize + 1;
        let (mut k, mut seen, mut coords) = (0usize, 0usize, 0usize);
        while seen < points {
            let f = *rest.get(k).ok_or_else(bad)?;
            k += 1;
            let mut repeat = 1;
            if f & REPEAT != 0 {
                repeat += *rest.get(k).ok_or_else(bad)? as usize;
                k += 1;
            }
            let x = if f & X_SHORT != 0 {
                1
            } else if f & X_SAME_OR_POSITIVE != 0 {
                0
            } else {
                2
            };
            let y = if f & Y_SHORT != 0 {
                1
            } else if f & Y_SAME_OR_POSITIVE != 0 {
                0
            } else {
                2
            };
            coords += (x + y) * repeat;
            seen += repeat;
        }
        let rest = rest.get(..k + coords).ok_or_else(bad)?;
        let mut out = g[..at].to_vec();
        out.extend([0, 0]);
        out.extend(rest);
        if out.len() % 2 == 1 {
            out.push(0);
        }
        return Ok(Some(out));
    }
    if n < 0 {
        let (mut at, mut any) = (10usize, false);
        let mut flag_positions = vec![];
        loop {
            let flags = u16_at(g.get(at..at + 4).ok_or_else(bad)?, 0);
            flag_positions.push(at);
            any |= flags & WE_HAVE_INSTRUCTIONS != 0;
            at += 4 + if flags & ARG_1_AND_2_ARE_WORDS != 0 { 4 } else { 2 };
            at += if flags & WE_HAVE_A_SCALE != 0 {
                2
            } else if flags & WE_HAVE_AN_X_AND_Y_SCALE != 0 {
                4
            } else if flags & WE_HAVE_A_TWO_BY_TWO != 0 {
                8
            } else {
                0
            };
            if flags & MORE_COMPONENTS == 0 {
                break;
            }
        }
        if !any {
            return Ok(None);
        }
        let mut out = g.get(..at).ok_or_else(bad)?.to_vec();
        for p in flag_positions {
            let f = u16_at(&out, p) & !WE_HAVE_INSTRUCTIONS;
            out[p..p + 2].copy_from_slice(&f.to_be_bytes());
        }
        if out.len() % 2 == 1 {
            out.push(0);
        }
        return Ok(Some(out));
    }
    Ok(None)
}

/// The components (glyph ids) of a composite record.
fn components(g: &[u8], gid: u32) -> Result<Vec<u32>> {
    let bad = || fail(format!("glyph {gid}: composite record truncated"));
    let mut at = 10usize;
    let mut out = vec![];
    loop {
        let r = g.get(at..at + 4).ok_or_else(bad)?;
        let flags = u16_at(r, 0);
        out.push(u16_at(r, 2) as u32);
        at += 4 + if flags & ARG_1_AND_2_ARE_WORDS != 0 { 4 } else { 2 };
        at += if flags & WE_HAVE_A_SCALE != 0 {
            2
        } else if flags & WE_HAVE_AN_X_AND_Y_SCALE != 0 {
            4
        } else if flags & WE_HAVE_A_TWO_BY_TWO != 0 {
            8
        } else {
            0
        };
        if flags & MORE_COMPONENTS == 0 {
            return Ok(out);
        }
    }
}

/// fontTools' `maxp` values of the written glyphs.
#[derive(Default)]
struct MaxpValues {
    points: u16,
    contours: u16,
    composite_points: u16,
    composite_contours: u16,
    component_elements: u16,
    component_depth: u16,
}

/// `(points, contours, depth)` of a composite, flattened (fontTools' `getCompositeMaxpValues`:
/// a composite of simple glyphs has depth 1).
fn composite_values(
    glyphs: &[Vec<u8>],
    gid: u32,
    depth: usize,
    memo: &mut BTreeMap<u32, (u64, u64, usize)>,
) -> Result<(u64, u64, usize)> {
    if let Some(v) = memo.get(&gid) {
        return Ok(*v);
    }
    if depth > MAX_DEPTH {
        return Err(fail(format!("glyph {gid}: composite nesting deeper than {MAX_DEPTH} (or cyclic)")));
    }
    let (mut points, mut contours, mut deepest) = (0u64, 0u64, 1usize);
    for c in components(&glyphs[gid as usize], gid)? {
        let g = glyphs.get(c as usize).ok_or_else(|| fail(format!("glyph {gid}: component {c} beyond the font")))?;
        if g.len() < 10 {
            continue;
        }
        let n = i16_at(g, 0);
        if n > 0 {
            points += u16_at(g, 10 + 2 * (n as usize - 1)) as u64 + 1;
            contours += n as u64;
        } else if n < 0 {
            let (p, k, d) = composite_values(glyphs, c, depth + 1, memo)?;
            points += p;
            contours += k;
            deepest = deepest.max(d + 1);
        }
    }
    memo.insert(gid, (points, contours, deepest));
    Ok((points, contours, deepest))
}

fn maxp_values(glyphs: &[Vec<u8>]) -> Result<MaxpValues> {
    let mut v = MaxpValues::default();
    let mut memo = BTreeMap::new();
    let clamp = |x: u64| x.min(u16::MAX as u64) as u16;
    for (gid, g) in glyphs.iter().enumerate() {
        if g.len() < 10 {
            continue;
        }
        let n = i16_at(g, 0);
        if n > 0 {
            let at = 10 + 2 * (n as usize - 1);
            let last = g.get(at..at + 2).ok_or_else(|| fail(format!("glyph {gid}: glyf record truncated")))?;
            v.points = v.points.max(clamp(u16_at(last, 0) as u64 + 1));
            v.contours = v.contours.max(n as u16);
        } else if n < 0 {
            let (p, k, d) = composite_values(glyphs, gid as u32, 0, &mut memo)?;
            v.composite_points = v.composite_points.max(clamp(p));
            v.composite_contours = v.composite_contours.max(clamp(k));
            v.component_elements = v.component_elements.max(clamp(components(g, gid as u32)?.len() as u64));
            v.component_depth = v.component_depth.max(clamp(d as u64));
        }
    }
    Ok(v)
}

/// The glyph records as `loca` delimits them.
fn glyph_records<'a>(tables: &Tables<'a>, num_glyphs: usize) -> Result<Vec<&'a [u8]>> {
    let head = tables.need(b"head", 54)?;
    let loca = tables.need(b"loca", 0)?;
    let glyf = tables.need(b"glyf", 0)?;
    let long = i16_at(head, 50) != 0;
    let need = (num_glyphs + 1) * if long { 4 } else { 2 };
    if loca.len() < need {
        return Err(fail(format!("loca has {} bytes, {need} needed for {num_glyphs} glyphs", loca.len())));
    }
    let offset = |k: usize| if long { u32_at(loca, 4 * k) as usize } else { 2 * u16_at(loca, 2 * k) as usize };
    (0..num_glyphs)
        .map(|g| {
            let (a, b) = (offset(g), offset(g + 1));
            if a > b || b > glyf.len() {
                return Err(fail(format!("glyph {g}: loca range {a}..{b} outside glyf ({} bytes)", glyf.len())));
            }
            Ok(&glyf[a..b])
        })
        .collect()
}

/// `(advance, lsb)` of every glyph from `hmtx`.
fn metrics(hmtx: &[u8], long_count: usize, num_glyphs: usize) -> Vec<(u16, i16)> {
    let mut last_advance = 0u16;
    (0..num_glyphs)
        .map(|g| {
            if g < long_count && hmtx.len() >= 4 * g + 4 {
                last_advance = u16_at(hmtx, 4 * g);
                (last_advance, i16_at(hmtx, 4 * g + 2))
            } else {
                let at = 4 * long_count + 2 * (g - long_count.min(g));
                (last_advance, if hmtx.len() >= at + 2 { i16_at(hmtx, at) } else { 0 })
            }
        })
        .collect()
}

/// The rewritten TrueType font (see the module documentation).
pub(super) fn write(tables: &Tables<'_>, num_glyphs: usize, written: &Written) -> Result<Vec<u8>> {
    let records = glyph_records(tables, num_glyphs)?;
    let long_count = u16_at(tables.need(b"hhea", 36)?, 34) as usize;
    let stored = metrics(tables.need(b"hmtx", 0)?, long_count, num_glyphs);
    let mut glyphs: Vec<Vec<u8>> = Vec::with_capacity(num_glyphs);
    let mut changed_box: BTreeMap<u32, Option<[i16; 4]>> = BTreeMap::new();
    for (gid, record) in records.iter().enumerate() {
        let gid = gid as u32;
        if let Some(contours) = written.changed.get(&gid) {
            // a simple glyph whose stored left side bearing is not its xMin is drawn shifted by
            // their difference (FreeType places the origin at xMin − lsb; fontTools' glyph set
            // draws so, and leaves composites as their components are stored): its rewrite
            // carries that shift, so it draws where it did (its lsb becomes its xMin below)
            let simple = record.len() >= 10 && i16_at(record, 0) >= 0;
            let shift = if simple { i32::from(stored[gid as usize].1) - i32::from(i16_at(record, 2)) } else { 0 };
            let contours: std::borrow::Cow<'_, [GridContour]> = if shift == 0 {
                contours.into()
            } else {
                let moved = |c: &GridContour| GridContour {
                    points: c.points.iter().map(|p| GridPoint { x: p.x + shift, ..*p }).collect(),
                };
                contours.iter().map(moved).collect::<Vec<_>>().into()
            };
            let (bytes, bbox) = encode_simple(&contours, gid)?;
            changed_box.insert(gid, bbox);
            glyphs.push(bytes);
        } else if written.strip_instructions(gid) {
            glyphs.push(without_instructions(record, gid)?.unwrap_or_else(|| record.to_vec()));
        } else {
            glyphs.push(record.to_vec());
        }
    }
    let build = |glyphs: &[Vec<u8>]| -> Result<Vec<u8>> { rebuild(tables, glyphs, &changed_box) };
    let mut font = build(&glyphs)?;
    // composites using a rewritten glyph: their box from the composed points
    let users = composites_using(&glyphs, &changed_box)?;
    if !users.is_empty() {
        let f = Font::open(&font, 0)?;
        let mut any = false;
        for gid in users {
            let (parts, lone) = f.outline_parts(gid)?;
            let mut bbox: Option<[num_rational::BigRational; 4]> = None;
            let pts = parts.iter().flatten().flat_map(|c| &c.segments).flat_map(|s| match s {
                crate::format::Segment::Bezier(ps) => ps.as_slice(),
                crate::format::Segment::Skipped { .. } => &[],
            });
            for p in pts.chain(lone.iter()) {
                let (x, y) = (&p.coords[0], &p.coords[1]);
                bbox = Some(match bbox {
                    None => [x.clone(), y.clone(), x.clone(), y.clone()],
                    Some([a, b, c, d]) => [a.min(x.clone()), b.min(y.clone()), c.max(x.clone()), d.max(y.clone())],
                });
            }
            let Some(bbox) = bbox else { continue };
            // fontTools rounds a composite's bounds half up (otRound)
            let half = num_rational::BigRational::new(1.into(), 2.into());
            let rounded = bbox.map(|v| {
                let r = (v + &half).floor().to_integer();
                let negative = r.sign() == num_bigint::Sign::Minus;
                i16::try_from(r).unwrap_or(if negative { i16::MIN } else { i16::MAX })
            });
            let g = &mut glyphs[gid as usize];
            let old = [i16_at(g, 2), i16_at(g, 4), i16_at(g, 6), i16_at(g, 8)];
            if old != rounded {
                for (k, v) in rounded.iter().enumerate() {
                    g[2 + 2 * k..4 + 2 * k].copy_from_slice(&v.to_be_bytes());
                }
                any = true;
            }
        }
        if any {
            font = build(&glyphs)?;
        }
    }
    Ok(font)
}

/// The composites (not rewritten) that use a rewritten glyph, directly or through others.
fn composites_using(glyphs: &[Vec<u8>], changed: &BTreeMap<u32, Option<[i16; 4]>>) -> Result<Vec<u32>> {
    let mut uses: BTreeMap<u32, Vec<u32>> = BTreeMap::new();
    for (gid, g) in glyphs.iter().enumerate() {
        if g.len() >= 10 && i16_at(g, 0) < 0 && !changed.contains_key(&(gid as u32)) {
            uses.insert(gid as u32, components(g, gid as u32)?);
        }
    }
    let mut affected: std::collections::BTreeSet<u32> = changed.keys().copied().collect();
    // a fixed point: each round adds the composites using an affected glyph (at most depth rounds)
    for _ in 0..=MAX_DEPTH {
        let before = affected.len();
        for (gid, comps) in &uses {
            if comps.iter().any(|c| affected.contains(c)) {
                affected.insert(*gid);
            }
        }
        if affected.len() == before {
            break;
        }
    }
    Ok(affected.into_iter().filter(|g| !changed.contains_key(g)).collect())
}

/// The font with these glyph records: `glyf`, `loca`, `head`, `hmtx`, `maxp`, `hhea` rebuilt.
fn rebuild(tables: &Tables<'_>, glyphs: &[Vec<u8>], changed: &BTreeMap<u32, Option<[i16; 4]>>) -> Result<Vec<u8>> {
    let num_glyphs = glyphs.len();
    let mut glyf = Vec::with_capacity(glyphs.iter().map(Vec::len).sum());
    let mut offsets = Vec::with_capacity(num_glyphs + 1);
    for g in glyphs {
        offsets.push(glyf.len());
        glyf.extend(g);
    }
    offsets.push(glyf.len());
    let short = glyf.len() < 0x20000 && offsets.iter().all(|o| o % 2 == 0);
    let loca: Vec<u8> = if short {
        offsets.iter().flat_map(|o| ((o / 2) as u16).to_be_bytes()).collect()
    } else {
        offsets
            .iter()
            .map(|&o| u32::try_from(o).map_err(|_| fail("glyf larger than 4 GiB".into())))
            .collect::<Result<Vec<u32>>>()?
            .into_iter()
            .flat_map(u32::to_be_bytes)
            .collect()
    };
    let mut head = tables.need(b"head", 54)?.to_vec();
    let hhea_in = tables.need(b"hhea", 36)?;
    let long_count = u16_at(hhea_in, 34) as usize;
    let mut hmtx = tables.need(b"hmtx", 0)?.to_vec();
    let mut m = metrics(&hmtx, long_count, num_glyphs);
    for (&gid, bbox) in changed {
        let g = gid as usize;
        let x_min = bbox.map_or(0, |b| b[0]);
        m[g].1 = x_min;
        let at = if g < long_count { 4 * g + 2 } else { 4 * long_count + 2 * (g - long_count) };
        if hmtx.len() >= at + 2 {
            hmtx[at..at + 2].copy_from_slice(&x_min.to_be_bytes());
        }
    }
    // head: the union of the boxes of glyphs with outlines; flags bit 1
    let mut union: Option<[i16; 4]> = None;
    let mut all_lsb_x_min = true;
    let (mut min_lsb, mut min_rsb, mut max_extent): (Option<i32>, Option<i32>, Option<i32>) = (None, None, None);
    for (g, rec) in glyphs.iter().enumerate() {
        if rec.len() < 10 || i16_at(rec, 0) == 0 {
            continue;
        }
        let b = [i16_at(rec, 2), i16_at(rec, 4), i16_at(rec, 6), i16_at(rec, 8)];
        union = Some(match union {
            None => b,
            Some(u) => [u[0].min(b[0]), u[1].min(b[1]), u[2].max(b[2]), u[3].max(b[3])],
        });
        let (advance, lsb) = m[g];
        all_lsb_x_min &= lsb == b[0];
        let width = b[2] as i32 - b[0] as i32;
        let (lsb, advance) = (lsb as i32, advance as i32);
        min_lsb = Some(min_lsb.map_or(lsb, |v| v.min(lsb)));
        min_rsb = Some(min_rsb.map_or(advance - lsb - width, |v| v.min(advance - lsb - width)));
        max_extent = Some(max_extent.map_or(lsb + width, |v| v.max(lsb + width)));
    }
    let u = union.unwrap_or([0; 4]);
    for (k, v) in u.iter().enumerate() {
        head[36 + 2 * k..38 + 2 * k].copy_from_slice(&v.to_be_bytes());
    }
    let flags = u16_at(&head, 16);
    let flags = if all_lsb_x_min { flags | 0x2 } else { flags & !0x2 };
    head[16..18].copy_from_slice(&flags.to_be_bytes());
    head[50..52].copy_from_slice(&(if short { 0i16 } else { 1 }).to_be_bytes());
    // hhea
    let mut hhea = hhea_in.to_vec();
    let advance_max = m.iter().take(long_count.max(1)).map(|x| x.0).max().unwrap_or(0);
    let sat = |v: i32| v.clamp(i16::MIN as i32, i16::MAX as i32) as i16;
    hhea[10..12].copy_from_slice(&advance_max.to_be_bytes());
    hhea[12..14].copy_from_slice(&sat(min_lsb.unwrap_or(0)).to_be_bytes());
    hhea[14..16].copy_from_slice(&sat(min_rsb.unwrap_or(0)).to_be_bytes());
    hhea[16..18].copy_from_slice(&sat(max_extent.unwrap_or(0)).to_be_bytes());
    // maxp (version 1.0 only carries the outline values)
    let mut maxp = tables.need(b"maxp", 6)?.to_vec();
    if u32_at(&maxp, 0) == 0x0001_0000 && maxp.len() >= 32 {
        let v = maxp_values(glyphs)?;
        for (at, value) in [
            (6, v.points),
            (8, v.contours),
            (10, v.composite_points),
            (12, v.composite_contours),
            (28, v.component_elements),
            (30, v.component_depth),
        ] {
            maxp[at..at + 2].copy_from_slice(&value.to_be_bytes());
        }
    }
    let mut out: Vec<([u8; 4], Vec<u8>)> = vec![];
    for (tag, data) in &tables.tables {
        let new = match tag {
            b"glyf" => std::mem::take(&mut glyf),
            b"loca" => loca.clone(),
            b"head" => head.clone(),
            b"hhea" => hhea.clone(),
            b"hmtx" => hmtx.clone(),
            b"maxp" => maxp.clone(),
            _ => data.to_vec(),
        };
        out.push((*tag, new));
    }
    Ok(assemble(tables.version, out))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::overlaps::GridPoint;

    fn p(x: i32, y: i32, on_curve: bool) -> GridPoint {
        GridPoint { x, y, on_curve }
    }

    #[test]
    fn simple_glyph_encoding_uses_short_and_repeated_forms() {
        let c = GridContour { points: vec![p(0, 0, true), p(0, 700, true), p(300, 700, false), p(600, 700, true)] };
        let (bytes, bbox) = encode_simple(&[c], 1).unwrap();
        assert_eq!(bbox, Some([0, 0, 600, 700]));
        // 1 contour, box, end point 3, no instructions
        assert_eq!(&bytes[..14], &[0, 1, 0, 0, 0, 0, 2, 88, 2, 188, 0, 3, 0, 0]);
        // flags: (0,0) same/same on; (0,700) x same, y word on; (300,700) x word, y same off; (600,700) same
        assert_eq!(&bytes[14..18], &[0x31, 0x11, 0x20, 0x21]);
    }

    #[test]
    fn instructions_are_spliced_out_of_simple_glyphs() {
        // one contour of one point, three instruction bytes
        let g = [0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 3, 0xb0, 1, 2, 0x31];
        let out = without_instructions(&g, 0).unwrap().unwrap();
        assert_eq!(out, [0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0x31, 0]);
        // a glyph without instructions keeps its bytes
        assert_eq!(without_instructions(&out, 0).unwrap(), None);
    }
}
