//! Polynomials with integer coefficients (`Vec<BigInt>`, lowest degree first): the
//! fraction-free kernels behind exact root isolation and algebraic numbers — primitive part,
//! the subresultant gcd, the square-free part (with a modular shortcut), exact quotients.
//! Rational polynomials ([`super::Poly`]) clear their denominators ([`to_integer`]) and come
//! here for the expensive steps: integer gcds are the slow operation of big-number arithmetic,
//! and these never form a fraction.

use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, Signed};

/// A positive multiple of `p` with integer coefficients (the denominators cleared).
pub(crate) fn to_integer(p: &[BigRational]) -> Vec<BigInt> {
    let d = p.iter().fold(BigInt::one(), |acc, x| acc.lcm(x.denom()));
    p.iter().map(|x| x.numer() * (&d / x.denom())).collect()
}

/// `p` divided by the gcd of its coefficients, with a positive leading coefficient (`[]` for
/// the zero polynomial).
pub(crate) fn primitive_part(p: Vec<BigInt>) -> Vec<BigInt> {
    let mut p = p;
    while p.last().is_some_and(num_traits::Zero::is_zero) {
        p.pop();
    }
    let Some(last) = p.last() else { return p };
    let mut content = <BigInt as num_traits::Zero>::zero();
    for x in &p {
        content = crate::num::word::gcd_big(&content, x);
        if content.is_one() {
            break;
        }
    }
    if last.is_negative() {
        content = -content;
    }
    if content.is_one() { p } else { p.into_iter().map(|x| x / &content).collect() }
}

/// The pseudo-remainder `lc(b)^(deg a − deg b + 1)·a mod b`, on integers (`b` non-zero,
/// trimmed, `deg a ≥ deg b`): exactly `deg a − deg b + 1` multiplications by `lc(b)`, even
/// when a step finds a zero leading coefficient (the subresultant sequence divides by the
/// factor this power predicts).
fn pseudo_rem(a: Vec<BigInt>, b: &[BigInt]) -> Vec<BigInt> {
    let lb = b.last().expect("non-zero divisor");
    let mut a = a;
    if a.len() < b.len() {
        return a;
    }
    let steps = a.len() - b.len() + 1;
    for step in 0..steps {
        let top = a.len() - 1 - step; // the coefficient eliminated in this step
        let la = a[top].clone();
        for x in a[..=top].iter_mut() {
            *x *= lb;
        }
        let shift = top + 1 - b.len();
        for (i, c) in b.iter().enumerate() {
            a[shift + i] -= &la * c;
        }
    }
    a.truncate(b.len() - 1);
    while a.last().is_some_and(num_traits::Zero::is_zero) {
        a.pop();
    }
    a
}

/// The primitive greatest common divisor of two integer polynomials (positive leading
/// coefficient; `[]` when both are zero), by the subresultant remainder sequence (Collins;
/// Brown–Traub): each pseudo-remainder is divided exactly by `g·h^δ`, which keeps the
/// coefficients at the size of the subresultants (bit length `O(n·τ)`) without computing a
/// single integer gcd until the final primitive part — integer gcds are the slow operation
/// of big-number arithmetic.
pub(crate) fn gcd_integer(a: &[BigInt], b: &[BigInt]) -> Vec<BigInt> {
    let (mut a, mut b) = (primitive_part(a.to_vec()), primitive_part(b.to_vec()));
    if a.len() < b.len() {
        std::mem::swap(&mut a, &mut b);
    }
    if b.is_empty() {
        return a;
    }
    let (mut g, mut h) = (BigInt::one(), BigInt::one());
    loop {
        let delta = (a.len() - b.len()) as u32;
        let r = pseudo_rem(a, &b);
        if r.is_empty() {
            return primitive_part(b);
        }
        if r.len() == 1 {
            return vec![BigInt::one()]; // a non-zero constant: coprime
        }
        let divisor = &g * num_traits::Pow::pow(&h, delta);
        a = b;
        b = r.into_iter().map(|x| x / &divisor).collect();
        g = a.last().expect("non-zero").clone();
        // h ← g^δ / h^(δ−1)
        h = if delta == 0 { h } else { num_traits::Pow::pow(&g, delta) / num_traits::Pow::pow(&h, delta - 1) };
    }
}

