//! A curve's integer power forms `(X, Y, W)` — the representation every exact step of
//! [`super`] works on — and the points they give at a parameter.

use crate::num::CheckedRing;
use crate::num::point::Point;
use crate::poly::Poly;
use crate::poly::algebraic::{RealAlgebraic, zv};
use crate::rational::RationalBezier;
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::One;

/// `(X, Y, W)` of a rational curve as integer power forms (one common positive scale).
pub(super) fn integer_forms(c: &RationalBezier<BigRational>) -> [Vec<BigInt>; 3] {
    forms_from_homogeneous(&homogeneous_rows(c))
}

/// `(X, Y, W)` as integer power forms from homogeneous control points `(wᵢxᵢ, wᵢyᵢ, wᵢ)`: every
/// number scaled by the lcm of the denominators, then `c_k = C(n,k) Δ^k b_0` (forward
/// differences) in integers.
pub(super) fn forms_from_homogeneous(rows: &[[BigRational; 3]]) -> [Vec<BigInt>; 3] {
    if let Some(f) = integer_forms_small(rows) {
        return f;
    }
    let scale = rows.iter().flatten().fold(BigInt::one(), |acc, x| {
        if x.denom().is_one() { acc } else { num_integer::Integer::lcm(&acc, x.denom()) }
    });
    let n = rows.len() - 1;
    [0, 1, 2].map(|k| {
        let mut diff: Vec<BigInt> = rows
            .iter()
            .map(|r| if r[k].denom() == &scale { r[k].numer().clone() } else { r[k].numer() * (&scale / r[k].denom()) })
            .collect();
        let mut out = Vec::with_capacity(n + 1);
        for j in 0..=n {
            out.push(&diff[0] * crate::poly::bernstein::binomial(n, j));
            for i in 0..n - j {
                diff[i] = &diff[i + 1] - &diff[i];
            }
        }
        zv::trim(out)
    })
}

/// [`forms_from_homogeneous`] in checked `i128` for integer control points that fit an `i64`
/// (the scale is then 1): the same forms, big integers made once at the end. `None` otherwise.
fn integer_forms_small(rows: &[[BigRational; 3]]) -> Option<[Vec<BigInt>; 3]> {
    use num_traits::ToPrimitive;
    let word = |x: &BigRational| if x.is_integer() { x.numer().to_i64() } else { None };
    let words: Vec<[i64; 3]> =
        rows.iter().map(|r| Some([word(&r[0])?, word(&r[1])?, word(&r[2])?])).collect::<Option<_>>()?;
    forms_of_words(&words)
}

/// `(X, Y, W)` of the polynomial curve with integer control points `points` (weights 1): as
/// [`forms_from_homogeneous`] gives them for those points. `None` on an overflow of `i128`.
pub(super) fn forms_from_integer_points(points: &[[i64; 2]]) -> Option<[Vec<BigInt>; 3]> {
    forms_of_words(&points.iter().map(|p| [p[0], p[1], 1]).collect::<Vec<_>>())
}

/// The forms of homogeneous integer control points: `c_k = C(n,k) Δ^k b_0` in checked `i128`.
fn forms_of_words(rows: &[[i64; 3]]) -> Option<[Vec<BigInt>; 3]> {
    let n = rows.len().checked_sub(1)?;
    let mut out: [Vec<BigInt>; 3] = Default::default();
    for (k, form) in out.iter_mut().enumerate() {
        let mut diff: Vec<i128> = rows.iter().map(|r| i128::from(r[k])).collect();
        let mut c = Vec::with_capacity(n + 1);
        let mut binomial: i128 = 1; // C(n, j)
        for j in 0..=n {
            c.push(diff[0].checked_mul(binomial)?);
            binomial = binomial.checked_mul((n - j) as i128)? / (j as i128 + 1);
            for i in 0..n - j {
                diff[i] = diff[i + 1].checked_sub(diff[i])?;
            }
        }
        *form = zv::trim(c.into_iter().map(BigInt::from).collect());
    }
    Some(out)
}

pub(super) fn to_rational(p: &[BigInt]) -> Poly<BigRational> {
    Poly::new(p.iter().map(|c| BigRational::from_integer(c.clone())).collect())
}

/// The coefficient of `t^k` (zero past the end).
pub(super) fn coefficient<T: CheckedRing>(p: &[T], k: usize) -> T {
    p.get(k).cloned().unwrap_or_else(T::zero)
}

/// `X/W` and `Y/W` are constant: every parameter gives one point.
pub(super) fn is_point(f: &[Vec<BigInt>; 3]) -> bool {
    if f[2].len() == 1 {
        // a constant weight (non-zero): X/W and Y/W are constant exactly when X and Y are
        return f[0].len() <= 1 && f[1].len() <= 1;
    }
    let parallel = |a: &[BigInt], w: &[BigInt]| {
        let n = a.len().max(w.len());
        (0..n)
            .all(|i| (i + 1..n).all(|j| coefficient(a, i) * coefficient(w, j) == coefficient(a, j) * coefficient(w, i)))
    };
    parallel(&f[0], &f[2]) && parallel(&f[1], &f[2])
}

/// The point `(X/W, Y/W)` at `x`.
pub(super) fn point_at(f: &[Vec<BigInt>; 3], x: &RealAlgebraic) -> [RealAlgebraic; 2] {
    let w = to_rational(&f[2]);
    [x.map_rational(&to_rational(&f[0]), &w), x.map_rational(&to_rational(&f[1]), &w)]
}

pub(super) fn rational_point(p: &[RealAlgebraic; 2]) -> Option<Point<BigRational>> {
    Some(Point::new(vec![p[0].to_rational()?.clone(), p[1].to_rational()?.clone()]))
}

/// The point `(X/W, Y/W)` at a rational parameter.
pub(super) fn point_at_rational(f: &[Vec<BigInt>; 3], x: &BigRational) -> Point<BigRational> {
    let eval = |p: &[BigInt]| crate::poly::algebraic::value_at(p, x);
    let w = eval(&f[2]);
    Point::new(vec![eval(&f[0]) / &w, eval(&f[1]) / &w])
}

/// The homogeneous control points `(wᵢxᵢ, wᵢyᵢ, wᵢ)`.
pub(super) fn homogeneous_rows(c: &RationalBezier<BigRational>) -> Vec<[BigRational; 3]> {
    c.homogeneous().points().iter().map(|p| [p.coords[0].clone(), p.coords[1].clone(), p.coords[2].clone()]).collect()
}

/// A polynomial cubic with integer control points `(v₀, v₁), …, (v₆, v₇)`, for tests.
#[cfg(test)]
pub(super) fn cubic(v: [i64; 8]) -> RationalBezier<BigRational> {
    use crate::num::scalar::rat;
    let pts = (0..4).map(|i| Point::new(vec![rat(v[2 * i]), rat(v[2 * i + 1])])).collect();
    RationalBezier::new(pts, vec![rat(1); 4]).unwrap()
}
