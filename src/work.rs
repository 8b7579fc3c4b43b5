//! Work estimates: what an exact operation will cost, computed from its input before it runs.
//!
//! Exact arithmetic has no rounding, so the size of the numbers grows with the work: de
//! Casteljau at `t = p/q` multiplies bit lengths by the degree, a power form carries binomials
//! of `n` bits. An accepted input must get its answer in bounded time, so every exact operation
//! the command line offers has a library entry taking a [`Budget`] (`Evaluation::new`
//! and the other `*_within` operations of [`crate::curve`], [`crate::rational`],
//! [`crate::rational::bounding_box`], ...) that estimates its cost here first and
//! refuses with [`Error::WorkLimit`] (naming the limit and the option that raises it) when the
//! estimate exceeds the budget.
//!
//! # Units
//! A *work unit* is about one nanosecond of this project's reference machine (2 cores, 2026):
//! each formula below counts big-integer limb operations (64-bit words) of the dominant loop
//! and carries a constant fitted to measured run times, so `1e10` units is about ten seconds.
//! The estimates are for the typical case (they are not worst-case bounds), and aim at the
//! truth within a factor of 3 either way (measured cases in `benches/README.md`); where the work
//! depends on the input beyond its sizes, the operation also counts its steps while running
//! and stops with an error naming the limit: root isolation charges each subdivision against
//! the budget ([`crate::poly::isolate_bernstein`]), and the expression language
//! charges each `sum`/`prod` term, large power, binomial and Bernstein polynomial
//! ([`crate::proof::expr::with_step_limit`]; the command line allows one step per 200 units).
//!
//! With `L(b) = b/64 + 1` limbs for a `b`-bit number, `n` the degree, `d` the dimension, `β`
//! the largest bit length of an input number (numerator plus denominator) and `τ` that of
//! the parameter, and `G = 18` the cost of a gcd per limb² (reducing an output fraction):
//!
//! | operation | estimate |
//! | --- | --- |
//! | evaluation at `t` (fraction-free Horner) | `d·(n·L(g)·L(τ) + G·L(g)²)`, `g = β + nτ` |
//! | subdivision at `t` | `d·(n²/2·L(g)·L(τ) + 2(n+1)·G·L(g)²)` |
//! | evaluation over reduced fractions | `600·d·(n(n+1)/2 + 1)·L(g)²` |
//! | Saito–Hosaka evaluation (seed 002 (19)–(20)) | `700·(n⁴/12 + d·n²)·L(g)²` |
//! | the whole scheme (`triangle`) | subdivision `+ d·(n+1)(n+2)/2·G·L(g)²` |
//! | power form, degree reduction | `8·d·n²·L(β + n)` |
//! | derivative of order `k` | `100·d·n·k·L(β + k·log₂ n)` |
//! | degree elevation by `r` (`m = n + r`, `g = β + m`) | `d·(m + 1)·(5000 + 12·L(g)² + 15·(n + 1)·L(g)·L(β))` |
//! | denominator root isolation | `250·n²·L(β + n)` up front, then `n²·L(b)` per split (`b`: current bits) |
//! | intersection of degrees `n`, `m` (`d = nm`), binary exponents spread over `s ≤ 1000` | `2·10⁴ + (1.5·10⁴ + 9·d^3.6)·L(β)^1.5` |
//! | … beyond (the exact route) | `(3500 + 17·d⁴)·L((n + m)·(β + 4 + s/2))²` |
//! | writing an irrational parameter of degree `d`, `b`-bit coefficients | `1.3·10⁴ + 7800·L(b)^1.6` for `d = 2`, else `1.3·10⁴ + 350·(d + 1)^1.8·L(b)^0.75` |
//! | a power or product with a `b`-bit result (the expression language) | `2·L(b)^1.6` |
//!
//! An arrangement (`shape::Arrangement`) is priced stage by stage from its segments' counts,
//! bit lengths and boxes before each stage starts: the candidate pairs counted from the boxes
//! (nothing collected), the pairs the hull screen leaves (each an intersection above), one ray
//! per chain of edges (see the private `shape::estimate` module).
//!
//! The estimates are the crate's own: an operation taking a [`Budget`] computes its estimate
//! and checks it; users choose the budget.
//!
//! ```
//! use casteljau::{BezierCurve, num::parse_points, work::Budget};
//! let c = BezierCurve::new(parse_points("0 0, 1 2, 2 0", 2, None).unwrap()).unwrap();
//! let budget = Budget::new(1e10, "--max-work");
//! assert!(budget.check("a cheap step", 1e3).is_ok());
//! let e = budget.check("an expensive step", 1e12).unwrap_err();
//! assert!(e.to_string().contains("--max-work"));
//! ```

