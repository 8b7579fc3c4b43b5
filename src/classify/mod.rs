//! Exact classification of planar polynomial Bézier curves of degree ≤ 3.
//!
//! Every curve falls in exactly one of 16 [`CurveClass`]es. A *genuine* cubic (real degree 3,
//! control points not collinear) has a [`NodeType`] decided from its power form
//! `P(t) = a0 + a1 t + a2 t² + a3 t³` with the invariants
//! `A = a2×a3`, `B = a1×a3`, `C = a1×a2` (`u×v = u_x v_y − u_y v_x`):
//!
//! * `A = 0`: **explicit** — an affine image of `y = x³`; one inflection at `t = −C/(3B)`,
//!   the double point at infinity.
//! * `A ≠ 0`: with `t_E = −B/(2A)` and `d = (4AC − 3B²)/(4A²)`, the self-intersection
//!   parameters are `t_E ± √d` (from `P(s) = P(t)`, `s ≠ t`, which gives `s + t = −B/A`,
//!   `st = (s+t)² − C/A`) and the inflection parameters are `t_E ± √(−d/3)` (roots of
//!   `P'×P''/2 = 3A t² + 3B t + C`). Hence `d > 0` **crunode**, `d = 0` **cusp** (at `t_E`),
//!   `d < 0` **acnode**. The double point is rational in every case:
//!   `D = a0 + a1 t_E + a2 (t_E² + d) + a3 (t_E³ + 3 t_E d)`.
//!
//! Segment features on the closed interval `[0, 1]` are decided exactly in `Q(√d)`.
//! The seed's moving-line route ([`MovingLines`]) and the Loop–Blinn discriminant
//! (Loop–Blinn) are independent cross-checks.

pub(crate) mod canonical;
pub(crate) mod certified;
pub(crate) mod evidence;
pub(crate) mod integer;
pub(crate) mod moving_line;
pub(crate) mod rational_cubic;
pub(crate) mod report;

pub use canonical::{CanonicalMap, Tower, canonical_map};
pub use evidence::{CanonicalEvidence, CubicEvidence, LoopBlinnEvidence, MovingLinesEvidence};
pub use moving_line::MovingLines;
pub use rational_cubic::{RationalClassification, classify_rational};
pub use report::{Classified, ClassifyOptions, ClassifyReport, FloatApproximations};

use crate::curve::bezier::BezierCurve;
use crate::error::{Error, Result};
use crate::num::point::Point;
use crate::num::quadratic_field::{QuadraticExt, Radical};
use crate::num::scalar::{Exact, Scalar, rat};
use crate::num::small::{SmallRational, checked};
use crate::poly::polynomial::{center_plus_minus_sqrt, quadratic_roots};
use num_rational::BigRational;
use std::cmp::Ordering;
use std::fmt;

/// An exact real parameter `a + b√m` (rational when `b = 0`).
pub type Parameter<K = BigRational> = QuadraticExt<K>;

/// The node type of a genuine cubic (seed 004, §3.3).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum NodeType {
    /// Self-intersection (`d > 0`): canonical form `x³ + x² − 3y² = 0`.
    Crunode,
    /// Cusp (`d = 0`): canonical form `x³ − 3y² = 0`.
    Cusp,
    /// Isolated double point (`d < 0`): canonical form `x³ − x² − 3y² = 0`.
    Acnode,
    /// Double point at infinity (`A = 0`): canonical form `y = x³`.
    Explicit,
}

/// The names of [`NodeType`], [`CurveClass`] and [`SegmentCategory`] in JSON: their `as_str`.
macro_rules! serialize_as_str {
    ($($t:ty),*) => {$(
        impl serde::Serialize for $t {
            fn serialize<S: serde::Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
                s.serialize_str(self.as_str())
            }
        }
    )*};
}
serialize_as_str!(NodeType, CurveClass, SegmentCategory);

impl NodeType {
    /// The canonical implicit equation of the node type: the curve every genuine cubic of this
    /// type is an affine image of (seed 004, §3.3).
    ///
    /// ```
    /// use casteljau::classify::NodeType;
    /// assert_eq!(NodeType::Crunode.canonical_equation(), "x^3 + x^2 - 3*y^2 = 0");
    /// ```
    pub fn canonical_equation(self) -> &'static str {
        match self {
            NodeType::Crunode => "x^3 + x^2 - 3*y^2 = 0",
            NodeType::Cusp => "x^3 - 3*y^2 = 0",
            NodeType::Acnode => "x^3 - x^2 - 3*y^2 = 0",
            NodeType::Explicit => "y - x^3 = 0",
        }
    }
}

