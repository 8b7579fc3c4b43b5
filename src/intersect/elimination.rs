//! Elimination: the polynomial in one curve's parameter whose roots contain every
//! intersection's parameter — the implicit (Bézout, moving-line) matrix's determinant, or the
//! Sylvester resultant — and the Bézoutian recurrence and divided differences it is built from.

use super::forms::coefficient;
use crate::num::CheckedRing;
use crate::poly::algebraic::{resultant_zv, zv};
use num_bigint::BigInt;

/// `F(s) W_B(t) − G(t) W_A(s)` as a polynomial in `t` with coefficients in `Z[s]`.
pub(super) fn cross_system(fa: &[BigInt], wa: &[BigInt], fb: &[BigInt], wb: &[BigInt]) -> Vec<zv::P> {
    let len = fb.len().max(wb.len());
    let mut out: Vec<zv::P> = (0..len)
        .map(|j| {
            let (w, g) = (coefficient(wb, j), coefficient(fb, j));
            // fa·w_j − g_j·wa
            let a: zv::P = fa.iter().map(|c| c * &w).collect();
            let b: zv::P = wa.iter().map(|c| c * &g).collect();
            zv::sub(&zv::trim(a), &zv::trim(b))
        })
        .collect();
    while out.last().is_some_and(|c| c.is_empty()) {
        out.pop();
    }
    out
}

/// A polynomial in `s` whose roots are the parameters where `A(s)` lies on `B`'s curve:
/// `Res_t(X_A(s)W_B(t) − X_B(t)W_A(s), Y_A(s)W_B(t) − Y_B(t)W_A(s))` up to a constant and the
/// factor `W_A(s)^m`. When both equations have one degree `m` in `t`, it is the determinant of
/// `B`'s implicit (Bézout) matrix at `A(s)`: `f(t)g(u) − f(u)g(t) = w·(t − u)·Σ M_ij t^i u^j`
/// with `M(x, y, w) = −x·Bz(W_B, Y_B) − y·Bz(X_B, W_B) + w·Bz(X_B, Y_B)`, `Bz(p, q)` the
/// Bézoutian `(p(t)q(u) − p(u)q(t))/(t − u)` — an `m × m` determinant (Sederberg's moving-line
/// matrix) instead of the `2m × 2m` Sylvester one, and `det M(x, y, w) = 0` is `B`'s implicit
/// equation. Otherwise (a line parallel to an axis, say) the Sylvester resultant.
pub(super) fn eliminate(fa: &[Vec<BigInt>; 3], fb: &[Vec<BigInt>; 3]) -> zv::P {
    let (df, dg) = (cross_degree(&fa[0], &fa[2], &fb[0], &fb[2]), cross_degree(&fa[1], &fa[2], &fb[1], &fb[2]));
    if df != dg || df.is_none_or(|d| d < 1) {
        let f = cross_system(&fa[0], &fa[2], &fb[0], &fb[2]);
        let g = cross_system(&fa[1], &fa[2], &fb[1], &fb[2]);
        return resultant_zv(&f, &g);
    }
    let m = df.unwrap_or_default();
    // in checked i128 when the coefficients allow (no allocation), else in BigInt
    let small = |f: &[Vec<BigInt>; 3]| -> Option<[Vec<i128>; 3]> {
        let row = |p: &[BigInt]| p.iter().map(num_traits::ToPrimitive::to_i128).collect::<Option<Vec<i128>>>();
        Some([row(&f[0])?, row(&f[1])?, row(&f[2])?])
    };
    let matrix: Vec<Vec<zv::P>> = match small(fa).zip(small(fb)).and_then(|(a, b)| implicit_matrix(&a, &b, m)) {
        Some(mm) => mm
            .into_iter()
            .map(|row| row.into_iter().map(|e| zv::trim(e.into_iter().map(BigInt::from).collect())).collect())
            .collect(),
        None => implicit_matrix(fa, fb, m)
            .expect("BigInt arithmetic does not overflow")
            .into_iter()
            .map(|row| row.into_iter().map(zv::trim).collect())
            .collect(),
    };
    zv::det(matrix)
}

/// [`eliminate`]'s implicit matrix `M(A(s))` of order `m`, entries polynomials in `s`:
/// `M_ij = W_A·Bz(X_B, Y_B)_ij − X_A·Bz(W_B, Y_B)_ij − Y_A·Bz(X_B, W_B)_ij`. `None` on an overflow.
fn implicit_matrix<T: CheckedRing>(fa: &[Vec<T>; 3], fb: &[Vec<T>; 3], m: usize) -> Option<Vec<Vec<Vec<T>>>> {
    let (b1, b2, b3) = (bezoutian(&fb[2], &fb[1], m)?, bezoutian(&fb[0], &fb[2], m)?, bezoutian(&fb[0], &fb[1], m)?);
    let len = fa.iter().map(Vec::len).max().unwrap_or(0);
    (0..m)
        .map(|i| {
            (0..m)
                .map(|j| {
                    (0..len)
                        .map(|k| {
                            let w = coefficient(&fa[2], k).mul(&b3[i][j])?;
                            let x = coefficient(&fa[0], k).mul(&b1[i][j])?;
                            let y = coefficient(&fa[1], k).mul(&b2[i][j])?;
                            w.sub(&x)?.sub(&y)
                        })
                        .collect()
                })
                .collect()
        })
        .collect()
}

