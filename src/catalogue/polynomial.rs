//! Claim kinds about polynomial curves and the Bernstein basis (seeds 001 and 003): identities,
//! formulas, power forms, subdivision, matrices and tables.

use crate::catalogue::common::{
    MAX_TABLE_DEGREE, Outcome, bad, compare, curve_from, num, parameters_of, points_of, rational_curve, verdict,
};
use crate::curve::bezier::BezierCurve;
use crate::curve::casteljau::subdivision_intervals;
use crate::curve::fraction_free;
use crate::error::Result;
use crate::num::fraction::Fraction;
use crate::num::parse::parse_points;
use crate::num::point::Point;
use crate::num::scalar::{Scalar, rat};
use crate::poly::bernstein::{bernstein, bernstein_to_power_matrix};
use crate::proof::expr::{Env, EvalError, Expr, parse_expr};
use crate::proof::{self, GridProver};
use num_rational::BigRational;
use serde::Deserialize;

/// `identity`: `lhs ≡ rhs` in the variables `vars`, for every instance of the integer `params`.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Identity {
    /// The variables, each of degree bounded by the expressions.
    #[serde(default)]
    pub vars: Vec<String>,
    /// Integer parameters, `"n in 0..=40"`, `"j in 0..=n"`, `"k in 1..n"`.
    #[serde(default)]
    pub params: Vec<String>,
    /// Left-hand side expression.
    pub lhs: String,
    /// Right-hand side expression.
    pub rhs: String,
}

/// `curve-formula`: the (rational) curve equals the formulas `x(t)`, `y(t)`[, `z(t)`].
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CurveFormula {
    /// Control points, `"x0 y0, x1 y1, …"`.
    pub curve: Option<String>,
    /// Weights (a rational curve).
    pub weights: Option<String>,
    /// Homogeneous control points instead of `curve` and `weights`.
    pub homogeneous: Option<String>,
    /// Formula for x(t).
    pub x: String,
    /// Formula for y(t).
    pub y: String,
    /// Formula for z(t).
    pub z: Option<String>,
}

/// `power-form`: the power coefficients of the curve (seed 003's matrix product).
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PowerForm {
    /// Control points.
    pub curve: String,
    /// Power coefficients `[[x, y], …]`, lowest degree first.
    pub power: Vec<Vec<String>>,
}

impl PowerForm {
    /// Exact comparison with the fraction-free power coefficients.
    ///
    /// # Errors
    /// Malformed numbers or polygons.
    pub fn check(&self) -> Result<Outcome> {
        let curve = curve_from(&self.curve)?;
        let expected = points_of(&self.power)?;
        Ok(compare(&fraction_free::power_coefficients(&curve), &expected, "power coefficients"))
    }
}

/// `subdivision`: the two halves at `t` (Lemma 2 of seed 001).
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Subdivision {
    /// Control points.
    pub curve: String,
    /// The split parameter.
    pub t: String,
    /// The printed left polygon.
    pub left: String,
    /// The printed right polygon.
    pub right: String,
}

/// `lemma-2`: Lemma 2 for every curve of degree `n ≤ degree`.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Lemma2 {
    /// The largest degree.
    pub degree: usize,
}

/// `repeated-subdivision`: `depth` rounds of splitting at `t` give `pieces` pieces.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RepeatedSubdivision {
    /// Control points.
    pub curve: String,
    /// The split parameter.
    pub t: String,
    /// The depth.
    pub depth: u32,
    /// The number of pieces.
    pub pieces: usize,
}

/// `matrix`: the Bernstein → power matrix of a degree.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Matrix {
    /// The degree `n`.
    pub degree: usize,
    /// The printed rows.
    pub rows: Vec<Vec<String>>,
}

impl Matrix {
    /// Entry-by-entry exact comparison with `A[k][i] = (−1)^(k−i) C(n,k) C(k,i)`.
    ///
    /// # Errors
    /// Malformed numbers.
    pub fn check(&self) -> Result<Outcome> {
        let (n, rows) = (self.degree, &self.rows);
        if n > MAX_TABLE_DEGREE {
            return Err(bad(format!("degree = {n} is more than the limit {MAX_TABLE_DEGREE}")));
        }
        let computed = bernstein_to_power_matrix(n);
        for (k, row) in rows.iter().enumerate() {
            for (i, v) in row.iter().enumerate() {
                let truth = computed.get(k).and_then(|r| r.get(i)).map(|x| BigRational::from_integer(x.clone()));
                if truth.as_ref() != Some(&num(v)?) {
                    let truth = truth.map_or("nothing".into(), |t| t.to_string());
                    return Ok(verdict(false, "exact-compare", format!("entry ({k}, {i}) printed {v}, is {truth}")));
                }
            }
        }
        if rows.len() != n + 1 || rows.iter().any(|r| r.len() != n + 1) {
            return Ok(verdict(false, "exact-compare", format!("not a {0}×{0} matrix", n + 1)));
        }
        Ok(verdict(true, "exact-compare", format!("{0}×{0} matrix equals A[k][i] = (-1)^(k-i) C(n,k) C(k,i)", n + 1)))
    }
}

