//! Implicit equations along rational curves, proved exactly.
//!
//! For a rational curve `x(t) = X(t)/W(t)` of degree `n` and a polynomial `f` of total degree
//! `d`, `W(t)^d · f(X/W, Y/W[, Z/W])` is a polynomial of degree ≤ `n·d` in `t`. It vanishes
//! identically iff it vanishes at `n·d + 1` distinct parameters; where `W(t) ≠ 0` that is
//! `f(x(t)) = 0`. So `n·d + 1` exact evaluations at parameters with `W ≠ 0` **prove**
//! `f(x(t)) ≡ 0`, and one non-zero value is an exact counterexample.
//!
//! `f` is written in the expression language of [`crate::proof::expr`] in the variables `x, y[, z]`
//! (`x^3 - 3*x*y + y^3`).

use crate::error::{Error, Result};
use crate::num::fraction::Fraction;
use crate::num::point::Point;
use crate::num::scalar::Scalar;
use crate::proof::expr::{Env, Expr, parse_expr};
use crate::rational::rational_bezier::RationalBezier;
use num_rational::BigRational;

/// The outcome of an implicit proof ([`ImplicitOutcome::new`]).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum ImplicitOutcome {
    /// `f(x(t)) ≡ 0`: the curve lies on the curve/surface `f = 0`.
    Proved {
        /// `n·d`, the degree bound of `W^d f(X/W, …)`.
        degree_bound: usize,
        /// The parameters used (all with `W ≠ 0`).
        parameters: Vec<BigRational>,
    },
    /// `f(x(t)) ≠ 0` at `t`.
    Counterexample {
        /// The parameter.
        t: BigRational,
        /// The curve point there.
        point: Point<BigRational>,
        /// `f` at that point.
        value: BigRational,
    },
}

impl ImplicitOutcome {
    /// `f(x(t)) ≡ 0` was proved.
    pub fn proved(&self) -> bool {
        matches!(self, ImplicitOutcome::Proved { .. })
    }
}

impl serde::Serialize for ImplicitOutcome {
    /// `{"proved": true, "degree_bound", "parameters"}` or `{"proved": false, "t", "point",
    /// "value"}`, exact numbers as strings.
    fn serialize<S: serde::Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
        use crate::num::serial::AsString;
        use serde::ser::SerializeStruct;
        match self {
            ImplicitOutcome::Proved { degree_bound, parameters } => {
                let mut st = s.serialize_struct("ImplicitOutcome", 3)?;
                st.serialize_field("proved", &true)?;
                st.serialize_field("degree_bound", degree_bound)?;
                st.serialize_field("parameters", &parameters.iter().map(AsString).collect::<Vec<_>>())?;
                st.end()
            }
            ImplicitOutcome::Counterexample { t, point, value } => {
                let mut st = s.serialize_struct("ImplicitOutcome", 4)?;
                st.serialize_field("proved", &false)?;
                st.serialize_field("t", &AsString(t))?;
                st.serialize_field("point", point)?;
                st.serialize_field("value", &AsString(value))?;
                st.end()
            }
        }
    }
}

const NAMES: [&str; 3] = ["x", "y", "z"];

/// The total degree of a polynomial expression in `vars`.
///
/// # Errors
/// [`Error::InvalidArgument`] when `f` divides by a variable (not a polynomial) or has a
/// non-constant integer argument.
pub(crate) fn total_degree(f: &Expr, vars: &[&str]) -> Result<usize> {
    // substitute v ↦ λ·v and take the degree in λ
    fn scale(e: &Expr, vars: &[&str]) -> Expr {
        use Expr::*;
        let b = |x: &Expr| Box::new(scale(x, vars));
        match e {
            Var(n) if vars.contains(&n.as_str()) => Bin('*', Box::new(Var("__lambda".into())), Box::new(e.clone())),
            Num(_) | Var(_) => e.clone(),
            Neg(a) => Neg(b(a)),
            Bin(op, l, r) => Bin(*op, b(l), b(r)),
            Pow(a, k) => Pow(b(a), k.clone()),
            Binom(..) => e.clone(),
            Bern(i, n, x) => Bern(i.clone(), n.clone(), b(x)),
            Fold(s, r, lo, hi, body) => Fold(*s, r.clone(), lo.clone(), hi.clone(), b(body)),
        }
    }
    let (num, den) = scale(f, vars)
        .degree("__lambda", &mut Env::new())
        .map_err(|e| Error::InvalidArgument { message: format!("the polynomial: {e}") })?;
    if den > 0 {
        return Err(Error::InvalidArgument {
            message: "the implicit equation must be a polynomial (no division by x, y, z)".into(),
        });
    }
    Ok(num)
}

