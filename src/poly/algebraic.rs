//! Exact real algebraic numbers: a square-free primitive integer polynomial and an open
//! interval with rational ends holding exactly one of its roots — or the rational number
//! itself. Comparison and sign are exact (intervals are refined until they separate, and
//! equality is decided by a gcd); `to_f64` is correctly rounded; `Display` writes a rational as
//! a rational, a root of a quadratic polynomial as `a + b*sqrt(d)`, anything else as
//! `root k of <poly> in [lo, hi]` (the `k`-th real root, ascending; `[lo, hi]` the coarsest
//! dyadic interval `[k/2^j, (k+1)/2^j]`, `j ≥ 4`, with no other root inside, so one number
//! prints alike whatever interval it carries). The polynomial is the
//! square-free part of the one the number came from, not factored further: a number whose
//! polynomial is reducible (√2 as a root of `t⁴ − 4`) keeps the general spelling.
//!
//! # Invariants
//! A `Root` is irrational (rational roots are detected when the number is made: a rational root
//! `p/q` of an integer polynomial has `q | lc`, so once the interval is narrower than `1/lc²` the
//! simplest rational inside is the only candidate), its polynomial is square-free, primitive,
//! with a positive leading coefficient, and does not vanish at either end, where it takes
//! opposite signs.
//!
//! # Termination
//! Refinement bisects; the sign at the midpoint picks the half with the root. Comparing two
//! distinct numbers refines until the intervals separate (they do: the numbers differ); equal
//! numbers are recognised by the gcd of the polynomials having a root in the common interval,
//! so no refinement loop is unbounded. `to_f64` refines until both ends round to the same `f64`,
//! which happens because an irrational number is never a rounding boundary.
//!
//! # Example
//! ```
//! use casteljau::poly::algebraic::RealAlgebraic;
//! use casteljau::{rat, ratio};
//! // t² − 2: √2 and −√2; t³ − 2: ∛2
//! let r = RealAlgebraic::real_roots(&[rat(-2), rat(0), rat(1)]);
//! assert_eq!(r.iter().map(|x| x.to_string()).collect::<Vec<_>>(), ["-sqrt(2)", "sqrt(2)"]);
//! let c = RealAlgebraic::real_roots(&[rat(-2), rat(0), rat(0), rat(1)]);
//! assert_eq!(c[0].to_string(), "root 1 of t^3 - 2 in [5/4, 21/16]");
//! assert_eq!(c[0].to_f64(), 2f64.cbrt());
//! assert!(c[0] < r[1] && r[0] < RealAlgebraic::from(ratio(-1, 1)));
//! // (2t − 1)(t² − 3): the rational root is a rational
//! let m = RealAlgebraic::real_roots(&[rat(3), rat(-6), rat(-1), rat(2)]);
//! assert_eq!(m[1].to_string(), "1/2");
//! ```

use crate::num::quadratic_field::QuadraticExt;
use crate::num::scalar::{Exact, rat, ratio_to_f64};
use crate::poly::bernstein::power_to_bernstein_matrix;
use crate::poly::polynomial::{
    derivative_integer, gcd_integer, primitive_part, quadratic_roots, square_free_integer, to_integer,
};
use crate::poly::roots::Root;
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};
use std::cmp::Ordering;
use std::fmt;

/// An exact real algebraic number (see the module documentation).
#[derive(Clone, Debug)]
pub struct RealAlgebraic(Repr);

#[derive(Clone, Debug)]
enum Repr {
    Rational(BigRational),
    Root { poly: Vec<BigInt>, lo: BigRational, hi: BigRational },
}

impl From<BigRational> for RealAlgebraic {
    fn from(r: BigRational) -> Self {
        RealAlgebraic(Repr::Rational(r))
    }
}

/// The sign of `p(r)` for an integer polynomial (lowest degree first): the sign of
/// `Σ c_i a^i b^(n−i)` for `r = a/b`, `b > 0`.
pub fn sign_at(p: &[BigInt], r: &BigRational) -> Ordering {
    if p.is_empty() {
        return Ordering::Equal;
    }
    let (a, b) = (r.numer(), r.denom());
    let n = p.len() - 1;
    if let Some((m, k)) = dyadic_parts(r) {
        // b = 2^k: the powers of b are shifts
        return homogeneous_value(p, m, k).sign().into_ordering();
    }
    // Horner in homogeneous form: acc = acc·a + c_i·b^(n−i)
    let mut acc = p[n].clone();
    let mut bpow = BigInt::one();
    for i in (0..n).rev() {
        bpow *= b;
        acc = acc * a + &p[i] * &bpow;
    }
    acc.sign().into_ordering()
}

trait IntoOrdering {
    fn into_ordering(self) -> Ordering;
}

impl IntoOrdering for num_bigint::Sign {
    fn into_ordering(self) -> Ordering {
        match self {
            num_bigint::Sign::Minus => Ordering::Less,
            num_bigint::Sign::NoSign => Ordering::Equal,
            num_bigint::Sign::Plus => Ordering::Greater,
        }
    }
}

/// The power-form coefficients of `p(lo + (hi − lo)·s)`.
fn shifted(p: &[BigRational], lo: &BigRational, hi: &BigRational) -> Vec<BigRational> {
    let w = hi.clone() - lo;
    let mut acc: Vec<BigRational> = vec![];
    for c in p.iter().rev() {
        // acc ← acc·(lo + w s) + c
        let mut next = vec![rat(0); acc.len() + 1];
        for (k, a) in acc.iter().enumerate() {
            next[k] += a * lo;
            next[k + 1] += a * &w;
        }
        next[0] += c;
        acc = next;
    }
    acc
}

/// A positive multiple of the power-form coefficients of `c(lo + (hi − lo)·u)` (`c` integer,
/// `lo < hi`), on integers: with `lo = L/D` and `hi − lo = V/D`, `D^n·c(lo + (hi − lo)u)` by
/// homogeneous Horner.
fn shifted_integer(c: &[BigInt], lo: &BigRational, hi: &BigRational) -> Vec<BigInt> {
    if num_traits::Zero::is_zero(lo) && num_traits::One::is_one(hi) {
        return c.to_vec();
    }
    let n = c.len() - 1;
    let (d, l, v) = match aligned(lo, hi) {
        // dyadic ends (the usual case): D = 2^k, no gcd
        Some((l, h, k)) => {
            let v = &h - &l;
            (BigInt::one() << k, l, v)
        }
        None => {
            let w = hi.clone() - lo;
            let d = num_integer::Integer::lcm(lo.denom(), w.denom());
            let l = lo.numer() * (&d / lo.denom());
            let v = w.numer() * (&d / w.denom());
            (d, l, v)
        }
    };
    let mut dpow = vec![BigInt::one()];
    for _ in 0..n {
        let last = dpow[dpow.len() - 1].clone();
        dpow.push(last * &d);
    }
    let mut q: Vec<BigInt> = vec![];
    for k in (0..=n).rev() {
        // q ← q·(l + v s) + c_k·D^(n−k)
        let mut next = vec![BigInt::zero(); q.len() + 1];
        for (i, a) in q.iter().enumerate() {
            next[i] += a * &l;
            next[i + 1] += a * &v;
        }
        next[0] += &c[k] * &dpow[n - k];
        q = next;
    }
    q.truncate(n + 1);
    q
}

/// The real roots of the square-free integer polynomial `p` (power form) in the closed interval
/// `[lo, hi]`, ascending, as exact rationals or isolating open intervals.
fn isolate_power(p: &[BigInt], lo: &BigRational, hi: &BigRational) -> Vec<Root> {
    let q = shifted_integer(p, lo, hi);
    let b = crate::poly::roots::power_to_bernstein_integer(&q);
    let map = |s: BigRational| lo.clone() + (hi.clone() - lo) * s;
    crate::poly::roots::isolate_square_free(b)
        .into_iter()
        .map(|r| match r {
            Root::Exact(s) => Root::Exact(map(s)),
            Root::Isolated(a, b) => Root::Isolated(map(a), map(b)),
        })
        .collect()
}

/// `true` when `p` provably has no rational root: `p mod q` has no root for some small prime
/// `q` not dividing the leading coefficient (a rational root `a/b` has `b | lc`, so `b` is
/// invertible mod `q` and `a·b⁻¹` would be a root mod `q`). `false` means "not proved"; the
/// slower exact search of `detect_rational` then decides.
pub(crate) fn no_rational_roots(p: &[BigInt]) -> bool {
    const PRIMES: [u64; 15] = [3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37, 41, 43, 47, 53];
    let Some(lc) = p.last() else { return false };
    let residue = crate::num::small::residue;
    PRIMES.iter().any(|&q| {
        if residue(lc, q) == 0 {
            return false;
        }
        let coeffs: Vec<u64> = p.iter().map(|c| residue(c, q)).collect();
        (0..q).all(|x| coeffs.iter().rev().fold(0u64, |acc, c| (acc * x + c) % q) != 0)
    })
}

