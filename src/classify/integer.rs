//! The classification of a planar cubic with integer control points, written straight to JSON:
//! the batch route of `casteljau classify --json`.
//!
//! The answer is [`classify`](crate::classify::classify)'s, byte for byte as its serde JSON
//! (a test compares both on every property strategy): the decisions come from
//! [`certified::decide`](crate::classify::certified::decide) over checked `i128`, and each exact number is built **once** from
//! integers and reduced once, with the formulas of the [module](crate::classify):
//!
//! * `a1 = 3(P1 − P0)`, `a2 = 3(P2 − 2P1 + P0)`, `a3 = P3 − 3P2 + 3P1 − P0`,
//!   `A = a2×a3`, `B = a1×a3`, `C = a1×a2`;
//! * `t_E = −B/(2A)`, `d = (4AC − 3B²)/(4A²)`, the double point
//!   `D = a0 + (a2·A − a3·B)·(AC − B²)/A³`;
//! * the parameters `t_E ± √d` (crunode), `t_E ± √(−d/3)` (acnode's inflections), `−C/(3B)`
//!   (explicit), spelled by [`Radical`](crate::num::quadratic_field::Radical).
//!
//! Why by hand: the generic route (`classify_in` over [`SmallRational`], then serde) reduces a
//! fraction after every product and allocates the answer's strings before serde copies and
//! escapes them; this one writes digits into the caller's buffer, and is several times faster
//! on a font's cubics. It handles the genuine cubics and degree-elevated quadratics; other
//! curves, and numbers that outgrow 128 bits, are refused (`false`), and the caller takes the
//! generic route.

use crate::classify::certified::decide;
use crate::classify::{CurveClass, EXPLICIT_REASON, NodeType, SegmentFeatures, write_node_reason};
use crate::num::quadratic_field::QuadraticExt;
use crate::num::scalar::{Exact, Scalar};
use crate::num::small::{SmallRational, checked};
use crate::poly::polynomial::center_plus_minus_sqrt;

/// Largest coordinate magnitude taken (`2^40`): every product below then fits or is checked.
pub const MAX_COORDINATE: i64 = 1 << 40;

/// Appends the JSON object (UTF-8) of [`classify`](crate::classify::classify) for the planar cubic with
/// control points `p` to `out` and returns `true`; or returns `false` with `out` unchanged when
/// this route does not take the curve (a coordinate beyond [`MAX_COORDINATE`], a collinear or
/// lower-degree curve other than a degree-elevated quadratic, or a number beyond 128 bits).
///
/// # Example
/// ```
/// use casteljau::classify::integer::classify_json;
/// let mut out = vec![];
/// assert!(classify_json(&[[0, 0], [3, 3], [0, 3], [3, 0]], &mut out));
/// let out = String::from_utf8(out).unwrap();
/// assert!(out.starts_with(r#"{"degree":3,"real_degree":3,"collinear":false,"class":"cusp""#));
/// assert!(out.contains(r#""double_point":["3/2","9/4"],"double_point_parameters":["1/2"]"#));
/// // collinear control points: the generic route answers
/// assert!(!classify_json(&[[0, 0], [1, 1], [2, 2], [3, 3]], &mut vec![]));
/// ```
pub fn classify_json(p: &[[i64; 2]; 4], out: &mut Vec<u8>) -> bool {
    if p.iter().flatten().any(|c| c.unsigned_abs() > MAX_COORDINATE as u64) {
        return false;
    }
    let start = out.len();
    let ok = matches!(checked(|| write(p, out)), Some(Some(())));
    if !ok {
        out.truncate(start);
    }
    ok
}

/// `fmt::Write` into bytes (for the one `reason` written with the formatting machinery).
struct Bytes<'a>(&'a mut Vec<u8>);

impl std::fmt::Write for Bytes<'_> {
    fn write_str(&mut self, s: &str) -> std::fmt::Result {
        self.0.extend_from_slice(s.as_bytes());
        Ok(())
    }
}

/// `n/d` reduced (`d ≠ 0`), or `None` when it does not fit.
fn ratio(n: i128, d: i128) -> Option<SmallRational> {
    SmallRational::new(n, d)
}

/// An integer as a JSON string.
fn push_integer(out: &mut Vec<u8>, n: i128) {
    out.push(b'"');
    SmallRational::integer(n).push_to(out);
    out.push(b'"');
}

