//! One input segment prepared for the arrangement: its homogeneous power form, the direction of
//! its tangent as a polynomial vector, an outward-rounded box, and exact evaluation.

use crate::num::point::Point2;
use crate::num::scalar::rat;
use crate::poly::Poly;
use crate::poly::algebraic::RealAlgebraic;
use crate::rational::RationalBezier;
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{Signed, ToPrimitive, Zero};
use std::cmp::Ordering;

/// The nearest `f64` below and above a rational (one ulp of slack on each side).
pub(crate) fn outward(x: &BigRational) -> (f64, f64) {
    let f = x.to_f64().unwrap_or(f64::NAN);
    if !f.is_finite() {
        return (f64::NEG_INFINITY, f64::INFINITY);
    }
    (f.next_down(), f.next_up())
}

/// Homogeneous power form `X, Y, W`, and `X'W − XW'`, `Y'W − YW'`: the tangent direction (the
/// derivative times `W² > 0`).
#[derive(Clone, Debug)]
struct Forms {
    x: Poly<BigRational>,
    y: Poly<BigRational>,
    w: Poly<BigRational>,
    dx: Poly<BigRational>,
    dy: Poly<BigRational>,
}

impl Forms {
    fn of(curve: &RationalBezier<BigRational>, polynomial: bool) -> Forms {
        let h = curve.homogeneous();
        if polynomial {
            // every weight w0: the affine power form of the points h_i / w0, W = 1
            let w0 = &h.points()[0].coords[2];
            let [x, y, _]: [Poly<BigRational>; 3] = h.coordinate_polynomials().try_into().expect("planar: X, Y, W");
            let (x, y) = if w0 == &rat(1) { (x, y) } else { (x.scale(&(rat(1) / w0)), y.scale(&(rat(1) / w0))) };
            let (dx, dy) = (x.derivative(), y.derivative());
            return Forms { x, y, w: Poly::constant(rat(1)), dx, dy };
        }
        let [x, y, w]: [Poly<BigRational>; 3] = h.coordinate_polynomials().try_into().expect("planar: X, Y, W");
        let dw = w.derivative();
        let cross = |a: &Poly<BigRational>| &(&a.derivative() * &w) - &(a * &dw);
        let (dx, dy) = (cross(&x), cross(&y));
        Forms { x, y, w, dx, dy }
    }
}

/// A segment of an input contour.
#[derive(Clone, Debug)]
pub(crate) struct Seg {
    /// The input (0 for `A`, 1 for `B`, …).
    pub input: usize,
    /// The contour within the input.
    pub contour: usize,
    /// The segment within the contour.
    pub index: usize,
    /// The curve.
    pub curve: RationalBezier<BigRational>,
    /// The power forms, computed when first needed (most segments of a glyph never are).
    forms: std::sync::OnceLock<Forms>,
    /// `X`, `Y`, `W` with integer coefficients and one common scale, when first needed.
    integer_forms: std::sync::OnceLock<[Vec<BigInt>; 3]>,
    /// Every weight equal: `W = 1` after scaling.
    pub polynomial: bool,
    /// The outward-rounded box `[x_min, y_min, x_max, y_max]` of the control points, when the
    /// weights have one sign (then the curve lies in their convex hull).
    pub bbox: Option<[f64; 4]>,
    /// The control points when the hull property holds.
    pub hull: Option<Vec<Point2<BigRational>>>,
    /// A single point (every control point the same): no region, ignored.
    pub degenerate: bool,
    /// The first control point (its start) and the last (its end), exactly.
    pub start: Point2<BigRational>,
    pub end: Point2<BigRational>,
    /// Twice the control points, when those are integers of at most 24 bits (font coordinates,
    /// with TrueType's implied on-curve points at half-integers): then the hull tests and the
    /// areas run in `i64`/`i128`, exactly.
    pub small: Option<Vec<[i64; 2]>>,
    /// The sizes of the homogeneous coordinates, for the cost estimates.
    pub sizes: crate::work::Magnitudes,
    /// The hull's points rounded to `f64`, when every coordinate is within `10^±150` or zero
    /// (their squares and products stay normal): the certified filters of the pair tests.
    pub approx: Option<Vec<[f64; 2]>>,
}