impl NodeType {
    /// `crunode`, `cusp`, `acnode` or `explicit`.
    pub fn as_str(self) -> &'static str {
        match self {
            NodeType::Crunode => "crunode",
            NodeType::Cusp => "cusp",
            NodeType::Acnode => "acnode",
            NodeType::Explicit => "explicit",
        }
    }
}

/// The 16 classes of planar polynomial Bézier curves of degree ≤ 3 (by written degree, real
/// degree of the power form, and collinearity of the control points).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CurveClass {
    /// Degree 0.
    Point,
    /// Degree 1, distinct endpoints.
    Line,
    /// Degree 1, coincident endpoints.
    LineReallyPoint,
    /// Degree 2, not collinear.
    Quadratic,
    /// Degree 2, collinear control points, real degree 2 (a segment traced with a turn-back
    /// or a non-uniform speed).
    CollinearQuadratic,
    /// Degree 2 whose power form has degree 1.
    QuadraticReallyLine,
    /// Degree 2 whose control points coincide.
    QuadraticReallyPoint,
    /// A genuine cubic of the given node type.
    Cubic(NodeType),
    /// Degree 3 whose power form has degree 2 (a degree-elevated quadratic), not collinear.
    CubicReallyQuadratic,
    /// Degree 3, real degree 3, collinear control points.
    CollinearCubic,
    /// Degree 3, real degree 2, collinear control points.
    CubicReallyCollinearQuadratic,
    /// Degree 3 whose power form has degree 1.
    CubicReallyLine,
    /// Degree 3 whose control points coincide.
    CubicReallyPoint,
}

impl CurveClass {
    /// The class name used in text and JSON output.
    pub fn as_str(self) -> &'static str {
        match self {
            CurveClass::Point => "point",
            CurveClass::Line => "line",
            CurveClass::LineReallyPoint => "line_really_point",
            CurveClass::Quadratic => "quadratic",
            CurveClass::CollinearQuadratic => "collinear_quadratic",
            CurveClass::QuadraticReallyLine => "quadratic_really_line",
            CurveClass::QuadraticReallyPoint => "quadratic_really_point",
            CurveClass::Cubic(n) => n.as_str(),
            CurveClass::CubicReallyQuadratic => "cubic_really_quadratic",
            CurveClass::CollinearCubic => "collinear_cubic",
            CurveClass::CubicReallyCollinearQuadratic => "cubic_really_collinear_quadratic",
            CurveClass::CubicReallyLine => "cubic_really_line",
            CurveClass::CubicReallyPoint => "cubic_really_point",
        }
    }
}

impl fmt::Display for CurveClass {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.as_str())
    }
}

/// The Stone–DeRose / flo_curves category of the segment `t ∈ [0, 1]`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum SegmentCategory {
    /// All control points coincide.
    Point,
    /// The curve lies on a line.
    Line,
    /// A non-degenerate quadratic (possibly written as a cubic).
    Parabola,
    /// A genuine cubic with no loop, cusp or inflection on `[0, 1]`.
    Arch,
    /// One inflection on `[0, 1]`.
    SingleInflection,
    /// Two inflections on `[0, 1]`.
    DoubleInflection,
    /// Both self-intersection parameters on `[0, 1]`.
    Loop,
    /// The cusp parameter on `[0, 1]`.
    Cusp,
}

impl SegmentCategory {
    /// The category name used in output.
    pub fn as_str(self) -> &'static str {
        match self {
            SegmentCategory::Point => "point",
            SegmentCategory::Line => "line",
            SegmentCategory::Parabola => "parabola",
            SegmentCategory::Arch => "arch",
            SegmentCategory::SingleInflection => "single_inflection",
            SegmentCategory::DoubleInflection => "double_inflection",
            SegmentCategory::Loop => "loop",
            SegmentCategory::Cusp => "cusp",
        }
    }
}

/// Features of the segment `t ∈ [0, 1]` (closed: endpoints count).
#[derive(Clone, Debug, PartialEq, Eq, serde::Serialize)]
pub struct SegmentFeatures {
    /// Both self-intersection parameters lie in `[0, 1]`.
    #[serde(rename = "loop")]
    pub has_loop: bool,
    /// The tangent vanishes and the curve turns back at a parameter in `[0, 1]` (the cusp of a
    /// genuine cubic, or the turning point of a collinear curve).
    #[serde(rename = "cusp")]
    pub has_cusp: bool,
    /// Number of distinct real inflection parameters in `[0, 1]`.
    pub inflections: usize,
    /// The Stone–DeRose category.
    pub category: SegmentCategory,
}

