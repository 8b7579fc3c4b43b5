//! Runners of the commands with their own input and output: `prove`, `plot`, `surface`,
//! `spline`, `gallery` (the curve commands share [`crate::batch`]'s reader).

use crate::answers;
use crate::args::{PatchArgs, PlotArgs, ProveArgs, SurfaceOp};
use crate::batch::{batch, rational_batch};
use crate::options::{Weights, option_number, patch_of, rational_curve, weights_family};
use crate::render::{Answer, Json};
use casteljau::error::{Error, Result};
use casteljau::surface::ParameterAxis;
use casteljau::surface::RationalPatch;
use std::io::Write;

pub(crate) fn surface(op: SurfaceOp, out: &mut dyn Write) -> i32 {
    let run_patch =
        |mut patch: PatchArgs, out: &mut dyn Write, f: &(dyn Fn(&RationalPatch) -> Result<Answer> + Sync)| {
            if patch.curve.dim == 2 {
                patch.curve.dim = 3; // patches are 3D unless --dim says otherwise
            }
            if patch.rational.homogeneous {
                patch.curve.dim += 1;
            }
            let (degree, rational) = (patch.degree.clone(), patch.rational.clone());
            batch(&patch.curve, out, |c| f(&patch_of(c, &degree, &rational)?))
        };
    match op {
        SurfaceOp::Eval { u, v, patch } => {
            let uv = option_number("--u", &u).and_then(|u| Ok((u, option_number("--v", &v)?)));
            let budget = patch.curve.budget();
            run_patch(patch, out, &|p| {
                let (u, v) = uv.clone()?;
                p.eval_checked(&u, &v, &budget).map(|s| answers::surface_point(&s))
            })
        }
        SurfaceOp::Subdivide { u, v, patch } => {
            let at = match (&u, &v) {
                (Some(u), None) => option_number("--u", u).map(|x| (ParameterAxis::U, x)),
                (None, Some(v)) => option_number("--v", v).map(|x| (ParameterAxis::V, x)),
                _ => Err(Error::InvalidArgument { message: "give exactly one of --u and --v".into() }),
            };
            run_patch(patch, out, &|p| {
                let (direction, x) = at.clone()?;
                p.split(direction, &x).map(|s| answers::surface_split(&s))
            })
        }
        SurfaceOp::Elevate { u_by, v_by, patch } => {
            run_patch(patch, out, &|p| p.elevate(u_by, v_by).map(|e| answers::patch(&e)))
        }
        SurfaceOp::Contour { z, polyline, patch } => {
            let z = option_number("--z", &z);
            run_patch(patch, out, &|p| p.contour(&z.clone()?, polyline).map(|c| answers::contour(&c)))
        }
    }
}

pub(crate) fn plot(args: PlotArgs, out: &mut dyn Write) -> i32 {
    if args.curve.json {
        eprintln!("casteljau: plot writes SVG; --json does not apply");
        return 2;
    }
    let PlotArgs {
        polygon,
        construction,
        subdivide_at,
        depth,
        features,
        weights_family: family,
        grid,
        title,
        width,
        output,
        rational,
        curve,
    } = args;
    let width = width.clamp(16, 8192);
    let opts = (|| -> Result<casteljau::plot::CurveOptions> {
        Ok(casteljau::plot::CurveOptions {
            polygon,
            construction: construction.as_deref().map(|t| option_number("--construction", t)).transpose()?,
            subdivide: subdivide_at
                .as_deref()
                .map(|t| option_number("--subdivide", t).map(|t| (t, depth)))
                .transpose()?,
            features,
        })
    })();
    use casteljau::plot::{Figure, PALETTE, draw_curve, draw_rational, draw_weight_family};
    use std::sync::Mutex;
    let fig = Mutex::new(Figure::new().grid(grid));
    if let Some(t) = &title {
        let f = std::mem::take(&mut *fig.lock().expect("figure"));
        *fig.lock().expect("figure") = f.title(t);
    }
    let count = Mutex::new(0usize);
    let family = match family.as_deref().map(weights_family).transpose() {
        Ok(f) => f,
        Err(e) => {
            eprintln!("casteljau: {e}");
            return 2;
        }
    };
    let mut sink: Vec<u8> = Vec::new();
    // one thread: the curves are drawn in input order (colours and the SVG are deterministic)
    let mut curve = curve;
    curve.threads = 1;
    let budget = curve.budget();
    let code = rational_batch(&rational, curve, &mut sink, |c, w| {
        let opts = opts.clone()?;
        opts.check_drawable(c, &budget)?;
        let k = *count.lock().expect("count");
        let color = PALETTE[k % PALETTE.len()];
        match (w, &family) {
            (Weights::Polynomial, None) => draw_curve(&mut fig.lock().expect("figure"), c, &opts, color)?,
            (w, None) => draw_rational(&mut fig.lock().expect("figure"), &rational_curve(c, w)?, color, opts.polygon),
            (w, Some((i, values))) => {
                draw_weight_family(&mut fig.lock().expect("figure"), &rational_curve(c, w)?, *i, values, opts.polygon)?
            }
        }
        *count.lock().expect("count") += 1;
        Ok(Answer { text: String::new(), json: Json::Value(serde_json::Value::Null), failed: false })
    });
    if code == 2 {
        return 2;
    }
    let fig = fig.into_inner().expect("figure");
    if !fig.is_drawable() {
        eprintln!(
            "casteljau: the figure's coordinates exceed the f64 range (NaN or inf in the drawing); nothing written"
        );
        return 2;
    }
    let svg = fig.to_svg(width);
    match output {
        Some(path) => {
            if let Err(e) = crate::files::write_atomically(&path, svg.as_bytes()) {
                eprintln!("casteljau: cannot write {}: {e}", path.display());
                return 2;
            }
        }
        None => {
            let _ = out.write_all(svg.as_bytes());
        }
    }
    code
}

