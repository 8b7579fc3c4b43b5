//! Real algebraic numbers (exact order, equality across polynomials, rationality, correctly
//! rounded floats) and the exact bounding box built on them, cross-checked against independent
//! routes: roots built from known factors, `Q(√d)` arithmetic for cubics, exact evaluation at
//! many rational parameters, and a 200-digit decimal oracle for the floats.

use crate::common::{run, stderr, stdout};
use casteljau::curve::BezierCurve;
use casteljau::num::Point;
use casteljau::poly::quadratic_roots;
use casteljau::poly::{Poly, RealAlgebraic};
use casteljau::rational::{BoundingBox, bounding_box};

/// The exact box of a polynomial curve (as a rational one of unit weights), no work limit.
fn bounding_box_polynomial(c: &casteljau::BezierCurve<num_rational::BigRational>) -> casteljau::Result<BoundingBox> {
    bounding_box(&c.clone().into(), &casteljau::work::Budget::unlimited())
}
use casteljau::{QuadraticExt, RationalBezier, rat, ratio};
use num_rational::BigRational;
use proptest::prelude::*;

/// `Π (t − r_i) · (t² − d)` in power form.
fn with_roots(roots: &[BigRational], d: i64) -> Poly<BigRational> {
    let mut p = vec![rat(-d), rat(0), rat(1)];
    for r in roots {
        let mut next = vec![rat(0); p.len() + 1];
        for (k, c) in p.iter().enumerate() {
            next[k + 1] = next[k + 1].clone() + c.clone();
            next[k] = next[k].clone() - c.clone() * r;
        }
        p = next;
    }
    Poly::new(p)
}

fn small() -> impl Strategy<Value = BigRational> {
    (-40i64..=40, 1i64..=12).prop_map(|(p, q)| ratio(p, q))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(60))]

    /// The roots of `Π(t − r_i)(t² − d)`: the rationals come back as rationals, `±√d` as
    /// `Q(√d)` numbers, all ascending and equal to the independent `Q(√d)` values.
    #[test]
    fn algebraic_roots_of_known_factors(rs in prop::collection::vec(small(), 0..4), d in 2i64..30) {
        let p = with_roots(&rs, d);
        let roots = RealAlgebraic::real_roots(&p);
        let mut expected: Vec<QuadraticExt<BigRational>> = rs.iter().map(|r| QuadraticExt::from_base(r.clone())).collect();
        for (x, _) in quadratic_roots(&rat(-d), &rat(0), &rat(1)) {
            expected.push(x);
        }
        expected.sort_by(|a, b| (a.clone() - b.clone()).sign_cmp());
        expected.dedup_by(|a, b| (a.clone() - b.clone()).sign_cmp() == std::cmp::Ordering::Equal);
        prop_assert_eq!(roots.len(), expected.len());
        for w in roots.windows(2) {
            prop_assert!(w[0] < w[1]);
        }
        for (r, e) in roots.iter().zip(&expected) {
            prop_assert_eq!(r.to_f64(), casteljau::Scalar::to_f64(e));
            if let Some(q) = e.to_base() {
                prop_assert_eq!(r.to_rational(), Some(&q));
            }
            // the same number from another polynomial: (t² − d)·(t − 100) alone
            let other = RealAlgebraic::real_roots(&with_roots(&[rat(100)], d));
            if e.to_base().is_none() {
                prop_assert!(other.contains(r));
            }
        }
    }
}

trait SignCmp {
    fn sign_cmp(&self) -> std::cmp::Ordering;
}

impl SignCmp for QuadraticExt<BigRational> {
    fn sign_cmp(&self) -> std::cmp::Ordering {
        casteljau::Exact::sign(self)
    }
}

#[test]
fn algebraic_floats_are_correctly_rounded_against_a_decimal_oracle() {
    // t³ − 2, t³ − 3t − 1 (three real roots), t⁵ − t − 1: values from 200-digit arithmetic
    // (Python decimal, Newton's method at 200 digits), rounded once to binary64
    let cases: [(&[i64], &[f64]); 3] = [
        (&[-2, 0, 0, 1], &[1.2599210498948732]),
        (&[-1, -3, 0, 1], &[-1.532088886237956, -0.3472963553338607, 1.8793852415718169]),
        (&[-1, -1, 0, 0, 0, 1], &[1.1673039782614187]),
    ];
    for (p, want) in cases {
        let p = Poly::new(p.iter().map(|&c| rat(c)).collect());
        let got: Vec<f64> = RealAlgebraic::real_roots(&p).iter().map(RealAlgebraic::to_f64).collect();
        assert_eq!(got, want);
    }
}

