//! Exact intersections of planar polynomial and rational Bézier curves, and self-intersections.
//!
//! Curve–curve: with `A(s) = (X_A, Y_A)/W_A` and `B(t) = (X_B, Y_B)/W_B`, a common point solves
//! `X_A(s)W_B(t) − X_B(t)W_A(s) = 0`, `Y_A(s)W_B(t) − Y_B(t)W_A(s) = 0`. The resultant in `t`
//! is a polynomial `R(s)` whose roots contain every intersection's `s`; the resultant in `s`
//! gives `T(t)` likewise. Each root `σ` of `R` in the domain is paired with each root `τ` of `T`
//! for which `A(σ) = B(τ)` — decided exactly, coordinate by coordinate, as equalities of real
//! algebraic numbers — so every pair reported is an intersection and every intersection is
//! reported, however tangential, at an endpoint, or through a cusp or double point.
//! `R ≡ 0` means the curves share a component: an **overlap** (see [`intersect`]).
//!
//! Self-intersection: `A(s) = A(t)`, `s < t`, from the divided differences
//! `(X(s)W(t) − X(t)W(s))/(s − t)` and the same for `Y`, paired the same way.
//!
//! Contact order: `min(multiplicity of σ in R, multiplicity of τ in T)` — the intersection
//! multiplicity when neither curve passes through the point twice; `1` is transversal, `≥ 2`
//! tangent (a line through a cusp counts 2 as well).
//!
//! # Example
//! ```
//! use casteljau::{BezierCurve, RationalBezier, num::parse_points, intersect::{intersect, Domain}, work::Budget};
//! let c = |s: &str| RationalBezier::from(BezierCurve::new(parse_points(s, 2, None).unwrap()).unwrap());
//! // the parabola y = 4t(1 − t)·… touches the line y = 1 at its apex: one tangency of order 2
//! let r = intersect(&c("0 0, 1 2, 2 0"), &c("0 1, 2 1"), Domain::Unit, &Budget::unlimited()).unwrap();
//! assert_eq!(r.intersections.len(), 1);
//! let i = &r.intersections[0];
//! assert_eq!((i.s.to_string(), i.t.to_string(), i.contact_order), ("1/2".into(), "1/2".into(), 2));
//! assert_eq!(i.kind.as_str(), "tangent");
//! ```

mod box_solver;
mod elimination;
mod filter;
mod fixed;
mod forms;
mod overlap;
mod pairing;
mod roots;
mod self_intersect;

use crate::error::{Error, Result};
use crate::num::point::Point;
use crate::num::scalar::rat;
use crate::poly::algebraic::RealAlgebraic;
use crate::rational::RationalBezier;
use num_bigint::BigInt;
use num_rational::BigRational;

/// Largest degree of either curve [`intersect`] accepts.
pub(crate) const MAX_INTERSECT_DEGREE: usize = 10;

/// Where parameters are sought.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Domain {
    /// The closed square `[0, 1]²` (ends included).
    Unit,
    /// Every real parameter.
    All,
}

/// Transversal or tangent.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Contact {
    /// The curves cross with distinct tangents (contact order 1).
    Transversal,
    /// Contact order ≥ 2.
    Tangent,
}

impl Contact {
    /// `transversal` or `tangent`.
    pub fn as_str(self) -> &'static str {
        match self {
            Contact::Transversal => "transversal",
            Contact::Tangent => "tangent",
        }
    }
}

impl serde::Serialize for Contact {
    fn serialize<S: serde::Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
        s.serialize_str(self.as_str())
    }
}

/// One intersection. JSON: `s`, `t` (exact strings), `s_float`, `t_float`, `point` (exact
/// strings, absent when irrational), `point_float`, `kind`, `contact_order`.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Intersection {
    /// The parameter on the first curve.
    pub s: RealAlgebraic,
    /// The parameter on the second curve (for a self-intersection, the larger parameter).
    pub t: RealAlgebraic,
    /// `s`, correctly rounded.
    pub s_float: f64,
    /// `t`, correctly rounded.
    pub t_float: f64,
    /// The common point, when its coordinates are rational.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub point: Option<Point<BigRational>>,
    /// The common point, each coordinate correctly rounded.
    pub point_float: [f64; 2],
    /// Transversal or tangent.
    pub kind: Contact,
    /// The contact order (see the module documentation).
    pub contact_order: usize,
}

