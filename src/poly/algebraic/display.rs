//! How a [`RealAlgebraic`] is written: a rational as a rational, a root of a quadratic as
//! `a + b*sqrt(d)`, anything else as `root k of <poly> in [lo, hi]` with `k` the root's index
//! among the polynomial's real roots and `[lo, hi]` the canonical interval, the coarsest dyadic
//! grid cell that isolates it — so one number prints alike whatever interval it carries.
//! `Serialize` writes the same string.

use super::dyadic::qcmp;
use super::evaluate::isolate_power;
use super::{RealAlgebraic, Repr};
use crate::num::quadratic_field::QuadraticExt;
use crate::num::scalar::{Exact, rat};
use crate::poly::polynomial::{Poly, quadratic_roots};
use crate::poly::roots::Root;
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};
use std::cmp::Ordering;
use std::fmt;

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

impl RealAlgebraic {
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

/// `c_n*t^n + … + c_0` with integer coefficients (the one printer, highest degree first).
fn poly_text(p: &[BigInt]) -> String {
    Poly::new(p.iter().map(|c| BigRational::from_integer(c.clone())).collect()).text_descending("t").to_string()
}

impl RealAlgebraic {
    /// For an irrational number: the coarsest dyadic interval `[k/2^j, (k+1)/2^j]`, `j ≥ 4`, that
    /// holds it and no other root of its polynomial inside — a function of the number alone, not
    /// of the interval it happens to carry (so every route to one number prints it alike).
    fn canonical_interval(&self) -> Option<(BigRational, BigRational)> {
        let Repr::Root { poly, .. } = &self.0 else { return None };
        let mut x = self.clone();
        // the cell of level j holding x, and whether it holds no other root inside; a cell that
        // isolates x contains the finer cells holding x, so isolation is monotone in j: a
        // galloping search then a bisection find the coarsest level in O(log j) isolations
        // (numbers of very different magnitudes need levels in the thousands)
        let mut cell_at = |j: u64| -> Option<(BigRational, BigRational, bool)> {
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
            Some((a, b, inside == 1))
        };
        let (mut coarse, mut fine) = (3u64, 4u64);
        let mut found = loop {
            let (a, b, isolated) = cell_at(fine)?;
            if isolated {
                break (a, b);
            }
            coarse = fine;
            fine = fine.checked_mul(2)?;
        };
        // the coarsest isolating level lies in (coarse, fine]
        while fine - coarse > 1 {
            let mid = coarse + (fine - coarse) / 2;
            let (a, b, isolated) = cell_at(mid)?;
            if isolated {
                fine = mid;
                found = (a, b);
            } else {
                coarse = mid;
            }
        }
        Some(found)
    }
}

impl fmt::Display for RealAlgebraic {
    /// A rational, `a + b*sqrt(d)`, or `root k of <poly> in [lo, hi]` with `[lo, hi]` the
    /// coarsest dyadic interval `[k/2^j, (k+1)/2^j]`, `j ≥ 4`, that holds no other root of the
    /// polynomial inside (the same string for the same number, whatever interval it carries).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        // a quadratic's root is written from its own isolating interval (any one picks the same
        // root); the canonical interval only for the other roots
        let quadratic = matches!(&self.0, Repr::Root { poly, .. } if poly.len() == 3);
        let mut shown = self.clone();
        if !quadratic
            && let Some((lo, hi)) = self.canonical_interval()
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
                    None => {
                        let (lo, hi) = self.canonical_interval().unwrap_or((lo.clone(), hi.clone()));
                        write!(f, "root {} of {} in [{lo}, {hi}]", shown.root_index(), poly_text(poly))
                    }
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
            for x in RealAlgebraic::real_roots(&crate::poly::Poly::new(p.clone())) {
                let Some((lo, hi)) = x.canonical_interval() else { continue };
                let text = x.to_string();
                let Repr::Root { poly, .. } = &x.0 else { continue };
                if !text.starts_with("root ") {
                    continue; // quadratic
                }
                // the index among the real roots of the displayed polynomial (rational roots of p
                // are divided out of it)
                let q: Vec<BigRational> = poly.iter().map(|c| BigRational::from_integer(c.clone())).collect();
                let i = RealAlgebraic::real_roots(&crate::poly::Poly::new(q.clone()))
                    .iter()
                    .position(|y| *y == x)
                    .expect("a root of its polynomial");
                assert!(text.starts_with(&format!("root {} of", i + 1)), "{text} is root {}", i + 1);
                assert!(
                    x.clone().cmp_rational(&lo) == Ordering::Greater && x.clone().cmp_rational(&hi) == Ordering::Less
                );
                shown += 1;
            }
        }
        assert!(shown > 40, "{shown} roots shown");
    }
}
