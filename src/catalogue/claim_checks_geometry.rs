//! Claim kinds for rational curves, splines, patches and nets (seed 000, seed 002 §2–§5); the
//! dispatch, the content format and the polynomial kinds live in [`crate::catalogue::claim_checks`].

use crate::catalogue::claim_checks::{Content, Outcome, bad, curve_of, need, num, verdict};
use crate::error::Result;
use crate::num::parse::parse_points;
use crate::num::point::Point;
use crate::num::scalar::{Exact, rat};
use num_rational::BigRational;

/// The `implicit` kind.
pub(crate) fn implicit(c: &Content) -> Result<Outcome> {
    use crate::rational::implicit::{ImplicitVerdict, prove_implicit};
    Ok(match prove_implicit(&rational_of(c)?, need(&c.poly, "poly")?)? {
        ImplicitVerdict::Proved { degree_bound, parameters } => verdict(
            true,
            "grid",
            format!(
                "W^d f(X/W) has degree ≤ {degree_bound} in t and vanishes at {} parameters with W ≠ 0",
                parameters.len()
            ),
        ),
        ImplicitVerdict::Counterexample { t, point, value } => {
            verdict(false, "exact-eval", format!("at t = {t}, x(t) = {point} and f = {value}"))
        }
    })
}

/// The `rational-elevation` kind.
pub(crate) fn rational_elevation(c: &Content) -> Result<Outcome> {
    let r = rational_of(c)?;
    let (h, sh) = (r.elevate(1)?, r.elevate_saito_hosaka()?);
    let same = h.points() == sh.points() && h.weights().iter().zip(sh.weights()).all(|(a, b)| *a == b);
    Ok(verdict(
        same,
        "exact-compare",
        if same {
            format!("(22) gives the {} control points and weights of the homogeneous elevation", r.degree() + 2)
        } else {
            format!("(22): {:?} / {:?}; homogeneous: {:?} / {:?}", sh.points(), sh.weights(), h.points(), h.weights())
        },
    ))
}

/// The `spline-segments` kind.
pub(crate) fn spline_segments(c: &Content) -> Result<Outcome> {
    use crate::spline::{Printed, RationalSpline, check_segments, seed_cubic_segment, seed_quadratic_segment};
    let curve = curve_of(c)?;
    let n = *need(&c.degree, "degree")?;
    let ratios = scalars(need(&c.ratios, "ratios")?)?;
    let weights = match &c.weights {
        Some(w) => scalars(w)?,
        None => vec![rat(1); curve.points().len()],
    };
    let sp = RationalSpline::new(n, curve.points(), &weights, &ratios)?;
    let segs: Vec<crate::rational::rational_bezier::RationalBezier<BigRational>> =
        match (c.method.as_deref().unwrap_or("boehm"), n) {
            ("boehm", _) => sp.to_bezier_boehm(),
            ("seed", 3) | ("seed-printed", 3) => {
                (0..sp.segments()).map(|s| seed_cubic_segment(&sp, s)).collect::<Result<_>>()?
            }
            ("seed", 2) => {
                (0..sp.segments()).map(|s| seed_quadratic_segment(&sp, s, Printed::Corrected)).collect::<Result<_>>()?
            }
            ("seed-printed", 2) => {
                (0..sp.segments()).map(|s| seed_quadratic_segment(&sp, s, Printed::AsPrinted)).collect::<Result<_>>()?
            }
            (m, n) => return Err(bad(format!("no method {m:?} for degree {n}"))),
        };
    Ok(match check_segments(&sp, &segs) {
        Ok(points) => verdict(
            true,
            "grid",
            format!(
                "{} segments, each the NURBS on its span ({points} exact points, type ≤ ({n}, {n})), joins C^{}",
                segs.len(),
                n - 1
            ),
        ),
        Err(e) => verdict(false, "grid", format!("{e:?}")),
    })
}

/// The `patch-evaluations` kind.
pub(crate) fn patch_evaluations(c: &Content) -> Result<Outcome> {
    let p = patch_of(c)?;
    let (m, n) = p.degree();
    for i in 0..=2 * m {
        for j in 0..=2 * n {
            let (u, v) = (
                BigRational::new((i as i64).into(), ((2 * m).max(1) as i64).into()),
                BigRational::new((j as i64).into(), ((2 * n).max(1) as i64).into()),
            );
            let s = p.eval(&u, &v)?;
            if p.eval_u_then_v(&u, &v)? != s || p.eval_v_then_u(&u, &v)? != s {
                return Ok(verdict(false, "exact-eval", format!("routes differ at (u, v) = ({u}, {v})")));
            }
        }
    }
    Ok(verdict(
        true,
        "grid",
        format!(
            "closed form (41) = u-then-v = v-then-u on a {}×{} grid (rational of type ({m},{m})×({n},{n}))",
            2 * m + 1,
            2 * n + 1
        ),
    ))
}

