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
    // curves of degree ≤ 3 with word-sized coefficients: fixed arrays, no allocation
    if let Some(d) = eliminate_in_words(fa, fb, m) {
        return d;
    }
    let small_matrix = small(fa).zip(small(fb)).and_then(|(a, b)| implicit_matrix(&a, &b, m));
    let matrix: Vec<Vec<zv::P>> = match small_matrix {
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

/// A polynomial of degree ≤ 3 in fixed-size words (lowest degree first).
type Words = [i128; WORDS];

/// The coefficients of a polynomial of degree ≤ 3.
const WORDS: usize = 4;

/// [`eliminate`]'s implicit-matrix determinant for curves of degree ≤ 3 (order `m ≤ 3`) whose
/// forms' coefficients fit an `i64`, in fixed arrays of words: the Bézoutians and entries in
/// checked `i128`, the determinant by [`words_det`]; as [`zv::det`] gives it (trimmed). `None`
/// on an overflow or a larger degree (the general route decides then).
fn eliminate_in_words(fa: &[Vec<BigInt>; 3], fb: &[Vec<BigInt>; 3], m: usize) -> Option<zv::P> {
    use num_traits::ToPrimitive;
    if m > 3 {
        return None;
    }
    let words = |p: &[BigInt]| -> Option<Words> {
        let mut w = [0; WORDS];
        for (k, c) in p.iter().enumerate() {
            *w.get_mut(k)? = i128::from(c.to_i64()?);
        }
        Some(w)
    };
    let (a, b) = ([words(&fa[0])?, words(&fa[1])?, words(&fa[2])?], [words(&fb[0])?, words(&fb[1])?, words(&fb[2])?]);
    // the Bézoutian of formal degree m, as [`bezoutian`]
    let bz = |p: &Words, q: &Words| -> Option<[Words; WORDS]> {
        let n = m + 1;
        let mut out = [[0i128; WORDS]; WORDS];
        for j in 0..n {
            for i in (1..n).rev() {
                let prev = if j > 0 { out[i][j - 1] } else { 0 };
                let pij = mul64(p[i], q[j])?.checked_sub(mul64(p[j], q[i])?)?;
                out[i - 1][j] = pij.checked_add(prev)?;
            }
        }
        Some(out)
    };
    let (b1, b2, b3) = (bz(&b[2], &b[1])?, bz(&b[0], &b[2])?, bz(&b[0], &b[1])?);
    let mut e = [[[0i128; WORDS]; 3]; 3];
    for i in 0..m {
        for j in 0..m {
            for k in 0..WORDS {
                let w = mul64(a[2][k], b3[i][j])?;
                let x = mul64(a[0][k], b1[i][j])?;
                let y = mul64(a[1][k], b2[i][j])?;
                e[i][j][k] = w.checked_sub(x)?.checked_sub(y)?;
            }
        }
    }
    words_det(&e, m)
}

/// The determinant of the leading `m × m` block (`m ≤ 3`) of a matrix over `Z[s]` with entries
/// of degree ≤ 3 in words (as [`zv::det`] gives it: trimmed): the minors in checked `i128`, the
/// last products summed in [`Wide`] (up to ~2^190). `None` on an overflow.
fn words_det(e: &[[Words; 3]; 3], m: usize) -> Option<zv::P> {
    // a·b, degree ≤ 6, in checked i128
    let product = |a: &Words, b: &Words| -> Option<[i128; 2 * WORDS - 1]> {
        let mut out = [0i128; 2 * WORDS - 1];
        for (i, x) in a.iter().enumerate() {
            for (j, y) in b.iter().enumerate() {
                out[i + j] = out[i + j].checked_add(mul64(*x, *y)?)?;
            }
        }
        Some(out)
    };
    let minor = |(j, l): (usize, usize)| -> Option<[i128; 2 * WORDS - 1]> {
        let (p, q) = (product(&e[1][j], &e[2][l])?, product(&e[1][l], &e[2][j])?);
        let mut out = [0i128; 2 * WORDS - 1];
        for k in 0..out.len() {
            out[k] = p[k].checked_sub(q[k])?;
        }
        Some(out)
    };
    // Σ sign·a_j·b_j in wide sums
    let mut out = [Wide::default(); 3 * WORDS - 2];
    let mut wide = |sign: i128, a: &Words, b: &[i128]| -> Option<()> {
        for (i, x) in a.iter().enumerate() {
            for (j, y) in b.iter().enumerate() {
                out[i + j].add_product(if sign < 0 { x.checked_neg()? } else { *x }, *y)?;
            }
        }
        Some(())
    };
    match m {
        1 => wide(1, &e[0][0], &[1])?,
        2 => {
            wide(1, &e[0][0], &e[1][1])?;
            wide(-1, &e[0][1], &e[1][0])?;
        }
        3 => {
            wide(1, &e[0][0], &minor((1, 2))?)?;
            wide(-1, &e[0][1], &minor((0, 2))?)?;
            wide(1, &e[0][2], &minor((0, 1))?)?;
        }
        _ => return None,
    }
    Some(zv::trim(out.into_iter().map(Wide::to_bigint).collect()))
}

/// `a·b` checked, by one machine multiplication when both fit an `i64` (`i128::checked_mul`
/// is a library call).
fn mul64(a: i128, b: i128) -> Option<i128> {
    match (i64::try_from(a), i64::try_from(b)) {
        (Ok(x), Ok(y)) => Some(i128::from(x) * i128::from(y)),
        _ => a.checked_mul(b),
    }
}

/// A signed integer `h·2^64 + l` (`0 ≤ l < 2^64`), for sums of products of an `i64`-sized
/// factor and an `i128` one (up to ~2^190) without allocating.
#[derive(Clone, Copy, Default)]
struct Wide {
    h: i128,
    l: i128,
}

impl Wide {
    /// `self += a·b` for `a` that fits an `i64` (checked: `None` otherwise, or on an overflow of
    /// a long sum).
    fn add_product(&mut self, a: i128, b: i128) -> Option<()> {
        const LOW: i128 = (1 << 64) - 1;
        let a = i128::from(i64::try_from(a).ok()?);
        // b = (b >> 64)·2^64 + (b & LOW), the high part signed, the low part in [0, 2^64): with
        // |a| ≤ 2^63 neither product overflows
        let (bh, bl) = (b >> 64, b & LOW);
        self.h = self.h.checked_add(a * bh)?;
        let t = self.l.checked_add(a * bl)?;
        self.h = self.h.checked_add(t >> 64)?;
        self.l = t & LOW;
        Some(())
    }

    fn to_bigint(self) -> BigInt {
        match self.h.checked_mul(1 << 64).and_then(|h| h.checked_add(self.l)) {
            Some(v) => BigInt::from(v),
            None => (BigInt::from(self.h) << 64u32) + BigInt::from(self.l),
        }
    }
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
    // in checked i128 when the coefficients allow, else in BigInt
    let words = |p: &[BigInt]| p.iter().map(num_traits::ToPrimitive::to_i128).collect::<Option<Vec<i128>>>();
    let small = words(f).zip(words(w)).and_then(|(f, w)| bezoutian(&f, &w, n));
    let q: Vec<Vec<BigInt>> = match small {
        Some(q) => q.into_iter().map(|row| row.into_iter().map(BigInt::from).collect()).collect(),
        None => bezoutian(f, w, n).expect("BigInt arithmetic does not overflow"),
    };
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

    /// The word-sized determinant against [`zv::det`], on random matrices of order 1 to 3 with
    /// entries of degree ≤ 3 up to 2^62 (wide sums past 2^127) and small ones.
    #[test]
    fn words_determinant_matches_bareiss() {
        let mut word = crate::num::xorshift(0x0B5E_55ED_D0D0_CAFE);
        for round in 0..300 {
            let n = 1 + round % 3;
            let bits = [62, 40, 8][round % 3];
            let mut e = [[[0i128; WORDS]; 3]; 3];
            for entry in e.iter_mut().flatten().take(9) {
                let len = 1 + (word() % 4) as usize;
                for c in entry.iter_mut().take(len) {
                    *c = (word() as i64 >> (64 - bits)) as i128;
                }
            }
            let big: Vec<Vec<zv::P>> = (0..n)
                .map(|i| (0..n).map(|j| zv::trim(e[i][j].iter().map(|&c| BigInt::from(c)).collect())).collect())
                .collect();
            let expected = zv::det(big);
            match words_det(&e, n) {
                Some(d) => assert_eq!(d, expected, "{e:?}"),
                None => assert!(bits == 62 && n == 3, "declined {e:?}"),
            }
        }
    }

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
            let pp = crate::poly::integer::primitive_part;
            assert_eq!(pp(sylvester), pp(bezout), "round {round}");
        }
    }
}
