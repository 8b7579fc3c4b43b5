//! Exact areas of boolean results: `∮ (x dy − y dx)/2` over each contour, summed piece by
//! piece — whole small-integer polynomial segments in `i128` from a precomputed Bernstein area
//! matrix, other polynomial pieces by their exact antiderivative at the pieces' ends (rational
//! or real algebraic), rational segments by Gauss–Legendre quadrature (no exact value then).
//!
//! The rounded total is the exact area correctly rounded whenever every piece is polynomial:
//! the rational part and an enclosure of each algebraic value are summed and the algebraic
//! values bisected until both ends of the enclosure round to the same `f64` (they do unless the
//! exact area is itself a rounding boundary, which an enclosure of width `2^-4096` times the
//! area's size still straddling is refused as, never guessed).

use super::graph::Arrangement;
use super::runs::Run;
use super::segment::Seg;
use crate::error::{Error, Result};
use crate::num::scalar::{rat, ratio_to_f64};
use crate::poly::Poly;
use crate::poly::algebraic::RealAlgebraic;
use num_rational::BigRational;
use num_traits::Signed;

/// One contour's area: exact when every piece's is, else a rational part plus algebraic values
/// (`F(t)` at the pieces' algebraic ends, each with its sign), plus a quadrature estimate for
/// rational segments.
#[derive(Clone, Debug)]
pub(super) struct ContourArea {
    /// The rational part (the whole area when `terms` is empty and `approx` is 0).
    rational: BigRational,
    /// Algebraic values added (`true`) or subtracted (`false`).
    terms: Vec<(bool, RealAlgebraic)>,
    /// Quadrature estimates of rational segments' pieces (no exact value).
    approx: Option<f64>,
}

impl ContourArea {
    /// The exact area when it is rational and known.
    pub(super) fn exact(&self) -> Option<BigRational> {
        (self.terms.is_empty() && self.approx.is_none()).then(|| self.rational.clone())
    }
}

/// The sum of the contours' areas: exact when every one is, with its correctly rounded value
/// (see the module documentation); a sum of rounded values when a rational segment's quadrature
/// takes part.
///
/// # Errors
/// [`Error::InvalidArgument`] when the rounding is not decided at `2^-4096` relative width.
pub(super) fn total_area(areas: &[ContourArea]) -> Result<(Option<BigRational>, f64)> {
    let rational = areas.iter().fold(rat(0), |acc, a| acc + &a.rational);
    let mut terms: Vec<(bool, RealAlgebraic)> = areas.iter().flat_map(|a| a.terms.iter().cloned()).collect();
    if let Some(approx) = areas.iter().filter_map(|a| a.approx).reduce(|x, y| x + y) {
        let algebraic: f64 = terms.iter().map(|(plus, t)| if *plus { t.to_f64() } else { -t.to_f64() }).sum();
        return Ok((None, ratio_to_f64(&rational) + algebraic + approx));
    }
    if terms.is_empty() {
        let f = ratio_to_f64(&rational);
        return Ok((Some(rational), f));
    }
    Ok((None, rounded_sum(&rational, &mut terms)?))
}

/// `r + Σ ±t`, correctly rounded: the enclosure's ends rounded until they agree, bisecting every
/// algebraic value's interval between tries (1, 2, 4, … up to 64 times).
fn rounded_sum(r: &BigRational, terms: &mut [(bool, RealAlgebraic)]) -> Result<f64> {
    let scale = terms.iter().fold(r.abs() + rat(1), |acc, (_, t)| {
        let (lo, hi) = t.interval();
        acc + lo.abs() + hi.abs()
    });
    let limit = scale / BigRational::from_integer(num_bigint::BigInt::from(1) << 4096u32);
    // bits gained per round: 1, 2, 4, … up to 64 (one sum and two roundings per round)
    let mut step = 1;
    loop {
        let (mut lo, mut hi) = (r.clone(), r.clone());
        for (plus, t) in terms.iter() {
            let (a, b) = t.interval();
            if *plus {
                lo += a;
                hi += b;
            } else {
                lo -= b;
                hi -= a;
            }
        }
        let (fl, fh) = (ratio_to_f64(&lo), ratio_to_f64(&hi));
        if fl == fh {
            return Ok(fl);
        }
        if hi - lo < limit {
            return Err(Error::InvalidArgument {
                message: format!(
                    "the area lies within 2^-4096 of the rounding boundary between {fl} and {fh}; its rounding is \
                     not decided"
                ),
            });
        }
        for (_, t) in terms.iter_mut() {
            t.bisect_times(step);
        }
        step = (step * 2).min(64);
    }
}