/// `table`: exact values of the curve at `ts` (or `k/steps`).
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Table {
    /// Control points.
    pub curve: String,
    /// Parameter values.
    pub ts: Option<Vec<String>>,
    /// `t = k/steps` for `k = 0..=steps`.
    pub steps: Option<u32>,
    /// The printed values `[[x, y], …]`.
    pub values: Vec<Vec<String>>,
}

impl Table {
    /// Exact evaluation at every parameter, compared with the printed values.
    ///
    /// # Errors
    /// Malformed numbers, or neither `ts` nor `steps`.
    pub fn check(&self) -> Result<Outcome> {
        let curve = curve_from(&self.curve)?;
        let ts = parameters_of(&self.ts, self.steps)?;
        let ic = fraction_free::IntegerCurve::new(&curve);
        let computed: Vec<_> = ts.iter().map(|t| fraction_free::eval_integer(&ic, t)).collect();
        Ok(compare(&computed, &points_of(&self.values)?, "table rows"))
    }
}

/// `basis-table`: `B_i^n(t_k)` exactly.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BasisTable {
    /// The degree `n`.
    pub degree: usize,
    /// Parameter values.
    pub ts: Option<Vec<String>>,
    /// `t = k/steps` for `k = 0..=steps`.
    pub steps: Option<u32>,
    /// Row `i`: `B_i^n` at every parameter.
    pub rows: Vec<Vec<String>>,
}

impl BasisTable {
    /// Every printed value compared with the exact Bernstein polynomial.
    ///
    /// # Errors
    /// Malformed numbers, or neither `ts` nor `steps`.
    pub fn check(&self) -> Result<Outcome> {
        let n = self.degree;
        if n > MAX_TABLE_DEGREE {
            return Err(bad(format!("degree = {n} is more than the limit {MAX_TABLE_DEGREE}")));
        }
        let ts = parameters_of(&self.ts, self.steps)?;
        for (i, row) in self.rows.iter().enumerate() {
            for (t, v) in ts.iter().zip(row) {
                let b = bernstein(i, n, t);
                if b != num(v)? {
                    return Ok(verdict(false, "exact-eval", format!("B_{i}^{n}({t}) printed {v}, is {b}")));
                }
            }
        }
        Ok(verdict(true, "exact-eval", format!("all {} values exact", (n + 1) * ts.len())))
    }
}

/// Grid values for variable `var`: family 0 is `0, 1, −1, 2, −2, …`; family 1 shifts them by an
/// integer that differs per variable (integers keep the arithmetic on the fast path); family
/// `f > 1` by a fraction that differs per variable and family — so that a denominator vanishing
/// on one family (typically where variables are 0 or equal) misses the next grid.
fn nodes(degree: usize, var: usize, family: usize) -> Vec<Fraction> {
    let shift = match family {
        0 => Fraction::zero(),
        1 => Fraction::from_i64(7 * var as i64 + 3),
        _ => Fraction::from(BigRational::new((((family * 37 + var * 61 + 11) % 97) as i64 + 1).into(), 101.into())),
    };
    (0..=degree as i64).map(|i| Fraction::from_i64(if i % 2 == 1 { (i + 1) / 2 } else { -(i / 2) }) + &shift).collect()
}

/// Families of grid values tried before a claim is declared undecidable on grids.
pub const NODE_FAMILIES: usize = 12;

/// Proves `f ≡ 0` for `f` of degree ≤ `degrees[j]` in variable `j`, replacing the grid when `f`
/// is undefined at a point. `Ok(Ok(points))`, `Ok(Err(counterexample))`, or `Err` when no
/// family avoids the poles.
fn grid_prove(
    degrees: &[usize],
    mut f: impl FnMut(&[Fraction]) -> std::result::Result<Vec<Fraction>, EvalError>,
) -> Result<std::result::Result<usize, proof::Counterexample<Fraction>>> {
    for family in 0..NODE_FAMILIES {
        let grid =
            GridProver::with_nodes(degrees, degrees.iter().enumerate().map(|(v, &d)| nodes(d, v, family)).collect())?;
        match grid.try_check_all(&mut f) {
            Ok(Ok(cert)) => return Ok(Ok(cert.points_checked)),
            Ok(Err(ce)) => return Ok(Err(ce)),
            Err(EvalError::DivisionByZero) => continue,
            Err(EvalError::Invalid(m)) => return Err(bad(m)),
        }
    }
    Err(bad(format!("every one of {NODE_FAMILIES} grid families meets a vanishing denominator")))
}

