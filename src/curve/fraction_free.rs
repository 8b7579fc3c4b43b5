//! Fraction-free exact kernels: integers over one common denominator, one reduction at the end.
//!
//! Naive `BigRational` de Casteljau reduces a fraction (a gcd) at every one of its `O(n²)`
//! operations. Here a curve with rational control points is written `bᵢ = Nᵢ / D` with integer
//! `Nᵢ` and `D = lcm` of all denominators, and `t = p/q` (reduced, `q > 0`). Then
//!
//! * evaluation (homogeneous Horner on the Bernstein form):
//!   `b(t) = Σ C(n,i) Nᵢ pⁱ (q−p)ⁿ⁻ⁱ / (D qⁿ)`, computed as `s_n = a_n`,
//!   `s_i = s_{i+1}·p + a_i·(q−p)^{n−i}` with `a_i = C(n,i) Nᵢ` — `O(n)` integer products;
//! * the triangle (subdivision): `β_i^r = (q−p) β_i^{r−1} + p β_{i+1}^{r−1}` on integers,
//!   with `b_i^r(t) = β_i^r / (D q^r)` — `O(n²)` integer products, no gcd until the output.
//!
//! Both try checked `i128` arithmetic first (most font-like inputs fit) and redo the work in
//! `BigInt` on overflow, so the result is always exact.

use crate::curve::bezier::BezierCurve;
use crate::curve::casteljau::DeCasteljauTriangle;
use crate::error::Result;
use crate::num::point::Point;
use crate::num::scalar::{Rational, Scalar};
use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{CheckedAdd, CheckedMul, One, Pow, ToPrimitive};

/// Integers the kernels run on: exact (`BigInt`, whose checked operations never fail) or
/// fixed width (`i128`); arithmetic is num-traits' [`CheckedAdd`]/[`CheckedMul`], so an
/// overflow is a `None` that sends the work to `BigInt`. Only the conversions are ours.
trait Int: Clone + CheckedAdd + CheckedMul + Into<BigInt> {
    /// The value, when it fits.
    fn from_big(v: &BigInt) -> Option<Self>;
}

impl Int for i128 {
    fn from_big(v: &BigInt) -> Option<Self> {
        v.to_i128()
    }
}

impl Int for BigInt {
    fn from_big(v: &BigInt) -> Option<Self> {
        Some(v.clone())
    }
}

/// A curve with rational control points as integer numerators over one denominator.
///
/// # Invariants
/// `denominator > 0`; `numerators[i·dim + c] / denominator` is coordinate `c` of point `i`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct IntegerCurve {
    /// Dimension of the points.
    pub dim: usize,
    /// Flat numerators, point after point.
    pub numerators: Vec<BigInt>,
    /// The common denominator (the lcm of all coordinate denominators).
    pub denominator: BigInt,
}

impl IntegerCurve {
    /// Brings all coordinates of `curve` over their least common denominator.
    pub fn new(curve: &BezierCurve<BigRational>) -> Self {
        let denominator =
            curve.points().iter().flat_map(|p| &p.coords).fold(BigInt::one(), |acc, c| acc.lcm(c.denom()));
        let numerators =
            curve.points().iter().flat_map(|p| &p.coords).map(|c| c.numer() * (&denominator / c.denom())).collect();
        IntegerCurve { dim: curve.dim(), numerators, denominator }
    }
    /// The degree of the curve.
    pub fn degree(&self) -> usize {
        self.numerators.len() / self.dim - 1
    }
}

/// `b(t)` exactly, fraction-free (see the module docs); equal to
/// [`BezierCurve::eval`] over `BigRational`, but `O(n)` integer products and one gcd per
/// coordinate instead of `O(n²)` reduced fractions.
///
/// # Example
/// ```
/// use casteljau::{BezierCurve, num::parse_points, ratio};
/// let c = BezierCurve::new(parse_points("0 1, 1 3, 2 4, 4 2", 2, None).unwrap()).unwrap();
/// // seed 003, example 2: x = 3t + t³, y = 1 + 6t − 3t² − 2t³
/// assert_eq!(c.eval(&ratio(1, 10)).to_string(), "(301/1000, 196/125)"); // this kernel
/// ```
pub fn eval(curve: &BezierCurve<BigRational>, t: &BigRational) -> Point<BigRational> {
    eval_integer(&IntegerCurve::new(curve), t)
}

/// [`BezierCurve::eval`] on a curve already brought over a common denominator (for repeated evaluation).
pub fn eval_integer(curve: &IntegerCurve, t: &BigRational) -> Point<BigRational> {
    let raw = horner::<i128>(curve, t.numer(), t.denom())
        .unwrap_or_else(|| horner::<BigInt>(curve, t.numer(), t.denom()).expect("BigInt arithmetic does not overflow"));
    let scale = &curve.denominator * Pow::pow(t.denom(), curve.degree());
    Point::new(raw.into_iter().map(|s| BigRational::new(s, scale.clone())).collect())
}

