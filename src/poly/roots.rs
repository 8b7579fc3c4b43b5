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

use crate::error::{Error, Result};
use crate::num::scalar::{Exact, Scalar, rat};
use crate::poly::bernstein::{split as split_at, split_integer};
use crate::poly::integer::{square_free_integer, to_integer};
use crate::work::Budget;
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

/// Isolates the real roots in `[0, 1]` of `p(t) = Σ c_i B_i^n(t)`, ascending, within a work
/// budget: the up-front work (power form, square-free part) is estimated before it starts, and
/// each subdivision step is counted as it runs ([`crate::work`]; [`Budget::unlimited`] for no
/// limit). Returns `None` when `p ≡ 0`.
///
/// Coefficients that are all non-zero and of one sign prove that there is no root at once
/// (the Bernstein polynomials are positive on `(0, 1)`), whatever the degree.
///
/// # Errors
/// [`Error::WorkLimit`] when the work would exceed `budget`; nothing is guessed.
///
/// # Example
/// ```
/// use casteljau::{ratio, rat, poly::{isolate_bernstein, Root}, work::Budget};
/// let any = Budget::unlimited();
/// // coefficients 1, −2, 1: 6t² − 6t + 1, roots 1/2 ± √3/6, each isolated
/// let r = isolate_bernstein(&[rat(1), rat(-2), rat(1)], &any).unwrap().unwrap();
/// assert!(matches!(r.as_slice(), [Root::Isolated(..), Root::Isolated(..)]));
/// // 1, −1, 1: (2t − 1)², one double root, found exactly
/// assert_eq!(isolate_bernstein(&[rat(1), rat(-1), rat(1)], &any).unwrap(), Some(vec![Root::Exact(ratio(1, 2))]));
/// // all weights positive: no root, no work even with a tiny budget
/// let tight = Budget::new(1.0, "--max-work");
/// assert_eq!(isolate_bernstein(&vec![rat(1); 5000], &tight).unwrap(), Some(vec![]));
/// assert!(isolate_bernstein(&[rat(1), rat(-2), rat(1)], &tight).is_err());
/// ```
pub fn isolate_bernstein(c: &[BigRational], budget: &Budget) -> Result<Option<Vec<Root>>> {
    if c.iter().all(Scalar::is_zero) {
        return Ok(None);
    }
    let first = c[0].sign();
    if first != Ordering::Equal && c.iter().all(|x| x.sign() == first) {
        return Ok(Some(vec![]));
    }
    let n = c.len() - 1;
    let upfront = crate::work::root_isolation(n, crate::work::max_bits_of(c));
    budget.check(format!("isolating the roots of a degree-{n} polynomial"), upfront)?;
    let power = bernstein_to_power_integer(&to_integer(c));
    let sf = square_free_integer(power);
    if sf.len() <= 1 {
        return Ok(Some(vec![])); // a non-zero constant
    }
    if sf.len() == 2 {
        // linear: the root −c0/c1 exactly
        let r = BigRational::new(-sf[0].clone(), sf[1].clone());
        let inside = r.sign() != Ordering::Less && (rat(1) - &r).sign() != Ordering::Less;
        return Ok(Some(if inside { vec![Root::Exact(r)] } else { vec![] }));
    }
    // signs and roots do not change under a positive factor: integers throughout
    let ints = power_to_bernstein_integer(&sf);
    isolate_square_free_within(ints, budget.limit - upfront).map(Some).map_err(|(splits, spent)| Error::WorkLimit {
        what: format!("isolating the roots of a degree-{n} polynomial (stopped after {splits} subdivisions)"),
        estimate: upfront + spent,
        limit: budget.limit,
        option: budget.option,
    })
}

/// The roots in `[0, 1]`, ascending, of a square-free polynomial whose Bernstein coefficients
/// are a positive multiple of the integers `b` (degree ≥ 1): the subdivision of
/// [`isolate_bernstein`] without its square-free step, for callers that hold the square-free
/// part already.
pub(crate) fn isolate_square_free(b: Vec<BigInt>) -> Vec<Root> {
    isolate_square_free_within(b, f64::INFINITY).expect("an unlimited allowance is never exceeded")
}