#[test]
fn algebraic_display_spells_rationals_quadratics_and_general_roots() {
    let r = RealAlgebraic::real_roots(&Poly::new(vec![rat(-1), rat(-3), rat(0), rat(1)]));
    assert_eq!(r[2].to_string(), "root 3 of t^3 - 3*t - 1 in [15/8, 31/16]");
    let q = RealAlgebraic::real_roots(&Poly::new(vec![rat(1), rat(-4), rat(2)])); // 2t² − 4t + 1
    assert_eq!(q[0].to_string(), "1 - 1/2*sqrt(2)");
    assert_eq!(serde_json::to_string(&q[1]).unwrap(), "\"1 + 1/2*sqrt(2)\"");
    let z = RealAlgebraic::roots_in(&Poly::new(vec![rat(0), rat(-1), rat(1)]), &rat(0), &rat(1)); // t² − t
    assert_eq!(z.iter().map(|x| x.to_string()).collect::<Vec<_>>(), ["0", "1"]);
}

fn curve(text: &str) -> BezierCurve<BigRational> {
    BezierCurve::new(casteljau::num::parse_points(text, 2, None).unwrap()).unwrap()
}

fn cubic() -> impl Strategy<Value = BezierCurve<BigRational>> {
    prop::collection::vec((-20i64..=20, -20i64..=20), 4)
        .prop_map(|v| BezierCurve::new(v.into_iter().map(|(x, y)| Point::new(vec![rat(x), rat(y)])).collect()).unwrap())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(40))]

    /// The box holds the curve at 65 rational parameters (exactly), its ends are attained
    /// where it says, and for a cubic the stationary parameters are the `Q(√d)` roots of the
    /// derivative.
    #[test]
    fn bbox_contains_the_curve_and_is_attained(c in cubic()) {
        let b = bounding_box_polynomial(&c).unwrap();
        for i in 0..=64 {
            let p = c.eval(&ratio(i, 64));
            for k in 0..2 {
                let v = RealAlgebraic::from(p.coords[k].clone());
                prop_assert!(b.min[k] <= v && v <= b.max[k]);
            }
        }
        let power = c.power_coefficients();
        for k in 0..2 {
            let x: Vec<BigRational> = power.iter().map(|p| p.coords[k].clone()).collect();
            let (xp, one) = (Poly::new(x.clone()), Poly::constant(rat(1)));
            prop_assert_eq!(&b.min_at[k].map_rational(&xp, &one), &b.min[k]);
            prop_assert_eq!(&b.max_at[k].map_rational(&xp, &one), &b.max[k]);
            // x'(t) = x1 + 2 x2 t + 3 x3 t²: its roots in [0, 1], independently
            let mut want: Vec<f64> = quadratic_roots(&x[1], &(rat(2) * &x[2]), &(rat(3) * &x[3]))
                .into_iter()
                .map(|(t, _)| t)
                .filter(|t| casteljau::Exact::sign(t) != std::cmp::Ordering::Less
                    && casteljau::Exact::sign(&(QuadraticExt::from_base(rat(1)) - t.clone())) != std::cmp::Ordering::Less)
                .map(|t| casteljau::Scalar::to_f64(&t))
                .collect();
            want.dedup();
            let got: Vec<f64> = b.stationary.iter().filter(|s| s.axis == k).map(|s| s.t_float).collect();
            if x[1..].iter().any(|c| *c != rat(0)) {
                prop_assert_eq!(got, want);
            }
        }
    }
}