/// `p / (q·t − n)` for a rational root `x = n/q` of the integer polynomial `p`, primitive
/// (`q` divides the leading coefficient by Gauss's lemma, so the quotient is integral).
fn without_rational_root(p: Vec<BigInt>, x: &BigRational) -> Vec<BigInt> {
    let linear = [-x.numer().clone(), x.denom().clone()];
    primitive_part(crate::poly::polynomial::exact_quotient_integer(p, &linear))
}

/// The rational root of `p` in `(a, b)` when a guess finds it: the simplest rational near an
/// `f64` candidate, confirmed by an exact zero. `None` proves nothing.
fn rational_guess(p: &[BigInt], a: &BigRational, b: &BigRational) -> Option<BigRational> {
    let f = f64_root_candidate(p, ratio_to_f64(a), ratio_to_f64(b))?;
    let fr = BigRational::from_float(f)?;
    let slack = BigRational::from_float(f.abs().max(f64::MIN_POSITIVE) * 1e-9)?;
    let x = simplest_rational(&(fr.clone() - &slack), &(fr + &slack));
    (x > *a && x < *b && sign_at(p, &x) == Ordering::Equal).then_some(x)
}

/// An integer `B` with every root strictly inside `(−B, B)`: the smaller of `2 + ⌊max |c_i| /
/// |c_n|⌋` (above Cauchy's bound `1 + max |c_i / c_n|`) and one more than an upper bound of
/// Fujiwara's `2·max_k |c_(n−k)/c_n|^(1/k)` (`|c_0/(2c_n)|^(1/n)` for the last term).
fn integer_root_bound(p: &[BigInt]) -> BigInt {
    let lc = p.last().expect("non-zero polynomial").abs();
    let m = p[..p.len() - 1].iter().map(|c| c.abs()).max().unwrap_or_default();
    let cauchy = m / &lc + 2;
    // Fujiwara's bound 2·max_k |c_(n−k)/c_n|^(1/k) (the last term halved) is often far smaller:
    // the k-th roots taken from bit lengths, rounded up (|c| < 2^bits)
    let n = p.len() - 1;
    let lc_bits = lc.bits() as f64 - 1.0; // |lc| ≥ 2^(bits − 1)
    let exponent = (1..=n)
        .filter(|&k| !p[n - k].is_zero())
        .map(|k| {
            let bits = p[n - k].bits() as f64 - if k == n { 1.0 } else { 0.0 };
            (bits - lc_bits) / k as f64
        })
        .fold(f64::NEG_INFINITY, f64::max);
    if exponent.is_finite() && exponent < 60.0 {
        let fujiwara = BigInt::from((2.0 * exponent.exp2()).ceil() as u64 + 1);
        return fujiwara.min(cauchy);
    }
    cauchy
}

