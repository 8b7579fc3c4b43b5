//! The kinds of claim a `proofs/` file can state, and how each is checked exactly.
//!
//! | kind | fields | check |
//! | --- | --- | --- |
//! | `identity` | `vars`, `params`, `lhs`, `rhs` | grid proof per parameter instance; degree bounds derived from the expressions |
//! | `curve-formula` | `curve`, `weights?`, `x`, `y`, `z?` (expressions in `t`) | grid proof in `t` that the (rational) curve equals the formula |
//! | `power-form` | `curve`, `power` | exact power coefficients (seed 003's matrix product) |
//! | `subdivision` | `curve`, `t`, `left`, `right` | exact halves, and Lemma 2 proved for the curve |
//! | `lemma-2` | `degree` | Lemma 2 for every curve of degree `n ≤ degree`: control points as variables (degree 1 each), `t0`, `s` (degree `n`) |
//! | `repeated-subdivision` | `curve`, `t`, `depth`, `pieces` | every piece proved equal to the curve on its interval |
//! | `matrix` | `degree`, `rows` | the Bernstein → power matrix |
//! | `table` | `curve`, `steps` or `ts`, `values` | exact values at the parameters |
//! | `basis-table` | `degree`, `steps`, `rows` | `B_i^n(t_k)` exactly |
//! | `classification` | `curve`, optional `class`, `node_type`, `double_point`, `parameters`, `segment_*` | exact classification |
//! | `moving-lines` | `curve` | seed 004 (3)–(8) proved and compared with the power-form route |
//! | `implicit` | `curve` + `weights`, or `homogeneous`; `poly` | `W^d f(X/W) ≡ 0`, degree ≤ `n·d`: proved at `n·d + 1` parameters (seed 000 examples) |
//! | `rational-evaluations` | rational curve | closed form (14), seed 000's recursion and Saito–Hosaka (19)–(20) are rational functions of type ≤ `(n, n)` in `t`, so agreeing at `2n + 1` parameters proves them equal |
//! | `rational-elevation` | rational curve | (22) gives the homogeneous elevation's points and weights |
//! | `weight-pull` | rational curve, `index`, `weight` | raising a weight moves every point of `(0, 1)` strictly towards that control point: (23) with `γ_i = B_i^n` proved, `γ_iΔw > 0` and `W > 0` on `(0, 1)` |
//! | `spline-segments` | `curve`, `weights`, `ratios`, `degree`, `method` | the rational Bézier segments equal the NURBS on each span (type-bounded grid) and join `C^{n−1}` |
//! | `patch-evaluations` | `net` (one patch), `net_weights` | closed form (41), de Casteljau `u`-then-`v` and `v`-then-`u` agree on a `(2m+1)×(2n+1)` grid (rational of type `(m,m)×(n,n)`) |
//! | `patch-weight-change` | patch, `index`, `index_v`, `weight` (Δw), `formulas` | (48)–(49) with the printed `γ` or the Bernstein one, on the type-bounded grid |
//! | `net` | `net`, `net_weights`, `ratios`, `ratios_v`, `degrees`, `method` | every patch equals the tensor NURBS, joins are `C^{min−1}`, and rows-first = columns-first |
//! | `moving-line-2` | `curve`, `formulas` | seed 004 (2): `P[τ] × P[t] = (t − τ)·r(τ)·M·c(t)`, degree ≤ 3 in `τ` and `t` (4×4 grid); as printed `r(τ)` is the scalar `(1−τ)²(1−t)τ − τ²` applied to the sum of the rows |
//! | `canonical-map` | `curve`, `formulas` | the affine map from the canonical cubic, proved in `Q(√3)(√r)` |

use crate::BezierCurve;
use crate::catalogue::claim_checks_geometry as geometry;
use crate::classify::canonical::{Formulas, canonical_map};
use crate::classify::moving_line::MovingLines;
use crate::classify::{NodeType, classify};
use crate::curve::casteljau::{subdivide_repeatedly, subdivision_intervals};
use crate::curve::fraction_free;
use crate::error::{Error, Result};
use crate::num::parse::{parse_number, parse_points};
use crate::num::point::Point;
use crate::num::scalar::{Exact, Rational, Scalar, rat};
use crate::poly::bernstein::{bernstein, bernstein_to_power_matrix};
use crate::proof::expr::{Env, EvalError, Expr, parse_expr};
use crate::proof::{self, GridProver};
use num_rational::BigRational;
use serde::Deserialize;

