//! The expression language of `proofs/` identities: exact, with degree bounds.
//!
//! ```text
//! expr   := term (("+" | "-") term)*
//! term   := unary (("*" | "/") unary)*
//! unary  := "-" unary | power
//! power  := atom ("^" unary)?                       integer exponents (negative: 1/x^k)
//! atom   := number | name | name "(" args ")" | "(" expr ")"
//! number := digits ["." digits] [("e"|"E") ["+"|"-"] digits]      (exact: 0.1 = 1/10)
//! ```
//! Functions: `C(n, k)` binomial (0 for k > n), `B(i, n, x)` Bernstein `C(n,i) xⁱ (1−x)ⁿ⁻ⁱ`,
//! `sum(r, a, b, e)` and `prod(r, a, b, e)` over integers `r = a..=b` (empty: 0 and 1).
//! Integer arguments (exponents, `C`, the `i, n` of `B`, summation bounds) must not depend on
//! the identity's variables.
//!
//! [`Expr::degree`] bounds the degree of an expression in one variable as a rational function
//! `num/den` (`(num, den)` degrees, cross-multiplying divisions), so `lhs − rhs`, written over
//! one denominator, has a numerator of degree ≤ `num`: the grid size that proves the identity.

use crate::error::{Error, Result};
use crate::num::fraction::Fraction;
use crate::num::parse::parse_number;
use crate::num::scalar::Scalar;
use crate::poly::bernstein::binomial;
use num_rational::BigRational;
use num_traits::{Signed, ToPrimitive};
use std::fmt;
use std::rc::Rc;

/// An expression tree.
#[derive(Clone, Debug, PartialEq)]
pub enum Expr {
    /// An exact number.
    Num(BigRational),
    /// A variable or integer parameter.
    Var(String),
    /// `−e`.
    Neg(Box<Expr>),
    /// `a op b` for `+ − * /`.
    Bin(char, Box<Expr>, Box<Expr>),
    /// `a ^ k`.
    Pow(Box<Expr>, Box<Expr>),
    /// `C(n, k)`.
    Binom(Box<Expr>, Box<Expr>),
    /// `B(i, n, x)`.
    Bern(Box<Expr>, Box<Expr>, Box<Expr>),
    /// `sum(r, a, b, e)` (`true`) or `prod(r, a, b, e)` (`false`).
    Fold(bool, String, Box<Expr>, Box<Expr>, Box<Expr>),
}

/// Why an evaluation has no value.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum EvalError {
    /// A denominator vanished at this point (the point is skipped and replaced).
    DivisionByZero,
    /// Anything else (unknown name, non-integer exponent, …): a malformed claim.
    Invalid(String),
}

impl std::fmt::Display for EvalError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            EvalError::DivisionByZero => f.write_str("division by zero"),
            EvalError::Invalid(m) => f.write_str(m),
        }
    }
}

/// A shared count of the fold terms an evaluation may still take (see [`with_step_limit`]).
#[derive(Debug)]
pub(crate) struct StepBudget {
    left: std::sync::atomic::AtomicU64,
    limit: u64,
}

std::thread_local! {
    /// The budget evaluations on this thread charge (none: unlimited).
    static STEPS: std::cell::RefCell<Option<std::sync::Arc<StepBudget>>> = const { std::cell::RefCell::new(None) };
}

/// Runs `f` allowing at most `steps` evaluation steps (each `sum`/`prod` term one step, a
/// power of exponent `k` `1 + k/4`, a binomial `C(n, k)` or a Bernstein polynomial of degree
/// `n` `1 + n²/2000`; a step is about 0.1–0.2 µs) in [`Expr::eval`] and
/// [`Expr::degree`]; past it, evaluation fails with [`EvalError::Invalid`] naming the limit.
/// A fold such as `sum(r, 0, 100000, sum(s, 0, 100000, x))` is small text but 10¹⁰ terms:
/// this is how a caller bounds its work. Work handed to other threads shares the budget when
/// it runs under the budget of the thread that started it. Outside any limit there is none.
///
/// ```
/// use casteljau::proof::expr::{parse_expr, with_step_limit, Env};
/// let e = parse_expr("sum(r, 0, 100000, sum(s, 0, 100000, r*s))").unwrap();
/// let err = with_step_limit(100_000, || e.eval(&mut Env::new())).unwrap_err();
/// assert!(err.to_string().contains("100000"));
/// ```
pub fn with_step_limit<T>(steps: u64, f: impl FnOnce() -> T) -> T {
    let budget = StepBudget { left: std::sync::atomic::AtomicU64::new(steps), limit: steps };
    with_steps(Some(std::sync::Arc::new(budget)), f)
}

