//! Moving lines of a planar cubic (seed 004, after Sederberg–Saito–Qi–Klimaszewski 1994),
//! encoded as printed.
//!
//! Homogeneous points `(X, Y, W)`, lines `(a, b, c)`; `P·L = 0` means the point is on the line,
//! `P0 × P1` is the line through two points and `L0 × L1` the meet of two lines. With
//! `Q0 = P0`, `Q1 = 3P1`, `Q2 = 3P2`, `Q3 = P3` (each `(x, y, 1)`) the curve is
//! `P[t] = (1−t)³Q0 + (1−t)²t Q1 + (1−t)t² Q2 + t³ Q3`, and with `V_ijk = Q_i·(Q_j × Q_k)`:
//!
//! * (3) `L0[t] = (1−t)L00 + t L01`, `L00 = V023(Q0×Q2) − V013(Q0×Q3 + Q1×Q2) + V012(Q1×Q3)`,
//!   `L01 = V023(Q0×Q3) − V013(Q1×Q3) + V012(Q2×Q3)`;
//! * (4) the double point `D = L00 × L01`;
//! * (5) `L1[t] = (1−t)²L10 + 2(1−t)t L11 + t² L12` with `L10 = −Q0×Q1 + Q0×Q2 − Q0×Q3`,
//!   `L11 = ½(−Q0×Q2 + Q0×Q3 + Q1×Q2 − Q1×Q3)`, `L12 = −Q0×Q3 + Q1×Q3 − Q2×Q3`;
//! * (7) `t_E = (c10 − c11)/(c10 − 2c11 + c12)`; (8) `E = L0[t_E] × L1[t_E]`;
//! * `f(t) = L1[t]·D`, whose discriminant `Δ` decides the node type (§3.3).
//!
//! [`MovingLines::verify`] proves `P[t]·L0[t] ≡ 0` (degree ≤ 4) and `P[t]·L1[t] ≡ 0`
//! (degree ≤ 5) with the grid prover.

use crate::curve::bezier::BezierCurve;
use crate::error::{Error, Result};
use crate::num::point::Point;
use crate::num::scalar::{Scalar, rat};
use crate::proof::{self, Certificate, Counterexample};
use num_rational::BigRational;

type P3 = Point<BigRational>;

/// The moving lines of a planar cubic and the points they define.
///
/// # Example
/// ```
/// # use casteljau::{BezierCurve, num::parse_points, classify::MovingLines, ratio};
/// // the cusp P0..P3 = (0,0) (1,1) (0,1) (1,0): cusp at t = 1/2, D = (1/2, 3/4)
/// let c = BezierCurve::new(parse_points("0 0, 1 1, 0 1, 1 0", 2, None).unwrap()).unwrap();
/// let ml = MovingLines::new(&c).unwrap();
/// assert_eq!(ml.double_point.from_homogeneous().unwrap().to_string(), "(1/2, 3/4)");
/// assert!(ml.verify().is_ok());
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct MovingLines {
    /// `Q0, Q1, Q2, Q3` (homogeneous, binomials absorbed).
    pub q: [P3; 4],
    /// `L00`, `L01` of (3).
    pub l0: [P3; 2],
    /// `L10`, `L11`, `L12` of (5).
    pub l1: [P3; 3],
    /// `D = L00 × L01` (4), homogeneous; `w = 0` means the double point is at infinity.
    pub double_point: P3,
}

fn hom(p: &Point<BigRational>, scale: i64) -> P3 {
    p.to_homogeneous(&rat(1)).scale(&rat(scale))
}
fn x(a: &P3, b: &P3) -> P3 {
    a.cross(b).expect("3-vectors")
}

impl MovingLines {
    /// The moving lines of a cubic, as printed in seed 004.
    ///
    /// # Errors
    /// [`Error::NotApplicable`] unless the curve is a planar cubic.
    ///
    /// # Example
    /// ```
    /// # use casteljau::{BezierCurve, num::parse_points, classify::MovingLines, ratio};
    /// // the cusp P0..P3 = (0,0) (1,1) (0,1) (1,0): cusp at t = 1/2, D = (1/2, 3/4)
    /// let c = BezierCurve::new(parse_points("0 0, 1 1, 0 1, 1 0", 2, None).unwrap()).unwrap();
    /// let ml = MovingLines::new(&c).unwrap();
    /// assert!(MovingLines::new(&BezierCurve::new(parse_points("0 0, 1 1, 2 0", 2, None).unwrap()).unwrap()).is_err());
    /// ```
    pub fn new(curve: &BezierCurve<BigRational>) -> Result<Self> {
        if curve.degree() != 3 || curve.dim() != 2 {
            return Err(Error::NotApplicable { message: "moving lines need a planar cubic".into() });
        }
        let p = curve.points();
        Ok(Self::from_homogeneous([hom(&p[0], 1), hom(&p[1], 3), hom(&p[2], 3), hom(&p[3], 1)]))
    }

