//! Overlap removal decided for every glyph of a font, with the time it takes: how many glyphs
//! stay unchanged, how many are rewritten (certified), how many could not be certified.
//!
//! ```sh
//! cargo run --release --example decide_glyphs -- /usr/share/fonts/truetype/dejavu/DejaVuSans.ttf
//! ```
//!
//! Composite `glyf` glyphs are given as their components (each placed by its offset and 2×2
//! matrix, exactly), so that a composite is rewritten only when its components overlap. The
//! command line's `remove-overlaps` writes the font; this only decides.

use casteljau::format::{Affine, Contour, Font};
use casteljau::overlaps::{Flavour, GlyphDecision, GlyphInput, decide_glyph};
use casteljau::work::Budget;
use casteljau::{Point, rat};
use num_rational::BigRational;
use read_fonts::tables::glyf::{Anchor, CompositeGlyphFlags, Glyph};
use read_fonts::types::GlyphId;
use read_fonts::{FontRef, TableProvider};
use std::time::Instant;

fn f2dot14(v: read_fonts::types::F2Dot14) -> BigRational {
    BigRational::new(v.to_bits().into(), 16384.into())
}

/// The glyph's components, each in glyph space (one entry for a simple or CFF glyph).
fn components(font: &Font<'_>, raw: &FontRef<'_>, gid: u32) -> Result<Vec<Vec<Contour>>, Box<dyn std::error::Error>> {
    if let (Ok(glyf), Ok(loca)) = (raw.glyf(), raw.loca(None))
        && let Some(Glyph::Composite(g)) = loca.get_glyf(GlyphId::new(gid), &glyf)?
    {
        let mut out = vec![];
        for comp in g.components() {
            let t = &comp.transform;
            let linear = Affine([f2dot14(t.xx), f2dot14(t.yx), f2dot14(t.xy), f2dot14(t.yy), rat(0), rat(0)]);
            let Anchor::Offset { x, y } = comp.anchor else {
                return Ok(vec![font.outline(gid)?]); // point-matched: taken whole
            };
            let o = Point::new(vec![rat(x.into()), rat(y.into())]);
            let scaled = comp.flags.contains(CompositeGlyphFlags::SCALED_COMPONENT_OFFSET)
                && !comp.flags.contains(CompositeGlyphFlags::UNSCALED_COMPONENT_OFFSET);
            let o = if scaled { linear.apply(&o) } else { o };
            let place = Affine([
                f2dot14(t.xx),
                f2dot14(t.yx),
                f2dot14(t.xy),
                f2dot14(t.yy),
                o.coords[0].clone(),
                o.coords[1].clone(),
            ]);
            let contours = font.outline(comp.glyph.to_u32())?;
            out.push(
                contours
                    .iter()
                    .map(|c| Contour {
                        segments: c.segments.iter().map(|s| place.apply_segment(s)).collect(),
                        closed: c.closed,
                    })
                    .collect(),
            );
        }
        return Ok(out);
    }
    Ok(vec![font.outline(gid)?])
}

/// This thread's CPU time in seconds (Linux; `None` elsewhere): the figure a loaded machine
/// does not distort.
fn cpu_seconds() -> Option<f64> {
    let s = std::fs::read_to_string("/proc/thread-self/schedstat").ok()?;
    Some(s.split_whitespace().next()?.parse::<f64>().ok()? / 1e9)
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let path = std::env::args().nth(1).unwrap_or_else(|| "tests/data/fonts/Tuffy.ttf".into());
    let verbose = std::env::args().any(|a| a == "-v");
    let data = std::fs::read(&path)?;
    let font = Font::open(&data, 0)?;
    let raw = FontRef::new(&data)?;
    let flavour = if font.is_cff() { Flavour::Cubic } else { Flavour::Quadratic };
    let budget = Budget::new(casteljau::work::DEFAULT_MAX_WORK, "--max-work");
    let inputs: Vec<GlyphInput> = (0..font.num_glyphs())
        .map(|gid| {
            Ok(GlyphInput {
                glyph_id: gid,
                name: font.glyph_name(gid),
                components: components(&font, &raw, gid)?,
                flavour,
                orientation: font.outer_orientation(),
            })
        })
        .collect::<Result<_, Box<dyn std::error::Error>>>()?;
    let start = Instant::now();
    let cpu_start = cpu_seconds();
    let (mut unchanged, mut rewritten, mut uncertified, mut errors) = (0, 0, 0, 0);
    let mut worst = rat(0);
    for input in &inputs {
        let name = input.name.clone().unwrap_or_else(|| format!("#{}", input.glyph_id));
        let t = Instant::now();
        let decision = decide_glyph(input, &budget);
        let ms = t.elapsed().as_secs_f64() * 1e3;
        match decision {
            Ok(GlyphDecision::Unchanged) => unchanged += 1,
            Ok(GlyphDecision::Rewritten { report, .. }) => {
                rewritten += 1;
                if report.distance_bound > worst {
                    worst = report.distance_bound.clone();
                }
                if verbose {
                    println!(
                        "{name}: rewritten, {} → {} contours, bound {}, repairs {:?} ({ms:.1} ms)",
                        report.contours_before, report.contours_after, report.distance_bound, report.repairs
                    );
                }
            }
            Ok(GlyphDecision::Uncertified { reason }) => {
                uncertified += 1;
                println!("{name}: uncertified: {reason} ({ms:.1} ms)");
            }
            Err(e) => {
                errors += 1;
                println!("{name}: error: {e}");
            }
        }
    }
    let secs = start.elapsed().as_secs_f64();
    let cpu = match (cpu_start, cpu_seconds()) {
        (Some(a), Some(b)) => format!(", {:.2} s CPU", b - a),
        _ => String::new(),
    };
    println!(
        "{path}: {} glyphs in {secs:.2} s (one core{cpu}): {unchanged} unchanged, {rewritten} rewritten (distance bound at most {worst} ≈ {:.4}), {uncertified} uncertified, {errors} errors",
        inputs.len(),
        num_traits::ToPrimitive::to_f64(&worst).unwrap_or(f64::NAN)
    );
    Ok(())
}
