//! proptest strategies for users' tests (feature `proptest`): exact rationals, random curves, and
//! the edge cases float classifiers get wrong, each constructed so its answer is known exactly.
//!
//! Every edge-case curve is a random invertible affine image (small integer matrix, integer
//! offset) of a canonical curve reparametrised so the feature sits exactly where promised; the
//! control points are exact rationals (use [`crate::num::ratio_to_f64`] to feed float code).
//!
//! ```
//! use casteljau::{classify::classify, strategies};
//! use proptest::prelude::*;
//! proptest!(|(c in strategies::cusp_at(strategies::unit_parameter()))| {
//!     let (curve, tau) = c;
//!     let k = classify(&curve).unwrap();
//!     prop_assert_eq!(k.node_type, Some(casteljau::classify::NodeType::Cusp));
//!     prop_assert!(k.segment.has_cusp, "cusp at t = {} in [0, 1]", tau);
//! });
//! ```

use crate::curve::bezier::BezierCurve;
use crate::num::point::Point;
use crate::num::scalar::{rat, ratio};
use num_bigint::BigInt;
use num_rational::BigRational;
use proptest::prelude::*;

/// Small exact rationals `p/q`, `|p| ≤ 200`, `1 ≤ q ≤ 60`.
pub fn small_rational() -> impl Strategy<Value = BigRational> {
    (-200i64..=200, 1i64..=60).prop_map(|(p, q)| ratio(p, q))
}

/// Parameters in `[0, 1]`, with the endpoints `0` and `1` drawn often.
pub fn unit_parameter() -> impl Strategy<Value = BigRational> {
    prop_oneof![Just(rat(0)), Just(rat(1)), (0i64..=97, 1i64..=97).prop_map(|(p, q)| ratio(p.min(q), q))]
}

/// Planar cubics with small rational control points.
pub fn cubic() -> impl Strategy<Value = BezierCurve<BigRational>> {
    prop::collection::vec((small_rational(), small_rational()), 4)
        .prop_map(|v| BezierCurve::new(v.into_iter().map(|(x, y)| Point::new(vec![x, y])).collect()).unwrap())
}

/// An invertible integer matrix `[m00, m01, m10, m11]` and an integer offset.
fn affine() -> impl Strategy<Value = ([i64; 4], [i64; 2])> {
    (prop::array::uniform4(-4i64..=4), prop::array::uniform2(-50i64..=50))
        .prop_filter("invertible", |(m, _)| m[0] * m[3] - m[1] * m[2] != 0)
}

/// The cubic with power form `(Σ x_k t^k, Σ y_k t^k)` mapped by `v ↦ M v + o`.
pub fn cubic_from_power(
    x: [BigRational; 4],
    y: [BigRational; 4],
    m: [i64; 4],
    o: [i64; 2],
) -> BezierCurve<BigRational> {
    let coeffs: Vec<Point<BigRational>> = (0..4)
        .map(|k| {
            let (u, v) = (&x[k], &y[k]);
            let (ox, oy) = if k == 0 { (rat(o[0]), rat(o[1])) } else { (rat(0), rat(0)) };
            Point::new(vec![rat(m[0]) * u + rat(m[1]) * v + ox, rat(m[2]) * u + rat(m[3]) * v + oy])
        })
        .collect();
    BezierCurve::from_power(&coeffs).expect("four coefficients")
}

/// Power coefficients of `(α t + β)^k`, `k = 0..=3`, as polynomials in `t`.
fn linear_powers(alpha: &BigRational, beta: &BigRational) -> [[BigRational; 4]; 4] {
    let (a, b) = (alpha.clone(), beta.clone());
    [
        [rat(1), rat(0), rat(0), rat(0)],
        [b.clone(), a.clone(), rat(0), rat(0)],
        [b.clone() * &b, rat(2) * &a * &b, a.clone() * &a, rat(0)],
        [b.clone() * &b * &b, rat(3) * &a * &b * &b, rat(3) * &a * &a * &b, a.clone() * &a * &a],
    ]
}

/// `Σ c_k s^k` with `s = α t + β`, as power coefficients in `t`.
fn compose(c: [BigRational; 4], alpha: &BigRational, beta: &BigRational) -> [BigRational; 4] {
    let p = linear_powers(alpha, beta);
    let mut out = [rat(0), rat(0), rat(0), rat(0)];
    for (k, ck) in c.iter().enumerate() {
        for j in 0..4 {
            out[j] = out[j].clone() + ck.clone() * &p[k][j];
        }
    }
    out
}