/// The square-free part of an integer polynomial: `p / gcd(p, p')` as a primitive integer
/// polynomial with positive leading coefficient (`[]` for zero).
///
/// Most polynomials are square-free already, and proving it is cheap: if `gcd(p, p') mod q`
/// is a constant for a prime `q` that does not divide the leading coefficient, then `p` is
/// square-free (a common factor `g` over `Z` would keep its degree mod `q`, since `lc(g)`
/// divides `lc(p)`). Only when that test fails for a few primes does the exact
/// [`gcd_integer`] run.
pub(crate) fn square_free_integer(p: Vec<BigInt>) -> Vec<BigInt> {
    let p = primitive_part(p);
    if p.len() <= 2 {
        return p;
    }
    let dp = derivative_integer(&p);
    if MODULAR_PRIMES.iter().any(|&q| coprime_mod(&p, &dp, q)) {
        return p;
    }
    let g = gcd_integer(&p, &dp);
    if g.len() <= 1 { p } else { primitive_part(exact_quotient(p, &g)) }
}

/// Primes below 2³¹ for the modular square-free test: products of two residues fit in a `u64`,
/// so every step is one machine multiplication and remainder (a 62-bit prime needed `u128`
/// remainders, a software division each, and cost more than the rest of the root isolation).
const MODULAR_PRIMES: [u64; 3] = [MERSENNE, 2_147_483_629, 2_147_483_587];

/// The Mersenne prime `2^31 − 1`, the first of [`MODULAR_PRIMES`].
const MERSENNE: u64 = (1 << 31) - 1;

/// The primitive part of a non-zero integer polynomial (trimmed, positive leading coefficient)
/// when every coefficient fits an `i128` and the modular test of [`square_free_integer`] proves
/// it square-free: then it is [`square_free_integer`]'s answer, found in machine words (the
/// content by word gcds, the residues by word remainders). `None` otherwise (decide with
/// [`square_free_integer`]).
pub(crate) fn square_free_small(p: &[BigInt]) -> Option<Vec<BigInt>> {
    let mut c: Vec<i128> = p.iter().map(num_traits::ToPrimitive::to_i128).collect::<Option<_>>()?;
    while c.last() == Some(&0) {
        c.pop();
    }
    let last = *c.last()?;
    let content = c
        .iter()
        .try_fold(0u128, |g, x| if g == 1 { None } else { Some(crate::num::word::gcd_u128(g, x.unsigned_abs())) });
    let content = i128::try_from(content.unwrap_or(1)).ok()?;
    let content = if last < 0 { -content } else { content };
    let c: Vec<i128> = if content == 1 { c } else { c.into_iter().map(|x| x / content).collect() };
    let big = || c.iter().map(|&x| BigInt::from(x)).collect();
    if c.len() <= 2 {
        return Some(big());
    }
    let dc: Vec<i128> = c.iter().enumerate().skip(1).map(|(k, x)| x.checked_mul(k as i128)).collect::<Option<_>>()?;
    let reduce = |v: &[i128], q: u64| -> Vec<u64> {
        let residue = |x: i128| if q == MERSENNE { residue_mersenne(x) } else { crate::num::word::residue_i128(x, q) };
        v.iter().map(|&x| residue(x)).collect()
    };
    MODULAR_PRIMES.iter().any(|&q| coprime_residues(reduce(&c, q), reduce(&dc, q), q)).then(big)
}

/// `x mod (2^31 − 1)` in `[0, 2^31 − 1)`, by folding 31-bit digits (`2^31 ≡ 1`): no division.
fn residue_mersenne(x: i128) -> u64 {
    let mut m = x.unsigned_abs();
    let mut r: u64 = 0;
    while m != 0 {
        r += (m as u64) & MERSENNE;
        m >>= 31;
    }
    // at most five digits: r < 5·2^31
    let r = (r & MERSENNE) + (r >> 31);
    let r = if r >= MERSENNE { r - MERSENNE } else { r };
    if x < 0 && r != 0 { MERSENNE - r } else { r }
}

/// `true` when `gcd(a mod q, b mod q)` is a non-zero constant and `q ∤ lc(a)`: then `a` and
/// `b` have no common factor of positive degree over `Q` (see [`square_free_integer`]).
fn coprime_mod(a: &[BigInt], b: &[BigInt], q: u64) -> bool {
    let reduce = |p: &[BigInt]| -> Vec<u64> { p.iter().map(|x| crate::num::word::residue(x, q)).collect() };
    coprime_residues(reduce(a), reduce(b), q)
}

