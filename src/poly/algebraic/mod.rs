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
//! use casteljau::poly::RealAlgebraic;
//! use casteljau::{rat, ratio};
//! // t² − 2: √2 and −√2; t³ − 2: ∛2
//! let r = RealAlgebraic::real_roots(&casteljau::poly::Poly::new(vec![rat(-2), rat(0), rat(1)]));
//! assert_eq!(r.iter().map(|x| x.to_string()).collect::<Vec<_>>(), ["-sqrt(2)", "sqrt(2)"]);
//! let c = RealAlgebraic::real_roots(&casteljau::poly::Poly::new(vec![rat(-2), rat(0), rat(0), rat(1)]));
//! assert_eq!(c[0].to_string(), "root 1 of t^3 - 2 in [5/4, 21/16]");
//! assert_eq!(c[0].to_f64(), 2f64.cbrt());
//! assert!(c[0] < r[1] && r[0] < RealAlgebraic::from(ratio(-1, 1)));
//! // (2t − 1)(t² − 3): the rational root is a rational
//! let m = RealAlgebraic::real_roots(&casteljau::poly::Poly::new(vec![rat(3), rat(-6), rat(-1), rat(2)]));
//! assert_eq!(m[1].to_string(), "1/2");
//! ```
//!
//! # Layout
//! This file holds the type, its construction from polynomials and its exact comparison. The
//! number's other operations live beside it, one concept to a file: `rounding` (correctly
//! rounded `f64`s and Newton narrowing), `image` (signs and images under rational maps) and
//! `display` (`Display`, the root index, the canonical interval), `field` (exact arithmetic in
//! `Q(α)`, crate-internal); with the helpers they share,
//! `rational_roots` (rational-root search, the simplest rational in an interval), `evaluate`
//! (integer polynomials at rationals and on rational intervals) and `dyadic` (exact dyadic
//! rationals). Resultants over `Z[v]` are `poly::resultant`'s.

mod display;
mod dyadic;
mod evaluate;
mod field;
mod image;
mod rational_roots;
mod rounding;

pub use evaluate::sign_at;
pub(crate) use evaluate::value_at;
pub(crate) use field::NumberField;
pub(crate) use rational_roots::no_rational_roots;
pub use rational_roots::simplest_rational;
pub(crate) use rounding::{f64_cell, newton_step_f64};
// the paths src/intersect uses
pub(crate) use crate::poly::resultant::{resultant_in_v, resultant_zv, zv};

use crate::num::scalar::rat;
use crate::poly::integer::{derivative_integer, gcd_integer, primitive_part, square_free_integer};
use crate::poly::polynomial::Poly;
use crate::poly::roots::Root;
use dyadic::qcmp;
use evaluate::isolate_power;
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::Signed;
use rational_roots::{rational_guess, without_rational_root};
use std::cmp::Ordering;

/// An exact real algebraic number (see the module documentation).
#[derive(Clone, Debug)]
pub struct RealAlgebraic(Repr);

#[derive(Clone, Debug)]
pub(in crate::poly::algebraic) enum Repr {
    Rational(BigRational),
    Root { poly: Vec<BigInt>, lo: BigRational, hi: BigRational },
}

impl From<BigRational> for RealAlgebraic {
    fn from(r: BigRational) -> Self {
        RealAlgebraic(Repr::Rational(r))
    }
}

/// `1 + max |c_i / c_n|`: every real root lies strictly inside `(−B, B)` (Cauchy).
fn cauchy_bound(p: &[BigRational]) -> BigRational {
    let lc = p.last().expect("non-zero polynomial").abs();
    let m = p[..p.len() - 1].iter().map(|c| c.abs() / &lc).max().unwrap_or_else(|| rat(0));
    (m + rat(1)).ceil() + rat(1)
}

