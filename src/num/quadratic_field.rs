//! Exact quadratic extensions `K(√d)` of an exact field `K`.
//!
//! Irrational answers of the theory — double-point parameters `t_E ± √(−c)`, the `√3` and
//! `√Δ` in the canonical cubic maps — are numbers `a + b√d` with `a, b, d ∈ K`. Nesting
//! (`QuadraticExt<QuadraticExt<BigRational>>`) gives towers such as `Q(√3)(√Δ)`.
//!
//! # Invariants
//! * `d` is not a square in `K` and is positive (so the extension is a real field and
//!   [`Exact::sign`] is meaningful). [`QuadraticExt::sqrt`] checks squareness for `K = Q`.
//! * Canonical form: when `b = 0` the radicand is stored as `0`. One number may still be
//!   spelled with different radicands (`1009·√2 = √(2·1009²)`): `==` is numeric equality
//!   whatever the spelling (`a₁ = a₂`, `b₁²d₁ = b₂²d₂` and `b₁, b₂` of one sign), and
//!   arithmetic brings two radicands whose quotient is a square in `K` onto one, whatever the
//!   size of their square factors.
//!
//! # Panics
//! **Arithmetic between two irrational elements of different fields panics** (radicands whose
//! quotient is not a square in `K`: `√2 + √3` is not in any `K(√d)`); so does division by zero.

use crate::num::scalar::{Exact, Scalar, rat};
use num_bigint::BigInt;

use num_rational::BigRational;
use num_traits::Signed;
use std::cmp::Ordering;
use std::fmt;
use std::ops::{Add, Div, Mul, Neg, Sub};

/// The number `a + b√d` of the real field `K(√d)`.
///
/// # Example
/// ```
/// use casteljau::{QuadraticExt, Scalar, Exact, ratio};
/// use num_rational::BigRational;
/// let s3 = QuadraticExt::sqrt(ratio(3, 1));             // √3
/// assert_eq!(s3.clone() * s3.clone(), QuadraticExt::from_i64(3));
/// let x = QuadraticExt::new(ratio(1, 2), ratio(1, 2), ratio(3, 1)); // (1 + √3)/2
/// assert_eq!((x.clone() * x.clone()).to_string(), "1 + 1/2*sqrt(3)");
/// assert_eq!((x - QuadraticExt::from_i64(2)).sign(), std::cmp::Ordering::Less);
/// ```
#[derive(Clone, Debug)]
pub struct QuadraticExt<K> {
    a: K,
    b: K,
    d: K,
}

impl<K: Exact> QuadraticExt<K> {
    /// `a + b√d`. `d` must be positive and not a square in `K` (see the module invariants).
    pub fn new(a: K, b: K, d: K) -> Self {
        assert!(d.sign() != Ordering::Less || b.is_zero(), "radicand must be positive");
        let mut q = QuadraticExt { a, b, d };
        q.normalise();
        q
    }

    /// The element `a` of the base field `K`, embedded.
    pub fn from_base(a: K) -> Self {
        QuadraticExt { a, b: K::zero(), d: K::zero() }
    }
    /// The rational part `a`.
    pub fn rational_part(&self) -> &K {
        &self.a
    }
    /// The coefficient `b` of `√d`.
    pub fn radical_coefficient(&self) -> &K {
        &self.b
    }
    /// The radicand `d` (`0` when the element lies in `K`).
    pub fn radicand(&self) -> &K {
        &self.d
    }
    /// The conjugate `a − b√d`.
    pub fn conjugate(&self) -> Self {
        QuadraticExt { a: self.a.clone(), b: -self.b.clone(), d: self.d.clone() }
    }
    /// The norm `(a + b√d)(a − b√d) = a² − b²d ∈ K`.
    pub fn norm(&self) -> K {
        self.a.clone() * &self.a - self.b.clone() * &self.b * &self.d
    }
    /// The element as a member of `K`, when it is one.
    pub fn to_base(&self) -> Option<K> {
        self.b.is_zero().then(|| self.a.clone())
    }

