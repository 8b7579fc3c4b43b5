//! Fast exact classification of cubics: a certified `f64` filter, fixed-width integers, BigInt.
//!
//! Every decision of [`classify`](crate::classify::classify) for a cubic is the sign of a small
//! polynomial in the control points. With `A = a2×a3`, `B = a1×a3`, `C = a1×a2`,
//! `δ = 4AC − 3B²` (so `d = δ/(4A²)`), `t_E = −B/(2A)`:
//!
//! * node type: `A = 0` explicit; else `sign δ` (> 0 crunode, = 0 cusp, < 0 acnode);
//! * a root `c ± √r` lies in `[0, 1]` iff `c ± √r ≥ 0` and `(1 − c) ∓ √r ≥ 0`, and
//!   `c + √r ≥ 0 ⟺ c ≥ 0 ∨ c² − r ≤ 0`, `c − √r ≥ 0 ⟺ c ≥ 0 ∧ c² − r ≥ 0`;
//! * for the double points `r = d`: `sign(c) = −sign(A)sign(B)`, `sign(c² − d) = sign(B² − AC)`,
//!   `sign(1 − c) = sign(A)sign(2A + B)`, `sign((1 − c)² − d) = sign(A² + AB + B² − AC)`;
//! * for the inflections `r = −d/3`: `sign(c² − r) = sign(A)sign(C)`,
//!   `sign((1 − c)² − r) = sign(A)sign(3A + 3B + C)`.
//!
//! [`decide`] runs these tests over any [`SignRing`]: checked `i128` (exact, `None` on overflow),
//! [`Certified`] `f64` (a value with a rigorous error bound; `None` when a sign is not certain),
//! `BigInt` (always exact), or plain `f64` (the uncertified baseline). [`summarize`] chains them:
//! unchecked `i128` where the input bound rules out overflow, checked `i128`, then `BigInt` — it
//! never disagrees with the exact classification.

use crate::classify::{CurveClass, NodeType, SegmentCategory, SegmentFeatures};
use crate::curve::bezier::BezierCurve;
use crate::curve::fraction_free::IntegerCurve;
use crate::num::CheckedRing;
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{Signed, ToPrimitive, Zero};
use std::cmp::Ordering;

/// Ring arithmetic ([`CheckedRing`]) with a possibly undecided sign.
pub trait SignRing: CheckedRing {
    /// `k · a` for a small integer `k`.
    fn scale(&self, k: i64) -> Option<Self>;
    /// The sign, or `None` when it cannot be certified.
    fn sign(&self) -> Option<Ordering>;
}

impl SignRing for i128 {
    fn scale(&self, k: i64) -> Option<Self> {
        self.checked_mul(k as i128)
    }
    fn sign(&self) -> Option<Ordering> {
        Some(self.cmp(&0))
    }
}

impl SignRing for BigInt {
    fn scale(&self, k: i64) -> Option<Self> {
        Some(self * k)
    }
    fn sign(&self) -> Option<Ordering> {
        Some(if self.is_negative() {
            Ordering::Less
        } else if self.is_zero() {
            Ordering::Equal
        } else {
            Ordering::Greater
        })
    }
}

/// `i128` arithmetic without overflow checks, for control points with |coordinates| < 2²⁴:
/// then `|a_k| < 2²⁹`, `|A|, |B|, |C| < 2⁵⁹` and every polynomial [`decide`] evaluates
/// (at most degree 2 in `A, B, C` with coefficients ≤ 4) stays below 2¹²², so nothing wraps.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SmallInt(pub i128);

/// Largest |coordinate| (exclusive) for which [`SmallInt`] arithmetic cannot overflow.
pub const SMALL_INT_LIMIT: i64 = 1 << 24;

impl CheckedRing for SmallInt {
    fn zero() -> Self {
        SmallInt(0)
    }
    fn add(&self, o: &Self) -> Option<Self> {
        Some(SmallInt(self.0 + o.0))
    }
    fn sub(&self, o: &Self) -> Option<Self> {
        Some(SmallInt(self.0 - o.0))
    }
    fn mul(&self, o: &Self) -> Option<Self> {
        Some(SmallInt(self.0 * o.0))
    }
}

impl SignRing for SmallInt {
    fn scale(&self, k: i64) -> Option<Self> {
        Some(SmallInt(self.0 * k as i128))
    }
    fn sign(&self) -> Option<Ordering> {
        Some(self.0.cmp(&0))
    }
}

