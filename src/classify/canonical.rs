//! Exact affine maps from the four canonical cubics to a genuine cubic (seed 004, (9)–(18),
//! and Case 4, which the seed omits).
//!
//! Every genuine planar cubic is `P(t) = M · C(t̃)`, `t̃ = (t − t_E)/(t_F − t_E)`, with `C` one of
//!
//! | node | canonical curve `C(s)` | implicit form |
//! | --- | --- | --- |
//! | crunode | `(s² − 1, (s³ − s)/√3)` | `x³ + x² − 3y² = 0` |
//! | cusp | `(s², s³/√3)` | `x³ − 3y² = 0` |
//! | acnode | `(s² + 1, (s³ + s)/√3)` | `x³ − x² − 3y² = 0` |
//! | explicit | `(s, s³)` | `y = x³` |
//!
//! and `M` an affine map built from reference points on the moving lines. The entries live in
//! `Q(√3)(√r)` (`r = |d|` for crunodes and acnodes), computed exactly in [`Tower`], and the
//! claim `M·C(t̃(t)) ≡ P(t)` (degree ≤ 3 in `t`) is **proved** with the grid prover.
//!
//! The seed's reference points, as printed and as they hold (see `proofs/README.md`):
//! * (9) crunode, `F = L0[t_F] × L1[t_F]`: both lines pass through `P(t_F) = D`, so `F = D` and
//!   `M` is wrong. What holds: `F = L0[t_F] × L1[t_E]` (the tangent at `D` meets the tangent at `E`).
//! * (12) cusp, `G = L0[t_E] × L1[t_E] = D`: `M` has a zero column. What holds:
//!   `G = L0[t_E] × L1[t_F]`; `F = L0[t_F] × L1[t_F] = P(t_F)` as printed.
//! * (15)–(18) acnode: as printed (`G = 2E − D`, `t_F` the larger root of `L1[t]·G = 0`).
//! * Case 4 explicit (derived here): `t_E` the inflection `−C/(3B)`, `t_F = t_E + 1`,
//!   `G = E + P'(t_E)`, `F = P(t_F)`, `M = [G − E | F − G | E]`, all rational.

use crate::classify::moving_line::MovingLines;
use crate::classify::{Classification, NodeType};
use crate::curve::bezier::BezierCurve;
use crate::error::{Error, Result};
use crate::num::point::Point;
use crate::num::quadratic_field::QuadraticExt;
use crate::num::scalar::{Exact, Scalar, rat};
use crate::proof::{Certificate, Counterexample, GridProver, Reading};
use num_rational::BigRational;
use std::cmp::Ordering;

/// `Q(√3)`.
pub(crate) type Sqrt3Field = QuadraticExt<BigRational>;
/// `Q(√3)(√r)`: where the canonical maps live (a [`QuadraticExt`] over `Q(√3)`).
///
/// # Example
/// ```
/// use casteljau::{QuadraticExt, Scalar, rat, classify::Tower};
/// let s3 = Tower::from_base(QuadraticExt::sqrt(rat(3))); // √3, in the base field Q(√3)
/// assert_eq!(s3.clone() * s3, Tower::from_i64(3));
/// ```
pub type Tower = QuadraticExt<Sqrt3Field>;

