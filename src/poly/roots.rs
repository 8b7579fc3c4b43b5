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

use crate::num::point::Point;
use crate::num::scalar::{Exact, Scalar, rat};
use crate::poly::bernstein::{from_power, split as split_at, split_integer, to_power};
use crate::poly::polynomial::square_free;
use num_bigint::{BigInt, Sign};
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::Zero;
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

fn sign_changes(c: &[BigInt]) -> usize {
    let signs: Vec<Sign> = c.iter().map(BigInt::sign).filter(|s| *s != Sign::NoSign).collect();
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
    let power: Vec<BigRational> = to_power(&pts).into_iter().map(|p| p.coords[0].clone()).collect();
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
    // signs and roots do not change under a positive factor: clear the denominators once
    let d = bern.iter().fold(BigInt::from(1), |acc, x| acc.lcm(x.denom()));
    let ints: Vec<BigInt> = bern.iter().map(|x| x.numer() * (&d / x.denom())).collect();
    let mut out = Vec::new();
    if ints[0].is_zero() {
        out.push(Root::Exact(rat(0)));
    }
    split(ints.clone(), rat(0), rat(1), &mut out);
    if ints.last().expect("coefficients").is_zero() {
        out.push(Root::Exact(rat(1)));
    }
    Some(out)
}

/// Roots in the open interval `(a, b)` of a square-free polynomial whose Bernstein
/// coefficients on `[a, b]` are a positive multiple of `c`, ascending. `V` sign changes bound
/// the roots in `(a, b)` with the same parity (Descartes' rule; zero coefficients are skipped),
/// so `V = 1` certifies exactly one. Terminates by Vincent's theorem (module docs); the pending
/// pieces are kept on an explicit stack, right halves below left ones, so roots come out in
/// order. The halves come from [`split_integer`] at `1/2`: integers only.
fn split(c: Vec<BigInt>, a: BigRational, b: BigRational, out: &mut Vec<Root>) {
    enum Task {
        Piece(Vec<BigInt>, BigRational, BigRational),
        Exact(BigRational),
    }
    let (one, two) = (BigInt::from(1), BigInt::from(2));
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
                let (lc, rc) = split_integer(&c, &one, &two);
                let m = (a.clone() + &b) / rat(2);
                let exact_mid = rc[0].is_zero();
                stack.push(Task::Piece(rc, m.clone(), b));
                if exact_mid {
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
    let right = if Scalar::is_zero(a) { c.to_vec() } else { split_at(c, a).1 };
    let s = (b.clone() - a) / (rat(1) - a);
    if s == rat(1) { right } else { split_at(&right, &s).0 }
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
