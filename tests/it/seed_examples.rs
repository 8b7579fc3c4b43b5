//! Every example of seeds 001 and 003 reproduced exactly, from `tests/data/seeds_core.json`
//! (each case carries its `source`); seed errata are asserted as the computed truth.

use casteljau::internal::subdivide_de_casteljau;
use casteljau::internal::subdivision_intervals;
use casteljau::num::{parse_number, parse_points};
use casteljau::poly::{bernstein, bernstein_to_power_matrix, power_to_bernstein_matrix};
use casteljau::{BezierCurve, Point, rat, ratio};
use num_bigint::BigInt;
use num_rational::BigRational;
use serde_json::Value;

fn fixture() -> Value {
    serde_json::from_str(include_str!("../data/seeds_core.json")).unwrap()
}
fn num(v: &Value) -> BigRational {
    parse_number(v.as_str().unwrap(), Default::default()).unwrap()
}
fn curve(v: &Value) -> BezierCurve<BigRational> {
    BezierCurve::new(parse_points(v.as_str().unwrap(), 2, None).unwrap()).unwrap()
}
fn points(v: &Value) -> Vec<Point<BigRational>> {
    v.as_array().unwrap().iter().map(|p| Point::new(p.as_array().unwrap().iter().map(num).collect())).collect()
}

#[test]
fn power_form_examples_match_seed_003_and_001() {
    for case in fixture()["power_forms"].as_array().unwrap() {
        let c = curve(&case["points"]);
        let expected = points(&case["power"]);
        assert_eq!(c.power_coefficients(), expected, "{}", case["source"]);
        // and back: the power form determines the control points
        assert_eq!(BezierCurve::from_power(&expected).unwrap(), c, "{}", case["source"]);
    }
}

#[test]
fn power_form_example_4_erratum_y_has_3t_squared_not_3t_cubed() {
    // seed 003 example 4 prints y(t) = 1 + 3t + 3t^3 - 7t^3; the matrix product gives 3t^2.
    let c = BezierCurve::new(parse_points("0 1, 4 2, 2 4, 1 0", 2, None).unwrap()).unwrap();
    let y: Vec<BigRational> = c.power_coefficients().iter().map(|p| p.coords[1].clone()).collect();
    assert_eq!(y, vec![rat(1), rat(3), rat(3), rat(-7)]);
}

#[test]
fn subdivision_seed_001_fig9_control_polygons() {
    for case in fixture()["subdivisions"].as_array().unwrap() {
        let c = curve(&case["points"]);
        let t = num(&case["t"]);
        let (l, r) = c.subdivide(&t);
        assert_eq!(l, curve(&case["left"]), "{}", case["source"]);
        assert_eq!(r, curve(&case["right"]), "{}", case["source"]);
        // the generic (naive) route agrees
        assert_eq!(subdivide_de_casteljau(&c, &t), (l, r));
    }
}

#[test]
fn subdivision_seed_001_curve_is_2t_minus_1_cubed() {
    let c = BezierCurve::new(parse_points("-1 -1, -1/3 1, 1/3 -1, 1 1", 2, None).unwrap()).unwrap();
    for k in -5..=15 {
        let t = ratio(k, 10);
        let u = rat(2) * &t - rat(1);
        assert_eq!(c.eval(&t), Point::new(vec![u.clone(), u.clone() * &u * &u]));
    }
}

#[test]
fn repeated_subdivision_seed_001_fig10_pieces_lie_on_curve() {
    for case in fixture()["repeated_subdivisions"].as_array().unwrap() {
        let c = curve(&case["points"]);
        let t0 = num(&case["t"]);
        let depth = case["depth"].as_u64().unwrap() as u32;
        let pieces = c.subdivide_repeatedly(&t0, depth).unwrap();
        assert_eq!(pieces.len() as u64, case["pieces"].as_u64().unwrap());
        let ivs = subdivision_intervals(&t0, depth);
        for (p, (a, b)) in pieces.iter().zip(&ivs) {
            // endpoints and an interior point of every piece are on the curve at the right parameter
            for s in [rat(0), ratio(1, 3), rat(1)] {
                let t = a.clone() + (b.clone() - a) * &s;
                assert_eq!(p.eval(&s), c.eval(&t));
            }
        }
        // consecutive pieces join
        for w in pieces.windows(2) {
            assert_eq!(w[0].points().last(), w[1].points().first());
        }
    }
}

