//! Exact arithmetic in `Q(α)` for a real algebraic number `α`: elements are polynomials in `α`
//! reduced modulo a polynomial `m` with `m(α) = 0`, signs are exact signs at `α`.
//!
//! `m` starts as the number's square-free polynomial, which may be reducible: `Q[t]/(m)` is then
//! a product of fields, not a field. Wherever that shows — an element that is not invertible
//! modulo `m` although it is non-zero at `α`, or one that vanishes at `α` without being zero
//! modulo `m` — `m` is replaced by the factor `α` is a root of (`m / gcd(m, a)` or `gcd(m, a)`),
//! so every answer is the one in the field `Q(α)` itself (dynamic evaluation). Representatives
//! reduced modulo the old `m` stay valid: the new `m` divides it.

use super::RealAlgebraic;
use crate::num::scalar::rat;
use crate::poly::polynomial::Poly;
use num_rational::BigRational;
use num_traits::Zero;
use std::cmp::Ordering;

/// `Q(α)`: see the module documentation.
#[derive(Clone, Debug)]
pub(crate) struct NumberField {
    alpha: RealAlgebraic,
    /// Monic, `m(α) = 0`.
    modulus: Poly<BigRational>,
}

/// An element of a [`NumberField`]: a polynomial in `α`.
pub(crate) type Element = Poly<BigRational>;

fn monic(p: Poly<BigRational>) -> Poly<BigRational> {
    let lead = p.coeffs().last().expect("a non-zero polynomial").clone();
    if lead == rat(1) { p } else { p.scale(&(rat(1) / lead)) }
}

impl NumberField {
    /// `Q(α)` (`Q` itself when `α` is rational).
    pub(crate) fn new(alpha: &RealAlgebraic) -> Self {
        let modulus = match alpha.to_rational() {
            Some(r) => Poly::new(vec![-r.clone(), rat(1)]),
            None => monic(Poly::new(alpha.polynomial().into_iter().map(BigRational::from_integer).collect())),
        };
        NumberField { alpha: alpha.clone(), modulus }
    }

    /// Whether the field is `Q`.
    pub(crate) fn is_rational(&self) -> bool {
        self.modulus.degree() == Some(1)
    }

    /// `p(α)` as an element: `p` reduced modulo `m`.
    pub(crate) fn reduce(&self, p: &Poly<BigRational>) -> Element {
        if p.degree().is_none_or(|d| d < self.modulus.degree().unwrap_or(0)) {
            return p.clone();
        }
        p.div_rem(&self.modulus).1
    }

    /// `a·b`.
    pub(crate) fn mul(&self, a: &Element, b: &Element) -> Element {
        if a.is_zero() || b.is_zero() {
            return Poly::zero();
        }
        self.reduce(&(a * b))
    }

    /// `a^k`.
    pub(crate) fn pow(&self, a: &Element, k: usize) -> Element {
        let mut out = Poly::constant(rat(1));
        let mut base = a.clone();
        let mut k = k;
        while k > 0 {
            if k & 1 == 1 {
                out = self.mul(&out, &base);
            }
            k >>= 1;
            if k > 0 {
                base = self.mul(&base, &base);
            }
        }
        out
    }

    /// The sign of `a(α)`, exactly; a zero that `m` does not show narrows `m` to `gcd(m, a)`.
    pub(crate) fn sign(&mut self, a: &Element) -> Ordering {
        if a.is_zero() {
            return Ordering::Equal;
        }
        if self.is_rational() {
            return a.coeff(0).cmp(&rat(0));
        }
        let s = self.alpha.sign_of(a);
        if s == Ordering::Equal {
            self.modulus = monic(self.modulus.gcd(a));
        }
        s
    }

    /// `1/a` for `a(α) ≠ 0` (checked by the caller with [`Self::sign`]): the Bézout coefficient
    /// of `a` modulo `m`, after dividing `m` by `gcd(m, a)` (which `α` is no root of).
    pub(crate) fn inverse(&mut self, a: &Element) -> Element {
        let a = self.reduce(a);
        loop {
            let g = self.modulus.gcd(&a);
            if g.degree() == Some(0) {
                break;
            }
            self.modulus = monic(self.modulus.div_rem(&g).0);
        }
        // extended Euclid: s·a ≡ r (mod m), down to a constant r
        let (mut r0, mut r1) = (self.modulus.clone(), self.reduce(&a));
        let (mut s0, mut s1) = (Poly::<BigRational>::zero(), Poly::constant(rat(1)));
        while r1.degree().is_some_and(|d| d > 0) {
            let (q, r) = r0.div_rem(&r1);
            let s = &s0 - &(&q * &s1);
            (r0, r1) = (r1, r);
            (s0, s1) = (s1, s);
        }
        let c = r1.coeff(0);
        debug_assert!(!c.is_zero(), "a is invertible modulo m");
        self.reduce(&s1.scale(&(rat(1) / c)))
    }

    /// `num(α)/den(α)` as a real algebraic number (`den(α) ≠ 0`).
    pub(crate) fn value(&self, num: &Element, den: &Element) -> RealAlgebraic {
        if self.is_rational() {
            return (num.coeff(0) / den.coeff(0)).into();
        }
        self.alpha.map_rational(num, den)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// √2 as a root of `t⁴ − 4 = (t² − 2)(t² + 2)`: `1/(α² + 2)` needs the factor `t² − 2`.
    #[test]
    fn field_inverse_narrows_a_reducible_modulus() {
        let p = Poly::new(vec![rat(-4), rat(0), rat(0), rat(0), rat(1)]);
        let s2 = RealAlgebraic::real_roots(&p)[1].clone();
        let mut f = NumberField::new(&s2);
        let a = Poly::new(vec![rat(2), rat(0), rat(1)]); // α² + 2 = 4
        let inv = f.inverse(&a);
        assert_eq!(f.mul(&inv, &a), Poly::constant(rat(1)));
        assert_eq!(f.value(&inv, &Poly::constant(rat(1))), RealAlgebraic::from(crate::num::scalar::ratio(1, 4)));
        // α² − 2 vanishes at α although it is not zero modulo t⁴ − 4
        let mut g = NumberField::new(&s2);
        assert_eq!(g.sign(&Poly::new(vec![rat(-2), rat(0), rat(1)])), Ordering::Equal);
        assert_eq!(g.reduce(&Poly::new(vec![rat(-2), rat(0), rat(1)])), Poly::zero());
        assert_eq!(g.sign(&Poly::new(vec![rat(0), rat(1)])), Ordering::Greater);
    }
}