    fn normalise(&mut self) {
        if self.b.is_zero() || self.d.is_zero() {
            self.b = K::zero();
            self.d = K::zero();
        }
    }

    /// `other` written over `self`'s radicand (or `self`'s over `other`'s when `self` is in
    /// `K`): returns `(d, b_self, b_other)` with both elements `a + b√d` for one `d`.
    ///
    /// # Panics
    /// **Panics when both are irrational and `other.d / self.d` is not a square in `K`.**
    fn aligned(&self, other: &Self) -> (K, K, K) {
        match (self.b.is_zero(), other.b.is_zero()) {
            (true, _) => (other.d.clone(), K::zero(), other.b.clone()),
            (_, true) => (self.d.clone(), self.b.clone(), K::zero()),
            _ if self.d == other.d => (self.d.clone(), self.b.clone(), other.b.clone()),
            _ => {
                // b₂√d₂ = b₂·r·√d₁ with r = √(d₂/d₁) ∈ K.
                let r = (other.d.clone() / &self.d).exact_sqrt().unwrap_or_else(|| {
                    panic!("QuadraticExt: sqrt({}) and sqrt({}) lie in different fields", self.d, other.d)
                });
                (self.d.clone(), self.b.clone(), other.b.clone() * &r)
            }
        }
    }
}

impl<K: Exact> PartialEq for QuadraticExt<K> {
    /// Numeric equality: `a₁ + b₁√d₁ = a₂ + b₂√d₂` iff `a₁ = a₂`, `b₁²d₁ = b₂²d₂` and
    /// `b₁`, `b₂` have one sign (`1`, `√d₁`, `√d₂` are independent over `K` unless `d₂/d₁` is a
    /// square).
    fn eq(&self, o: &Self) -> bool {
        self.a == o.a && self.b.sign() == o.b.sign() && self.b.clone() * &self.b * &self.d == o.b.clone() * &o.b * &o.d
    }
}

impl<K: Exact> Eq for QuadraticExt<K> {}

impl<K: Exact + std::hash::Hash> std::hash::Hash for QuadraticExt<K> {
    /// Hashes `a` and `b²d`, which equal numbers share.
    fn hash<H: std::hash::Hasher>(&self, state: &mut H) {
        self.a.hash(state);
        (self.b.clone() * &self.b * &self.d).hash(state);
    }
}

impl QuadraticExt<BigRational> {
    /// `√d` for a non-negative rational `d`: rational when `d` is a square of a rational,
    /// otherwise `b·√m` with `m` a positive integer free of the squares of primes below 1000
    /// (`√(4/3)` becomes `2/3·√3`), so equal radicals print alike.
    ///
    /// # Panics
    /// **Panics if `d < 0`.**
    pub fn sqrt(d: BigRational) -> Self {
        assert!(!d.is_negative(), "sqrt of a negative rational");
        if let Some(r) = rational_sqrt(&d) {
            return QuadraticExt::from_ratio(&r);
        }
        // √(p/q) = √(p·q)/q, then pull out square factors k² of p·q.
        let q = d.denom().clone();
        let (k, m) = crate::num::word::extract_small_squares_big((d.numer() * &q).magnitude());
        let m = BigInt::from(m);
        // b = k/q reduced; k (a product of primes below 1000) is usually a word: one remainder
        let b = match num_traits::ToPrimitive::to_u128(&k) {
            Some(w) => {
                let r = num_traits::ToPrimitive::to_u128(&(q.magnitude() % w)).expect("below a u128");
                let g = BigInt::from(crate::num::word::gcd_u128(w, r));
                BigRational::new_raw(BigInt::from(k) / &g, q / g)
            }
            None => BigRational::new(BigInt::from(k), q),
        };
        if let Some(r) = int_sqrt(&m) {
            return QuadraticExt::from_ratio(&(b * BigRational::from_integer(r)));
        }
        QuadraticExt::new(rat(0), b, BigRational::from_integer(m))
    }
}