/// `name in a..=b` / `name in a..b`.
fn parse_param(spec: &str) -> Result<(String, Expr, Expr, bool)> {
    let (name, range) =
        spec.split_once(" in ").ok_or_else(|| bad(format!("parameter {spec:?}: write `n in 0..=40`")))?;
    let (lo, hi, inclusive) = if let Some((a, b)) = range.split_once("..=") {
        (a, b, true)
    } else if let Some((a, b)) = range.split_once("..") {
        (a, b, false)
    } else {
        return Err(bad(format!("parameter {spec:?}: the range is a..=b or a..b")));
    };
    Ok((name.trim().to_string(), parse_expr(lo.trim())?, parse_expr(hi.trim())?, inclusive))
}

/// Every assignment of the integer parameters, in order.
/// Most values one integer parameter may range over.
pub const MAX_PARAMETER_RANGE: usize = 100_000;

/// Most parameter instances of one identity claim.
pub const MAX_INSTANCES: usize = 100_000;

fn instances(params: &[(String, Expr, Expr, bool)]) -> Result<Vec<Env>> {
    let mut out = vec![Env::new()];
    for (name, lo, hi, inclusive) in params {
        let mut next = Vec::new();
        for env in out {
            let mut e = env.clone();
            let int = |x: &Expr, e: &mut Env| -> Result<i64> {
                let v = x.eval(e).map_err(|m| bad(format!("range of {name}: {m:?}")))?;
                v.to_big().to_integer().try_into().map_err(|_| bad(format!("range of {name} is not a small integer")))
            };
            let (a, b) = (int(lo, &mut e)?, int(hi, &mut e)?);
            let b = if *inclusive { b } else { b.saturating_sub(1) };
            // i128: no overflow for any i64 range
            if (b as i128) - (a as i128) >= MAX_PARAMETER_RANGE as i128 {
                return Err(bad(format!("parameter {name} ranges over more than {MAX_PARAMETER_RANGE} values")));
            }
            for k in a..=b {
                // the cap is checked while the list grows, never after building it
                if next.len() >= MAX_INSTANCES {
                    return Err(bad(format!("more than {MAX_INSTANCES} parameter instances")));
                }
                let mut v = env.clone();
                v.push((name.clone(), Fraction::from_i64(k)));
                next.push(v);
            }
        }
        out = next;
    }
    Ok(out)
}

fn show_env(env: &Env) -> String {
    env.iter().map(|(n, v)| format!("{n} = {v}")).collect::<Vec<_>>().join(", ")
}

impl Identity {
    /// Grid proof per parameter instance (see the module docs).
    ///
    /// # Errors
    /// Malformed expressions or parameter ranges.
    pub fn check(&self) -> Result<Outcome> {
        let c = self;
        let lhs = parse_expr(&c.lhs)?;
        let rhs = parse_expr(&c.rhs)?;
        let diff = Expr::Bin('-', Box::new(lhs), Box::new(rhs));
        let params: Vec<_> = c.params.iter().map(|p| parse_param(p)).collect::<Result<_>>()?;
        let envs = instances(&params)?;
        // instances are independent: rayon shares the cores with the other claims being checked
        let results: Vec<Result<Instance>> = {
            use rayon::prelude::*;
            // the caller's fold-term limit applies on every worker thread
            let steps = crate::proof::expr::current_steps();
            envs.par_iter()
                .map(|env| crate::proof::expr::with_steps(steps.clone(), || identity_instance(&diff, &c.vars, env)))
                .collect()
        };
        let mut points = 0;
        let mut largest: Vec<usize> = vec![];
        for (env, r) in envs.iter().zip(results) {
            let (degrees, res) = r?;
            match res {
                Ok(p) => {
                    points += p;
                    if degrees.iter().sum::<usize>() >= largest.iter().sum() {
                        largest = degrees;
                    }
                }
                Err(ce) => {
                    let at = if env.is_empty() { String::new() } else { format!("at {}: ", show_env(env)) };
                    return Ok(verdict(false, "grid", format!("{at}{ce}")));
                }
            }
        }
        let shape: Vec<String> = largest.iter().map(|d| (d + 1).to_string()).collect();
        Ok(verdict(
            true,
            "grid",
            format!(
                "{} instance{}, degree bounds derived per instance (largest grid {}), {points} exact points",
                envs.len(),
                if envs.len() == 1 { "" } else { "s" },
                if shape.is_empty() { "1".into() } else { shape.join("×") }
            ),
        ))
    }
}