/// Plain `f64`: **not exact** — the baseline a float classifier would be. Its signs are taken
/// at face value.
impl CheckedRing for f64 {
    fn zero() -> Self {
        0.0
    }
    fn add(&self, o: &Self) -> Option<Self> {
        Some(self + o)
    }
    fn sub(&self, o: &Self) -> Option<Self> {
        Some(self - o)
    }
    fn mul(&self, o: &Self) -> Option<Self> {
        Some(self * o)
    }
}

impl SignRing for f64 {
    fn scale(&self, k: i64) -> Option<Self> {
        Some(self * k as f64)
    }
    fn sign(&self) -> Option<Ordering> {
        self.partial_cmp(&0.0)
    }
}

/// An `f64` value `v` with a bound `e` on its distance to the exact value: `|v − exact| ≤ e`.
///
/// # Invariant
/// Every operation keeps the bound rigorous: the propagated input errors plus the rounding of
/// the operation (`≤ u·|result|` with `u = 2⁻⁵³`, or 0 when the operands are exact integers
/// and the result is an integer of magnitude ≤ 2⁵³, where `f64` arithmetic is exact).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Certified {
    /// The computed value.
    pub v: f64,
    /// The error bound.
    pub e: f64,
}

const U: f64 = f64::EPSILON / 2.0;
const EXACT_LIMIT: f64 = 9_007_199_254_740_992.0; // 2^53

impl Certified {
    /// An exactly known value.
    pub fn exact(v: f64) -> Self {
        Certified { v, e: 0.0 }
    }
    fn round(v: f64, e_in: f64, exact_inputs: bool) -> Option<Self> {
        if !v.is_finite() {
            return None;
        }
        let exact = exact_inputs && v.abs() <= EXACT_LIMIT && v.fract() == 0.0;
        // The bound itself is rounded up by one more ulp-relative step.
        let e = if exact { e_in } else { (e_in + U * v.abs()) * (1.0 + 2.0 * U) + f64::MIN_POSITIVE };
        Some(Certified { v, e })
    }
    fn is_exact_int(&self) -> bool {
        self.e == 0.0 && self.v.fract() == 0.0
    }
}

impl CheckedRing for Certified {
    fn zero() -> Self {
        Certified::exact(0.0)
    }
    fn add(&self, o: &Self) -> Option<Self> {
        Certified::round(self.v + o.v, self.e + o.e, self.is_exact_int() && o.is_exact_int())
    }
    fn sub(&self, o: &Self) -> Option<Self> {
        Certified::round(self.v - o.v, self.e + o.e, self.is_exact_int() && o.is_exact_int())
    }
    fn mul(&self, o: &Self) -> Option<Self> {
        let e = self.v.abs() * o.e + o.v.abs() * self.e + self.e * o.e;
        Certified::round(self.v * o.v, e * (1.0 + 4.0 * U), self.is_exact_int() && o.is_exact_int())
    }
}

impl SignRing for Certified {
    fn scale(&self, k: i64) -> Option<Self> {
        self.mul(&Certified::exact(k as f64))
    }
    fn sign(&self) -> Option<Ordering> {
        if self.v.abs() > self.e {
            self.v.partial_cmp(&0.0)
        } else if self.e == 0.0 {
            Some(Ordering::Equal)
        } else {
            None
        }
    }
}

/// What the fast paths decide: the class and the segment features.
pub type Summary = (CurveClass, SegmentFeatures);

fn s(x: &impl SignRing) -> Option<i8> {
    x.sign().map(|o| o as i8)
}

/// `c + s√r ≥ 0` (`r ≥ 0`) from `sign(c)` and `sign(c² − r)`.
fn nonneg(sign_c: i8, sign_c2_r: i8, plus: bool) -> bool {
    if plus { sign_c >= 0 || sign_c2_r <= 0 } else { sign_c >= 0 && sign_c2_r >= 0 }
}

/// `c + s√r ∈ [0, 1]` from the signs of `c`, `c² − r`, `1 − c`, `(1 − c)² − r`.
pub(crate) fn in_unit(sc: i8, sc2: i8, s1c: i8, s1c2: i8, plus: bool) -> bool {
    nonneg(sc, sc2, plus) && nonneg(s1c, s1c2, !plus)
}

