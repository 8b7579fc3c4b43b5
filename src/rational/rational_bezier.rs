//! Rational Bézier curves (seed 000, (14); seed 002, §2), exact.
//!
//! `x(t) = Σ w_i b_i B_i^n(t) / Σ w_i B_i^n(t)`. The curve is stored in homogeneous form
//! `H_i = (w_i b_i, w_i)`, so a control point with weight 0 is a *point at infinity* (a
//! direction `(d, 0)`): seed 000's example 5 at `s = π` is a semicircle with `H_1 = (0, 1, 0)`.
//!
//! Three independent evaluations must agree exactly:
//! * [`RationalBezier::eval`]: the closed form (14), a Bernstein sum of the homogeneous points;
//! * [`RationalBezier::eval_rational_de_casteljau`]: seed 000's recursion
//!   `b_i^r = (1−t) w_i^{r−1}/w_i^r b_i^{r−1} + t w_{i+1}^{r−1}/w_i^r b_{i+1}^{r−1}`,
//!   `w_i^r = (1−t) w_i^{r−1} + t w_{i+1}^{r−1}`;
//! * [`RationalBezier::eval_saito_hosaka`]: seed 002 (19)–(20), rational interpolation
//!   `P_i^r = 𝒱[t·W_{i+1}(t; r−1) : (1−t)·W_i(t; r−1)](P_i^{r−1}, P_{i+1}^{r−1})` with the weights
//!   `W_i(t; r) = (1 − t + tE)^r w_i = Σ_k C(r,k)(1−t)^{r−k} t^k w_{i+k}` of (11)–(13).
//!
//! `𝒱[a:b](P, Q) = (b·P + a·Q)/(a + b)` is the point dividing `PQ` in the ratio `a : b` (17).

use crate::curve::bezier::BezierCurve;
use crate::error::{Error, Result};
use crate::num::point::Point;
use crate::num::scalar::{Exact, Scalar};
use crate::poly::bernstein::{binomial_scalar, pow};
use crate::poly::roots::{Root, isolate_in};
use crate::proof::Reading;
use num_rational::BigRational;
use std::cmp::Ordering;

/// `𝒱[a:b](P, Q) = (b·P + a·Q)/(a + b)`: the point dividing `PQ` in the ratio `a : b` (seed
/// 002, (17)). `None` when `a + b = 0`.
pub(crate) fn divide<S: Scalar>(a: &S, b: &S, p: &Point<S>, q: &Point<S>) -> Option<Point<S>> {
    let s = a.clone() + b;
    if s.is_zero() {
        return None;
    }
    Some(p.scale(b).add(&q.scale(a)).scale(&(S::one() / s)))
}

/// A rational Bézier curve of any degree and dimension.
///
/// # Invariants
/// `homogeneous` has points of dimension `dim + 1` (last coordinate the weight), none of them
/// the zero vector.
///
/// # Example
/// ```
/// use casteljau::{rational::RationalBezier, num::parse_points, ratio, rat};
/// // seed 000 example 2: the folium (3t/(1+t³), 3t²/(1+t³))
/// let c = RationalBezier::new(parse_points("0 0, 1 0, 2 1, 3/2 3/2", 2, None).unwrap(), vec![rat(1), rat(1), rat(1), rat(2)]).unwrap();
/// assert_eq!(c.eval(&ratio(1, 2)).unwrap().to_string(), "(4/3, 2/3)");
/// assert_eq!(c.eval_saito_hosaka(&ratio(1, 2)).unwrap(), c.eval(&ratio(1, 2)).unwrap());
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct RationalBezier<S> {
    homogeneous: BezierCurve<S>,
}

/// The homogeneous point `(w·P, w)`, the same as [`Point::to_homogeneous`] but without the
/// products when `w = 1` (an exact product by 1 still reduces every coordinate: most curves
/// are polynomial).
pub(crate) fn weighted_homogeneous<S: Scalar>(p: &Point<S>, w: &S) -> Point<S> {
    if *w == S::one() {
        let mut coords = Vec::with_capacity(p.dim() + 1);
        coords.extend_from_slice(&p.coords);
        coords.push(S::one());
        Point::new(coords)
    } else {
        p.to_homogeneous(w)
    }
}