fn isolate_square_free_within(ints: Vec<BigInt>, allowance: f64) -> std::result::Result<Vec<Root>, (usize, f64)> {
    let mut out = Vec::new();
    if ints[0].is_zero() {
        out.push(Root::Exact(rat(0)));
    }
    let last_zero = ints.last().expect("coefficients").is_zero();
    split(ints, &mut out, allowance)?;
    if last_zero {
        out.push(Root::Exact(rat(1)));
    }
    Ok(out)
}

/// Binomial rows `C(k, 0..=k)` for `k = 0..=n`, exact.
fn binomial_rows(n: usize) -> Vec<Vec<BigInt>> {
    let mut rows: Vec<Vec<BigInt>> = vec![vec![BigInt::from(1)]];
    for k in 1..=n {
        let prev = &rows[k - 1];
        let mut row = Vec::with_capacity(k + 1);
        row.push(BigInt::from(1));
        for i in 1..k {
            row.push(&prev[i - 1] + &prev[i]);
        }
        row.push(BigInt::from(1));
        rows.push(row);
    }
    rows
}

/// Power-form coefficients of `Σ b_i B_i^n(t)` on integers:
/// `c_k = C(n,k) Σ_{i≤k} (−1)^{k−i} C(k,i) b_i` (no fraction anywhere).
fn bernstein_to_power_integer(b: &[BigInt]) -> Vec<BigInt> {
    let n = b.len() - 1;
    let rows = binomial_rows(n);
    (0..=n)
        .map(|k| {
            let mut acc = BigInt::zero();
            for i in 0..=k {
                let term = &rows[k][i] * &b[i];
                if (k - i) % 2 == 1 {
                    acc -= term;
                } else {
                    acc += term;
                }
            }
            acc * &rows[n][k]
        })
        .collect()
}

/// A positive multiple of the Bernstein coefficients of `Σ c_k t^k` (degree `n`), on
/// integers: `b_i = Σ_{k≤i} C(i,k)/C(n,k) c_k = Σ_{k≤i} C(n−k, i−k) c_k / C(n,i)`, scaled by
/// `L = lcm_i C(n,i)`.
pub(crate) fn power_to_bernstein_integer(c: &[BigInt]) -> Vec<BigInt> {
    let n = c.len() - 1;
    let rows = binomial_rows(n);
    let l = rows[n].iter().fold(BigInt::from(1), |acc, x| acc.lcm(x));
    (0..=n)
        .map(|i| {
            let mut acc = BigInt::zero();
            for k in 0..=i {
                acc += &rows[n - k][i - k] * &c[k];
            }
            acc * (&l / &rows[n][i])
        })
        .collect()
}

