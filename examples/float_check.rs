//! A float-library check: a cubic's bounding box computed in `f64` the way quick geometry code
//! often does it, compared with casteljau's exact answer.
//!
//! ```sh
//! cargo run --example float_check
//! ```
//!
//! Two `f64` routines are checked: sampling the curve at 17 parameters, and the textbook one that
//! solves `x′(t) = 0` by the quadratic formula. casteljau computes the exact box (the extrema are
//! exact algebraic numbers, `*_float` their correctly rounded values), and the program prints
//! every side where a float box falls short of the exact one by more than a tolerance. The
//! control points are exact `f64`s, so both sides see the same curve.

use casteljau::BezierCurve;
use casteljau::num::{NumberMode, parse_points_in};
use casteljau::rational::{BoundingBox, bounding_box};

/// The exact box of a polynomial curve (as a rational one of unit weights), no work limit.
fn bounding_box_polynomial(c: &casteljau::BezierCurve<num_rational::BigRational>) -> casteljau::Result<BoundingBox> {
    bounding_box(&c.clone().into(), &casteljau::work::Budget::unlimited())
}

type Cubic = [[f64; 2]; 4];

/// The coordinate `axis` of the cubic at `t`, in `f64`.
fn at(c: &Cubic, axis: usize, t: f64) -> f64 {
    let s = 1.0 - t;
    s * s * s * c[0][axis] + 3.0 * s * s * t * c[1][axis] + 3.0 * s * t * t * c[2][axis] + t * t * t * c[3][axis]
}

/// The box of 17 samples: misses any extremum between them.
fn sampled_box(c: &Cubic) -> [[f64; 2]; 2] {
    let mut b = [[f64::INFINITY; 2], [f64::NEG_INFINITY; 2]];
    for i in 0..=16 {
        for axis in 0..2 {
            let v = at(c, axis, i as f64 / 16.0);
            b[0][axis] = b[0][axis].min(v);
            b[1][axis] = b[1][axis].max(v);
        }
    }
    b
}

/// The end points and the roots of `x′(t) = a t² + b t + c` by the quadratic formula: divides by
/// zero when `a = 0` (a derivative of degree 1), and the NaN roots then fail `0 ≤ t ≤ 1`.
fn textbook_box(c: &Cubic) -> [[f64; 2]; 2] {
    let mut b = [[f64::INFINITY; 2], [f64::NEG_INFINITY; 2]];
    for axis in 0..2 {
        let p = [c[0][axis], c[1][axis], c[2][axis], c[3][axis]];
        let a = 3.0 * (-p[0] + 3.0 * p[1] - 3.0 * p[2] + p[3]);
        let bb = 6.0 * (p[0] - 2.0 * p[1] + p[2]);
        let cc = 3.0 * (p[1] - p[0]);
        let d = (bb * bb - 4.0 * a * cc).sqrt();
        let mut ts = vec![0.0, 1.0, (-bb + d) / (2.0 * a), (-bb - d) / (2.0 * a)];
        ts.retain(|t| (0.0..=1.0).contains(t));
        for t in ts {
            let v = at(c, axis, t);
            b[0][axis] = b[0][axis].min(v);
            b[1][axis] = b[1][axis].max(v);
        }
    }
    b
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let cubics: [(&str, Cubic); 3] = [
        ("an arch (y′ has degree 1)", [[0.0, 0.0], [1.0, 2.0], [3.0, 2.0], [4.0, 0.0]]),
        ("an S-bend (x greatest at an irrational t)", [[0.0, 0.0], [3.0, 1.0], [-1.0, 2.0], [1.0, 3.0]]),
        ("a font-like cubic", [[0.5, 0.25], [3.75, 8.0], [-2.5, 6.125], [4.0, -1.0]]),
    ];
    let tolerance = 1e-9;
    let mut disagreements = 0;
    for (name, c) in &cubics {
        // each f64 written in shortest round-trip form and read back as that binary64 value, exactly
        let text: Vec<String> = c.iter().map(|p| format!("{:?} {:?}", p[0], p[1])).collect();
        let exact_curve = BezierCurve::new(parse_points_in(&text.join(", "), 2, None, NumberMode::Binary64)?)?;
        let exact = bounding_box_polynomial(&exact_curve)?;
        println!("{name}: exact x in [{}, {}], y in [{}, {}]", exact.min[0], exact.max[0], exact.min[1], exact.max[1]);
        for (routine, b) in [("sampled", sampled_box(c)), ("textbook", textbook_box(c))] {
            for axis in 0..2 {
                let (lo, hi) = (exact.min_float[axis], exact.max_float[axis]);
                let short = (b[0][axis] - lo).max(hi - b[1][axis]);
                if short > tolerance {
                    disagreements += 1;
                    println!(
                        "  {routine}: {} in [{}, {}], exact [{lo}, {hi}]: short by {short:.3e}",
                        ["x", "y"][axis],
                        b[0][axis],
                        b[1][axis]
                    );
                }
            }
        }
    }
    println!("{disagreements} disagreements");
    Ok(())
}
