//! Binomials, Bernstein polynomials, and the power basis ↔ Bernstein basis conversion.
//!
//! `B_i^n(t) = C(n,i) tⁱ (1−t)ⁿ⁻ⁱ`. A curve `Σ bᵢ B_i^n(t)` has the power form `Σ c_k t^k`
//! with `c = A·b`, where `A[k][i] = (−1)^{k−i} C(n,k) C(k,i)` (seed 003's "matrix form"; for
//! `n = 3` the rows are `1 0 0 0 / −3 3 0 0 / 3 −6 3 0 / −1 3 −3 1`). The inverse is
//! `b_i = Σ_{k≤i} C(i,k)/C(n,k) · c_k`.

use crate::num::point::Point;
use crate::num::scalar::Scalar;
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, ToPrimitive};

/// The binomial coefficient `C(n, k)` (0 when `k > n`), exact.
///
/// # Example
/// ```
/// assert_eq!(casteljau::poly::binomial(5, 2), 10.into());
/// ```
pub fn binomial(n: usize, k: usize) -> BigInt {
    if k > n {
        return BigInt::from(0);
    }
    if n <= PASCAL_ROWS {
        return pascal()[n][k].clone();
    }
    let k = k.min(n - k);
    let mut c = BigInt::one();
    for i in 0..k {
        c = c * (n - i) / (i + 1);
    }
    c
}

/// Rows of Pascal's triangle kept in memory (the rest are computed on demand).
const PASCAL_ROWS: usize = 256;

fn pascal() -> &'static Vec<Vec<BigInt>> {
    static TABLE: std::sync::OnceLock<Vec<Vec<BigInt>>> = std::sync::OnceLock::new();
    TABLE.get_or_init(|| {
        let mut rows: Vec<Vec<BigInt>> = vec![vec![BigInt::one()]];
        for n in 1..=PASCAL_ROWS {
            let prev = &rows[n - 1];
            let row = (0..=n)
                .map(|k| match (k.checked_sub(1).and_then(|j| prev.get(j)), prev.get(k)) {
                    (Some(a), Some(b)) => a + b,
                    (Some(a), None) => a.clone(),
                    (None, Some(b)) => b.clone(),
                    (None, None) => unreachable!("k ≤ n"),
                })
                .collect();
            rows.push(row);
        }
        rows
    })
}

/// `C(n, k)` as a scalar (exact for exact scalars, rounded for `f64` when beyond 2⁵³).
pub fn binomial_scalar<S: Scalar>(n: usize, k: usize) -> S {
    let c = binomial(n, k);
    match c.to_i64() {
        Some(v) => S::from_i64(v),
        None => S::from_ratio(&BigRational::from_integer(c)),
    }
}

/// Row `n` of Pascal's triangle as scalars: `C(n, 0), …, C(n, n)`, by the recurrence
/// `C(n, k+1) = C(n, k)·(n−k)/(k+1)` on integers (`O(n)` operations).
pub fn binomial_row<S: Scalar>(n: usize) -> Vec<S> {
    let mut row = Vec::with_capacity(n + 1);
    let mut small: Option<i64> = Some(1);
    let mut big = BigInt::one();
    for k in 0..=n {
        row.push(match small {
            Some(v) => S::from_i64(v),
            None => S::from_ratio(&BigRational::from_integer(big.clone())),
        });
        if k < n {
            big = big * (n - k) / (k + 1);
            small = small.and_then(|v| v.checked_mul((n - k) as i64)).map(|v| v / (k as i64 + 1));
            if small.is_none() {
                small = big.to_i64();
            }
        }
    }
    row
}

/// `tᵏ` for `k = 0..=n`.
pub fn powers<S: Scalar>(t: &S, n: usize) -> Vec<S> {
    let mut p = Vec::with_capacity(n + 1);
    p.push(S::one());
    for k in 1..=n {
        let next = p[k - 1].clone() * t;
        p.push(next);
    }
    p
}

/// The Bernstein polynomial `B_i^n(t) = C(n,i) tⁱ (1−t)ⁿ⁻ⁱ` (0 when `i > n`).
///
/// # Example
/// ```
/// use casteljau::{poly::bernstein, ratio};
/// assert_eq!(bernstein(1, 3, &ratio(1, 3)), ratio(4, 9));
/// ```
pub fn bernstein<S: Scalar>(i: usize, n: usize, t: &S) -> S {
    if i > n {
        return S::zero();
    }
    let u = S::one() - t;
    binomial_scalar::<S>(n, i) * pow(t, i) * pow(&u, n - i)
}