/// One claim's checkable content (every kind's fields; each kind reads its own).
#[derive(Clone, Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Content {
    /// The kind (see the module table).
    pub kind: String,
    /// Variables of an identity.
    #[serde(default)]
    pub vars: Vec<String>,
    /// Integer parameters, `"n in 0..=40"`, `"j in 0..=n"`, `"k in 1..n"`.
    #[serde(default)]
    pub params: Vec<String>,
    /// Left-hand side expression.
    pub lhs: Option<String>,
    /// Right-hand side expression.
    pub rhs: Option<String>,
    /// Control points, `"x0 y0, x1 y1, …"`.
    pub curve: Option<String>,
    /// Weights of a rational curve.
    pub weights: Option<String>,
    /// Homogeneous control points `w·x w·y w, …` (a rational curve; `w = 0` at infinity).
    pub homogeneous: Option<String>,
    /// An implicit polynomial in `x, y[, z]`.
    pub poly: Option<String>,
    /// A control point index.
    pub index: Option<usize>,
    /// A new weight.
    pub weight: Option<String>,
    /// A second index (the `v` index of a patch control point).
    pub index_v: Option<usize>,
    /// Scale ratios along `u` (splines, nets).
    pub ratios: Option<String>,
    /// Scale ratios along `v` (nets).
    pub ratios_v: Option<String>,
    /// A patch or net: rows separated by `;`, points by `,`.
    pub net: Option<String>,
    /// Weights of a patch or net: rows separated by `;`.
    pub net_weights: Option<String>,
    /// Degrees `"nu,nv"` of a net (default `2,2`).
    pub degrees: Option<String>,
    /// `seed`, `seed-printed` or `boehm` (spline and net conversions).
    pub method: Option<String>,
    /// Formula for x(t).
    pub x: Option<String>,
    /// Formula for y(t).
    pub y: Option<String>,
    /// Formula for z(t).
    pub z: Option<String>,
    /// Power coefficients `[[x, y], …]`.
    pub power: Option<Vec<Vec<String>>>,
    /// A parameter value.
    pub t: Option<String>,
    /// Parameter values of a table.
    pub ts: Option<Vec<String>>,
    /// `t = k/steps` for `k = 0..=steps`.
    pub steps: Option<u32>,
    /// Left control polygon.
    pub left: Option<String>,
    /// Right control polygon.
    pub right: Option<String>,
    /// Subdivision depth.
    pub depth: Option<u32>,
    /// Number of pieces.
    pub pieces: Option<usize>,
    /// A degree.
    pub degree: Option<usize>,
    /// Matrix or table rows.
    pub rows: Option<Vec<Vec<String>>>,
    /// Table values `[[x, y], …]`.
    pub values: Option<Vec<Vec<String>>>,
    /// Expected class name.
    pub class: Option<String>,
    /// Expected node type.
    pub node_type: Option<String>,
    /// Expected double point.
    pub double_point: Option<Vec<String>>,
    /// Expected double-point (or cusp) parameters.
    pub parameters: Option<Vec<String>>,
    /// Expected inflection parameters.
    pub inflections: Option<Vec<String>>,
    /// Expected: loop on [0, 1].
    pub segment_loop: Option<bool>,
    /// Expected: cusp on [0, 1].
    pub segment_cusp: Option<bool>,
    /// Expected: inflections on [0, 1].
    pub segment_inflections: Option<usize>,
    /// `as-printed` or `corrected` (canonical maps).
    pub formulas: Option<String>,
}

/// The result of one check: whether the statement holds, how it was checked, and the evidence.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Outcome {
    /// The statement holds.
    pub holds: bool,
    /// `grid`, `exact-compare`, `exact-eval`, …
    pub method: &'static str,
    /// Certificate or counterexample, in words.
    pub detail: String,
}

