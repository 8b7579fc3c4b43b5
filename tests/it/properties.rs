//! Properties with exact `==`: independent routes to the same answer must agree.

use casteljau::internal::{
    eval_de_casteljau, subdivide_de_casteljau, subdivide_repeatedly_de_casteljau, triangle_de_casteljau,
};
use casteljau::num::{Rational, ratio_to_f64};
use casteljau::num::{parse_number, parse_points};
use casteljau::poly::binomial;
use casteljau::{BezierCurve, Exact, Point, QuadraticExt, Scalar, rat};
use num_bigint::BigInt;
use num_rational::BigRational;
use proptest::prelude::*;

/// Small exact rationals p/q, |p| ≤ 200, 1 ≤ q ≤ 60.
fn small_rational() -> impl Strategy<Value = BigRational> {
    (-200i64..=200, 1i64..=60).prop_map(|(p, q)| BigRational::new(p.into(), q.into()))
}

/// Parameters, mostly in [0, 1] but also outside.
fn parameter() -> impl Strategy<Value = BigRational> {
    prop_oneof![(0i64..=97, 1i64..=97).prop_map(|(p, q)| BigRational::new(p.min(q).into(), q.into())), small_rational(),]
}

/// Curves of degree 0..=7 in dimension 1..=3.
fn curve() -> impl Strategy<Value = BezierCurve<BigRational>> {
    (1usize..=3, 1usize..=8).prop_flat_map(|(dim, len)| {
        prop::collection::vec(prop::collection::vec(small_rational(), dim), len)
            .prop_map(|pts| BezierCurve::new(pts.into_iter().map(Point::new).collect()).unwrap())
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    #[test]
    fn eval_de_casteljau_equals_bernstein_sum_equals_power_form(c in curve(), t in parameter()) {
        let a = c.eval(&t);
        prop_assert_eq!(&a, &c.eval_bernstein(&t));
        prop_assert_eq!(&a, &c.eval_power(&t));
    }

    #[test]
    fn eval_fraction_free_equals_naive(c in curve(), t in parameter()) {
        prop_assert_eq!(c.eval(&t), eval_de_casteljau(&c, &t));
    }

    #[test]
    fn eval_fraction_free_bigint_fallback_equals_naive(c in curve(), k in 60u32..=70) {
        // t with a denominator near 2^k pushes the i128 path into overflow
        let t = BigRational::new(BigInt::from(3) , BigInt::from(2).pow(k) + 1);
        let big = c.elevate(12).unwrap();
        prop_assert_eq!(big.eval(&t), eval_de_casteljau(&c, &t));
    }

    #[test]
    fn triangle_fraction_free_equals_naive(c in curve(), t in parameter()) {
        prop_assert_eq!(c.triangle(&t), triangle_de_casteljau(&c, &t));
    }

    #[test]
    fn subdivision_halves_reproduce_the_curve(c in curve(), t0 in parameter(), s in parameter()) {
        let (l, r) = c.subdivide(&t0);
        prop_assert_eq!(l.eval(&s), c.eval(&(t0.clone() * &s)));
        prop_assert_eq!(r.eval(&s), c.eval(&(t0.clone() + (rat(1) - &t0) * &s)));
        prop_assert_eq!((l.clone(), r.clone()), subdivide_de_casteljau(&c, &t0));
    }

    #[test]
    fn repeated_subdivision_fraction_free_equals_naive(c in curve(), t0 in parameter(), depth in 0u32..=3) {
        prop_assert_eq!(
            c.subdivide_repeatedly(&t0, depth).unwrap(),
            subdivide_repeatedly_de_casteljau(&c, &t0, depth).unwrap()
        );
    }

    #[test]
    fn elevation_preserves_the_curve_and_reduction_undoes_it(c in curve(), by in 0usize..=4, t in parameter()) {
        let e = c.elevate(by).unwrap();
        prop_assert_eq!(e.degree(), c.degree() + by);
        prop_assert_eq!(e.eval(&t), c.eval(&t));
        let r = e.reduce_degree();
        prop_assert_eq!(r.degree(), c.real_degree());
        prop_assert_eq!(&r, &c.reduce_degree());
        // reduction then elevation back gives the original control points
        prop_assert_eq!(r.elevate(c.degree() - r.degree()).unwrap(), c.clone());
    }

    #[test]
    fn fraction_free_power_elevate_reduce_equal_generic(c in curve(), by in 0usize..=4) {
        // the generic code over the integer-fast Rational is the independent route
        let generic = c.map(|x| Rational(x.clone()));
        let back = |c: BezierCurve<Rational>| c.map(|x| x.0.clone());
        let back_points = |p: Vec<Point<Rational>>| -> Vec<Point<BigRational>> {
            p.into_iter().map(|q| Point::new(q.coords.into_iter().map(|x| x.0).collect())).collect()
        };
        prop_assert_eq!(c.power_coefficients(), back_points(generic.power_coefficients()));
        prop_assert_eq!(c.elevate(by).unwrap(), back(generic.elevate(by).unwrap()));
        prop_assert_eq!(c.elevate(by).unwrap().reduce_degree(), back(generic.reduce_degree()));
    }

    #[test]
    fn power_form_round_trips(c in curve()) {
        prop_assert_eq!(BezierCurve::from_power(&c.power_coefficients()).unwrap(), c);
    }

    #[test]
    fn derivative_matches_power_form_derivative(c in curve(), t in parameter()) {
        let d = c.derivative(1);
        let coeffs = c.power_coefficients();
        let dc: Vec<Point<BigRational>> = coeffs.iter().enumerate().skip(1).map(|(k, p)| p.scale(&rat(k as i64))).collect();
        let expected = if dc.is_empty() { Point::origin(c.dim()) } else { BezierCurve::from_power(&dc).unwrap().eval_power(&t) };
        prop_assert_eq!(d.eval(&t), expected);
        // second derivative is the derivative of the derivative
        prop_assert_eq!(c.derivative(2).eval(&t), d.derivative(1).eval(&t));
    }

    /// f64 de Casteljau error bound for t ∈ [0, 1]: |fl(b(t)) − b(t)| ≤ (4n + 6)·u·M with
    /// u = 2⁻⁵³ and M = max |b_i| (convex combinations; rounding of t, the points and the result).
    #[test]
    fn eval_f64_within_stated_error_bound(c in curve(), p in 0i64..=1000) {
        let t = BigRational::new(p.into(), 1000.into());
        let exact = c.eval(&t);
        let approx = c.map(|v| v.to_f64()).eval(&ratio_to_f64(&t));
        let m = c.points().iter().flat_map(|q| &q.coords).map(|v| ratio_to_f64(v).abs()).fold(0.0, f64::max);
        let bound = (4.0 * c.degree() as f64 + 6.0) * f64::EPSILON / 2.0 * m;
        for (e, a) in exact.coords.iter().zip(&approx.coords) {
            prop_assert!((ratio_to_f64(e) - a).abs() <= bound, "{} vs {} bound {}", e, a, bound);
        }
    }

    #[test]
    fn parse_formats_round_trip(x in small_rational()) {
        prop_assert_eq!(parse_number(&x.to_string(), Default::default()).unwrap(), x);
    }

    #[test]
    fn parse_curve_display_round_trips(c in curve()) {
        let text = c.to_string();
        prop_assert_eq!(BezierCurve::new(parse_points(&text, c.dim(), None).unwrap()).unwrap(), c);
    }

    #[test]
    fn rational_fast_paths_agree_with_bigrational(a in small_rational(), b in small_rational(), k in -50i64..50) {
        let (ra, rb) = (Rational(a.clone()), Rational(b.clone()));
        let ki = Rational::from_i64(k);
        prop_assert_eq!((ra.clone() + &rb).0, a.clone() + &b);
        prop_assert_eq!((ra.clone() - &rb).0, a.clone() - &b);
        prop_assert_eq!((ra.clone() * &rb).0, a.clone() * &b);
        prop_assert_eq!((ki.clone() * &ki).0, rat(k * k));
        prop_assert_eq!((ki.clone() + &Rational::from_i64(3)).0, rat(k + 3));
        if !b.is_zero() { prop_assert_eq!((ra / &rb).0, a / &b); }
    }

    #[test]
    fn quadratic_extension_field_laws(a in small_rational(), b in small_rational(), c in small_rational(), e in small_rational(), d in 2i64..30) {
        prop_assume!(Exact::exact_sqrt(&rat(d)).is_none());
        let x = QuadraticExt::new(a.clone(), b.clone(), rat(d));
        let y = QuadraticExt::new(c, e, rat(d));
        prop_assert_eq!(x.clone() * &y, y.clone() * &x);
        prop_assert_eq!((x.clone() + &y) - &y, x.clone());
        if !y.is_zero() { prop_assert_eq!((x.clone() / &y) * &y, x.clone()); }
        // the sign is exact: compare with the f64 value where it is far from 0
        let f = x.to_f64();
        if f.abs() > 1e-6 { prop_assert_eq!(x.sign(), if f > 0.0 { std::cmp::Ordering::Greater } else { std::cmp::Ordering::Less }); }
        prop_assert_eq!(x.norm(), a.clone() * &a - b.clone() * &b * rat(d));
    }
}

#[test]
fn bernstein_partition_of_unity_and_binomial_symmetry() {
    for n in 0..30 {
        let t = BigRational::new(7.into(), 19.into());
        let s = casteljau::poly::bernstein_all(n, &t).into_iter().fold(rat(0), |a, b| a + b);
        assert_eq!(s, rat(1));
        for k in 0..=n {
            assert_eq!(binomial(n, k), binomial(n, n - k));
        }
    }
}

#[test]
fn quadratic_extension_sign_of_near_cancellation() {
    // 1351/780 is a convergent of √3 from above: 1351/780 − √3 > 0 but tiny.
    let x = QuadraticExt::new(BigRational::new(1351.into(), 780.into()), rat(-1), rat(3));
    assert_eq!(x.sign(), std::cmp::Ordering::Greater);
    let y = QuadraticExt::new(BigRational::new(989.into(), 571.into()), rat(-1), rat(3));
    assert_eq!(y.sign(), std::cmp::Ordering::Less); // 989/571 < √3
    assert_eq!(
        QuadraticExt::sqrt(BigRational::new(9.into(), 4.into())),
        QuadraticExt::from_ratio(&BigRational::new(3.into(), 2.into()))
    );
}

mod polynomial_routes {
    use casteljau::poly::Poly;
    use casteljau::poly::{Root, isolate_bernstein};
    use casteljau::rat;
    use num_rational::BigRational;
    use proptest::prelude::*;

    /// The product by the schoolbook sum, independent of [`Poly`]'s own.
    fn mul(a: &Poly<BigRational>, b: &Poly<BigRational>) -> Poly<BigRational> {
        let (a, b) = (a.coeffs(), b.coeffs());
        let mut out = vec![rat(0); a.len() + b.len() - 1];
        for (i, x) in a.iter().enumerate() {
            for (j, y) in b.iter().enumerate() {
                out[i + j] = out[i + j].clone() + x.clone() * y;
            }
        }
        Poly::new(out)
    }

    fn poly(max_degree: usize) -> impl Strategy<Value = Poly<BigRational>> {
        prop::collection::vec(-20i64..=20, 2..=max_degree + 1)
            .prop_filter("non-constant", |v| v.iter().skip(1).any(|&x| x != 0))
            .prop_map(|v| Poly::new(v.into_iter().map(rat).collect()))
            .prop_filter("non-constant", |p| p.degree() >= Some(1))
    }

    /// Whether `b` divides `a`.
    fn divides(b: &Poly<BigRational>, a: &Poly<BigRational>) -> bool {
        a.div_rem(b).1.is_zero()
    }

    /// Evaluates a power-form polynomial.
    fn eval(p: &[BigRational], t: &BigRational) -> BigRational {
        p.iter().rev().fold(rat(0), |acc, c| acc * t + c)
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]

        /// The integer subresultant gcd of `a·c` and `b·c` is a multiple of `c` that divides both.
        #[test]
        fn gcd_contains_the_common_factor_and_divides_both(a in poly(4), b in poly(4), c in poly(3)) {
            let (ac, bc) = (mul(&a, &c), mul(&b, &c));
            let g = ac.gcd(&bc);
            prop_assert!(g.degree() >= c.degree());
            prop_assert!(divides(&g, &ac));
            prop_assert!(divides(&g, &bc));
            prop_assert!(divides(&c, &g));
        }

        /// `square_free(a²·b)` has the roots of `a·b`, each simple: it divides `a·b` and shares
        /// no factor with its derivative.
        #[test]
        fn square_free_keeps_every_root_once(a in poly(3), b in poly(3)) {
            let p = mul(&mul(&a, &a), &b);
            let sf = p.square_free();
            let ab = mul(&a, &b);
            prop_assert!(divides(&sf, &ab));
            prop_assert_eq!(sf.gcd(&sf.derivative()).degree(), Some(0));
            prop_assert!(divides(&a.square_free(), &a.square_free()));
            prop_assert_eq!(&p, &(&(&a * &a) * &b)); // the product agrees with the schoolbook one
        }

        /// Roots placed at rational points of [0, 1] (with multiplicity) are found exactly or
        /// isolated, each once; the isolating intervals hold a sign change.
        #[test]
        fn isolation_finds_planted_roots(roots in prop::collection::vec((0i64..=8, 1usize..=3), 1..=3)) {
            let mut p = Poly::constant(rat(1));
            let mut distinct: Vec<BigRational> = vec![];
            for (k, m) in &roots {
                let r = BigRational::new((*k).into(), 8.into());
                for _ in 0..*m {
                    p = mul(&p, &Poly::new(vec![-r.clone(), rat(1)]));
                }
                if !distinct.contains(&r) {
                    distinct.push(r);
                }
            }
            distinct.sort();
            // to Bernstein form of degree deg p
            let pts: Vec<casteljau::Point<BigRational>> = p.coeffs().iter().map(|c| casteljau::Point::new(vec![c.clone()])).collect();
            let bern: Vec<BigRational> = casteljau::BezierCurve::from_power(&pts).unwrap().points().iter().map(|q| q.coords[0].clone()).collect();
            let found = isolate_bernstein(&bern, &casteljau::work::Budget::unlimited()).unwrap().unwrap();
            prop_assert_eq!(found.len(), distinct.len());
            for (f, r) in found.iter().zip(&distinct) {
                match f {
                    Root::Exact(x) => prop_assert_eq!(x, r),
                    Root::Isolated(lo, hi) => prop_assert!(lo < r && r < hi && eval(p.coeffs(), r) == rat(0)),
                }
            }
        }
    }
}

/// `a + b√d` to 200 fractional bits below its leading bit: `a + b·⌊√(d·4^k)⌋/2^k`, an oracle
/// independent of the exact-sign search in `to_f64`.
fn high_precision(a: &BigRational, b: &BigRational, d: &BigRational) -> BigRational {
    let k = 400u32;
    let scale = BigInt::from(1) << k;
    let num = d.numer() * &scale * &scale * d.denom();
    let root = num.sqrt(); // ⌊√(p q 4^k)⌋ = ⌊2^k √d · q⌋
    a + b * BigRational::new(root, scale * d.denom())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    /// `to_f64` of `a + b√d` is the correctly rounded value: it agrees with rounding a
    /// 400-bit approximation, including under heavy cancellation (a ≈ −b√d).
    #[test]
    fn quadratic_extension_to_f64_is_correctly_rounded(
        p in -1000i64..1000, q in 1i64..1000, r in -1000i64..1000, s in 1i64..1000, d in 2i64..10_000, shift in 0u32..60,
    ) {
        let d = BigRational::from_integer(BigInt::from(d));
        prop_assume!(Exact::exact_sqrt(&d).is_none());
        let (a, b) = (BigRational::new(p.into(), q.into()), BigRational::new(r.into(), s.into()));
        prop_assume!(!b.is_zero());
        // a cancelling pair: a' = nearest 2^-shift-grid value to -b√d, so x = a' + b√d is tiny
        let approx = -(b.clone() * high_precision(&rat(0), &rat(1), &d));
        let grid = BigRational::from_integer(BigInt::from(1) << shift);
        let a2 = (approx * &grid).round() / &grid;
        for a in [a, a2] {
            let x = QuadraticExt::new(a.clone(), b.clone(), d.clone());
            prop_assert_eq!(x.to_f64(), ratio_to_f64(&high_precision(&a, &b, &d)), "{}", x);
        }
    }
}
