//! Exact classification of rational (weighted) planar cubics, projectively.
//!
//! A rational cubic is the homogeneous polynomial curve `R(t) = Σ B_i^3(t) H_i`, with
//! `H_i = w_i (x_i, y_i, 1)` (or any homogeneous control point `(X, Y, W)`; `W = 0` is a point at
//! infinity). Projectively every irreducible plane cubic with a rational parametrisation has
//! exactly one singular point, the double point `D`, which may lie at infinity:
//!
//! * `D = L00 × L01` from the moving line (3) of seed 004 with `Q_i = C(3,i) H_i` (the seed's
//!   construction is projective, so weights enter through the `Q_i`);
//! * the double-point parameters are the common roots of the three cubic polynomials
//!   `R(t) × D ≡ 0`, i.e. the roots of `g = gcd`: two real (crunode), one double (cusp) or a
//!   complex pair (acnode). A parameter at `t = ∞` shows as `deg g < 2`.
//!
//! Degenerate input is named: all `H_i` on one projective line (the curve is a line), or a
//! common factor of `X(t), Y(t), W(t)` (the curve has lower degree: a conic or a line).
//! With unit weights this reproduces [`crate::classify`]: an explicit polynomial cubic is a cusp
//! whose double point is at infinity.

use crate::classify::moving_line::MovingLines;
use crate::classify::{NodeType, Parameter, in_unit_interval};
use crate::error::{Error, Result};
use crate::num::point::Point;
use crate::num::scalar::{Exact, Scalar, rat};
use crate::poly::bernstein::to_power;
use crate::rational::RationalBezier;
use num_rational::BigRational;
use std::cmp::Ordering;

use crate::poly::polynomial::{Poly, center_plus_minus_sqrt};

/// What [`classify_rational`] finds.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct RationalClassification {
    /// `"rational_cubic"`, `"line"` (all control points on one projective line),
    /// `"reduces_to_conic"` / `"reduces_to_line"` (common factor), or `"point"`.
    pub class: &'static str,
    /// Why, in words.
    pub reason: String,
    /// Node type of a genuine rational cubic (projective: no "explicit").
    pub node_type: Option<NodeType>,
    /// The double point, homogeneous `(X, Y, W)`.
    pub double_point_homogeneous: Option<Point<BigRational>>,
    /// The affine double point, when `W ≠ 0`.
    pub double_point: Option<Point<BigRational>>,
    /// The double point is at infinity (`W = 0`).
    pub at_infinity: bool,
    /// Finite real double-point parameters, ascending (one for a cusp).
    pub double_point_parameters: Vec<Parameter>,
    /// A double-point parameter is `t = ∞`.
    pub parameter_at_infinity: bool,
    /// Both double-point parameters real and in `[0, 1]` (crunode).
    pub has_loop: bool,
    /// The cusp parameter is in `[0, 1]`.
    pub has_cusp: bool,
}

impl serde::Serialize for RationalClassification {
    /// The fields of `classify --json --weights`: `rational` (`true`), `class`, `reason`,
    /// `node_type`, `double_point`, `double_point_homogeneous`, `double_point_at_infinity`,
    /// `double_point_parameters`, `parameter_at_infinity` and `segment` (`{"loop", "cusp"}`).
    fn serialize<S: serde::Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
        #[derive(serde::Serialize)]
        struct Segment {
            #[serde(rename = "loop")]
            has_loop: bool,
            #[serde(rename = "cusp")]
            has_cusp: bool,
        }
        #[derive(serde::Serialize)]
        struct View<'a> {
            rational: bool,
            class: &'a str,
            reason: &'a str,
            node_type: Option<NodeType>,
            double_point: &'a Option<Point<BigRational>>,
            double_point_homogeneous: &'a Option<Point<BigRational>>,
            double_point_at_infinity: bool,
            double_point_parameters: &'a [Parameter],
            parameter_at_infinity: bool,
            segment: Segment,
        }
        serde::Serialize::serialize(
            &View {
                rational: true,
                class: self.class,
                reason: &self.reason,
                node_type: self.node_type,
                double_point: &self.double_point,
                double_point_homogeneous: &self.double_point_homogeneous,
                double_point_at_infinity: self.at_infinity,
                double_point_parameters: &self.double_point_parameters,
                parameter_at_infinity: self.parameter_at_infinity,
                segment: Segment { has_loop: self.has_loop, has_cusp: self.has_cusp },
            },
            s,
        )
    }
}