/// An affine map `M` (2×3, last column the translation) from a canonical cubic to a curve.
///
/// # Example
/// ```
/// # use casteljau::{BezierCurve, num::parse_points, proof::Reading};
/// # use casteljau::classify::{classify, CanonicalMap, MovingLines, canonical_map};
/// let c = BezierCurve::new(parse_points("0 0, 1 1, 0 1, 1 0", 2, None).unwrap()).unwrap();
/// let (k, ml) = (classify(&c).unwrap(), MovingLines::new(&c).unwrap());
/// let map = canonical_map(&c, &k, &ml, Reading::Corrected).unwrap();
/// assert_eq!(map.node.canonical_equation(), "x^3 - 3*y^2 = 0");
/// assert!(map.prove(&c).is_ok());
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CanonicalMap {
    /// The node type, naming the canonical curve.
    pub node: NodeType,
    /// `M`: `P = M·(x, y, 1)`.
    pub matrix: [[Tower; 3]; 2],
    /// `t_E` (rational).
    pub t_e: BigRational,
    /// `t_F` (in the tower), with `t̃ = (t − t_E)/(t_F − t_E)`.
    pub t_f: Tower,
    /// The named reference points used (`D`, `E`, `F`, `G`), affine.
    pub points: Vec<(&'static str, Point<Tower>)>,
}

fn lift(r: &BigRational) -> Tower {
    Tower::from_ratio(r)
}
fn lift_point(p: &Point<BigRational>) -> Point<Tower> {
    Point::new(p.coords.iter().map(lift).collect())
}
/// `√3` as an element of the tower (it lies in the base field `Q(√3)`).
fn sqrt3() -> Tower {
    Tower::from_base(Sqrt3Field::sqrt(rat(3)))
}

/// `√r` for rational `r ≥ 0` in the tower: rational, a rational multiple of `√3`, or a new
/// generator over `Q(√3)`.
pub(crate) fn tower_sqrt(r: &BigRational) -> Tower {
    // √r = q√m with m an integer (Sqrt3Field::sqrt normalises); √m = √3·√(m/3) when 3 | m.
    let s = Sqrt3Field::sqrt(r.clone());
    if s.to_base().is_some() || *s.radicand() == rat(3) {
        return Tower::from_base(s);
    }
    let (q, m) = (s.radical_coefficient().clone(), s.radicand().clone());
    let three = rat(3);
    if (m.clone() / &three).is_integer() {
        let coeff = Sqrt3Field::sqrt(three.clone()) * Sqrt3Field::from_ratio(&q);
        return Tower::new(Sqrt3Field::zero(), coeff, Sqrt3Field::from_ratio(&(m / three)));
    }
    Tower::new(Sqrt3Field::zero(), Sqrt3Field::from_ratio(&q), Sqrt3Field::from_ratio(&m))
}

/// The canonical curve `C(s)` of a node type, over the tower.
pub(crate) fn canonical_point(node: NodeType, s: &Tower) -> Point<Tower> {
    let s2 = s.clone() * s;
    let s3 = s2.clone() * s;
    let r3 = sqrt3();
    match node {
        NodeType::Crunode => Point::new(vec![s2 - Tower::one(), (s3 - s) / &r3]),
        NodeType::Cusp => Point::new(vec![s2, s3 / &r3]),
        NodeType::Acnode => Point::new(vec![s2 + Tower::one(), (s3 + s) / &r3]),
        NodeType::Explicit => Point::new(vec![s.clone(), s3]),
    }
}

struct Lines<'a> {
    ml: &'a MovingLines,
}

impl Lines<'_> {
    fn at(&self, l: &[Point<BigRational>], t: &Tower) -> Point<Tower> {
        let u = Tower::one() - t;
        match l.len() {
            2 => lift_point(&l[0]).scale(&u).add(&lift_point(&l[1]).scale(t)),
            _ => lift_point(&l[0])
                .scale(&(u.clone() * &u))
                .add(&lift_point(&l[1]).scale(&(Tower::from_i64(2) * &u * t)))
                .add(&lift_point(&l[2]).scale(&(t.clone() * t))),
        }
    }
    /// `L0[a] × L1[b]`, affine; `None` at infinity (or when the lines coincide).
    fn meet(&self, a: &Tower, b: &Tower) -> Option<Point<Tower>> {
        let p = self.at(&self.ml.l0, a).cross(&self.at(&self.ml.l1, b)).expect("3-vectors");
        p.from_homogeneous()
    }
}