impl RealAlgebraic {
    /// The distinct real roots of `p` (power form, lowest degree first), ascending; empty for a
    /// non-zero constant.
    ///
    /// # Panics
    /// **Panics for the zero polynomial** (every number is a root).
    pub fn real_roots(p: &Poly<BigRational>) -> Vec<RealAlgebraic> {
        assert!(!p.is_zero(), "the zero polynomial has every number as a root");
        if p.degree() == Some(0) {
            return vec![];
        }
        let b = cauchy_bound(p.coeffs());
        Self::roots_in(p, &-b.clone(), &b)
    }

    /// The distinct real roots of `p` in the closed interval `[lo, hi]`, ascending.
    ///
    /// # Panics
    /// **Panics for the zero polynomial** or `lo > hi`.
    pub fn roots_in(p: &Poly<BigRational>, lo: &BigRational, hi: &BigRational) -> Vec<RealAlgebraic> {
        assert!(!p.is_zero(), "the zero polynomial has every number as a root");
        assert!(lo <= hi, "empty interval [{lo}, {hi}]");
        if lo == hi {
            let ip = primitive_part(p.to_integer());
            return if sign_at(&ip, lo) == Ordering::Equal { vec![lo.clone().into()] } else { vec![] };
        }
        Self::roots_of_square_free(square_free_integer(primitive_part(p.to_integer())), lo, hi)
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

    /// The root of `poly` in `(lo, hi)` (`lo < hi`) when the caller has proved the whole
    /// invariant without evaluating `poly` at the ends: `poly` square-free, primitive, with a
    /// positive leading coefficient, and a root of it strictly inside `[lo, hi]`, where its
    /// derivative keeps one sign (so the root is the only one in `[lo, hi]`, and `poly` is
    /// non-zero at the ends with opposite signs). `irrational` as for
    /// [`Self::certified_root`]. The box solver's fixed-point refinement builds parameters this
    /// way from `f64` rounding cells.
    pub(crate) fn proved_root(poly: Vec<BigInt>, lo: BigRational, hi: BigRational, irrational: bool) -> Self {
        let mut x = RealAlgebraic(Repr::Root { poly, lo, hi });
        if !irrational {
            x.detect_rational();
        }
        x
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

    /// A rational strictly between `a < b`: the intervals are bisected until `a`'s upper end
    /// lies below `b`'s lower end, then the simplest rational (smallest denominator) of that
    /// gap, or its midpoint when the simplest is one of the gap's ends (which may be `a` or `b`
    /// itself).
    ///
    /// Terminates for `a < b`: each bisection halves an irrational number's interval and a
    /// rational one is exact, so the gap opens after finitely many steps.
    ///
    /// # Panics
    /// **Panics (in debug builds) unless `a < b`**; with `a ≥ b` it would not terminate.
    ///
    /// ```
    /// use casteljau::{rat, ratio, poly::{Poly, RealAlgebraic}};
    /// let s2 = RealAlgebraic::real_roots(&Poly::new(vec![rat(-2), rat(0), rat(1)]))[1].clone(); // √2
    /// assert_eq!(RealAlgebraic::rational_between(&s2, &rat(2).into()), ratio(7, 4));
    /// assert_eq!(RealAlgebraic::rational_between(&rat(0).into(), &rat(1).into()), ratio(1, 2));
    /// ```
    pub fn rational_between(a: &RealAlgebraic, b: &RealAlgebraic) -> BigRational {
        debug_assert!(a < b, "rational_between needs a < b");
        let (mut a, mut b) = (a.clone(), b.clone());
        loop {
            let (ah, bl) = (a.interval().1, b.interval().0);
            if ah < bl {
                let r = simplest_rational(&ah, &bl);
                return if r == ah || r == bl { (ah + bl) / rat(2) } else { r };
            }
            a.bisect();
            b.bisect();
        }
    }

    /// Halves the interval once (it may become the rational midpoint itself).
    pub fn bisect(&mut self) {
        self.bisect_while(|_, _| true, 1);
    }

    /// Bisects `times` times (stopping early when the number turns out rational).
    pub(crate) fn bisect_times(&mut self, times: usize) {
        self.bisect_while(|_, _| true, times);
    }

    /// Narrows the interval below `width` (`width > 0`).
    pub fn refine(&mut self, width: &BigRational) {
        self.bisect_while(|lo, hi| hi.clone() - lo >= *width, usize::MAX);
    }

    /// Bisects while `go(lo, hi)` holds, at most `times` times, stopping when the number turns
    /// out rational. The sign at `lo` is the same at every step (the interval isolates one
    /// root of the square-free polynomial, and `lo` never passes it), so it is computed once.
    fn bisect_while(&mut self, go: impl Fn(&BigRational, &BigRational) -> bool, times: usize) {
        let Repr::Root { poly, lo, hi } = &mut self.0 else { return };
        let lo_sign = sign_at(poly, lo);
        let mut exact = None;
        for _ in 0..times {
            if !go(lo, hi) {
                break;
            }
            let mid = (lo.clone() + &*hi) / rat(2);
            let s = sign_at(poly, &mid);
            if s == Ordering::Equal {
                exact = Some(mid);
                break;
            } else if s == lo_sign {
                *lo = mid;
            } else {
                *hi = mid;
            }
        }
        if let Some(mid) = exact {
            self.0 = Repr::Rational(mid);
        }
    }

    /// Puts `r` outside the open interval, or finds that the number is `r`: the number
    /// compared with the rational `r`, exactly.
    pub(in crate::poly::algebraic) fn cmp_rational(&mut self, r: &BigRational) -> Ordering {
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

    /// The sign of the polynomial at the lower end (`Equal` for a rational).
    pub(in crate::poly::algebraic) fn sign_at_lo(&self) -> Ordering {
        match &self.0 {
            Repr::Rational(_) => Ordering::Equal,
            Repr::Root { poly, lo, .. } => sign_at(poly, lo),
        }
    }

    /// Where the number lies relative to the rational `m`, without changing it: `Less` when
    /// the number is below `m` (`sign_lo`: the sign of the polynomial at the lower end).
    pub(in crate::poly::algebraic) fn position_given(&self, m: &BigRational, sign_lo: Ordering) -> Ordering {
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

    /// A lower bound for the degree of the number over `Q` (the degree of its minimal
    /// polynomial): `1` for a rational, at least `2` for a root (which is irrational), more when
    /// reductions modulo primes prove that its polynomial has no factor of
    /// smaller degree. Stops looking once the bound reaches `enough`.
    ///
    /// # Example
    /// ```
    /// use casteljau::{rat, poly::RealAlgebraic};
    /// // a root of t³ − 2 (irreducible: degree 3); √2 as a root of t⁴ − 4 = (t² − 2)(t² + 2): 2
    /// let c = RealAlgebraic::real_roots(&casteljau::poly::Poly::new(vec![rat(-2), rat(0), rat(0), rat(1)]));
    /// assert_eq!(c[0].degree_lower_bound(10), 3);
    /// let q = RealAlgebraic::real_roots(&casteljau::poly::Poly::new(vec![rat(-4), rat(0), rat(0), rat(0), rat(1)]));
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn algebraic_order_and_equality_across_polynomials() {
        // √2 as a root of t² − 2 and of t⁴ − 4 (another polynomial): equal
        let a = RealAlgebraic::real_roots(&crate::poly::Poly::new(vec![rat(-2), rat(0), rat(1)]))[1].clone();
        let b = RealAlgebraic::real_roots(&crate::poly::Poly::new(vec![rat(-4), rat(0), rat(0), rat(0), rat(1)]))[1]
            .clone();
        assert_eq!(a, b);
        // the polynomial is kept as given (square-free, not factored): √2 is spelled as a root of it
        assert_eq!(b.to_string(), "root 2 of t^4 - 4 in [11/8, 23/16]");
        let c = RealAlgebraic::real_roots(&crate::poly::Poly::new(vec![rat(-3), rat(0), rat(1)]))[1].clone();
        assert!(a < c);
        assert_eq!(a.sign(), Ordering::Greater);
        assert_eq!(a.to_f64(), 2f64.sqrt());
    }
}