/// The degree in `t` of [`cross_system`]`(fa, wa, fb, wb)` (`None` when it vanishes), without
/// building it: the largest `j` with `fa·w_j ≠ g_j·wa` (`w_j`, `g_j` the coefficients of `t^j`).
fn cross_degree(fa: &[BigInt], wa: &[BigInt], fb: &[BigInt], wb: &[BigInt]) -> Option<usize> {
    let n = fa.len().max(wa.len());
    (0..fb.len().max(wb.len())).rev().find(|&j| {
        let (w, g) = (coefficient(wb, j), coefficient(fb, j));
        (0..n).any(|k| coefficient(fa, k) * &w != coefficient(wa, k) * &g)
    })
}

/// The Bézoutian of `p` and `q` in formal degree `m`: the `m × m` matrix `Q` with
/// `p(t)q(u) − p(u)q(t) = (t − u)·Σ Q_ij t^i u^j`. From `P_ij = p_i q_j − p_j q_i` and
/// `P_ij = Q_(i−1)j − Q_i(j−1)`: `Q_(i−1)j = P_ij + Q_i(j−1)`. One recurrence for every use:
/// integers (the implicit matrix, in `i128` or `BigInt`; the divided differences) and `f64`
/// enclosures ([`filter::no_common_root`](super::filter::no_common_root)). `None` on an overflow.
pub(super) fn bezoutian<T: CheckedRing>(p: &[T], q: &[T], m: usize) -> Option<Vec<Vec<T>>> {
    let n = m + 1;
    let mut out = vec![vec![T::zero(); n]; n];
    for j in 0..n {
        for i in (1..n).rev() {
            let prev = if j > 0 { out[i][j - 1].clone() } else { T::zero() };
            let pij = coefficient(p, i).mul(&coefficient(q, j))?.sub(&coefficient(p, j).mul(&coefficient(q, i))?)?;
            out[i - 1][j] = pij.add(&prev)?;
        }
    }
    out.truncate(m);
    for row in &mut out {
        row.truncate(m);
    }
    Some(out)
}

/// `(F(s)W(t) − F(t)W(s)) / (s − t)` as a polynomial in `t` with coefficients in `Z[s]`.
pub(super) fn divided_difference(f: &[BigInt], w: &[BigInt]) -> Vec<zv::P> {
    // Q[i][j], the coefficient of s^i t^j: the Bézoutian of f and w in formal degree n
    let n = f.len().max(w.len());
    let q = bezoutian(f, w, n).expect("BigInt arithmetic does not overflow");
    let mut out: Vec<zv::P> = (0..n).map(|j| zv::trim((0..n).map(|i| q[i][j].clone()).collect())).collect();
    while out.last().is_some_and(|c| c.is_empty()) {
        out.pop();
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::intersect::forms::integer_forms;
    use crate::num::point::Point;
    use crate::num::scalar::rat;
    use crate::rational::RationalBezier;
    use num_bigint::BigInt;
    use num_rational::BigRational;

    /// The implicit-matrix elimination against the Sylvester resultant: equal up to a constant
    /// and the factor `W_A^m`, on random polynomial and rational cubics, quadratics and lines.
    #[test]
    fn bezout_elimination_matches_sylvester() {
        let mut next = crate::num::symmetric(0x1234_5678_9ABC_DEF1);
        for round in 0..40 {
            let degree = |r: usize| [3, 2, 1, 3][r % 4];
            // every seventh round with coordinates near 2^70 (the BigInt route of the matrix)
            let huge = if round % 7 == 0 { BigRational::from_integer(BigInt::from(1) << 70u32) } else { rat(1) };
            let mut curve = |n: usize, rational: bool| {
                let mut c = || rat(next(60)) * &huge + rat(next(60));
                let pts = (0..=n).map(|_| Point::new(vec![c(), c()])).collect();
                let w = (0..=n).map(|_| if rational { rat(next(5).abs() + 1) } else { rat(1) }).collect();
                RationalBezier::new(pts, w).unwrap()
            };
            let (a, b) = (curve(degree(round), round % 3 == 0), curve(degree(round / 4), round % 5 == 0));
            let (fa, fb) = (integer_forms(&a), integer_forms(&b));
            let sylvester = resultant_zv(
                &cross_system(&fa[0], &fa[2], &fb[0], &fb[2]),
                &cross_system(&fa[1], &fa[2], &fb[1], &fb[2]),
            );
            let mut bezout = eliminate(&fa, &fb);
            let m = cross_system(&fa[0], &fa[2], &fb[0], &fb[2]).len() - 1;
            for _ in 0..m {
                bezout = zv::mul(&bezout, &fa[2]);
            }
            let pp = crate::poly::polynomial::primitive_part;
            assert_eq!(pp(sylvester), pp(bezout), "round {round}");
        }
    }
}
