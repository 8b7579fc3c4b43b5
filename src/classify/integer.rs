//! The classification of a planar cubic written straight to JSON: the batch route of
//! `casteljau classify --json` for integer control points ([`classify_json`], `i128`) and for
//! rational ones over a common denominator ([`classify_json_scaled`], big integers).
//!
//! The answer is [`classify`](crate::classify::classify)'s, byte for byte as its serde JSON
//! (tests compare both on every property strategy): the decisions come from
//! [`certified::decide`] (checked `i128`, the certified `f64` filter, or `BigInt`), and each exact
//! number is built **once** from integers and reduced once, with the formulas of the
//! [module](crate::classify):
//!
//! * `a1 = 3(P1 − P0)`, `a2 = 3(P2 − 2P1 + P0)`, `a3 = P3 − 3P2 + 3P1 − P0`,
//!   `A = a2×a3`, `B = a1×a3`, `C = a1×a2`;
//! * `t_E = −B/(2A)`, `d = (4AC − 3B²)/(4A²)`, the double point
//!   `D = a0 + (a2·A − a3·B)·(AC − B²)/A³`;
//! * the parameters `t_E ± √d` (crunode), `t_E ± √(−d/3)` (acnode's inflections), `−C/(3B)`
//!   (explicit), spelled by [`Radical`];
//! * for `P/s` (integer `P`, common denominator `s`): `t_E`, `d` and the parameters are those of
//!   `P`, the invariants are divided by `s²` and the double point by `s`.
//!
//! Why by hand: the generic route (`classify_in` over [`SmallRational`] or [`BigRational`], then
//! serde) reduces a fraction after every operation — num-bigint's gcd is Stein's bit-by-bit
//! algorithm, microseconds per 200-bit pair, even against `1` — and allocates the answer's
//! strings before serde copies and escapes them. Here every denominator is a known product
//! (`2A`, `4A²`, `A³`, `3B`, `s`, `s²`), so each reduction is one big remainder by a word and
//! word gcds (`gcd(x, w^k)` as at most `k` word gcds); digits go straight into the caller's buffer. Genuine cubics
//! and degree-elevated quadratics are taken; other curves (collinear, lower degree), and numbers
//! past the fixed widths, are refused (`false`) and the caller takes the generic route.

use crate::classify::certified::{self, decide};
use crate::classify::{CurveClass, EXPLICIT_REASON, NodeType, SegmentFeatures, write_node_reason};
use crate::num::quadratic_field::{QuadraticExt, Radical};
use crate::num::scalar::Scalar;
use crate::num::small::{SmallRational, checked};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};
use std::cmp::Ordering;

/// Largest coordinate magnitude taken (`2^40`): every product below then fits or is checked.
pub const MAX_COORDINATE: i64 = 1 << 40;

/// Appends the JSON object (UTF-8) of [`classify`](crate::classify::classify) for the planar cubic with
/// control points `p` to `out` and returns `true`; or returns `false` with `out` unchanged when
/// this route does not take the curve (a coordinate beyond [`MAX_COORDINATE`], a collinear or
/// lower-degree curve other than a degree-elevated quadratic, or a number beyond 128 bits).
///
/// # Example
/// ```
/// use casteljau::internal::classify_json;
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
    match checked(|| values_i128(p)) {
        Some(Some(v)) => {
            write_values(&v, out);
            true
        }
        _ => false,
    }
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

/// Exact numbers that append their `Display` spelling to bytes.
trait Digits: Radical {
    fn push_digits(&self, out: &mut Vec<u8>);
}

impl Digits for SmallRational {
    fn push_digits(&self, out: &mut Vec<u8>) {
        self.push_to(out);
    }
}

impl Digits for BigRational {
    fn push_digits(&self, out: &mut Vec<u8>) {
        let push = |x: &BigInt, out: &mut Vec<u8>| match x.to_i128() {
            Some(w) => SmallRational::integer(w).push_to(out),
            None => out.extend_from_slice(x.to_string().as_bytes()),
        };
        push(self.numer(), out);
        if !self.denom().is_one() {
            out.push(b'/');
            push(self.denom(), out);
        }
    }
}