/// The outward-rounded box of points.
fn boxed(ps: &[Point2<BigRational>]) -> [f64; 4] {
    let mut b = [f64::INFINITY, f64::INFINITY, f64::NEG_INFINITY, f64::NEG_INFINITY];
    for p in ps {
        for (k, c) in [&p.x, &p.y].into_iter().enumerate() {
            let (lo, hi) = outward(c);
            b[k] = b[k].min(lo);
            b[k + 2] = b[k + 2].max(hi);
        }
    }
    b
}

/// The points rounded to `f64`, when every coordinate is 0 or within `10^±150`.
fn rounded(ps: &[Point2<BigRational>]) -> Option<Vec<[f64; 2]>> {
    let round = |c: &BigRational| -> Option<f64> {
        let f = crate::num::scalar::ratio_to_f64(c);
        (f == 0.0 && c.is_zero() || (1e-150..=1e150).contains(&f.abs())).then_some(f)
    };
    ps.iter().map(|p| Some([round(&p.x)?, round(&p.y)?])).collect()
}

/// Twice the points as small integers (`|2c| < 2²⁴`), when they are (read off the reduced
/// fractions: `2c` is an integer exactly when the denominator is 1 or 2, no arithmetic needed).
fn small_points(ps: &[Point2<BigRational>]) -> Option<Vec<[i64; 2]>> {
    const LIMIT: i64 = 1 << 24;
    let c = |v: &BigRational| -> Option<i64> {
        let n = v.numer().to_i64()?;
        let two = match v.denom().to_i64()? {
            1 => n.checked_mul(2)?,
            2 => n,
            _ => return None,
        };
        (two.abs() < LIMIT).then_some(two)
    };
    ps.iter().map(|p| Some([c(&p.x)?, c(&p.y)?])).collect()
}

impl Seg {
    pub(crate) fn new(
        input: usize,
        contour: usize,
        index: usize,
        curve: RationalBezier<BigRational>,
    ) -> crate::error::Result<Seg> {
        let h = curve.homogeneous().points();
        let polynomial = h.iter().all(|p| p.coords[2] == h[0].coords[2]) && !h[0].coords[2].is_zero();
        let weights = curve.weights();
        let positive = weights.iter().all(|w| w.is_positive()) || weights.iter().all(|w| w.is_negative());
        let hull: Option<Vec<Point2<BigRational>>> = if polynomial {
            let w0 = &h[0].coords[2];
            let one = w0 == &rat(1);
            Some(
                h.iter()
                    .map(|p| {
                        if one {
                            Point2::new(p.coords[0].clone(), p.coords[1].clone())
                        } else {
                            Point2::new(&p.coords[0] / w0, &p.coords[1] / w0)
                        }
                    })
                    .collect(),
            )
        } else if positive {
            curve.points().iter().map(|p| p.as_ref().and_then(|p| Point2::try_from(p).ok())).collect::<Option<Vec<_>>>()
        } else {
            None
        };
        let bbox = hull.as_ref().map(|ps| boxed(ps));
        let small = hull.as_ref().and_then(|ps| small_points(ps));
        let (start, end) = match &hull {
            Some(ps) => (ps[0].clone(), ps[ps.len() - 1].clone()),
            None => (Point2::try_from(&curve.eval(&rat(0))?)?, Point2::try_from(&curve.eval(&rat(1))?)?),
        };
        let forms = std::sync::OnceLock::new();
        let degenerate = match &hull {
            Some(ps) => ps.iter().all(|p| *p == ps[0]),
            None => {
                let f = Forms::of(&curve, polynomial);
                let d = f.dx.is_zero() && f.dy.is_zero();
                let _ = forms.set(f);
                d
            }
        };
        let integer_forms = std::sync::OnceLock::new();
        let sizes = crate::work::Magnitudes::of(h);
        let approx = hull.as_ref().and_then(|ps| rounded(ps));
        Ok(Seg {
            input,
            contour,
            index,
            curve,
            forms,
            integer_forms,
            polynomial,
            bbox,
            hull,
            degenerate,
            start,
            end,
            small,
            sizes,
            approx,
        })
    }