use crate::num::scalar::integer_sqrt as int_sqrt;
pub(crate) use crate::num::scalar::rational_sqrt;

impl<K: Exact> Scalar for QuadraticExt<K> {
    fn zero() -> Self {
        QuadraticExt { a: K::zero(), b: K::zero(), d: K::zero() }
    }
    fn one() -> Self {
        QuadraticExt { a: K::one(), b: K::zero(), d: K::zero() }
    }
    fn from_i64(n: i64) -> Self {
        QuadraticExt { a: K::from_i64(n), b: K::zero(), d: K::zero() }
    }
    fn from_ratio(r: &BigRational) -> Self {
        QuadraticExt { a: K::from_ratio(r), b: K::zero(), d: K::zero() }
    }
    fn is_zero(&self) -> bool {
        self.a.is_zero() && self.b.is_zero()
    }
    /// Correctly rounded (nearest, ties to even) when `K` is a rational type, decided by exact
    /// signs; for towers (`K` itself an extension) the floating-point value
    /// of `a + b·√d`.
    fn to_f64(&self) -> f64 {
        if self.b.is_zero() {
            return self.a.to_f64();
        }
        let approx = self.a.to_f64() + self.b.to_f64() * self.d.to_f64().sqrt();
        // decided in Q(√d) over BigRational: every rational the search compares with fits there
        match (self.a.to_ratio(), self.b.to_ratio(), self.d.to_ratio()) {
            (Some(a), Some(b), Some(d)) => {
                let x = QuadraticExt { a, b, d };
                nearest_f64(|r| (x.clone() - &QuadraticExt::from_base(r.clone())).sign(), approx)
            }
            // a tower element: the approximation (not certified)
            _ => approx,
        }
    }
}

/// The `f64` nearest to a real number `x` (ties to even; `±inf` from `±(2^1024 − 2^970)` on, as
/// IEEE-754 rounds), given only `sign_minus(r) = sign(x − r)` for rationals `r` and a guess.
///
/// The guess is checked and walked a few ulps; if it is farther off (cancellation in
/// `a + b√d`), a binary search over the ordered `f64` bit patterns finds the two neighbours
/// of `x` in at most 64 exact comparisons. Then `x` is compared with their midpoint. Every
/// decision is an exact sign, so the result is the correctly rounded value whatever the guess.
pub(crate) fn nearest_f64(sign_minus: impl Fn(&BigRational) -> Ordering, guess: f64) -> f64 {
    use num_traits::Pow;
    let limit = || -> BigRational { Pow::pow(BigRational::from_integer(2.into()), 1024u32) };
    // the value of f, with ±inf standing for ±2^1024 (the next exponent's first value)
    let ext = |f: f64| -> BigRational {
        if f.is_infinite() {
            if f > 0.0 { limit() } else { -limit() }
        } else {
            BigRational::from_float(f).expect("finite")
        }
    };
    // x ≥ f
    let at_least = |f: f64| sign_minus(&ext(f)) != Ordering::Less;
    if at_least(f64::INFINITY) {
        return f64::INFINITY;
    }
    if !at_least(f64::NEG_INFINITY) {
        return f64::NEG_INFINITY;
    }
    // f with ext(f) ≤ x < ext(next_up(f))
    let mut f = if guess.is_finite() { guess } else { 0.0 };
    let mut found = false;
    for _ in 0..4 {
        if !at_least(f) {
            f = f.next_down();
        } else if at_least(f.next_up()) {
            f = f.next_up();
        } else {
            found = true;
            break;
        }
    }
    if !found {
        // ordered keys of the f64s from -inf to +inf; the largest key with ext ≤ x
        let key = |x: f64| -> u64 {
            let b = x.to_bits();
            if b >> 63 == 1 { !b } else { b | 1 << 63 }
        };
        let unkey = |k: u64| -> f64 { f64::from_bits(if k >> 63 == 1 { k & !(1 << 63) } else { !k }) };
        let (mut lo, mut hi) = (key(f64::NEG_INFINITY), key(f64::INFINITY));
        while hi - lo > 1 {
            let mid = lo + (hi - lo) / 2;
            if at_least(unkey(mid)) { lo = mid } else { hi = mid }
        }
        f = unkey(lo);
    }
    let up = f.next_up();
    let m = (ext(f) + ext(up)) / BigRational::from_integer(2.into());
    match sign_minus(&m) {
        Ordering::Less => f,
        Ordering::Greater => up,
        // a tie: the neighbour with an even significand (MAX is odd: a tie above it goes to inf)
        Ordering::Equal if up.is_infinite() || up.to_bits() & 1 == 0 => up,
        Ordering::Equal => f,
    }
}

