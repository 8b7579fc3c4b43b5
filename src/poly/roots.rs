//! Exact real root isolation for polynomials in Bernstein form.
//!
//! The polynomial `p(t) = Σ c_i B_i^n(t)` on `[0, 1]` is first made square-free
//! (`p / gcd(p, p')`, exactly), then split by de Casteljau subdivision. On each piece the number
//! of sign changes `V` of the Bernstein coefficients bounds the number of roots in the open
//! interval and has the same parity (Descartes' rule for the Bernstein basis): `V = 0` means no
//! root, `V = 1` exactly one. Roots that fall exactly on a split point or an end are reported
//! exactly. Nothing is rounded.
//!
//! # Termination
//! There is no depth limit. For a square-free polynomial, Vincent's theorem (in the Bernstein
//! form of Collins–Akritas) guarantees that once an interval is narrower than a fixed
//! fraction of the distance between distinct complex roots, its coefficients show `V ≤ 1`
//! sign changes, so the subdivision stops. The depth reached is about
//! `log₂(1 / root separation)`, which the Mahler–Mignotte bound limits by `O(n·(τ + log n))`
//! bits for degree `n` and `τ`-bit coefficients. The work list is explicit (no recursion), so
//! deep subdivisions cannot overflow the stack.

use crate::curve::bezier::BezierCurve;
use crate::num::point::Point;
use crate::num::scalar::{Exact, Scalar, rat};
use crate::poly::bernstein::{from_power, to_power};
use num_rational::BigRational;
use std::cmp::Ordering;
use std::fmt;

/// A real root located exactly.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Root {
    /// The root itself.
    Exact(BigRational),
    /// An open interval `(a, b)` containing exactly one root, a simple root of the square-free
    /// part (certified by one sign change of the Bernstein coefficients; never a guess).
    Isolated(BigRational, BigRational),
}

impl fmt::Display for Root {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Root::Exact(r) => write!(f, "t = {r}"),
            Root::Isolated(a, b) => write!(f, "t in ({a}, {b})"),
        }
    }
}

/// Remainder of `a` divided by `b` (power form, lowest degree first; `b` without trailing zeros).
pub(crate) fn poly_rem(mut a: Vec<BigRational>, b: &[BigRational]) -> Vec<BigRational> {
    let lb = b.last().expect("non-zero divisor").clone();
    while a.len() >= b.len() && !a.is_empty() {
        let f = a.last().expect("non-empty").clone() / &lb;
        let shift = a.len() - b.len();
        for (i, c) in b.iter().enumerate() {
            a[shift + i] = a[shift + i].clone() - f.clone() * c;
        }
        while a.last().is_some_and(Scalar::is_zero) {
            a.pop();
        }
    }
    a
}

fn poly_div(mut a: Vec<BigRational>, b: &[BigRational]) -> Vec<BigRational> {
    let lb = b.last().expect("non-zero divisor").clone();
    let mut q = vec![rat(0); a.len().saturating_sub(b.len()) + 1];
    while a.len() >= b.len() && !a.is_empty() {
        let f = a.last().expect("non-empty").clone() / &lb;
        let shift = a.len() - b.len();
        q[shift] = f.clone();
        for (i, c) in b.iter().enumerate() {
            a[shift + i] = a[shift + i].clone() - f.clone() * c;
        }
        a.pop();
    }
    q
}

/// The monic greatest common divisor of two power-form polynomials (`[]` for gcd(0, 0)).
pub(crate) fn poly_gcd(a: Vec<BigRational>, b: Vec<BigRational>) -> Vec<BigRational> {
    let trim = |mut p: Vec<BigRational>| {
        while p.last().is_some_and(Scalar::is_zero) {
            p.pop();
        }
        p
    };
    let (mut a, mut b) = (trim(a), trim(b));
    while !b.is_empty() {
        let r = poly_rem(a, &b);
        a = b;
        b = r;
    }
    match a.last().cloned() {
        Some(l) => a.into_iter().map(|c| c / &l).collect(),
        None => a,
    }
}

/// The square-free part of a power-form polynomial (lowest degree first, non-zero).
fn square_free(p: Vec<BigRational>) -> Vec<BigRational> {
    let dp: Vec<BigRational> = p.iter().enumerate().skip(1).map(|(k, c)| c.clone() * rat(k as i64)).collect();
    let g = poly_gcd(p.clone(), dp);
    if g.len() <= 1 { p } else { poly_div(p, &g) }
}

fn sign_changes(c: &[BigRational]) -> usize {
    let signs: Vec<Ordering> = c.iter().map(Exact::sign).filter(|s| *s != Ordering::Equal).collect();
    signs.windows(2).filter(|w| w[0] != w[1]).count()
}

