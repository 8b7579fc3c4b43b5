//! Runners of the curve commands (`eval`, `subdivide`, `elevate`, `power`, `triangle`,
//! `derivative`, `reduce`, `implicit`, `defined`, `bbox`, `conic`, `classify`): parse the
//! options once, then answer every curve of the batch with one library call (which checks its
//! own work budget) and render it ([`crate::answers`]). Each returns the exit code.

use crate::answers;
use crate::args::{CurveArgs, Detail, RationalArgs};
use crate::batch::{batch, batch_lines_with, rational_batch};
use crate::options::{Weights, option_number_in, rational_curve};
use casteljau::classify::{ClassifyOptions, classify_rational};
use casteljau::curve::{
    DegreeReduction, Derivative, Elevation, Evaluation, PowerForm, RepeatedSubdivision, Scheme, Subdivision,
};
use casteljau::error::{Error, Result};
use casteljau::rational::{
    Definedness, ImplicitOutcome, ParameterInterval, RationalElevation, RationalEvaluation, RationalSubdivision,
    bounding_box,
};
use num_rational::BigRational;
use std::io::Write;

/// `eval --t …`.
pub(crate) fn eval(t: &[String], rational: &RationalArgs, curve: CurveArgs, out: &mut dyn Write) -> i32 {
    let mode = curve.numbers.into();
    let ts: Result<Vec<BigRational>> = t.iter().map(|s| option_number_in("--t", s, mode)).collect();
    let budget = curve.budget();
    rational_batch(rational, curve, out, move |c, w| {
        let ts = ts.clone()?;
        match w {
            Weights::Polynomial => Evaluation::new(c, &ts, &budget).map(|e| answers::eval(&e)),
            w => RationalEvaluation::new(&rational_curve(c, w)?, &ts, &budget).map(|e| answers::eval_rational(&e)),
        }
    })
}

/// `subdivide --t [--depth]`.
pub(crate) fn subdivide(
    t: &str,
    depth: Option<u32>,
    rational: &RationalArgs,
    curve: CurveArgs,
    out: &mut dyn Write,
) -> i32 {
    let t = option_number_in("--t", t, curve.numbers.into());
    let budget = curve.budget();
    rational_batch(rational, curve, out, move |c, w| {
        let t = t.clone()?;
        match (w, depth) {
            (Weights::Polynomial, None) => Subdivision::new(c, &t, &budget).map(|s| answers::subdivide(&s)),
            (Weights::Polynomial, Some(depth)) => {
                RepeatedSubdivision::new(c, &t, depth, &budget).map(|s| answers::subdivide_repeatedly(&s))
            }
            (_, Some(d)) if d != 1 => Err(Error::InvalidArgument {
                message: "--depth is for polynomial curves; rational curves split once".into(),
            }),
            (w, _) => {
                RationalSubdivision::new(&rational_curve(c, w)?, &t, &budget).map(|s| answers::subdivide_rational(&s))
            }
        }
    })
}

/// `elevate --by`.
pub(crate) fn elevate(by: usize, rational: &RationalArgs, curve: CurveArgs, out: &mut dyn Write) -> i32 {
    let budget = curve.budget();
    rational_batch(rational, curve, out, move |c, w| match w {
        Weights::Polynomial => Elevation::new(c, by, &budget).map(|e| answers::curve(&e.curve)),
        w => RationalElevation::new(&rational_curve(c, w)?, by, &budget).map(|e| answers::rational(&e.curve)),
    })
}

/// `implicit --poly`.
pub(crate) fn implicit(poly: &str, rational: &RationalArgs, curve: CurveArgs, out: &mut dyn Write) -> i32 {
    let budget = curve.budget();
    rational_batch(rational, curve, out, move |c, w| {
        ImplicitOutcome::new(&rational_curve(c, w)?, poly, &budget).map(|o| answers::implicit(&o))
    })
}

/// `defined --from --to`.
pub(crate) fn defined(from: &str, to: &str, rational: &RationalArgs, curve: CurveArgs, out: &mut dyn Write) -> i32 {
    let mode = curve.numbers.into();
    let interval = option_number_in("--from", from, mode).and_then(|a| {
        let b = option_number_in("--to", to, mode)?;
        ParameterInterval::new(a.clone(), b.clone())
            .map_err(|_| Error::InvalidArgument { message: format!("need 0 <= --from < --to <= 1, got [{a}, {b}]") })
    });
    let budget = curve.budget();
    rational_batch(rational, curve, out, move |c, w| {
        let interval = interval.clone()?;
        Definedness::new(&rational_curve(c, w)?, &interval, &budget).map(|d| answers::defined(&d))
    })
}

/// `bbox`.
pub(crate) fn bbox(rational: &RationalArgs, curve: CurveArgs, out: &mut dyn Write) -> i32 {
    let budget = curve.budget();
    rational_batch(rational, curve, out, move |c, w| {
        bounding_box(&rational_curve(c, w)?, &budget).map(|b| answers::bbox(&b))
    })
}

/// `conic`.
pub(crate) fn conic(rational: &RationalArgs, curve: CurveArgs, out: &mut dyn Write) -> i32 {
    rational_batch(rational, curve, out, move |c, w| rational_curve(c, w)?.conic().map(|k| answers::conic(&k)))
}

/// `power`.
pub(crate) fn power(curve: &CurveArgs, out: &mut dyn Write) -> i32 {
    let budget = curve.budget();
    batch(curve, out, |c| PowerForm::new(c, &budget).map(|p| answers::power(&p)))
}

/// `triangle --t`.
pub(crate) fn triangle(t: &str, curve: &CurveArgs, out: &mut dyn Write) -> i32 {
    let t = option_number_in("--t", t, curve.numbers.into());
    let budget = curve.budget();
    batch(curve, out, |c| {
        let t = t.clone()?;
        Scheme::new(c, &t, &budget).map(|s| answers::triangle(&s))
    })
}

/// `derivative --order`.
pub(crate) fn derivative(order: usize, curve: &CurveArgs, out: &mut dyn Write) -> i32 {
    let budget = curve.budget();
    batch(curve, out, |c| Derivative::new(c, order, &budget).map(|d| answers::derivative(&d)))
}

/// `reduce`.
pub(crate) fn reduce(curve: &CurveArgs, out: &mut dyn Write) -> i32 {
    let budget = curve.budget();
    batch(curve, out, |c| DegreeReduction::new(c, &budget).map(|r| answers::reduce(&r)))
}

/// `classify`: polynomial curves by the route [`ClassifyOptions`] chooses (JSON straight from
/// the text where it can), rational cubics projectively.
pub(crate) fn classify(
    float: bool,
    detail: Detail,
    rational: &RationalArgs,
    curve: CurveArgs,
    out: &mut dyn Write,
) -> i32 {
    if rational.weights.is_some() || rational.homogeneous {
        return rational_batch(rational, curve, out, move |c, w| {
            classify_rational(&rational_curve(c, w)?).map(|k| answers::classified_rational(&k))
        });
    }
    let options =
        ClassifyOptions { dim: curve.dim, mode: curve.numbers.into(), evidence: detail == Detail::Full, float };
    let json = curve.json;
    let direct = |text: &str, out: &mut Vec<u8>| options.write_json_direct(text, out);
    batch_lines_with(&curve, out, &direct, |line, text| {
        options.classify_text(text, line).map(|k| answers::classified(&k, float, json))
    })
}