/// Everything casteljau knows exactly about a planar curve of degree ≤ 3.
///
/// Its JSON (the fields of `classify --json`): `degree`, `real_degree`, `collinear`, `class`,
/// `reason`, `node_type` (or `null`), `double_point` (exact strings, or `null`),
/// `double_point_parameters`, `inflection_parameters`, `cusp_parameters` (exact strings such as
/// `"1/2 + 1/6*sqrt(5)"`), `invariants` (`{"A", "B", "C"}`), `t_E` and `d` (only when `A ≠ 0`)
/// and `segment` (`{"loop", "cusp", "inflections", "category"}`).
///
/// `K` is the exact field the answer is written in: [`BigRational`] from [`classify`], or the
/// fixed-width [`SmallRational`] from [`classify_in`] on the fast route; [`Classification::map`]
/// changes it, and both spell every number alike.
#[derive(Clone, Debug, serde::Serialize)]
#[serde(bound(serialize = "K: Radical"))]
pub struct Classification<K = BigRational> {
    /// The written degree.
    pub degree: usize,
    /// The degree of the power form (0–3).
    pub real_degree: usize,
    /// All control points on one line.
    pub collinear: bool,
    /// The class.
    pub class: CurveClass,
    /// Why the curve is in its class, in words.
    pub reason: String,
    /// The node type of a genuine cubic.
    pub node_type: Option<NodeType>,
    /// The double point (crunode, acnode) or the cusp point (cusp): always rational.
    pub double_point: Option<Point<K>>,
    /// `t_E ± √d` (crunode), `t_E` (cusp); empty otherwise.
    pub double_point_parameters: Vec<Parameter<K>>,
    /// Real inflection parameters, ascending (any `t`, not only `[0, 1]`).
    pub inflection_parameters: Vec<Parameter<K>>,
    /// Parameters where the tangent vanishes and the curve turns back (cusp, collinear turning
    /// points), ascending.
    pub cusp_parameters: Vec<Parameter<K>>,
    /// `(A, B, C) = (a2×a3, a1×a3, a1×a2)`.
    #[serde(serialize_with = "invariants_json")]
    pub invariants: [K; 3],
    /// `t_E = −B/(2A)` and `d = (4AC − 3B²)/(4A²)` when `A ≠ 0`.
    #[serde(flatten, serialize_with = "t_e_and_d_json")]
    pub t_e_and_d: Option<(K, K)>,
    /// Features of the segment `[0, 1]`.
    pub segment: SegmentFeatures,
}

fn invariants_json<K: fmt::Display, S: serde::Serializer>(v: &[K; 3], s: S) -> std::result::Result<S::Ok, S::Error> {
    use serde::ser::SerializeMap;
    let mut m = s.serialize_map(Some(3))?;
    for (name, x) in ["A", "B", "C"].iter().zip(v) {
        m.serialize_entry(name, &crate::num::serial::AsString(x))?;
    }
    m.end()
}

fn t_e_and_d_json<K: fmt::Display, S: serde::Serializer>(
    v: &Option<(K, K)>,
    s: S,
) -> std::result::Result<S::Ok, S::Error> {
    use serde::ser::SerializeMap;
    let mut m = s.serialize_map(None)?;
    if let Some((t_e, d)) = v {
        m.serialize_entry("t_E", &crate::num::serial::AsString(t_e))?;
        m.serialize_entry("d", &crate::num::serial::AsString(d))?;
    }
    m.end()
}

/// Largest degree [`classify`] accepts.
pub(crate) const MAX_CLASSIFY_DEGREE: usize = 3;

/// A planar vector of the power form, held inline (the classifier allocates no points).
type Vector<K> = [K; 2];

fn cross<K: Scalar>(u: &Vector<K>, v: &Vector<K>) -> K {
    u[0].clone() * &v[1] - u[1].clone() * &v[0]
}

