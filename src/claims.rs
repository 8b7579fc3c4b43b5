//! The seeds' checkable claims built into `casteljau prove`.
//!
//! Each [`Claim`] is checked exactly and compared with its expected verdict: `holds`, or
//! `fails-as-printed` for a seed erratum (the check then also proves the corrected statement).
//! Claims come from identity (8) of seed 001 (proved for every `n ≤ 40` by the grid prover) and
//! from the exact fixture `tests/data/seeds_core.json` (seed 001's subdivision example and
//! Fig. 10, seed 003's matrices, power forms, expansions and tables), embedded at build time.

use crate::BezierCurve;
use crate::bernstein::{bernstein_all, bernstein_to_power_matrix, binomial, to_power};
use crate::casteljau::{subdivide_repeatedly, subdivision_intervals};
use crate::fraction_free;
use crate::parse::{parse_number, parse_points};
use crate::point::Point;
use crate::proof::{self, Certificate, Counterexample};
use crate::scalar::{Exact, Rational, Scalar};
use num_bigint::BigInt;
use num_rational::BigRational;
use serde::Deserialize;
use std::time::Instant;

/// The exact fixture of seeds 001 and 003.
pub const SEEDS_CORE_JSON: &str = include_str!("../tests/data/seeds_core.json");

/// What a claim is expected to do.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Verdict {
    /// The statement holds (proved or verified exactly).
    Holds,
    /// The statement as printed in the seed is false (an erratum); a corrected one holds.
    FailsAsPrinted,
}

impl Verdict {
    /// `holds` or `fails-as-printed`.
    pub fn as_str(self) -> &'static str {
        match self {
            Verdict::Holds => "holds",
            Verdict::FailsAsPrinted => "fails-as-printed",
        }
    }
}

/// The outcome of checking one claim.
#[derive(Clone, Debug)]
pub struct ClaimResult {
    /// Unique claim id.
    pub id: String,
    /// Seed file and place.
    pub source: String,
    /// The expected verdict.
    pub expected: Verdict,
    /// The verdict found.
    pub found: Verdict,
    /// How it was checked (`grid`, `exact-eval`, `exact-compare`).
    pub method: &'static str,
    /// Certificate or counterexample, in words.
    pub detail: String,
    /// Wall time of the check, in seconds.
    pub seconds: f64,
}

impl ClaimResult {
    /// Whether the found verdict is the expected one.
    pub fn passed(&self) -> bool {
        self.expected == self.found
    }
}

/// Identity (8) of seed 001 for one `n`, all `j` at once:
/// `B_j^n(st) − Σ_{r=j}^{n} B_j^r(s) B_r^n(t) = 0`, degree ≤ n in `s` and in `t`.
///
/// `upper` replaces the sum's upper limit `n` (pass `n`; a smaller value is a wrong variant
/// used to show the prover refutes it).
///
/// # Errors
/// A counterexample `(s, t)` with the failing `j` as its `identity`.
pub fn identity_8(n: usize, upper: usize) -> Result<Certificate, Counterexample<Rational>> {
    // The grid varies t fastest: the B_j^r(s) table is rebuilt only when s changes.
    let mut cache: Option<(Rational, Vec<Vec<Rational>>)> = None;
    proof::identities::<Rational>(&[n, n], |v| {
        let (s, t) = (&v[0], &v[1]);
        if cache.as_ref().is_none_or(|(cs, _)| cs != s) {
            cache = Some((s.clone(), (0..=n).map(|r| bernstein_all(r, s)).collect()));
        }
        let b_s = &cache.as_ref().expect("just filled").1;
        let lhs = bernstein_all(n, &(s.clone() * t));
        let b_t = bernstein_all(n, t);
        (0..=n)
            .map(|j| {
                let rhs = (j..=upper.min(n)).fold(Rational::zero(), |acc, r| acc + b_s[r][j].clone() * &b_t[r]);
                lhs[j].clone() - rhs
            })
            .collect()
    })
}

#[derive(Deserialize)]
struct Fixture {
    power_forms: Vec<PowerForm>,
    subdivisions: Vec<Subdivision>,
    repeated_subdivisions: Vec<Repeated>,
    matrices: Vec<Matrix>,
    bernstein_expansions: Vec<Expansion>,
    tables: Vec<Table>,
}
#[derive(Deserialize)]
struct PowerForm {
    id: String,
    source: String,
    points: String,
    power: Vec<Vec<String>>,
    printed_y_power: Option<Vec<String>>,
}
#[derive(Deserialize)]
struct Subdivision {
    id: String,
    source: String,
    points: String,
    t: String,
    left: String,
    right: String,
}
#[derive(Deserialize)]
struct Repeated {
    id: String,
    source: String,
    points: String,
    t: String,
    depth: u32,
    pieces: usize,
}
#[derive(Deserialize)]
struct Matrix {
    degree: usize,
    source: String,
    rows: Vec<Vec<i64>>,
}
#[derive(Deserialize)]
struct Expansion {
    degree: usize,
    source: String,
    printed: Vec<Vec<i64>>,
    #[serde(default)]
    errata: Vec<serde_json::Value>,
}
#[derive(Deserialize)]
struct Table {
    id: String,
    source: String,
    points: String,
    t: Vec<String>,
    values: Vec<Vec<String>>,
    corrected_points: Option<String>,
}