/// The budget of the innermost [`with_step_limit`] on this thread, to share with workers.
// used by the catalogue (feature `catalogue`) and the unit tests
#[cfg_attr(not(feature = "catalogue"), allow(dead_code))]
pub(crate) fn current_steps() -> Option<std::sync::Arc<StepBudget>> {
    STEPS.with(|s| s.borrow().clone())
}

/// Runs `f` charging `budget` (from [`current_steps`] on another thread).
pub(crate) fn with_steps<T>(budget: Option<std::sync::Arc<StepBudget>>, f: impl FnOnce() -> T) -> T {
    let saved = STEPS.with(|s| s.replace(budget));
    let out = f();
    STEPS.with(|s| s.replace(saved));
    out
}

/// Charges `n` steps against the current budget. Steps are gathered per thread and taken
/// from the shared count 4096 at a time (a shared counter touched on every step would make
/// the threads fight over one cache line); the limit may be overrun by that much per thread.
fn step_n(n: u64) -> std::result::Result<(), EvalError> {
    const BATCH: u64 = 4096;
    std::thread_local! {
        static PENDING: std::cell::Cell<u64> = const { std::cell::Cell::new(0) };
    }
    let pending = PENDING.with(|p| {
        let v = p.get().saturating_add(n);
        p.set(if v >= BATCH { 0 } else { v });
        v
    });
    STEPS.with(|s| match &*s.borrow() {
        None => Ok(()),
        Some(b) => {
            use std::sync::atomic::Ordering::Relaxed;
            // a read of a line nobody writes is cheap; once exhausted, every thread stops
            let exhausted = b.left.load(Relaxed) == 0;
            let within = !exhausted
                && (pending < BATCH || b.left.fetch_update(Relaxed, Relaxed, |left| left.checked_sub(pending)).is_ok());
            if within {
                Ok(())
            } else {
                b.left.store(0, Relaxed);
                Err(EvalError::Invalid(format!(
                    "more than {} evaluation steps (sum/prod terms, powers; the work limit, raise it with --max-work)",
                    b.limit
                )))
            }
        }
    })
}

/// Charges `n` steps of work done outside [`Expr::eval`] (a grid point of a proof, say) against
/// the budget of the innermost [`with_step_limit`]; without one, nothing is charged.
///
/// # Errors
/// [`EvalError::Invalid`] naming the limit (and `--max-work`) once the budget is spent.
///
// used by the catalogue (feature `catalogue`) and the unit tests
#[cfg_attr(not(feature = "catalogue"), allow(dead_code))]
pub(crate) fn charge_steps(n: u64) -> std::result::Result<(), EvalError> {
    step_n(n)
}

/// Charges one fold term.
fn step() -> std::result::Result<(), EvalError> {
    step_n(1)
}

/// A name → value binding list (few names: a linear scan is fastest).
pub type Env = Vec<(String, Fraction)>;

fn lookup<'a>(env: &'a Env, name: &str) -> Option<&'a Fraction> {
    // names are a few bytes: compare inline rather than through a `memcmp` call
    let same = |n: &str| n.len() == name.len() && n.bytes().zip(name.bytes()).all(|(a, b)| a == b);
    env.iter().rev().find(|(n, _)| same(n)).map(|(_, v)| v)
}

struct Parser<'a> {
    text: &'a str,
    chars: Vec<(usize, char)>,
    pos: usize,
    depth: usize,
}

/// Deepest accepted expression tree (parentheses, calls, unary minus, powers and chains of
/// `+ − * /` all count): parsing, degree bounds and evaluation recurse on the tree, so a bound
/// keeps them within any thread's stack. Deeper input is an error naming the column.
pub const MAX_EXPR_DEPTH: usize = 400;