use crate::error::{Error, Result};
use crate::num::point::Point;
use num_rational::BigRational;

/// The default budget of the command line: about ten seconds of work.
pub const DEFAULT_MAX_WORK: f64 = 1e10;

/// Work units per evaluation step of the expression language (a step costs about 0.2 µs).
pub(crate) const UNITS_PER_STEP: f64 = 200.0;

/// A work limit and the option that raises it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Budget {
    /// The largest accepted estimate, in work units.
    pub limit: f64,
    /// How a user raises it (e.g. `--max-work`), named in the error.
    pub option: &'static str,
}

impl Budget {
    /// A budget of `limit` units, raised with `option`.
    pub fn new(limit: f64, option: &'static str) -> Self {
        Budget { limit, option }
    }

    /// No limit (library use).
    pub fn unlimited() -> Self {
        Budget { limit: f64::INFINITY, option: "" }
    }

    /// The evaluation steps of the expression language this budget allows (one per
    /// [`UNITS_PER_STEP`] units: a step costs about 0.2 µs), for
    /// [`crate::proof::expr::with_step_limit`].
    pub(crate) fn expression_steps(&self) -> u64 {
        (self.limit / UNITS_PER_STEP).min(u64::MAX as f64) as u64
    }

    /// `Ok` when `estimate ≤ limit`, else [`Error::WorkLimit`] naming `what`.
    ///
    /// # Errors
    /// [`Error::WorkLimit`] when the estimate exceeds the limit.
    pub fn check(&self, what: impl Into<String>, estimate: f64) -> Result<()> {
        if estimate <= self.limit {
            Ok(())
        } else {
            Err(Error::WorkLimit { what: what.into(), estimate, limit: self.limit, option: self.option })
        }
    }
}

std::thread_local! {
    /// The budget of the innermost [`metered`] run on this thread and the units charged so far.
    static METER: std::cell::Cell<Option<(Budget, f64)>> = const { std::cell::Cell::new(None) };
}

/// Runs `f` under `budget`, `spent` units already estimated for it: the steps inside whose
/// cost shows only once earlier steps have run (the exact images of a resultant's roots) are
/// priced with [`charge`] before each starts, and refused when the total passes the limit.
/// Outside any meter a charge is free (library calls without a budget).
pub(crate) fn metered<T>(budget: &Budget, spent: f64, f: impl FnOnce() -> Result<T>) -> Result<T> {
    let saved = METER.with(|m| m.replace(Some((*budget, spent))));
    let out = f();
    METER.with(|m| m.set(saved));
    out
}

/// Charges `units` to the innermost [`metered`] run on this thread: [`Error::WorkLimit`] naming
/// `what` (with everything charged so far) when the total passes its limit.
pub(crate) fn charge(what: impl FnOnce() -> String, units: f64) -> Result<()> {
    METER.with(|m| match m.get() {
        None => Ok(()),
        Some((budget, spent)) => {
            let total = spent + units;
            m.set(Some((budget, total)));
            budget.check(what(), total)
        }
    })
}

/// The exact image of an algebraic number of degree `d` (a minimal polynomial with `bp`-bit
/// coefficients) under a rational map of degree `n` (`bq`-bit coefficients): the Sylvester
/// determinant of order `N = d + n` over `Z[v]` by Bareiss, whose step `k` updates `(N − k)²`
/// entries, each products of polynomials of `v`-degree up to `min(k, d) + 1` with
/// coefficients of about `(k + 1)·b` bits (`b = max(bp, bq)`):
/// `0.075·Σ_k (N − k)²·(min(k, d) + 2)²·L((k + 1)·b)²`, plus the root's isolation. Fitted on
/// the self-intersection points of integer curves of degree 8 and 9 (`d` = 42 and 56; one point
/// is two images): 6.5 s measured, 5.4 s estimated; 11 s, 12 s; 70 s, 141 s; 76 s, 144 s.
pub(crate) fn algebraic_image(d: usize, n: usize, bp: u64, bq: u64) -> f64 {
    let order = d + n;
    let b = bp.max(bq);
    (0..order)
        .map(|k| {
            let rest = (order - k) as f64;
            let degree = (k.min(d) + 2) as f64;
            let l = limbs(((k + 1) as u64).saturating_mul(b));
            0.075 * rest * rest * degree * degree * l * l
        })
        .sum::<f64>()
        + root_isolation(d, bp)
}