/// Largest degree bound `n·d` of an implicit proof (it evaluates the curve at `n·d + 1`
/// parameters).
pub const MAX_IMPLICIT_DEGREE: usize = 20_000;

/// Proves or refutes `f(x(t)) ≡ 0` along `curve` (see the module docs).
///
/// # Errors
/// A malformed `f`, a curve of dimension > 3, or a denominator vanishing everywhere tried.
pub(crate) fn prove_implicit(curve: &RationalBezier<BigRational>, f: &str) -> Result<ImplicitOutcome> {
    let dim = curve.dim();
    if dim > 3 {
        return Err(Error::NotApplicable { message: "implicit equations take curves of dimension ≤ 3".into() });
    }
    let f = parse_expr(f)?;
    let vars = &NAMES[..dim];
    let d = total_degree(&f, vars)?;
    let bound = curve.degree().saturating_mul(d);
    if bound > MAX_IMPLICIT_DEGREE {
        return Err(Error::TooLarge {
            what: "degree of W^d·f(X/W) (curve degree × degree of f)",
            value: bound,
            limit: MAX_IMPLICIT_DEGREE,
        });
    }
    let eval = curve.exact_evaluator();
    let mut params = Vec::with_capacity(bound + 1);
    // parameters 0, 1, 1/2, 1/3, 2/3, … (denominators grow slowly), skipping poles of W
    let mut q = 1i64;
    let mut tried = 0usize;
    'outer: loop {
        for p in 0..=q {
            if num_integer::gcd(p, q) != 1 && !(p == 0 && q == 1) {
                continue;
            }
            tried += 1;
            if tried > 10 * (bound + 1) + 100 {
                return Err(Error::Degenerate { message: "the denominator vanishes at every parameter tried".into() });
            }
            let t = BigRational::new(p.into(), q.into());
            let Ok(point) = eval(&t) else { continue };
            let mut env: Env =
                vars.iter().zip(&point.coords).map(|(n, v)| (n.to_string(), Fraction::from(v.clone()))).collect();
            let value =
                f.eval(&mut env).map_err(|e| Error::InvalidArgument { message: format!("the polynomial: {e}") })?;
            if !value.is_zero() {
                return Ok(ImplicitOutcome::Counterexample { t, point, value: value.to_big() });
            }
            params.push(t);
            if params.len() > bound {
                break 'outer;
            }
        }
        q += 1;
    }
    Ok(ImplicitOutcome::Proved { degree_bound: bound, parameters: params })
}

/// The examples of the crate-internal items above, run as unit tests.
#[cfg(test)]
mod doc_examples {
    use super::*;
    #[test]
    fn prove_implicit_example() {
        use crate::{num::parse_points, rat, rational::ImplicitOutcome, rational::RationalBezier};
        let folium = RationalBezier::new(
            parse_points("0 0, 1 0, 2 1, 3/2 3/2", 2, None).unwrap(),
            vec![rat(1), rat(1), rat(1), rat(2)],
        )
        .unwrap();
        assert!(matches!(
            prove_implicit(&folium, "x^3 - 3*x*y + y^3").unwrap(),
            ImplicitOutcome::Proved { degree_bound: 9, .. }
        ));
        assert!(matches!(
            prove_implicit(&folium, "x^3 - 2*x*y + y^3").unwrap(),
            ImplicitOutcome::Counterexample { .. }
        ));
    }
}