/// All `B_0^n(t), …, B_n^n(t)` (they sum to 1: the partition of unity).
pub fn bernstein_all<S: Scalar>(n: usize, t: &S) -> Vec<S> {
    let tp = powers(t, n);
    let up = powers(&(S::one() - t), n);
    binomial_row::<S>(n).into_iter().enumerate().map(|(i, c)| c * &tp[i] * &up[n - i]).collect()
}

/// `x^e` by repeated squaring.
pub fn pow<S: Scalar>(x: &S, mut e: usize) -> S {
    let mut base = x.clone();
    let mut acc = S::one();
    while e > 0 {
        if e & 1 == 1 {
            acc = acc * &base;
        }
        e >>= 1;
        if e > 0 {
            base = base.clone() * &base;
        }
    }
    acc
}

/// The Bernstein sum `Σ bᵢ B_i^n(t)` evaluated term by term (an oracle independent of de
/// Casteljau's recursion).
pub fn bernstein_sum<S: Scalar>(points: &[Point<S>], t: &S) -> Point<S> {
    let n = points.len() - 1;
    let basis = bernstein_all(n, t);
    let mut acc = Point::origin(points[0].dim());
    for (b, p) in basis.iter().zip(points) {
        acc = acc.add(&p.scale(b));
    }
    acc
}

/// The conversion matrix `A` with `power coefficients = A · control points`:
/// `A[k][i] = (−1)^{k−i} C(n,k) C(k,i)` for `i ≤ k`, else 0.
///
/// # Example
/// ```
/// let a = casteljau::poly::bernstein_to_power_matrix(2);
/// let rows: Vec<Vec<i64>> = a.iter().map(|r| r.iter().map(|x| x.try_into().unwrap()).collect()).collect();
/// assert_eq!(rows, vec![vec![1, 0, 0], vec![-2, 2, 0], vec![1, -2, 1]]);
/// ```
pub fn bernstein_to_power_matrix(n: usize) -> Vec<Vec<BigInt>> {
    let pascal: Vec<Vec<BigInt>> = (0..=n).map(binomial_row::<BigRational>).map(integers).collect();
    (0..=n)
        .map(|k| {
            (0..=n)
                .map(|i| {
                    if i > k {
                        return BigInt::from(0);
                    }
                    let v = &pascal[n][k] * &pascal[k][i];
                    if (k - i) % 2 == 1 { -v } else { v }
                })
                .collect()
        })
        .collect()
}

fn integers(row: Vec<BigRational>) -> Vec<BigInt> {
    row.into_iter().map(|r| r.to_integer()).collect()
}

/// The inverse conversion matrix: `b_i = Σ_k M[i][k] c_k` with `M[i][k] = C(i,k) / C(n,k)`.
pub fn power_to_bernstein_matrix(n: usize) -> Vec<Vec<BigRational>> {
    (0..=n).map(|i| (0..=n).map(|k| BigRational::new(binomial(i, k), binomial(n, k))).collect()).collect()
}

/// Power-form coefficients `c_0, …, c_n` (vectors) of the curve with control points `points`:
/// `Σ bᵢ B_i^n(t) = Σ c_k t^k`, with `c_k = C(n,k) Σ_{i≤k} (−1)^{k−i} C(k,i) bᵢ = C(n,k) Δ^k b_0`
/// (computed as the forward-difference table: `n(n+1)/2` subtractions and `n + 1` scalings).
pub fn to_power<S: Scalar>(points: &[Point<S>]) -> Vec<Point<S>> {
    let n = points.len() - 1;
    let row_n = binomial_row::<S>(n);
    let mut diff = points.to_vec();
    let mut out = Vec::with_capacity(n + 1);
    for (k, c) in row_n.iter().enumerate() {
        out.push(if k == 0 || k == n { diff[0].clone() } else { diff[0].scale(c) });
        for i in 0..n - k {
            diff[i] = diff[i + 1].sub(&diff[i]);
        }
    }
    out
}