/// The depth of an expression tree, without recursion.
fn tree_depth(e: &Expr) -> usize {
    let mut max = 0;
    let mut stack = vec![(e, 1usize)];
    while let Some((e, d)) = stack.pop() {
        max = max.max(d);
        match e {
            Expr::Num(_) | Expr::Var(_) => {}
            Expr::Neg(a) => stack.push((a, d + 1)),
            Expr::Bin(_, a, b) | Expr::Pow(a, b) | Expr::Binom(a, b) => {
                stack.push((a, d + 1));
                stack.push((b, d + 1));
            }
            Expr::Bern(a, b, c) => {
                stack.extend([(a.as_ref(), d + 1), (b.as_ref(), d + 1), (c.as_ref(), d + 1)]);
            }
            Expr::Fold(_, _, a, b, c) => {
                stack.extend([(a.as_ref(), d + 1), (b.as_ref(), d + 1), (c.as_ref(), d + 1)]);
            }
        }
    }
    max
}

/// Parses an expression.
///
/// # Errors
/// [`Error::Expression`] naming the 1-based column and what was expected.
///
/// # Example
/// ```
/// use casteljau::proof::expr::parse_expr;
/// let e = parse_expr("sum(r, j, n, B(j, r, s) * B(r, n, t))").unwrap();
/// assert!(parse_expr("B(j, n, s*t").unwrap_err().to_string().contains("column 12"));
/// # let _ = e;
/// ```
pub fn parse_expr(text: &str) -> Result<Expr> {
    let mut p = Parser { text, chars: text.char_indices().collect(), pos: 0, depth: 0 };
    let e = p.expr()?;
    p.skip_ws();
    if p.pos < p.chars.len() {
        return Err(p.error(&format!("unexpected {:?}", p.chars[p.pos].1)));
    }
    let depth = tree_depth(&e);
    if depth > MAX_EXPR_DEPTH {
        return Err(Error::Expression {
            text: text.to_string(),
            column: 1,
            message: format!(
                "the expression is {depth} levels deep, more than {MAX_EXPR_DEPTH} (write long sums with sum(r, a, b, e))"
            ),
        });
    }
    Ok(e)
}