pub(crate) fn bad(message: impl Into<String>) -> Error {
    Error::InvalidArgument { message: message.into() }
}
pub(crate) fn need<'a, T>(v: &'a Option<T>, field: &str) -> Result<&'a T> {
    v.as_ref().ok_or_else(|| bad(format!("missing field `{field}`")))
}
pub(crate) fn num(s: &str) -> Result<BigRational> {
    parse_number(s.trim(), Default::default())
}
pub(crate) fn curve_of(c: &Content) -> Result<BezierCurve<BigRational>> {
    let text = need(&c.curve, "curve")?;
    let dim = if text.contains(',') { text.split(',').next().map_or(2, |p| p.split_whitespace().count()) } else { 2 };
    BezierCurve::new(parse_points(text, dim, None)?)
}
fn points_of(rows: &[Vec<String>]) -> Result<Vec<Point<BigRational>>> {
    rows.iter().map(|r| Ok(Point::new(r.iter().map(|v| num(v)).collect::<Result<_>>()?))).collect()
}
fn parameters_of(c: &Content) -> Result<Vec<BigRational>> {
    match (&c.ts, c.steps) {
        (Some(ts), _) => ts.iter().map(|t| num(t)).collect(),
        (None, Some(n)) if n > 0 => Ok((0..=n).map(|k| BigRational::new(k.into(), n.into())).collect()),
        _ => Err(bad("a table needs `ts` or `steps`")),
    }
}
pub(crate) fn verdict(holds: bool, method: &'static str, detail: String) -> Outcome {
    Outcome { holds, method, detail }
}

/// Checks one claim's content.
///
/// # Errors
/// A malformed claim (missing field, bad number or expression, unknown kind).
pub fn check(c: &Content) -> Result<Outcome> {
    match c.kind.as_str() {
        "identity" => identity(c),
        "curve-formula" => curve_formula(c),
        "power-form" => {
            let curve = curve_of(c)?;
            let expected = points_of(need(&c.power, "power")?)?;
            Ok(compare(&fraction_free::power_coefficients(&curve), &expected, "power coefficients"))
        }
        "subdivision" => subdivision(c),
        "lemma-2" => lemma_2(*need(&c.degree, "degree")?),
        "repeated-subdivision" => repeated_subdivision(c),
        "matrix" => {
            let n = *need(&c.degree, "degree")?;
            let rows = need(&c.rows, "rows")?;
            let computed = bernstein_to_power_matrix(n);
            for (k, row) in rows.iter().enumerate() {
                for (i, v) in row.iter().enumerate() {
                    let truth = computed.get(k).and_then(|r| r.get(i)).map(|x| BigRational::from_integer(x.clone()));
                    if truth.as_ref() != Some(&num(v)?) {
                        let truth = truth.map_or("nothing".into(), |t| t.to_string());
                        return Ok(verdict(
                            false,
                            "exact-compare",
                            format!("entry ({k}, {i}) printed {v}, is {truth}"),
                        ));
                    }
                }
            }
            if rows.len() != n + 1 || rows.iter().any(|r| r.len() != n + 1) {
                return Ok(verdict(false, "exact-compare", format!("not a {0}×{0} matrix", n + 1)));
            }
            Ok(verdict(
                true,
                "exact-compare",
                format!("{0}×{0} matrix equals A[k][i] = (-1)^(k-i) C(n,k) C(k,i)", n + 1),
            ))
        }
        "table" => {
            let curve = curve_of(c)?;
            let ts = parameters_of(c)?;
            let ic = fraction_free::IntegerCurve::new(&curve);
            let computed: Vec<_> = ts.iter().map(|t| fraction_free::eval_integer(&ic, t)).collect();
            Ok(compare(&computed, &points_of(need(&c.values, "values")?)?, "table rows"))
        }
        "basis-table" => {
            let n = *need(&c.degree, "degree")?;
            let ts = parameters_of(c)?;
            for (i, row) in need(&c.rows, "rows")?.iter().enumerate() {
                for (t, v) in ts.iter().zip(row) {
                    let b = bernstein(i, n, t);
                    if b != num(v)? {
                        return Ok(verdict(false, "exact-eval", format!("B_{i}^{n}({t}) printed {v}, is {b}")));
                    }
                }
            }
            Ok(verdict(true, "exact-eval", format!("all {} values exact", (n + 1) * ts.len())))
        }
        "classification" => classification(c),
        "moving-lines" => moving_lines(c),
        "moving-line-2" => moving_line_2(c),
        "implicit" => geometry::implicit(c),
        "rational-evaluations" => geometry::rational_evaluations(&geometry::rational_of(c)?),
        "rational-elevation" => geometry::rational_elevation(c),
        "weight-pull" => geometry::weight_pull(c),
        "spline-segments" => geometry::spline_segments(c),
        "patch-evaluations" => geometry::patch_evaluations(c),
        "patch-weight-change" => geometry::patch_weight_change(c),
        "net" => geometry::net(c),
        "rational-subdivision" => geometry::rational_subdivision(c),
        "canonical-map" => {
            let curve = curve_of(c)?;
            let formulas = match c.formulas.as_deref() {
                Some("as-printed") | None => Formulas::AsPrinted,
                Some("corrected") => Formulas::Corrected,
                Some(other) => return Err(bad(format!("formulas must be as-printed or corrected, not {other:?}"))),
            };
            Ok(match canonical_map(&curve, formulas) {
                Ok(m) => match m.prove(&curve) {
                    Ok(cert) => verdict(true, "grid", format!("M·C(t̃) ≡ P(t) in Q(√3)(√r): {cert}")),
                    Err(e) => {
                        let pts: Vec<String> = m.points.iter().map(|(n, p)| format!("{n} = {p}")).collect();
                        verdict(false, "grid", format!("{}; {e}", pts.join(", ")))
                    }
                },
                Err(e) => verdict(false, "exact-compare", e.to_string()),
            })
        }
        other => Err(bad(format!("unknown kind {other:?}"))),
    }
}

