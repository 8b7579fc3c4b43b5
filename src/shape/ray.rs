//! Winding numbers of cycles of curve pieces (segments restricted to exact parameter intervals)
//! around a rational point, by an axis-parallel ray — the rule of [`crate::path`]
//! generalised in three ways: the pieces end at real algebraic parameters, the ray may point
//! along any of the four axis directions (a quarter turn of the plane, which keeps winding
//! numbers), and the ray's origin may lie on the pieces (`Origin::Excluded`): then crossings at
//! the origin are not counted, which gives the winding number of the points of the ray just
//! beyond it — the winding number on one side of an edge.
//!
//! Pieces whose outward-rounded box misses the ray's line, or lies wholly behind the origin,
//! are decided without roots: their crossings, if any, are not counted.

use super::segment::Seg;
use crate::error::{Error, Result};
use crate::num::point::Point2;
use crate::num::scalar::rat;
use crate::path::winding::{Event, count_crossings};
use crate::poly::Poly;
use crate::poly::algebraic::RealAlgebraic;
use num_rational::BigRational;
use std::cmp::Ordering;

/// The direction of the ray.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Axis {
    PosX,
    NegX,
    PosY,
    NegY,
}

impl Axis {
    /// An axis direction `d` with `d·n > 0` (`n ≠ 0`).
    pub(crate) fn toward(n: &[BigRational; 2]) -> Axis {
        use num_traits::Signed;
        if n[0].is_positive() {
            Axis::PosX
        } else if n[0].is_negative() {
            Axis::NegX
        } else if n[1].is_positive() {
            Axis::PosY
        } else {
            Axis::NegY
        }
    }

    /// The rotated coordinates `(u, v)` in which the ray points along `+u`: a rotation, so
    /// winding numbers are kept.
    fn rotate<T: Clone + std::ops::Neg<Output = T>>(self, x: &T, y: &T) -> (T, T) {
        match self {
            Axis::PosX => (x.clone(), y.clone()),
            Axis::NegX => (-x.clone(), -y.clone()),
            Axis::PosY => (y.clone(), -x.clone()),
            Axis::NegY => (-y.clone(), x.clone()),
        }
    }

    /// The rotated box `[u_min, v_min, u_max, v_max]`.
    fn rotate_box(self, b: &[f64; 4]) -> [f64; 4] {
        let [x0, y0, x1, y1] = *b;
        match self {
            Axis::PosX => [x0, y0, x1, y1],
            Axis::NegX => [-x1, -y1, -x0, -y0],
            Axis::PosY => [y0, -x1, y1, -x0],
            Axis::NegY => [-y1, x0, -y0, x1],
        }
    }
}

/// What a ray origin on the pieces means.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Origin {
    /// The origin is a free point: reaching it means it lies on the cycles.
    Free,
    /// The origin lies on the cycles where they cross the ray: those crossings are not counted.
    Excluded,
}

/// A segment restricted to `[lo, hi]`, traversed forwards or backwards.
#[derive(Clone, Debug)]
pub(crate) struct Piece<'a> {
    pub seg: &'a Seg,
    pub lo: RealAlgebraic,
    pub hi: RealAlgebraic,
    pub forward: bool,
}

/// The answer of [`winding`].
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum RayWinding {
    /// The winding number.
    Off(i64),
    /// The origin (`Origin::Free`) lies on piece `piece` of cycle `cycle` at parameter `t`.
    On { cycle: usize, piece: usize, t: RealAlgebraic },
}