    /// The moving lines from homogeneous `Q0..Q3` directly (`Q_i = C(3,i)·w_i·(x_i, y_i, 1)` for
    /// a rational cubic; the construction (3)–(5) is projective).
    ///
    /// # Example
    /// ```
    /// # use casteljau::{BezierCurve, num::parse_points, classify::MovingLines, ratio};
    /// // the cusp P0..P3 = (0,0) (1,1) (0,1) (1,0): cusp at t = 1/2, D = (1/2, 3/4)
    /// let c = BezierCurve::new(parse_points("0 0, 1 1, 0 1, 1 0", 2, None).unwrap()).unwrap();
    /// let ml = MovingLines::new(&c).unwrap();
    /// assert_eq!(MovingLines::from_homogeneous(ml.q.clone()), ml);
    /// ```
    pub fn from_homogeneous(q: [P3; 4]) -> Self {
        let v = |i: usize, j: usize, k: usize| q[i].dot(&x(&q[j], &q[k]));
        let (v023, v013, v012) = (v(0, 2, 3), v(0, 1, 3), v(0, 1, 2));
        let l00 = x(&q[0], &q[2])
            .scale(&v023)
            .sub(&x(&q[0], &q[3]).add(&x(&q[1], &q[2])).scale(&v013))
            .add(&x(&q[1], &q[3]).scale(&v012));
        let l01 = x(&q[0], &q[3]).scale(&v023).sub(&x(&q[1], &q[3]).scale(&v013)).add(&x(&q[2], &q[3]).scale(&v012));
        let l10 = x(&q[0], &q[2]).sub(&x(&q[0], &q[1])).sub(&x(&q[0], &q[3]));
        let l11 = x(&q[0], &q[3])
            .sub(&x(&q[0], &q[2]))
            .add(&x(&q[1], &q[2]))
            .sub(&x(&q[1], &q[3]))
            .scale(&BigRational::new(1.into(), 2.into()));
        let l12 = x(&q[1], &q[3]).sub(&x(&q[0], &q[3])).sub(&x(&q[2], &q[3]));
        let double_point = x(&l00, &l01);
        MovingLines { q, l0: [l00, l01], l1: [l10, l11, l12], double_point }
    }