fn num(s: &str) -> BigRational {
    parse_number(s, Default::default()).expect("fixture numbers are exact")
}
fn curve(s: &str) -> BezierCurve<BigRational> {
    BezierCurve::new(parse_points(s, 2, None).expect("fixture curves parse")).expect("fixture curves are valid")
}
fn points(rows: &[Vec<String>]) -> Vec<Point<BigRational>> {
    rows.iter().map(|r| Point::new(r.iter().map(|v| num(v)).collect())).collect()
}

/// Checks every built-in claim whose id `wanted` accepts, identity (8) for `n ≤ max_n`.
pub fn check_all(max_n: usize, wanted: &dyn Fn(&str) -> bool) -> Vec<ClaimResult> {
    let mut out = Vec::new();
    let mut push = |id: String, source: &str, expected, method, check: &mut dyn FnMut() -> (Verdict, String)| {
        if !wanted(&id) {
            return;
        }
        let start = Instant::now();
        let (found, detail) = check();
        out.push(ClaimResult {
            id,
            source: source.to_string(),
            expected,
            found,
            method,
            detail,
            seconds: start.elapsed().as_secs_f64(),
        });
    };
    let s001 = "001_8a5894bbd9ecfc92.txt, (8)";
    for n in 0..=max_n {
        push(format!("001-identity-8-n{n}"), s001, Verdict::Holds, "grid", &mut || match identity_8(n, n) {
            Ok(c) => (Verdict::Holds, c.to_string()),
            Err(e) => (Verdict::FailsAsPrinted, format!("j = {}: {e}", e.identity)),
        });
    }
    seed_004_claims(&mut push);
    let fx: Fixture = serde_json::from_str(SEEDS_CORE_JSON).expect("embedded fixture is valid JSON");
    for pf in &fx.power_forms {
        let c = curve(&pf.points);
        let computed = c.power_coefficients();
        push(pf.id.clone(), &pf.source, Verdict::Holds, "exact-compare", &mut || {
            compare(&computed, &points(&pf.power), "power coefficients")
        });
        if let Some(printed) = &pf.printed_y_power {
            let ys: Vec<BigRational> = computed.iter().map(|p| p.coords[1].clone()).collect();
            let printed: Vec<BigRational> = printed.iter().map(|v| num(v)).collect();
            push(
                format!("{}-printed-formula", pf.id),
                &pf.source,
                Verdict::FailsAsPrinted,
                "exact-compare",
                &mut || match ys.iter().zip(&printed).position(|(a, b)| a != b) {
                    None => (Verdict::Holds, "printed y(t) equals the computed power form".into()),
                    Some(k) => (
                        Verdict::FailsAsPrinted,
                        format!("t^{k} coefficient printed {} but the matrix product gives {}", printed[k], ys[k]),
                    ),
                },
            );
        }
    }
    for sd in &fx.subdivisions {
        push(sd.id.clone(), &sd.source, Verdict::Holds, "exact-compare", &mut || {
            let c = curve(&sd.points);
            let t0 = num(&sd.t);
            let (l, r) = fraction_free::subdivide(&c, &t0);
            if l != curve(&sd.left) || r != curve(&sd.right) {
                return (Verdict::FailsAsPrinted, format!("computed halves {l} | {r}"));
            }
            // Lemma 2 for this curve: left(s) ≡ b(t0·s), right(s) ≡ b(t0 + (1−t0)s), degree ≤ n.
            let n = c.degree();
            let res = proof::identities::<BigRational>(&[n], |v| {
                let s = &v[0];
                let lt = t0.clone() * s;
                let rt = t0.clone() + (BigRational::from_i64(1) - &t0) * s;
                let dl = l.eval(s).sub(&c.eval(&lt));
                let dr = r.eval(s).sub(&c.eval(&rt));
                dl.coords.into_iter().chain(dr.coords).collect()
            });
            match res {
                Ok(cert) => (Verdict::Holds, format!("halves as fixed; Lemma 2 proved: {cert}")),
                Err(e) => (Verdict::FailsAsPrinted, e.to_string()),
            }
        });
    }
    for rs in &fx.repeated_subdivisions {
        push(rs.id.clone(), &rs.source, Verdict::Holds, "grid", &mut || {
            let c = curve(&rs.points);
            let t0 = num(&rs.t);
            let pieces = subdivide_repeatedly(&c, &t0, rs.depth).expect("depth within limits");
            let ivs = subdivision_intervals(&t0, rs.depth);
            if pieces.len() != rs.pieces {
                return (Verdict::FailsAsPrinted, format!("{} pieces", pieces.len()));
            }
            for (k, (piece, (a, b))) in pieces.iter().zip(&ivs).enumerate() {
                let res = proof::identities::<BigRational>(&[c.degree()], |v| {
                    let t = a.clone() + (b.clone() - a) * &v[0];
                    piece.eval(&v[0]).sub(&c.eval(&t)).coords
                });
                if let Err(e) = res {
                    return (Verdict::FailsAsPrinted, format!("piece {k}: {e}"));
                }
            }
            (Verdict::Holds, format!("{} pieces, each equal to the curve on its interval", pieces.len()))
        });
    }
    for m in &fx.matrices {
        push(format!("003-matrix-degree-{}", m.degree), &m.source, Verdict::Holds, "exact-compare", &mut || {
            let computed = bernstein_to_power_matrix(m.degree);
            let printed: Vec<Vec<BigInt>> =
                m.rows.iter().map(|r| r.iter().map(|&v| BigInt::from(v)).collect()).collect();
            if computed == printed {
                (Verdict::Holds, format!("{0}×{0} matrix equals A[k][i] = (-1)^(k-i) C(n,k) C(k,i)", m.degree + 1))
            } else {
                (Verdict::FailsAsPrinted, format!("computed {computed:?}"))
            }
        });
    }
    for e in &fx.bernstein_expansions {
        let expected = if e.errata.is_empty() { Verdict::Holds } else { Verdict::FailsAsPrinted };
        push(format!("003-bernstein-expansion-degree-{}", e.degree), &e.source, expected, "exact-compare", &mut || {
            let n = e.degree;
            for i in 0..=n {
                let unit: Vec<Point<BigRational>> =
                    (0..=n).map(|k| Point::new(vec![BigRational::from_i64((k == i) as i64)])).collect();
                let coeffs = to_power(&unit);
                for (k, c) in coeffs.iter().enumerate() {
                    if c.coords[0] != BigRational::from_i64(e.printed[i][k]) {
                        return (
                            Verdict::FailsAsPrinted,
                            format!(
                                "B_{i}^{n}: t^{k} coefficient printed {} but is {} (= (-1)^({k}-{i}) C({n},{k}) C({k},{i}) = {})",
                                e.printed[i][k],
                                c.coords[0],
                                signed_binomial(n, k, i)
                            ),
                        );
                    }
                }
            }
            (Verdict::Holds, "every printed expansion equals the exact one".into())
        });
    }
    for tb in &fx.tables {
        let expected = if tb.corrected_points.is_some() { Verdict::FailsAsPrinted } else { Verdict::Holds };
        push(tb.id.clone(), &tb.source, expected, "exact-eval", &mut || {
            let table = points(&tb.values);
            let eval_all = |c: &BezierCurve<BigRational>| -> Vec<Point<BigRational>> {
                tb.t.iter().map(|t| fraction_free::eval(c, &num(t))).collect()
            };
            let computed = eval_all(&curve(&tb.points));
            match compare(&computed, &table, "table rows") {
                ok @ (Verdict::Holds, _) => ok,
                (_, why) => match &tb.corrected_points {
                    Some(fix) if eval_all(&curve(fix)) == table => {
                        (Verdict::FailsAsPrinted, format!("{why}; the table is exactly the curve {fix}"))
                    }
                    _ => (Verdict::FailsAsPrinted, why),
                },
            }
        });
    }
    out
}