/// `1 + max |c_i / c_n|`: every real root lies strictly inside `(−B, B)` (Cauchy).
fn cauchy_bound(p: &[BigRational]) -> BigRational {
    let lc = p.last().expect("non-zero polynomial").abs();
    let m = p[..p.len() - 1].iter().map(|c| c.abs() / &lc).max().unwrap_or_else(|| rat(0));
    (m + rat(1)).ceil() + rat(1)
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
    /// The distinct real roots of `p` (power form, lowest degree first), ascending; empty for a
    /// non-zero constant.
    ///
    /// # Panics
    /// **Panics for the zero polynomial** (every number is a root).
    pub fn real_roots(p: &[BigRational]) -> Vec<RealAlgebraic> {
        let p = crate::poly::polynomial::trim(p.to_vec());
        assert!(!p.is_empty(), "the zero polynomial has every number as a root");
        if p.len() == 1 {
            return vec![];
        }
        let b = cauchy_bound(&p);
        Self::roots_in(&p, &-b.clone(), &b)
    }

    /// The distinct real roots of `p` in the closed interval `[lo, hi]`, ascending.
    ///
    /// # Panics
    /// **Panics for the zero polynomial** or `lo > hi`.
    pub fn roots_in(p: &[BigRational], lo: &BigRational, hi: &BigRational) -> Vec<RealAlgebraic> {
        let p = crate::poly::polynomial::trim(p.to_vec());
        assert!(!p.is_empty(), "the zero polynomial has every number as a root");
        assert!(lo <= hi, "empty interval [{lo}, {hi}]");
        if lo == hi {
            let ip = primitive_part(to_integer(&p));
            return if sign_at(&ip, lo) == Ordering::Equal { vec![lo.clone().into()] } else { vec![] };
        }
        Self::roots_of_square_free(square_free_integer(primitive_part(to_integer(&p))), lo, hi)
    }

    /// [`Self::roots_in`] for a square-free primitive integer polynomial (`lo < hi`).
    pub(crate) fn roots_of_square_free(sf: Vec<BigInt>, lo: &BigRational, hi: &BigRational) -> Vec<RealAlgebraic> {
        if sf.len() <= 1 {
            return vec![];
        }
        let isolated = isolate_power(&sf, lo, hi);
        if !isolated.iter().any(|r| matches!(r, Root::Isolated(..))) {
            return isolated
                .into_iter()
                .map(|r| if let Root::Exact(x) = r { x.into() } else { unreachable!() })
                .collect();
        }
        // the polynomial of the other roots: the square-free part without the rational roots
        // found, exactly at split points or by a rational guess from an f64 candidate
        let mut poly = sf;
        for r in &isolated {
            if let Root::Exact(x) = r {
                poly = without_rational_root(poly, x);
            }
        }
        let mut found: Vec<Option<BigRational>> = vec![None; isolated.len()];
        let mut irrational = no_rational_roots(&poly);
        if !irrational {
            for (k, r) in isolated.iter().enumerate() {
                if let Root::Isolated(a, b) = r
                    && let Some(x) = rational_guess(&poly, a, b)
                {
                    poly = without_rational_root(poly, &x);
                    found[k] = Some(x);
                }
            }
            irrational = no_rational_roots(&poly);
        }
        isolated
            .into_iter()
            .zip(found)
            .map(|(r, f)| match (r, f) {
                (Root::Exact(x), _) | (_, Some(x)) => x.into(),
                (Root::Isolated(a, b), None) => Self::from_isolated(poly.clone(), a, b, irrational),
            })
            .collect()
    }

    /// The root of `poly` in `(lo, hi)` (`lo < hi`) when the exact signs of `poly` at the ends
    /// are non-zero and opposite; `None` otherwise. The caller has proved the rest of the
    /// representation's invariant: `poly` square-free and primitive, and at most one root in
    /// `(lo, hi)` (a derivative that keeps its sign there, say); `irrational` when it has also
    /// proved that `poly` has no rational root ([`no_rational_roots`]), else the root is checked
    /// for a rational. The intersection oracle's fast route builds parameters this way from `f64`
    /// rounding cells.
    pub(crate) fn certified_root(
        poly: Vec<BigInt>,
        lo: BigRational,
        hi: BigRational,
        irrational: bool,
    ) -> Option<Self> {
        let (a, b) = (sign_at(&poly, &lo), sign_at(&poly, &hi));
        if a == Ordering::Equal || b == Ordering::Equal || a == b || qcmp(&lo, &hi) != Ordering::Less {
            return None;
        }
        let mut x = RealAlgebraic(Repr::Root { poly, lo, hi });
        if !irrational {
            x.detect_rational();
        }
        Some(x)
    }

    /// The root of `poly` (square-free, primitive) in `(lo, hi)`, where it changes sign; made
    /// rational when it is.
    fn from_isolated(poly: Vec<BigInt>, mut lo: BigRational, mut hi: BigRational, irrational: bool) -> Self {
        // an end may be another root of the polynomial (found exactly at a split point): move it
        // inward. p has exactly one root r in (lo, hi), all roots simple, so just inside a root
        // end p has the sign of p′ there (right of lo) or of −p′ (left of hi); bisecting with
        // those signs keeps r and ends with two ends where p ≠ 0.
        let dp = derivative_integer(&poly);
        loop {
            let s_lo = match sign_at(&poly, &lo) {
                Ordering::Equal => sign_at(&dp, &lo),
                s => s,
            };
            if sign_at(&poly, &lo) != Ordering::Equal && sign_at(&poly, &hi) != Ordering::Equal {
                break;
            }
            let mid = (lo.clone() + &hi) / rat(2);
            let s_mid = sign_at(&poly, &mid);
            if s_mid == Ordering::Equal {
                return mid.into();
            }
            if s_mid == s_lo {
                lo = mid;
            } else {
                // s_mid is the sign just inside hi: the root is in (lo, mid)
                hi = mid;
            }
        }
        let mut x = RealAlgebraic(Repr::Root { poly, lo, hi });
        if !irrational {
            x.detect_rational();
        }
        x
    }

    fn detect_rational(&mut self) {
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

    /// The number when it is rational.
    pub fn to_rational(&self) -> Option<&BigRational> {
        match &self.0 {
            Repr::Rational(r) => Some(r),
            Repr::Root { .. } => None,
        }
    }

    /// An interval `[lo, hi]` holding the number (`lo = hi` when rational).
    pub fn interval(&self) -> (BigRational, BigRational) {
        match &self.0 {
            Repr::Rational(r) => (r.clone(), r.clone()),
            Repr::Root { lo, hi, .. } => (lo.clone(), hi.clone()),
        }
    }

    /// The polynomial the number is a root of (square-free, primitive; degree 1 for a rational).
    pub fn polynomial(&self) -> Vec<BigInt> {
        match &self.0 {
            Repr::Rational(r) => vec![-r.numer().clone(), r.denom().clone()],
            Repr::Root { poly, .. } => poly.clone(),
        }
    }

    /// Halves the interval once (it may become the rational midpoint itself).
    pub fn bisect(&mut self) {
        let Repr::Root { poly, lo, hi } = &mut self.0 else { return };
        let mid = (lo.clone() + &*hi) / rat(2);
        let s = sign_at(poly, &mid);
        if s == Ordering::Equal {
            self.0 = Repr::Rational(mid);
        } else if s == sign_at(poly, lo) {
            *lo = mid;
        } else {
            *hi = mid;
        }
    }

    /// Narrows the interval below `width` (`width > 0`).
    pub fn refine(&mut self, width: &BigRational) {
        while let Repr::Root { lo, hi, .. } = &self.0 {
            if hi.clone() - lo < *width {
                return;
            }
            self.bisect();
        }
    }

    /// Puts `r` outside the open interval, or finds that the number is `r`: the number
    /// compared with the rational `r`, exactly.
    fn cmp_rational(&mut self, r: &BigRational) -> Ordering {
        let Repr::Root { lo, hi, .. } = &self.0 else { return self.position_given(r, Ordering::Equal) };
        if qcmp(r, lo) != Ordering::Greater || qcmp(r, hi) != Ordering::Less {
            return self.position_given(r, Ordering::Equal); // decided by the ends alone
        }
        let o = self.position_given(r, self.sign_at_lo());
        match (&mut self.0, o) {
            // r is the root itself: impossible for an irrational number, kept for safety
            (_, Ordering::Equal) => self.0 = Repr::Rational(r.clone()),
            (Repr::Root { hi, .. }, Ordering::Less) => *hi = r.clone(),
            (Repr::Root { lo, .. }, _) => *lo = r.clone(),
            _ => {}
        }
        o
    }

    /// The sign, exactly.
    pub fn sign(&self) -> Ordering {
        self.clone().cmp_rational(&rat(0))
    }

    /// The nearest `f64` (ties to even), correctly rounded: an `f64` candidate from a
    /// safeguarded Newton iteration, refined by one exact Newton step whose interval the exact
    /// signs prove and which rounds to one `f64`; else the candidate proved by the signs at
    /// the ends of its rounding cell (the midpoints to its neighbours); bisection when both
    /// fail ([`Self::narrowed_with_f64`]).
    pub fn to_f64(&self) -> f64 {
        match &self.0 {
            Repr::Rational(r) => ratio_to_f64(r),
            Repr::Root { .. } => self.narrowed_with_f64().1,
        }
    }

    /// [`Self::to_f64`] by bisection alone: the oracle of the fast route.
    fn to_f64_by_bisection(&self) -> f64 {
        let mut x = self.clone();
        loop {
            match &x.0 {
                Repr::Rational(r) => return ratio_to_f64(r),
                Repr::Root { lo, hi, .. } => {
                    let (a, b) = (ratio_to_f64(lo), ratio_to_f64(hi));
                    if a == b {
                        return a;
                    }
                }
            }
            x.bisect();
        }
    }

    /// The sign of the polynomial at the lower end (`Equal` for a rational).
    fn sign_at_lo(&self) -> Ordering {
        match &self.0 {
            Repr::Rational(_) => Ordering::Equal,
            Repr::Root { poly, lo, .. } => sign_at(poly, lo),
        }
    }

    /// Where the number lies relative to the rational `m`, without changing it: `Less` when
    /// the number is below `m` (`sign_lo`: the sign of the polynomial at the lower end).
    fn position_given(&self, m: &BigRational, sign_lo: Ordering) -> Ordering {
        match &self.0 {
            Repr::Rational(r) => r.cmp(m),
            Repr::Root { poly, lo, hi } => {
                if qcmp(m, lo) != Ordering::Greater {
                    return Ordering::Greater;
                }
                if qcmp(m, hi) != Ordering::Less {
                    return Ordering::Less;
                }
                match sign_at(poly, m) {
                    Ordering::Equal => Ordering::Equal,
                    s if s == sign_lo => Ordering::Greater,
                    _ => Ordering::Less,
                }
            }
        }
    }

    /// For an irrational number: narrows the interval to half an `f64` spacing — between an
    /// `f64` and the midpoint to its neighbour — and returns the nearest `f64`. The candidate
    /// comes from [`f64_root_candidate`]; exact signs at `f64`s around it (galloping outwards,
    /// then bisecting over the `f64`s in order) find the two consecutive `f64`s around the
    /// number, and the sign at their midpoint picks the nearer. `None` (number unchanged) when
    /// it is rational, rounds to zero, or lies outside the finite `f64` range.
    fn narrow_to_f64_cell(&mut self) -> Option<f64> {
        let Repr::Root { poly, lo, hi } = &self.0 else { return None };
        let start = f64_root_candidate(poly, ratio_to_f64(lo), ratio_to_f64(hi))?;
        // f64s in order as integers (negative ones mirrored), and back
        let key = |f: f64| -> i64 {
            if f.is_sign_negative() { -((f.to_bits() & !(1 << 63)) as i64) } else { f.to_bits() as i64 }
        };
        let from_key = |k: i64| -> f64 { if k < 0 { -f64::from_bits((-k) as u64) } else { f64::from_bits(k as u64) } };
        let exact = exact_f64;
        // the number's side of the f64 with key k: Greater when above it
        let sign_lo = self.sign_at_lo();
        let side = |k: i64| -> Option<Ordering> { Some(self.position_given(&exact(from_key(k))?, sign_lo)) };
        let k0 = key(start);
        let first = side(k0)?;
        if first == Ordering::Equal {
            return None;
        }
        let dir: i64 = if first == Ordering::Greater { 1 } else { -1 };
        // gallop: k0 on the number's near side, k1 past it
        let (mut near, mut step) = (k0, 1i64);
        let mut far = loop {
            let k = near.checked_add(dir * step)?;
            match side(k)? {
                Ordering::Equal => return None,
                o if o == first => {
                    near = k;
                    step = step.checked_mul(2)?;
                }
                _ => break k,
            }
        };
        while (far - near).abs() > 1 {
            let mid = near + (far - near) / 2;
            match side(mid)? {
                Ordering::Equal => return None,
                o if o == first => near = mid,
                _ => far = mid,
            }
        }
        let (below, above) = if dir == 1 { (near, far) } else { (far, near) };
        let (fb, fa) = (from_key(below), from_key(above));
        if !fb.is_finite()
            || !fa.is_finite()
            || fb == 0.0
            || fa == 0.0
            || fb.is_sign_negative() != fa.is_sign_negative()
        {
            return None;
        }
        let (eb, ea) = (exact(fb)?, exact(fa)?);
        let mid = {
            let (mb, ma, k) = aligned(&eb, &ea)?;
            dyadic(mb + ma, k + 1)
        };
        let (f, a, b) = match self.position_given(&mid, sign_lo) {
            Ordering::Equal => return None,
            Ordering::Less => (fb, eb, mid),
            Ordering::Greater => (fa, mid, ea),
        };
        let Repr::Root { lo, hi, .. } = &mut self.0 else { return None };
        if a > *lo {
            *lo = a;
        }
        if b < *hi {
            *hi = b;
        }
        Some(f)
    }

    /// A copy narrowed to half an `f64` spacing (when the fast route applies; otherwise
    /// unchanged), with the number correctly rounded to `f64`: both at the cost of one
    /// [`Self::to_f64`]. The copy is the same number; its tight interval makes enclosures of
    /// functions of it tight.
    pub fn narrowed_with_f64(&self) -> (RealAlgebraic, f64) {
        let mut x = self.clone();
        if let Some(f) = x.narrow_by_newton() {
            return (x, f);
        }
        match x.narrow_to_f64_cell() {
            Some(f) => (x, f),
            None => (x, self.to_f64_by_bisection()),
        }
    }

    /// A copy whose interval is narrower than `2^−bits` relative to the number (Newton steps
    /// proved by exact signs; a rational is returned as it is, and a number outside the fast
    /// route's reach as narrow as it got). Functions of the copy enclose tightly: narrow once,
    /// then take several images (as [`Self::map_rational_to_f64`] does) at the price of one.
    pub fn narrowed(&self, bits: u64) -> RealAlgebraic {
        let mut x = self.clone();
        x.refine_newton(bits);
        x
    }

    /// The `k`-th (1-based) real root of the number's polynomial, ascending: the roots of the
    /// (square-free) polynomial in `[−B, lo]` counted by isolation (no numbers built; `lo` is
    /// not a root), `B` an integer root bound, plus one.
    fn root_index(&self) -> usize {
        let Repr::Root { poly, lo, .. } = &self.0 else { return 1 };
        let b = BigRational::from_integer(integer_root_bound(poly));
        if *lo <= -b.clone() {
            return 1;
        }
        if lo.sign() != Ordering::Greater {
            return isolate_power(poly, &-b, lo).len() + 1;
        }
        // the negative roots, counted by Descartes' rule on p(−t) when that is exact (no sign
        // change: none; one: exactly one), else by isolation; then the roots in [0, lo]
        let signs = poly
            .iter()
            .enumerate()
            .filter(|(_, c)| !c.is_zero())
            .map(|(i, c)| c.is_negative() != (i % 2 == 1))
            .collect::<Vec<bool>>();
        let changes = signs.windows(2).filter(|w| w[0] != w[1]).count();
        let negative = if changes <= 1 {
            changes
        } else {
            isolate_power(poly, &-b, &rat(0)).iter().filter(|r| !matches!(r, Root::Exact(x) if x.is_zero())).count()
        };
        negative + isolate_power(poly, &rat(0), lo).len() + 1
    }
}

/// An `f64` near the root of `p` in `(lo, hi)`, where `p` changes sign: Newton's method kept
/// inside a bracket that `f64` signs shrink (bisection when a step leaves it). Only a
/// candidate: the exact test of [`RealAlgebraic::narrow_to_f64_cell`] decides. `None` when the
/// coefficients do not fit `f64` or the bracket is not finite.
fn f64_root_candidate(p: &[BigInt], lo: f64, hi: f64) -> Option<f64> {
    use num_traits::ToPrimitive;
    if !(lo.is_finite() && hi.is_finite() && lo <= hi) {
        return None;
    }
    if lo == hi {
        return Some(lo); // an interval within one f64 spacing
    }
    // scaled so that the largest coefficient is near 1 (signs and roots unchanged)
    let bits = p.iter().map(BigInt::bits).max().unwrap_or(0);
    let shift = bits.saturating_sub(60);
    let c: Vec<f64> = p.iter().map(|x| (x >> shift).to_f64().filter(|v| v.is_finite())).collect::<Option<_>>()?;
    let d: Vec<f64> = c.iter().enumerate().skip(1).map(|(k, v)| v * k as f64).collect();
    let horner = |q: &[f64], x: f64| q.iter().rev().fold(0.0, |acc, v| acc * x + v);
    let (mut a, mut b) = (lo, hi);
    let sa = horner(&c, a).signum();
    let mut x = a + (b - a) / 2.0;
    for _ in 0..100 {
        let fx = horner(&c, x);
        if fx == 0.0 {
            return Some(x);
        }
        if fx.signum() == sa {
            a = x;
        } else {
            b = x;
        }
        let dx = horner(&d, x);
        let newton = x - fx / dx;
        let next = if newton > a && newton < b { newton } else { a + (b - a) / 2.0 };
        if next == x || b <= a.next_up() {
            return Some(next);
        }
        x = next;
    }
    Some(x)
}

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

/// Bernstein coefficients of `p` (power form) on `[lo, hi]`.
fn bernstein_on(p: &[BigRational], lo: &BigRational, hi: &BigRational) -> Vec<BigRational> {
    let q = shifted(p, lo, hi);
    if q.is_empty() {
        return vec![rat(0)];
    }
    let n = q.len() - 1;
    let m = power_to_bernstein_matrix(n);
    (0..=n).map(|i| (0..=n).fold(rat(0), |acc, k| acc + &m[i][k] * &q[k])).collect()
}

impl RealAlgebraic {
    /// The sign of `q(x)` for this number `x` (`q` in power form), exactly: zero when `q` and
    /// the number's polynomial share a root in its interval, otherwise the sign on an interval
    /// refined until `q` has no root in it.
    pub fn sign_of(&self, q: &[BigRational]) -> Ordering {
        let q = crate::poly::polynomial::trim(q.to_vec());
        if q.is_empty() {
            return Ordering::Equal;
        }
        let qi = primitive_part(to_integer(&q));
        let scale_sign = q.last().expect("non-zero").sign();
        let adjust = |o: Ordering| if scale_sign == Ordering::Less { o.reverse() } else { o };
        let mut x = self.clone();
        if let Some(r) = x.to_rational() {
            return adjust(sign_at(&qi, r));
        }
        let g = gcd_integer(&x.polynomial(), &qi);
        let (lo, hi) = x.interval();
        if g.len() > 1 {
            let (a, b) = (sign_at(&g, &lo), sign_at(&g, &hi));
            if a != b && a != Ordering::Equal && b != Ordering::Equal {
                return Ordering::Equal;
            }
        }
        loop {
            if let Some(r) = x.to_rational() {
                return adjust(sign_at(&qi, r));
            }
            let (lo, hi) = x.interval();
            let qr: Vec<BigRational> = qi.iter().map(|c| BigRational::from_integer(c.clone())).collect();
            if Self::roots_in(&qr, &lo, &hi).is_empty() {
                return adjust(sign_at(&qi, &lo));
            }
            x.bisect();
        }
    }

    /// `num(x) / den(x)` for this number `x`, exactly (power forms, lowest degree first):
    /// rational when `x` is, otherwise the root of `Res_t(p(t), den(t)·v − num(t))` (`p` the
    /// number's polynomial) that the Bernstein enclosure of `num/den` over `x`'s interval
    /// isolates, refining `x` until it does.
    ///
    /// # Panics
    /// **Panics when `den(x) = 0`.**
    ///
    /// # Example
    /// ```
    /// use casteljau::{rat, poly::algebraic::RealAlgebraic};
    /// let s2 = RealAlgebraic::real_roots(&[rat(-2), rat(0), rat(1)])[1].clone(); // √2
    /// // (x² + x)/(x + 1) = x; x³ = 2√2
    /// assert_eq!(s2.map_rational(&[rat(0), rat(1), rat(1)], &[rat(1), rat(1)]), s2);
    /// assert_eq!(s2.map_rational(&[rat(0), rat(0), rat(0), rat(1)], &[rat(1)]).to_string(), "2*sqrt(2)");
    /// ```
    pub fn map_rational(&self, num: &[BigRational], den: &[BigRational]) -> RealAlgebraic {
        let eval = |p: &[BigRational], x: &BigRational| p.iter().rev().fold(rat(0), |acc, c| acc * x + c);
        if let Some(x) = self.to_rational() {
            let d = eval(den, x);
            assert!(d != rat(0), "the denominator vanishes at {x}");
            return (eval(num, x) / d).into();
        }
        let num = crate::poly::polynomial::trim(num.to_vec());
        let den = crate::poly::polynomial::trim(den.to_vec());
        assert!(!den.is_empty(), "zero denominator");
        // integer numerator and denominator with one common scale
        let scale = num.iter().chain(&den).fold(BigInt::one(), |acc, c| num_integer::Integer::lcm(&acc, c.denom()));
        let int = |p: &[BigRational]| -> Vec<BigInt> {
            p.iter().map(|c| (c * BigRational::from_integer(scale.clone())).to_integer()).collect()
        };
        let (n_int, d_int) = (int(&num), int(&den));
        let mut p = self.polynomial();
        let r = loop {
            let len = n_int.len().max(d_int.len());
            let q: Vec<zv::P> = (0..len)
                .map(|j| {
                    let nj = n_int.get(j).cloned().unwrap_or_default();
                    let dj = d_int.get(j).cloned().unwrap_or_default();
                    zv::trim(vec![-nj, dj])
                })
                .collect();
            let q = {
                let mut q = q;
                while q.last().is_some_and(|c| c.is_empty()) {
                    q.pop();
                }
                q
            };
            let r = resultant_in_v(&p, &q);
            if !r.is_empty() {
                break r;
            }
            // num and den share a root with p (not x: den(x) ≠ 0): divide it out
            let g = gcd_integer(&p, &gcd_integer(&n_int, &d_int));
            p = crate::poly::polynomial::exact_quotient_integer(p, &g);
        };
        let r: Vec<BigRational> =
            square_free_integer(primitive_part(r)).into_iter().map(BigRational::from_integer).collect();
        // both in one degree, so that their Bernstein coefficients pair up
        let degree = num.len().max(den.len());
        let pad = |p: &[BigRational]| -> Vec<BigRational> {
            let mut v = p.to_vec();
            v.resize(degree, rat(0));
            v
        };
        let (num_d, den_d) = (pad(&num), pad(&den));
        let mut x = self.clone();
        loop {
            let (lo, hi) = x.interval();
            if let Some(xr) = x.to_rational() {
                let d = eval(&den, xr);
                return (eval(&num, xr) / d).into();
            }
            let bd = bernstein_on(&den_d, &lo, &hi);
            let positive = bd.iter().all(|c| c.sign() == Ordering::Greater);
            let negative = bd.iter().all(|c| c.sign() == Ordering::Less);
            if positive || negative {
                let bn = bernstein_on(&num_d, &lo, &hi);
                let ratios: Vec<BigRational> = bn.iter().zip(&bd).map(|(a, b)| a / b).collect();
                let e0 = ratios.iter().min().expect("coefficients").clone();
                let e1 = ratios.iter().max().expect("coefficients").clone();
                let roots = RealAlgebraic::roots_in(&r, &e0, &e1);
                if roots.len() == 1 {
                    return roots.into_iter().next().expect("one root");
                }
            }
            x.bisect();
        }
    }
}

/// `(m, k)` with `r = m / 2^k`, when the denominator of `r` is a power of two.
fn dyadic_parts(r: &BigRational) -> Option<(&BigInt, u64)> {
    let d = r.denom();
    let k = d.bits() - 1;
    (d.trailing_zeros() == Some(k)).then_some((r.numer(), k))
}

/// Two dyadic numbers over one power of two: `(m_a, m_b, k)` with `a = m_a/2^k`,
/// `b = m_b/2^k`; `None` unless both are dyadic.
fn aligned(a: &BigRational, b: &BigRational) -> Option<(BigInt, BigInt, u64)> {
    let ((ma, ka), (mb, kb)) = (dyadic_parts(a)?, dyadic_parts(b)?);
    let k = ka.max(kb);
    Some((ma << (k - ka), mb << (k - kb), k))
}

/// `a` against `b`, exactly: by a shift when both are dyadic (the usual case here), else by
/// cross-multiplication — `Ratio`'s own comparison divides, which costs more on these sizes.
fn qcmp(a: &BigRational, b: &BigRational) -> Ordering {
    if let Some((ma, mb, _)) = aligned(a, b) {
        return ma.cmp(&mb);
    }
    (a.numer() * b.denom()).cmp(&(b.numer() * a.denom()))
}

/// The larger of `a` and `b` ([`qcmp`]).
fn qmax(a: BigRational, b: &BigRational) -> BigRational {
    if qcmp(&a, b) == Ordering::Less { b.clone() } else { a }
}

/// The smaller of `a` and `b` ([`qcmp`]).
fn qmin(a: BigRational, b: &BigRational) -> BigRational {
    if qcmp(&a, b) == Ordering::Greater { b.clone() } else { a }
}

/// A finite positive `f64` as `m·2^e` (`m` an integer).
fn dyadic_parts_f64(x: f64) -> (u64, i64) {
    let (m, e, _) = num_traits::Float::integer_decode(x);
    (m, i64::from(e))
}

/// The rounding cell of the finite non-zero `f64` `u`: the numbers nearer to `u` than to its
/// neighbours, `[(u⁻ + u)/2, (u + u⁺)/2]`, exactly (`None` at the ends of the range).
pub(crate) fn f64_cell(u: f64) -> Option<(BigRational, BigRational)> {
    let (below, above) = (u.next_down(), u.next_up());
    if !(below.is_finite() && above.is_finite()) || u == 0.0 {
        return None;
    }
    let mid = |a: f64, b: f64| -> Option<BigRational> {
        let (ma, mb, k) = aligned(&exact_f64(a)?, &exact_f64(b)?)?;
        Some(dyadic(ma + mb, k + 1))
    };
    Some((mid(below, u)?, mid(u, above)?))
}

/// `m / 2^k` as a reduced ratio, by trailing zeros (no gcd).
fn dyadic(m: BigInt, k: u64) -> BigRational {
    if m.is_zero() {
        return rat(0);
    }
    let tz = m.trailing_zeros().unwrap_or(0).min(k);
    BigRational::new_raw(m >> tz, BigInt::one() << (k - tz))
}

/// A finite `f64` as an exact reduced ratio, without a gcd (its denominator is a power of two).
fn exact_f64(f: f64) -> Option<BigRational> {
    if !f.is_finite() {
        return None;
    }
    let (mantissa, exponent, sign) = num_traits::Float::integer_decode(f);
    let m = BigInt::from(mantissa) * i64::from(sign);
    Some(if exponent >= 0 {
        BigRational::from_integer(m << exponent as u64)
    } else {
        dyadic(m, u64::from(exponent.unsigned_abs()))
    })
}

/// One Newton step for the integer polynomial `p` (derivative `dp`) from `c = cm/2^ck`: the
/// dyadic interval `x₁ ± ε` around `x₁ = c − p(c)/p′(c)`, with `ε` about `2^16` times the
/// square of the step (quadratic convergence). `None` where `p(c) = 0` or `p′(c) = 0`. Only a
/// proposal — the caller proves it by exact signs at its ends — so the step is divided from
/// the leading bits of `p(c)` and `p′(c)`, with an error far below `ε`.
fn newton_proposal(p: &[BigInt], dp: &[BigInt], cm: &BigInt, ck: u64) -> Option<(BigRational, BigRational)> {
    let pv = homogeneous_value(p, cm, ck); // 2^(ck·n) p(c)
    let dv = homogeneous_value(dp, cm, ck) << ck; // 2^(ck·n) p′(c)
    if dv.is_zero() || pv.is_zero() {
        return None;
    }
    // the step p(c)/p′(c) is about 2^−e; ε = 2^−r, on the grid 2^−kn
    let e = dv.bits() as i64 - pv.bits() as i64;
    let r = (2 * e - 16).max(ck as i64 + 1);
    let kn = (r + 8) as u64;
    let sh = dv.bits().saturating_sub((kn as i64 - e).max(0) as u64 + 64);
    let q = ((pv << kn) >> sh) / (dv >> sh);
    let x = (cm << (kn - ck)) - q;
    let unit = BigInt::from(256);
    Some((dyadic(&x - &unit, kn), dyadic(x + unit, kn)))
}

/// One exact Newton step `u − p(u)/p′(u)` for the integer polynomial `p` (derivative `dp`) from
/// the `f64` `u`, rounded to `f64`: near a simple root, `u` within `ε` of it gives a point within
/// about `ε²` (times `p″/p′`), so this is the root correctly rounded unless the root lies that
/// close to a rounding boundary. Only a proposal (the caller proves what it uses). `None` where
/// `p′(u) = 0` or `u` is not finite.
pub(crate) fn newton_step_f64(p: &[BigInt], dp: &[BigInt], u: f64) -> Option<f64> {
    let c = exact_f64(u)?;
    let (m, k) = dyadic_parts(&c)?;
    // p(u) = P/2^(kn), p′(u) = D/2^(k(n−1)): u − p(u)/p′(u) = (m·D − P)/(D·2^k)
    let n = p.len().checked_sub(1)?;
    let (pv, dv) = (homogeneous_value(p, m, k), homogeneous_value(dp, m, k));
    // dp has formal degree n − 1 when dp.len() = n
    if dv.is_zero() || dp.len() != n {
        return None;
    }
    let (num, den) = (m * &dv - pv, dv << k);
    let (num, den) = if den.is_negative() { (-num, -den) } else { (num, den) };
    Some(ratio_to_f64(&BigRational::new_raw(num, den)))
}

/// `2^(k·n)·p(m/2^k)` for an integer polynomial of formal degree `n = p.len() − 1`.
fn homogeneous_value(p: &[BigInt], m: &BigInt, k: u64) -> BigInt {
    let Some(n) = p.len().checked_sub(1) else { return BigInt::zero() };
    let mut acc = p[n].clone();
    for i in (0..n).rev() {
        acc = acc * m + (&p[i] << (k * (n - i) as u64));
    }
    acc
}

/// `p(r)` exactly, for an integer polynomial (homogeneous Horner, one division at the end).
pub(crate) fn value_at(p: &[BigInt], r: &BigRational) -> BigRational {
    let Some(n) = p.len().checked_sub(1) else { return rat(0) };
    let (a, b) = (r.numer(), r.denom());
    let mut acc = p[n].clone();
    let mut bpow = BigInt::one();
    for c in p[..n].iter().rev() {
        bpow *= b;
        acc = acc * a + c * &bpow;
    }
    BigRational::new(acc, bpow)
}

impl RealAlgebraic {
    /// A lower bound for the degree of the number over `Q` (the degree of its minimal
    /// polynomial): `1` for a rational, at least `2` for a root (which is irrational), more when
    /// [`crate::poly::modular::min_factor_degree`] proves that its polynomial has no factor of
    /// smaller degree. Stops looking once the bound reaches `enough`.
    ///
    /// # Example
    /// ```
    /// use casteljau::{rat, poly::algebraic::RealAlgebraic};
    /// // a root of t³ − 2 (irreducible: degree 3); √2 as a root of t⁴ − 4 = (t² − 2)(t² + 2): 2
    /// let c = RealAlgebraic::real_roots(&[rat(-2), rat(0), rat(0), rat(1)]);
    /// assert_eq!(c[0].degree_lower_bound(10), 3);
    /// let q = RealAlgebraic::real_roots(&[rat(-4), rat(0), rat(0), rat(0), rat(1)]);
    /// assert_eq!(q[1].degree_lower_bound(10), 2);
    /// ```
    pub fn degree_lower_bound(&self, enough: usize) -> usize {
        match &self.0 {
            Repr::Rational(_) => 1,
            // irrational: 2 already, and nothing more is asked for below 3
            Repr::Root { .. } if enough <= 2 => 2,
            Repr::Root { poly, .. } => crate::poly::modular::min_factor_degree(poly, enough).max(2),
        }
    }

    /// Narrows the interval below `2^−bits` relative to the number's magnitude: Newton steps
    /// in exact dyadic arithmetic from the `f64` cell ([`Self::narrow_to_f64_cell`]), each
    /// proposing an interval about the square of the current width that the exact signs at its
    /// ends prove (or four bisections when they do not), so precision roughly doubles per step.
    /// Returns `false` (the number unchanged or partly narrowed) when the number is rational, its
    /// `f64` cell is unavailable, or an end is not dyadic.
    fn refine_newton(&mut self, bits: u64) -> bool {
        let Repr::Root { lo, hi, .. } = &self.0 else { return false };
        let (flo, fhi) = (ratio_to_f64(lo), ratio_to_f64(hi));
        // the magnitude, for the target: the ends' when they are a few f64s apart (an f64
        // rounding cell, say; the smaller end's, so the target is no coarser), else found by
        // narrowing to a cell first (Newton from a wide interval's midpoint may not converge)
        let close = flo != 0.0 && flo.is_sign_negative() == fhi.is_sign_negative() && fhi <= flo.next_up().next_up();
        let f = if close {
            if flo.abs() < fhi.abs() { flo } else { fhi }
        } else {
            self.narrow_to_f64_cell().unwrap_or(0.0)
        };
        if f == 0.0 || !f.is_finite() {
            return false;
        }
        // the target: width below 2^target
        let target = f.abs().log2().floor() as i64 - bits as i64;
        let mut sign_lo = None;
        for _ in 0..64 {
            let Repr::Root { poly, lo, hi } = &self.0 else { return false };
            let Some((ml, mh, k)) = aligned(lo, hi) else { return false };
            // the width m_w / 2^k and its binary order, −log₂ w ≈ k − bits(m_w)
            let wbits = k as i64 - (&mh - &ml).bits() as i64;
            if wbits > -target {
                return true;
            }
            // Newton from the midpoint (ml + mh) / 2^(k+1)
            let dp = derivative_integer(poly);
            let proposed = newton_proposal(poly, &dp, &(&ml + &mh), k + 1).map(|(a, b)| (qmax(a, lo), qmin(b, hi)));
            let sign_lo = *sign_lo.get_or_insert_with(|| self.sign_at_lo());
            let proved = proposed.filter(|(a, b)| {
                self.position_given(a, sign_lo) == Ordering::Greater
                    && self.position_given(b, sign_lo) == Ordering::Less
            });
            match proved {
                Some((a, b)) => {
                    let Repr::Root { lo, hi, .. } = &mut self.0 else { return false };
                    *lo = a;
                    *hi = b;
                }
                None => {
                    for _ in 0..4 {
                        self.bisect();
                    }
                }
            }
        }
        true
    }

    /// For an irrational number: narrows the interval by one Newton step from an `f64`
    /// candidate ([`f64_root_candidate`], [`newton_proposal`]) to about the square of an `f64`
    /// spacing, proved by the exact signs at its ends, and returns the `f64` both ends round
    /// to. `None` (number unchanged) when the step is not proved or its interval straddles a
    /// rounding boundary; [`Self::narrow_to_f64_cell`] then decides.
    fn narrow_by_newton(&mut self) -> Option<f64> {
        let Repr::Root { poly, lo, hi } = &self.0 else { return None };
        let f = f64_root_candidate(poly, ratio_to_f64(lo), ratio_to_f64(hi))?;
        if f == 0.0 {
            return None;
        }
        let c = exact_f64(f)?;
        let (cm, ck) = dyadic_parts(&c)?;
        let dp = derivative_integer(poly);
        let (a, b) = newton_proposal(poly, &dp, cm, ck)?;
        let (a, b) = (qmax(a, lo), qmin(b, hi));
        let rounded = ratio_to_f64(&a);
        if rounded != ratio_to_f64(&b) || rounded == 0.0 || !rounded.is_finite() {
            return None;
        }
        let sign_lo = self.sign_at_lo();
        if self.position_given(&a, sign_lo) != Ordering::Greater || self.position_given(&b, sign_lo) != Ordering::Less {
            return None;
        }
        let Repr::Root { lo, hi, .. } = &mut self.0 else { return None };
        *lo = a;
        *hi = b;
        Some(rounded)
    }

    /// `num(x) / den(x)` for this number `x`, correctly rounded to `f64` (integer power forms,
    /// lowest degree first), without the exact image: the Bernstein coefficients of `num` and
    /// `den` over a narrow interval of `x` ([`Self::narrowed`]) enclose the value; once
    /// both ends of the enclosure round to one `f64`, so does the value. Falls back to the exact
    /// image ([`Self::map_rational`]) when that does not settle (a value on a rounding
    /// boundary is rational, and only the exact route can say so).
    ///
    /// # Panics
    /// **Panics when `den(x) = 0`.**
    ///
    /// # Example
    /// ```
    /// use casteljau::{rat, poly::algebraic::RealAlgebraic};
    /// use num_bigint::BigInt;
    /// let s2 = RealAlgebraic::real_roots(&[rat(-2), rat(0), rat(1)])[1].clone(); // √2
    /// let b = |c: &[i64]| c.iter().map(|&x| BigInt::from(x)).collect::<Vec<_>>();
    /// // (x³ + 1)/3 at √2 = 1.27614237491539669920…, correctly rounded; the f64 expression
    /// // (2.0 * 2f64.sqrt() + 1.0) / 3.0 rounds three times and lands one f64 higher
    /// let v = s2.map_rational_to_f64(&b(&[1, 0, 0, 1]), &b(&[3]));
    /// assert_eq!(v, 1.2761423749153966);
    /// assert_eq!((2.0 * 2f64.sqrt() + 1.0) / 3.0, v.next_up());
    /// ```
    pub fn map_rational_to_f64(&self, num: &[BigInt], den: &[BigInt]) -> f64 {
        if let Some(x) = self.to_rational() {
            let d = value_at(den, x);
            assert!(!d.is_zero(), "the denominator vanishes at {x}");
            return ratio_to_f64(&(value_at(num, x) / d));
        }
        self.map_rational_by_enclosure(num, den).unwrap_or_else(|| {
            let q = |p: &[BigInt]| p.iter().map(|c| BigRational::from_integer(c.clone())).collect::<Vec<_>>();
            self.map_rational(&q(num), &q(den)).to_f64()
        })
    }

    /// [`Self::map_rational_to_f64`] for a constant denominator `d` (a polynomial image), by the
    /// mean value theorem: over a narrow dyadic interval `[lo, hi]` of the number `x`,
    /// `|num(x) − num(lo)| ≤ B·(hi − lo)` with `B = Σ k|c_k|·R^(k−1) ≥ max |num′|` (`R ≥
    /// |lo|, |hi|`; `B` summed in `f64` rounded upwards), so `num(x)/d` lies within
    /// `B·(hi − lo)/|d|` of `num(lo)/d` (exact); once both ends of that interval round to one
    /// `f64`, so does the value. One exact evaluation instead of the Bernstein conversions of
    /// the general route. `None` when it does not settle.
    fn map_polynomial_to_f64(&self, num: &[BigInt], d: &BigInt) -> Option<f64> {
        use num_traits::ToPrimitive;
        let n = num.len().checked_sub(1)?;
        if d.is_zero() {
            return None;
        }
        let mut x = self.clone();
        for bits in [60, 120] {
            if !x.refine_newton(bits) {
                return None;
            }
            let Repr::Root { lo, hi, .. } = &x.0 else { return None };
            let (ml, mh, k) = aligned(lo, hi)?;
            let r = ratio_to_f64(lo).abs().max(ratio_to_f64(hi).abs()).next_up();
            let mut b = 0.0f64;
            for (i, c) in num.iter().enumerate().skip(1).rev() {
                let term = ((i as f64) * c.abs().to_f64()?.next_up()).next_up();
                b = ((b * r).next_up() + term).next_up();
            }
            if !b.is_finite() || !r.is_finite() {
                return None;
            }
            let (bm, be) = dyadic_parts_f64(b);
            // over the denominator 2^(kn + s)·|d|: num(lo)/d and δ = B·(hi − lo)/|d|
            let h = homogeneous_value(num, &ml, k); // 2^(kn)·num(lo)
            let h = if d.is_negative() { -h } else { h };
            let kn1 = (k * n.saturating_sub(1) as u64) as i64;
            let s = (-be - kn1).max(0);
            let nv = h << s as u64;
            let nd = (BigInt::from(bm) * (mh - ml)) << (be + kn1 + s) as u64;
            let den = d.abs() << (k * n as u64 + s as u64);
            let (a, c) = (
                ratio_to_f64(&BigRational::new_raw(&nv - &nd, den.clone())),
                ratio_to_f64(&BigRational::new_raw(nv + nd, den)),
            );
            if a == c {
                return Some(a);
            }
        }
        None
    }

    /// The enclosure route of [`Self::map_rational_to_f64`] for an irrational number; `None`
    /// when it does not settle.
    fn map_rational_by_enclosure(&self, num: &[BigInt], den: &[BigInt]) -> Option<f64> {
        if den.len() == 1
            && let Some(v) = self.map_polynomial_to_f64(num, &den[0])
        {
            return Some(v);
        }
        let degree = num.len().max(den.len()).max(1) - 1;
        let pad = |p: &[BigInt]| -> Vec<BigInt> {
            let mut v = p.to_vec();
            v.resize(degree + 1, BigInt::zero());
            v
        };
        let (num_d, den_d) = (pad(num), pad(den));
        let mut x = self.clone();
        for bits in [60, 120, 240] {
            if !x.refine_newton(bits) {
                return None;
            }
            let Repr::Root { lo, hi, .. } = &x.0 else { return None };
            let to_b = |p: &[BigInt]| crate::poly::roots::power_to_bernstein_integer(&shifted_integer(p, lo, hi));
            let (bn, bd) = (to_b(&num_d), to_b(&den_d));
            let sign = bd[0].sign();
            if sign == num_bigint::Sign::NoSign || bd.iter().any(|c| c.sign() != sign) {
                continue;
            }
            // the extreme ratios bn_i / bd_i by cross-multiplication (bd of one sign), then
            // rounded unreduced: no gcd
            let less = |i: usize, j: usize| {
                let o = (&bn[i] * &bd[j]).cmp(&(&bn[j] * &bd[i]));
                if sign == num_bigint::Sign::Minus { o == Ordering::Greater } else { o == Ordering::Less }
            };
            let (mut i0, mut i1) = (0, 0);
            for i in 1..bn.len() {
                if less(i, i0) {
                    i0 = i;
                }
                if less(i1, i) {
                    i1 = i;
                }
            }
            let round = |i: usize| {
                let (n, d) = if sign == num_bigint::Sign::Minus {
                    (-bn[i].clone(), -bd[i].clone())
                } else {
                    (bn[i].clone(), bd[i].clone())
                };
                ratio_to_f64(&BigRational::new_raw(n, d))
            };
            let (f0, f1) = (round(i0), round(i1));
            if f0 == f1 {
                return Some(f0);
            }
        }
        None
    }
}

impl PartialEq for RealAlgebraic {
    fn eq(&self, o: &Self) -> bool {
        self.cmp(o) == Ordering::Equal
    }
}

impl Eq for RealAlgebraic {}

impl PartialOrd for RealAlgebraic {
    fn partial_cmp(&self, o: &Self) -> Option<Ordering> {
        Some(self.cmp(o))
    }
}

impl Ord for RealAlgebraic {
    /// Exact comparison (see the module's termination note).
    fn cmp(&self, o: &Self) -> Ordering {
        let (mut x, mut y) = (self.clone(), o.clone());
        if let Some(r) = y.to_rational().cloned() {
            return x.cmp_rational(&r);
        }
        if let Some(r) = x.to_rational().cloned() {
            return y.cmp_rational(&r).reverse();
        }
        // both irrational: cut both at the ends of the overlap
        let ((xl, xh), (yl, yh)) = (x.interval(), y.interval());
        if xh <= yl {
            return Ordering::Less;
        }
        if yh <= xl {
            return Ordering::Greater;
        }
        let (l, h) = (xl.max(yl), xh.min(yh));
        for cut in [&l, &h] {
            let (cx, cy) = (x.cmp_rational(cut), y.cmp_rational(cut));
            if cx != cy {
                return if cx == Ordering::Equal { cy.reverse() } else { cx.cmp(&cy) };
            }
        }
        // both in (l, h): equal iff gcd(p, q) has a root there (then it is both numbers)
        let (p, q) = (x.polynomial(), y.polynomial());
        let g = gcd_integer(&p, &q);
        if g.len() > 1 {
            let (sl, sh) = (sign_at(&g, &l), sign_at(&g, &h));
            if sl != sh && sl != Ordering::Equal && sh != Ordering::Equal {
                return Ordering::Equal;
            }
        }
        // distinct: refine both until the intervals separate (open intervals: touching ends
        // separate them too)
        loop {
            x.bisect();
            y.bisect();
            if x.to_rational().is_some() || y.to_rational().is_some() {
                return x.cmp(&y);
            }
            let ((xl, xh), (yl, yh)) = (x.interval(), y.interval());
            if xh <= yl {
                return Ordering::Less;
            }
            if yh <= xl {
                return Ordering::Greater;
            }
        }
    }
}

/// `c_n t^n + … + c_0` with integer coefficients.
fn poly_text(p: &[BigInt]) -> String {
    let mut s = String::new();
    for (k, c) in p.iter().enumerate().rev() {
        if c.is_zero() {
            continue;
        }
        let neg = c.is_negative();
        let mag = c.abs();
        s.push_str(match (s.is_empty(), neg) {
            (true, true) => "-",
            (true, false) => "",
            (false, true) => " - ",
            (false, false) => " + ",
        });
        let one = mag.is_one();
        match k {
            0 => s.push_str(&mag.to_string()),
            _ => {
                if !one {
                    s.push_str(&format!("{mag}*"));
                }
                s.push('t');
                if k > 1 {
                    s.push_str(&format!("^{k}"));
                }
            }
        }
    }
    s
}

impl RealAlgebraic {
    /// For an irrational number: the coarsest dyadic interval `[k/2^j, (k+1)/2^j]`, `j ≥ 4`, that
    /// holds it and no other root of its polynomial inside — a function of the number alone, not
    /// of the interval it happens to carry (so every route to one number prints it alike).
    fn canonical_interval(&self) -> Option<(BigRational, BigRational)> {
        let Repr::Root { poly, .. } = &self.0 else { return None };
        let mut x = self.clone();
        for j in 4u64.. {
            let cell = BigRational::new(BigInt::one(), BigInt::one() << j);
            x.refine(&cell);
            let Repr::Root { lo, hi, .. } = &x.0 else { return None };
            // x lies in the grid cell of lo or in the next one (the width is below a cell)
            let k = (lo.clone() / &cell).floor();
            let next = (k.clone() + BigRational::one()) * &cell;
            let k = if qcmp(&next, hi) == Ordering::Less && x.cmp_rational(&next) == Ordering::Greater {
                k + BigRational::one()
            } else {
                k
            };
            let (a, b) = (k.clone() * &cell, (k + BigRational::one()) * &cell);
            let inside = isolate_power(poly, &a, &b)
                .iter()
                .filter(|r| !matches!(r, Root::Exact(e) if *e == a || *e == b))
                .count();
            if inside == 1 {
                return Some((a, b));
            }
        }
        None
    }
}

impl fmt::Display for RealAlgebraic {
    /// A rational, `a + b*sqrt(d)`, or `root k of <poly> in [lo, hi]` with `[lo, hi]` the
    /// coarsest dyadic interval `[k/2^j, (k+1)/2^j]`, `j ≥ 4`, that holds no other root of the
    /// polynomial inside (the same string for the same number, whatever interval it carries).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let mut shown = self.clone();
        if let Some((lo, hi)) = self.canonical_interval()
            && let Repr::Root { poly, .. } = &self.0
        {
            shown = RealAlgebraic(Repr::Root { poly: poly.clone(), lo, hi });
        }
        match &shown.0 {
            Repr::Rational(r) => write!(f, "{r}"),
            Repr::Root { poly, lo, hi } if poly.len() == 3 => {
                let c: Vec<BigRational> = poly.iter().map(|c| BigRational::from_integer(c.clone())).collect();
                let inside = |x: &QuadraticExt<BigRational>| {
                    (x.clone() - QuadraticExt::from_base(lo.clone())).sign() == Ordering::Greater
                        && (x.clone() - QuadraticExt::from_base(hi.clone())).sign() == Ordering::Less
                };
                match quadratic_roots(&c[0], &c[1], &c[2]).into_iter().map(|(x, _)| x).find(inside) {
                    Some(x) => write!(f, "{x}"),
                    None => write!(f, "root {} of {} in [{lo}, {hi}]", shown.root_index(), poly_text(poly)),
                }
            }
            Repr::Root { poly, lo, hi } => {
                write!(f, "root {} of {} in [{lo}, {hi}]", shown.root_index(), poly_text(poly))
            }
        }
    }
}

