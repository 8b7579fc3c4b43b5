//! Integer polynomials reduced modulo word-sized primes: what their factorization modulo `q`
//! says about their factors over `Q`.
//!
//! If `q` does not divide the leading coefficient of `p` and `p mod q` is square-free, a
//! factorization `p = g·h` over `Z` (Gauss's lemma: every factor over `Q` is one over `Z` up to
//! a constant) reduces to one modulo `q` with the same degrees, so the degree of any factor of
//! `p` over `Q` is a sum of degrees of irreducible factors of `p mod q`. The distinct-degree
//! factorization (Cantor–Zassenhaus, first stage: `gcd(f, x^(q^i) − x)` collects the
//! irreducible factors of degree `i`) gives those degrees without splitting further; the
//! achievable sums, intersected over several primes, bound the degree of every factor from
//! below — `deg p` itself when `p` is proved irreducible.
//!
//! Written by hand: the crates that factor over finite fields pull in a computer-algebra
//! system for what is a hundred lines of word arithmetic here.

use num_bigint::BigInt;

/// Primes between `2^8` and `2^9`, of every residue class mod 8 and mod 3 (primes of one class
/// would split the same small factors every time): raising to the `q`-th power takes eight
/// squarings, and sums of a hundred products of residues fit a `u32`. A prime dividing the
/// leading coefficient or the discriminant is skipped; with sixteen of them, that costs nothing
/// in practice.
const PRIMES: [u32; 16] = [257, 263, 269, 271, 277, 281, 283, 293, 307, 311, 313, 317, 331, 337, 347, 349];

/// A polynomial over `Z/qZ`, lowest degree first, no trailing zeros.
type Poly = Vec<u32>;

/// A lower bound, capped at `enough`, for the degree of every non-constant factor of `p` over
/// `Q` (integer coefficients, lowest degree first, degree ≥ 1): the smallest achievable sum of
/// distinct-degree factor degrees, over the primes tried (see the module documentation). Only
/// factors of degree below `enough` are sought, and the search stops once the bound reaches
/// it; `1` when nothing is proved (degree above 127, or no usable prime).
pub fn min_factor_degree(p: &[BigInt], enough: usize) -> usize {
    let n = p.len().saturating_sub(1);
    if n <= 1 {
        return n;
    }
    if n > 127 {
        return 1;
    }
    // bit k: a factor of degree k is still possible
    let mut possible: u128 = u128::MAX >> (127 - n);
    let mut bound = 1;
    let enough = enough.clamp(1, n);
    for &q in &PRIMES {
        let Some(degrees) = factor_degrees(p, q, enough) else { continue };
        let mut sums: u128 = 1;
        for d in degrees {
            sums |= sums << d;
        }
        possible &= sums;
        bound = ((possible & !1).trailing_zeros() as usize).min(enough);
        if bound >= enough {
            break;
        }
    }
    bound
}

/// The degrees of the irreducible factors of `p mod q` of degree below `below` (with
/// repetition), then the degree of the product of the others (if any; every sum of degrees
/// below `below` is then exact), when `q` does not divide the leading coefficient and `p mod q`
/// is square-free; `None` otherwise.
fn factor_degrees(p: &[BigInt], q: u32, below: usize) -> Option<Vec<usize>> {
    let f = reduce(p, q);
    if f.len() != p.len() {
        return None;
    }
    let df = trim((1..f.len()).map(|k| (f[k] as usize * k % q as usize) as u32).collect());
    if gcd(f.clone(), df, q).len() != 1 {
        return None;
    }
    let mut f = monic(f, q);
    let mut out = vec![];
    // h = x^(q^i) mod f₀ (the whole polynomial), by the Frobenius map (linear over Z/q):
    // h(x)^q = Σ h_k x^(qk); the factor f left over divides f₀, so h is x^(q^i) mod f as well
    // once reduced (the gcd reduces it)
    let mut h: Poly = rem(vec![0, 1], &f, q);
    let rows = frobenius_matrix(&f, q);
    let mut i = 0;
    while f.len() > 1 {
        i += 1;
        if 2 * i > f.len() - 1 || i >= below {
            out.push(f.len() - 1); // irreducible, or factors of degree ≥ below only
            break;
        }
        h = frobenius(&h, &rows, q);
        let mut hx = h.clone();
        hx.resize(hx.len().max(2), 0);
        hx[1] = (hx[1] + q - 1) % q;
        let g = gcd(f.clone(), trim(hx), q);
        if g.len() > 1 {
            out.extend(std::iter::repeat_n(i, (g.len() - 1) / i));
            f = div_exact(&f, &g, q);
        }
    }
    Some(out)
}