/// Limbs of a `bits`-bit number: `bits/64 + 1`.
pub(crate) fn limbs(bits: u64) -> f64 {
    (bits / 64 + 1) as f64
}

/// Bit length of an exact number: numerator plus denominator.
pub(crate) fn bits(x: &BigRational) -> u64 {
    x.numer().bits() + x.denom().bits()
}

/// The largest [`bits`] over the coordinates of `points` (0 when there are none).
pub(crate) fn max_bits(points: &[Point<BigRational>]) -> u64 {
    points.iter().flat_map(|p| p.coords.iter()).map(bits).max().unwrap_or(0)
}

/// The largest [`bits`] of `values`.
pub(crate) fn max_bits_of(values: &[BigRational]) -> u64 {
    values.iter().map(bits).max().unwrap_or(0)
}

/// Cost of reducing one fraction (a gcd) of `limbs` words, relative to a limb product.
const GCD: f64 = 18.0;

/// Bits of the numbers after `n` de Casteljau steps at a `tau`-bit parameter.
fn grown(beta: u64, n: usize, tau: u64) -> u64 {
    beta.saturating_add((n as u64).saturating_mul(tau))
}

/// Evaluation at one parameter of `tau` bits (fraction-free Horner): degree `n`, dimension
/// `dim`, input numbers of `beta` bits.
pub(crate) fn evaluation(n: usize, dim: usize, beta: u64, tau: u64) -> f64 {
    let g = limbs(grown(beta, n, tau));
    dim as f64 * (n as f64 * g * limbs(tau) + GCD * g * g)
}

/// One subdivision at a `tau`-bit parameter (fraction-free triangle, `2(n+1)` reduced points).
pub(crate) fn subdivision(n: usize, dim: usize, beta: u64, tau: u64) -> f64 {
    let g = limbs(grown(beta, n, tau));
    let nf = n as f64;
    dim as f64 * (nf * nf / 2.0 * g * limbs(tau) + 2.0 * (nf + 1.0) * GCD * g * g)
}

/// `depth` rounds of subdivision at a `tau`-bit parameter (`2^j` pieces in round `j`, whose
/// numbers have grown by `j·n·tau` bits).
pub(crate) fn repeated_subdivision(n: usize, dim: usize, beta: u64, tau: u64, depth: u32) -> f64 {
    (0..depth.min(64))
        .map(|j| {
            let grown = beta.saturating_add(u64::from(j).saturating_mul(n as u64).saturating_mul(tau));
            2f64.powi(j as i32) * subdivision(n, dim, grown, tau)
        })
        .sum()
}

/// Evaluation at one parameter of `tau` bits by de Casteljau over reduced fractions (every
/// operation followed by a gcd, as `BezierCurve::eval` over `BigRational` and the grid proofs of
/// the claim checker do): `n(n+1)/2 + 1` point combinations in dimension `dim`, each
/// `600·L(g)²` with `g = β + nτ`, on the safe side of a measurement on this machine (the grid
/// proof of a depth-8 subdivision of a degree-10 curve, 306-bit numbers:
/// 1.3 ms measured per evaluation, 1.7 ms estimated).
///
// used by the catalogue (feature `catalogue`) and the unit tests
#[cfg_attr(not(feature = "catalogue"), allow(dead_code))]
pub(crate) fn rational_evaluation(n: usize, dim: usize, beta: u64, tau: u64) -> f64 {
    let nf = n as f64;
    let g = limbs(grown(beta, n, tau));
    600.0 * dim as f64 * (nf * (nf + 1.0) / 2.0 + 1.0) * g * g
}