impl<S: Scalar> From<BezierCurve<S>> for RationalBezier<S> {
    /// The polynomial curve as a rational one: every weight 1, the same points for every `t`.
    ///
    /// ```
    /// use casteljau::{BezierCurve, RationalBezier, num::parse_points, ratio};
    /// let c = BezierCurve::new(parse_points("0 0, 1 2, 2 0", 2, None).unwrap()).unwrap();
    /// let r = RationalBezier::from(c.clone());
    /// assert_eq!(r.eval(&ratio(1, 3)).unwrap(), c.eval(&ratio(1, 3)));
    /// ```
    fn from(c: BezierCurve<S>) -> Self {
        let h = c.points().iter().map(|p| weighted_homogeneous(p, &S::one())).collect();
        RationalBezier { homogeneous: BezierCurve::new(h).expect("as many points as the curve") }
    }
}

impl<S: Scalar> RationalBezier<S> {
    /// From control points and weights.
    ///
    /// # Errors
    /// [`Error::WeightCount`] for a count mismatch, [`Error::ZeroWeight`] for a zero weight (a
    /// point at infinity must be given in homogeneous form, [`Self::from_homogeneous`]).
    pub fn new(points: Vec<Point<S>>, weights: Vec<S>) -> Result<Self> {
        if points.len() != weights.len() {
            return Err(Error::WeightCount { weights: weights.len(), points: points.len(), row: None });
        }
        if let Some(i) = weights.iter().position(Scalar::is_zero) {
            return Err(Error::ZeroWeight { index: i + 1, row: None });
        }
        let h = points.iter().zip(&weights).map(|(p, w)| weighted_homogeneous(p, w)).collect();
        Ok(RationalBezier { homogeneous: BezierCurve::new(h)? })
    }

    /// From homogeneous control points `(w·x, w·y[, w·z], w)`; `w = 0` is a point at infinity.
    ///
    /// # Errors
    /// [`Error::PointAtInfinity`] for a zero vector, [`Error::NotApplicable`] for points of
    /// dimension < 2.
    pub fn from_homogeneous(h: Vec<Point<S>>) -> Result<Self> {
        if let Some(i) = h.iter().position(|p| p.coords.iter().all(Scalar::is_zero)) {
            return Err(Error::PointAtInfinity {
                message: format!("homogeneous control point {} is the zero vector", i + 1),
            });
        }
        let c = BezierCurve::new(h)?;
        if c.dim() < 2 {
            return Err(Error::NotApplicable { message: "homogeneous points need a weight coordinate".into() });
        }
        Ok(RationalBezier { homogeneous: c })
    }

    /// The degree `n`.
    pub fn degree(&self) -> usize {
        self.homogeneous.degree()
    }
    /// The dimension of the curve's points.
    pub fn dim(&self) -> usize {
        self.homogeneous.dim() - 1
    }
    /// The homogeneous control polygon.
    pub fn homogeneous(&self) -> &BezierCurve<S> {
        &self.homogeneous
    }
    /// The weights `w_i`.
    pub fn weights(&self) -> Vec<S> {
        self.homogeneous.points().iter().map(|p| p.coords[self.dim()].clone()).collect()
    }
    /// The control points (`None` for a point at infinity).
    pub fn points(&self) -> Vec<Option<Point<S>>> {
        self.homogeneous.points().iter().map(Point::from_homogeneous).collect()
    }
    /// The same curve with weight `w_i` replaced by `w` (the point `b_i` kept).
    ///
    /// # Errors
    /// [`Error::PointAtInfinity`] for a point at infinity, [`Error::InvalidArgument`] for an index
    /// out of range or `w = 0`.
    pub fn with_weight(&self, i: usize, w: S) -> Result<Self> {
        let pts: Option<Vec<Point<S>>> = self.points().into_iter().collect();
        let pts = pts
            .ok_or_else(|| Error::PointAtInfinity { message: "a point at infinity has no weight to change".into() })?;
        let mut ws = self.weights();
        *ws.get_mut(i).ok_or_else(|| Error::InvalidArgument { message: format!("no control point {}", i + 1) })? = w;
        Self::new(pts, ws)
    }

    /// The homogeneous point `Σ B_i^n(t) H_i` (never fails).
    pub fn eval_homogeneous(&self, t: &S) -> Point<S> {
        self.homogeneous.eval_bernstein(t)
    }