pub(crate) fn gallery(dir: &std::path::Path, out: &mut dyn Write) -> i32 {
    match crate::files::write_gallery(dir) {
        Ok(files) => {
            let _ = writeln!(out, "wrote {} files to {}", files.len(), dir.display());
            0
        }
        Err(e) => {
            eprintln!("casteljau: cannot write {}: {e}", dir.display());
            2
        }
    }
}

pub(crate) fn prove(args: &ProveArgs, out: &mut dyn Write) -> i32 {
    let (paths, filter, json_out) = (&args.paths, args.filter.as_deref(), args.json);
    let (junit, write_readme) = (args.junit.as_deref(), args.write_readme.as_deref());
    use casteljau::catalogue;
    use std::io::IsTerminal;
    let paths = if paths.is_empty() { vec![catalogue::default_path()] } else { paths.to_vec() };
    let claims = match catalogue::load(&paths) {
        Ok(c) => c,
        Err(e) => {
            eprintln!("casteljau: {e}");
            return 2;
        }
    };
    let claims: Vec<_> = claims.into_iter().filter(|c| filter.is_none_or(|f| c.id.contains(f))).collect();
    let progress = std::io::stderr().is_terminal() && !json_out && !args.quiet;
    let (mut passed, mut failed, mut malformed) = (0, 0, 0);
    // claims are independent: check them on all cores, report in catalogue order
    let finished = std::sync::atomic::AtomicUsize::new(0);
    let Some(pool) = crate::pipeline::thread_pool(args.threads, Some(claims.len())) else { return 2 };
    let checked: Vec<_> = pool.install(|| {
        use rayon::prelude::*;
        claims
            .par_iter()
            .map(|c| {
                let r = catalogue::check(c, &casteljau::work::Budget::new(args.max_work, "--max-work"));
                let k = finished.fetch_add(1, std::sync::atomic::Ordering::Relaxed) + 1;
                if progress {
                    eprint!("\r\x1b[K[{k}/{}] {}", claims.len(), c.id);
                }
                r
            })
            .collect()
    });
    if progress {
        eprint!("\r\x1b[K");
    }
    let mut results = Vec::new();
    for r in checked {
        let r = match r {
            Ok(r) => r,
            Err(e) => {
                malformed += 1;
                eprintln!("casteljau: {e}");
                continue;
            }
        };
        if r.passed() {
            passed += 1;
        } else {
            failed += 1;
        }
        let line = if json_out {
            serde_json::to_value(&r).expect("claim results serialize").to_string()
        } else {
            format!(
                "{} {:<44} {:<17} {:<13} {:>8.4}s  {}",
                if r.passed() { "ok  " } else { "FAIL" },
                r.id,
                r.found.as_str(),
                r.method,
                r.seconds,
                r.detail
            )
        };
        if writeln!(out, "{line}").is_err() {
            return 2;
        }
        results.push(r);
    }
    if !json_out {
        let _ = writeln!(out, "{passed} passed, {failed} failed");
    }
    if malformed > 0 && junit.is_some() {
        eprintln!("casteljau: --junit not written: {malformed} claim(s) could not be checked (all or nothing)");
    } else if let Some(path) = junit
        && let Err(e) = crate::files::write_atomically(path, catalogue::junit(&results).as_bytes())
    {
        eprintln!("casteljau: cannot write {}: {e}", path.display());
        return 2;
    }
    if let Some(path) = write_readme {
        if malformed > 0 || filter.is_some() {
            eprintln!("casteljau: --write-readme needs the whole catalogue, checked without errors");
            return 2;
        }
        if let Err(e) = crate::files::write_atomically(path, catalogue::readme(&claims, &results).as_bytes()) {
            eprintln!("casteljau: cannot write {}: {e}", path.display());
            return 2;
        }
    }
    if malformed > 0 {
        2
    } else if failed == 0 {
        0
    } else {
        1
    }
}
