//! `BezierCurve`'s operations, one name each whatever the scalar: de Casteljau's scheme (seed
//! 001, (7)) and its subdivision (Lemma 2) run generically for `f64`, `Rational`, `Q(√d)`, …, and
//! the fraction-free integer kernels ([`fraction_free`](crate::curve::fraction_free)) run when the
//! scalar is `BigRational` (chosen by the type at run time, `std::any::Any`: Rust has no
//! specialization). Kept apart from `bezier.rs` so that the kernels, which take a
//! `BezierCurve`, sit between the type and the methods that call them.

use crate::curve::bezier::{BezierCurve, MAX_DEGREE};
use crate::curve::casteljau::{self, DeCasteljauTriangle};
use crate::curve::fraction_free;
use crate::error::{Error, Result};
use crate::num::point::Point;
use crate::num::scalar::{Exact, Scalar};
use crate::poly::Poly;
use crate::poly::bernstein::{self, binomial_row};
use num_rational::BigRational;
use std::any::Any;

/// The curve and parameter as `BezierCurve<BigRational>` and `&BigRational` when `S` is
/// `BigRational`: the methods below hand exact work to the fraction-free kernels
/// ([`fraction_free`](crate::curve::fraction_free)) and run de Casteljau's scheme generically for
/// every other scalar (`f64`, `Rational`, `Q(√d)`, …). One name per operation, whatever the type.
fn as_exact<'a, S: Scalar>(c: &'a BezierCurve<S>, t: &'a S) -> Option<(&'a BezierCurve<BigRational>, &'a BigRational)> {
    let c = (c as &dyn Any).downcast_ref::<BezierCurve<BigRational>>()?;
    Some((c, (t as &dyn Any).downcast_ref::<BigRational>()?))
}

/// A value computed over `BigRational` returned as the same type spelled generically (`T` is
/// that type whenever [`as_exact`] succeeded).
fn same<T: 'static>(x: impl Any) -> T {
    *(Box::new(x) as Box<dyn Any>).downcast::<T>().expect("S is BigRational")
}

impl<S: Scalar> BezierCurve<S> {
    /// `b(t)` by de Casteljau's scheme (7): `b_i^r = (1−t) b_i^{r−1} + t b_{i+1}^{r−1}`,
    /// in place on one flat buffer; `O(n²·dim)` field operations. Over `BigRational` the
    /// fraction-free kernel computes the same point with `O(n)` integer products and one
    /// reduction: `Σ C(n,i) Nᵢ pⁱ(q−p)ⁿ⁻ⁱ / (D qⁿ)` for `t = p/q` and control points `Nᵢ/D`.
    ///
    /// # Example
    /// ```
    /// use casteljau::{BezierCurve, num::parse_points, ratio};
    /// let c = BezierCurve::new(parse_points("0 1, 1 3, 2 4, 4 2", 2, None).unwrap()).unwrap();
    /// assert_eq!(c.eval(&ratio(1, 3)).to_string(), "(28/27, 70/27)");
    /// ```
    pub fn eval(&self, t: &S) -> Point<S> {
        if let Some((c, t)) = as_exact(self, t) {
            return same(fraction_free::eval(c, t));
        }
        self.eval_de_casteljau(t)
    }

    /// [`Self::eval`] by de Casteljau's scheme for every scalar, `BigRational` included (one
    /// reduced fraction per operation there): the generic route the fraction-free kernel is
    /// checked against.
    pub(crate) fn eval_de_casteljau(&self, t: &S) -> Point<S> {
        let dim = self.dim();
        let n = self.degree();
        let mut buf: Vec<S> = self.points.iter().flat_map(|p| p.coords.iter().cloned()).collect();
        let u = S::one() - t;
        for r in 1..=n {
            for i in 0..=(n - r) {
                for c in 0..dim {
                    let k = i * dim + c;
                    buf[k] = u.clone() * &buf[k] + t.clone() * &buf[k + dim];
                }
            }
        }
        buf.truncate(dim);
        Point::new(buf)
    }

    /// Power-form coefficients `c_0, …, c_n` with `b(t) = Σ c_k t^k` (seed 003's matrix form):
    /// `c_k = C(n,k) Σ_{i≤k} (−1)^{k−i} C(k,i) bᵢ` (fraction-free over `BigRational`).
    pub fn power_coefficients(&self) -> Vec<Point<S>> {
        if let Some(c) = (self as &dyn Any).downcast_ref::<BezierCurve<BigRational>>() {
            return same(fraction_free::power_coefficients(c));
        }
        bernstein::to_power(&self.points)
    }