/// The power coefficients `a_k = C(n, k) Δ^k P_0` of a planar curve of degree `n ≤ 3`, padded
/// with zeros to four (the same numbers as [`BezierCurve::power_coefficients`]).
fn power_form<K: Scalar>(curve: &BezierCurve<K>) -> [Vector<K>; 4] {
    let n = curve.degree();
    let mut diff: [Vector<K>; 4] = std::array::from_fn(|i| match curve.points().get(i) {
        Some(p) => [p.coords[0].clone(), p.coords[1].clone()],
        None => [K::zero(), K::zero()],
    });
    let mut out: [Vector<K>; 4] = std::array::from_fn(|_| [K::zero(), K::zero()]);
    for k in 0..=n {
        // C(n, k) for n ≤ 3
        let c = [[1, 0, 0, 0], [1, 1, 0, 0], [1, 2, 1, 0], [1, 3, 3, 1]][n][k];
        out[k] = if c == 1 { diff[0].clone() } else { diff[0].clone().map(|x| K::from_i64(c) * &x) };
        for i in 0..n - k {
            diff[i] = [diff[i + 1][0].clone() - &diff[i][0], diff[i + 1][1].clone() - &diff[i][1]];
        }
    }
    out
}

/// `0 ≤ t ≤ 1`, exactly.
pub(crate) fn in_unit_interval<K: Exact>(t: &Parameter<K>) -> bool {
    t.sign() != Ordering::Less && (Parameter::<K>::one() - t).sign() != Ordering::Less
}

impl<K: Radical> PartialEq for Classification<K> {
    /// Field by field, numbers by numeric equality.
    fn eq(&self, o: &Self) -> bool {
        self.degree == o.degree
            && self.real_degree == o.real_degree
            && self.collinear == o.collinear
            && self.class == o.class
            && self.reason == o.reason
            && self.node_type == o.node_type
            && self.double_point == o.double_point
            && self.double_point_parameters == o.double_point_parameters
            && self.inflection_parameters == o.inflection_parameters
            && self.cusp_parameters == o.cusp_parameters
            && self.invariants == o.invariants
            && self.t_e_and_d == o.t_e_and_d
            && self.segment == o.segment
    }
}

impl<K: Radical> Eq for Classification<K> {}

impl<K: Radical> Classification<K> {
    /// The same answer written in another exact field: `f` maps every number (an injective
    /// field homomorphism such as [`SmallRational::to_big`]).
    pub fn map<L: Radical>(&self, f: impl Fn(&K) -> L) -> Classification<L> {
        let params = |ps: &[Parameter<K>]| ps.iter().map(|p| p.map(&f)).collect();
        Classification {
            degree: self.degree,
            real_degree: self.real_degree,
            collinear: self.collinear,
            class: self.class,
            reason: self.reason.clone(),
            node_type: self.node_type,
            double_point: self.double_point.as_ref().map(|p| Point::new(p.coords.iter().map(&f).collect())),
            double_point_parameters: params(&self.double_point_parameters),
            inflection_parameters: params(&self.inflection_parameters),
            cusp_parameters: params(&self.cusp_parameters),
            invariants: [f(&self.invariants[0]), f(&self.invariants[1]), f(&self.invariants[2])],
            t_e_and_d: self.t_e_and_d.as_ref().map(|(t, d)| (f(t), f(d))),
            segment: self.segment.clone(),
        }
    }
}

/// Classifies a planar curve of degree ≤ 3, exactly.
///
/// # Errors
/// [`Error::DimensionMismatch`] unless 2D; [`Error::TooLarge`] for degree > 3.
///
/// # Example
/// ```
/// use casteljau::{BezierCurve, classify::{classify, NodeType}, num::parse_points};
/// // a cusp at t = 1/2: P0 P1 P2 P3 = (0,0) (1,1) (0,1) (1,0)
/// let c = BezierCurve::new(parse_points("0 0, 1 1, 0 1, 1 0", 2, None).unwrap()).unwrap();
/// let k = classify(&c).unwrap();
/// assert_eq!(k.node_type, Some(NodeType::Cusp));
/// assert_eq!(k.double_point.unwrap().to_string(), "(1/2, 3/4)");
/// assert!(k.segment.has_cusp);
/// ```
pub fn classify(curve: &BezierCurve<BigRational>) -> Result<Classification> {
    // The fast route: every coordinate fits i128 and no step overflows (decided, not guessed).
    let small: Option<Vec<Point<SmallRational>>> = curve
        .points()
        .iter()
        .map(|p| p.coords.iter().map(SmallRational::from_big).collect::<Option<Vec<_>>>().map(Point::new))
        .collect();
    if let Some(Ok(k)) = small.and_then(|pts| checked(|| classify_in(&BezierCurve::new(pts)?))) {
        return Ok(k.map(SmallRational::to_big));
    }
    classify_in(curve)
}