/// A cusp exactly at `t = τ` (τ from `tau`): an affine image of `(s², s³)`, `s = t − τ`.
/// Yields the curve and `τ`.
pub fn cusp_at(
    tau: impl Strategy<Value = BigRational>,
) -> impl Strategy<Value = (BezierCurve<BigRational>, BigRational)> {
    (tau, affine()).prop_map(|(tau, (m, o))| {
        let (one, mt) = (rat(1), -tau.clone());
        let x = compose([rat(0), rat(0), rat(1), rat(0)], &one, &mt);
        let y = compose([rat(0), rat(0), rat(0), rat(1)], &one, &mt);
        (cubic_from_power(x, y, m, o), tau)
    })
}

/// A loop whose double point is reached exactly at `t = t0` and `t = t1` (`t0 < t1`, drawn from
/// `{0, 1}` and `[0, 2]`, so boundary cases are frequent): an affine image of the crunode
/// `(s² − 1, s³ − s)` with `s = −1` at `t0` and `s = 1` at `t1`. Yields the curve and `(t0, t1)`.
pub fn loop_between() -> impl Strategy<Value = (BezierCurve<BigRational>, (BigRational, BigRational))> {
    let end = prop_oneof![Just(rat(0)), Just(rat(1)), (0i64..=40).prop_map(|p| ratio(p, 20))];
    (end.clone(), end, affine()).prop_filter_map("distinct parameters", |(a, b, (m, o))| {
        let (t0, t1) = if a < b {
            (a, b)
        } else if b < a {
            (b, a)
        } else {
            return None;
        };
        // s = α t + β with s(t0) = −1, s(t1) = 1
        let alpha = rat(2) / (t1.clone() - &t0);
        let beta = rat(-1) - alpha.clone() * &t0;
        let x = compose([rat(-1), rat(0), rat(1), rat(0)], &alpha, &beta);
        let y = compose([rat(0), rat(-1), rat(0), rat(1)], &alpha, &beta);
        Some((cubic_from_power(x, y, m, o), (t0, t1)))
    })
}

/// An inflection exactly at an endpoint: an affine image of `(s, s³)` (explicit cubic) with the
/// inflection `s = 0` at `t = 0` or `t = 1`. Yields the curve and the endpoint.
pub fn inflection_at_endpoint() -> impl Strategy<Value = (BezierCurve<BigRational>, BigRational)> {
    (prop_oneof![Just(rat(0)), Just(rat(1))], 1i64..=5, affine()).prop_map(|(at, scale, (m, o))| {
        let alpha = rat(scale);
        let beta = -alpha.clone() * &at;
        let x = compose([rat(0), rat(1), rat(0), rat(0)], &alpha, &beta);
        let y = compose([rat(0), rat(0), rat(0), rat(1)], &alpha, &beta);
        (cubic_from_power(x, y, m, o), at)
    })
}

/// A quadratic with thirds in its coordinates, written as a cubic (degree-elevated): the class
/// is `cubic_really_quadratic` (or collinear if the quadratic was).
pub fn degree_elevated_quadratic() -> impl Strategy<Value = BezierCurve<BigRational>> {
    prop::collection::vec((-30i64..=30, -30i64..=30), 3).prop_map(|v| {
        let q = v.into_iter().map(|(x, y)| Point::new(vec![ratio(x, 3), ratio(y, 3)])).collect();
        BezierCurve::new(q).unwrap().elevate(1).unwrap()
    })
}

/// A cubic whose four control points lie on one line (random positions along it).
pub fn collinear_cubic() -> impl Strategy<Value = BezierCurve<BigRational>> {
    collinear_from(small_rational)
}

/// Four points `c + s_i·d` on the line through `(c, 0)` with a small integer direction `d`, the
/// numbers `s_i` and `c` drawn from `numbers`.
fn collinear_from<S: Strategy<Value = BigRational>>(
    numbers: impl Fn() -> S,
) -> impl Strategy<Value = BezierCurve<BigRational>> {
    (prop::collection::vec(numbers(), 4), (-5i64..=5, -5i64..=5), numbers()).prop_map(|(s, (dx, dy), c)| {
        let d = if dx == 0 && dy == 0 { (1, 0) } else { (dx, dy) };
        let pts = s.into_iter().map(|s| Point::new(vec![s.clone() * rat(d.0) + &c, s * rat(d.1)])).collect();
        BezierCurve::new(pts).unwrap()
    })
}