impl<K: Exact> Exact for QuadraticExt<K> {
    /// Sign of `a + b√d` with `d > 0`: when `a` and `b` disagree, compare `a²` with `b²d`.
    fn sign(&self) -> Ordering {
        let (sa, sb) = (self.a.sign(), self.b.sign());
        if sb == Ordering::Equal || sa == sb {
            return if sa == Ordering::Equal { sb } else { sa };
        }
        if sa == Ordering::Equal {
            return sb;
        }
        let a2 = self.a.clone() * &self.a;
        let b2d = self.b.clone() * &self.b * &self.d;
        match (a2 - b2d).sign() {
            Ordering::Greater => sa,
            Ordering::Less => sb,
            Ordering::Equal => Ordering::Equal,
        }
    }

    /// `√(a + b√d)` in `K(√d)`: for `b = 0`, `√a ∈ K` or `√(a/d)·√d`; otherwise
    /// `(x + y√d)² = a + b√d` needs `x² = (a ± √(a² − b²d))/2` in `K` and `y = b/(2x)`.
    fn exact_sqrt(&self) -> Option<Self> {
        if self.sign() == Ordering::Less {
            return None;
        }
        if self.b.is_zero() {
            if let Some(r) = self.a.exact_sqrt() {
                return Some(QuadraticExt::from_base(r));
            }
            if self.d.is_zero() {
                return None;
            }
            let y = (self.a.clone() / &self.d).exact_sqrt()?;
            return Some(QuadraticExt::new_unchecked(K::zero(), y, self.d.clone()));
        }
        let s = self.norm().exact_sqrt()?;
        let two = K::from_i64(2);
        for x2 in [(self.a.clone() + &s) / &two, (self.a.clone() - &s) / &two] {
            if let Some(x) = x2.exact_sqrt().filter(|x| !x.is_zero()) {
                let y = self.b.clone() / &(two.clone() * &x);
                let r = QuadraticExt::new_unchecked(x, y, self.d.clone());
                // of the two roots ±r, the non-negative one
                return Some(if r.sign() == Ordering::Less { -r } else { r });
            }
        }
        None
    }
}

impl<K: Exact> fmt::Display for QuadraticExt<K> {
    /// `a`, `b*sqrt(d)` or `a + b*sqrt(d)` / `a - b*sqrt(d)`, with `K`'s own formatting
    /// (parenthesised where `K` spells a number with spaces).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.b.is_zero() {
            return write!(f, "{}", self.a);
        }
        let paren = |f: &mut fmt::Formatter<'_>, x: &K| -> fmt::Result {
            if K::ATOMIC_DISPLAY {
                return write!(f, "{x}");
            }
            let s = x.to_string();
            if s.contains(' ') { write!(f, "({s})") } else { f.write_str(&s) }
        };
        let radical = |f: &mut fmt::Formatter<'_>, b: &K| -> fmt::Result {
            if *b != K::one() {
                paren(f, b)?;
                f.write_str("*")?;
            }
            f.write_str("sqrt(")?;
            paren(f, &self.d)?;
            f.write_str(")")
        };
        let negative = self.b.sign() == Ordering::Less;
        if !self.a.is_zero() {
            write!(f, "{} {} ", self.a, if negative { '-' } else { '+' })?;
        } else if negative {
            f.write_str("-")?;
        }
        if negative { radical(f, &-self.b.clone()) } else { radical(f, &self.b) }
    }
}