impl Parser<'_> {
    fn error(&self, message: &str) -> Error {
        Error::Expression { text: self.text.to_string(), column: self.pos + 1, message: message.to_string() }
    }
    fn skip_ws(&mut self) {
        while self.pos < self.chars.len() && self.chars[self.pos].1.is_whitespace() {
            self.pos += 1;
        }
    }
    fn peek(&mut self) -> Option<char> {
        self.skip_ws();
        self.chars.get(self.pos).map(|c| c.1)
    }
    fn eat(&mut self, c: char) -> bool {
        if self.peek() == Some(c) {
            self.pos += 1;
            true
        } else {
            false
        }
    }
    fn expect(&mut self, c: char) -> Result<()> {
        if self.eat(c) { Ok(()) } else { Err(self.error(&format!("expected {c:?}"))) }
    }
    /// Runs `f` one nesting level deeper, refusing past [`MAX_EXPR_DEPTH`].
    fn nested(&mut self, f: fn(&mut Self) -> Result<Expr>) -> Result<Expr> {
        self.depth += 1;
        if self.depth > MAX_EXPR_DEPTH {
            return Err(self.error(&format!("nested more than {MAX_EXPR_DEPTH} levels deep")));
        }
        let e = f(self);
        self.depth -= 1;
        e
    }
    fn expr(&mut self) -> Result<Expr> {
        self.nested(Self::sum)
    }
    fn sum(&mut self) -> Result<Expr> {
        let mut e = self.term()?;
        while let Some(op @ ('+' | '-')) = self.peek() {
            self.pos += 1;
            e = Expr::Bin(op, Box::new(e), Box::new(self.term()?));
        }
        Ok(e)
    }
    fn term(&mut self) -> Result<Expr> {
        let mut e = self.unary()?;
        while let Some(op @ ('*' | '/')) = self.peek() {
            self.pos += 1;
            e = Expr::Bin(op, Box::new(e), Box::new(self.unary()?));
        }
        Ok(e)
    }
    fn unary(&mut self) -> Result<Expr> {
        self.nested(Self::unary_inner)
    }
    fn unary_inner(&mut self) -> Result<Expr> {
        if self.eat('-') {
            return Ok(Expr::Neg(Box::new(self.unary()?)));
        }
        let base = self.atom()?;
        if self.eat('^') {
            return Ok(Expr::Pow(Box::new(base), Box::new(self.unary()?)));
        }
        Ok(base)
    }
    fn atom(&mut self) -> Result<Expr> {
        match self.peek() {
            Some('(') => {
                self.pos += 1;
                let e = self.expr()?;
                self.expect(')')?;
                Ok(e)
            }
            Some(c) if c.is_ascii_digit() || c == '.' => {
                let start = self.pos;
                while self.pos < self.chars.len() {
                    let c = self.chars[self.pos].1;
                    let exp_sign = matches!(c, '+' | '-') && matches!(self.chars[self.pos - 1].1, 'e' | 'E');
                    if c.is_ascii_digit() || c == '.' || c == 'e' || c == 'E' || exp_sign {
                        self.pos += 1;
                    } else {
                        break;
                    }
                }
                let tok: String = self.chars[start..self.pos].iter().map(|c| c.1).collect();
                let pos = crate::error::Position { line: None, column: start + 1, token: 1 };
                parse_number(&tok, pos).map(Expr::Num).map_err(|_| Error::Expression {
                    text: self.text.to_string(),
                    column: start + 1,
                    message: format!("bad number {tok:?}"),
                })
            }
            Some(c) if c.is_alphabetic() || c == '_' => {
                let start = self.pos;
                while self.pos < self.chars.len()
                    && (self.chars[self.pos].1.is_alphanumeric() || self.chars[self.pos].1 == '_')
                {
                    self.pos += 1;
                }
                let name: String = self.chars[start..self.pos].iter().map(|c| c.1).collect();
                if !self.eat('(') {
                    return Ok(Expr::Var(name));
                }
                let args_at = self.pos;
                let mut args = vec![self.expr()?];
                while self.eat(',') {
                    args.push(self.expr()?);
                }
                self.expect(')')?;
                self.call(name, args, args_at)
            }
            Some(c) => Err(self.error(&format!("unexpected {c:?}"))),
            None => Err(self.error("unexpected end of expression")),
        }
    }
    fn call(&mut self, name: String, mut args: Vec<Expr>, at: usize) -> Result<Expr> {
        let arity = |n: usize, args: &[Expr]| {
            if args.len() == n {
                Ok(())
            } else {
                Err(Error::Expression {
                    text: self.text.to_string(),
                    column: at,
                    message: format!("{name} takes {n} arguments, got {}", args.len()),
                })
            }
        };
        let b = Box::new;
        match name.as_str() {
            "C" => {
                arity(2, &args)?;
                let k = args.pop().expect("2");
                Ok(Expr::Binom(b(args.pop().expect("2")), b(k)))
            }
            "B" => {
                arity(3, &args)?;
                let x = args.pop().expect("3");
                let n = args.pop().expect("3");
                Ok(Expr::Bern(b(args.pop().expect("3")), b(n), b(x)))
            }
            "sum" | "prod" => {
                arity(4, &args)?;
                let body = args.pop().expect("4");
                let hi = args.pop().expect("4");
                let lo = args.pop().expect("4");
                let Some(Expr::Var(r)) = args.pop() else {
                    return Err(Error::Expression {
                        text: self.text.to_string(),
                        column: at,
                        message: format!("the first argument of {name} is the index name"),
                    });
                };
                Ok(Expr::Fold(name == "sum", r, b(lo), b(hi), b(body)))
            }
            _ => Err(Error::Expression {
                text: self.text.to_string(),
                column: at,
                message: format!("unknown function {name}"),
            }),
        }
    }
}

fn int_of(v: &Fraction, what: &str) -> std::result::Result<i64, EvalError> {
    if let Some(k) = v.to_i64() {
        return Ok(k);
    }
    if !v.is_integer() {
        return Err(EvalError::Invalid(format!("{what} must be an integer, got {v}")));
    }
    v.to_big().to_integer().to_i64().ok_or_else(|| EvalError::Invalid(format!("{what} {v} is too large")))
}