/// [`classify`] in any exact field with canonical radicals. Over [`SmallRational`] run it inside
/// [`checked`]: `None` there means a number outgrew 128 bits
/// (redo it with [`classify`]); otherwise the answer is exact and equal to [`classify`]'s.
///
/// # Errors
/// As [`classify`].
///
/// # Example
/// ```
/// use casteljau::internal::{SmallRational, checked, classify_in};
/// use casteljau::{BezierCurve, Point, Scalar};
/// let p = |x: i64, y: i64| Point::new(vec![SmallRational::from_i64(x), SmallRational::from_i64(y)]);
/// let c = BezierCurve::new(vec![p(0, 0), p(30, 40), p(-20, 40), p(10, 0)]).unwrap();
/// let k = checked(|| classify_in(&c)).expect("fits 128 bits").unwrap();
/// assert_eq!(k.double_point_parameters[0].to_string(), "1/2 - 1/4*sqrt(3)");
/// ```
#[doc(hidden)]
pub fn classify_in<K: Radical>(curve: &BezierCurve<K>) -> Result<Classification<K>> {
    if curve.dim() != 2 {
        return Err(Error::DimensionMismatch { expected: 2, found: curve.dim() });
    }
    let n = curve.degree();
    if n > MAX_CLASSIFY_DEGREE {
        return Err(Error::TooLarge { what: "degree to classify", value: n, limit: MAX_CLASSIFY_DEGREE });
    }
    let a = power_form(curve);
    let inv = [cross(&a[2], &a[3]), cross(&a[1], &a[3]), cross(&a[1], &a[2])];
    let [big_a, big_b, big_c] = inv.clone();
    let collinear = inv.iter().all(Scalar::is_zero);
    let real_degree = (0..4).rev().find(|&k| a[k].iter().any(|x| !Scalar::is_zero(x))).unwrap_or(0);
    let mut out = Classification {
        degree: n,
        real_degree,
        collinear,
        class: CurveClass::Point,
        reason: String::new(),
        node_type: None,
        double_point: None,
        double_point_parameters: vec![],
        inflection_parameters: vec![],
        cusp_parameters: vec![],
        invariants: inv,
        t_e_and_d: None,
        segment: SegmentFeatures { has_loop: false, has_cusp: false, inflections: 0, category: SegmentCategory::Point },
    };
    let (class, reason) = degenerate_class(n, real_degree, collinear);
    out.class = class;
    out.reason = reason;
    if collinear {
        out.cusp_parameters = turning_points(&a);
    } else if real_degree == 3 {
        genuine_cubic(&mut out, &a, &big_a, &big_b, &big_c);
    }
    let seg = &mut out.segment;
    match out.node_type {
        // t_E ± √r ∈ [0, 1] decided by signs of polynomials in A, B, C (see `unit_signs`): no
        // products of radicals, so fixed-width numbers do not outgrow the answer
        Some(node @ (NodeType::Crunode | NodeType::Cusp | NodeType::Acnode)) => {
            let signs = unit_signs(node, &big_a, &big_b, &big_c);
            let inside = |plus| certified::in_unit(signs[0], signs[1], signs[2], signs[3], plus);
            match node {
                NodeType::Crunode => seg.has_loop = inside(false) && inside(true),
                NodeType::Cusp => seg.has_cusp = signs[0] >= 0 && signs[2] >= 0,
                _ => seg.inflections = usize::from(inside(false)) + usize::from(inside(true)),
            }
        }
        _ => {
            seg.has_cusp = out.cusp_parameters.iter().any(in_unit_interval);
            seg.inflections = out.inflection_parameters.iter().filter(|t| in_unit_interval(t)).count();
        }
    }
    seg.category = if real_degree == 0 {
        SegmentCategory::Point
    } else if collinear {
        SegmentCategory::Line
    } else if real_degree == 2 {
        SegmentCategory::Parabola
    } else if seg.has_loop {
        SegmentCategory::Loop
    } else if seg.has_cusp {
        SegmentCategory::Cusp
    } else {
        match seg.inflections {
            0 => SegmentCategory::Arch,
            1 => SegmentCategory::SingleInflection,
            _ => SegmentCategory::DoubleInflection,
        }
    };
    Ok(out)
}