/// The winding number of the cycles around `q` by the ray from `q` along `axis` (the sum over
/// the cycles), or where `q` lies on them (`Origin::Free`).
///
/// # Errors
/// [`Error::InvalidArgument`] when, with `Origin::Excluded`, a piece lies on the ray's line
/// through the origin (the origin must be a point where the pieces cross the ray).
pub(crate) fn winding(
    cycles: &[Vec<Piece<'_>>],
    q: &Point2<BigRational>,
    axis: Axis,
    origin: Origin,
) -> Result<RayWinding> {
    let (qu, qv) = axis.rotate(&q.x, &q.y);
    let (qu_lo, qu_hi) = super::segment::outward(&qu);
    let (qv_lo, qv_hi) = super::segment::outward(&qv);
    let mut total = 0i64;
    for (ci, cycle) in cycles.iter().enumerate() {
        let mut events: Vec<Event> = vec![];
        for (pi, piece) in cycle.iter().enumerate() {
            if let Some(b) = &piece.seg.bbox {
                let [u0, v0, u1, v1] = axis.rotate_box(b);
                if v0 > qv_hi {
                    events.push(Event::Sign(Ordering::Greater));
                    continue;
                }
                if v1 < qv_lo {
                    events.push(Event::Sign(Ordering::Less));
                    continue;
                }
                if u1 < qu_lo {
                    events.push(Event::Zero(false)); // any crossing is behind the origin
                    continue;
                }
                if u0 > qu_hi {
                    // wholly beyond the origin: only the sides of its ends matter, when they are
                    // off the line (crossings in between net out to their difference)
                    if let Some((a, b)) = end_sides(piece, &qv, axis) {
                        let (a, b) = if piece.forward { (a, b) } else { (b, a) };
                        events.extend([Event::Sign(a), Event::Zero(true), Event::Sign(b)]);
                        continue;
                    }
                }
            }
            let mut own = vec![];
            if let Some(t) = piece_events(piece, &qu, &qv, axis, origin, &mut own)? {
                return Ok(RayWinding::On { cycle: ci, piece: pi, t });
            }
            if !piece.forward {
                own.reverse();
            }
            events.extend(own);
        }
        total += count_crossings(&events);
    }
    Ok(RayWinding::Off(total))
}

/// The sides (`v − q_v` signs) of a whole segment's two ends, when neither is on the line.
fn end_sides(piece: &Piece<'_>, qv: &BigRational, axis: Axis) -> Option<(Ordering, Ordering)> {
    let (zero, one) = (rat(0), rat(1));
    if piece.lo.to_rational() != Some(&zero) || piece.hi.to_rational() != Some(&one) {
        return None;
    }
    let side = |p: &Point2<BigRational>| {
        let (_, v) = axis.rotate(&p.x, &p.y);
        v.cmp(qv)
    };
    let (a, b) = (side(&piece.seg.start), side(&piece.seg.end));
    (a != Ordering::Equal && b != Ordering::Equal).then_some((a, b))
}

/// The events of one piece, in increasing parameter; `Some(t)` when the free origin is on it.
fn piece_events(
    piece: &Piece<'_>,
    qu: &BigRational,
    qv: &BigRational,
    axis: Axis,
    origin: Origin,
    events: &mut Vec<Event>,
) -> Result<Option<RealAlgebraic>> {
    let s = piece.seg;
    let (u, v): (Poly<BigRational>, Poly<BigRational>) = match axis {
        Axis::PosX => (s.x().clone(), s.y().clone()),
        Axis::NegX => (-s.x(), -s.y()),
        Axis::PosY => (s.y().clone(), -s.x()),
        Axis::NegY => (-s.y(), s.x().clone()),
    };
    let fu = &u - &s.w().scale(qu);
    let fv = &v - &s.w().scale(qv);
    let (lo, hi) = (&piece.lo, &piece.hi);
    if fv.is_zero() {
        // the piece lies on the ray's line
        let mid = RealAlgebraic::from(RealAlgebraic::rational_between(lo, hi));
        if !fu.is_zero() {
            let (a, _) = lo.interval();
            let (_, b) = hi.interval();
            if let Some(t) = RealAlgebraic::roots_in(&fu, &a, &b).into_iter().find(|r| r >= lo && r <= hi) {
                return match origin {
                    Origin::Free => Ok(Some(t)),
                    Origin::Excluded => Err(Error::InvalidArgument {
                        message: "a piece lies on the ray through a point beside an edge".into(),
                    }),
                };
            }
            events.push(Event::Zero(mid.sign_of(&fu) == Ordering::Greater));
            return Ok(None);
        }
        return match origin {
            Origin::Free => Ok(Some(lo.clone())),
            Origin::Excluded => {
                Err(Error::InvalidArgument { message: "a degenerate piece on the ray's origin".into() })
            }
        };
    }
    let (a, _) = lo.interval();
    let (_, b) = hi.interval();
    let roots: Vec<RealAlgebraic> =
        RealAlgebraic::roots_in(&fv, &a, &b).into_iter().filter(|r| r >= lo && r <= hi).collect();
    let mut breaks: Vec<RealAlgebraic> = vec![lo.clone()];
    for r in &roots {
        if r != &breaks[breaks.len() - 1] {
            breaks.push(r.clone());
        }
    }
    if &breaks[breaks.len() - 1] != hi {
        breaks.push(hi.clone());
    }
    for (k, t) in breaks.iter().enumerate() {
        if roots.iter().any(|r| r == t) {
            let side = t.sign_of(&fu);
            if side == Ordering::Equal {
                match origin {
                    Origin::Free => return Ok(Some(t.clone())),
                    Origin::Excluded => events.push(Event::Zero(false)),
                }
            } else {
                events.push(Event::Zero(side == Ordering::Greater));
            }
        }
        if let Some(next) = breaks.get(k + 1) {
            let mid = RealAlgebraic::rational_between(t, next);
            events.push(Event::Sign(RealAlgebraic::from(mid).sign_of(&fv)));
        }
    }
    Ok(None)
}

/// Pieces of whole segments (parameters `[0, 1]`, forwards).
pub(crate) fn whole(seg: &Seg) -> Piece<'_> {
    Piece { seg, lo: rat(0).into(), hi: rat(1).into(), forward: true }
}