    /// `P[t]` in homogeneous coordinates.
    ///
    /// # Example
    /// ```
    /// # use casteljau::{BezierCurve, num::parse_points, classify::MovingLines, ratio};
    /// // the cusp P0..P3 = (0,0) (1,1) (0,1) (1,0): cusp at t = 1/2, D = (1/2, 3/4)
    /// let c = BezierCurve::new(parse_points("0 0, 1 1, 0 1, 1 0", 2, None).unwrap()).unwrap();
    /// let ml = MovingLines::new(&c).unwrap();
    /// assert_eq!(ml.point(&ratio(1, 2)).from_homogeneous().unwrap(), c.eval(&ratio(1, 2)));
    /// ```
    pub fn point(&self, t: &BigRational) -> P3 {
        let u = rat(1) - t;
        let b = [u.clone() * &u * &u, u.clone() * &u * t, u.clone() * t * t, t.clone() * t * t];
        self.q.iter().zip(&b).fold(Point::origin(3), |acc, (q, w)| acc.add(&q.scale(w)))
    }
    /// `L0[t] = (1−t)L00 + tL01`.
    ///
    /// # Example
    /// ```
    /// # use casteljau::{BezierCurve, num::parse_points, classify::MovingLines, ratio};
    /// // the cusp P0..P3 = (0,0) (1,1) (0,1) (1,0): cusp at t = 1/2, D = (1/2, 3/4)
    /// let c = BezierCurve::new(parse_points("0 0, 1 1, 0 1, 1 0", 2, None).unwrap()).unwrap();
    /// let ml = MovingLines::new(&c).unwrap();
    /// let t = ratio(1, 3);
    /// assert_eq!(ml.l0_at(&t).dot(&ml.point(&t)), ratio(0, 1)); // P[t]·L0[t] = 0
    /// ```
    pub fn l0_at(&self, t: &BigRational) -> P3 {
        self.l0[0].lerp(&self.l0[1], t)
    }
    /// `L1[t] = (1−t)²L10 + 2(1−t)t L11 + t²L12`.
    ///
    /// # Example
    /// ```
    /// # use casteljau::{BezierCurve, num::parse_points, classify::MovingLines, ratio};
    /// // the cusp P0..P3 = (0,0) (1,1) (0,1) (1,0): cusp at t = 1/2, D = (1/2, 3/4)
    /// let c = BezierCurve::new(parse_points("0 0, 1 1, 0 1, 1 0", 2, None).unwrap()).unwrap();
    /// let ml = MovingLines::new(&c).unwrap();
    /// let t = ratio(2, 7);
    /// assert_eq!(ml.l1_at(&t).dot(&ml.point(&t)), ratio(0, 1)); // P[t]·L1[t] = 0
    /// ```
    pub fn l1_at(&self, t: &BigRational) -> P3 {
        let u = rat(1) - t;
        self.l1[0]
            .scale(&(u.clone() * &u))
            .add(&self.l1[1].scale(&(rat(2) * &u * t)))
            .add(&self.l1[2].scale(&(t.clone() * t)))
    }
    /// `t_E` of (7), `None` when its denominator vanishes.
    ///
    /// # Example
    /// ```
    /// # use casteljau::{BezierCurve, num::parse_points, classify::MovingLines, ratio};
    /// // the cusp P0..P3 = (0,0) (1,1) (0,1) (1,0): cusp at t = 1/2, D = (1/2, 3/4)
    /// let c = BezierCurve::new(parse_points("0 0, 1 1, 0 1, 1 0", 2, None).unwrap()).unwrap();
    /// let ml = MovingLines::new(&c).unwrap();
    /// assert_eq!(ml.t_e(), Some(ratio(1, 2)));
    /// ```
    pub fn t_e(&self) -> Option<BigRational> {
        let c = |l: &P3| l.coords[2].clone();
        let den = c(&self.l1[0]) - rat(2) * c(&self.l1[1]) + c(&self.l1[2]);
        (!Scalar::is_zero(&den)).then(|| (c(&self.l1[0]) - c(&self.l1[1])) / den)
    }
    /// `E = L0[t_E] × L1[t_E]` of (8), homogeneous.
    ///
    /// # Example
    /// ```
    /// # use casteljau::{BezierCurve, num::parse_points, classify::MovingLines, ratio};
    /// // the cusp P0..P3 = (0,0) (1,1) (0,1) (1,0): cusp at t = 1/2, D = (1/2, 3/4)
    /// let c = BezierCurve::new(parse_points("0 0, 1 1, 0 1, 1 0", 2, None).unwrap()).unwrap();
    /// let ml = MovingLines::new(&c).unwrap();
    /// assert_eq!(ml.e_point().unwrap().from_homogeneous(), Some(c.eval(&ratio(1, 2))));
    /// ```
    pub fn e_point(&self) -> Option<P3> {
        let t = self.t_e()?;
        Some(x(&self.l0_at(&t), &self.l1_at(&t)))
    }
    /// `f(t) = L1[t]·D` as power coefficients `[f0, f1, f2]`, and its discriminant `f1² − 4f0f2`.
    ///
    /// # Example
    /// ```
    /// # use casteljau::{BezierCurve, num::parse_points, classify::MovingLines, ratio};
    /// // the cusp P0..P3 = (0,0) (1,1) (0,1) (1,0): cusp at t = 1/2, D = (1/2, 3/4)
    /// let c = BezierCurve::new(parse_points("0 0, 1 1, 0 1, 1 0", 2, None).unwrap()).unwrap();
    /// let ml = MovingLines::new(&c).unwrap();
    /// let (_, disc) = ml.f_and_discriminant();
    /// assert_eq!(disc, ratio(0, 1)); // a cusp: the discriminant vanishes
    /// ```
    pub fn f_and_discriminant(&self) -> ([BigRational; 3], BigRational) {
        let d = &self.double_point;
        let (c0, c1, c2) = (self.l1[0].dot(d), self.l1[1].dot(d), self.l1[2].dot(d));
        // (1−t)²c0 + 2(1−t)t c1 + t² c2 = c0 + 2(c1 − c0)t + (c0 − 2c1 + c2)t²
        let f = [c0.clone(), rat(2) * (c1.clone() - &c0), c0 - rat(2) * c1 + c2];
        let disc = f[1].clone() * &f[1] - rat(4) * &f[0] * &f[2];
        (f, disc)
    }

    /// Proves `P[t]·L0[t] ≡ 0` and `P[t]·L1[t] ≡ 0` (degrees ≤ 4 and ≤ 5 in `t`).
    ///
    /// # Errors
    /// The exact parameter where one of them fails.
    ///
    /// # Example
    /// ```
    /// # use casteljau::{BezierCurve, num::parse_points, classify::MovingLines, ratio};
    /// // the cusp P0..P3 = (0,0) (1,1) (0,1) (1,0): cusp at t = 1/2, D = (1/2, 3/4)
    /// let c = BezierCurve::new(parse_points("0 0, 1 1, 0 1, 1 0", 2, None).unwrap()).unwrap();
    /// let ml = MovingLines::new(&c).unwrap();
    /// let cert = ml.verify().unwrap();
    /// assert!(cert.points_checked > 0);
    /// ```
    pub fn verify(&self) -> std::result::Result<Certificate, Counterexample<BigRational>> {
        proof::identities::<BigRational>(&[5], |v| {
            let t = &v[0];
            let p = self.point(t);
            vec![p.dot(&self.l0_at(t)), p.dot(&self.l1_at(t))]
        })
    }
}