impl serde::Serialize for RealAlgebraic {
    /// The exact string of `Display`.
    fn serialize<S: serde::Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
        s.collect_str(self)
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

    /// The displayed root index and interval agree with the ascending order of `real_roots` on
    /// random polynomials (negative roots counted by Descartes' rule or by isolation, the root
    /// bound Fujiwara's or Cauchy's), and the interval holds the number.
    #[test]
    fn displayed_index_and_interval_match_the_roots() {
        let mut next = crate::num::symmetric(0x0B5E_55ED_D15B_1A7E);
        let mut shown = 0;
        for round in 0..80 {
            let n = 2 + round % 7;
            let p: Vec<BigRational> = (0..=n).map(|_| rat(next(1 << (round % 40)) + next(9))).collect();
            if p[n] == rat(0) {
                continue;
            }
            for x in RealAlgebraic::real_roots(&p) {
                let Some((lo, hi)) = x.canonical_interval() else { continue };
                let text = x.to_string();
                let Repr::Root { poly, .. } = &x.0 else { continue };
                if !text.starts_with("root ") {
                    continue; // quadratic
                }
                // the index among the real roots of the displayed polynomial (rational roots of p
                // are divided out of it)
                let q: Vec<BigRational> = poly.iter().map(|c| BigRational::from_integer(c.clone())).collect();
                let i = RealAlgebraic::real_roots(&q).iter().position(|y| *y == x).expect("a root of its polynomial");
                assert!(text.starts_with(&format!("root {} of", i + 1)), "{text} is root {}", i + 1);
                assert!(
                    x.clone().cmp_rational(&lo) == Ordering::Greater && x.clone().cmp_rational(&hi) == Ordering::Less
                );
                shown += 1;
            }
        }
        assert!(shown > 40, "{shown} roots shown");
    }