/// The `patch-weight-change` kind.
pub(crate) fn patch_weight_change(c: &Content) -> Result<Outcome> {
    let p = patch_of(c)?;
    let (i, j) = (*need(&c.index, "index")?, *need(&c.index_v, "index_v")?);
    let dw = num(need(&c.weight, "weight")?)?;
    let printed = c.formulas.as_deref() != Some("corrected");
    let changed = p.with_weight_change(i, j, &dw)?;
    let (m, n) = p.degree();
    for a in 0..=2 * m {
        for b in 0..=2 * n {
            let (u, v) = (
                BigRational::new((a as i64).into(), ((2 * m) as i64 + 1).into()),
                BigRational::new((b as i64).into(), ((2 * n) as i64 + 1).into()),
            );
            let (claimed, truth) = (p.weight_change(i, j, &dw, &u, &v, printed)?, changed.eval(&u, &v)?);
            if claimed != truth {
                return Ok(verdict(
                    false,
                    "exact-eval",
                    format!("at (u, v) = ({u}, {v}): (49) gives {claimed}, the changed patch is at {truth}"),
                ));
            }
        }
    }
    Ok(verdict(
        true,
        "grid",
        format!("(49) ≡ the patch with w_{i}{j} + Δw on a {}×{} grid (type ({m},{m})×({n},{n}))", 2 * m + 1, 2 * n + 1),
    ))
}

/// The `net` kind.
pub(crate) fn net(c: &Content) -> Result<Outcome> {
    use crate::spline::Printed;
    use crate::spline::net::{Conversion, SplineNet, check_net};
    let (rows, weights) = net_rows(c)?;
    let (nu, nv) = match &c.degrees {
        None => (2, 2),
        Some(d) => d
            .split_once(',')
            .and_then(|(a, b)| Some((a.trim().parse().ok()?, b.trim().parse().ok()?)))
            .ok_or_else(|| bad(format!("degrees must be \"nu,nv\", not {d:?}")))?,
    };
    let net = SplineNet::new(
        (nu, nv),
        rows,
        weights,
        scalars(need(&c.ratios, "ratios")?)?,
        scalars(need(&c.ratios_v, "ratios_v")?)?,
    )?;
    let how = match c.method.as_deref().unwrap_or("boehm") {
        "boehm" => Conversion::Boehm,
        "seed" => Conversion::SeedQuadratic(Printed::Corrected),
        "seed-printed" => Conversion::SeedQuadratic(Printed::AsPrinted),
        m => return Err(bad(format!("no net method {m:?}"))),
    };
    let r = check_net(&net, how)?;
    let ok = r.order_independent && r.equals_nurbs && r.smooth_joins;
    Ok(verdict(
        ok,
        "grid",
        format!(
            "{} patches; equal to the tensor NURBS: {}; C^{} joins: {}; rows-first = columns-first: {}{}",
            r.patches,
            r.equals_nurbs,
            nu.min(nv) - 1,
            r.smooth_joins,
            r.order_independent,
            r.problem.map(|p| format!(" ({p})")).unwrap_or_default()
        ),
    ))
}

/// The `rational-subdivision` kind.
pub(crate) fn rational_subdivision(c: &Content) -> Result<Outcome> {
    let r = rational_of(c)?;
    let t0 = num(need(&c.t, "t")?)?;
    let (l, rt) = r.subdivide(&t0);
    let n = r.degree();
    // the halves are rational of type ≤ (n, n) in s: 2n + 1 parameters decide each
    let ts = parameters_where(2 * n + 1, |s| {
        r.eval(&(t0.clone() * s)).is_ok() && r.eval(&(t0.clone() + (rat(1) - &t0) * s)).is_ok()
    });
    for s in &ts {
        let (a, b) = (r.eval(&(t0.clone() * s))?, r.eval(&(t0.clone() + (rat(1) - &t0) * s))?);
        if l.eval(s)? != a || rt.eval(s)? != b {
            return Ok(verdict(false, "exact-eval", format!("a half differs from the curve at s = {s}")));
        }
    }
    // the left half's control points are the rational interpolation points of (19)–(20)
    let mut row: Vec<Point<BigRational>> =
        r.points().into_iter().collect::<Option<_>>().ok_or_else(|| bad("finite points"))?;
    let mut left = vec![row[0].clone()];
    for k in 1..=n {
        let u = rat(1) - &t0;
        row = (0..row.len() - 1)
            .map(|i| {
                let a = t0.clone() * r.shifted_weight(i + 1, k - 1, &t0);
                let b = u.clone() * r.shifted_weight(i, k - 1, &t0);
                crate::rational::rational_bezier::divide(&a, &b, &row[i], &row[i + 1])
                    .ok_or_else(|| bad("vanishing ratio"))
            })
            .collect::<Result<_>>()?;
        left.push(row[0].clone());
    }
    let found: Vec<Point<BigRational>> =
        l.points().into_iter().collect::<Option<_>>().ok_or_else(|| bad("finite points"))?;
    Ok(verdict(
        found == left,
        "grid",
        format!(
            "halves ≡ the curve on [0, t0] and [t0, 1] ({} parameters each); left control points = P0, Pa, Pd, …, P of (19)–(20): {}",
            ts.len(),
            found == left
        ),
    ))
}