/// Roots in the open interval `(0, 1)` of a square-free polynomial whose Bernstein
/// coefficients on `[0, 1]` are a positive multiple of `c`, ascending. `V` sign changes bound
/// the roots in an interval with the same parity (Descartes' rule; zero coefficients are
/// skipped), so `V = 1` certifies exactly one. Terminates by Vincent's theorem (module docs);
/// the pending pieces are kept on an explicit stack, right halves below left ones, so roots come
/// out in order. The halves come from [`split_integer`] at `1/2`: integers only, each half
/// divided by the power of two its coefficients share (signs and roots unchanged). A piece is
/// the dyadic interval `[k/2^j, (k + 1)/2^j]`, held as the integer `k` and the level `j`, so a
/// root near an end (`2^−1000` from it, say: a thousand levels) costs no fraction arithmetic on
/// the way down; fractions are made only for the answer. Each split is charged
/// [`crate::work::root_split`] against `allowance`; past it, `Err((splits, work spent))`.
fn split(c: Vec<BigInt>, out: &mut Vec<Root>, allowance: f64) -> std::result::Result<(), (usize, f64)> {
    let mut spent = 0.0;
    let mut splits = 0usize;
    enum Task {
        Piece(Vec<BigInt>, BigInt, u64),
        Exact(BigInt, u64),
    }
    let (one, two) = (BigInt::from(1), BigInt::from(2));
    let mut stack = vec![Task::Piece(c, BigInt::zero(), 0)];
    while let Some(task) = stack.pop() {
        let (c, k, j) = match task {
            Task::Exact(k, j) => {
                out.push(Root::Exact(dyadic(k, j)));
                continue;
            }
            Task::Piece(c, k, j) => (c, k, j),
        };
        match sign_changes(&c) {
            0 => {}
            1 => {
                let next = &k + 1;
                out.push(Root::Isolated(dyadic(k, j), dyadic(next, j)));
            }
            _ => {
                let bits = c.iter().map(BigInt::bits).max().unwrap_or(0);
                spent += crate::work::root_split(c.len() - 1, bits);
                if spent > allowance {
                    return Err((splits, spent));
                }
                splits += 1;
                let (lc, rc) = split_integer(&c, &one, &two);
                let (lc, rc) = (without_shared_twos(lc), without_shared_twos(rc));
                let left: BigInt = &k << 1u8;
                let right: BigInt = &left + 1;
                let exact_mid = rc[0].is_zero();
                if exact_mid {
                    stack.push(Task::Piece(rc, right.clone(), j + 1));
                    stack.push(Task::Exact(right, j + 1));
                } else {
                    stack.push(Task::Piece(rc, right, j + 1));
                }
                stack.push(Task::Piece(lc, left, j + 1));
            }
        }
    }
    Ok(())
}

/// `k / 2^j` as a reduced fraction (the power of two cancelled by shifts, no gcd; `0/1` for
/// `k = 0`).
pub(crate) fn dyadic(k: BigInt, j: u64) -> BigRational {
    let z = k.trailing_zeros().unwrap_or(j).min(j);
    BigRational::new_raw(k >> z, BigInt::from(1) << (j - z))
}

/// `c` divided by the largest power of two that divides every coefficient.
fn without_shared_twos(c: Vec<BigInt>) -> Vec<BigInt> {
    match c.iter().filter_map(BigInt::trailing_zeros).min() {
        Some(z) if z > 0 => c.into_iter().map(|x| x >> z).collect(),
        _ => c,
    }
}

/// Bernstein coefficients of the same polynomial on `[a, b]` (`0 ≤ a < b ≤ 1`), by two
/// subdivisions.
pub(crate) fn restrict(c: &[BigRational], a: &BigRational, b: &BigRational) -> Vec<BigRational> {
    let right = if Scalar::is_zero(a) { c.to_vec() } else { split_at(c, a).1 };
    let s = (b.clone() - a) / (rat(1) - a);
    if s == rat(1) { right } else { split_at(&right, &s).0 }
}

/// The roots of `p(t) = Σ c_i B_i^n(t)` in `[a, b]`, mapped back to `t`, within a work budget
/// (see [`isolate_bernstein`]).
///
/// # Errors
/// [`Error::WorkLimit`] when the work would exceed `budget`.
pub(crate) fn isolate_in(
    c: &[BigRational],
    a: &BigRational,
    b: &BigRational,
    budget: &Budget,
) -> Result<Option<Vec<Root>>> {
    let n = c.len().saturating_sub(1);
    if !(Scalar::is_zero(a) && *b == rat(1)) {
        budget.check(
            format!("restricting a degree-{n} polynomial to [{a}, {b}]"),
            crate::work::subdivision(n, 1, crate::work::max_bits_of(c), crate::work::bits(a).max(crate::work::bits(b))),
        )?;
    }
    let Some(local) = isolate_bernstein(&restrict(c, a, b), budget)? else { return Ok(None) };
    let map = |s: BigRational| a.clone() + (b.clone() - a) * s;
    Ok(Some(
        local
            .into_iter()
            .map(|r| match r {
                Root::Exact(s) => Root::Exact(map(s)),
                Root::Isolated(s0, s1) => Root::Isolated(map(s0), map(s1)),
            })
            .collect(),
    ))
}