/// Evaluation at one parameter of `tau` bits by Saito–Hosaka's rational interpolation
/// (seed 002 (19)–(20)) over reduced fractions: each of the `n(n+1)/2` interpolation points
/// takes two shifted weights of up to `n` terms, each term a binomial and two powers, about
/// `n⁴/12` products in all, each `700·L(g)²` with `g = β + nτ` (degree 20, 41 parameters:
/// 6.0 s measured, 6.4 s estimated).
///
// used by the catalogue (feature `catalogue`) and the unit tests
#[cfg_attr(not(feature = "catalogue"), allow(dead_code))]
pub(crate) fn saito_hosaka_evaluation(n: usize, dim: usize, beta: u64, tau: u64) -> f64 {
    let nf = n as f64 + 1.0;
    let g = limbs(grown(beta, n, tau));
    700.0 * (nf * nf * nf * nf / 12.0 + dim as f64 * nf * nf) * g * g
}

/// The whole de Casteljau scheme (`(n+1)(n+2)/2` reduced points).
pub(crate) fn de_casteljau_scheme(n: usize, dim: usize, beta: u64, tau: u64) -> f64 {
    let g = limbs(grown(beta, n, tau));
    let nf = n as f64;
    subdivision(n, dim, beta, tau) + dim as f64 * (nf + 1.0) * (nf + 2.0) / 2.0 * GCD * g * g
}

/// Conversion to (or from) the power form, and exact degree reduction.
pub(crate) fn power_form(n: usize, dim: usize, beta: u64) -> f64 {
    let nf = n as f64 + 1.0;
    8.0 * dim as f64 * nf * nf * limbs(beta.saturating_add(n as u64))
}

/// The derivative of order `k` of a degree-`n` curve (numbers grow by `k·log₂ n` bits).
pub(crate) fn derivative(n: usize, k: usize, dim: usize, beta: u64) -> f64 {
    let growth = (k as u64).saturating_mul(u64::from(usize::BITS - n.leading_zeros()));
    100.0 * dim as f64 * (n as f64 + 1.0) * (k as f64 + 1.0) * limbs(beta.saturating_add(growth))
}

/// Degree elevation of a degree-`n` curve by `r`: each of the `d·(m + 1)` output coordinates
/// (`m = n + r`) sums `n + 1` products of a `β`-bit coordinate and a binomial, and is reduced
/// against `C(m, i)` (numbers of `g = β + m` bits; the gcd dominates):
/// `d·(m + 1)·(5000 + 12·L(g)² + 15·(n + 1)·L(g)·L(β))` (a cubic by 9997 with 1000-digit
/// coordinates: 11.6 s measured, 24 s estimated; with one-digit coordinates 3.1 s and 6.2 s; by
/// 1000 with 1000-digit coordinates 0.46 s and 0.55 s).
pub(crate) fn elevation(n: usize, r: usize, dim: usize, beta: u64) -> f64 {
    let m = n.saturating_add(r);
    let (g, b) = (limbs(beta.saturating_add(m as u64)), limbs(beta));
    dim as f64 * (m as f64 + 1.0) * (5000.0 + 12.0 * g * g + 15.0 * (n as f64 + 1.0) * g * b)
}

/// The up-front part of isolating the roots of a degree-`n` polynomial with `beta`-bit
/// coefficients (power form, square-free part).
pub(crate) fn root_isolation(n: usize, beta: u64) -> f64 {
    let nf = n as f64 + 1.0;
    250.0 * nf * nf * limbs(beta.saturating_add(n as u64))
}

/// The sizes of a curve's homogeneous coordinates that its intersection costs depend on: the
/// largest bit length (numerator plus denominator) and the range of binary exponents
/// (`⌊log₂ |x|⌋`, about) of the non-zero ones — of `wx` and `wy` only when every weight is
/// the same (a polynomial curve: scaling the plane by a power of two changes no common point,
/// and the `f64` filters scale it), of `w` too otherwise.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Magnitudes {
    /// The largest [`bits`].
    pub bits: u64,
    /// The smallest binary exponent of a non-zero coordinate (0 when there is none).
    pub min_exp: i64,
    /// The largest binary exponent of a non-zero coordinate (0 when there is none).
    pub max_exp: i64,
}

