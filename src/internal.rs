//! Not part of the API: the crate's internal fast paths (fixed-width and certified routes that
//! the public operations take first), public only so that the crate's own benches and
//! integration tests can time them and cross-check them against the exact routes. Anything
//! here may change or disappear in any release; depend on the public operations instead.

pub use crate::classify::certified::{
    Certified, SMALL_INT_LIMIT, SignRing, SmallInt, Summary, decide, filter_f64, summarize, summarize_f64,
    summarize_integers,
};
pub use crate::classify::integer::{MAX_COORDINATE, classify_json, classify_json_scaled, classify_json_small};
pub use crate::classify::{classify_in, loop_blinn};
pub use crate::curve::casteljau::subdivision_intervals;
pub use crate::curve::fraction_free::{IntegerCurve, eval_integer};
#[cfg(feature = "svg")]
pub use crate::format::svg_element::parse_transform;
pub use crate::num::CheckedRing;
pub use crate::num::parse::{integer_cubic, parse_points_small, parse_points_small_in, small_cubic};
pub use crate::num::small::{SmallRational, checked};
pub use crate::proof::identity_8;
pub use crate::spline::{check_segments, seed_cubic_segment, seed_quadratic_segment};

pub use crate::curve::casteljau::{
    subdivide as subdivide_de_casteljau, subdivide_repeatedly as subdivide_repeatedly_de_casteljau,
    triangle as triangle_de_casteljau,
};

/// `b(t)` by the generic de Casteljau scheme whatever the scalar (for `BigRational`, the route
/// [`BezierCurve::eval`](crate::BezierCurve::eval) does not take): the naive route of the benches.
pub fn eval_de_casteljau<S: crate::num::Scalar>(c: &crate::curve::BezierCurve<S>, t: &S) -> crate::num::Point<S> {
    c.eval_de_casteljau(t)
}