    /// `x(t)` by the closed form (14).
    ///
    /// # Errors
    /// [`Error::WeightsVanish`] when the denominator `Σ w_i B_i^n(t)` is 0 at `t`.
    pub fn eval(&self, t: &S) -> Result<Point<S>> {
        self.eval_homogeneous(t).from_homogeneous().ok_or_else(|| vanish_at(t))
    }

    /// `x(t)` by seed 000's rational de Casteljau recursion.
    ///
    /// # Errors
    /// [`Error::WeightsVanish`] when some intermediate weight `w_i^r(t)` is 0 (the recursion
    /// divides by it) or a control point is at infinity.
    pub fn eval_rational_de_casteljau(&self, t: &S) -> Result<Point<S>> {
        let u = S::one() - t;
        let mut w = self.weights();
        let mut b: Vec<Point<S>> = self.points().into_iter().collect::<Option<_>>().ok_or_else(|| vanish_at(t))?;
        for r in 1..=self.degree() {
            let mut nb = Vec::with_capacity(b.len() - 1);
            let mut nw = Vec::with_capacity(w.len() - 1);
            for i in 0..=self.degree() - r {
                let wr = u.clone() * &w[i] + t.clone() * &w[i + 1];
                if wr.is_zero() {
                    return Err(vanish_at(t));
                }
                let left = b[i].scale(&(u.clone() * &w[i] / wr.clone()));
                let right = b[i + 1].scale(&(t.clone() * &w[i + 1] / wr.clone()));
                nb.push(left.add(&right));
                nw.push(wr);
            }
            b = nb;
            w = nw;
        }
        Ok(b.swap_remove(0))
    }

    /// `W_i(t; r) = (1 − t + tE)^r w_i = Σ_k C(r,k) (1−t)^{r−k} t^k w_{i+k}` (seed 002, (11)).
    pub(crate) fn shifted_weight(&self, i: usize, r: usize, t: &S) -> S {
        let w = self.weights();
        let u = S::one() - t;
        (0..=r).fold(S::zero(), |acc, k| acc + binomial_scalar::<S>(r, k) * pow(&u, r - k) * pow(t, k) * &w[i + k])
    }

    /// `x(t)` by Saito–Hosaka's rational interpolation (19)–(20), with weights from (11).
    ///
    /// # Errors
    /// [`Error::WeightsVanish`] when a ratio `a + b` vanishes or a point is at infinity.
    pub fn eval_saito_hosaka(&self, t: &S) -> Result<Point<S>> {
        let u = S::one() - t;
        let mut p: Vec<Point<S>> = self.points().into_iter().collect::<Option<_>>().ok_or_else(|| vanish_at(t))?;
        for r in 1..=self.degree() {
            p = (0..p.len() - 1)
                .map(|i| {
                    let a = t.clone() * self.shifted_weight(i + 1, r - 1, t);
                    let b = u.clone() * self.shifted_weight(i, r - 1, t);
                    divide(&a, &b, &p[i], &p[i + 1]).ok_or_else(|| vanish_at(t))
                })
                .collect::<Result<_>>()?;
        }
        Ok(p.swap_remove(0))
    }

    /// Splits at `t0`: the rational halves for `[0, t0]` and `[t0, 1]` (seed 002 §2.3: control
    /// points `P0, Pa, Pd, P` and `P, Pe, Pc, P3` with their weights), from the homogeneous
    /// de Casteljau triangle.
    pub fn subdivide(&self, t0: &S) -> Result<(Self, Self)> {
        let (l, r) = crate::curve::casteljau::subdivide(&self.homogeneous, t0);
        Ok((Self::from_homogeneous(l.points().to_vec())?, Self::from_homogeneous(r.points().to_vec())?))
    }