fn compare(computed: &[Point<BigRational>], expected: &[Point<BigRational>], what: &str) -> Outcome {
    if computed.len() != expected.len() {
        return verdict(
            false,
            "exact-compare",
            format!("{} {what} computed, {} printed", computed.len(), expected.len()),
        );
    }
    match computed.iter().zip(expected).position(|(a, b)| a != b) {
        None => verdict(true, "exact-compare", format!("all {} {what} equal exactly", computed.len())),
        Some(k) => {
            verdict(false, "exact-compare", format!("{what}: entry {k} printed {} but is {}", expected[k], computed[k]))
        }
    }
}

/// Grid values for variable `var`: family 0 is `0, 1, −1, 2, −2, …`; family 1 shifts them by an
/// integer that differs per variable (integers keep the arithmetic on the fast path); family
/// `f > 1` by a fraction that differs per variable and family — so that a denominator vanishing
/// on one family (typically where variables are 0 or equal) misses the next grid.
fn nodes(degree: usize, var: usize, family: usize) -> Vec<Rational> {
    let shift = match family {
        0 => Rational::zero(),
        1 => Rational::from_i64(7 * var as i64 + 3),
        _ => Rational(BigRational::new((((family * 37 + var * 61 + 11) % 97) as i64 + 1).into(), 101.into())),
    };
    (0..=degree as i64).map(|i| Rational::from_i64(if i % 2 == 1 { (i + 1) / 2 } else { -(i / 2) }) + &shift).collect()
}

/// Families of grid values tried before a claim is declared undecidable on grids.
pub const NODE_FAMILIES: usize = 12;

