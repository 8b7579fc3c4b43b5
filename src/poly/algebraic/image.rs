//! Images of a [`RealAlgebraic`] under rational maps: the exact sign of a polynomial at the
//! number, the exact image `num(x)/den(x)` (a root of a resultant, isolated by a Bernstein
//! enclosure), and that image correctly rounded to `f64` from enclosures over a narrowed
//! interval, without the resultant.

use super::dyadic::{aligned, dyadic_parts_f64, homogeneous_value};
use super::evaluate::{shifted_integer, sign_at, value_at};
use super::{RealAlgebraic, Repr};
use crate::num::scalar::{Exact, rat, ratio_to_f64};
use crate::poly::bernstein::power_to_bernstein_matrix;
use crate::poly::integer::{gcd_integer, primitive_part, square_free_integer};
use crate::poly::polynomial::Poly;
use crate::poly::resultant::{resultant_in_v, zv};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};
use std::cmp::Ordering;

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
    /// One round of a refinement loop whose rounds each cost a root isolation: narrows to
    /// `steps` more bits (Newton steps proved by exact signs, or `steps` bisections where
    /// those do not apply), then doubles `steps`, so the rounds grow with the logarithm of the
    /// bits a decision needs rather than with the bits (numbers of very different magnitudes
    /// need thousands).
    fn refine_faster(&mut self, steps: &mut usize) {
        let (lo, hi) = self.interval();
        let width = hi.clone() - &lo;
        // bits below the binary point of the width, and above it of the magnitude: the
        // precision relative to the number that narrows by `steps` more bits
        let (below, above) = (width.recip().to_integer().bits(), lo.abs().max(hi.abs()).to_integer().bits());
        let target = below.saturating_add(above).saturating_add(*steps as u64);
        let narrowed = self.refine_newton(target) && {
            let (lo, hi) = self.interval();
            (hi - lo) * rat(2) <= width
        };
        if !narrowed {
            self.bisect_times(*steps);
        }
        *steps = steps.saturating_mul(2);
    }

    /// The sign of `q(x)` for this number `x` (`q` in power form), exactly: zero when `q` and
    /// the number's polynomial share a root in its interval, otherwise the sign on an interval
    /// refined until `q` has no root in it.
    pub fn sign_of(&self, q: &Poly<BigRational>) -> Ordering {
        if q.is_zero() {
            return Ordering::Equal;
        }
        let qi = primitive_part(q.to_integer());
        let scale_sign = q.coeffs().last().expect("non-zero").sign();
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
        // each round narrows twice as far as the last (`refine_faster`)
        let qr = Poly::new(qi.iter().map(|c| BigRational::from_integer(c.clone())).collect());
        let mut steps = 1usize;
        loop {
            if let Some(r) = x.to_rational() {
                return adjust(sign_at(&qi, r));
            }
            let (lo, hi) = x.interval();
            if Self::roots_in(&qr, &lo, &hi).is_empty() {
                return adjust(sign_at(&qi, &lo));
            }
            x.refine_faster(&mut steps);
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
    /// use casteljau::{rat, poly::RealAlgebraic};
    /// use casteljau::poly::Poly;
    /// let s2 = RealAlgebraic::real_roots(&Poly::new(vec![rat(-2), rat(0), rat(1)]))[1].clone(); // √2
    /// // (x² + x)/(x + 1) = x; x³ = 2√2
    /// let (x2_plus_x, x_plus_1) = (Poly::new(vec![rat(0), rat(1), rat(1)]), Poly::new(vec![rat(1), rat(1)]));
    /// assert_eq!(s2.map_rational(&x2_plus_x, &x_plus_1), s2);
    /// let cube = Poly::new(vec![rat(0), rat(0), rat(0), rat(1)]);
    /// assert_eq!(s2.map_rational(&cube, &Poly::constant(rat(1))).to_string(), "2*sqrt(2)");
    /// ```
    pub fn map_rational(&self, num: &Poly<BigRational>, den: &Poly<BigRational>) -> RealAlgebraic {
        if let Some(x) = self.to_rational() {
            let d = den.eval(x);
            assert!(d != rat(0), "the denominator vanishes at {x}");
            return (num.eval(x) / d).into();
        }
        let (num_p, den_p) = (num, den);
        let (num, den) = (num.coeffs(), den.coeffs());
        assert!(!den.is_empty(), "zero denominator");
        // integer numerator and denominator with one common scale
        let scale = num.iter().chain(den).fold(BigInt::one(), |acc, c| num_integer::Integer::lcm(&acc, c.denom()));
        let int = |p: &[BigRational]| -> Vec<BigInt> {
            p.iter().map(|c| (c * BigRational::from_integer(scale.clone())).to_integer()).collect()
        };
        let (n_int, d_int) = (int(num), int(den));
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
            p = crate::poly::integer::exact_quotient_integer(p, &g);
        };
        let r = Poly::new(square_free_integer(primitive_part(r)).into_iter().map(BigRational::from_integer).collect());
        // both in one degree, so that their Bernstein coefficients pair up
        let degree = num.len().max(den.len());
        let pad = |p: &[BigRational]| -> Vec<BigRational> {
            let mut v = p.to_vec();
            v.resize(degree, rat(0));
            v
        };
        let (num_d, den_d) = (pad(num), pad(den));
        let mut x = self.clone();
        let mut steps = 1usize;
        loop {
            let (lo, hi) = x.interval();
            if let Some(xr) = x.to_rational() {
                return (num_p.eval(xr) / den_p.eval(xr)).into();
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
            x.refine_faster(&mut steps);
        }
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
    /// use casteljau::{rat, poly::RealAlgebraic};
    /// use num_bigint::BigInt;
    /// let s2 = RealAlgebraic::real_roots(&casteljau::poly::Poly::new(vec![rat(-2), rat(0), rat(1)]))[1].clone(); // √2
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
            let q = |p: &[BigInt]| Poly::new(p.iter().map(|c| BigRational::from_integer(c.clone())).collect());
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

#[cfg(test)]
mod tests {
    use super::*;

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
            let q = |p: &[BigInt]| Poly::new(p.iter().map(|c| BigRational::from_integer(c.clone())).collect());
            for r in RealAlgebraic::real_roots(&Poly::new(p)) {
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
}