    /// The power form of each coordinate, `[x(t), y(t), …]`: coordinate `c` of
    /// [`BezierCurve::power_coefficients`] as a [`Poly`] (for a homogeneous curve of a rational
    /// one, `[X, Y, W]`).
    ///
    /// # Example
    /// ```
    /// use casteljau::{BezierCurve, num::parse_points};
    /// let c = BezierCurve::new(parse_points("0 1, 4 2, 2 4, 1 0", 2, None).unwrap()).unwrap();
    /// let [x, y]: [_; 2] = c.coordinate_polynomials().try_into().unwrap();
    /// assert_eq!((x.to_string(), y.to_string()), ("12t - 18t^2 + 7t^3".into(), "1 + 3t + 3t^2 - 7t^3".into()));
    /// ```
    pub fn coordinate_polynomials(&self) -> Vec<Poly<S>> {
        let c = self.power_coefficients();
        (0..self.dim()).map(|k| Poly::new(c.iter().map(|p| p.coords[k].clone()).collect())).collect()
    }

    /// The whole de Casteljau triangle at `t` (any `t`, not only `[0, 1]`): `rows[r][i] = b_i^r(t)`.
    ///
    /// # Example
    /// ```
    /// use casteljau::{BezierCurve, num::parse_points, ratio};
    /// let c = BezierCurve::new(parse_points("0 0, 1 2, 2 0", 2, None).unwrap()).unwrap();
    /// let tri = c.triangle(&ratio(1, 2));
    /// assert_eq!(tri.rows[1][0].to_string(), "(1/2, 1)");
    /// assert_eq!(tri.point().to_string(), "(1, 1)");
    /// ```
    pub fn triangle(&self, t: &S) -> DeCasteljauTriangle<S> {
        if let Some((c, t)) = as_exact(self, t) {
            return same(fraction_free::triangle(c, t));
        }
        casteljau::triangle(self, t)
    }

    /// Splits the curve at `t0` into the pieces for `[0, t0]` and `[t0, 1]`, each
    /// reparametrised to `[0, 1]` (Lemma 2): `left(s) = b(t0·s)`, `right(s) = b(t0 + (1−t0)·s)`;
    /// their control points are the triangle's boundary.
    ///
    /// # Example
    /// ```
    /// use casteljau::{BezierCurve, num::parse_points, ratio};
    /// let c = BezierCurve::new(parse_points("-1 -1, -1/3 1, 1/3 -1, 1 1", 2, None).unwrap()).unwrap();
    /// let (l, r) = c.subdivide(&ratio(1, 3));
    /// assert_eq!(l.to_string(), "-1 -1, -7/9 -1/3, -5/9 -1/9, -1/3 -1/27");
    /// assert_eq!(r.eval(&ratio(0, 1)), l.eval(&ratio(1, 1)));
    /// ```
    pub fn subdivide(&self, t0: &S) -> (Self, Self) {
        if let Some((c, t)) = as_exact(self, t0) {
            return same(fraction_free::subdivide(c, t));
        }
        casteljau::subdivide(self, t0)
    }