pub(crate) fn rational_of(c: &Content) -> Result<crate::rational::rational_bezier::RationalBezier<BigRational>> {
    use crate::rational::rational_bezier::RationalBezier;
    if let Some(h) = &c.homogeneous {
        let dim = h.split(',').next().map_or(3, |p| p.split_whitespace().count());
        return RationalBezier::from_homogeneous(parse_points(h, dim, None)?);
    }
    let curve = curve_of(c)?;
    let w = match &c.weights {
        Some(w) => parse_points(w, 1, None)?.into_iter().map(|p| p.coords[0].clone()).collect(),
        None => vec![rat(1); curve.points().len()],
    };
    RationalBezier::new(curve.points().to_vec(), w)
}

/// Parameters `0, 1, 1/2, 1/3, 2/3, …` where `keep` holds, `count` of them.
pub(crate) fn parameters_where(count: usize, mut keep: impl FnMut(&BigRational) -> bool) -> Vec<BigRational> {
    let mut out = Vec::new();
    let mut q = 1i64;
    while out.len() < count && q < 10_000 {
        for p in 0..=q {
            if num_integer::gcd(p, q) == 1 || (p == 0 && q == 1) {
                let t = BigRational::new(p.into(), q.into());
                if keep(&t) {
                    out.push(t);
                    if out.len() == count {
                        break;
                    }
                }
            }
        }
        q += 1;
    }
    out
}

pub(crate) fn rational_evaluations(
    r: &crate::rational::rational_bezier::RationalBezier<BigRational>,
) -> Result<Outcome> {
    let n = r.degree();
    let ts = parameters_where(2 * n + 1, |t| r.eval_rational_de_casteljau(t).is_ok() && r.eval_saito_hosaka(t).is_ok());
    if ts.len() < 2 * n + 1 {
        return Err(bad("too few parameters where every route is defined"));
    }
    for t in &ts {
        let x = r.eval(t)?;
        for (name, y) in [
            ("seed 000 recursion", r.eval_rational_de_casteljau(t)?),
            ("Saito–Hosaka (19)–(20)", r.eval_saito_hosaka(t)?),
        ] {
            if y != x {
                return Ok(verdict(false, "exact-eval", format!("at t = {t}: (14) gives {x}, {name} gives {y}")));
            }
        }
    }
    Ok(verdict(
        true,
        "grid",
        format!("three routes, rational of type ≤ ({n}, {n}) in t, agree at {} parameters", ts.len()),
    ))
}

pub(crate) fn weight_pull(c: &Content) -> Result<Outcome> {
    let r = rational_of(c)?;
    let i = *need(&c.index, "index")?;
    let w_new = num(need(&c.weight, "weight")?)?;
    let dw = w_new.clone() - &r.weights()[i];
    if dw.sign() != std::cmp::Ordering::Greater {
        return Err(bad("weight-pull needs a larger new weight"));
    }
    let moved = r.with_weight(i, w_new)?;
    let open = (rat(0), rat(1));
    for (name, curve) in [("W", &r), ("W'", &moved)] {
        if let Err(e) = curve.check_defined(&open.0, &open.1) {
            return Ok(verdict(false, "exact-eval", format!("{name}: {e}")));
        }
    }
    let n = r.degree();
    for t in parameters_where(2 * n + 1, |_| true) {
        let (claimed, truth) = (r.weight_change(i, &dw, &t)?, moved.eval(&t)?);
        if claimed != truth {
            return Ok(verdict(false, "exact-eval", format!("(23) at t = {t}: {claimed} ≠ {truth}")));
        }
    }
    Ok(verdict(
        true,
        "grid",
        format!(
            "(23) with γ = B_{i}^{n} proved (type ≤ ({n}, {n}), {} points); W, W' > 0 and γΔw > 0 on (0, 1): every point moves strictly towards b_{i}",
            2 * n + 1
        ),
    ))
}

pub(crate) fn scalars(text: &str) -> Result<Vec<BigRational>> {
    Ok(parse_points(text, 1, None)?.into_iter().map(|p| p.coords[0].clone()).collect())
}

pub(crate) type Grid = (Vec<Vec<Point<BigRational>>>, Vec<Vec<BigRational>>);

pub(crate) fn net_rows(c: &Content) -> Result<Grid> {
    let text = need(&c.net, "net")?;
    let rows: Vec<Vec<Point<BigRational>>> =
        text.split(';').map(|r| parse_points(r.trim(), 3, None)).collect::<Result<_>>()?;
    let weights: Vec<Vec<BigRational>> = match &c.net_weights {
        Some(w) => w.split(';').map(|r| scalars(r.trim())).collect::<Result<_>>()?,
        None => rows.iter().map(|r| vec![rat(1); r.len()]).collect(),
    };
    Ok((rows, weights))
}

pub(crate) fn patch_of(c: &Content) -> Result<crate::surface::RationalPatch> {
    let (rows, weights) = net_rows(c)?;
    crate::surface::RationalPatch::new(rows, weights)
}