impl Magnitudes {
    /// The sizes of `points`' homogeneous coordinates `(wx, wy, w)`.
    pub(crate) fn of(points: &[Point<BigRational>]) -> Magnitudes {
        let mut m = Magnitudes { bits: 0, min_exp: i64::MAX, max_exp: i64::MIN };
        let first = points.first().and_then(|p| p.coords.last());
        let same_weights = points.iter().all(|p| p.coords.last() == first);
        for p in points {
            let spread_of = if same_weights { p.coords.len().saturating_sub(1) } else { p.coords.len() };
            for (k, x) in p.coords.iter().enumerate() {
                m.bits = m.bits.max(bits(x));
                if k < spread_of && !num_traits::Zero::is_zero(x) {
                    let e = x.numer().bits() as i64 - x.denom().bits() as i64;
                    m.min_exp = m.min_exp.min(e);
                    m.max_exp = m.max_exp.max(e);
                }
            }
        }
        if m.min_exp > m.max_exp {
            (m.min_exp, m.max_exp) = (0, 0);
        }
        m
    }

    /// The sizes of two curves together.
    pub(crate) fn with(self, other: Magnitudes) -> Magnitudes {
        Magnitudes {
            bits: self.bits.max(other.bits),
            min_exp: self.min_exp.min(other.min_exp),
            max_exp: self.max_exp.max(other.max_exp),
        }
    }

    /// The range of binary exponents, `max_exp − min_exp`.
    pub(crate) fn spread(self) -> u64 {
        (self.max_exp - self.min_exp).max(0) as u64
    }
}

/// The largest range of binary exponents of a pair's coordinates that the certified `f64`
/// filters of [`crate::intersect`] still hold once the plane is scaled by a power of two:
/// beyond it the exact route decides.
const FILTERED_SPREAD: u64 = 1000;

/// Exact intersection of a degree-`n` and a degree-`m` planar curve (`d = nm`), for the typical
/// pair that an arrangement cannot decide from hulls (the pair's coordinates `sizes`, `L` the
/// limbs of their largest bit length `β`, `s` the spread of their binary exponents):
///
/// - `s ≤ 1000` (the certified `f64` filters and the box solver decide, the plane scaled by a
///   power of two when the coordinates lie far from 1):
///   `2·10⁴ + (1.5·10⁴ + 9·d^3.6)·L^1.5` (cubic pairs: 10-bit coordinates 45 µs measured per
///   pair, 60 µs estimated; 500-bit 1.3 ms, 0.9 ms; 1000-bit 2.3 ms, 2.6 ms; degree 7: 10-bit
///   2.5 ms, 11 ms; 60-bit 22 ms, 31 ms; 150-bit 56 ms, 57 ms; 300-bit 165 ms, 123 ms);
/// - beyond (the resultants' roots isolated and mapped exactly): `(3500 + 17·d⁴)·l²` with
///   `l = L((n + m)·(β + 4 + s/2))`, the resultant's coefficients being sums of products of
///   `m` coordinates of one curve and `n` of the other (a line with coordinates `±10³⁰⁰` and
///   `10⁻³⁰⁰` against a cubic: 30 ms measured, 77 ms estimated; with `±10¹⁶⁰`, `10⁻¹⁶⁰`:
///   14 ms, 22 ms).
///
/// Writing the exact parameters found is priced apart ([`description`]).
pub(crate) fn intersection(n: usize, m: usize, sizes: Magnitudes) -> f64 {
    let d = (n.max(1) * m.max(1)) as f64;
    let l = limbs(sizes.bits);
    if sizes.spread() <= FILTERED_SPREAD {
        return 2e4 + (1.5e4 + 9.0 * d.powf(3.6)) * l.powf(1.5);
    }
    let spread = sizes.spread();
    let grown = ((n.max(1) + m.max(1)) as u64).saturating_mul(sizes.bits.saturating_add(4).saturating_add(spread / 2));
    let l = limbs(grown);
    (3500.0 + 17.0 * d * d * d * d) * l * l
}

/// Writing one irrational parameter exactly, a root of a degree-`d` polynomial with `b`-bit
/// coefficients (`Display`): for a quadratic's root `a + b*sqrt(d)`, the square factors of
/// the discriminant taken out, `1.3·10⁴ + 7800·L(b)^1.6` (5-bit: 15 µs measured, 21 µs
/// estimated; 1066-bit: 0.8–1.0 ms, 0.7 ms; 2000-bit: 1.9–2.4 ms, 2.0 ms; 3000-bit: 3.7 ms,
/// 3.7 ms); otherwise the canonical isolating interval and the root's index, a few isolations
/// on cells near the root, `1.3·10⁴ + 350·(d + 1)^1.8·L(b)^0.75` (degree 9, 21-bit: 35 µs,
/// 35 µs; degree 9, 6000-bit: 0.9 ms, 0.7 ms; degree 48, 66-bit: 0.96 ms, 0.66 ms).
pub(crate) fn description(d: usize, b: u64) -> f64 {
    let l = limbs(b);
    if d == 2 {
        return 1.3e4 + 7800.0 * l.powf(1.6);
    }
    1.3e4 + 350.0 * (d as f64 + 1.0).powf(1.8) * l.powf(0.75)
}