    /// The piece for `t` from `a` to `b`, reparametrised to `[0, 1]`: the homogeneous curve's
    /// [`BezierCurve::subsegment`] (`a > b` gives it reversed).
    ///
    /// # Errors
    /// As [`Self::from_homogeneous`]: a homogeneous control point of the piece that is the
    /// zero vector.
    ///
    /// ```
    /// use casteljau::{RationalBezier, num::parse_points, rat, ratio};
    /// // the quarter circle (1, 0) → (0, 1): its middle half, still on the circle
    /// let q = RationalBezier::new(parse_points("1 0, 1 1, 0 1", 2, None).unwrap(), vec![rat(1), rat(1), rat(2)]).unwrap();
    /// let p = q.subsegment(&ratio(1, 4), &ratio(3, 4)).unwrap();
    /// assert_eq!(p.eval(&ratio(1, 2)).unwrap(), q.eval(&ratio(1, 2)).unwrap());
    /// ```
    pub fn subsegment(&self, a: &S, b: &S) -> Result<Self> {
        Self::from_homogeneous(self.homogeneous.subsegment(a, b).into_points())
    }

    /// Degree elevation by `r` (homogeneous elevation).
    ///
    /// # Errors
    /// As [`BezierCurve::elevate`].
    pub fn elevate(&self, r: usize) -> Result<Self> {
        Self::from_homogeneous(self.homogeneous.elevate(r)?.points().to_vec())
    }

    /// One degree elevation by seed 002 (22): `P'_i = 𝒱[(n+1−i)·w_i : i·w_{i−1}](P_{i−1}, P_i)`,
    /// `w'_i = (i w_{i−1} + (n+1−i) w_i)/(n+1)` (finite control points only).
    ///
    /// # Errors
    /// [`Error::PointAtInfinity`] for a point at infinity or a vanishing new weight.
    pub fn elevate_saito_hosaka(&self) -> Result<Self> {
        let n = self.degree();
        let p: Vec<Point<S>> = self
            .points()
            .into_iter()
            .collect::<Option<_>>()
            .ok_or_else(|| Error::NotApplicable { message: "(22) needs finite control points".into() })?;
        let w = self.weights();
        let m = S::from_i64(n as i64 + 1);
        let mut pts = Vec::with_capacity(n + 2);
        let mut ws = Vec::with_capacity(n + 2);
        for i in 0..=n + 1 {
            let (fi, fr) = (S::from_i64(i as i64), S::from_i64((n + 1 - i) as i64));
            let (a, b) = (
                fr.clone() * w.get(i).unwrap_or(&S::zero()),
                fi.clone() * w.get(i.wrapping_sub(1)).unwrap_or(&S::zero()),
            );
            let (pl, pr) = (p.get(i.wrapping_sub(1)).unwrap_or(&p[i.min(n)]), p.get(i).unwrap_or(&p[n]));
            let point = divide(&a, &b, pl, pr).ok_or_else(|| Error::InvalidArgument {
                message: format!("(22): the new weight w'{i} (counting from w'0) vanishes"),
            })?;
            ws.push((a + b) / m.clone());
            pts.push(point);
        }
        Self::new(pts, ws)
    }

    /// The derivative `x'(t) = (X'W − XW')/W²` (quotient rule on the homogeneous curve).
    ///
    /// # Errors
    /// [`Error::WeightsVanish`] where `W(t) = 0`.
    pub fn derivative_at(&self, t: &S) -> Result<Point<S>> {
        let h = self.eval_homogeneous(t);
        let dh = self.homogeneous.derivative(1).eval_bernstein(t);
        let d = self.dim();
        let (w, dw) = (h.coords[d].clone(), dh.coords[d].clone());
        if w.is_zero() {
            return Err(vanish_at(t));
        }
        let w2 = w.clone() * &w;
        Ok(Point::new((0..d).map(|k| (dh.coords[k].clone() * &w - h.coords[k].clone() * &dw) / w2.clone()).collect()))
    }

    /// `x(t), x'(t), …, x^(k)(t)` exactly, from `W x = X` by Leibniz:
    /// `x^(r) = (X^(r) − Σ_{i=1}^{r} C(r,i) W^(i) x^(r−i)) / W`.
    ///
    /// # Errors
    /// [`Error::WeightsVanish`] where `W(t) = 0`.
    pub fn derivatives_at(&self, t: &S, k: usize) -> Result<Vec<Point<S>>> {
        let d = self.dim();
        let hd: Vec<Point<S>> = (0..=k).map(|r| self.homogeneous.derivative(r).eval_bernstein(t)).collect();
        let w = hd[0].coords[d].clone();
        if w.is_zero() {
            return Err(vanish_at(t));
        }
        let mut out: Vec<Point<S>> = Vec::with_capacity(k + 1);
        for r in 0..=k {
            let mut acc = Point::new(hd[r].coords[..d].to_vec());
            for i in 1..=r {
                acc = acc.sub(&out[r - i].scale(&(binomial_scalar::<S>(r, i) * &hd[i].coords[d])));
            }
            out.push(acc.scale(&(S::one() / w.clone())));
        }
        Ok(out)
    }