fn signed_binomial(n: usize, k: usize, i: usize) -> BigInt {
    let v = binomial(n, k) * binomial(k, i);
    if (k + i) % 2 == 1 { -v } else { v }
}

fn compare(computed: &[Point<BigRational>], expected: &[Point<BigRational>], what: &str) -> (Verdict, String) {
    if computed.len() != expected.len() {
        return (Verdict::FailsAsPrinted, format!("{} {what} computed, {} printed", computed.len(), expected.len()));
    }
    match computed.iter().zip(expected).position(|(a, b)| a != b) {
        None => (Verdict::Holds, format!("all {} {what} equal exactly", computed.len())),
        Some(k) => {
            (Verdict::FailsAsPrinted, format!("{what}: entry {k} printed {} but computed {}", expected[k], computed[k]))
        }
    }
}

/// Example cubics for seed 004's four kinds (Figs. 1–4 show one of each).
pub const SEED_004_EXAMPLES: [(&str, &str); 5] = [
    ("crunode", "0 0, 2 2, -1 2, 1 0"),
    ("crunode-outside", "0 0, 1 0, 2 1, 3/2 3/2"),
    ("cusp", "0 0, 1 1, 0 1, 1 0"),
    ("acnode", "1 -4, -1/3 0, 1/3 -4, 1 4"),
    ("explicit", "0 0, 1 2, 2 -1, 3 1"),
];

