//! Polynomials over `Z[v]` and resultants: the arithmetic of polynomials in `v` with integer
//! coefficients ([`zv`]: product, difference, exact division, the Bareiss determinant), and
//! `Res_t` of polynomials in `t` whose coefficients lie in `Z[v]` (Sylvester determinants). Used
//! for the images of algebraic numbers under rational maps ([`crate::poly::algebraic`]) and by
//! the intersection code's elimination. Hand-written: the determinants are fraction-free
//! (every Bareiss division exact), which no polynomial crate offers over `Z[v]`.

use num_bigint::BigInt;
use num_traits::One;

/// Polynomials in `v` with integer coefficients (lowest degree first), for resultants.
pub(crate) mod zv {
    use num_bigint::BigInt;
    use num_traits::Zero;

    pub type P = Vec<BigInt>;

    pub fn trim(mut p: P) -> P {
        while p.last().is_some_and(Zero::is_zero) {
            p.pop();
        }
        p
    }

    pub fn mul(a: &P, b: &P) -> P {
        if a.is_empty() || b.is_empty() {
            return vec![];
        }
        if let (Some(x), Some(y)) = (small(a), small(b)) {
            // every product below 2^120 and at most 64 of them per sum: i128 holds it exactly
            if x.len().min(y.len()) <= 64 {
                let mut out = vec![0i128; x.len() + y.len() - 1];
                for (i, &u) in x.iter().enumerate() {
                    for (j, &v) in y.iter().enumerate() {
                        out[i + j] += i128::from(u) * i128::from(v);
                    }
                }
                return trim(out.into_iter().map(BigInt::from).collect());
            }
        }
        let mut out = vec![BigInt::zero(); a.len() + b.len() - 1];
        for (i, x) in a.iter().enumerate() {
            if x.is_zero() {
                continue;
            }
            for (j, y) in b.iter().enumerate() {
                out[i + j] += x * y;
            }
        }
        trim(out)
    }

    /// The coefficients as `i64`s when every one is below `2^60` in magnitude.
    fn small(a: &P) -> Option<Vec<i64>> {
        a.iter().map(|c| if c.bits() <= 60 { num_traits::ToPrimitive::to_i64(c) } else { None }).collect()
    }

    pub fn sub(a: &P, b: &P) -> P {
        let mut out = vec![BigInt::zero(); a.len().max(b.len())];
        for (i, x) in a.iter().enumerate() {
            out[i] += x;
        }
        for (i, y) in b.iter().enumerate() {
            out[i] -= y;
        }
        trim(out)
    }

    /// `a / b` when `b` divides `a` exactly over `Z[v]`.
    pub fn div_exact(a: &P, b: &P) -> P {
        let mut r = a.clone();
        if r.is_empty() {
            return vec![];
        }
        let db = b.len() - 1;
        let lb = &b[db];
        let mut q = vec![BigInt::zero(); r.len().saturating_sub(db).max(1)];
        while r.len() > db {
            let k = r.len() - 1 - db;
            let c = &r[r.len() - 1] / lb;
            for (i, y) in b.iter().enumerate() {
                let t = &c * y;
                r[k + i] -= t;
            }
            q[k] = c;
            // the top coefficient is zero when the division is exact; drop it either way
            r.pop();
            r = trim(r);
        }
        debug_assert!(r.is_empty(), "inexact division in Z[v]");
        trim(q)
    }

    /// The determinant of a square matrix over `Z[v]` (Bareiss: every division is exact).
    pub fn det(mut m: Vec<Vec<P>>) -> P {
        let n = m.len();
        // small orders by cofactors: no exact divisions (Bareiss divides by the previous pivot)
        let minor = |m: &[Vec<P>], (i, k): (usize, usize), (j, l): (usize, usize)| {
            sub(&mul(&m[i][j], &m[k][l]), &mul(&m[i][l], &m[k][j]))
        };
        match n {
            0 => return vec![BigInt::from(1)],
            1 => return m[0][0].clone(),
            2 => return minor(&m, (0, 1), (0, 1)),
            3 => {
                let t0 = mul(&m[0][0], &minor(&m, (1, 2), (1, 2)));
                let t1 = mul(&m[0][1], &minor(&m, (1, 2), (0, 2)));
                let t2 = mul(&m[0][2], &minor(&m, (1, 2), (0, 1)));
                return sub(&sub(&t0, &t1), &sub(&vec![], &t2));
            }
            _ => {}
        }
        let mut negate = false;
        let mut prev: P = vec![BigInt::from(1)];
        for k in 0..n {
            if m[k][k].is_empty() {
                let Some(i) = (k + 1..n).find(|&i| !m[i][k].is_empty()) else { return vec![] };
                m.swap(k, i);
                negate = !negate;
            }
            if k + 1 == n {
                break;
            }
            for i in k + 1..n {
                for j in k + 1..n {
                    let t = sub(&mul(&m[k][k], &m[i][j]), &mul(&m[i][k], &m[k][j]));
                    m[i][j] =
                        if prev.len() == 1 && num_traits::One::is_one(&prev[0]) { t } else { div_exact(&t, &prev) };
                }
            }
            prev = m[k][k].clone();
        }
        let d = m[n - 1][n - 1].clone();
        if negate { d.into_iter().map(|x| -x).collect() } else { d }
    }
}

/// `Res_t(p(t), q(t))` where `q`'s coefficients are polynomials in `v` (Sylvester matrix).
pub(crate) fn resultant_in_v(p: &[BigInt], q: &[zv::P]) -> zv::P {
    let constants: Vec<zv::P> = p.iter().map(|c| zv::trim(vec![c.clone()])).collect();
    resultant_zv(&constants, q)
}

/// `Res_t(f, g)` where both have coefficients in `Z[v]` (lowest degree in `t` first; no
/// trailing zero coefficients): the Sylvester determinant, by Bareiss.
pub(crate) fn resultant_zv(f: &[zv::P], g: &[zv::P]) -> zv::P {
    let (m, n) = (f.len().saturating_sub(1), g.len().saturating_sub(1));
    let size = m + n;
    if size == 0 {
        return vec![BigInt::one()];
    }
    let mut rows: Vec<Vec<zv::P>> = vec![];
    for r in 0..n {
        let mut row = vec![vec![]; size];
        for (i, c) in f.iter().rev().enumerate() {
            row[r + i] = c.clone();
        }
        rows.push(row);
    }
    for r in 0..m {
        let mut row = vec![vec![]; size];
        for (i, c) in g.iter().rev().enumerate() {
            row[r + i] = c.clone();
        }
        rows.push(row);
    }
    zv::det(rows)
}