/// A cubic with two coincident control points (P0 = P1, P1 = P2 or P2 = P3).
pub fn coincident_control_points() -> impl Strategy<Value = BezierCurve<BigRational>> {
    coincident_from(cubic())
}

/// A cubic from `cubics` with one control point copied onto the next.
fn coincident_from(
    cubics: impl Strategy<Value = BezierCurve<BigRational>>,
) -> impl Strategy<Value = BezierCurve<BigRational>> {
    (cubics, 0usize..3).prop_map(|(c, i)| {
        let mut pts = c.into_points();
        pts[i + 1] = pts[i].clone();
        BezierCurve::new(pts).unwrap()
    })
}

/// A near-cusp: the exact cusp `(0,0) (1,1) (0,1) (1,0)` (cusp at t = 1/2) with `P1.y` moved by
/// `±10^-k`, `k` from `exponents`. Exactly a crunode or an acnode, never a cusp.
pub fn near_cusp(exponents: std::ops::RangeInclusive<u32>) -> impl Strategy<Value = (BezierCurve<BigRational>, u32)> {
    near_cusp_in_base(exponents, 10)
}

/// The cusp `(0,0) (1,1) (0,1) (1,0)` with `P1.y` moved by `±base^-k`.
fn near_cusp_in_base(
    exponents: std::ops::RangeInclusive<u32>,
    base: u32,
) -> impl Strategy<Value = (BezierCurve<BigRational>, u32)> {
    (exponents, prop_oneof![Just(1i64), Just(-1i64)]).prop_map(move |(k, sign)| {
        let eps = BigRational::new(BigInt::from(sign), BigInt::from(base).pow(k));
        let pts = [(0, 0), (1, 1), (0, 1), (1, 0)]
            .iter()
            .enumerate()
            .map(|(i, &(x, y))| Point::new(vec![rat(x), if i == 1 { rat(y) + &eps } else { rat(y) }]))
            .collect();
        (BezierCurve::new(pts).unwrap(), k)
    })
}

/// The same hard cases with control points that are **exact binary64 values**, so float code
/// sees exactly the curve casteljau decides: parameters are dyadic (`k/2^m`), the affine maps have
/// integer entries times 3 (which clears the thirds of the Bézier ↔ power conversion), and every
/// coordinate is checked to be an `f64` exactly ([`binary64::points`] gives them).
///
/// ```
/// use casteljau::{classify::{classify, NodeType}, strategies::binary64};
/// use proptest::prelude::*;
/// proptest!(|((curve, tau) in binary64::cusp_at(binary64::unit_parameter()))| {
///     let pts: Vec<[f64; 2]> = binary64::points(&curve); // exact: no rounding happened
///     prop_assert_eq!(classify(&curve).unwrap().node_type, Some(NodeType::Cusp));
///     prop_assert_eq!(pts.len(), 4);
///     let _ = tau;
/// });
/// ```
pub mod binary64 {
    use super::compose;
    use crate::curve::bezier::BezierCurve;
    use crate::num::point::Point;
    use crate::num::scalar::{rat, ratio};
    use num_rational::BigRational;
    use proptest::prelude::*;

    /// `x` is an `f64` exactly.
    pub fn is_binary64(x: &BigRational) -> bool {
        let f = crate::num::scalar::ratio_to_f64(x);
        f.is_finite() && BigRational::from_float(f).as_ref() == Some(x)
    }

    /// The control points as `f64`s.
    ///
    /// # Panics
    /// **Panics when a coordinate is not exactly an `f64`** (never for this module's curves).
    pub fn points(c: &BezierCurve<BigRational>) -> Vec<[f64; 2]> {
        c.points()
            .iter()
            .map(|p| {
                let f = |x: &BigRational| {
                    assert!(is_binary64(x), "{x} is not a binary64 value");
                    crate::num::scalar::ratio_to_f64(x)
                };
                [f(&p.coords[0]), f(&p.coords[1])]
            })
            .collect()
    }

    fn exact_curve(c: BezierCurve<BigRational>) -> Option<BezierCurve<BigRational>> {
        c.points().iter().all(|p| p.coords.iter().all(is_binary64)).then_some(c)
    }