/// A parameter as [`QuadraticExt`]'s `Display` spells it over an atomic field: `a`,
/// `a ± b*sqrt(d)`, `b*sqrt(d)`, `-sqrt(d)`, … (`b` omitted when it is 1); `a_digits`: `a`
/// already rendered.
fn push_parameter<K: Digits>(out: &mut Vec<u8>, q: &QuadraticExt<K>, a_digits: Option<&[u8]>) {
    let (a, b, d) = (q.rational_part(), q.radical_coefficient(), q.radicand());
    if b.is_zero() {
        return a.push_digits(out);
    }
    let negative = b.sign() == Ordering::Less;
    if !a.is_zero() {
        match a_digits {
            Some(s) => out.extend_from_slice(s),
            None => a.push_digits(out),
        }
        out.extend_from_slice(if negative { b" - " } else { b" + " });
    } else if negative {
        out.push(b'-');
    }
    let b = if negative { -b.clone() } else { b.clone() };
    if b != K::one() {
        b.push_digits(out);
        out.push(b'*');
    }
    out.extend_from_slice(b"sqrt(");
    d.push_digits(out);
    out.push(b')');
}

/// Everything the JSON shows, in the field it is written in.
struct Values<K> {
    class: CurveClass,
    node: Option<NodeType>,
    seg: SegmentFeatures,
    invariants: [K; 3],
    double_point: Option<[K; 2]>,
    /// The parameters: the first `count` of them.
    params: [QuadraticExt<K>; 2],
    count: usize,
    te_d: Option<(K, K)>,
}

/// The node type, or `None` for a degree-elevated quadratic; refuses the other classes.
fn node_of(class: CurveClass) -> Option<Option<NodeType>> {
    match class {
        CurveClass::Cubic(node) => Some(Some(node)),
        CurveClass::CubicReallyQuadratic => Some(None),
        _ => None,
    }
}

/// The parameters of a genuine cubic from `t_E` and `d` (`count` of them): `t_E ∓ √r` as
/// [`center_plus_minus_sqrt`](crate::poly::center_plus_minus_sqrt) gives them, built
/// from their parts (no field operations with `0`, which cost a big gcd each in `BigRational`).
fn parameters<K: Radical>(
    node: NodeType,
    te: &K,
    d: &K,
    minus_d_over_3: impl FnOnce() -> K,
) -> ([QuadraticExt<K>; 2], usize) {
    let r = match node {
        NodeType::Crunode => d.clone(),
        NodeType::Acnode => minus_d_over_3(),
        _ => return ([QuadraticExt::from_base(te.clone()), QuadraticExt::from_base(K::zero())], 1),
    };
    let s = K::radical(&r);
    let (b, m) = (s.radical_coefficient(), s.radicand());
    if b.is_zero() {
        let r = s.rational_part();
        return ([QuadraticExt::from_base(te.clone() - r), QuadraticExt::from_base(te.clone() + r)], 2);
    }
    ([QuadraticExt::new(te.clone(), -b.clone(), m.clone()), QuadraticExt::new(te.clone(), b.clone(), m.clone())], 2)
}

impl<K: Radical> Values<K> {
    /// The values before the node type's numbers are filled in.
    fn new(class: CurveClass, node: Option<NodeType>, seg: SegmentFeatures, invariants: [K; 3]) -> Self {
        let zero = || QuadraticExt::from_base(K::zero());
        Values { class, node, seg, invariants, double_point: None, params: [zero(), zero()], count: 0, te_d: None }
    }
}

/// `[a2, a3]` and `[A, B, C]` of integer control points `|q| ≤ 2^40` (so every product is checked
/// and fits): the power form and its invariants in words.
fn power_form_words(q: &[[i128; 2]; 4]) -> Option<([[i128; 2]; 2], [i128; 3])> {
    let v = |f: &dyn Fn(usize) -> i128| [f(0), f(1)];
    let a1 = v(&|i| 3 * (q[1][i] - q[0][i]));
    let a2 = v(&|i| 3 * (q[2][i] - 2 * q[1][i] + q[0][i]));
    let a3 = v(&|i| q[3][i] - 3 * q[2][i] + 3 * q[1][i] - q[0][i]);
    let cross = |u: [i128; 2], w: [i128; 2]| u[0].checked_mul(w[1])?.checked_sub(u[1].checked_mul(w[0])?);
    Some(([a2, a3], [cross(a2, a3)?, cross(a1, a3)?, cross(a1, a2)?]))
}