/// `p mod q`, residues in `[0, q)`.
fn reduce(p: &[BigInt], q: u32) -> Poly {
    trim(p.iter().map(|c| crate::num::word::residue(c, u64::from(q)) as u32).collect())
}

fn trim(mut p: Poly) -> Poly {
    while p.last() == Some(&0) {
        p.pop();
    }
    p
}

fn inverse(a: u32, q: u32) -> u32 {
    // a^(q−2) mod q
    let (mut base, mut e, mut acc) = (a % q, q - 2, 1u32);
    while e > 0 {
        if e & 1 == 1 {
            acc = acc * base % q;
        }
        base = base * base % q;
        e >>= 1;
    }
    acc
}

fn monic(p: Poly, q: u32) -> Poly {
    let li = inverse(*p.last().expect("non-zero"), q);
    p.into_iter().map(|c| c * li % q).collect()
}

/// `x mod q` by Barrett reduction with `m = ⌊2^64 / q⌋` (the estimate of `⌊x/q⌋` is low by
/// at most one): a multiplication instead of a division.
fn barrett(x: u64, q: u64, m: u64) -> u64 {
    let r = x - ((u128::from(x) * u128::from(m)) >> 64) as u64 * q;
    if r >= q { r - q } else { r }
}

/// `a mod b` (`b` non-zero; `a`'s entries below `2^31`, reduced or not).
fn rem(a: Poly, b: &[u32], q: u32) -> Poly {
    if a.len() < b.len() {
        return trim(a.into_iter().map(|v| v % q).collect());
    }
    let li = u64::from(inverse(*b.last().expect("non-zero"), q));
    let (q64, qq) = (u64::from(q), u64::from(q) * u64::from(q));
    let m = u64::MAX / q64;
    // lazy: each step adds q² − f·c (< 2^20) to an entry, reduced only where the next leading
    // coefficient is read and at the end
    let mut acc: Vec<u64> = a.into_iter().map(u64::from).collect();
    while acc.len() >= b.len() {
        let f = barrett(barrett(*acc.last().expect("non-empty"), q64, m) * li, q64, m);
        let shift = acc.len() - b.len();
        for (i, c) in b.iter().enumerate() {
            acc[shift + i] += qq - f * u64::from(*c);
        }
        acc.pop();
    }
    trim(acc.into_iter().map(|v| barrett(v, q64, m) as u32).collect())
}

/// `a / b` when `b` divides `a`.
fn div_exact(a: &[u32], b: &[u32], q: u32) -> Poly {
    let li = inverse(*b.last().expect("non-zero"), q);
    let mut a = a.to_vec();
    let mut out = vec![0; a.len() + 1 - b.len()];
    while a.len() >= b.len() {
        let f = a.last().expect("non-empty") * li % q;
        let shift = a.len() - b.len();
        out[shift] = f;
        for (i, c) in b.iter().enumerate() {
            a[shift + i] = (a[shift + i] + q * q - f * c) % q;
        }
        a.pop();
    }
    debug_assert!(trim(a).is_empty(), "inexact division mod {q}");
    out
}

/// The monic gcd.
fn gcd(mut a: Poly, mut b: Poly, q: u32) -> Poly {
    while !b.is_empty() {
        let r = rem(a, &b, q);
        a = b;
        b = r;
    }
    if a.is_empty() { a } else { monic(a, q) }
}

/// `a·b mod f`.
fn mul_mod(a: &[u32], b: &[u32], f: &[u32], q: u32) -> Poly {
    if a.is_empty() || b.is_empty() {
        return vec![];
    }
    // at most 128 products below 2^20 each: the sums fit below 2^27, reduced by `rem`
    let mut out = vec![0u32; a.len() + b.len() - 1];
    for (i, x) in a.iter().enumerate() {
        for (j, y) in b.iter().enumerate() {
            out[i + j] += x * y;
        }
    }
    rem(out, f, q)
}

/// `x^q mod f`, by repeated squaring.
fn x_to_the_q(f: &[u32], q: u32) -> Poly {
    let mut xq: Poly = vec![1];
    let (mut base, mut e) = (rem(vec![0, 1], f, q), q);
    while e > 0 {
        if e & 1 == 1 {
            xq = mul_mod(&xq, &base, f, q);
        }
        base = mul_mod(&base, &base, f, q);
        e >>= 1;
    }
    xq
}

