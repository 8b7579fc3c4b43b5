//! A crate that depends on casteljau's maths core (`default-features = false`) and uses it as an
//! oracle for a float library: [`within`] decides exactly whether a float answer lies within a
//! tolerance of an exact algebraic one. The tests in `tests/kurbo.rs` check kurbo's bounding
//! boxes and inflections of cubics with it.

use casteljau::poly::RealAlgebraic;
use num_rational::BigRational;

/// Whether `|x − e| ≤ tol`, decided exactly: `x` and `tol` are taken as the exact values of their
/// `f64`s, `e` is an exact real algebraic number. No rounding happens anywhere.
///
/// # Panics
/// When `x` or `tol` is not finite.
///
/// ```
/// use casteljau::poly::RealAlgebraic;
/// use casteljau::rat;
/// use casteljau_dependant::within;
/// // √2 is the root of t² − 2 in [1, 2]
/// let t2_minus_2 = casteljau::poly::Poly::new(vec![rat(-2), rat(0), rat(1)]);
/// let sqrt2 = RealAlgebraic::roots_in(&t2_minus_2, &rat(1), &rat(2))[0].clone();
/// assert!(within(&sqrt2, std::f64::consts::SQRT_2, 0.0) == false); // no f64 is √2
/// assert!(within(&sqrt2, std::f64::consts::SQRT_2, 1e-15));
/// ```
pub fn within(e: &RealAlgebraic, x: f64, tol: f64) -> bool {
    let exact = |v: f64| BigRational::from_float(v).expect("a finite f64");
    let (x, tol) = (exact(x), exact(tol));
    RealAlgebraic::from(&x - &tol) <= *e && *e <= RealAlgebraic::from(&x + &tol)
}