type Instance = (Vec<usize>, std::result::Result<usize, String>);

fn identity_instance(diff: &Expr, vars: &[String], env: &Env) -> Result<Instance> {
    let mut p = env.clone();
    let degrees: Vec<usize> = vars
        .iter()
        .map(|v| diff.degree(v, &mut p).map(|d| d.0).map_err(|e| bad(format!("{e:?}"))))
        .collect::<Result<_>>()?;
    // the grid is known only now: charge its points (each an evaluation of the whole tree)
    // against the step budget before evaluating any of them
    let points = degrees.iter().fold(1u64, |p, &d| p.saturating_mul(d as u64 + 1));
    // each point's value is a polynomial of total degree D at grid values of about
    // log₂(d + 1) + 4 bits: numbers of D times that many bits, whose products the tree pays
    let value_bits: u64 = degrees.iter().map(|&d| d as u64 * (u64::from(usize::BITS - d.leading_zeros()) + 4)).sum();
    let products = (crate::work::power(value_bits) / crate::work::UNITS_PER_STEP).min(u64::MAX as f64) as u64;
    crate::proof::expr::charge_steps(points.saturating_mul((1 + diff.size() as u64 / 8).saturating_add(products)))
        .map_err(|e| bad(e.to_string()))?;
    let res = grid_prove(&degrees, |x| {
        let mut e = env.clone();
        e.extend(vars.iter().cloned().zip(x.iter().cloned()));
        diff.eval(&mut e).map(|v| vec![v])
    })?;
    Ok((
        degrees,
        res.map_err(|ce| {
            let pt: Vec<String> = vars.iter().zip(&ce.point).map(|(n, v)| format!("{n} = {v}")).collect();
            format!("({}) lhs − rhs = {}", pt.join(", "), ce.value)
        }),
    ))
}

impl CurveFormula {
    /// Grid proof in `t` after cross-multiplying by the denominator.
    ///
    /// # Errors
    /// Malformed curve or formulas, or a count of formulas other than the dimension.
    pub fn check(&self) -> Result<Outcome> {
        let c = self;
        let rational = rational_curve(c.curve.as_deref(), c.weights.as_deref(), c.homogeneous.as_deref())?;
        let formulas: Vec<Expr> = [Some(&c.x), Some(&c.y), c.z.as_ref()]
            .iter()
            .filter_map(|f| *f)
            .map(|f| parse_expr(f))
            .collect::<Result<_>>()?;
        if formulas.len() != rational.dim() {
            return Err(bad(format!("{} formulas for a {}D curve", formulas.len(), rational.dim())));
        }
        let hom = rational.homogeneous().clone();
        let curve = &hom;
        let mut degree = 0;
        for f in &formulas {
            let (n, d) = f.degree("t", &mut Env::new()).map_err(|e| bad(format!("{e:?}")))?;
            degree = degree.max(curve.degree() + n.max(d));
        }
        let ic = fraction_free::IntegerCurve::new(&hom);
        let res = grid_prove(&[degree], |x| {
            let p = fraction_free::eval_integer(&ic, &x[0].to_big());
            let (w, xy) = p.coords.split_last().expect("homogeneous");
            if w.is_zero() {
                return Err(EvalError::DivisionByZero);
            }
            let mut env: Env = vec![("t".into(), x[0].clone())];
            formulas.iter().zip(xy).map(|(f, v)| Ok(Fraction::from(v.clone() / w) - f.eval(&mut env)?)).collect()
        })?;
        Ok(match res {
            Ok(points) => verdict(
                true,
                "grid",
                format!("curve ≡ formula: degree ≤ {degree} in t after cross-multiplying, {points} exact points"),
            ),
            Err(ce) => verdict(
                false,
                "grid",
                format!("at t = {}: coordinate {} differs by {}", ce.point[0], ce.identity, ce.value),
            ),
        })
    }
}