/// The exact bounding box of a degree-`n` (rational) curve with `beta`-bit homogeneous
/// coordinates: the roots of `X′W − XW′` (degree `2n − 2`, about `2·beta` bits) isolated and
/// each mapped to its coordinate: `5000·(n + 1)⁴·limbs(4·beta + 2n)²`, on the safe side of
/// measurements on this machine (degree 10, 60-bit: 0.9 s measured, 1.8 s estimated; degree 20,
/// 60-bit: 23 s measured, 26 s estimated).
pub(crate) fn extrema(n: usize, beta: u64) -> f64 {
    let nf = n as f64 + 1.0;
    let l = limbs(beta.saturating_mul(4).saturating_add(2 * n as u64));
    5000.0 * nf * nf * nf * nf * l * l
}

/// One degree-`n` segment of a winding number (`beta` bits, the query point's included): the
/// roots of `y(t) − q_y` isolated and the side of each crossing decided, plus reading the
/// segment: `2·10⁵ + 20·(n + 1)⁴·limbs(beta + n)²` (degree 30, 60-bit: 34 ms measured per
/// segment, 74 ms estimated).
pub(crate) fn winding_segment(n: usize, beta: u64) -> f64 {
    let nf = n as f64 + 1.0;
    let l = limbs(beta.saturating_add(n as u64));
    2e5 + 20.0 * nf * nf * nf * nf * l * l
}

/// One piece of a cycle crossing a ray's line in an arrangement's winding numbers (degree `n`,
/// `β`-bit coordinates): the roots of the piece's coordinate along the line isolated, each
/// crossing's side decided exactly: `3·10⁴ + 20·(n + 1)⁴·L(β + n)²`.
pub(crate) fn winding_piece(n: usize, beta: u64) -> f64 {
    let nf = n as f64 + 1.0;
    let l = limbs(beta.saturating_add(n as u64));
    3e4 + 20.0 * nf * nf * nf * nf * l * l
}

/// A power or product whose result has `bits` bits: `2·L(bits)^1.6` (Karatsuba's exponent;
/// `(1 + s)^100000` at a 20-bit `s`: 8.5 ms measured, 8.9 ms estimated).
pub(crate) fn power(bits: u64) -> f64 {
    2.0 * limbs(bits).powf(1.6)
}

/// One subdivision step of root isolation (degree `n`, `beta`-bit coefficients).
pub(crate) fn root_split(n: usize, beta: u64) -> f64 {
    let nf = n as f64;
    nf * nf * limbs(beta.saturating_add(2 * n as u64))
}

/// The sizes of a spline for its cost models: degree `n`, control points, homogeneous
/// dimension and the largest bit length of a control coordinate or knot.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct SplineShape {
    /// The degree `n`.
    pub degree: usize,
    /// The number of control points `m + 1`.
    pub points: usize,
    /// Coordinates of a homogeneous control point.
    pub dim: usize,
    /// The largest bit length of a control coordinate or knot.
    pub bits: u64,
}

/// Bézier extraction of a spline and the proof of its joins, per segment (at most one per
/// control point): Boehm insertion of the span's ends into its window of `n + 1` points, and
/// the derivatives of orders up to `n − 1` at each join, numbers grown to about `β·(n + 1)`
/// bits: `2·10⁴·(n + 1) + 40·n²·dim·G·L(β·(n + 1))²` (degree 12, 500 points: 1.5 s measured,
/// 1.5 s estimated; degree 3, 10,000 points: 2.0 s measured, 1.0 s estimated, output
/// included in the measurement).
pub(crate) fn spline_conversion(s: SplineShape) -> f64 {
    let n = s.degree as f64;
    let l = limbs(s.bits.saturating_mul(s.degree as u64 + 1));
    s.points.max(1) as f64 * (2e4 * (n + 1.0) + 40.0 * n * n * s.dim as f64 * GCD * l * l)
}