/// Decides class and segment features of the planar cubic `p` over the ring `R`; `None` when
/// `R` overflows or cannot certify a sign.
pub fn decide<R: SignRing>(p: &[[R; 2]; 4]) -> Option<Summary> {
    let sub = |a: &[R; 2], b: &[R; 2]| Some([a[0].sub(&b[0])?, a[1].sub(&b[1])?]);
    let scale = |a: &[R; 2], k: i64| Some([a[0].scale(k)?, a[1].scale(k)?]);
    let cross = |a: &[R; 2], b: &[R; 2]| a[0].mul(&b[1])?.sub(&a[1].mul(&b[0])?);
    let d10 = sub(&p[1], &p[0])?;
    let d21 = sub(&p[2], &p[1])?;
    let d32 = sub(&p[3], &p[2])?;
    let a1 = scale(&d10, 3)?;
    let a2 = scale(&sub(&d21, &d10)?, 3)?;
    let a3 = sub(&sub(&d32, &d21)?, &sub(&d21, &d10)?)?;
    let nz = |a: &[R; 2]| -> Option<bool> { Some(s(&a[0])? != 0 || s(&a[1])? != 0) };
    let real = if nz(&a3)? {
        3
    } else if nz(&a2)? {
        2
    } else if nz(&a1)? {
        1
    } else {
        0
    };
    let (ca, cb, cc) = (cross(&a2, &a3)?, cross(&a1, &a3)?, cross(&a1, &a2)?);
    let (sa, sb, sc) = (s(&ca)?, s(&cb)?, s(&cc)?);
    let collinear = sa == 0 && sb == 0 && sc == 0;
    let mut seg =
        SegmentFeatures { has_loop: false, has_cusp: false, inflections: 0, category: SegmentCategory::Point };
    let class = match (real, collinear) {
        (0, _) => CurveClass::CubicReallyPoint,
        (1, _) => CurveClass::CubicReallyLine,
        (2, true) => CurveClass::CubicReallyCollinearQuadratic,
        (2, false) => CurveClass::CubicReallyQuadratic,
        (_, true) => CurveClass::CollinearCubic,
        (_, false) if sa == 0 => {
            // explicit: inflection at −C/(3B) (B ≠ 0)
            let s_num1 = s(&cc.add(&cb.scale(3)?)?)?; // sign(C + 3B): −C/(3B) ≤ 1 ⟺ (C+3B)/B ≥ 0
            seg.inflections = usize::from(-sc * sb >= 0 && s_num1 * sb >= 0);
            CurveClass::Cubic(NodeType::Explicit)
        }
        _ => {
            let delta = ca.mul(&cc)?.scale(4)?.sub(&cb.mul(&cb)?.scale(3)?)?;
            let s1c = sa * s(&ca.scale(2)?.add(&cb)?)?; // sign(1 − t_E)
            let stc = -sa * sb; // sign(t_E)
            match s(&delta)? {
                1 => {
                    let s_c2 = s(&cb.mul(&cb)?.sub(&ca.mul(&cc)?)?)?;
                    let s_1c2 = s(&ca.mul(&ca)?.add(&ca.mul(&cb)?)?.add(&cb.mul(&cb)?)?.sub(&ca.mul(&cc)?)?)?;
                    seg.has_loop = in_unit(stc, s_c2, s1c, s_1c2, false) && in_unit(stc, s_c2, s1c, s_1c2, true);
                    CurveClass::Cubic(NodeType::Crunode)
                }
                0 => {
                    seg.has_cusp = stc >= 0 && s1c >= 0;
                    CurveClass::Cubic(NodeType::Cusp)
                }
                _ => {
                    let s_c2 = sa * sc;
                    let s_1c2 = sa * s(&ca.scale(3)?.add(&cb.scale(3)?)?.add(&cc)?)?;
                    seg.inflections =
                        [false, true].iter().filter(|&&plus| in_unit(stc, s_c2, s1c, s_1c2, plus)).count();
                    CurveClass::Cubic(NodeType::Acnode)
                }
            }
        }
    };
    if collinear && real >= 2 {
        // turning points: simple roots of β1 + 2β2 t + 3β3 t² (β: one non-zero coordinate)
        let k = if nz(&[a1[0].clone(), a2[0].clone()])? || s(&a3[0])? != 0 { 0 } else { 1 };
        let (q0, q1, q2) = (a1[k].clone(), a2[k].scale(2)?, a3[k].scale(3)?);
        let s2 = s(&q2)?;
        seg.has_cusp = if s2 == 0 {
            let s1 = s(&q1)?;
            s1 != 0 && -s(&q0)? * s1 >= 0 && s(&q0.add(&q1)?)? * s1 >= 0
        } else {
            let disc = q1.mul(&q1)?.sub(&q0.mul(&q2)?.scale(4)?)?;
            if s(&disc)? <= 0 {
                false
            } else {
                let sc_ = -s(&q1)? * s2;
                let s_c2 = s(&q0)? * s2;
                let s1c = s(&q2.scale(2)?.add(&q1)?)? * s2;
                let s_1c2 = s(&q0.add(&q1)?.add(&q2)?)? * s2;
                in_unit(sc_, s_c2, s1c, s_1c2, false) || in_unit(sc_, s_c2, s1c, s_1c2, true)
            }
        };
    }
    seg.category = match class {
        CurveClass::CubicReallyPoint => SegmentCategory::Point,
        CurveClass::CubicReallyQuadratic => SegmentCategory::Parabola,
        _ if collinear => SegmentCategory::Line,
        _ if seg.has_loop => SegmentCategory::Loop,
        _ if seg.has_cusp => SegmentCategory::Cusp,
        _ => match seg.inflections {
            0 => SegmentCategory::Arch,
            1 => SegmentCategory::SingleInflection,
            _ => SegmentCategory::DoubleInflection,
        },
    };
    Some((class, seg))
}