    /// Weight change, seed 002 (23): the point of the curve with `w_i + Δw`, claimed to be
    /// `𝒱[γ_i(t)Δw : W_0(t;n)](x(t), P_i)`, with `γ_i(t) = C(n,i)(1−t)^i t^{n−i}` as printed
    /// ([`Reading::AsPrinted`], which fails) or the Bernstein polynomial `γ_i(t) = B_i^n(t)`
    /// that makes it hold ([`Reading::Corrected`]).
    ///
    /// # Errors
    /// As [`Self::eval`], or for a point at infinity.
    pub fn weight_change(&self, i: usize, dw: &S, t: &S, reading: Reading) -> Result<Point<S>> {
        let n = self.degree();
        let gamma = match reading {
            Reading::AsPrinted => binomial_scalar::<S>(n, i) * pow(&(S::one() - t), i) * pow(t, n - i),
            Reading::Corrected => crate::poly::bernstein::bernstein(i, n, t),
        };
        let p =
            self.points()[i].clone().ok_or_else(|| Error::PointAtInfinity { message: "point at infinity".into() })?;
        let x = self.eval(t)?;
        let w0 = self.shifted_weight(0, self.degree(), t);
        divide(&(gamma * dw), &w0, &x, &p).ok_or_else(|| vanish_at(t))
    }
}

fn vanish_at<S: Scalar>(t: &S) -> Error {
    Error::WeightsVanish { interval: (t.to_string(), t.to_string()) }
}

/// The type of a rational quadratic's conic, from `w1² − w0·w2` (the discriminant of the
/// denominator: its real roots are the points at infinity).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ConicType {
    /// `w1² < w0 w2` (shape factor `w1²/(w0 w2) < 1`).
    Ellipse,
    /// `w1² = w0 w2`.
    Parabola,
    /// `w1² > w0 w2`.
    Hyperbola,
    /// Collinear control points: a segment of a line (a degenerate conic).
    Degenerate,
}

impl ConicType {
    /// `ellipse`, `parabola`, `hyperbola` or `degenerate`.
    pub fn as_str(self) -> &'static str {
        match self {
            ConicType::Ellipse => "ellipse",
            ConicType::Parabola => "parabola",
            ConicType::Hyperbola => "hyperbola",
            ConicType::Degenerate => "degenerate",
        }
    }
}