#[test]
fn conversion_matrices_seed_003_degrees_2_to_5() {
    for case in fixture()["matrices"].as_array().unwrap() {
        let n = case["degree"].as_u64().unwrap() as usize;
        let printed: Vec<Vec<BigInt>> = case["rows"]
            .as_array()
            .unwrap()
            .iter()
            .map(|r| r.as_array().unwrap().iter().map(|v| BigInt::from(v.as_i64().unwrap())).collect())
            .collect();
        assert_eq!(bernstein_to_power_matrix(n), printed, "{}", case["source"]);
        // the inverse matrix really is the inverse
        let inv = power_to_bernstein_matrix(n);
        for i in 0..=n {
            for k in 0..=n {
                let s = (0..=n)
                    .fold(rat(0), |acc, j| acc + inv[i][j].clone() * BigRational::from_integer(printed[j][k].clone()));
                assert_eq!(s, rat((i == k) as i64));
            }
        }
    }
}

#[test]
fn bernstein_expansions_seed_003_with_quartic_erratum() {
    for case in fixture()["bernstein_expansions"].as_array().unwrap() {
        let n = case["degree"].as_u64().unwrap() as usize;
        let a = bernstein_to_power_matrix(n);
        let errata: Vec<(usize, usize)> = case
            .get("errata")
            .map(|e| {
                e.as_array()
                    .unwrap()
                    .iter()
                    .map(|x| (x["basis"].as_u64().unwrap() as usize, x["power"].as_u64().unwrap() as usize))
                    .collect()
            })
            .unwrap_or_default();
        for (i, row) in case["printed"].as_array().unwrap().iter().enumerate() {
            for (k, v) in row.as_array().unwrap().iter().enumerate() {
                // the t^k coefficient of B_i^n is A[k][i]
                let truth = &a[k][i];
                let printed = BigInt::from(v.as_i64().unwrap());
                assert_eq!(truth == &printed, !errata.contains(&(i, k)), "degree {n}, B_{i}, t^{k}");
            }
        }
    }
    // the erratum itself: 4t(1-t)^3 = 4t - 12t^2 + 12t^3 - 4t^4
    assert_eq!(bernstein_to_power_matrix(4)[4][1], BigInt::from(-4));
}

#[test]
fn value_tables_seed_003_exact() {
    for case in fixture()["tables"].as_array().unwrap() {
        let ts: Vec<BigRational> = case["t"].as_array().unwrap().iter().map(num).collect();
        let table = points(&case["values"]);
        let on = |c: &BezierCurve<BigRational>| ts.iter().map(|t| c.eval(t)).collect::<Vec<_>>();
        match case.get("corrected_points") {
            None => assert_eq!(on(&curve(&case["points"])), table, "{}", case["source"]),
            Some(fix) => {
                assert_ne!(on(&curve(&case["points"])), table, "{}", case["source"]);
                assert_eq!(on(&curve(fix)), table, "corrected: {}", case["source"]);
            }
        }
    }
}

#[test]
fn value_table_example_1_erratum_x_column_is_3t_squared() {
    let c = BezierCurve::new(parse_points("0 1, 1 2, 2 2, 3 1", 2, None).unwrap()).unwrap();
    let t = ratio(1, 10);
    assert_eq!(c.eval(&t).coords[0], ratio(3, 10)); // Example 1: x = 3t
    // the printed table has 0.03 = 3t^2 at t = 0.1
}

#[test]
fn bernstein_basis_table_seed_003() {
    let case = &fixture()["bernstein_table"];
    let ts: Vec<BigRational> = case["t"].as_array().unwrap().iter().map(num).collect();
    for (i, row) in case["rows"].as_array().unwrap().iter().enumerate() {
        for (t, v) in ts.iter().zip(row.as_array().unwrap()) {
            assert_eq!(bernstein(i, 3, t), num(v), "B_{i}^3({t})");
        }
    }
    // the seed's remark: each column sums to 1
    for t in &ts {
        assert_eq!((0..=3).fold(rat(0), |a, i| a + bernstein(i, 3, t)), rat(1));
    }
}