/// Largest `|exponent|`, binomial `n` and summation length accepted.
pub(crate) const MAX_INTEGER_ARGUMENT: i64 = 100_000;

fn small_int(v: &Fraction, what: &str) -> std::result::Result<i64, EvalError> {
    let k = int_of(v, what)?;
    if k.abs() > MAX_INTEGER_ARGUMENT {
        return Err(EvalError::Invalid(format!("{what} {k} exceeds {MAX_INTEGER_ARGUMENT}")));
    }
    Ok(k)
}

/// Largest number of memoised values per thread (the memo is emptied when it is full).
const MEMO_ENTRIES: usize = 1 << 18;

thread_local! {
    /// `B_i^n(x)` at integer `x` and `C(n, k)`, per thread: grid proofs evaluate the same
    /// Bernstein polynomials at the same integer nodes for every point and every instance
    /// (identity (8): `Σ_r B_j^r(s) B_r^n(t)` over a 41 × 41 grid for 861 instances).
    static MEMO: std::cell::RefCell<Memo> = std::cell::RefCell::new(Memo::default());
}

/// Memoised values by `(i, n, x)`.
type Memo = std::collections::HashMap<MemoKey, Rc<Fraction>, MemoHash>;

/// `B_i^n(x)` at an integer `x`, or `C(n, k)`: distinct keys whatever the values.
#[derive(Clone, Copy, PartialEq, Eq, Hash)]
enum MemoKey {
    Bernstein(i64, i64, i64),
    Binomial(i64, i64),
}

/// A multiplicative hash for the memo's small integer keys (SipHash's DoS resistance is not
/// needed for keys the evaluator makes itself, and it cost a tenth of identity (8)'s time).
type MemoHash = std::hash::BuildHasherDefault<MemoHasher>;

#[derive(Default)]
struct MemoHasher(u64);

impl std::hash::Hasher for MemoHasher {
    fn finish(&self) -> u64 {
        self.0
    }
    fn write(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.write_u64(b as u64);
        }
    }
    fn write_i64(&mut self, n: i64) {
        self.write_u64(n as u64);
    }
    fn write_usize(&mut self, n: usize) {
        self.write_u64(n as u64);
    }
    fn write_u64(&mut self, n: u64) {
        self.0 = (self.0.rotate_left(5) ^ n).wrapping_mul(0x51_7c_c1_b7_27_22_0a_95);
    }
}

fn memo(key: MemoKey, f: impl FnOnce() -> Fraction) -> Rc<Fraction> {
    if let Some(v) = MEMO.with(|m| m.borrow().get(&key).cloned()) {
        return v;
    }
    let v = Rc::new(f());
    MEMO.with(|m| {
        let mut m = m.borrow_mut();
        if m.len() >= MEMO_ENTRIES {
            m.clear();
        }
        m.insert(key, v.clone());
    });
    v
}

/// A value, possibly shared with the memo: it is copied only when an operation must own it.
enum Operand {
    Owned(Fraction),
    Shared(Rc<Fraction>),
}

impl Operand {
    fn get(&self) -> &Fraction {
        match self {
            Operand::Owned(x) => x,
            Operand::Shared(x) => x,
        }
    }
    fn into_owned(self) -> Fraction {
        match self {
            Operand::Owned(x) => x,
            Operand::Shared(x) => Rc::unwrap_or_clone(x),
        }
    }
}

/// `x op y` for `op` in `+ − * /`, copying a shared operand only where no by-reference form exists.
fn combine(op: char, x: Operand, y: Operand) -> std::result::Result<Fraction, EvalError> {
    use Operand::{Owned, Shared};
    if op == '/' && y.get().is_zero() {
        return Err(EvalError::DivisionByZero);
    }
    let apply = |x: Fraction, y: &Fraction| match op {
        '+' => x + y,
        '-' => x - y,
        '*' => x * y,
        _ => x / y,
    };
    Ok(match (x, y) {
        (Owned(x), y) => apply(x, y.get()),
        (Shared(x), Owned(y)) => match op {
            '+' => y + &*x,
            '*' => y * &*x,
            '-' => -(y - &*x),
            _ => apply((*x).clone(), &y),
        },
        (Shared(x), Shared(y)) if op == '*' => Fraction::product(&x, &y),
        (Shared(x), Shared(y)) => apply((*x).clone(), &y),
    })
}