/// Numerators `Σ C(n,i) Nᵢ pⁱ (q−p)ⁿ⁻ⁱ` per coordinate, or `None` on overflow of `I`.
fn horner<I: Int>(curve: &IntegerCurve, p: &BigInt, q: &BigInt) -> Option<Vec<BigInt>> {
    let n = curve.degree();
    let dim = curve.dim;
    let pi = I::from_big(p)?;
    let r = I::from_big(&(q - p))?;
    // (q−p)^k for k = 0..=n and C(n, i) for i = 0..=n.
    let mut rpow = Vec::with_capacity(n + 1);
    rpow.push(I::from_big(&BigInt::one())?);
    for k in 1..=n {
        rpow.push(rpow[k - 1].checked_mul(&r)?);
    }
    let mut binom = vec![BigInt::one(); n + 1];
    for i in 1..=n {
        binom[i] = &binom[i - 1] * (n - i + 1) / i;
    }
    let binom: Vec<I> = binom.iter().map(I::from_big).collect::<Option<_>>()?;
    let nums: Vec<I> = curve.numerators.iter().map(I::from_big).collect::<Option<_>>()?;
    let mut out = Vec::with_capacity(dim);
    for c in 0..dim {
        let mut s = binom[n].checked_mul(&nums[n * dim + c])?;
        for i in (0..n).rev() {
            let a = binom[i].checked_mul(&nums[i * dim + c])?;
            s = s.checked_mul(&pi)?.checked_add(&a.checked_mul(&rpow[n - i])?)?;
        }
        out.push(s.into());
    }
    Some(out)
}

/// The whole de Casteljau triangle at `t`, computed on integers (`β_i^r = (q−p)β_i^{r−1} +
/// pβ_{i+1}^{r−1}`, `b_i^r = β_i^r / (D q^r)`), each entry reduced once at the end.
pub fn triangle(curve: &BezierCurve<BigRational>, t: &BigRational) -> DeCasteljauTriangle<BigRational> {
    let ic = IntegerCurve::new(curve);
    let rows = integer_rows::<i128>(&ic, t.numer(), t.denom())
        .unwrap_or_else(|| integer_rows::<BigInt>(&ic, t.numer(), t.denom()).expect("BigInt does not overflow"));
    let dim = ic.dim;
    let mut scale = ic.denominator.clone();
    let mut out = Vec::with_capacity(rows.len());
    for row in rows {
        let pts = row
            .chunks(dim)
            .map(|c| Point::new(c.iter().map(|v| BigRational::new(v.clone(), scale.clone())).collect()))
            .collect();
        out.push(pts);
        scale *= t.denom();
    }
    DeCasteljauTriangle { rows: out }
}

/// Splits at `t0` (Lemma 2) on the fraction-free triangle; equal to
/// [`casteljau::subdivide`](crate::curve::casteljau::subdivide) over `BigRational`.
pub fn subdivide(
    curve: &BezierCurve<BigRational>,
    t0: &BigRational,
) -> (BezierCurve<BigRational>, BezierCurve<BigRational>) {
    let ic = IntegerCurve::new(curve);
    let (p, q) = (t0.numer(), t0.denom());
    let (left, right) = integer_edges::<i128>(&ic, p, q)
        .unwrap_or_else(|| integer_edges::<BigInt>(&ic, p, q).expect("BigInt does not overflow"));
    // b_0^r = β_0^r / (D q^r) on the left, b_{n−r}^r on the right (stored from r = n down)
    let dim = ic.dim;
    let n = ic.degree();
    let mut scales = Vec::with_capacity(n + 1);
    let mut scale = ic.denominator.clone();
    for _ in 0..=n {
        scales.push(scale.clone());
        scale *= q;
    }
    let point =
        |c: &[BigInt], s: &BigInt| Point::new(c.iter().map(|v| BigRational::new(v.clone(), s.clone())).collect());
    let l = left.chunks(dim).zip(&scales).map(|(c, s)| point(c, s)).collect();
    let r = right.chunks(dim).zip(scales.iter().rev()).map(|(c, s)| point(c, s)).collect();
    (BezierCurve::new(l).expect("n + 1 points"), BezierCurve::new(r).expect("n + 1 points"))
}