/// Isolates the real roots in `[0, 1]` of `p(t) = Σ c_i B_i^n(t)`, ascending.
///
/// Returns `None` when `p ≡ 0`.
///
/// # Example
/// ```
/// use casteljau::{ratio, rat, poly::roots::{isolate_bernstein, Root}};
/// // coefficients 1, −2, 1: 6t² − 6t + 1, roots 1/2 ± √3/6, each isolated
/// let r = isolate_bernstein(&[rat(1), rat(-2), rat(1)]).unwrap();
/// assert!(matches!(r.as_slice(), [Root::Isolated(..), Root::Isolated(..)]));
/// // 1, −1, 1: (2t − 1)², one double root, found exactly
/// assert_eq!(isolate_bernstein(&[rat(1), rat(-1), rat(1)]).unwrap(), vec![Root::Exact(ratio(1, 2))]);
/// // 1, 0, −1: 1 − 2t
/// assert_eq!(isolate_bernstein(&[rat(1), rat(0), rat(-1)]).unwrap(), vec![Root::Exact(ratio(1, 2))]);
/// ```
pub fn isolate_bernstein(c: &[BigRational]) -> Option<Vec<Root>> {
    if c.iter().all(Scalar::is_zero) {
        return None;
    }
    let pts: Vec<Point<BigRational>> = c.iter().map(|v| Point::new(vec![v.clone()])).collect();
    let mut power: Vec<BigRational> = to_power(&pts).into_iter().map(|p| p.coords[0].clone()).collect();
    while power.last().is_some_and(Scalar::is_zero) {
        power.pop();
    }
    let sf = square_free(power);
    if sf.len() <= 1 {
        return Some(vec![]); // a non-zero constant
    }
    if sf.len() == 2 {
        // linear: the root −c0/c1 exactly
        let r = -sf[0].clone() / &sf[1];
        let inside = r.sign() != Ordering::Less && (rat(1) - &r).sign() != Ordering::Less;
        return Some(if inside { vec![Root::Exact(r)] } else { vec![] });
    }
    let sf_pts: Vec<Point<BigRational>> = sf.iter().map(|v| Point::new(vec![v.clone()])).collect();
    let bern: Vec<BigRational> = from_power(&sf_pts).into_iter().map(|p| p.coords[0].clone()).collect();
    let mut out = Vec::new();
    if bern[0].is_zero() {
        out.push(Root::Exact(rat(0)));
    }
    split(bern.clone(), rat(0), rat(1), &mut out);
    if bern.last().expect("coefficients").is_zero() {
        out.push(Root::Exact(rat(1)));
    }
    Some(out)
}

/// Roots in the open interval `(a, b)` of a square-free polynomial with Bernstein coefficients
/// `c` on `[a, b]`, ascending. `V` sign changes bound the roots in `(a, b)` with the same
/// parity (Descartes' rule; zero coefficients are skipped), so `V = 1` certifies exactly one.
/// Terminates by Vincent's theorem (module docs); the pending pieces are kept on an explicit
/// stack, right halves below left ones, so roots come out in order.
fn split(c: Vec<BigRational>, a: BigRational, b: BigRational, out: &mut Vec<Root>) {
    enum Task {
        Piece(Vec<BigRational>, BigRational, BigRational),
        Exact(BigRational),
    }
    let half = BigRational::new(1.into(), 2.into());
    let mut stack = vec![Task::Piece(c, a, b)];
    while let Some(task) = stack.pop() {
        let (c, a, b) = match task {
            Task::Exact(m) => {
                out.push(Root::Exact(m));
                continue;
            }
            Task::Piece(c, a, b) => (c, a, b),
        };
        match sign_changes(&c) {
            0 => {}
            1 => out.push(Root::Isolated(a, b)),
            _ => {
                let curve =
                    BezierCurve::new(c.iter().map(|v| Point::new(vec![v.clone()])).collect()).expect("coefficients");
                let (l, r) = crate::curve::fraction_free::subdivide(&curve, &half);
                let m = (a.clone() + &b) / rat(2);
                let lc: Vec<BigRational> = l.points().iter().map(|p| p.coords[0].clone()).collect();
                let rc: Vec<BigRational> = r.points().iter().map(|p| p.coords[0].clone()).collect();
                stack.push(Task::Piece(rc.clone(), m.clone(), b));
                if rc[0].is_zero() {
                    stack.push(Task::Exact(m.clone()));
                }
                stack.push(Task::Piece(lc, a, m));
            }
        }
    }
}

/// Bernstein coefficients of the same polynomial on `[a, b]` (`0 ≤ a < b ≤ 1`), by two
/// subdivisions.
pub fn restrict(c: &[BigRational], a: &BigRational, b: &BigRational) -> Vec<BigRational> {
    let curve = BezierCurve::new(c.iter().map(|v| Point::new(vec![v.clone()])).collect()).expect("coefficients");
    let right = if a.is_zero() { curve } else { crate::curve::fraction_free::subdivide(&curve, a).1 };
    let s = (b.clone() - a) / (rat(1) - a);
    let piece = if s == rat(1) { right } else { crate::curve::fraction_free::subdivide(&right, &s).0 };
    piece.points().iter().map(|p| p.coords[0].clone()).collect()
}

/// The roots of `p(t) = Σ c_i B_i^n(t)` in `[a, b]`, mapped back to `t`.
pub fn isolate_in(c: &[BigRational], a: &BigRational, b: &BigRational) -> Option<Vec<Root>> {
    let local = isolate_bernstein(&restrict(c, a, b))?;
    let map = |s: BigRational| a.clone() + (b.clone() - a) * s;
    Some(
        local
            .into_iter()
            .map(|r| match r {
                Root::Exact(s) => Root::Exact(map(s)),
                Root::Isolated(s0, s1) => Root::Isolated(map(s0), map(s1)),
            })
            .collect(),
    )
}