    /// The piece of the curve for `t` from `a` to `b`, reparametrised to `[0, 1]`:
    /// `piece(s) = b(a + (b − a)·s)`. Its control points are the blossom values
    /// `P_i = b[a, …, a, b, …, b]` (`n − i` copies of `a`, `i` of `b`), found by two de Casteljau
    /// splits (`O(n²)`, fraction-free over `BigRational`): `[0, b]` then its part from `a/b`
    /// (or `[a, 1]` then its part up to `(b − a)/(1 − a)` when `b = 0`). `a > b` gives the
    /// piece reversed; `a = b`, the point `b(a)` repeated. Any `a`, `b`, not only in `[0, 1]`.
    ///
    /// # Laws
    /// `piece.eval(s) == self.eval(a + (b − a)·s)` for every `s` (exactly for exact scalars);
    /// `self.subsegment(0, 1) == self`; `self.subsegment(b, a)` is `self.subsegment(a, b)`
    /// reversed.
    ///
    /// # Example
    /// ```
    /// use casteljau::{BezierCurve, num::parse_points, ratio};
    /// let c = BezierCurve::new(parse_points("0 0, 1 2, 3 2, 4 0", 2, None).unwrap()).unwrap();
    /// let piece = c.subsegment(&ratio(1, 4), &ratio(3, 4));
    /// assert_eq!(piece.to_string(), "29/32 9/8, 51/32 13/8, 77/32 13/8, 99/32 9/8");
    /// assert_eq!(piece.eval(&ratio(1, 3)), c.eval(&ratio(5, 12)));
    /// // in binary64 too, for drawings
    /// let f = c.map(|x| casteljau::Scalar::to_f64(x)).subsegment(&0.25, &0.75);
    /// assert_eq!(f.points()[0].coords, vec![0.90625, 1.125]);
    /// ```
    pub fn subsegment(&self, a: &S, b: &S) -> Self {
        let n = self.degree();
        if a == b {
            return BezierCurve { points: vec![self.eval(a); n + 1] };
        }
        let one = S::one();
        if !b.is_zero() {
            let (to_b, _) = self.subdivide(b);
            to_b.subdivide(&(a.clone() / b)).1
        } else if *a != one {
            // b = 0: [a, 1], then its part up to (b − a)/(1 − a)
            let (_, from_a) = self.subdivide(a);
            from_a.subdivide(&((b.clone() - a) / &(one - a))).0
        } else {
            // from 1 to 0: the curve reversed
            BezierCurve { points: self.points.iter().rev().cloned().collect() }
        }
    }

    /// Subdivides `depth` times, each piece at its own local parameter `t0`: `2^depth` pieces in
    /// order along the curve (seed 001, Fig. 10: `t0 = 1/2`, depth 4); piece `k` covers
    /// the `k`-th interval of the `2^depth` intervals of this nested splitting (the pieces of
    /// [`RepeatedSubdivision`](crate::curve::RepeatedSubdivision) list them).
    ///
    /// # Errors
    /// [`Error::TooLarge`] for `depth >` 16 (`MAX_SUBDIVISION_DEPTH`).
    pub fn subdivide_repeatedly(&self, t0: &S, depth: u32) -> Result<Vec<Self>> {
        if let Some((c, t)) = as_exact(self, t0) {
            return fraction_free::subdivide_repeatedly(c, t, depth).map(same);
        }
        casteljau::subdivide_repeatedly(self, t0, depth)
    }

    /// Degree elevation by `r`: the same curve with degree `n + r`,
    /// `b'_i = Σ_j C(r, i−j) C(n, j) / C(n+r, i) · b_j`.
    ///
    /// # Errors
    /// [`Error::TooLarge`] when `n + r` exceeds 10,000 (`MAX_DEGREE`).
    pub fn elevate(&self, r: usize) -> Result<Self> {
        if let Some(c) = (self as &dyn Any).downcast_ref::<BezierCurve<BigRational>>() {
            return fraction_free::elevate(c, r).map(same);
        }
        let n = self.degree();
        let m = n.checked_add(r).filter(|m| *m <= MAX_DEGREE).ok_or(Error::TooLarge {
            what: "elevated degree",
            value: n.saturating_add(r),
            limit: MAX_DEGREE,
        })?;
        let (row_r, row_n, row_m) = (binomial_row::<S>(r), binomial_row::<S>(n), binomial_row::<S>(m));
        let points = (0..=m)
            .map(|i| {
                let mut acc = Point::origin(self.dim());
                for j in i.saturating_sub(r)..=i.min(n) {
                    let w = row_r[i - j].clone() * &row_n[j];
                    acc = acc.add(&self.points[j].scale(&w));
                }
                acc.scale(&(S::one() / row_m[i].clone()))
            })
            .collect();
        Ok(BezierCurve { points })
    }
}

impl<S: Exact> BezierCurve<S> {
    /// Exact degree reduction: when the curve is really of degree `m < n`, the degree-`m`
    /// control points of the same curve (`self` unchanged when `m = n`).
    ///
    /// Elevation followed by reduction is the identity; reduction followed by elevation to `n`
    /// gives back the original control points.
    pub fn reduce_degree(&self) -> Self {
        if let Some(c) = (self as &dyn Any).downcast_ref::<BezierCurve<BigRational>>() {
            return same(fraction_free::reduce_degree(c));
        }
        let m = self.real_degree();
        if m == self.degree() {
            return self.clone();
        }
        let c = self.power_coefficients();
        BezierCurve { points: bernstein::from_power(&c[..=m]) }
    }
}