/// The class from written degree, real degree and collinearity; genuine cubics get their node
/// type later (`Cubic(Explicit)` is a placeholder here).
fn degenerate_class(n: usize, real: usize, collinear: bool) -> (CurveClass, String) {
    use CurveClass::*;
    let why = |s: &str| s.to_string();
    match (n, real, collinear) {
        (0, _, _) => (Point, why("one control point")),
        (1, 0, _) => (LineReallyPoint, why("a1 = 0: both control points coincide")),
        (1, _, _) => (Line, why("two distinct control points")),
        (2, 0, _) => (QuadraticReallyPoint, why("a1 = a2 = 0: all control points coincide")),
        (2, 1, _) => (QuadraticReallyLine, why("a2 = 0: P1 is the midpoint of P0P2 (a degree-elevated line)")),
        (2, _, true) => (CollinearQuadratic, why("a1 × a2 = 0: control points collinear")),
        (2, _, false) => (Quadratic, why("a1 × a2 ≠ 0")),
        (_, 0, _) => (CubicReallyPoint, why("a1 = a2 = a3 = 0: all control points coincide")),
        (_, 1, _) => (CubicReallyLine, why("a2 = a3 = 0: a degree-elevated line")),
        (_, 2, true) => {
            (CubicReallyCollinearQuadratic, why("a3 = 0 and a1 × a2 = 0: a degree-elevated collinear quadratic"))
        }
        (_, 2, false) => (CubicReallyQuadratic, why("a3 = 0: degree-elevated quadratic")),
        (_, _, true) => (CollinearCubic, why("a1×a2 = a1×a3 = a2×a3 = 0: control points collinear")),
        (_, _, false) => (Cubic(NodeType::Explicit), String::new()),
    }
}

fn genuine_cubic<K: Radical>(out: &mut Classification<K>, a: &[Vector<K>; 4], big_a: &K, big_b: &K, big_c: &K) {
    let rat = K::from_i64;
    if Scalar::is_zero(big_a) {
        out.class = CurveClass::Cubic(NodeType::Explicit);
        out.node_type = Some(NodeType::Explicit);
        out.reason = EXPLICIT_REASON.into();
        let t = -big_c.clone() / (rat(3) * big_b);
        out.inflection_parameters = vec![Parameter::from_base(t)];
        return;
    }
    let te = -big_b.clone() / (rat(2) * big_a);
    let d = (rat(4) * big_a * big_c - rat(3) * big_b * big_b) / (rat(4) * big_a * big_a);
    // D = a0 + a1 t_E + a2 (t_E² + d) + a3 (t_E³ + 3 t_E d), simplified with A a1 − B a2 + C a3 = 0
    let ratio = (big_a.clone() * big_c - big_b.clone() * big_b) / (big_a.clone() * big_a * big_a);
    let dp = (0..2).map(|i| a[0][i].clone() + &((a[2][i].clone() * big_a - a[3][i].clone() * big_b) * &ratio));
    out.double_point = Some(Point::new(dp.collect()));
    let node = match d.sign() {
        Ordering::Greater => NodeType::Crunode,
        Ordering::Equal => NodeType::Cusp,
        Ordering::Less => NodeType::Acnode,
    };
    out.node_type = Some(node);
    out.class = CurveClass::Cubic(node);
    write_node_reason(&mut out.reason, node, &d, &te).expect("writing to a String");
    match node {
        NodeType::Crunode => {
            out.double_point_parameters = center_plus_minus_sqrt(&te, &d).to_vec();
        }
        NodeType::Cusp => {
            out.double_point_parameters = vec![Parameter::from_base(te.clone())];
            out.cusp_parameters = vec![Parameter::from_base(te.clone())];
        }
        _ => {
            let r = -d.clone() / rat(3);
            out.inflection_parameters = center_plus_minus_sqrt(&te, &r).to_vec();
        }
    }
    out.t_e_and_d = Some((te, d));
}

/// The `reason` of a genuine cubic with `A = 0`.
pub(crate) const EXPLICIT_REASON: &str = "A = a2×a3 = 0: double point at infinity (affine image of y = x³)";

/// Writes the `reason` of a genuine cubic with `A ≠ 0` (one wording for every route).
pub(crate) fn write_node_reason(
    out: &mut impl fmt::Write,
    node: NodeType,
    d: &dyn fmt::Display,
    te: &dyn fmt::Display,
) -> fmt::Result {
    match node {
        NodeType::Crunode => write!(out, "d = {d} > 0: self-intersection at t_E ± √d, t_E = {te}"),
        NodeType::Cusp => write!(out, "d = 0: cusp at t_E = {te}"),
        _ => write!(out, "d = {d} < 0: isolated double point; inflections at t_E ± √(−d/3), t_E = {te}"),
    }
}