/// `∮ (x dy − y dx)/2` over one contour: exact when every piece is polynomial with rational
/// ends (or ends where the antiderivative is rational), else a rational part and the
/// antiderivative's algebraic values (or Gauss–Legendre quadrature for rational segments).
pub(super) fn contour_area(arr: &Arrangement, runs: &[Run]) -> ContourArea {
    let mut area = ContourArea { rational: rat(0), terms: vec![], approx: None };
    // whole small-integer pieces: numerators over 240 in i128 (60·K, and 4 for the doubled points)
    let mut sixtieths: i128 = 0;
    let (zero, one) = (RealAlgebraic::from(rat(0)), RealAlgebraic::from(rat(1)));
    for r in runs {
        let s = &arr.segs[r.seg];
        let sign = if r.from == zero && r.to == one {
            Some(1)
        } else if r.from == one && r.to == zero {
            Some(-1)
        } else {
            None
        };
        if let (Some(sign), Some(v)) = (sign, whole_area_sixtieths(s))
            && let Some(next) = sixtieths.checked_add(sign * v)
        {
            sixtieths = next;
            continue;
        }
        match piece_area(s, &r.from, &r.to) {
            PieceArea::Exact(a) => area.rational += a,
            PieceArea::Algebraic { from, to } => {
                area.terms.push((true, *to));
                area.terms.push((false, *from));
            }
            PieceArea::Approx(f) => *area.approx.get_or_insert(0.0) += f,
        }
    }
    area.rational += BigRational::new(sixtieths.into(), 240.into());
    area
}

/// [`whole_area`] times 240 for a polynomial segment of degree ≤ 3 with small control points:
/// `Σ 60·K[i][j]·(XᵢYⱼ − XⱼYᵢ)` in `i128` with `X = 2x`, `Y = 2y` (`60·K` is integral for these
/// degrees).
fn whole_area_sixtieths(s: &Seg) -> Option<i128> {
    use std::sync::OnceLock;
    static TABLES: OnceLock<Vec<Vec<Vec<i128>>>> = OnceLock::new();
    let tables = TABLES.get_or_init(|| {
        (0..=3)
            .map(|n| {
                if n == 0 {
                    return vec![];
                }
                area_matrix(n)
                    .iter()
                    .map(|row| {
                        row.iter()
                            .map(|k| {
                                let v = k * rat(60);
                                assert!(v.is_integer(), "60·K is integral for degree ≤ 3");
                                num_traits::ToPrimitive::to_i128(&v.to_integer()).expect("small")
                            })
                            .collect()
                    })
                    .collect()
            })
            .collect()
    });
    let (p, n) = (s.small.as_ref()?, s.degree());
    if !s.polynomial || n == 0 || n > 3 {
        return None;
    }
    let k = &tables[n];
    let mut total: i128 = 0;
    for i in 0..=n {
        for j in i + 1..=n {
            let cross = p[i][0] as i128 * p[j][1] as i128 - p[j][0] as i128 * p[i][1] as i128;
            total += k[i][j] * cross;
        }
    }
    Some(total)
}

/// `K[i][j] = (M[i][j] − M[j][i])/2` with `M[i][j] = ∫₀¹ Bᵢⁿ (Bⱼⁿ)′ dt`, so that a whole
/// polynomial segment's `∫ (x dy − y dx)/2 = Σ_{i<j} K[i][j] (xᵢyⱼ − xⱼyᵢ)`; from
/// `(Bⱼⁿ)′ = n(Bⱼ₋₁ⁿ⁻¹ − Bⱼⁿ⁻¹)` and `∫₀¹ Bᵢⁿ Bₖᵐ = C(n,i)C(m,k) / ((n+m+1) C(n+m, i+k))`.
fn area_matrix(n: usize) -> Vec<Vec<BigRational>> {
    let c = |n: usize, k: usize| -> BigRational {
        BigRational::from_integer((0..k).fold(num_bigint::BigInt::from(1), |acc, i| acc * (n - i) / (i + 1)))
    };
    let prod = |i: usize, k: usize| -> BigRational {
        // ∫ B_i^n B_k^{n−1}
        c(n, i) * c(n - 1, k) / (BigRational::from_integer((2 * n).into()) * c(2 * n - 1, i + k))
    };
    let m = |i: usize, j: usize| -> BigRational {
        let mut v = rat(0);
        if j >= 1 {
            v += prod(i, j - 1);
        }
        if j < n {
            v -= prod(i, j);
        }
        v * rat(n as i64)
    };
    (0..=n).map(|i| (0..=n).map(|j| (m(i, j) - m(j, i)) / rat(2)).collect()).collect()
}