/// [`coprime_mod`] on the residues `x` of `a` and `y` of `b` (untrimmed: `x` as long as `a`).
fn coprime_residues(mut x: Vec<u64>, mut y: Vec<u64>, q: u64) -> bool {
    let len = x.len();
    for v in [&mut x, &mut y] {
        while v.last() == Some(&0) {
            v.pop();
        }
    }
    if x.len() != len || y.is_empty() {
        return false; // q divides lc(a), or b vanishes mod q: no conclusion
    }
    // v mod q for v < 2^62; by folding for the Mersenne prime 2^31 − 1 (no division)
    let reduce = |v: u64| {
        if q == MERSENNE {
            let v = (v & MERSENNE) + (v >> 31);
            let v = (v & MERSENNE) + (v >> 31);
            if v >= MERSENNE { v - MERSENNE } else { v }
        } else {
            v % q
        }
    };
    let mul = |u: u64, v: u64| reduce(u * v);
    if x.len() < y.len() {
        std::mem::swap(&mut x, &mut y);
    }
    while y.len() > 1 {
        // x ← lc(y)·x − lc(x)·t^shift·y until deg x < deg y: a non-zero multiple of x mod y over
        // Z_q, so the degrees of the remainder sequence are Euclid's (no inverses needed)
        while x.len() >= y.len() {
            let (lx, ly) = (*x.last().expect("non-empty"), *y.last().expect("non-zero"));
            let shift = x.len() - y.len();
            for i in 0..x.len() - 1 {
                let sub = if i >= shift { mul(lx, y[i - shift]) } else { 0 };
                x[i] = reduce(mul(x[i], ly) + q - sub);
            }
            x.pop();
            while x.last() == Some(&0) {
                x.pop();
            }
        }
        if x.is_empty() {
            return false; // y divides x: a common factor of positive degree mod q
        }
        std::mem::swap(&mut x, &mut y);
    }
    true // y is a non-zero constant
}

/// Exact quotient `a / b` of integer polynomials when `b` divides `a` in `Z[x]` (as the
/// primitive parts of `p` and of a divisor of `p` do, by Gauss's lemma).
/// `a / b` for integer polynomials when `b` divides `a` exactly (lowest degree first).
pub(crate) fn exact_quotient_integer(a: Vec<BigInt>, b: &[BigInt]) -> Vec<BigInt> {
    exact_quotient(a, b)
}

fn exact_quotient(a: Vec<BigInt>, b: &[BigInt]) -> Vec<BigInt> {
    let lb = b.last().expect("non-zero divisor");
    let mut a = a;
    let mut q = vec![<BigInt as num_traits::Zero>::zero(); a.len().saturating_sub(b.len()) + 1];
    while a.len() >= b.len() && !a.is_empty() {
        let f = a.last().expect("non-empty") / lb;
        let shift = a.len() - b.len();
        for (i, c) in b.iter().enumerate() {
            a[shift + i] -= &f * c;
        }
        q[shift] = f;
        a.pop();
        while a.last().is_some_and(num_traits::Zero::is_zero) {
            a.pop();
        }
    }
    debug_assert!(a.is_empty(), "exact_quotient: b does not divide a");
    q
}

/// `p'` of an integer polynomial (lowest degree first; not trimmed).
pub(crate) fn derivative_integer(p: &[BigInt]) -> Vec<BigInt> {
    p.iter().enumerate().skip(1).map(|(k, c)| c * BigInt::from(k)).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The word route of the square-free part ([`square_free_small`]) against
    /// [`square_free_integer`] on random polynomials with contents, repeated factors and
    /// coefficients near `2^100`; and the Mersenne residues against big-integer remainders.
    #[test]
    fn square_free_in_words_matches_big_integers() {
        let mut next = crate::num::symmetric(0x5F5F_0DD5_EED5_0001);
        let mut decided = 0;
        for round in 0..300 {
            let n = 1 + round % 6;
            let scale = BigInt::from(1) << (round % 3 * 45) as u32;
            let mut p: Vec<BigInt> = (0..=n).map(|_| BigInt::from(next(1000)) * &scale).collect();
            if round % 4 == 0 {
                // a repeated factor (t + c)²
                let c = BigInt::from(next(9));
                for _ in 0..2 {
                    let mut q = vec![BigInt::from(0); p.len() + 1];
                    for (i, x) in p.iter().enumerate() {
                        q[i] += x * &c;
                        q[i + 1] += x;
                    }
                    p = q;
                }
            }
            if p.iter().all(num_traits::Zero::is_zero) {
                continue;
            }
            if let Some(sf) = square_free_small(&p) {
                assert_eq!(sf, square_free_integer(p.clone()), "{p:?}");
                decided += 1;
            }
        }
        assert!(decided > 150, "{decided} decided in words");
        let mut word = crate::num::xorshift(0x0A0B_0C0D_0E0F_1011);
        for k in 0..500 {
            let v = ((u128::from(word()) << 64 | u128::from(word())) >> (k % 127)) as i128;
            for x in [v, -v, i128::MIN, i128::MAX] {
                assert_eq!(residue_mersenne(x), crate::num::word::residue(&BigInt::from(x), MERSENNE), "{x}");
            }
        }
    }
}