/// A shared arc: matching closed parameter intervals, ends exact (rational, or algebraic where a
/// curve on a line turns back). JSON: `s`, `t` as `[lo, hi]` exact strings (`t` descending when
/// the second curve runs backwards), `s_float`, `t_float` the ends correctly rounded. A single
/// point (`s[0] = s[1]`, `t[0] = t[1]`) is an arc of length zero: the curves share a component
/// and only touch inside the square (collinear segments end to end, say).
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Overlap {
    /// The interval on the first curve.
    pub s: [RealAlgebraic; 2],
    /// The matching interval on the second curve, `t(s_lo)` then `t(s_hi)`.
    pub t: [RealAlgebraic; 2],
    /// `s`, correctly rounded.
    pub s_float: [f64; 2],
    /// `t`, correctly rounded.
    pub t_float: [f64; 2],
}

/// Everything two curves share. JSON: `intersections` (sorted by `s`), `overlaps`.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Intersections {
    /// The isolated common points, sorted by `s`, then `t`.
    pub intersections: Vec<Intersection>,
    /// Shared arcs.
    pub overlaps: Vec<Overlap>,
}

/// The control points `(x, y)` as words when every coordinate is an integer below `2^53` in
/// magnitude (exact in `f64`), from planar points, or from homogeneous ones `(x, y, 1)`
/// (`weighted`: every weight exactly 1, a polynomial curve).
fn integer_points(points: &[Point<BigRational>], weighted: bool) -> Option<Vec<[i64; 2]>> {
    let word = |x: &BigRational| {
        let v = if x.is_integer() { num_traits::ToPrimitive::to_i64(x.numer()) } else { None }?;
        (v.unsigned_abs() < 1 << 53).then_some(v)
    };
    points
        .iter()
        .map(|p| {
            let unit = !weighted || num_traits::One::is_one(p.coords.get(2)?);
            unit.then_some([word(&p.coords[0])?, word(&p.coords[1])?])
        })
        .collect()
}

/// Planar, and of degree at most 10 (`MAX_INTERSECT_DEGREE`).
fn check_shape(dim: usize, degree: usize) -> Result<()> {
    if dim != 2 {
        return Err(Error::DimensionMismatch { expected: 2, found: dim });
    }
    if degree > MAX_INTERSECT_DEGREE {
        return Err(Error::TooLarge { what: "degree to intersect", value: degree, limit: MAX_INTERSECT_DEGREE });
    }
    Ok(())
}

fn check(c: &RationalBezier<BigRational>, domain: Domain) -> Result<()> {
    check_shape(c.dim(), c.degree())?;
    if domain == Domain::Unit {
        c.check_defined(&rat(0), &rat(1))?;
    }
    Ok(())
}