/// `B_i^n(x)`: zero outside `0 ≤ i ≤ n`; memoised (shared) at integer `x`.
fn bern(i: &Expr, n: &Expr, x: &Expr, env: &mut Env) -> std::result::Result<Operand, EvalError> {
    let (i, n) = (int_arg(i, env, "B's i")?, int_arg(n, env, "B's n")?);
    if n < 0 || i < 0 || i > n {
        return Ok(Operand::Owned(Fraction::zero()));
    }
    if n >= 64 {
        step_n(1 + (n as u64).saturating_mul(n as u64) / 2_000)?;
    }
    // a bound variable is read in place, without a copy of its value
    let at = match x {
        Expr::Var(name) => lookup(env, name).and_then(Fraction::to_i64),
        _ => None,
    };
    let at = match at {
        Some(k) => k,
        None => {
            let v = x.eval(env)?;
            match v.to_i64() {
                Some(k) => k,
                None => return Ok(Operand::Owned(crate::poly::bernstein::bernstein(i as usize, n as usize, &v))),
            }
        }
    };
    Ok(Operand::Shared(memo(MemoKey::Bernstein(i, n, at), || {
        crate::poly::bernstein::bernstein(i as usize, n as usize, &Fraction::from_i64(at))
    })))
}

/// `C(n, k)` (`0 ≤ k ≤ n`), memoised.
fn binomial_memo(n: i64, k: i64) -> Fraction {
    Rc::unwrap_or_clone(memo(MemoKey::Binomial(n, k), || {
        Fraction::from(BigRational::from_integer(binomial(n as usize, k as usize)))
    }))
}

/// An integer argument (exponent, `C`'s and `B`'s indices, fold bounds), as [`small_int`] of its
/// value; integer variables, literals and their sums, differences and products are read
/// without building a [`Fraction`].
fn int_arg(e: &Expr, env: &mut Env, what: &str) -> std::result::Result<i64, EvalError> {
    fn fast(e: &Expr, env: &Env) -> Option<i64> {
        match e {
            Expr::Var(n) => lookup(env, n)?.to_i64(),
            Expr::Num(v) if v.is_integer() => v.numer().to_i64(),
            Expr::Neg(a) => fast(a, env)?.checked_neg(),
            Expr::Bin('+', a, b) => fast(a, env)?.checked_add(fast(b, env)?),
            Expr::Bin('-', a, b) => fast(a, env)?.checked_sub(fast(b, env)?),
            Expr::Bin('*', a, b) => fast(a, env)?.checked_mul(fast(b, env)?),
            _ => None,
        }
    }
    match fast(e, env) {
        Some(k) if k.abs() <= MAX_INTEGER_ARGUMENT => Ok(k),
        _ => small_int(&e.eval(env)?, what),
    }
}

fn pow(x: &Fraction, k: i64) -> std::result::Result<Fraction, EvalError> {
    let p = crate::poly::bernstein::pow(x, k.unsigned_abs() as usize);
    if k >= 0 {
        Ok(p)
    } else if p.is_zero() {
        Err(EvalError::DivisionByZero)
    } else {
        Ok(Fraction::one() / p)
    }
}

impl Expr {
    /// The number of nodes of the tree: what one evaluation costs, up to powers and folds.
    ///
    /// ```
    /// use casteljau::proof::expr::parse_expr;
    /// assert_eq!(parse_expr("x*y + 1").unwrap().size(), 5);
    /// ```
    pub fn size(&self) -> usize {
        1 + match self {
            Expr::Num(_) | Expr::Var(_) => 0,
            Expr::Neg(e) => e.size(),
            Expr::Bin(_, a, b) | Expr::Pow(a, b) | Expr::Binom(a, b) => a.size() + b.size(),
            Expr::Bern(a, b, c) => a.size() + b.size() + c.size(),
            Expr::Fold(_, _, a, b, c) => a.size() + b.size() + c.size(),
        }
    }