/// Builds the map of a genuine cubic with the given formulas, from the curve's
/// [`classify`](crate::classify::classify) result `k` and its [`MovingLines`] (computed once by
/// the caller, not again here).
///
/// # Errors
/// [`Error::Degenerate`] when the curve is not a genuine planar cubic,
/// [`Error::PointAtInfinity`] when a reference point of the chosen formulas is at infinity.
///
/// # Example
/// ```
/// use casteljau::{BezierCurve, num::parse_points, proof::Reading};
/// use casteljau::classify::{classify, NodeType, canonical_map, MovingLines};
/// // a cusp at t = 1/2: canonical curve x³ − 3y² = 0
/// let c = BezierCurve::new(parse_points("0 0, 1 1, 0 1, 1 0", 2, None).unwrap()).unwrap();
/// let (k, ml) = (classify(&c).unwrap(), MovingLines::new(&c).unwrap());
/// let map = canonical_map(&c, &k, &ml, Reading::Corrected).unwrap();
/// assert_eq!(map.node, NodeType::Cusp);
/// assert!(map.prove(&c).is_ok()); // M·C((t − t_E)/(t_F − t_E)) ≡ P(t), proved on a grid
/// // as printed, (12) puts G on D and the map degenerates
/// let printed = canonical_map(&c, &k, &ml, Reading::AsPrinted).unwrap();
/// assert!(printed.prove(&c).is_err());
/// ```
pub fn canonical_map(
    curve: &BezierCurve<BigRational>,
    k: &Classification,
    moving_lines: &MovingLines,
    formulas: Reading,
) -> Result<CanonicalMap> {
    let node = k.node_type.filter(|_| curve.degree() == 3).ok_or_else(|| Error::Degenerate {
        message: format!("canonical forms need a genuine cubic; this curve is {}", k.class),
    })?;
    let lines = Lines { ml: moving_lines };
    let fail = |what: &str| Error::PointAtInfinity { message: format!("reference point {what} is at infinity") };
    let p_at = |t: &Tower| lift_curve(curve).eval(t);
    let col = |v: Point<Tower>, f: &Tower| v.scale(f);
    let (t_e, t_f, cols, points) = match node {
        NodeType::Explicit => {
            let t_e = k.inflection_parameters[0].to_base().expect("rational inflection");
            let te = lift(&t_e);
            let tf = te.clone() + Tower::one();
            let e = p_at(&te);
            let g = e.add(&lift_curve(&curve.derivative(1)).eval(&te));
            let f = p_at(&tf);
            (t_e, tf, [g.sub(&e), f.sub(&g), e.clone()], vec![("E", e), ("F", f), ("G", g)])
        }
        _ => {
            let (t_e, d) = k.t_e_and_d.clone().expect("A ≠ 0");
            let te = lift(&t_e);
            let dp = lift_point(k.double_point.as_ref().expect("double point"));
            let e = lines.meet(&te, &te).ok_or_else(|| fail("E"))?;
            match node {
                NodeType::Crunode => {
                    let tf = te.clone() + tower_sqrt(&d);
                    let f = match formulas {
                        Reading::AsPrinted => lines.meet(&tf, &tf),
                        Reading::Corrected => lines.meet(&tf, &te),
                    }
                    .ok_or_else(|| fail("F"))?;
                    let c1 = col(e.sub(&f), &sqrt3());
                    (t_e, tf, [dp.sub(&e), c1, dp.clone()], vec![("D", dp), ("E", e), ("F", f)])
                }
                NodeType::Cusp => {
                    let tf = te.clone() + Tower::one();
                    let f = lines.meet(&tf, &tf).ok_or_else(|| fail("F"))?;
                    let g = match formulas {
                        Reading::AsPrinted => lines.meet(&te, &te),
                        Reading::Corrected => lines.meet(&te, &tf),
                    }
                    .ok_or_else(|| fail("G"))?;
                    let c1 = col(f.sub(&g), &sqrt3());
                    (t_e, tf, [g.sub(&dp), c1, dp.clone()], vec![("D", dp), ("E", e), ("F", f), ("G", g)])
                }
                _ => {
                    // (15) G = 2E − D; (16) t_F the larger root of L1[t]·G = 0.
                    let g = e.scale(&Tower::from_i64(2)).sub(&dp);
                    let tf = larger_root(lines.ml, &g).ok_or_else(|| fail("t_F"))?;
                    let f = lines.meet(&tf, &tf).ok_or_else(|| fail("F"))?;
                    let half = Tower::one() / Tower::from_i64(2);
                    let c0 = g.sub(&dp).scale(&half);
                    let c1 = f.sub(&g).scale(&(sqrt3() * &half));
                    (t_e, tf, [c0, c1, dp.clone()], vec![("D", dp), ("E", e), ("F", f), ("G", g)])
                }
            }
        }
    };
    let matrix = [0, 1].map(|r| [cols[0].coords[r].clone(), cols[1].coords[r].clone(), cols[2].coords[r].clone()]);
    Ok(CanonicalMap { node, matrix, t_e, t_f, points })
}

fn lift_curve(c: &BezierCurve<BigRational>) -> BezierCurve<Tower> {
    c.map(lift)
}

/// The larger root of `L1[t]·G = 0` (G has rational coordinates for the acnode: `G = 2E − D`).
fn larger_root(ml: &MovingLines, g: &Point<Tower>) -> Option<Tower> {
    let g: Vec<BigRational> = g.coords.iter().map(|c| c.to_base().and_then(|b| b.to_base())).collect::<Option<_>>()?;
    let g = Point::new(vec![g[0].clone(), g[1].clone(), rat(1)]);
    let (c0, c1, c2) = (ml.l1[0].dot(&g), ml.l1[1].dot(&g), ml.l1[2].dot(&g));
    // c0(1−t)² + 2c1(1−t)t + c2 t² = c0 + 2(c1 − c0)t + (c0 − 2c1 + c2)t²
    let (a, b, c) = (c0.clone() - rat(2) * &c1 + &c2, rat(2) * (c1 - &c0), c0);
    if a.is_zero() {
        return (!b.is_zero()).then(|| lift(&(-c / b)));
    }
    let disc = b.clone() * &b - rat(4) * &a * &c;
    if disc.sign() == Ordering::Less {
        return None;
    }
    let center = lift(&(-b / (rat(2) * &a)));
    let r = tower_sqrt(&(disc / (rat(4) * &a * &a)));
    Some(center + r)
}