impl Subdivision {
    /// The printed halves compared exactly, then Lemma 2 proved for the curve.
    ///
    /// # Errors
    /// Malformed numbers or polygons.
    pub fn check(&self) -> Result<Outcome> {
        let c = self;
        let curve = curve_from(&c.curve)?;
        let t0 = num(&c.t)?;
        let (l, r) = fraction_free::subdivide(&curve, &t0);
        let expect =
            |f: &str| -> Result<BezierCurve<BigRational>> { BezierCurve::new(parse_points(f, curve.dim(), None)?) };
        if l != expect(&c.left)? || r != expect(&c.right)? {
            return Ok(verdict(false, "exact-compare", format!("computed halves {l} | {r}")));
        }
        let n = curve.degree();
        let res = proof::identities::<BigRational>(&[n], |v| {
            let s = &v[0];
            let dl = l.eval(s).sub(&curve.eval(&(t0.clone() * s)));
            let dr = r.eval(s).sub(&curve.eval(&(t0.clone() + (rat(1) - &t0) * s)));
            dl.coords.into_iter().chain(dr.coords).collect()
        });
        Ok(match res {
            Ok(cert) => verdict(
                true,
                "grid",
                format!("halves exact; left(s) ≡ b(t0 s), right(s) ≡ b(t0 + (1−t0)s) proved: {cert}"),
            ),
            Err(e) => verdict(false, "grid", e.to_string()),
        })
    }
}

impl RepeatedSubdivision {
    /// Every piece proved equal to the curve on its parameter interval.
    ///
    /// # Errors
    /// Malformed numbers or polygons, or a depth past the subdivision limit.
    pub fn check(&self) -> Result<Outcome> {
        let c = self;
        let curve = curve_from(&c.curve)?;
        let t0 = num(&c.t)?;
        let depth = c.depth;
        let pieces = fraction_free::subdivide_repeatedly(&curve, &t0, depth)?;
        if pieces.len() != c.pieces {
            return Ok(verdict(false, "exact-compare", format!("{} pieces", pieces.len())));
        }
        for (k, (piece, (a, b))) in pieces.iter().zip(subdivision_intervals(&t0, depth)).enumerate() {
            let res = proof::identities::<BigRational>(&[curve.degree()], |v| {
                piece.eval(&v[0]).sub(&curve.eval(&(a.clone() + (b.clone() - &a) * &v[0]))).coords
            });
            if let Err(e) = res {
                return Ok(verdict(false, "grid", format!("piece {k}: {e}")));
            }
        }
        Ok(verdict(
            true,
            "grid",
            format!("{} pieces, each proved equal to the curve on its parameter interval", pieces.len()),
        ))
    }
}

/// Lemma 2 of seed 001 for all curves of degree `1..=max`: with the control points `b_0..b_n`
/// as variables, `Σ_r b_0^r(t0) B_r^n(s) ≡ b(t0·s)` and `Σ_r b_r^{n−r}(t0) B_r^n(s) ≡
/// b(t0 + (1−t0)s)`; degree 1 in each `b_j` and `n` in `t0` and `s`.
impl Lemma2 {
    /// Lemma 2 with the control points as variables, for every degree up to `degree` (≤ 8).
    ///
    /// # Errors
    /// A degree above 8.
    pub fn check(&self) -> Result<Outcome> {
        let max = self.degree;
        if max > 8 {
            return Err(bad("lemma-2 is checked up to degree 8 (2^(n+1)·(n+1)² grid points)"));
        }
        let mut total = 0;
        for n in 1..=max {
            let mut degrees = vec![1; n + 1];
            degrees.extend([n, n]);
            let res = proof::identities::<Fraction>(&degrees, |v| {
                let (b, rest) = v.split_at(n + 1);
                let (t0, s) = (&rest[0], &rest[1]);
                let curve = BezierCurve::new(b.iter().map(|x| Point::new(vec![x.clone()])).collect()).expect("points");
                let tri = crate::curve::casteljau::triangle(&curve, t0);
                let left = BezierCurve::new(tri.left_polygon()).expect("n+1 points");
                let right = BezierCurve::new(tri.right_polygon()).expect("n+1 points");
                let one = Fraction::one();
                let dl = left.eval_bernstein(s).sub(&curve.eval(&(t0.clone() * s)));
                let dr = right.eval_bernstein(s).sub(&curve.eval(&(t0.clone() + (one - t0) * s)));
                vec![dl.coords[0].clone(), dr.coords[0].clone()]
            });
            match res {
                Ok(cert) => total += cert.points_checked,
                Err(e) => return Ok(verdict(false, "grid", format!("degree {n}: {e}"))),
            }
        }
        Ok(verdict(
            true,
            "grid",
            format!("proved for every curve of degree 1..={max} (control points as variables), {total} exact points"),
        ))
    }
}