/// Classifies the rational cubic with homogeneous control points `h` (`(X, Y, W)` each).
///
/// # Errors
/// [`Error::NotApplicable`] unless there are four 3-vectors, [`Error::PointAtInfinity`] for a
/// zero one, [`Error::Degenerate`] when `R(t) × D` vanishes identically.
///
/// # Example
/// ```
/// use casteljau::{Point, RationalBezier, rat, classify::classify_rational, classify::NodeType};
/// // seed 000 example 2 (the folium): b = (0,0) (1,0) (2,1) (3/2,3/2), w = 1 1 1 2
/// let h: Vec<Point<_>> = [(0, 0, 1), (1, 0, 1), (2, 1, 1), (3, 3, 2)]
///     .iter().map(|&(x, y, w)| Point::new(vec![rat(x), rat(y), rat(w)])).collect();
/// let k = classify_rational(&RationalBezier::from_homogeneous(h).unwrap()).unwrap();
/// assert_eq!(k.node_type, Some(NodeType::Crunode));
/// assert_eq!(k.double_point.unwrap().to_string(), "(0, 0)");
/// assert!(k.parameter_at_infinity); // the folium passes its node at t = 0 and t = ∞
/// ```
pub fn classify_rational(c: &RationalBezier<BigRational>) -> Result<RationalClassification> {
    if c.degree() != 3 || c.dim() != 2 {
        return Err(Error::NotApplicable { message: "rational classification takes planar cubics".into() });
    }
    classify_homogeneous(c.homogeneous().points())
}