/// A parameter as [`QuadraticExt`]'s `Display` spells it over [`SmallRational`]: `a`,
/// `a ± b*sqrt(d)`, `b*sqrt(d)`, `-sqrt(d)`, … (`b` omitted when it is 1).
fn push_parameter(out: &mut Vec<u8>, q: &QuadraticExt<SmallRational>) {
    let (a, b, d) = (q.rational_part(), q.radical_coefficient(), q.radicand());
    if b.is_zero() {
        return a.push_to(out);
    }
    let negative = b.sign() == std::cmp::Ordering::Less;
    if !a.is_zero() {
        a.push_to(out);
        out.extend_from_slice(if negative { b" - " } else { b" + " });
    } else if negative {
        out.push(b'-');
    }
    let b = if negative { -*b } else { *b };
    if b != SmallRational::one() {
        b.push_to(out);
        out.push(b'*');
    }
    out.extend_from_slice(b"sqrt(");
    d.push_to(out);
    out.push(b')');
}

fn write(p: &[[i64; 2]; 4], out: &mut Vec<u8>) -> Option<()> {
    let q: [[i128; 2]; 4] = p.map(|c| c.map(i128::from));
    let (class, seg) = decide(&q)?;
    let node = match class {
        CurveClass::Cubic(node) => Some(node),
        CurveClass::CubicReallyQuadratic => None,
        _ => return None,
    };
    let v = |f: &dyn Fn(usize) -> i128| [f(0), f(1)];
    let a1 = v(&|i| 3 * (q[1][i] - q[0][i]));
    let a2 = v(&|i| 3 * (q[2][i] - 2 * q[1][i] + q[0][i]));
    let a3 = v(&|i| q[3][i] - 3 * q[2][i] + 3 * q[1][i] - q[0][i]);
    let cross = |u: [i128; 2], w: [i128; 2]| u[0].checked_mul(w[1])?.checked_sub(u[1].checked_mul(w[0])?);
    let (a, b, c) = (cross(a2, a3)?, cross(a1, a3)?, cross(a1, a2)?);
    out.extend_from_slice(br#"{"degree":3,"real_degree":"#);
    out.push(if node.is_some() { b'3' } else { b'2' });
    out.extend_from_slice(br#","collinear":false,"class":""#);
    out.extend_from_slice(class.as_str().as_bytes());
    out.extend_from_slice(br#"","reason":""#);
    let mut lists: [&[QuadraticExt<SmallRational>]; 3] = [&[], &[], &[]];
    // the parameters (the first `count` of them) and (t_E, d)
    let (params, count, te_d): ([QuadraticExt<SmallRational>; 2], usize, Option<(SmallRational, SmallRational)>);
    let zero = || QuadraticExt::from_base(SmallRational::zero());
    let mut double_point = None;
    match node {
        None => {
            out.extend_from_slice(super::degenerate_class(3, 2, false).1.as_bytes());
            (params, count, te_d) = ([zero(), zero()], 0, None);
        }
        Some(NodeType::Explicit) => {
            out.extend_from_slice(EXPLICIT_REASON.as_bytes());
            (params, count) = ([QuadraticExt::from_base(ratio(-c, b.checked_mul(3)?)?), zero()], 1);
            te_d = None;
        }
        Some(node) => {
            let te = ratio(-b, a.checked_mul(2)?)?;
            let delta = a.checked_mul(c)?.checked_mul(4)?.checked_sub(b.checked_mul(b)?.checked_mul(3)?)?;
            let d = ratio(delta, a.checked_mul(a)?.checked_mul(4)?)?;
            // (AC − B²)/A³ first: each reduction then has a word-sized argument
            let r = ratio(a.checked_mul(c)?.checked_sub(b.checked_mul(b)?)?, a.checked_mul(a)?.checked_mul(a)?)?;
            let coordinate = |i: usize| -> Option<SmallRational> {
                let m = a2[i].checked_mul(a)?.checked_sub(a3[i].checked_mul(b)?)?;
                Some(SmallRational::integer(q[0][i]) + SmallRational::integer(m) * r)
            };
            double_point = Some([coordinate(0)?, coordinate(1)?]);
            write_node_reason(&mut Bytes(out), node, &d, &te).ok()?;
            (params, count) = match node {
                NodeType::Crunode => (center_plus_minus_sqrt(&te, &d), 2),
                // −d/3 from the reduced d: only a factor 3 can cancel
                NodeType::Acnode => (center_plus_minus_sqrt(&te, &(-d / SmallRational::integer(3))), 2),
                _ => ([QuadraticExt::from_base(te), zero()], 1),
            };
            te_d = Some((te, d));
        }
    }
    // [double_point_parameters, inflection_parameters, cusp_parameters]
    let params = &params[..count];
    match node {
        Some(NodeType::Crunode) => lists[0] = params,
        Some(NodeType::Cusp) => (lists[0], lists[2]) = (params, params),
        Some(NodeType::Acnode | NodeType::Explicit) => lists[1] = params,
        None => {}
    }
    out.extend_from_slice(br#"","node_type":"#);
    match node {
        Some(n) => {
            out.push(b'"');
            out.extend_from_slice(n.as_str().as_bytes());
            out.push(b'"');
        }
        None => out.extend_from_slice(b"null"),
    }
    out.extend_from_slice(br#","double_point":"#);
    match &double_point {
        Some([x, y]) => {
            out.extend_from_slice(b"[\"");
            x.push_to(out);
            out.extend_from_slice(b"\",\"");
            y.push_to(out);
            out.extend_from_slice(b"\"]");
        }
        None => out.extend_from_slice(b"null"),
    }
    for (name, list) in ["double_point_parameters", "inflection_parameters", "cusp_parameters"].iter().zip(lists) {
        out.extend_from_slice(b",\"");
        out.extend_from_slice(name.as_bytes());
        out.extend_from_slice(b"\":[");
        for (i, t) in list.iter().enumerate() {
            if i > 0 {
                out.push(b',');
            }
            out.push(b'"');
            push_parameter(out, t);
            out.push(b'"');
        }
        out.push(b']');
    }
    out.extend_from_slice(br#","invariants":{"A":"#);
    push_integer(out, a);
    out.extend_from_slice(br#","B":"#);
    push_integer(out, b);
    out.extend_from_slice(br#","C":"#);
    push_integer(out, c);
    out.push(b'}');
    if let Some((te, d)) = te_d {
        out.extend_from_slice(br#","t_E":""#);
        te.push_to(out);
        out.extend_from_slice(br#"","d":""#);
        d.push_to(out);
        out.push(b'"');
    }
    let SegmentFeatures { has_loop, has_cusp, inflections, category } = seg;
    let flag = |x: bool| if x { &b"true"[..] } else { &b"false"[..] };
    out.extend_from_slice(br#","segment":{"loop":"#);
    out.extend_from_slice(flag(has_loop));
    out.extend_from_slice(br#","cusp":"#);
    out.extend_from_slice(flag(has_cusp));
    out.extend_from_slice(br#","inflections":"#);
    out.extend_from_slice(itoa::Buffer::new().format(inflections).as_bytes());
    out.extend_from_slice(br#","category":""#);
    out.extend_from_slice(category.as_str().as_bytes());
    out.extend_from_slice(br#""}}"#);
    Some(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::BezierCurve;
    use crate::num::point::Point;

    fn generic(p: &[[i64; 2]; 4]) -> String {
        let pts = p.iter().map(|c| Point::new(vec![crate::rat(c[0]), crate::rat(c[1])])).collect();
        serde_json::to_string(&crate::classify::classify(&BezierCurve::new(pts).unwrap()).unwrap()).unwrap()
    }

    #[test]
    fn integer_route_writes_the_generic_json_on_every_node_type() {
        let cases = [
            [[0, 0], [0, 1], [1, 1], [1, 0]],  // crunode, loop outside
            [[0, 0], [3, 3], [0, 3], [3, 0]],  // cusp at 1/2
            [[0, 0], [2, 2], [-1, 2], [1, 0]], // loop
            [[0, 0], [1, 0], [2, 1], [3, 3]],  // degree-elevated quadratic
            [[0, 0], [1, 1], [2, -1], [3, 0]], // inflection
            [[0, 0], [1, 0], [2, 0], [3, 1]],  // explicit?
            [[-1769, 146], [-1769, 146], [692, -206], [-564, -1592]],
        ];
        for p in &cases {
            let mut out = vec![];
            if classify_json(p, &mut out) {
                assert_eq!(String::from_utf8(out).unwrap(), generic(p), "{p:?}");
            }
        }
    }
}