/// The two edges of the integer triangle: `β_0^r` for `r = 0..=n` (left polygon) and
/// `β_{n−r}^r` for `r = n..=0` (right polygon), flat, with `O(n)` memory; `None` on overflow.
fn integer_edges<I: Int>(curve: &IntegerCurve, p: &BigInt, q: &BigInt) -> Option<(Vec<BigInt>, Vec<BigInt>)> {
    let dim = curve.dim;
    let n = curve.degree();
    let pi = I::from_big(p)?;
    let r = I::from_big(&(q - p))?;
    let mut row: Vec<I> = curve.numerators.iter().map(I::from_big).collect::<Option<_>>()?;
    let mut left: Vec<BigInt> = Vec::with_capacity((n + 1) * dim);
    let mut right_rev: Vec<Vec<BigInt>> = Vec::with_capacity(n + 1);
    loop {
        left.extend(row[..dim].iter().cloned().map(Into::into));
        right_rev.push(row[row.len() - dim..].iter().cloned().map(Into::into).collect());
        if row.len() == dim {
            break;
        }
        for k in 0..row.len() - dim {
            row[k] = row[k].checked_mul(&r)?.checked_add(&row[k + dim].checked_mul(&pi)?)?;
        }
        row.truncate(row.len() - dim);
    }
    let right = right_rev.into_iter().rev().flatten().collect();
    Some((left, right))
}

/// [`casteljau::subdivide_repeatedly`](crate::curve::casteljau::subdivide_repeatedly) on the
/// fraction-free kernel: `2^depth` pieces, each split at its own local `t0`.
///
/// # Errors
/// [`Error::TooLarge`](crate::Error::TooLarge) for `depth` beyond
/// 16 (`MAX_SUBDIVISION_DEPTH`).
pub fn subdivide_repeatedly(
    curve: &BezierCurve<BigRational>,
    t0: &BigRational,
    depth: u32,
) -> Result<Vec<BezierCurve<BigRational>>> {
    crate::curve::casteljau::split_repeatedly(curve, depth, |c| subdivide(c, t0))
}

/// Integer triangle rows (flat), or `None` on overflow of `I`.
fn integer_rows<I: Int>(curve: &IntegerCurve, p: &BigInt, q: &BigInt) -> Option<Vec<Vec<BigInt>>> {
    let dim = curve.dim;
    let n = curve.degree();
    let pi = I::from_big(p)?;
    let r = I::from_big(&(q - p))?;
    let mut row: Vec<I> = curve.numerators.iter().map(I::from_big).collect::<Option<_>>()?;
    let mut rows = vec![curve.numerators.clone()];
    for _ in 1..=n {
        let next: Vec<I> = (0..row.len() - dim)
            .map(|k| row[k].checked_mul(&r)?.checked_add(&row[k + dim].checked_mul(&pi)?))
            .collect::<Option<_>>()?;
        rows.push(next.iter().cloned().map(Into::into).collect());
        row = next;
    }
    Some(rows)
}

impl IntegerCurve {
    /// The numerators as a curve over the integer-fast [`Rational`] (the curve scaled by `D`).
    fn scaled_curve(&self) -> BezierCurve<Rational> {
        let pts = self
            .numerators
            .chunks(self.dim)
            .map(|c| Point::new(c.iter().map(|v| Rational(BigRational::from_integer(v.clone()))).collect()))
            .collect();
        BezierCurve::new(pts).expect("an IntegerCurve has points")
    }

    /// Divides points computed on [`Self::scaled_curve`] by `D`: the one reduction.
    fn unscale(&self, pts: Vec<Point<Rational>>) -> Vec<Point<BigRational>> {
        let d = BigRational::from_integer(self.denominator.clone());
        pts.into_iter().map(|p| Point::new(p.coords.into_iter().map(|v| v.0 / &d).collect())).collect()
    }
}

/// Power-form coefficients, fraction-free: `c_k = C(n,k) Σ_{i≤k} (−1)^{k−i} C(k,i) Nᵢ / D`
/// with integer sums and one division per coefficient. Equal to
/// [`BezierCurve::power_coefficients`].
pub fn power_coefficients(curve: &BezierCurve<BigRational>) -> Vec<Point<BigRational>> {
    let ic = IntegerCurve::new(curve);
    ic.unscale(ic.scaled_curve().power_coefficients())
}

/// Degree elevation by `r`, fraction-free: integer sums `Σ_j C(r,i−j) C(n,j) N_j`, then one
/// division by `C(n+r,i)·D` per coordinate. Equal to [`BezierCurve::elevate`].
///
/// # Errors
/// As [`BezierCurve::elevate`].
pub fn elevate(curve: &BezierCurve<BigRational>, r: usize) -> Result<BezierCurve<BigRational>> {
    let ic = IntegerCurve::new(curve);
    let e = ic.scaled_curve().elevate(r)?;
    BezierCurve::new(ic.unscale(e.into_points()))
}

/// Exact degree reduction with the power form computed fraction-free: equal to
/// [`BezierCurve::reduce_degree`].
pub fn reduce_degree(curve: &BezierCurve<BigRational>) -> BezierCurve<BigRational> {
    let c = power_coefficients(curve);
    let m = (0..c.len()).rev().find(|&k| c[k].coords.iter().any(|x| !Scalar::is_zero(x))).unwrap_or(0);
    if m == curve.degree() {
        return curve.clone();
    }
    BezierCurve::new(crate::poly::bernstein::from_power(&c[..=m])).expect("non-empty")
}