/// Every intersection of two planar curves (polynomial or rational, degree ≤
/// 10 (`MAX_INTERSECT_DEGREE`)) with parameters in the domain, and their shared arcs.
///
/// Overlaps: when the curves share a component, the shared arcs are reported as matching
/// parameter intervals inside `[0, 1]²` (also with [`Domain::All`], where only the isolated
/// intersections use every real parameter): for curves that are Möbius reparametrizations of
/// one another, `B(t) = A((αt + β)/(γt + δ))` (sub-segments, reversed, degree-elevated and
/// reweighted copies, polynomial or rational), with the points where the shared curve crosses
/// itself as isolated intersections; for curves on one line (any parametrization, turn-backs
/// included) arc by monotone piece, ends exact algebraic numbers; for a single point, the
/// parameters where the other curve passes through it (see the private `overlap` module).
///
/// # Errors
/// [`Error::DimensionMismatch`] unless planar; [`Error::TooLarge`] above the degree limit;
/// [`Error::WeightsVanish`] when a weight polynomial vanishes on `[0, 1]` (unit domain);
/// [`Error::InvalidArgument`] for a shared component that one curve traces more than once off a
/// line (an improper parametrization, such as `(s², s⁴)` on `y = x²`), or, with
/// [`Domain::All`], when a weight vanishes on `[0, 1]` where the arcs are sought;
/// [`Error::WorkLimit`] when the estimated work exceeds `budget` (checked before any work
/// starts, and again with the cost of writing the irrational parameters found, before they
/// are written; [`Budget::unlimited`](crate::work::Budget::unlimited) for no limit).
pub fn intersect(
    a: &RationalBezier<BigRational>,
    b: &RationalBezier<BigRational>,
    domain: Domain,
    budget: &crate::work::Budget,
) -> Result<Intersections> {
    check(a, domain)?;
    check(b, domain)?;
    let estimated = estimate(a, b);
    budget.check(format!("intersecting degree {} with degree {}", a.degree(), b.degree()), estimated)?;
    crate::work::metered(budget, estimated, || described(intersect_checked(a, b, domain)?))
}

/// `found`, once writing its irrational parameters exactly is charged
/// ([`crate::work::description`]: their canonical form is what `Display` and the JSON print).
fn described(found: Intersections) -> Result<Intersections> {
    let numbers = found
        .intersections
        .iter()
        .flat_map(|i| [&i.s, &i.t])
        .chain(found.overlaps.iter().flat_map(|o| o.s.iter().chain(&o.t)));
    let units: f64 = numbers
        .filter(|x| x.to_rational().is_none())
        .map(|x| {
            let p = x.polynomial();
            crate::work::description(p.len().saturating_sub(1), p.iter().map(BigInt::bits).max().unwrap_or(0))
        })
        .sum();
    let count = found.intersections.len() + found.overlaps.len();
    crate::work::charge(|| format!("writing the exact parameters of {count} common points and arcs"), units)?;
    Ok(found)
}

/// [`intersect`] once the curves and the estimate are checked.
fn intersect_checked(
    a: &RationalBezier<BigRational>,
    b: &RationalBezier<BigRational>,
    domain: Domain,
) -> Result<Intersections> {
    let words = |c: &RationalBezier<BigRational>| integer_points(c.homogeneous().points(), true);
    if let (Some(pa), Some(pb)) = (words(a), words(b))
        && let Some(found) = pairing::intersect_integer_points(&pa, &pb, domain)
    {
        return found;
    }
    pairing::intersect_rows(&forms::homogeneous_rows(a), &forms::homogeneous_rows(b), domain)
}

/// The estimated work of intersecting `a` with `b` ([`crate::work::intersection`]).
fn estimate(a: &RationalBezier<BigRational>, b: &RationalBezier<BigRational>) -> f64 {
    let sizes = |c: &RationalBezier<BigRational>| crate::work::Magnitudes::of(c.homogeneous().points());
    crate::work::intersection(a.degree(), b.degree(), sizes(a).with(sizes(b)))
}

/// Every self-intersection `A(s) = A(t)`, `s < t`, with both parameters in the domain (a
/// cubic's double point is the special case: it agrees with [`crate::classify::classify`]).
/// A curve on a line that turns back overlaps itself: its `overlaps` pair different monotone
/// pieces (`s` on the earlier one), inside `[0, 1]²`.
///
/// # Errors
/// As [`intersect`]; [`Error::InvalidArgument`] when the curve traces a curve more than once
/// off a line (every point of an arc would be a self-intersection), or is a single point.
pub fn self_intersect(
    a: &RationalBezier<BigRational>,
    domain: Domain,
    budget: &crate::work::Budget,
) -> Result<Intersections> {
    check(a, domain)?;
    let estimated = estimate(a, a);
    budget.check(format!("self-intersecting degree {}", a.degree()), estimated)?;
    crate::work::metered(budget, estimated, || {
        described(overlap::self_intersections(&forms::integer_forms(a), domain)?)
    })
}