fn values_i128(p: &[[i64; 2]; 4]) -> Option<Values<SmallRational>> {
    let q: [[i128; 2]; 4] = p.map(|c| c.map(i128::from));
    let (class, seg) = decide(&q)?;
    let node = node_of(class)?;
    let ([a2, a3], [a, b, c]) = power_form_words(&q)?;
    let zero = || QuadraticExt::from_base(SmallRational::zero());
    let integer = SmallRational::integer;
    let mut out = Values::new(class, node, seg, [integer(a), integer(b), integer(c)]);
    match node {
        None => {}
        Some(NodeType::Explicit) => {
            (out.params, out.count) = ([QuadraticExt::from_base(ratio(-c, b.checked_mul(3)?)?), zero()], 1);
        }
        Some(node) => {
            let te = ratio(-b, a.checked_mul(2)?)?;
            let delta = a.checked_mul(c)?.checked_mul(4)?.checked_sub(b.checked_mul(b)?.checked_mul(3)?)?;
            let d = ratio(delta, a.checked_mul(a)?.checked_mul(4)?)?;
            // (AC − B²)/A³ first: each reduction then has a word-sized argument
            let r = ratio(a.checked_mul(c)?.checked_sub(b.checked_mul(b)?)?, a.checked_mul(a)?.checked_mul(a)?)?;
            let coordinate = |i: usize| -> Option<SmallRational> {
                let m = a2[i].checked_mul(a)?.checked_sub(a3[i].checked_mul(b)?)?;
                Some(integer(q[0][i]) + integer(m) * r)
            };
            out.double_point = Some([coordinate(0)?, coordinate(1)?]);
            // −d/3 from the reduced d: only a factor 3 can cancel
            (out.params, out.count) = parameters(node, &te, &d, || -d / SmallRational::integer(3));
            out.te_d = Some((te, d));
        }
    }
    Some(out)
}

/// `|x| mod w` for `0 < w`, without allocating when `w < 2^96` (32 bits at a time).
fn rem_word(x: &num_bigint::BigUint, w: u128) -> u128 {
    if w >> 96 != 0 {
        return (x % w).to_u128().expect("a remainder below a u128 fits");
    }
    x.iter_u32_digits().rev().fold(0u128, |r, d| ((r << 32) | u128::from(d)) % w)
}

/// `gcd(|x|, w)` for a word `w > 0`: one big remainder, then words.
fn gcd_word(x: &BigInt, w: u128) -> u128 {
    crate::num::small::gcd_u128(w, rem_word(x.magnitude(), w))
}

/// `gcd(|x|, w^k)` for a word `w > 0`, as a product of at most `k` word gcds: step `j` takes
/// `h = gcd(x_j, w)` out of `x` (so at most `k·v_p(w)` of each prime `p`, and all of
/// `v_p(x)` below that).
fn gcd_with_power(x: &BigInt, w: u128, k: usize) -> BigInt {
    let mut x = x.magnitude().clone();
    let mut g = BigInt::from(1);
    for _ in 0..k {
        let h = crate::num::small::gcd_u128(w, rem_word(&x, w));
        if h == 1 {
            break;
        }
        x /= h;
        g *= h;
    }
    g
}

/// `n/d` reduced by a known `g = gcd(n, d)`, with a positive denominator.
fn reduced_by(n: BigInt, d: BigInt, g: &BigInt) -> BigRational {
    let (n, d) = if g.is_one() { (n, d) } else { (n / g, d / g) };
    if d.is_negative() { BigRational::new_raw(-n, -d) } else { BigRational::new_raw(n, d) }
}