    fn forms(&self) -> &Forms {
        self.forms.get_or_init(|| Forms::of(&self.curve, self.polynomial))
    }

    /// `X`.
    pub(crate) fn x(&self) -> &Poly<BigRational> {
        &self.forms().x
    }

    /// `Y`.
    pub(crate) fn y(&self) -> &Poly<BigRational> {
        &self.forms().y
    }

    /// `W`.
    pub(crate) fn w(&self) -> &Poly<BigRational> {
        &self.forms().w
    }

    /// `X'W − XW'`.
    pub(crate) fn dx(&self) -> &Poly<BigRational> {
        &self.forms().dx
    }

    /// `Y'W − YW'`.
    pub(crate) fn dy(&self) -> &Poly<BigRational> {
        &self.forms().dy
    }

    /// The point at a rational parameter.
    pub(crate) fn point_at(&self, t: &BigRational) -> Point2<BigRational> {
        let w = self.w().eval(t);
        Point2::new(self.x().eval(t) / &w, self.y().eval(t) / &w)
    }

    /// The tangent direction at a rational parameter (zero at a cusp).
    pub(crate) fn direction_at(&self, t: &BigRational) -> Point2<BigRational> {
        Point2::new(self.dx().eval(t), self.dy().eval(t))
    }

    /// The point at an algebraic parameter, each coordinate an exact real algebraic number.
    pub(crate) fn point_at_algebraic(&self, t: &RealAlgebraic) -> [RealAlgebraic; 2] {
        match t.to_rational() {
            Some(r) => {
                let p = self.point_at(r);
                [p.x.clone().into(), p.y.clone().into()]
            }
            None => [t.map_rational(self.x(), self.w()), t.map_rational(self.y(), self.w())],
        }
    }

    /// The point at an algebraic parameter, each coordinate correctly rounded.
    pub(crate) fn point_float(&self, t: &RealAlgebraic) -> [f64; 2] {
        match t.to_rational() {
            Some(r) => {
                let p = self.point_at(r);
                [crate::num::scalar::ratio_to_f64(&p.x), crate::num::scalar::ratio_to_f64(&p.y)]
            }
            None => {
                // the ratios rounded from enclosures (no exact image: mapping a root through
                // a resultant is the costly step)
                let [x, y, w] = self.integer_forms.get_or_init(|| {
                    let all: Vec<BigRational> =
                        [self.x(), self.y(), self.w()].iter().flat_map(|p| p.coeffs().iter().cloned()).collect();
                    let scaled = crate::poly::integer::to_integer(&all);
                    let (nx, ny) = (self.x().coeffs().len(), self.y().coeffs().len());
                    [scaled[..nx].to_vec(), scaled[nx..nx + ny].to_vec(), scaled[nx + ny..].to_vec()]
                });
                let t = t.narrowed(60);
                [t.map_rational_to_f64(x, w), t.map_rational_to_f64(y, w)]
            }
        }
    }

    /// Whether the point at `t` is `q`, exactly.
    pub(crate) fn passes_through(&self, t: &RealAlgebraic, q: &Point2<BigRational>) -> bool {
        let fx = self.x() - &self.w().scale(&q.x);
        let fy = self.y() - &self.w().scale(&q.y);
        t.sign_of(&fx) == Ordering::Equal && t.sign_of(&fy) == Ordering::Equal
    }

    /// The polynomial degree of the curve.
    pub(crate) fn degree(&self) -> usize {
        self.curve.degree()
    }
}