type Push<'a> = dyn FnMut(String, &str, Verdict, &'static str, &mut dyn FnMut() -> (Verdict, String)) + 'a;

fn seed_004_claims(push: &mut Push<'_>) {
    use crate::canonical::{Formulas, canonical_map};
    use crate::classify::{NodeType, classify};
    use crate::moving_line::MovingLines;
    let src = "004_3773f109b5f2edbe.txt";
    for (name, pts) in SEED_004_EXAMPLES {
        let c = curve(pts);
        let k = classify(&c).expect("planar cubic");
        let node = k.node_type.expect("genuine cubic");
        push(
            format!("004-moving-lines-3-5-{name}"),
            &format!("{src}, (2)-(5): P[t]·L0[t] = P[t]·L1[t] = 0"),
            Verdict::Holds,
            "grid",
            &mut || match MovingLines::new(&c).expect("cubic").verify() {
                Ok(cert) => (Verdict::Holds, cert.to_string()),
                Err(e) => (Verdict::FailsAsPrinted, e.to_string()),
            },
        );
        if node != NodeType::Explicit {
            push(
                format!("004-double-point-4-7-8-{name}"),
                &format!("{src}, (4) D = L00×L01, (7) t_E, (8) E"),
                Verdict::Holds,
                "exact-compare",
                &mut || {
                    let ml = MovingLines::new(&c).expect("cubic");
                    let (te, _) = k.t_e_and_d.clone().expect("A ≠ 0");
                    let d_ok = ml.double_point.from_homogeneous() == k.double_point;
                    let te_ok = ml.t_e() == Some(te.clone());
                    let e_ok = ml.e_point().and_then(|e| e.from_homogeneous()) == Some(c.eval(&te));
                    let (_, disc) = ml.f_and_discriminant();
                    let sign_ok = disc.sign()
                        == match node {
                            NodeType::Crunode => std::cmp::Ordering::Greater,
                            NodeType::Cusp => std::cmp::Ordering::Equal,
                            _ => std::cmp::Ordering::Less,
                        };
                    if d_ok && te_ok && e_ok && sign_ok {
                        (
                            Verdict::Holds,
                            format!(
                                "D = {}, t_E = {te}, E = P(t_E), sign of the discriminant of L1[t]·D gives {}",
                                k.double_point.as_ref().expect("D"),
                                node.as_str()
                            ),
                        )
                    } else {
                        (
                            Verdict::FailsAsPrinted,
                            format!("D {d_ok}, t_E {te_ok}, E {e_ok}, discriminant sign {sign_ok}"),
                        )
                    }
                },
            );
        }
        let (eq, expected) = match node {
            NodeType::Crunode => ("(9)-(11)", Verdict::FailsAsPrinted),
            NodeType::Cusp => ("(12)-(14)", Verdict::FailsAsPrinted),
            NodeType::Acnode => ("(15)-(18)", Verdict::Holds),
            NodeType::Explicit => ("Case 4 (omitted in the seed; derived)", Verdict::Holds),
        };
        let check = |formulas: Formulas| -> (Verdict, String) {
            match canonical_map(&c, formulas) {
                Ok(m) => match m.prove(&c) {
                    Ok(cert) => (Verdict::Holds, format!("M·C(t̃) ≡ P(t): {cert}")),
                    Err(e) => {
                        let pts: Vec<String> = m.points.iter().map(|(n, p)| format!("{n} = {p}")).collect();
                        (Verdict::FailsAsPrinted, format!("{} ; {e}", pts.join(", ")))
                    }
                },
                Err(e) => (Verdict::FailsAsPrinted, e.to_string()),
            }
        };
        let label = if node == NodeType::Explicit { "derived" } else { "as-printed" };
        push(format!("004-canonical-map-{label}-{name}"), &format!("{src}, {eq}"), expected, "grid", &mut || {
            check(Formulas::AsPrinted)
        });
        if expected == Verdict::FailsAsPrinted {
            push(
                format!("004-canonical-map-corrected-{name}"),
                &format!("{src}, {eq} corrected"),
                Verdict::Holds,
                "grid",
                &mut || check(Formulas::Corrected),
            );
        }
    }
}