#[test]
fn bbox_of_a_rational_arc_and_a_vanishing_leading_coefficient() {
    // kurbo #593's trap in another guise: a cubic whose leading coefficient is zero (a quadratic
    // written as a cubic) — its box is the quadratic's
    let elevated = curve("0 0, 2/3 4/3, 4/3 4/3, 2 0");
    let b = bounding_box_polynomial(&elevated).unwrap();
    assert_eq!((b.max[1].to_string(), b.max_at[1].to_string()), ("1".into(), "1/2".into()));
    // a quarter of the unit circle as a rational quadratic (weights 1, 1, 2: the conic through
    // (1,0), (0,1) with tangents meeting at (1,1)): x decreases, y increases, no interior extremum
    let pts =
        vec![Point::new(vec![rat(1), rat(0)]), Point::new(vec![rat(1), rat(1)]), Point::new(vec![rat(0), rat(1)])];
    let arc = RationalBezier::new(pts, vec![rat(2), rat(1), rat(1)]).unwrap();
    let b = bounding_box(&arc, &casteljau::work::Budget::unlimited()).unwrap();
    assert_eq!(b.min.iter().map(|x| x.to_string()).collect::<Vec<_>>(), ["0", "0"]);
    assert_eq!(b.max.iter().map(|x| x.to_string()).collect::<Vec<_>>(), ["1", "1"]);
    // weights that vanish inside make no box
    let bad = RationalBezier::new(
        vec![Point::new(vec![rat(1), rat(0)]), Point::new(vec![rat(1), rat(1)]), Point::new(vec![rat(0), rat(1)])],
        vec![rat(1), rat(-2), rat(1)],
    )
    .unwrap();
    assert!(bounding_box(&bad, &casteljau::work::Budget::unlimited()).is_err());
}

#[test]
fn cli_bbox_text_json_and_errors() {
    let o = run(&["bbox", "0 0, 3 1, -1 2, 1 3"], None);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(stdout(&o).starts_with("x in [0, 133/169 + 20/169*sqrt(10)]"), "{}", stdout(&o));
    let o = run(&["bbox", "--json", "0 0, 1 2, 2 0"], None);
    let v: serde_json::Value = serde_json::from_str(stdout(&o).trim()).unwrap();
    assert_eq!(v["max"], serde_json::json!(["2", "1"]));
    assert_eq!(v["stationary"][0]["axis"], "y");
    assert_eq!(v["stationary"][0]["t"], "1/2");
    assert_eq!(run(&["bbox", "--weights", "1 -2 1", "1 0, 1 1, 0 1"], None).status.code(), Some(2));
    assert_eq!(run(&["bbox", "0 0, 1"], None).status.code(), Some(2));
}

/// Roots a thousand binary places from an end of `[0, 1]` and close together (the
/// subdivision goes a thousand levels down, its pieces held as dyadic integers): the rational
/// roots `2^−1000` and `3·2^−1000` of `(2^1000·t − 1)(2^1000·t − 3)` come out exactly; the
/// irrational root `2^−1000.5` of `(2^2001·t² − 1)(2^999·t − 1)` is isolated from `2^−999` by
/// an interval that holds it, and its float is correctly rounded.
#[test]
fn algebraic_roots_near_an_end_of_the_interval_are_isolated_exactly() {
    let big = |k: usize| BigRational::from_integer(num_bigint::BigInt::from(1) << k);
    let tiny = rat(1) / big(1000);
    let p = Poly::new(vec![rat(3), -big(1000) * rat(4), big(2000)]);
    let roots = RealAlgebraic::roots_in(&p, &rat(0), &rat(1));
    let found: Vec<Option<BigRational>> = roots.iter().map(|r| r.to_rational().cloned()).collect();
    assert_eq!(found, [Some(tiny.clone()), Some(tiny.clone() * rat(3))]);
    let q = Poly::new(vec![rat(1), -big(999), -big(2001), big(3000)]);
    let roots = RealAlgebraic::roots_in(&q, &rat(0), &rat(1));
    assert_eq!(roots.len(), 2);
    assert_eq!(roots[1].to_rational(), Some(&(tiny.clone() * rat(2))));
    let (lo, hi) = roots[0].interval();
    let at = |x: &BigRational| x.clone() * x * big(2001) - rat(1);
    assert!(at(&lo) < rat(0) && at(&hi) > rat(0), "[{lo}, {hi}] does not hold the root");
    assert!(hi <= tiny * rat(2), "[{lo}, {hi}] is not a thousand levels down");
    assert_eq!(roots[0].to_f64(), 0.5f64.sqrt() * 2f64.powi(-1000));
}