/// Control points of the degree-`n` curve `Σ c_k t^k` (`n = coeffs.len() − 1`):
/// `b_i = Σ_{k≤i} C(i,k)/C(n,k) · c_k`.
pub fn from_power<S: Scalar>(coeffs: &[Point<S>]) -> Vec<Point<S>> {
    let n = coeffs.len() - 1;
    let dim = coeffs[0].dim();
    let scaled: Vec<Point<S>> =
        binomial_row::<S>(n).iter().zip(coeffs).map(|(c, p)| p.scale(&(S::one() / c.clone()))).collect();
    (0..=n)
        .map(|i| {
            let row_i = binomial_row::<S>(i);
            let mut acc = Point::origin(dim);
            for k in 0..=i {
                acc = acc.add(&scaled[k].scale(&row_i[k]));
            }
            acc
        })
        .collect()
}

/// Horner evaluation of the power form `Σ c_k t^k` (the third oracle).
pub fn eval_power<S: Scalar>(coeffs: &[Point<S>], t: &S) -> Point<S> {
    let mut acc = coeffs.last().expect("at least one coefficient").clone();
    for c in coeffs.iter().rev().skip(1) {
        acc = acc.scale(t).add(c);
    }
    acc
}

/// De Casteljau's split of Bernstein coefficients on the integers: for `c` the coefficients of
/// `p` on `[a, b]` and `t = p_t/q_t` (`q_t > 0`), returns the coefficients of `p` on
/// `[a, a + t(b − a)]` and `[a + t(b − a), b]`, **both scaled by `q_tⁿ`** (a positive constant,
/// so signs and roots are unchanged): `β_i^r = (q_t − p_t)β_i^{r−1} + p_t β_{i+1}^{r−1}`, left
/// `β_0^r q_t^{n−r}`, right `β_r^{n−r} q_t^r`. No fraction is formed.
pub fn split_integer(c: &[BigInt], p: &BigInt, q: &BigInt) -> (Vec<BigInt>, Vec<BigInt>) {
    let n = c.len() - 1;
    let u = q - p;
    let mut q_pow = vec![BigInt::one()];
    for k in 1..=n {
        q_pow.push(&q_pow[k - 1] * q);
    }
    let mut row = c.to_vec();
    let mut left = vec![&row[0] * &q_pow[n]];
    let mut right = vec![BigInt::from(0); n + 1];
    right[n] = &row[n] * &q_pow[n];
    for r in 1..=n {
        row = (0..row.len() - 1).map(|i| &u * &row[i] + p * &row[i + 1]).collect();
        left.push(&row[0] * &q_pow[n - r]);
        right[n - r] = &row[n - r] * &q_pow[n - r];
    }
    (left, right)
}

/// The same split with exact rational coefficients and no scaling: the Bernstein coefficients
/// of `p` on `[0, t]` and `[t, 1]` (one common denominator, one reduction per coefficient).
///
/// # Example
/// ```
/// use casteljau::{rat, ratio, poly::split};
/// // 1 − 2t (coefficients 1, −1) on [0, 1/4] and [1/4, 1]
/// assert_eq!(split(&[rat(1), rat(-1)], &ratio(1, 4)), (vec![rat(1), ratio(1, 2)], vec![ratio(1, 2), rat(-1)]));
/// ```
pub fn split(c: &[BigRational], t: &BigRational) -> (Vec<BigRational>, Vec<BigRational>) {
    let d = c.iter().fold(BigInt::one(), |acc, x| num_integer::Integer::lcm(&acc, x.denom()));
    let ints: Vec<BigInt> = c.iter().map(|x| x.numer() * (&d / x.denom())).collect();
    let (l, r) = split_integer(&ints, t.numer(), t.denom());
    let scale = d * num_traits::Pow::pow(t.denom(), c.len() - 1);
    let back = |v: Vec<BigInt>| v.into_iter().map(|x| BigRational::new(x, scale.clone())).collect();
    (back(l), back(r))
}

/// The examples of the crate-internal items above, run as unit tests.
#[cfg(test)]
mod doc_examples {
    #[test]
    fn split_integer_example() {
        use super::split_integer;
        use num_bigint::BigInt;
        // (1 − 2t)² has coefficients 1, −1, 1; at t = 1/2 each half is scaled by 2² = 4
        let c: Vec<BigInt> = [1, -1, 1].map(BigInt::from).to_vec();
        let (l, r) = split_integer(&c, &BigInt::from(1), &BigInt::from(2));
        assert_eq!(l, [4, 0, 0].map(BigInt::from).to_vec());
        assert_eq!(r, [0, 0, 4].map(BigInt::from).to_vec());
    }
}