impl<K: Exact> Neg for QuadraticExt<K> {
    type Output = Self;
    fn neg(self) -> Self {
        QuadraticExt { a: -self.a, b: -self.b, d: self.d }
    }
}

impl<K: Exact> Add<&QuadraticExt<K>> for QuadraticExt<K> {
    type Output = Self;
    fn add(self, o: &Self) -> Self {
        let (d, bs, bo) = self.aligned(o);
        QuadraticExt::new_unchecked(self.a + &o.a, bs + &bo, d)
    }
}

impl<K: Exact> Sub<&QuadraticExt<K>> for QuadraticExt<K> {
    type Output = Self;
    fn sub(self, o: &Self) -> Self {
        let (d, bs, bo) = self.aligned(o);
        QuadraticExt::new_unchecked(self.a - &o.a, bs - &bo, d)
    }
}

impl<K: Exact> Mul<&QuadraticExt<K>> for QuadraticExt<K> {
    type Output = Self;
    /// `(a + b√d)(c + e√d) = (ac + be·d) + (ae + bc)√d`.
    fn mul(self, o: &Self) -> Self {
        let (d, bs, bo) = self.aligned(o);
        let a = self.a.clone() * &o.a + bs.clone() * &bo * &d;
        let b = self.a * &bo + bs * &o.a;
        QuadraticExt::new_unchecked(a, b, d)
    }
}

impl<K: Exact> Div<&QuadraticExt<K>> for QuadraticExt<K> {
    type Output = Self;
    /// `x / y = x · conj(y) / norm(y)`.
    fn div(self, o: &Self) -> Self {
        let n = o.norm();
        assert!(!n.is_zero(), "QuadraticExt: division by zero");
        let p = self * &o.conjugate();
        QuadraticExt::new_unchecked(p.a / &n, p.b / &n, p.d)
    }
}

/// Exact fields whose square roots have one spelling in `K(√m)`: the radicand of `√d` is
/// chosen by a fixed rule, so every route that takes the root of one number prints it alike.
pub trait Radical: Exact {
    /// `√d` for `d ≥ 0`, spelled as [`QuadraticExt::sqrt`] spells it for `BigRational`:
    /// rational when `d` is a square, else `b·√m` with `m` the integer `p·q` (`d = p/q`
    /// reduced) freed of the squares of primes below 1000 and `b = k/q`.
    ///
    /// # Panics
    /// **Panics if `d < 0`.**
    fn radical(d: &Self) -> QuadraticExt<Self>;
}

impl Radical for BigRational {
    fn radical(d: &Self) -> QuadraticExt<Self> {
        QuadraticExt::sqrt(d.clone())
    }
}

impl<K: Exact> QuadraticExt<K> {
    /// The same number with `f` applied to `a`, `b` and `d` (a change of base field: `f` must be
    /// an injective field homomorphism, such as the embedding of one exact rational type in another).
    pub fn map<L: Exact>(&self, f: impl Fn(&K) -> L) -> QuadraticExt<L> {
        QuadraticExt::new_unchecked(f(&self.a), f(&self.b), f(&self.d))
    }

    fn new_unchecked(a: K, b: K, d: K) -> Self {
        let mut q = QuadraticExt { a, b, d };
        q.normalise();
        q
    }
}

macro_rules! by_value {
    ($($tr:ident $m:ident),*) => {$(
        impl<K: Exact> $tr for QuadraticExt<K> {
            type Output = Self;
            fn $m(self, o: Self) -> Self {
                <Self as $tr<&Self>>::$m(self, &o)
            }
        }
    )*};
}
by_value!(Add add, Sub sub, Mul mul, Div div);