/// The Frobenius map `h ↦ h^q mod f` as a matrix: row `k` is `x^(qk) mod f` (`k < deg f`). The
/// map is linear over `Z/q`, so `h^q = Σ h_k x^(qk)`.
fn frobenius_matrix(f: &[u32], q: u32) -> Vec<Poly> {
    let n = f.len() - 1;
    let xq = x_to_the_q(f, q);
    let mut rows: Vec<Poly> = vec![vec![1]];
    for k in 1..n {
        rows.push(mul_mod(&rows[k - 1], &xq, f, q));
    }
    rows
}

/// `h^q mod f` by the matrix of [`frobenius_matrix`] (`h` reduced mod `f`).
fn frobenius(h: &[u32], rows: &[Poly], q: u32) -> Poly {
    let n = rows.len();
    let mut acc = vec![0u64; n];
    for (k, &c) in h.iter().enumerate() {
        for (i, v) in rows[k].iter().enumerate() {
            acc[i] += u64::from(c) * u64::from(*v);
        }
    }
    let m = u64::MAX / u64::from(q);
    trim(acc.into_iter().map(|v| barrett(v, u64::from(q), m) as u32).collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ints(c: &[i64]) -> Vec<BigInt> {
        c.iter().map(|&x| BigInt::from(x)).collect()
    }

    /// Products of known factors: the bound never exceeds the smallest true factor's degree,
    /// and reaches the degree for irreducible cubics and quartics built as such.
    #[test]
    fn factor_degree_bound_is_a_lower_bound() {
        let mul = |a: &[BigInt], b: &[BigInt]| -> Vec<BigInt> {
            let mut out = vec![BigInt::from(0); a.len() + b.len() - 1];
            for (i, x) in a.iter().enumerate() {
                for (j, y) in b.iter().enumerate() {
                    out[i + j] += x * y;
                }
            }
            out
        };
        // Eisenstein at 2: irreducible
        let cubic = ints(&[2, 4, -6, 1]);
        let quartic = ints(&[6, 2, 0, 4, 3]); // Eisenstein at 2
        let quadratic = ints(&[-3, 0, 1]);
        assert_eq!(min_factor_degree(&cubic, 10), 3);
        assert_eq!(min_factor_degree(&quartic, 10), 4);
        assert!(min_factor_degree(&mul(&cubic, &quartic), 10) <= 3);
        assert!(min_factor_degree(&mul(&quadratic, &quartic), 10) <= 2);
        assert_eq!(min_factor_degree(&mul(&ints(&[1, 1]), &cubic), 10), 1);
        // x^9 − 2 (Eisenstein): irreducible, proved by the degree patterns
        let mut p9 = ints(&[-2]);
        p9.resize(9, BigInt::from(0));
        p9.push(BigInt::from(1));
        assert_eq!(min_factor_degree(&p9, 9), 9);
    }

    /// The distinct-degree factorization's degrees add up to the degree, on random polynomials
    /// over several primes.
    #[test]
    fn distinct_degree_factorization_accounts_for_every_degree() {
        let mut word = crate::num::xorshift(7);
        for n in 2..14 {
            let p: Vec<BigInt> = (0..=n)
                .map(|_| {
                    let x = word();
                    BigInt::from((x % 2001) as i64 - 1000) + i64::from(u8::from(x % 2001 == 1000))
                })
                .collect();
            for &q in &PRIMES[..4] {
                if let Some(d) = factor_degrees(&p, q, n + 1) {
                    assert_eq!(d.iter().sum::<usize>(), n, "{p:?} mod {q}");
                }
            }
        }
    }
}

/// The examples of the crate-internal items above, run as unit tests.
#[cfg(test)]
mod doc_examples {
    #[test]
    fn modular_example() {
        use super::min_factor_degree;
        use num_bigint::BigInt;
        let p = |c: &[i64]| c.iter().map(|&x| BigInt::from(x)).collect::<Vec<_>>();
        // t⁴ − 10t² + 1 (the minimal polynomial of √2 + √3) is irreducible over Q, but splits
        // into quadratics or linear factors modulo every prime: the bound is 2, not 4
        assert_eq!(min_factor_degree(&p(&[1, 0, -10, 0, 1]), 4), 2);
        // t³ − 2 is irreducible
        assert_eq!(min_factor_degree(&p(&[-2, 0, 0, 1]), 3), 3);
        // (t² + 1)(t³ − t − 1) = t⁵ − t² − t − 1: a quadratic factor
        assert_eq!(min_factor_degree(&p(&[-1, -1, -1, 0, 0, 1]), 5), 2);
    }
}