/// Proves `f ≡ 0` for `f` of degree ≤ `degrees[j]` in variable `j`, replacing the grid when `f`
/// is undefined at a point. `Ok(Ok(points))`, `Ok(Err(counterexample))`, or `Err` when no
/// family avoids the poles.
fn grid_prove(
    degrees: &[usize],
    mut f: impl FnMut(&[Rational]) -> std::result::Result<Vec<Rational>, EvalError>,
) -> Result<std::result::Result<usize, proof::Counterexample<Rational>>> {
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
fn instances(params: &[(String, Expr, Expr, bool)]) -> Result<Vec<Env>> {
    let mut out = vec![Env::new()];
    for (name, lo, hi, inclusive) in params {
        let mut next = Vec::new();
        for env in out {
            let mut e = env.clone();
            let int = |x: &Expr, e: &mut Env| -> Result<i64> {
                let v = x.eval(e).map_err(|m| bad(format!("range of {name}: {m:?}")))?;
                v.0.to_integer().try_into().map_err(|_| bad(format!("range of {name} is not a small integer")))
            };
            let (a, b) = (int(lo, &mut e)?, int(hi, &mut e)?);
            let b = if *inclusive { b } else { b - 1 };
            if b - a > 100_000 {
                return Err(bad(format!("parameter {name} ranges over more than 100000 values")));
            }
            for k in a..=b {
                let mut v = env.clone();
                v.push((name.clone(), Rational::from_i64(k)));
                next.push(v);
            }
        }
        out = next;
        if out.len() > 1_000_000 {
            return Err(bad("more than 1000000 parameter instances"));
        }
    }
    Ok(out)
}

fn show_env(env: &Env) -> String {
    env.iter().map(|(n, v)| format!("{n} = {v}")).collect::<Vec<_>>().join(", ")
}

fn identity(c: &Content) -> Result<Outcome> {
    let lhs = parse_expr(need(&c.lhs, "lhs")?)?;
    let rhs = parse_expr(need(&c.rhs, "rhs")?)?;
    let diff = Expr::Bin('-', Box::new(lhs), Box::new(rhs));
    let params: Vec<_> = c.params.iter().map(|p| parse_param(p)).collect::<Result<_>>()?;
    let envs = instances(&params)?;
    let results: Vec<Result<Instance>> = std::thread::scope(|scope| {
        let workers = std::thread::available_parallelism().map_or(1, |n| n.get()).min(envs.len().max(1));
        // interleaved: instance i goes to worker i mod workers (instances grow along the list)
        let handles: Vec<_> = (0..workers)
            .map(|w| {
                let (diff, vars, envs) = (&diff, &c.vars, &envs);
                scope.spawn(move || {
                    envs.iter()
                        .enumerate()
                        .skip(w)
                        .step_by(workers)
                        .map(|(i, env)| (i, identity_instance(diff, vars, env)))
                        .collect::<Vec<_>>()
                })
            })
            .collect();
        let mut all: Vec<_> = handles.into_iter().flat_map(|h| h.join().expect("worker finished")).collect();
        all.sort_by_key(|(i, _)| *i);
        all.into_iter().map(|(_, r)| r).collect()
    });
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

type Instance = (Vec<usize>, std::result::Result<usize, String>);

fn identity_instance(diff: &Expr, vars: &[String], env: &Env) -> Result<Instance> {
    let mut p = env.clone();
    let degrees: Vec<usize> = vars
        .iter()
        .map(|v| diff.degree(v, &mut p).map(|d| d.0).map_err(|e| bad(format!("{e:?}"))))
        .collect::<Result<_>>()?;
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

fn curve_formula(c: &Content) -> Result<Outcome> {
    let rational = geometry::rational_of(c)?;
    let formulas: Vec<Expr> =
        [&c.x, &c.y, &c.z].iter().filter_map(|f| f.as_ref()).map(|f| parse_expr(f)).collect::<Result<_>>()?;
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
        let p = fraction_free::eval_integer(&ic, &x[0].0);
        let (w, xy) = p.coords.split_last().expect("homogeneous");
        if w.is_zero() {
            return Err(EvalError::DivisionByZero);
        }
        let mut env: Env = vec![("t".into(), x[0].clone())];
        formulas.iter().zip(xy).map(|(f, v)| Ok(Rational(v.clone() / w) - f.eval(&mut env)?)).collect()
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

fn subdivision(c: &Content) -> Result<Outcome> {
    let curve = curve_of(c)?;
    let t0 = num(need(&c.t, "t")?)?;
    let (l, r) = fraction_free::subdivide(&curve, &t0);
    let expect = |f: &Option<String>, name: &str| -> Result<BezierCurve<BigRational>> {
        BezierCurve::new(parse_points(need(f, name)?, curve.dim(), None)?)
    };
    if l != expect(&c.left, "left")? || r != expect(&c.right, "right")? {
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
        Ok(cert) => {
            verdict(true, "grid", format!("halves exact; left(s) ≡ b(t0 s), right(s) ≡ b(t0 + (1−t0)s) proved: {cert}"))
        }
        Err(e) => verdict(false, "grid", e.to_string()),
    })
}

fn repeated_subdivision(c: &Content) -> Result<Outcome> {
    let curve = curve_of(c)?;
    let t0 = num(need(&c.t, "t")?)?;
    let depth = *need(&c.depth, "depth")?;
    let pieces = subdivide_repeatedly(&curve, &t0, depth)?;
    if Some(pieces.len()) != c.pieces {
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

fn classification(c: &Content) -> Result<Outcome> {
    let curve = curve_of(c)?;
    let k = classify(&curve)?;
    let mut wrong = Vec::new();
    let mut check = |what: &str, found: String, expected: Option<String>| {
        if let Some(e) = expected
            && e != found
        {
            wrong.push(format!("{what} expected {e}, found {found}"));
        }
    };
    check("class", k.class.as_str().into(), c.class.clone());
    check("node_type", k.node_type.map_or("none".into(), |n| n.as_str().into()), c.node_type.clone());
    check(
        "double_point",
        k.double_point.as_ref().map_or("none".into(), |p| p.to_string()),
        c.double_point.as_ref().map(|p| format!("({})", p.join(", "))),
    );
    let params = if k.node_type == Some(NodeType::Cusp) { &k.cusp_parameters } else { &k.double_point_parameters };
    check(
        "parameters",
        format!("{:?}", params.iter().map(|p| p.to_string()).collect::<Vec<_>>()),
        c.parameters.as_ref().map(|p| format!("{p:?}")),
    );
    check(
        "inflections",
        format!("{:?}", k.inflection_parameters.iter().map(|p| p.to_string()).collect::<Vec<_>>()),
        c.inflections.as_ref().map(|p| format!("{p:?}")),
    );
    check("segment loop", k.segment.has_loop.to_string(), c.segment_loop.map(|b| b.to_string()));
    check("segment cusp", k.segment.has_cusp.to_string(), c.segment_cusp.map(|b| b.to_string()));
    check("segment inflections", k.segment.inflections.to_string(), c.segment_inflections.map(|b| b.to_string()));
    Ok(if wrong.is_empty() {
        verdict(true, "exact-compare", format!("{}: {}", k.class, k.reason))
    } else {
        verdict(false, "exact-compare", wrong.join("; "))
    })
}

fn moving_lines(c: &Content) -> Result<Outcome> {
    let curve = curve_of(c)?;
    let ml = MovingLines::new(&curve)?;
    if let Err(e) = ml.verify() {
        return Ok(verdict(false, "grid", format!("P[t]·L[t] ≢ 0: {e}")));
    }
    let k = classify(&curve)?;
    let Some((te, _)) = k.t_e_and_d.clone() else {
        let at_inf = ml.double_point.coords[2].is_zero();
        return Ok(verdict(
            at_inf,
            "grid",
            format!("P·L0 ≡ P·L1 ≡ 0 proved; D = L00 × L01 = {} (at infinity: {at_inf})", ml.double_point),
        ));
    };
    let node = k.node_type.expect("genuine cubic");
    let d_ok = ml.double_point.from_homogeneous() == k.double_point;
    let te_ok = ml.t_e() == Some(te.clone());
    let e_ok = ml.e_point().and_then(|e| e.from_homogeneous()) == Some(curve.eval(&te));
    let (_, disc) = ml.f_and_discriminant();
    let expected_sign = match node {
        NodeType::Crunode => std::cmp::Ordering::Greater,
        NodeType::Cusp => std::cmp::Ordering::Equal,
        _ => std::cmp::Ordering::Less,
    };
    let sign_ok = disc.sign() == expected_sign;
    Ok(verdict(
        d_ok && te_ok && e_ok && sign_ok,
        "grid",
        format!(
            "P·L0 ≡ P·L1 ≡ 0 proved; (4) D = {} {}; (7) t_E = {te} {}; (8) E = P(t_E) {}; sign of disc(L1[t]·D) gives {} {}",
            k.double_point.as_ref().expect("D"),
            ok(d_ok),
            ok(te_ok),
            ok(e_ok),
            node.as_str(),
            ok(sign_ok)
        ),
    ))
}

fn ok(b: bool) -> &'static str {
    if b { "✓" } else { "✗" }
}

/// Lemma 2 of seed 001 for all curves of degree `1..=max`: with the control points `b_0..b_n`
/// as variables, `Σ_r b_0^r(t0) B_r^n(s) ≡ b(t0·s)` and `Σ_r b_r^{n−r}(t0) B_r^n(s) ≡
/// b(t0 + (1−t0)s)`; degree 1 in each `b_j` and `n` in `t0` and `s`.
fn lemma_2(max: usize) -> Result<Outcome> {
    if max > 8 {
        return Err(bad("lemma-2 is checked up to degree 8 (2^(n+1)·(n+1)² grid points)"));
    }
    let mut total = 0;
    for n in 1..=max {
        let mut degrees = vec![1; n + 1];
        degrees.extend([n, n]);
        let res = proof::identities::<Rational>(&degrees, |v| {
            let (b, rest) = v.split_at(n + 1);
            let (t0, s) = (&rest[0], &rest[1]);
            let curve = BezierCurve::new(b.iter().map(|x| Point::new(vec![x.clone()])).collect()).expect("points");
            let tri = crate::curve::casteljau::triangle(&curve, t0);
            let left = BezierCurve::new(tri.left_polygon()).expect("n+1 points");
            let right = BezierCurve::new(tri.right_polygon()).expect("n+1 points");
            let one = Rational::one();
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

/// Seed 004 (2): `L[t] = P[τ] × P[t] = (t − τ)·r(τ)·M·c(t)` with `c(t) = ((1−t)², (1−t)t, t²)` and
/// `M` the matrix of cross products `Q_i × Q_j`.
fn moving_line_2(c: &Content) -> Result<Outcome> {
    let curve = curve_of(c)?;
    let ml = MovingLines::new(&curve)?;
    let q = &ml.q;
    let x = |a: &Point<BigRational>, b: &Point<BigRational>| a.cross(b).expect("3-vectors");
    let m = [
        [x(&q[0], &q[1]), x(&q[0], &q[2]), x(&q[0], &q[3])],
        [x(&q[0], &q[2]), x(&q[0], &q[3]).add(&x(&q[1], &q[2])), x(&q[1], &q[3])],
        [x(&q[0], &q[3]), x(&q[1], &q[3]), x(&q[2], &q[3])],
    ];
    let printed = c.formulas.as_deref() != Some("corrected");
    let res = proof::identities::<BigRational>(&[3, 3], |v| {
        let (tau, t) = (&v[0], &v[1]);
        let (u, ut) = (rat(1) - tau, rat(1) - t);
        let col = [ut.clone() * &ut, ut.clone() * t, t.clone() * t];
        let row: [BigRational; 3] = if printed {
            let s = u.clone() * &u * &ut * tau - tau.clone() * tau;
            [s.clone(), s.clone(), s]
        } else {
            [u.clone() * &u, u.clone() * tau, tau.clone() * tau]
        };
        let mut rhs = Point::origin(3);
        for a in 0..3 {
            for b in 0..3 {
                rhs = rhs.add(&m[a][b].scale(&(row[a].clone() * &col[b])));
            }
        }
        let rhs = rhs.scale(&(t.clone() - tau));
        x(&ml.point(tau), &ml.point(t)).sub(&rhs).coords
    });
    Ok(match res {
        Ok(cert) => verdict(true, "grid", format!("P[τ] × P[t] ≡ (t − τ) r(τ) M c(t): {cert}")),
        Err(e) => verdict(
            false,
            "grid",
            format!("at (τ, t) = ({}, {}) coordinate {} differs by {}", e.point[0], e.point[1], e.identity, e.value),
        ),
    })
}