/// `[sign c, sign(c² − r), sign(1 − c), sign((1 − c)² − r)]` for the parameters `c ± √r` of a
/// genuine cubic with `A ≠ 0`, `c = t_E = −B/(2A)`: `r = d` (double points; a cusp has `d = 0`)
/// or `r = −d/3` (inflections of an acnode). With `d = (4AC − 3B²)/(4A²)`:
/// `sign c = −sign(A)·sign(B)`, `sign(1 − c) = sign(A)·sign(2A + B)`; for `r = d`
/// `sign(c² − d) = sign(B² − AC)`, `sign((1 − c)² − d) = sign(A² + AB + B² − AC)`; for `r = −d/3`
/// `sign(c² − r) = sign(A)·sign(C)`, `sign((1 − c)² − r) = sign(A)·sign(3A + 3B + C)`.
fn unit_signs<K: Exact>(node: NodeType, a: &K, b: &K, c: &K) -> [i8; 4] {
    let s = |x: K| x.sign() as i8;
    let sa = a.sign() as i8;
    let two = K::from_i64(2);
    let three = K::from_i64(3);
    let sc = -sa * b.sign() as i8;
    let s1c = sa * s(two * a + b);
    let b2_ac = b.clone() * b - a.clone() * c;
    if node == NodeType::Acnode {
        [sc, sa * c.sign() as i8, s1c, sa * s(three.clone() * a + &(three * b) + c)]
    } else {
        [sc, s(b2_ac.clone()), s1c, s(a.clone() * a + &(a.clone() * b) + &b2_ac)]
    }
}

/// Simple real roots of `p'(t)` for a collinear curve `P(t) = a0 + v·p(t)`: where it turns back.
fn turning_points<K: Radical>(a: &[Vector<K>; 4]) -> Vec<Parameter<K>> {
    let rat = K::from_i64;
    let Some(v) = a[1..].iter().find(|p| p.iter().any(|x| !Scalar::is_zero(x))) else {
        return vec![];
    };
    // α_k with a_k = α_k v (v has a non-zero coordinate c)
    let c = if Scalar::is_zero(&v[0]) { 1 } else { 0 };
    let alpha: Vec<K> = a.iter().map(|p| p[c].clone() / &v[c]).collect();
    // p'(t) = α1 + 2α2 t + 3α3 t²
    // a double root of p' is no turning point: the speed vanishes but the curve goes on
    let (c0, c1, c2) = (alpha[1].clone(), rat(2) * &alpha[2], rat(3) * &alpha[3]);
    quadratic_roots(&c0, &c1, &c2).into_iter().filter(|(_, m)| *m == 1).map(|(t, _)| t).collect()
}

/// The Loop–Blinn classification (GPU Gems 3, ch. 25), computed exactly from the Bézier control
/// points: `a1 = b0·(b3×b2)`, `a2 = b1·(b0×b3)`, `a3 = b2·(b1×b0)` in homogeneous `(x, y, 1)`,
/// `d1 = a1 − 2a2 + 3a3`, `d2 = −a2 + 3a3`, `d3 = 3a3`, discriminant `d1²(3d2² − 4d1d3)`.
/// Returns `(d1, d2, d3)` and the node type it implies for a genuine cubic: serpentine =
/// acnode (discriminant > 0), loop = crunode (< 0), cusp (= 0, d1 ≠ 0), cusp at infinity =
/// explicit (d1 = 0, d2 ≠ 0); `None` for d1 = d2 = 0 (not a genuine cubic).
#[doc(hidden)]
pub fn loop_blinn(curve: &BezierCurve<BigRational>) -> ([BigRational; 3], Option<NodeType>) {
    let b: Vec<Point<BigRational>> = curve.points().iter().map(|p| p.to_homogeneous(&rat(1))).collect();
    let x = |i: usize, j: usize, k: usize| b[i].dot(&b[j].cross(&b[k]).expect("3-vectors"));
    let (a1, a2, a3) = (x(0, 3, 2), x(1, 0, 3), x(2, 1, 0));
    let d1 = a1 - rat(2) * &a2 + rat(3) * &a3;
    let d2 = -a2 + rat(3) * &a3;
    let d3 = rat(3) * a3;
    let node = if !Scalar::is_zero(&d1) {
        let disc = d1.clone() * &d1 * (rat(3) * &d2 * &d2 - rat(4) * &d1 * &d3);
        Some(match disc.sign() {
            Ordering::Greater => NodeType::Acnode,
            Ordering::Less => NodeType::Crunode,
            Ordering::Equal => NodeType::Cusp,
        })
    } else if !Scalar::is_zero(&d2) {
        Some(NodeType::Explicit)
    } else {
        None
    };
    ([d1, d2, d3], node)
}