    /// Dyadic parameters in `[0, 1]`, endpoints and `1/2` often.
    pub fn unit_parameter() -> impl Strategy<Value = BigRational> {
        prop_oneof![
            Just(rat(0)),
            Just(rat(1)),
            Just(ratio(1, 2)),
            (0u32..=8).prop_flat_map(|m| (0i64..=(1 << m)).prop_map(move |k| ratio(k, 1 << m)))
        ]
    }

    /// Dyadic parameters outside `[0, 1]`.
    pub fn outside_parameter() -> impl Strategy<Value = BigRational> {
        prop_oneof![(1i64..=64).prop_map(|k| ratio(-k, 16)), (17i64..=80).prop_map(|k| ratio(k, 16))]
    }

    /// An invertible integer matrix times 3 and an integer offset.
    fn affine3() -> impl Strategy<Value = ([i64; 4], [i64; 2])> {
        (prop::array::uniform4(-4i64..=4), prop::array::uniform2(-50i64..=50))
            .prop_filter("invertible", |(m, _)| m[0] * m[3] - m[1] * m[2] != 0)
            .prop_map(|(m, o)| (m.map(|x| 3 * x), o))
    }

    /// A cusp exactly at the dyadic `t = τ`: an affine image of `(s², s³)`, `s = t − τ`.
    pub fn cusp_at(
        tau: impl Strategy<Value = BigRational>,
    ) -> impl Strategy<Value = (BezierCurve<BigRational>, BigRational)> {
        (tau, affine3()).prop_filter_map("binary64", |(tau, (m, o))| {
            let (one, mt) = (rat(1), -tau.clone());
            let x = compose([rat(0), rat(0), rat(1), rat(0)], &one, &mt);
            let y = compose([rat(0), rat(0), rat(0), rat(1)], &one, &mt);
            exact_curve(super::cubic_from_power(x, y, m, o)).map(|c| (c, tau))
        })
    }

    /// A loop whose double point is reached exactly at `t0` and `t1 = t0 + 2^-j` (`t0 = 0` and
    /// `t1 = 1` frequent): an affine image of `(s² − 1, s³ − s)`, `s = −1` at `t0`, `1` at `t1`.
    pub fn loop_between() -> impl Strategy<Value = (BezierCurve<BigRational>, (BigRational, BigRational))> {
        let start = |j: u32| {
            let width = ratio(1, 1 << j);
            prop_oneof![Just(rat(0)), Just(rat(1) - width.clone()), (-16i64..=16).prop_map(|k| ratio(k, 16)),]
                .prop_map(move |t0| (t0.clone(), t0 + width.clone()))
        };
        ((0u32..=3).prop_flat_map(start), affine3()).prop_filter_map("binary64", |((t0, t1), (m, o))| {
            let alpha = rat(2) / (t1.clone() - &t0);
            let beta = rat(-1) - alpha.clone() * &t0;
            let x = compose([rat(-1), rat(0), rat(1), rat(0)], &alpha, &beta);
            let y = compose([rat(0), rat(-1), rat(0), rat(1)], &alpha, &beta);
            exact_curve(super::cubic_from_power(x, y, m, o)).map(|c| (c, (t0, t1)))
        })
    }

    /// An inflection exactly at `t = 0` or `t = 1`: an affine image of `(s, s³)`.
    pub fn inflection_at_endpoint() -> impl Strategy<Value = (BezierCurve<BigRational>, BigRational)> {
        (prop_oneof![Just(rat(0)), Just(rat(1))], 1i64..=5, affine3()).prop_filter_map("binary64", |(at, k, (m, o))| {
            let alpha = rat(k);
            let beta = -alpha.clone() * &at;
            let x = compose([rat(0), rat(1), rat(0), rat(0)], &alpha, &beta);
            let y = compose([rat(0), rat(0), rat(0), rat(1)], &alpha, &beta);
            exact_curve(super::cubic_from_power(x, y, m, o)).map(|c| (c, at))
        })
    }

    /// A quadratic with integer points (multiples of 3) written as a cubic: integer control points.
    pub fn degree_elevated_quadratic() -> impl Strategy<Value = BezierCurve<BigRational>> {
        prop::collection::vec((-30i64..=30, -30i64..=30), 3).prop_map(|v| {
            let q = v.into_iter().map(|(x, y)| Point::new(vec![rat(3 * x), rat(3 * y)])).collect();
            BezierCurve::new(q).unwrap().elevate(1).unwrap()
        })
    }