impl RationalBezier<BigRational> {
    /// A fraction-free exact evaluator for repeated use: the homogeneous curve is brought over
    /// one common denominator once, each call runs the integer Horner kernel of
    /// the fraction-free kernels and divides by `W(t)` at the end. Equal to [`Self::eval`].
    ///
    /// # Errors
    /// The returned function gives [`Error::WeightsVanish`] where `W(t) = 0`.
    pub(crate) fn exact_evaluator(&self) -> impl Fn(&BigRational) -> Result<Point<BigRational>> + '_ {
        let ic = crate::curve::fraction_free::IntegerCurve::new(&self.homogeneous);
        move |t| crate::curve::fraction_free::eval_integer(&ic, t).from_homogeneous().ok_or_else(|| vanish_at(t))
    }

    /// Exact roots of the denominator `W(t) = Σ w_i B_i^n(t)` in `[a, b]` (`None`: `W ≡ 0`),
    /// within a work budget ([`crate::poly::isolate_bernstein`]).
    ///
    /// # Errors
    /// [`Error::WorkLimit`] when the isolation would exceed `budget`.
    pub fn denominator_roots(
        &self,
        a: &BigRational,
        b: &BigRational,
        budget: &crate::work::Budget,
    ) -> Result<Option<Vec<Root>>> {
        isolate_in(&self.weights(), a, b, budget)
    }

    /// Checks that the curve is defined on `[a, b]` (`0 ≤ a < b ≤ 1`).
    ///
    /// # Errors
    /// [`Error::WeightsVanish`] naming an isolating interval of a root of the denominator.
    pub fn check_defined(&self, a: &BigRational, b: &BigRational) -> Result<()> {
        match self.denominator_roots(a, b, &crate::work::Budget::unlimited())? {
            None => Err(Error::WeightsVanish { interval: (a.to_string(), b.to_string()) }),
            Some(roots) => match roots.first() {
                None => Ok(()),
                Some(Root::Exact(r)) => Err(Error::WeightsVanish { interval: (r.to_string(), r.to_string()) }),
                Some(Root::Isolated(x, y)) => Err(Error::WeightsVanish { interval: (x.to_string(), y.to_string()) }),
            },
        }
    }

    /// The conic of a rational quadratic.
    ///
    /// # Errors
    /// [`Error::NotApplicable`] unless the degree is 2.
    pub fn conic_type(&self) -> Result<(ConicType, Option<BigRational>)> {
        if self.degree() != 2 {
            return Err(Error::NotApplicable { message: format!("a conic needs degree 2, not {}", self.degree()) });
        }
        // collinear control points ⟺ the three homogeneous points have rank ≤ 2 ⟺ every 3×3
        // minor of the 3×(dim+1) matrix vanishes
        let h = self.homogeneous.points();
        let d = h[0].dim();
        let minor = |c: [usize; 3]| {
            let m = |r: usize, k: usize| h[r].coords[c[k]].clone();
            m(0, 0) * &(m(1, 1) * &m(2, 2) - m(1, 2) * &m(2, 1)) - m(0, 1) * &(m(1, 0) * &m(2, 2) - m(1, 2) * &m(2, 0))
                + m(0, 2) * &(m(1, 0) * &m(2, 1) - m(1, 1) * &m(2, 0))
        };
        let mut flat = true;
        for a in 0..d {
            for b in a + 1..d {
                for c in b + 1..d {
                    flat &= minor([a, b, c]).is_zero();
                }
            }
        }
        let w = self.weights();
        let shape = (!(w[0].clone() * &w[2]).is_zero()).then(|| w[1].clone() * &w[1] / (w[0].clone() * &w[2]));
        if flat {
            return Ok((ConicType::Degenerate, shape));
        }
        let disc = w[1].clone() * &w[1] - w[0].clone() * &w[2];
        let kind = match disc.sign() {
            Ordering::Less => ConicType::Ellipse,
            Ordering::Equal => ConicType::Parabola,
            Ordering::Greater => ConicType::Hyperbola,
        };
        Ok((kind, shape))
    }

    /// The standard form `w0 = wn = 1` by the Möbius reparametrisation
    /// `t = ρs/(1 − s + ρs)`, `w'_i = w_i ρ^i / w0`, `ρ = (w0/wn)^{1/n}` — when `ρ` is rational.
    /// Returns the new curve and `ρ`.
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] when `w0·wn ≤ 0` or `ρ` is irrational.
    pub fn standard_form(&self) -> Result<(Self, BigRational)> {
        let w = self.weights();
        let n = self.degree();
        let (w0, wn) = (w[0].clone(), w[n].clone());
        if (w0.clone() * &wn).sign() != Ordering::Greater {
            return Err(Error::InvalidArgument { message: "standard form needs end weights of one sign".into() });
        }
        let ratio = w0.clone() / &wn;
        let rho = nth_root(&ratio, n as u32).ok_or_else(|| Error::InvalidArgument {
            message: format!("(w0/wn)^(1/{n}) = ({ratio})^(1/{n}) is irrational: no rational standard form"),
        })?;
        let h =
            self.homogeneous.points().iter().enumerate().map(|(i, p)| p.scale(&(pow(&rho, i) / w0.clone()))).collect();
        Ok((RationalBezier { homogeneous: BezierCurve::new(h)? }, rho))
    }
}

/// The positive rational `n`-th root of a positive rational, when it exists.
fn nth_root(x: &BigRational, n: u32) -> Option<BigRational> {
    if n == 0 || x.sign() != Ordering::Greater {
        return None;
    }
    let root = |v: &num_bigint::BigInt| {
        let r = v.nth_root(n);
        (num_traits::Pow::pow(&r, n) == *v).then_some(r)
    };
    Some(BigRational::new(root(x.numer())?, root(x.denom())?))
}
