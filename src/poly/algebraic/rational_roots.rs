//! Rational-root search for [`RealAlgebraic`]: a proof by residues that a polynomial has no
//! rational root, a guess from an `f64` candidate confirmed by an exact zero, the exact test
//! that makes a number rational when it is, and the simplest rational in an interval (integer
//! continued fractions, hand-written so that no gcd is taken and a bound on the denominator
//! stops the search early).

use super::evaluate::sign_at;
use super::rounding::f64_root_candidate;
use super::{RealAlgebraic, Repr};
use crate::num::scalar::{Exact, rat, ratio_to_f64};
use crate::poly::integer::primitive_part;
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};
use std::cmp::Ordering;

/// `true` when `p` provably has no rational root: `p mod q` has no root for some prime `q` from
/// 3 to 53 not dividing the leading coefficient (a rational root `a/b` has `b | lc`, so `b` is
/// invertible mod `q` and `a·b⁻¹` would be a root mod `q`). `false` means "not proved"; the
/// slower exact search of `detect_rational` then decides.
pub(crate) fn no_rational_roots(p: &[BigInt]) -> bool {
    if p.is_empty() {
        return false;
    }
    // the residues modulo products of the primes, once per coefficient (word remainders when
    // the coefficients fit an i128), then modulo each prime (a constant: no division)
    let small: Option<Vec<i128>> = p.iter().map(num_traits::ToPrimitive::to_i128).collect();
    let residues = |m: u64| -> Vec<u64> {
        match &small {
            Some(c) => c.iter().map(|&x| crate::num::word::residue_i128(x, m)).collect(),
            None => p.iter().map(|x| crate::num::word::residue(x, m)).collect(),
        }
    };
    let first = residues(3 * 5 * 7 * 11 * 13 * 17 * 19 * 23);
    if no_root_mod::<3>(&first)
        || no_root_mod::<5>(&first)
        || no_root_mod::<7>(&first)
        || no_root_mod::<11>(&first)
        || no_root_mod::<13>(&first)
        || no_root_mod::<17>(&first)
        || no_root_mod::<19>(&first)
        || no_root_mod::<23>(&first)
    {
        return true;
    }
    let second = residues(29 * 31 * 37 * 41 * 43);
    if no_root_mod::<29>(&second)
        || no_root_mod::<31>(&second)
        || no_root_mod::<37>(&second)
        || no_root_mod::<41>(&second)
        || no_root_mod::<43>(&second)
    {
        return true;
    }
    let third = residues(47 * 53);
    no_root_mod::<47>(&third) || no_root_mod::<53>(&third)
}

/// The polynomial with residues `r` modulo a multiple of the prime `Q` has no root modulo `Q`,
/// and `Q` does not divide its leading coefficient.
fn no_root_mod<const Q: u64>(r: &[u64]) -> bool {
    let c: Vec<u64> = r.iter().map(|x| x % Q).collect();
    if c.last().is_none_or(|&lc| lc == 0) {
        return false;
    }
    (0..Q).all(|x| c.iter().rev().fold(0u64, |acc, v| (acc * x + v) % Q) != 0)
}

/// `p / (q·t − n)` for a rational root `x = n/q` of the integer polynomial `p`, primitive
/// (`q` divides the leading coefficient by Gauss's lemma, so the quotient is integral).
pub(super) fn without_rational_root(p: Vec<BigInt>, x: &BigRational) -> Vec<BigInt> {
    let linear = [-x.numer().clone(), x.denom().clone()];
    primitive_part(crate::poly::integer::exact_quotient_integer(p, &linear))
}

/// The rational root of `p` in `(a, b)` when a guess finds it: the simplest rational near an
/// `f64` candidate, confirmed by an exact zero. `None` proves nothing.
pub(super) fn rational_guess(p: &[BigInt], a: &BigRational, b: &BigRational) -> Option<BigRational> {
    let f = f64_root_candidate(p, ratio_to_f64(a), ratio_to_f64(b))?;
    let fr = BigRational::from_float(f)?;
    let slack = BigRational::from_float(f.abs().max(f64::MIN_POSITIVE) * 1e-9)?;
    let x = simplest_rational(&(fr.clone() - &slack), &(fr + &slack));
    (x > *a && x < *b && sign_at(p, &x) == Ordering::Equal).then_some(x)
}

/// The simplest rational (smallest denominator, then numerator) in the closed interval
/// `[lo, hi]`, by continued fractions (Stern–Brocot; the crate's bounded search without a
/// bound).
pub fn simplest_rational(lo: &BigRational, hi: &BigRational) -> BigRational {
    debug_assert!(lo <= hi);
    simplest_rational_bounded(lo, hi, None).expect("no bound on the denominator")
}