    /// Small dyadic numbers `k/2^m`, `|k| ≤ 1024`, `m ≤ 10`.
    pub fn dyadic() -> impl Strategy<Value = BigRational> {
        (-1024i64..=1024, 0u32..=10).prop_map(|(k, m)| ratio(k, 1 << m))
    }

    /// Cubics with dyadic control points.
    pub fn cubic() -> impl Strategy<Value = BezierCurve<BigRational>> {
        prop::collection::vec((dyadic(), dyadic()), 4)
            .prop_map(|v| BezierCurve::new(v.into_iter().map(|(x, y)| Point::new(vec![x, y])).collect()).unwrap())
    }

    /// Four dyadic control points on one line.
    pub fn collinear_cubic() -> impl Strategy<Value = BezierCurve<BigRational>> {
        super::collinear_from(dyadic)
    }

    /// A dyadic cubic with two coincident control points.
    pub fn coincident_control_points() -> impl Strategy<Value = BezierCurve<BigRational>> {
        super::coincident_from(cubic())
    }

    /// A near-cusp: the cusp `(0,0) (1,1) (0,1) (1,0)` with `P1.y` moved by `±2^-k`; exactly a
    /// crunode or an acnode, never a cusp. `1 ± 2^-k` is an `f64` for `k ≤ 52` (`1 − 2^-53` too);
    /// larger `k` are not drawn.
    pub fn near_cusp(
        exponents: std::ops::RangeInclusive<u32>,
    ) -> impl Strategy<Value = (BezierCurve<BigRational>, u32)> {
        let (lo, hi) = (*exponents.start().min(&52), (*exponents.end()).min(52));
        super::near_cusp_in_base(lo..=hi.max(lo), 2)
    }
}

/// Hard intersection cases with exact binary64 control points (see [`binary64`]): each strategy
/// yields the two curves (and what is promised), for float intersection code checked with
/// [`crate::oracle::check_intersections`].
pub mod intersections {
    use super::binary64::{cubic, is_binary64, unit_parameter};
    use crate::curve::bezier::BezierCurve;
    use crate::num::point::Point;
    use crate::num::scalar::{rat, ratio};
    use num_rational::BigRational;
    use proptest::prelude::*;

    type Curve = BezierCurve<BigRational>;

    fn exact(c: Curve) -> Option<Curve> {
        c.points().iter().all(|p| p.coords.iter().all(is_binary64)).then_some(c)
    }

    /// An invertible integer matrix and offset, applied to points.
    fn affine() -> impl Strategy<Value = ([i64; 4], [i64; 2])> {
        (prop::array::uniform4(-4i64..=4), prop::array::uniform2(-40i64..=40))
            .prop_filter("invertible", |(m, _)| m[0] * m[3] - m[1] * m[2] != 0)
    }

    fn map(c: &Curve, m: [i64; 4], o: [i64; 2]) -> Curve {
        let pts = c
            .points()
            .iter()
            .map(|p| {
                let (x, y) = (&p.coords[0], &p.coords[1]);
                Point::new(vec![rat(m[0]) * x + rat(m[1]) * y + rat(o[0]), rat(m[2]) * x + rat(m[3]) * y + rat(o[1])])
            })
            .collect();
        BezierCurve::new(pts).expect("points")
    }

    /// `(u, u^k)` with `u = s − τ` as a Bézier curve of degree `k` on `s ∈ [0, 1]`.
    fn monomial(k: usize, tau: &BigRational) -> Curve {
        let mut x = vec![rat(0); k + 1];
        let mut y = vec![rat(0); k + 1];
        // u = s − τ; u^k by the binomial theorem
        x[0] = -tau.clone();
        x[1] = rat(1);
        for j in 0..=k {
            let c = crate::poly::bernstein::binomial_scalar::<BigRational>(k, j);
            let pow = crate::poly::bernstein::pow(&-tau.clone(), k - j);
            y[j] = c * pow;
        }
        let coeffs: Vec<Point<BigRational>> = (0..=k).map(|j| Point::new(vec![x[j].clone(), y[j].clone()])).collect();
        BezierCurve::from_power(&coeffs).expect("coefficients")
    }