    #[test]
    fn simplest_rationals_of_intervals() {
        assert_eq!(simplest_rational(&ratio(1, 3), &ratio(1, 2)), ratio(1, 2));
        assert_eq!(simplest_rational(&ratio(3, 10), &ratio(4, 10)), ratio(1, 3));
        assert_eq!(simplest_rational(&ratio(-7, 10), &ratio(-6, 10)), ratio(-2, 3));
        assert_eq!(simplest_rational(&ratio(-1, 10), &ratio(6, 10)), rat(0));
        assert_eq!(simplest_rational(&ratio(31415, 10000), &ratio(31416, 10000)), ratio(333, 106));
    }

    /// The fast `to_f64` (Newton candidate, exact cell test) against bisection alone, on every
    /// real root of random integer polynomials of degree 2 to 9 (wide and clustered roots).
    #[test]
    fn to_f64_cell_proof_matches_bisection() {
        let mut next = crate::num::symmetric(0x2545_F491_4F6C_DD1D);
        let (mut checked, mut fast, mut newton, mut irrational) = (0, 0, 0, 0);
        for round in 0..120 {
            let n = 2 + round % 8;
            let m = [3, 1000, 1 << 40][round % 3];
            let p: Vec<BigRational> = (0..=n).map(|_| rat(next(m))).collect();
            if p[n] == rat(0) {
                continue;
            }
            for r in RealAlgebraic::real_roots(&p) {
                assert_eq!(r.to_f64().to_bits(), r.to_f64_by_bisection().to_bits(), "{r}");
                let (narrow, f) = r.narrowed_with_f64();
                assert_eq!((narrow == r, f.to_bits()), (true, r.to_f64().to_bits()), "{r}");
                checked += 1;
                fast += usize::from(r.clone().narrow_to_f64_cell().is_some());
                newton += usize::from(r.clone().narrow_by_newton().is_some());
                irrational += usize::from(r.to_rational().is_none());
            }
        }
        assert!(checked > 100 && fast == irrational, "{checked} roots, {fast} of {irrational} by the cell proof");
        assert!(10 * newton >= 9 * irrational, "{newton} of {irrational} by one Newton step");
    }