impl CanonicalMap {
    /// `M · (x, y, 1)`.
    ///
    /// # Example
    /// ```
    /// # use casteljau::{BezierCurve, num::parse_points, proof::Reading};
    /// # use casteljau::classify::{classify, CanonicalMap, MovingLines, canonical_map, Tower};
    /// let c = BezierCurve::new(parse_points("0 0, 1 1, 0 1, 1 0", 2, None).unwrap()).unwrap();
    /// let (k, ml) = (classify(&c).unwrap(), MovingLines::new(&c).unwrap());
    /// let map = canonical_map(&c, &k, &ml, Reading::Corrected).unwrap();
    /// use casteljau::Scalar;
    /// // M maps the canonical cusp point (0, 0) to D
    /// let d = map.apply(&casteljau::Point::new(vec![Tower::from_i64(0), Tower::from_i64(0)]));
    /// assert_eq!(d.to_string(), "(1/2, 3/4)");
    /// ```
    pub fn apply(&self, p: &Point<Tower>) -> Point<Tower> {
        Point::new(
            self.matrix
                .iter()
                .map(|row| row[0].clone() * &p.coords[0] + row[1].clone() * &p.coords[1] + &row[2])
                .collect(),
        )
    }

    /// Proves `M · C((t − t_E)/(t_F − t_E)) ≡ P(t)` (both sides of degree ≤ 3 in `t`) on the
    /// grid `t = 0, 1, 2, 3`.
    ///
    /// # Errors
    /// A counterexample `t` (with the coordinate index as `identity`) when the map is wrong.
    ///
    /// # Example
    /// ```
    /// # use casteljau::{BezierCurve, num::parse_points, proof::Reading};
    /// # use casteljau::classify::{classify, CanonicalMap, MovingLines, canonical_map, Tower};
    /// let c = BezierCurve::new(parse_points("0 0, 1 1, 0 1, 1 0", 2, None).unwrap()).unwrap();
    /// let (k, ml) = (classify(&c).unwrap(), MovingLines::new(&c).unwrap());
    /// let map = canonical_map(&c, &k, &ml, Reading::Corrected).unwrap();
    /// assert!(map.prove(&c).is_ok());
    /// ```
    pub fn prove(&self, curve: &BezierCurve<BigRational>) -> std::result::Result<Certificate, Counterexample<Tower>> {
        let lifted = lift_curve(curve);
        let te = lift(&self.t_e);
        let scale = self.t_f.clone() - &te;
        let grid = GridProver::<Tower>::new(&[3]).expect("small grid");
        grid.check_all(|v| {
            let s = (v[0].clone() - &te) / &scale;
            self.apply(&canonical_point(self.node, &s)).sub(&lifted.eval(&v[0])).coords
        })
    }
}

/// The examples of the crate-internal items above, run as unit tests.
#[cfg(test)]
mod doc_examples {
    use super::*;
    #[test]
    fn sqrt3_field_example() {
        use crate::{Scalar, rat};
        let s3 = Sqrt3Field::sqrt(rat(3));
        assert_eq!(s3.clone() * s3, Sqrt3Field::from_i64(3));
    }

    #[test]
    fn tower_sqrt_example() {
        use crate::{Scalar, classify::Tower, rat};
        assert_eq!(tower_sqrt(&rat(4)), Tower::from_i64(2));
        assert_eq!(tower_sqrt(&rat(12)) * tower_sqrt(&rat(12)), Tower::from_i64(12));
    }

    #[test]
    fn canonical_point_example() {
        use crate::{
            Scalar,
            classify::{NodeType, Tower},
        };
        // the canonical cusp x³ − 3y² = 0 at s = 1
        let p = canonical_point(NodeType::Cusp, &Tower::from_i64(1));
        let (x, y) = (p.coords[0].clone(), p.coords[1].clone());
        assert!((x.clone() * x.clone() * x - Tower::from_i64(3) * y.clone() * y).is_zero());
    }
}
