//! The exact numbers a finding carries, and the small vector arithmetic of the checks.

use crate::num::point::Point;
use crate::num::quadratic_field::QuadraticExt;
use crate::num::scalar::{Exact, Scalar, rat};
use crate::poly::algebraic::RealAlgebraic;
use num_rational::BigRational;
use serde::Serialize;
use std::cmp::Ordering;
use std::fmt;

/// An exact real number of a finding: a rational, an element `a + b·√d` of a quadratic field
/// (the parameters and points of a cubic's extrema), or a real algebraic number (a crossing of
/// two curves). Each form is canonical (a reduced rational; `a + b·√d` with `d` square-free
/// and `b ≠ 0`; the root of a square-free polynomial in its canonical interval), so two
/// values of one form are equal exactly when their strings are. Serialized as its string.
///
/// # Example
/// ```
/// use casteljau::lint::ExactValue;
/// use casteljau::QuadraticExt;
/// use casteljau::rat;
/// let half = ExactValue::from(QuadraticExt::from_base(rat(1) / rat(2)));
/// assert_eq!(half, ExactValue::Rational(rat(1) / rat(2)));
/// let r = ExactValue::from(QuadraticExt::sqrt(rat(12)));
/// assert_eq!(r.to_string(), "2*sqrt(3)");
/// assert_eq!(serde_json::to_string(&r).unwrap(), r#""2*sqrt(3)""#);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub enum ExactValue {
    /// A rational number.
    Rational(BigRational),
    /// `a + b·√d`, irrational.
    Quadratic(QuadraticExt<BigRational>),
    /// A real algebraic number of higher degree (or one not brought to the other forms).
    Algebraic(RealAlgebraic),
}

impl From<BigRational> for ExactValue {
    fn from(r: BigRational) -> Self {
        ExactValue::Rational(r)
    }
}

impl From<QuadraticExt<BigRational>> for ExactValue {
    fn from(q: QuadraticExt<BigRational>) -> Self {
        match q.to_base() {
            Some(r) => ExactValue::Rational(r),
            None => ExactValue::Quadratic(q),
        }
    }
}

impl From<RealAlgebraic> for ExactValue {
    fn from(a: RealAlgebraic) -> Self {
        match a.to_rational() {
            Some(r) => ExactValue::Rational(r.clone()),
            None => ExactValue::Algebraic(a),
        }
    }
}

impl ExactValue {
    /// The nearest `f64` (correctly rounded).
    ///
    /// # Example
    /// ```
    /// use casteljau::lint::ExactValue;
    /// assert_eq!(ExactValue::from(casteljau::rat(3) / casteljau::rat(4)).to_f64(), 0.75);
    /// ```
    pub fn to_f64(&self) -> f64 {
        match self {
            ExactValue::Rational(r) => r.to_f64(),
            ExactValue::Quadratic(q) => q.to_f64(),
            ExactValue::Algebraic(a) => a.to_f64(),
        }
    }
}

impl fmt::Display for ExactValue {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ExactValue::Rational(r) => write!(f, "{r}"),
            ExactValue::Quadratic(q) => write!(f, "{q}"),
            ExactValue::Algebraic(a) => write!(f, "{a}"),
        }
    }
}

impl Serialize for ExactValue {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.collect_str(self)
    }
}

/// A planar vector with rational coordinates.
pub(crate) type V = [BigRational; 2];

pub(crate) fn v(p: &Point<BigRational>) -> V {
    [p.coords[0].clone(), p.coords[1].clone()]
}

pub(crate) fn sub(a: &V, b: &V) -> V {
    [&a[0] - &b[0], &a[1] - &b[1]]
}

pub(crate) fn cross(a: &V, b: &V) -> BigRational {
    &a[0] * &b[1] - &a[1] * &b[0]
}

pub(crate) fn dot(a: &V, b: &V) -> BigRational {
    &a[0] * &b[0] + &a[1] * &b[1]
}

/// The exact signed area enclosed by a polynomial Bézier segment and the origin,
/// `½∫₀¹ (x y′ − y x′) dt`, from its control points (`×` the planar cross product):
///
/// * line: `½ P0×P1`;
/// * quadratic: `(2 P0×P1 + P0×P2 + 2 P1×P2) / 6`;
/// * cubic: `(6 P0×P1 + 3 P0×P2 + P0×P3 + 3 P1×P2 + 3 P1×P3 + 6 P2×P3) / 20`.
///
/// Summed over a closed contour this is Green's theorem: the contour's signed area, positive
/// counter-clockwise (with the y axis up).
pub(crate) fn segment_area(ps: &[Point<BigRational>]) -> BigRational {
    if let Some(d) = doubled_all(ps) {
        // the same sums on the doubled points in i128 (four times the area's numerators)
        let c = |i: usize, j: usize| d[i][0] as i128 * d[j][1] as i128 - d[j][0] as i128 * d[i][1] as i128;
        let (sum, den) = match d.len() {
            2 => (c(0, 1), 2),
            3 => (c(0, 1) * 2 + c(0, 2) + c(1, 2) * 2, 6),
            4 => (c(0, 1) * 6 + c(0, 2) * 3 + c(0, 3) + c(1, 2) * 3 + c(1, 3) * 3 + c(2, 3) * 6, 20),
            _ => (0, 1),
        };
        return BigRational::new(sum.into(), (4 * den).into());
    }
    let p: Vec<V> = ps.iter().map(v).collect();
    let c = |i: usize, j: usize| cross(&p[i], &p[j]);
    match p.len() {
        2 => c(0, 1) / rat(2),
        3 => (c(0, 1) * rat(2) + c(0, 2) + c(1, 2) * rat(2)) / rat(6),
        4 => {
            (c(0, 1) * rat(6) + c(0, 2) * rat(3) + c(0, 3) + c(1, 2) * rat(3) + c(1, 3) * rat(3) + c(2, 3) * rat(6))
                / rat(20)
        }
        _ => rat(0),
    }
}

/// `x` in the open interval `(0, 1)`.
pub(crate) fn strictly_inside<K: Exact>(x: &K) -> bool {
    x.sign() == Ordering::Greater && (K::one() - x).sign() == Ordering::Greater
}

/// Largest doubled coordinate the word-sized screens take: products of two differences and
/// their squares stay far inside `i128`.
const SMALL: i64 = 1 << 40;

/// `2p` when both coordinates are integers or halves (font units: `glyf` points and their
/// implied midpoints, integral CFF points) of magnitude below 2^39: the word-sized screens of
/// the checks work on these exactly.
pub(crate) fn doubled(p: &Point<BigRational>) -> Option<[i64; 2]> {
    use num_traits::ToPrimitive;
    let one = |c: &BigRational| -> Option<i64> {
        let n = c.numer().to_i64()?;
        let v = match c.denom().to_i64()? {
            1 => n.checked_mul(2)?,
            2 => n,
            _ => return None,
        };
        (v.abs() < SMALL).then_some(v)
    };
    Some([one(&p.coords[0])?, one(&p.coords[1])?])
}

/// The doubled control points of a segment, when every one is small ([`doubled`]).
pub(crate) fn doubled_all(ps: &[Point<BigRational>]) -> Option<Vec<[i64; 2]>> {
    ps.iter().map(doubled).collect()
}