    /// The value of an operand of `+ − * /`: Bernstein values come shared from the memo.
    fn operand(&self, env: &mut Env) -> std::result::Result<Operand, EvalError> {
        match self {
            Expr::Bern(i, n, x) => bern(i, n, x, env),
            e => Ok(Operand::Owned(e.eval(env)?)),
        }
    }

    /// The exact value under `env`.
    ///
    /// # Errors
    /// [`EvalError::DivisionByZero`] where a denominator vanishes; [`EvalError::Invalid`] for
    /// unknown names or non-integer integer arguments.
    pub fn eval(&self, env: &mut Env) -> std::result::Result<Fraction, EvalError> {
        Ok(match self {
            Expr::Num(v) => Fraction::from(v.clone()),
            Expr::Var(n) => lookup(env, n).cloned().ok_or_else(|| EvalError::Invalid(format!("unknown name {n}")))?,
            Expr::Neg(e) => -e.eval(env)?,
            Expr::Bin(op, a, b) => {
                let (x, y) = (a.operand(env)?, b.operand(env)?);
                combine(*op, x, y)?
            }
            Expr::Pow(a, k) => {
                let k = int_arg(k, env, "exponent")?;
                let base = a.eval(env)?;
                if k.unsigned_abs() >= 64 {
                    // small powers are paid for by the fold term or the text around them; a
                    // large one by its squarings too, which grow with the result's size
                    let bits = base.bits().saturating_mul(k.unsigned_abs());
                    let products = crate::work::power(bits) / crate::work::UNITS_PER_STEP;
                    step_n((1 + k.unsigned_abs() / 4).saturating_add(products.min(u64::MAX as f64) as u64))?;
                }
                pow(&base, k)?
            }
            Expr::Binom(n, k) => {
                let (n, k) = (int_arg(n, env, "C's n")?, int_arg(k, env, "C's k")?);
                if n < 0 || k < 0 || k > n {
                    Fraction::zero()
                } else {
                    if n >= 64 {
                        step_n(1 + (n as u64).saturating_mul(n as u64) / 2_000)?;
                    }
                    binomial_memo(n, k)
                }
            }
            Expr::Bern(i, n, x) => bern(i, n, x, env)?.into_owned(),
            Expr::Fold(is_sum, r, lo, hi, body) => {
                let (lo, hi) = (int_arg(lo, env, "lower bound")?, int_arg(hi, env, "upper bound")?);
                let mut acc = if *is_sum { Fraction::zero() } else { Fraction::one() };
                if lo > hi {
                    return Ok(acc);
                }
                // every term is charged before the first is evaluated
                step_n((hi - lo + 1) as u64)?;
                env.push((r.clone(), Fraction::zero()));
                let slot = env.len() - 1;
                for k in lo..=hi {
                    env[slot].1 = Fraction::from_i64(k);
                    match body.eval(env) {
                        Ok(v) => acc = if *is_sum { acc + v } else { acc * v },
                        Err(e) => {
                            env.pop();
                            return Err(e);
                        }
                    }
                }
                env.pop();
                acc
            }
        })
    }

    /// Whether the name `name` occurs in this expression (free or bound).
    pub fn mentions(&self, name: &str) -> bool {
        match self {
            Expr::Num(_) => false,
            Expr::Var(n) => n == name,
            Expr::Neg(e) => e.mentions(name),
            Expr::Bin(_, a, b) | Expr::Pow(a, b) | Expr::Binom(a, b) => a.mentions(name) || b.mentions(name),
            Expr::Bern(i, n, x) => i.mentions(name) || n.mentions(name) || x.mentions(name),
            Expr::Fold(_, r, lo, hi, body) => {
                r == name || lo.mentions(name) || hi.mentions(name) || body.mentions(name)
            }
        }
    }