/// The simplest rational in the closed interval `[lo, hi]` (as [`simplest_rational`]) when its
/// denominator is at most `max_den` (any, for `None`); `None` otherwise. Integer continued
/// fractions (no gcd), stopped as soon as a convergent's denominator — a lower bound for the
/// answer's — exceeds `max_den`.
pub(crate) fn simplest_rational_bounded(
    lo: &BigRational,
    hi: &BigRational,
    max_den: Option<&BigInt>,
) -> Option<BigRational> {
    if lo.sign() != Ordering::Greater && hi.sign() != Ordering::Less {
        return Some(rat(0));
    }
    if hi.sign() == Ordering::Less {
        return simplest_rational_bounded(&-hi.clone(), &-lo.clone(), max_den).map(|x| -x);
    }
    let within = |k: &BigInt| max_den.is_none_or(|m| k <= m);
    // 0 < a/b ≤ c/d (b, d > 0)
    let (mut a, mut b, mut c, mut d) = (lo.numer().clone(), lo.denom().clone(), hi.numer().clone(), hi.denom().clone());
    let mut parts: Vec<BigInt> = vec![];
    // convergent denominators k_(−1) = 0, k_0 = 1: k_n = q_n·k_(n−1) + k_(n−2)
    let (mut k1, mut k2) = (BigInt::zero(), BigInt::one());
    loop {
        let (q, r) = num_integer::Integer::div_rem(&a, &b);
        // the least integer ≥ a/b, if it is ≤ c/d, ends the expansion
        let ceil = if r.is_zero() { q.clone() } else { &q + 1 };
        if &ceil * &d <= c {
            let (mut num, mut den) = (ceil, BigInt::one());
            for f in parts.into_iter().rev() {
                // f + 1/(num/den) = (f·num + den)/num
                let next = &f * &num + den;
                den = num;
                num = next;
            }
            return within(&den).then(|| BigRational::new_raw(num, den));
        }
        // both in (q, q+1): subtract q and invert (the order flips)
        let k = &q * &k1 + &k2;
        if !within(&k) {
            return None;
        }
        (k2, k1) = (k1, k);
        let (na, nb) = (d.clone(), &c - &q * &d);
        let (nc, nd) = (b.clone(), &a - &q * &b);
        (a, b, c, d) = (na, nb, nc, nd);
        parts.push(q);
    }
}

impl RealAlgebraic {
    pub(super) fn detect_rational(&mut self) {
        let Repr::Root { poly, .. } = &self.0 else { return };
        if poly.len() == 2 {
            let r = BigRational::new(-poly[0].clone(), poly[1].clone());
            self.0 = Repr::Rational(r);
            return;
        }
        let lc = poly.last().expect("non-constant").abs();
        let bound = BigRational::from_integer(&lc * &lc).recip();
        // below width 1/lc² by Newton steps (quadratic) when they apply, else by bisection
        let (lo, hi) = self.interval();
        let magnitude = ratio_to_f64(&lo).abs().max(ratio_to_f64(&hi).abs());
        let e = if magnitude.is_finite() && magnitude > 0.0 { magnitude.log2().ceil() as i64 } else { 0 };
        let bits = (e + 2 * lc.bits() as i64 + 2).max(1) as u64;
        self.refine_newton(bits);
        self.refine(&bound);
        let Repr::Root { poly, lo, hi } = &self.0 else { return };
        // two fractions with denominators ≤ lc are 1/lc² apart or more: at most one lies inside,
        // the simplest one if any
        if let Some(c) = simplest_rational_bounded(lo, hi, Some(&lc))
            && sign_at(poly, &c) == Ordering::Equal
        {
            self.0 = Repr::Rational(c);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::scalar::ratio;

    /// The simplest rational against a search by denominators (the least `q` with a fraction
    /// `p/q` inside, `p` the least in magnitude), and the bounded search against it: the same
    /// fraction when its denominator is within the bound, `None` otherwise.
    #[test]
    fn simplest_rational_matches_a_search_by_denominators() {
        let search = |lo: &BigRational, hi: &BigRational| -> BigRational {
            if lo.sign() != Ordering::Greater && hi.sign() != Ordering::Less {
                return rat(0);
            }
            let (l, h, sign) = if lo.sign() == Ordering::Greater {
                (lo.clone(), hi.clone(), 1)
            } else {
                (-hi.clone(), -lo.clone(), -1)
            };
            (1i64..)
                .find_map(|q| {
                    let p = (l.clone() * rat(q)).ceil();
                    (p <= h.clone() * rat(q)).then(|| p / rat(q) * rat(sign))
                })
                .expect("a fraction in every interval")
        };
        let mut next = crate::num::symmetric(0x005E_ED0F_F4AC_7105);
        for _ in 0..400 {
            let (a, b) = (ratio(next(5000), next(400).abs() + 1), ratio(next(5000), next(400).abs() + 1));
            let (lo, hi) = if a <= b { (a, b) } else { (b, a) };
            let expected = search(&lo, &hi);
            assert_eq!(simplest_rational(&lo, &hi), expected, "[{lo}, {hi}]");
            for bound in [1, 3, 17, 400, 100000] {
                let bounded = simplest_rational_bounded(&lo, &hi, Some(&BigInt::from(bound)));
                assert_eq!(
                    bounded,
                    (*expected.denom() <= BigInt::from(bound)).then(|| expected.clone()),
                    "[{lo}, {hi}] bound {bound}"
                );
            }
        }
    }

    #[test]
    fn simplest_rationals_of_intervals() {
        assert_eq!(simplest_rational(&ratio(1, 3), &ratio(1, 2)), ratio(1, 2));
        assert_eq!(simplest_rational(&ratio(3, 10), &ratio(4, 10)), ratio(1, 3));
        assert_eq!(simplest_rational(&ratio(-7, 10), &ratio(-6, 10)), ratio(-2, 3));
        assert_eq!(simplest_rational(&ratio(-1, 10), &ratio(6, 10)), rat(0));
        assert_eq!(simplest_rational(&ratio(31415, 10000), &ratio(31416, 10000)), ratio(333, 106));
    }
}