/// The area contribution of a whole polynomial segment traversed forwards, from its control
/// points (small integers: the cross products in `i128`).
fn whole_area(s: &Seg) -> Option<BigRational> {
    use std::sync::OnceLock;
    static TABLES: OnceLock<Vec<Vec<Vec<BigRational>>>> = OnceLock::new();
    let tables = TABLES.get_or_init(|| {
        (0..=crate::intersect::MAX_INTERSECT_DEGREE).map(|n| if n == 0 { vec![] } else { area_matrix(n) }).collect()
    });
    let n = s.degree();
    if !s.polynomial || n == 0 || n >= tables.len() {
        return None;
    }
    let k = &tables[n];
    let mut total = rat(0);
    match (&s.small, &s.hull) {
        (Some(p), _) => {
            for i in 0..=n {
                for j in i + 1..=n {
                    // the doubled points: cross products four times too large
                    let cross = p[i][0] as i128 * p[j][1] as i128 - p[j][0] as i128 * p[i][1] as i128;
                    if cross != 0 {
                        total += &k[i][j] * BigRational::new(cross.into(), 4.into());
                    }
                }
            }
        }
        (None, Some(p)) => {
            for i in 0..=n {
                for j in i + 1..=n {
                    total += &k[i][j] * p[i].cross(&p[j]);
                }
            }
        }
        _ => return None,
    }
    Some(total)
}

/// The antiderivative of `(X Y' − Y X')/(2W²)` for a polynomial segment (`W` constant).
fn area_antiderivative(s: &Seg) -> Option<Poly<BigRational>> {
    if !s.polynomial {
        return None;
    }
    let w = s.w().coeff(0);
    let integrand = &(s.x() * &s.y().derivative()) - &(s.y() * &s.x().derivative());
    Some(integrand.scale(&(rat(1) / (&w * &w * rat(2)))).integral())
}

/// A piece's area: exact, `F(to) − F(from)` with an algebraic end, or a quadrature estimate.
enum PieceArea {
    Exact(BigRational),
    Algebraic { from: Box<RealAlgebraic>, to: Box<RealAlgebraic> },
    Approx(f64),
}

fn piece_area(s: &Seg, from: &RealAlgebraic, to: &RealAlgebraic) -> PieceArea {
    let (zero, one) = (RealAlgebraic::from(rat(0)), RealAlgebraic::from(rat(1)));
    let whole = if *from == zero && *to == one {
        Some(false)
    } else if *from == one && *to == zero {
        Some(true)
    } else {
        None
    };
    if let Some(reversed) = whole
        && let Some(a) = whole_area(s)
    {
        return PieceArea::Exact(if reversed { -a } else { a });
    }
    if let Some(f) = area_antiderivative(s) {
        if let (Some(a), Some(b)) = (from.to_rational(), to.to_rational()) {
            return PieceArea::Exact(f.eval(b) - f.eval(a));
        }
        // F at an algebraic end: a real algebraic number, rational more often than not (a
        // piece on a line through the origin, a symmetric end)
        let at = |t: &RealAlgebraic| match t.to_rational() {
            Some(r) => RealAlgebraic::from(f.eval(r)),
            None => t.map_rational(&f, &Poly::constant(rat(1))),
        };
        let (fa, fb) = (at(from), at(to));
        if let (Some(a), Some(b)) = (fa.to_rational(), fb.to_rational()) {
            return PieceArea::Exact(b - a);
        }
        return PieceArea::Algebraic { from: Box::new(fa), to: Box::new(fb) };
    }
    // rational segment: Gauss–Legendre on the homogeneous form
    let (a, b) = (from.to_f64(), to.to_f64());
    let (dx, dy, dw) = (s.x().derivative(), s.y().derivative(), s.w().derivative());
    let integrand = |t: f64| {
        let (x, y, w) = (s.x().eval_f64(t), s.y().eval_f64(t), s.w().eval_f64(t));
        let (xp, yp, wp) = (dx.eval_f64(t), dy.eval_f64(t), dw.eval_f64(t));
        // d(x/w) = (x'w − xw')/w², so x dy − y dx = (x(y'w − yw') − y(x'w − xw'))/w³
        (x * (yp * w - y * wp) - y * (xp * w - x * wp)) / (w * w * w) / 2.0
    };
    PieceArea::Approx(gauss_legendre(integrand, a, b))
}

fn gauss_legendre(f: impl Fn(f64) -> f64, a: f64, b: f64) -> f64 {
    // 16 nodes on each half of [a, b]
    const X: [f64; 8] = [
        0.0950125098376374,
        0.2816035507792589,
        0.4580167776572274,
        0.6178762444026438,
        0.755_404_408_355_003,
        0.8656312023878318,
        0.9445750230732326,
        0.9894009349916499,
    ];
    const W: [f64; 8] = [
        0.1894506104550685,
        0.1826034150449236,
        0.1691565193950025,
        0.1495959888165767,
        0.1246289712555339,
        0.0951585116824928,
        0.0622535239386479,
        0.0271524594117541,
    ];
    let half = |a: f64, b: f64| {
        let (c, r) = ((a + b) / 2.0, (b - a) / 2.0);
        r * X.iter().zip(W).map(|(x, w)| w * (f(c - r * x) + f(c + r * x))).sum::<f64>()
    };
    let m = (a + b) / 2.0;
    half(a, m) + half(m, b)
}