/// [`classify_rational`] of four homogeneous control points `(X, Y, W)`.
pub(crate) fn classify_homogeneous(h: &[Point<BigRational>]) -> Result<RationalClassification> {
    if h.len() != 4 || h.iter().any(|p| p.dim() != 3) {
        return Err(Error::InvalidArgument {
            message: "a rational cubic needs four homogeneous points (X Y W)".into(),
        });
    }
    if let Some(i) = h.iter().position(|p| p.coords.iter().all(Scalar::is_zero)) {
        return Err(Error::PointAtInfinity {
            message: format!("control point {} is (0, 0, 0): weight and point both vanish", i + 1),
        });
    }
    let mut out = RationalClassification {
        class: "rational_cubic",
        reason: String::new(),
        node_type: None,
        double_point_homogeneous: None,
        double_point: None,
        at_infinity: false,
        double_point_parameters: vec![],
        parameter_at_infinity: false,
        has_loop: false,
        has_cusp: false,
    };
    let power = to_power(h); // X(t), Y(t), W(t) coefficients
    let coord = |c: usize| -> Poly<BigRational> { Poly::new(power.iter().map(|p| p.coords[c].clone()).collect()) };
    let (x, y, w) = (coord(0), coord(1), coord(2));
    // rank of the control points: all on one projective line ⟺ every triple determinant vanishes
    let det = |a: &Point<BigRational>, b: &Point<BigRational>, c: &Point<BigRational>| a.dot(&b.cross(c).expect("3D"));
    let rank_le_2 =
        [(0, 1, 2), (0, 1, 3), (0, 2, 3), (1, 2, 3)].iter().all(|&(i, j, k)| det(&h[i], &h[j], &h[k]).is_zero());
    let common = x.gcd(&y).gcd(&w);
    let max_deg = [&x, &y, &w].iter().filter_map(|p| p.degree()).max().unwrap_or(0);
    let real_deg = max_deg.saturating_sub(common.degree().unwrap_or(0));
    if rank_le_2 {
        out.class = if real_deg == 0 { "point" } else { "line" };
        out.reason = "all homogeneous control points lie on one projective line".into();
        return Ok(out);
    }
    if real_deg < 3 {
        out.class = if real_deg == 2 { "reduces_to_conic" } else { "reduces_to_line" };
        out.reason = format!(
            "X(t), Y(t), W(t) share a factor of degree {}: the curve has degree {real_deg}",
            common.degree().unwrap_or(0)
        );
        return Ok(out);
    }
    // Q_i = C(3, i) H_i: the seed's moving lines accept homogeneous input through a curve whose
    // points are H_i / W_i — so build the lines directly from the Q_i here.
    let ml = MovingLines::from_homogeneous([h[0].clone(), h[1].scale(&rat(3)), h[2].scale(&rat(3)), h[3].clone()]);
    let d = ml.double_point.clone();
    if d.coords.iter().all(Scalar::is_zero) {
        out.class = "reduces_to_conic";
        out.reason = "the moving line through the double point degenerates (L00 × L01 = 0)".into();
        return Ok(out);
    }
    // R(t) × D, componentwise cubic polynomials
    let cross_poly =
        |a: &Poly<BigRational>, b: &Poly<BigRational>, da: &BigRational, db: &BigRational| &a.scale(db) - &b.scale(da);
    let (dx, dy, dw) = (&d.coords[0], &d.coords[1], &d.coords[2]);
    let g = cross_poly(&y, &w, dy, dw).gcd(&cross_poly(&w, &x, dw, dx)).gcd(&cross_poly(&x, &y, dx, dy));
    out.at_infinity = dw.is_zero();
    out.double_point = d.from_homogeneous();
    out.double_point_homogeneous = Some(d);
    match g.degree() {
        Some(2) => {
            // t² + b t + c
            let (c, b) = (g.coeff(0), g.coeff(1));
            let disc = b.clone() * &b - rat(4) * &c;
            let center = -b / rat(2);
            let node = match disc.sign() {
                Ordering::Greater => NodeType::Crunode,
                Ordering::Equal => NodeType::Cusp,
                Ordering::Less => NodeType::Acnode,
            };
            out.node_type = Some(node);
            match node {
                NodeType::Crunode => {
                    let r = disc / rat(4);
                    out.double_point_parameters = center_plus_minus_sqrt(&center, &r).to_vec();
                    out.has_loop = out.double_point_parameters.iter().all(in_unit_interval);
                }
                NodeType::Cusp => {
                    out.double_point_parameters = vec![Parameter::from_ratio(&center)];
                    out.has_cusp = in_unit_interval(&out.double_point_parameters[0]);
                }
                _ => {}
            }
        }
        Some(1) => {
            // one finite parameter, the other at t = ∞ (a crunode through R(∞)), or a cusp at ∞
            out.parameter_at_infinity = true;
            let t = Parameter::from_ratio(&(-g.coeff(0)));
            out.node_type = Some(NodeType::Crunode);
            out.double_point_parameters = vec![t];
        }
        Some(0) => {
            out.parameter_at_infinity = true;
            out.node_type = Some(NodeType::Cusp); // both branches at t = ∞
        }
        _ => {
            return Err(Error::Degenerate { message: "R(t) × D vanishes identically: degenerate cubic".into() });
        }
    }
    out.reason = format!(
        "double point {} from the moving lines; R(t) × D = 0 has {}",
        out.double_point_homogeneous.as_ref().expect("set"),
        match g.degree() {
            Some(2) => "two roots (a quadratic factor)",
            Some(1) => "one finite root (the other at t = ∞)",
            _ => "no finite root (a cusp at t = ∞)",
        }
    );
    Ok(out)
}