fn values_big(p: &[[BigInt; 2]; 4], scale: &BigInt) -> Option<Values<BigRational>> {
    let (class, seg) = match p
        .iter()
        .flatten()
        .map(|c| c.to_i64().filter(|v| v.unsigned_abs() < 1 << 53))
        .collect::<Option<Vec<i64>>>()
    {
        // coordinates that are exact doubles: the certified f64 filter usually decides
        Some(v) => certified::filter_f64(&[
            [v[0] as f64, v[1] as f64],
            [v[2] as f64, v[3] as f64],
            [v[4] as f64, v[5] as f64],
            [v[6] as f64, v[7] as f64],
        ])
        .or_else(|| decide(p))?,
        None => decide(p)?,
    };
    let node = node_of(class)?;
    let small: Option<[[i128; 2]; 4]> = p
        .iter()
        .flatten()
        .map(|x| x.to_i128().filter(|v| v.unsigned_abs() <= MAX_COORDINATE as u128))
        .collect::<Option<Vec<i128>>>()
        .map(|v| [[v[0], v[1]], [v[2], v[3]], [v[4], v[5]], [v[6], v[7]]]);
    let ([a2, a3], [a, b, c]) = match small {
        // coordinates ≤ 2^40: the power form and A, B, C (≤ 2^88) in words, then big
        Some(q) => {
            let (a23, abc) = power_form_words(&q)?;
            (a23.map(|u| u.map(BigInt::from)), abc.map(BigInt::from))
        }
        None => {
            let v = |f: &dyn Fn(usize) -> BigInt| [f(0), f(1)];
            let a1 = v(&|i| 3 * (&p[1][i] - &p[0][i]));
            let a2 = v(&|i| 3 * (&p[2][i] - 2 * &p[1][i] + &p[0][i]));
            let a3 = v(&|i| &p[3][i] - 3 * &p[2][i] + 3 * &p[1][i] - &p[0][i]);
            let cross = |u: &[BigInt; 2], w: &[BigInt; 2]| &u[0] * &w[1] - &u[1] * &w[0];
            let abc = [cross(&a2, &a3), cross(&a1, &a3), cross(&a1, &a2)];
            ([a2, a3], abc)
        }
    };
    // the words every reduction is taken against
    let scale2 = (scale * scale).to_u128()?;
    let word = |x: &BigInt| x.magnitude().to_u128().filter(|&w| w != 0);
    let one = BigInt::from(1);
    // the invariants of p/scale are A/scale², …
    let invariant = |x: &BigInt| reduced_by(x.clone(), BigInt::from(scale2), &BigInt::from(gcd_word(x, scale2)));
    let zero = || QuadraticExt::from_base(<BigRational as Scalar>::zero());
    let mut out = Values::new(class, node, seg, [invariant(&a), invariant(&b), invariant(&c)]);
    match node {
        None => {}
        Some(NodeType::Explicit) => {
            let d3 = &b * 3;
            let g = BigInt::from(gcd_word(&c, word(&d3)?));
            (out.params, out.count) = ([QuadraticExt::from_base(reduced_by(-c.clone(), d3, &g)), zero()], 1);
        }
        Some(node) => {
            let (wa, w2a) = (word(&a)?, word(&(&a * 2))?);
            let te = reduced_by(-b.clone(), &a * 2, &BigInt::from(gcd_word(&b, w2a)));
            let delta: BigInt = &a * &c * 4 - &b * &b * 3;
            let d = reduced_by(delta.clone(), &a * &a * 4, &gcd_with_power(&delta, w2a, 2));
            // r = (AC − B²)/A³ reduced, then D = a0 + m·r and D/scale, every gcd against a word
            let k = &a * &c - &b * &b;
            let cube = &a * &a * &a;
            let gk = gcd_with_power(&k, wa, 3);
            let (rn, rd) = (&k / &gk, &cube / &gk);
            let rd = if rd.is_negative() { -rd } else { rd };
            let rn = if cube.is_negative() != gk.is_negative() { -rn } else { rn };
            let coordinate = |i: usize| -> Option<BigRational> {
                let m = &a2[i] * &a - &a3[i] * &b;
                // gcd(m, rd) divides gcd(m, A³), a product of word gcds
                let gm = gcd_with_power(&m, wa, 3);
                let g = match word(&gm) {
                    Some(w) => BigInt::from(gcd_word(&rd, w)),
                    None => num_integer::Integer::gcd(&gm, &rd),
                };
                let (m, rd) = (m / &g, &rd / &g);
                let num = &p[0][i] * &rd + m * &rn;
                let den = rd * scale;
                let g2 = match word(scale) {
                    Some(w) => BigInt::from(gcd_word(&num, w)),
                    None => num_integer::Integer::gcd(&num, scale),
                };
                Some(reduced_by(num, den, if g2.is_zero() { &one } else { &g2 }))
            };
            out.double_point = Some([coordinate(0)?, coordinate(1)?]);
            // −d/3 = −n/(3q) from the reduced d = n/q: only a factor 3 can cancel
            let minus_d_over_3 = || {
                let (n, q) = (d.numer(), d.denom());
                if (n % 3u32).is_zero() {
                    BigRational::new_raw(-(n / 3u32), q.clone())
                } else {
                    BigRational::new_raw(-n.clone(), q * 3u32)
                }
            };
            (out.params, out.count) = parameters(node, &te, &d, minus_d_over_3);
            out.te_d = Some((te, d));
        }
    }
    Some(out)
}

