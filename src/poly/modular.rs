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
//!
//! # Example
//! ```
//! use casteljau::poly::modular::min_factor_degree;
//! use num_bigint::BigInt;
//! let p = |c: &[i64]| c.iter().map(|&x| BigInt::from(x)).collect::<Vec<_>>();
//! // t⁴ − 10t² + 1 (the minimal polynomial of √2 + √3) is irreducible over Q, but splits
//! // into quadratics or linear factors modulo every prime: the bound is 2, not 4
//! assert_eq!(min_factor_degree(&p(&[1, 0, -10, 0, 1]), 4), 2);
//! // t³ − 2 is irreducible
//! assert_eq!(min_factor_degree(&p(&[-2, 0, 0, 1]), 3), 3);
//! // (t² + 1)(t³ − t − 1) = t⁵ − t² − t − 1: a quadratic factor
//! assert_eq!(min_factor_degree(&p(&[-1, -1, -1, 0, 0, 1]), 5), 2);
//! ```

use num_bigint::{BigInt, Sign};

/// Primes below `2^10`: sums of a hundred products of residues fit a `u32`, and raising to the
/// `q`-th power takes ten squarings. (A prime dividing the leading coefficient or the
/// discriminant is skipped; with sixteen of them, that costs nothing in practice.)
const PRIMES: [u32; 16] = [1021, 1019, 1013, 1009, 997, 991, 983, 977, 971, 967, 953, 947, 941, 937, 929, 919];

/// A polynomial over `Z/qZ`, lowest degree first, no trailing zeros.
type Poly = Vec<u32>;

/// A lower bound for the degree of every non-constant factor of `p` over `Q` (integer
/// coefficients, lowest degree first, degree ≥ 1): the smallest achievable sum of
/// distinct-degree factor degrees, over the primes tried (see the module documentation).
/// Stops early once the bound reaches `enough`; `1` when nothing is proved (degree above 127,
/// or no usable prime).
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
    for &q in &PRIMES {
        let Some(degrees) = factor_degrees(p, q) else { continue };
        let mut sums: u128 = 1;
        for d in degrees {
            sums |= sums << d;
        }
        possible &= sums;
        bound = (possible & !1).trailing_zeros() as usize;
        if bound >= enough.min(n) {
            break;
        }
    }
    bound
}

/// The degrees of the irreducible factors of `p mod q` (with repetition), when `q` does not
/// divide the leading coefficient and `p mod q` is square-free; `None` otherwise.
fn factor_degrees(p: &[BigInt], q: u32) -> Option<Vec<usize>> {
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
    // h = x^(q^i) mod f, by the Frobenius map (linear over Z/q): h(x)^q = Σ h_k x^(qk)
    let mut h: Poly = vec![0, 1];
    let mut xq = x_to_the_q(&f, q);
    let mut i = 0;
    while f.len() > 1 {
        i += 1;
        if 2 * i > f.len() - 1 {
            out.push(f.len() - 1); // what is left is irreducible
            break;
        }
        h = frobenius(&h, &xq, &f, q);
        let mut hx = h.clone();
        hx.resize(hx.len().max(2), 0);
        hx[1] = (hx[1] + q - 1) % q;
        let g = gcd(f.clone(), trim(hx), q);
        if g.len() > 1 {
            out.extend(std::iter::repeat_n(i, (g.len() - 1) / i));
            f = div_exact(&f, &g, q);
            h = rem(h, &f, q);
            xq = rem(xq, &f, q);
        }
    }
    Some(out)
}

/// `p mod q`, residues in `[0, q)`.
fn reduce(p: &[BigInt], q: u32) -> Poly {
    trim(
        p.iter()
            .map(|c| {
                let r = crate::num::small::rem_u64(c.magnitude(), u64::from(q)) as u32;
                if c.sign() == Sign::Minus && r != 0 { q - r } else { r }
            })
            .collect(),
    )
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

/// `a mod b` (`b` non-zero).
fn rem(mut a: Poly, b: &[u32], q: u32) -> Poly {
    let li = inverse(*b.last().expect("non-zero"), q);
    while a.len() >= b.len() {
        let f = a.last().expect("non-empty") * li % q;
        let shift = a.len() - b.len();
        for (i, c) in b.iter().enumerate() {
            // a − f·c with one reduction: q² − f·c > 0
            a[shift + i] = (a[shift + i] + q * q - f * c) % q;
        }
        a.pop();
        a = trim(a);
    }
    a
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
    // at most 128 products below 2^20 each: the sums fit a u32, reduced once
    let mut out = vec![0u32; a.len() + b.len() - 1];
    for (i, x) in a.iter().enumerate() {
        for (j, y) in b.iter().enumerate() {
            out[i + j] += x * y;
        }
    }
    rem(trim(out.into_iter().map(|v| v % q).collect()), f, q)
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

/// `h^q mod f` from `xq = x^q mod f`: the Frobenius map is linear over `Z/q`, so
/// `h(x)^q = Σ h_k (x^q)^k` (Horner in `x^q`).
fn frobenius(h: &[u32], xq: &[u32], f: &[u32], q: u32) -> Poly {
    let mut acc: Poly = vec![];
    for &c in h.iter().rev() {
        acc = mul_mod(&acc, xq, f, q);
        if acc.is_empty() {
            acc.push(0);
        }
        acc[0] = (acc[0] + c) % q;
        acc = trim(acc);
    }
    acc
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
        let mut x: u64 = 7;
        for n in 2..14 {
            let p: Vec<BigInt> = (0..=n)
                .map(|_| {
                    x ^= x << 13;
                    x ^= x >> 7;
                    x ^= x << 17;
                    BigInt::from((x % 2001) as i64 - 1000) + i64::from(u8::from(x % 2001 == 1000))
                })
                .collect();
            for &q in &PRIMES[..4] {
                if let Some(d) = factor_degrees(&p, q) {
                    assert_eq!(d.iter().sum::<usize>(), n, "{p:?} mod {q}");
                }
            }
        }
    }
}