    /// The touching line `y = 0` from `(−λ, 0)` to `(μ, 0)`: the touch is at `t = λ/(λ + μ)`.
    fn axis_line(lambda: i64, mu: i64) -> Curve {
        BezierCurve::new(vec![Point::new(vec![rat(-lambda), rat(0)]), Point::new(vec![rat(mu), rat(0)])])
            .expect("points")
    }

    fn lengths() -> impl Strategy<Value = (i64, i64)> {
        prop_oneof![Just((1, 1)), Just((1, 3)), Just((3, 1)), Just((1, 7)), Just((2, 2))]
    }

    /// A tangency of contact order `k` (2: a parabola and its tangent; 3: a cubic and its
    /// inflection tangent) at `s = τ` (dyadic, endpoints often) and `t = λ/(λ + μ)`. Yields the
    /// curves and `(τ, t)`.
    pub fn tangency(k: usize) -> impl Strategy<Value = (Curve, Curve, (BigRational, BigRational))> {
        (unit_parameter(), lengths(), affine()).prop_filter_map("binary64", move |(tau, (l, m), (mx, o))| {
            let a = exact(map(&monomial(k, &tau), mx, o))?;
            let b = exact(map(&axis_line(l, m), mx, o))?;
            Some((a, b, (tau, ratio(l, l + m))))
        })
    }

    /// A line starting exactly on a cubic at `A(τ)` (`τ` dyadic): the hit `(τ, 0)` is at an end
    /// of the line. Yields the curves and `τ`.
    pub fn endpoint_hit() -> impl Strategy<Value = (Curve, Curve, BigRational)> {
        (cubic(), unit_parameter(), (-64i64..=64, -64i64..=64)).prop_filter_map("binary64", |(a, tau, (dx, dy))| {
            let p = a.eval(&tau);
            let q = Point::new(vec![p.coords[0].clone() + rat(dx), p.coords[1].clone() + rat(dy)]);
            if p == q {
                return None;
            }
            let b = exact(BezierCurve::new(vec![p, q]).ok()?)?;
            Some((a, b, tau))
        })
    }

    /// A cubic and its own left piece up to `u ∈ {1/4, 1/2, 3/4}` (de Casteljau keeps dyadic
    /// numbers dyadic): an overlap on `s ∈ [0, u]`. Yields the curves and `u`.
    pub fn overlap() -> impl Strategy<Value = (Curve, Curve, BigRational)> {
        (cubic(), prop_oneof![Just(ratio(1, 4)), Just(ratio(1, 2)), Just(ratio(3, 4))]).prop_filter_map(
            "binary64 and not a point",
            |(a, u)| {
                let left = crate::curve::casteljau::subdivide(&a, &u).0;
                let genuine = a.points().windows(2).any(|w| w[0] != w[1]);
                (genuine).then_some(())?;
                Some((a, exact(left)?, u))
            },
        )
    }

    /// Two arches whose bounding boxes touch along `x = 2` without the curves meeting: the first
    /// ends at `(2, 0)`, the second starts at `(2, h)`, `h > 0`, and goes right.
    pub fn touching_boxes() -> impl Strategy<Value = (Curve, Curve)> {
        (1i64..=8, 1i64..=8, affine()).prop_filter_map("binary64", |(h, k, (m, o))| {
            let pt = |x: i64, y: i64| Point::new(vec![rat(x), rat(y)]);
            let a = BezierCurve::new(vec![pt(0, 0), pt(1, k), pt(2, 0)]).ok()?;
            let b = BezierCurve::new(vec![pt(2, h), pt(3, h + k), pt(4, h)]).ok()?;
            Some((exact(map(&a, m, o))?, exact(map(&b, m, o))?))
        })
    }

    /// A line through the cusp of a cubic (cusp at the dyadic `τ`): they meet at `(τ, 1/2)`.
    pub fn through_cusp() -> impl Strategy<Value = (Curve, Curve, BigRational)> {
        (super::binary64::cusp_at(unit_parameter()), (-16i64..=16, -16i64..=16)).prop_filter_map(
            "binary64 and a direction",
            |((a, tau), (dx, dy))| {
                if dx == 0 && dy == 0 {
                    return None;
                }
                let p = a.eval(&tau);
                let end =
                    |s: i64| Point::new(vec![p.coords[0].clone() + rat(s * dx), p.coords[1].clone() + rat(s * dy)]);
                let b = exact(BezierCurve::new(vec![end(-1), end(1)]).ok()?)?;
                Some((a, b, tau))
            },
        )
    }
}