/// Appends the JSON of [`classify`](crate::classify::classify) for the planar cubic `p/scale`
/// (integer control points `p`, `0 < scale < 2^64`, a common denominator) and returns `true`;
/// or returns `false` with `out` unchanged for a curve this route does not take (as
/// [`classify_json`]: collinear or lower-degree curves other than degree-elevated quadratics).
/// Big integers throughout, but every reduction is one big remainder and word gcds (against
/// `2A`, `A`, `3B` and the scale), never a gcd of two big numbers when those fit 128 bits.
///
/// # Example
/// ```
/// use casteljau::internal::classify_json_scaled;
/// use num_bigint::BigInt;
/// // 0 0, 1/2 1/2, 0 1/2, 1/2 0 (a cusp at 1/2) over the common denominator 2
/// let p = [[0, 0], [1, 1], [0, 1], [1, 0]].map(|c| c.map(BigInt::from));
/// let mut out = vec![];
/// assert!(classify_json_scaled(&p, &BigInt::from(2), &mut out));
/// let out = String::from_utf8(out).unwrap();
/// assert!(out.contains(r#""double_point":["1/4","3/8"]"#), "{out}");
/// ```
pub fn classify_json_scaled(p: &[[BigInt; 2]; 4], scale: &BigInt, out: &mut Vec<u8>) -> bool {
    if !scale.is_positive() || scale.bits() > 64 {
        return false;
    }
    match values_big(p, scale) {
        Some(v) => {
            write_values(&v, out);
            true
        }
        None => false,
    }
}

/// Digits rendered once, shown through `Display` (for [`write_node_reason`]).
struct Rendered<'a>(&'a [u8]);

impl std::fmt::Display for Rendered<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(std::str::from_utf8(self.0).map_err(|_| std::fmt::Error)?)
    }
}

thread_local! {
    /// Scratch space for the digits of `t_E` and `d` (reused: no allocation per curve).
    static SCRATCH: std::cell::RefCell<(Vec<u8>, Vec<u8>)> = const { std::cell::RefCell::new((Vec::new(), Vec::new())) };
}

/// [`classify_json_scaled`] of a cubic with fixed-width rational control points (as
/// [`small_cubic`](crate::internal::small_cubic) reads them): scaled by the lcm of the
/// denominators; `false` when that scale does not fit `i128` or the route does not take the curve.
///
/// # Example
/// ```
/// use casteljau::internal::classify_json_small;
/// use casteljau::{internal::small_cubic, num::NumberMode};
/// let p = small_cubic("0 0, 1/2 1/2, 0 1/2, 1/2 0", NumberMode::Exact).unwrap();
/// let mut out = vec![];
/// assert!(classify_json_small(&p, &mut out));
/// assert!(String::from_utf8(out).unwrap().contains(r#""double_point":["1/4","3/8"]"#));
/// ```
pub fn classify_json_small(p: &[[SmallRational; 2]; 4], out: &mut Vec<u8>) -> bool {
    let lcm = |l: i128, d: i128| l.checked_mul(d / num_integer::Integer::gcd(&l, &d));
    let Some(scale) = p.iter().flatten().try_fold(1i128, |l, x| lcm(l, x.denom())) else { return false };
    let ints = p.map(|q| q.map(|x| BigInt::from(x.numer()) * (scale / x.denom())));
    classify_json_scaled(&ints, &BigInt::from(scale), out)
}

fn write_values<K: Digits>(v: &Values<K>, out: &mut Vec<u8>) {
    SCRATCH.with(|scratch| match scratch.try_borrow_mut() {
        Ok(mut s) => {
            let (te_s, d_s) = &mut *s;
            write_values_with(v, out, te_s, d_s);
        }
        Err(_) => write_values_with(v, out, &mut vec![], &mut vec![]),
    })
}