    /// Degree bound `(num, den)` in `var` of this expression as a rational function, with
    /// integer parameters bound in `params` (integer arguments are evaluated there).
    ///
    /// # Errors
    /// [`EvalError::Invalid`] when an integer argument depends on a variable.
    pub fn degree(&self, var: &str, params: &mut Env) -> std::result::Result<(usize, usize), EvalError> {
        let int = |e: &Expr, params: &mut Env, what: &str| -> std::result::Result<i64, EvalError> {
            let v = e
                .eval(params)
                .map_err(|_| EvalError::Invalid(format!("{what} must depend only on integer parameters")))?;
            small_int(&v, what)
        };
        Ok(match self {
            Expr::Num(_) => (0, 0),
            Expr::Var(n) => ((n == var && lookup(params, n).is_none()) as usize, 0),
            Expr::Neg(e) => e.degree(var, params)?,
            Expr::Bin(op, a, b) => {
                let ((na, da), (nb, db)) = (a.degree(var, params)?, b.degree(var, params)?);
                match op {
                    '+' | '-' => ((na + db).max(nb + da), da + db),
                    '*' => (na + nb, da + db),
                    _ => (na + db, da + nb),
                }
            }
            Expr::Pow(a, k) => {
                let k = int(k, params, "exponent")?;
                let (n, d) = a.degree(var, params)?;
                let m = k.unsigned_abs() as usize;
                if k >= 0 { (n * m, d * m) } else { (d * m, n * m) }
            }
            Expr::Binom(n, k) => {
                int(n, params, "C's n")?;
                int(k, params, "C's k")?;
                (0, 0)
            }
            Expr::Bern(i, n, x) => {
                int(i, params, "B's i")?;
                let n = int(n, params, "B's n")?.max(0) as usize;
                let (nx, dx) = x.degree(var, params)?;
                (n * nx.max(dx), n * dx)
            }
            Expr::Fold(is_sum, r, lo, hi, body) if !body.mentions(r) => {
                // every term has the same degree: no need to visit them one by one
                let (lo, hi) = (int(lo, params, "lower bound")?, int(hi, params, "upper bound")?);
                step()?;
                let count = (i128::from(hi) - i128::from(lo) + 1).max(0) as usize;
                if count == 0 {
                    return Ok((0, 0));
                }
                let (n, d) = body.degree(var, params)?;
                // what the term-by-term loop below accumulates for `count` equal terms
                if *is_sum {
                    (n.max(d).saturating_add(d.saturating_mul(count - 1)), d.saturating_mul(count))
                } else {
                    (n.saturating_mul(count), d.saturating_mul(count))
                }
            }
            Expr::Fold(is_sum, r, lo, hi, body) => {
                let (lo, hi) = (int(lo, params, "lower bound")?, int(hi, params, "upper bound")?);
                let mut acc = (0, 0);
                for k in lo..=hi {
                    step()?;
                    params.push((r.clone(), Fraction::from_i64(k)));
                    let d = body.degree(var, params);
                    params.pop();
                    let (n, dd) = d?;
                    acc = if *is_sum { ((acc.0 + dd).max(n + acc.1), acc.1 + dd) } else { (acc.0 + n, acc.1 + dd) };
                }
                acc
            }
        })
    }
}

impl fmt::Display for Expr {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            // `61/2` bare inside `1 / 61/2` would read back as `(1/61)/2`
            Expr::Num(v) if !v.is_integer() || v.is_negative() => write!(f, "({v})"),
            Expr::Num(v) => write!(f, "{v}"),
            Expr::Var(n) => write!(f, "{n}"),
            Expr::Neg(e) => write!(f, "-({e})"),
            Expr::Bin(op, a, b) => write!(f, "({a} {op} {b})"),
            Expr::Pow(a, k) => write!(f, "({a})^({k})"),
            Expr::Binom(n, k) => write!(f, "C({n}, {k})"),
            Expr::Bern(i, n, x) => write!(f, "B({i}, {n}, {x})"),
            Expr::Fold(s, r, a, b, e) => write!(f, "{}({r}, {a}, {b}, {e})", if *s { "sum" } else { "prod" }),
        }
    }
}

/// The examples of the crate-internal items above, run as unit tests.
#[cfg(test)]
mod doc_examples {
    #[test]
    fn charge_steps_example() {
        use crate::proof::expr::{charge_steps, with_step_limit};
        assert!(charge_steps(1_000_000).is_ok()); // no limit
        assert!(with_step_limit(100_000, || charge_steps(1_000_000)).is_err());
    }
}