/// One de Boor evaluation of a spline at a `tau`-bit parameter: `n(n + 1)/2` homogeneous
/// interpolations of `dim` reduced coordinates.
pub(crate) fn spline_evaluation(s: SplineShape, tau: u64) -> f64 {
    let n = s.degree as f64;
    let l = limbs(grown(s.bits, s.degree, tau));
    n * (n + 1.0) / 2.0 * s.dim as f64 * GCD * l * l + 1.0
}

/// The check of a spline's Bézier segments: the extraction (twice for the seed's formulas),
/// and `2n + 1` evaluations of each segment and of the spline per segment (degree 12, 500
/// points: 2.5 s measured, 3.0 s estimated; degree 3, 10,000 points: 4.1 s measured, 2.0 s
/// estimated, output included in the measurement).
pub(crate) fn spline_check(s: SplineShape) -> f64 {
    let segments = (s.points.saturating_sub(s.degree)).max(1) as f64;
    let samples = segments * (2.0 * s.degree as f64 + 1.0);
    let tau = 64 - (2 * s.degree as u64).leading_zeros() as u64;
    2.0 * spline_conversion(s)
        + samples * (spline_evaluation(s, tau + s.bits) + evaluation(s.degree, s.dim, s.bits, tau))
}

/// Bézier extraction of a NURBS surface of degrees `(p, q)` with `points` homogeneous control
/// points of `dim` coordinates and `bits`-bit numbers, and its check: extraction along `u` of
/// every column and along `v` of every row, then `(2p + 1)(2q + 1)` samples per patch.
pub(crate) fn surface_extraction(degree: (usize, usize), points: usize, dim: usize, bits: u64) -> f64 {
    let (p, q) = (degree.0.max(1), degree.1.max(1));
    let shape = |n: usize| SplineShape { degree: n, points, dim, bits };
    let samples = points as f64 * ((2 * p + 1) * (2 * q + 1)) as f64;
    spline_conversion(shape(p)) * (q + 1) as f64
        + spline_conversion(shape(q)) * (p + 1) as f64
        + samples * evaluation(p.max(q), dim, bits.saturating_mul((p + q) as u64), 8)
}

/// The examples of the crate-internal items above, run as unit tests.
#[cfg(test)]
mod doc_examples {
    #[test]
    fn rational_evaluation_estimate() {
        use crate::work::rational_evaluation;
        assert!(rational_evaluation(10, 2, 240, 8) > rational_evaluation(3, 2, 240, 8));
    }

    #[test]
    fn saito_hosaka_evaluation_estimate() {
        use crate::work::{rational_evaluation, saito_hosaka_evaluation};
        assert!(saito_hosaka_evaluation(20, 3, 16, 8) > rational_evaluation(20, 3, 16, 8));
    }

    #[test]
    fn spline_shape() {
        use crate::work::{SplineShape, spline_check, spline_conversion};
        let s = SplineShape { degree: 3, points: 6, dim: 3, bits: 8 };
        assert!(spline_check(s) > spline_conversion(s));
    }

    #[test]
    fn spline_conversion_estimate() {
        use crate::work::{SplineShape, spline_conversion};
        let cubic = |points| spline_conversion(SplineShape { degree: 3, points, dim: 3, bits: 16 });
        assert!(cubic(1000) > 100.0 * cubic(6));
    }

    #[test]
    fn spline_evaluation_estimate() {
        use crate::work::{SplineShape, spline_evaluation};
        let s = SplineShape { degree: 3, points: 6, dim: 3, bits: 16 };
        assert!(spline_evaluation(s, 1000) > spline_evaluation(s, 2));
    }

    #[test]
    fn spline_check_estimate() {
        use crate::work::{Budget, DEFAULT_MAX_WORK, SplineShape, spline_check};
        let budget = Budget::new(DEFAULT_MAX_WORK, "--max-work");
        let shape = |degree, points| SplineShape { degree, points, dim: 3, bits: 13 };
        assert!(budget.check("check", spline_check(shape(3, 1000))).is_ok());
        assert!(budget.check("check", spline_check(shape(12, 10_000))).is_err()); // about a minute
    }

    #[test]
    fn surface_extraction_estimate() {
        use crate::work::surface_extraction;
        assert!(surface_extraction((3, 3), 100, 4, 16) > surface_extraction((1, 1), 100, 4, 16));
    }
}