fn write_values_with<K: Digits>(v: &Values<K>, out: &mut Vec<u8>, te_s: &mut Vec<u8>, d_s: &mut Vec<u8>) {
    // t_E and d appear up to four times: their digits are rendered once
    te_s.clear();
    d_s.clear();
    if let Some((te, d)) = &v.te_d {
        te.push_digits(te_s);
        d.push_digits(d_s);
    }
    let (te_s, d_s) = (&te_s[..], &d_s[..]);
    out.extend_from_slice(br#"{"degree":3,"real_degree":"#);
    out.push(if v.node.is_some() { b'3' } else { b'2' });
    out.extend_from_slice(br#","collinear":false,"class":""#);
    out.extend_from_slice(v.class.as_str().as_bytes());
    out.extend_from_slice(br#"","reason":""#);
    match (v.node, &v.te_d) {
        (None, _) => out.extend_from_slice(super::degenerate_class(3, 2, false).1.as_bytes()),
        (Some(NodeType::Explicit), _) => out.extend_from_slice(EXPLICIT_REASON.as_bytes()),
        (Some(node), Some(_)) => {
            write_node_reason(&mut Bytes(out), node, &Rendered(d_s), &Rendered(te_s)).expect("writing to bytes");
        }
        (Some(_), None) => unreachable!("a node with A ≠ 0 has t_E and d"),
    }
    // [double_point_parameters, inflection_parameters, cusp_parameters]
    let mut lists: [&[QuadraticExt<K>]; 3] = [&[], &[], &[]];
    let params = &v.params[..v.count];
    match v.node {
        Some(NodeType::Crunode) => lists[0] = params,
        Some(NodeType::Cusp) => (lists[0], lists[2]) = (params, params),
        Some(NodeType::Acnode | NodeType::Explicit) => lists[1] = params,
        None => {}
    }
    out.extend_from_slice(br#"","node_type":"#);
    match v.node {
        Some(n) => {
            out.push(b'"');
            out.extend_from_slice(n.as_str().as_bytes());
            out.push(b'"');
        }
        None => out.extend_from_slice(b"null"),
    }
    out.extend_from_slice(br#","double_point":"#);
    match &v.double_point {
        Some([x, y]) => {
            out.extend_from_slice(b"[\"");
            x.push_digits(out);
            out.extend_from_slice(b"\",\"");
            y.push_digits(out);
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
            // the rational part of every parameter but a rational t_E ± r is t_E itself
            let te = v.te_d.as_ref().filter(|(te, _)| t.rational_part() == te && !t.radical_coefficient().is_zero());
            push_parameter(out, t, te.map(|_| te_s));
            out.push(b'"');
        }
        out.push(b']');
    }
    for (k, (name, x)) in ["A", "B", "C"].iter().zip(&v.invariants).enumerate() {
        out.extend_from_slice(if k == 0 { br#","invariants":{""# } else { br#",""# });
        out.extend_from_slice(name.as_bytes());
        out.extend_from_slice(br#"":""#);
        x.push_digits(out);
        out.push(b'"');
    }
    out.push(b'}');
    if v.te_d.is_some() {
        out.extend_from_slice(br#","t_E":""#);
        out.extend_from_slice(te_s);
        out.extend_from_slice(br#"","d":""#);
        out.extend_from_slice(d_s);
        out.push(b'"');
    }
    let SegmentFeatures { has_loop, has_cusp, inflections, category } = &v.seg;
    let flag = |x: bool| if x { &b"true"[..] } else { &b"false"[..] };
    out.extend_from_slice(br#","segment":{"loop":"#);
    out.extend_from_slice(flag(*has_loop));
    out.extend_from_slice(br#","cusp":"#);
    out.extend_from_slice(flag(*has_cusp));
    out.extend_from_slice(br#","inflections":"#);
    out.extend_from_slice(itoa::Buffer::new().format(*inflections).as_bytes());
    out.extend_from_slice(br#","category":""#);
    out.extend_from_slice(category.as_str().as_bytes());
    out.extend_from_slice(br#""}}"#);
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::curve::BezierCurve;
    use crate::num::point::Point;

    fn generic(p: &[[i64; 2]; 4]) -> String {
        let pts = p.iter().map(|c| Point::new(vec![crate::num::rat(c[0]), crate::num::rat(c[1])])).collect();
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