/// The certified `f64` filter: decides from `f64` control points (taken as exact inputs) when
/// every sign it uses is certified by the error bound; `None` otherwise.
pub fn filter_f64(p: &[[f64; 2]; 4]) -> Option<Summary> {
    decide(&p.map(|q| q.map(Certified::exact)))
}

/// Class and segment features of a planar cubic with integer control points, exactly:
/// unchecked [`SmallInt`] arithmetic when |coordinates| < 2²⁴ (font-like inputs; no overflow is
/// possible), else checked `i128`, else `BigInt`. (For integers the certified `f64` filter is
/// slower than exact `i128`; it serves inputs that are floats — see [`filter_f64`].)
pub fn summarize_integers(p: &[[i64; 2]; 4]) -> Summary {
    if p.iter().flatten().all(|v| v.abs() < SMALL_INT_LIMIT) {
        return decide(&p.map(|q| q.map(|v| SmallInt(v as i128)))).expect("SmallInt never overflows below the limit");
    }
    if let Some(s) = decide(&p.map(|q| q.map(|v| v as i128))) {
        return s;
    }
    decide(&p.map(|q| q.map(BigInt::from))).expect("BigInt decides every sign")
}

/// Class and segment features of a planar cubic, exactly, on the integer numerators over the
/// common denominator (the features are invariant under that scaling): [`summarize_integers`]
/// when they fit in `i64`, else `BigInt`.
///
/// # Panics
/// **Panics** unless `curve` is a planar cubic.
pub fn summarize(curve: &BezierCurve<BigRational>) -> Summary {
    assert!(curve.degree() == 3 && curve.dim() == 2, "summarize takes a planar cubic");
    let ic = IntegerCurve::new(curve);
    let n = &ic.numerators;
    if let Some(v) = n.iter().map(ToPrimitive::to_i64).collect::<Option<Vec<i64>>>() {
        return summarize_integers(&[0, 1, 2, 3].map(|i| [v[2 * i], v[2 * i + 1]]));
    }
    decide(&[0, 1, 2, 3].map(|i| [n[2 * i].clone(), n[2 * i + 1].clone()])).expect("BigInt decides every sign")
}

/// Class and segment features of a cubic given in `f64` (each value taken as the exact binary
/// number it is): the certified filter when it can decide, otherwise the exact rational path.
/// Never disagrees with [`classify`](crate::classify::classify) on the exact input.
///
/// # Errors
/// [`Error::InvalidArgument`](crate::Error::InvalidArgument) for a NaN or infinite coordinate.
///
/// # Example
/// ```
/// use casteljau::internal::summarize_f64;
/// use casteljau::classify::{CurveClass, NodeType};
/// let s = summarize_f64(&[[0.0, 0.0], [1.0, 1.0], [0.0, 1.0], [1.0, 0.0]]).unwrap();
/// assert_eq!(s.0, CurveClass::Cubic(NodeType::Cusp)); // exact cusp: the filter abstains, exact decides
/// ```
pub fn summarize_f64(p: &[[f64; 2]; 4]) -> crate::error::Result<Summary> {
    if let Some(s) = filter_f64(p) {
        return Ok(s);
    }
    let mut pts = Vec::with_capacity(4);
    for (i, q) in p.iter().enumerate() {
        let coords = q.iter().map(|&v| BigRational::from_float(v)).collect::<Option<Vec<_>>>().ok_or_else(|| {
            crate::error::Error::InvalidArgument { message: format!("control point {} is not finite", i + 1) }
        })?;
        pts.push(crate::num::point::Point::new(coords));
    }
    Ok(summarize(&BezierCurve::new(pts)?))
}