    /// The rounded image by enclosures against the rounded exact image, on roots of random
    /// integer polynomials and random rational maps of degree ≤ 3.
    #[test]
    fn rounded_image_matches_the_exact_image() {
        let mut next = crate::num::symmetric(0x9E37_79B9_7F4A_7C15);
        let (mut checked, mut fast, mut irrational) = (0, 0, 0);
        let (mut constant, mut mean_value) = (0, 0);
        for round in 0..60 {
            let n = 2 + round % 6;
            let p: Vec<BigRational> = (0..=n).map(|_| rat(next(2000))).collect();
            if p[n] == rat(0) {
                continue;
            }
            let num: Vec<BigInt> = (0..4).map(|_| BigInt::from(next(3000))).collect();
            let den: Vec<BigInt> = if round % 2 == 0 {
                vec![BigInt::from((next(50).abs() + 1) * if round % 4 == 0 { -1 } else { 1 })]
            } else {
                vec![BigInt::from(40), BigInt::from(next(9)), BigInt::from(next(9))]
            };
            let q = |p: &[BigInt]| p.iter().map(|c| BigRational::from_integer(c.clone())).collect::<Vec<_>>();
            for r in RealAlgebraic::real_roots(&p) {
                if r.sign_of(&q(&den)) == Ordering::Equal {
                    continue;
                }
                let exact = r.map_rational(&q(&num), &q(&den)).to_f64();
                assert_eq!(r.map_rational_to_f64(&num, &den).to_bits(), exact.to_bits(), "{r}");
                checked += 1;
                if r.to_rational().is_none() {
                    irrational += 1;
                    fast += usize::from(r.map_rational_by_enclosure(&num, &den).is_some());
                    if den.len() == 1 {
                        constant += 1;
                        if let Some(v) = r.map_polynomial_to_f64(&num, &den[0]) {
                            assert_eq!(v.to_bits(), exact.to_bits(), "{r}");
                            mean_value += 1;
                        }
                    }
                }
            }
        }
        assert!(checked > 50 && fast == irrational, "{checked} checked, {fast} of {irrational} by enclosures");
        assert!(constant > 20 && mean_value == constant, "{mean_value} of {constant} by the mean value bound");
    }

    #[test]
    fn algebraic_order_and_equality_across_polynomials() {
        // √2 as a root of t² − 2 and of t⁴ − 4 (another polynomial): equal
        let a = RealAlgebraic::real_roots(&[rat(-2), rat(0), rat(1)])[1].clone();
        let b = RealAlgebraic::real_roots(&[rat(-4), rat(0), rat(0), rat(0), rat(1)])[1].clone();
        assert_eq!(a, b);
        // the polynomial is kept as given (square-free, not factored): √2 is spelled as a root of it
        assert_eq!(b.to_string(), "root 2 of t^4 - 4 in [11/8, 23/16]");
        let c = RealAlgebraic::real_roots(&[rat(-3), rat(0), rat(1)])[1].clone();
        assert!(a < c);
        assert_eq!(a.sign(), Ordering::Greater);
        assert_eq!(a.to_f64(), 2f64.sqrt());
    }
}