/// A fact about one segment that float code most often gets wrong (the `flags` of `casteljau
/// scan`), serialized as its stable snake_case name ([`SegmentFlag::as_str`]).
///
/// # Example
/// ```
/// use casteljau::classify::SegmentFlag;
/// assert_eq!(SegmentFlag::ZeroLengthHandle.as_str(), "zero_length_handle");
/// assert_eq!(serde_json::to_string(&SegmentFlag::CuspAtEndpoint).unwrap(), r#""cusp_at_endpoint""#);
/// assert!(SegmentFlag::LoopAtEndpoint.at_endpoint() && !SegmentFlag::Degenerate.at_endpoint());
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum SegmentFlag {
    /// The real degree is below the written degree (a zero-length line, a degree-elevated
    /// curve, coincident points).
    Degenerate,
    /// A control point at its end point (`P1 = P0` or `P(n−1) = Pn`, degree ≥ 2).
    ZeroLengthHandle,
    /// A cusp parameter exactly `0` or `1`.
    CuspAtEndpoint,
    /// A self-intersection parameter of a crunode exactly `0` or `1`.
    LoopAtEndpoint,
    /// An inflection parameter exactly `0` or `1`.
    InflectionAtEndpoint,
}

impl SegmentFlag {
    /// The stable name: `degenerate`, `zero_length_handle`, `cusp_at_endpoint`,
    /// `loop_at_endpoint`, `inflection_at_endpoint`.
    ///
    /// # Example
    /// ```
    /// use casteljau::classify::SegmentFlag;
    /// assert_eq!(SegmentFlag::InflectionAtEndpoint.as_str(), "inflection_at_endpoint");
    /// ```
    pub fn as_str(self) -> &'static str {
        match self {
            SegmentFlag::Degenerate => "degenerate",
            SegmentFlag::ZeroLengthHandle => "zero_length_handle",
            SegmentFlag::CuspAtEndpoint => "cusp_at_endpoint",
            SegmentFlag::LoopAtEndpoint => "loop_at_endpoint",
            SegmentFlag::InflectionAtEndpoint => "inflection_at_endpoint",
        }
    }

    /// A cusp, loop or inflection exactly at `t = 0` or `1`.
    ///
    /// # Example
    /// ```
    /// use casteljau::classify::SegmentFlag;
    /// assert!(SegmentFlag::CuspAtEndpoint.at_endpoint());
    /// ```
    pub fn at_endpoint(self) -> bool {
        matches!(self, SegmentFlag::CuspAtEndpoint | SegmentFlag::LoopAtEndpoint | SegmentFlag::InflectionAtEndpoint)
    }
}

impl std::fmt::Display for SegmentFlag {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.as_str())
    }
}

impl<K: Radical> Classification<K> {
    /// The [`SegmentFlag`]s of one segment, in the order of the enum.
    ///
    /// # Example
    /// ```
    /// use casteljau::{BezierCurve, classify::{SegmentFlag, classify}, num::parse_points};
    /// let c = BezierCurve::new(parse_points("0 0, 0 0, 1 1, 2 0", 2, None).unwrap()).unwrap();
    /// let k = classify(&c).unwrap();
    /// assert_eq!(k.segment_flags(c.points()), [SegmentFlag::ZeroLengthHandle, SegmentFlag::CuspAtEndpoint]);
    /// ```
    pub fn segment_flags(&self, points: &[Point<K>]) -> Vec<SegmentFlag> {
        let k = self;
        let mut flags = vec![];
        let n = points.len().saturating_sub(1);
        if k.real_degree < k.degree {
            flags.push(SegmentFlag::Degenerate);
        }
        if n >= 2 && (points[0] == points[1] || points[n - 1] == points[n]) {
            flags.push(SegmentFlag::ZeroLengthHandle);
        }
        let at_end = |ps: &[Parameter<K>]| {
            ps.iter().any(|t| t.radicand().is_zero() && (t.rational_part().is_zero() || *t.rational_part() == K::one()))
        };
        if at_end(&k.cusp_parameters) {
            flags.push(SegmentFlag::CuspAtEndpoint);
        }
        if k.node_type == Some(NodeType::Crunode) && at_end(&k.double_point_parameters) {
            flags.push(SegmentFlag::LoopAtEndpoint);
        }
        if at_end(&k.inflection_parameters) {
            flags.push(SegmentFlag::InflectionAtEndpoint);
        }
        flags
    }
}
