//! The exact numbers behind the rounding: enclosures of exact points, their grid candidates with
//! proved displacement bounds, and a rational upper bound of a square root.
//!
//! **Why control-point displacements bound the distance.** A piece of the exact boundary is the
//! sub-segment `P(s)` of an input segment, `s ∈ [0, 1]`, with control points `P_i`; the written
//! piece has the same degree and control points `Q_i`. Then `Q(s) − P(s) = Σ B_i(s)·(Q_i − P_i)`
//! is the Bézier curve of the differences, a convex combination of them, so `|Q(s) − P(s)| ≤
//! max_i |Q_i − P_i|` for every `s`: every written point is that close to the exact point of the
//! same parameter, and back. The sub-segment's control points are the blossom values
//! `P_i = b(a, …, a, b, …, b)` (`n − i` times the start parameter `a`, `i` times the end `b`);
//! the blossom is affine in each argument, so over a box of argument intervals its values lie
//! between the least and greatest of its values at the box's corners — rational enclosures of
//! control points with irrational parameters, however the parameters are related.

use crate::num::point::Point2;
use crate::num::scalar::rat;
use crate::poly::algebraic::RealAlgebraic;
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{Signed, Zero};

/// A closed rational interval.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct Interval {
    pub lo: BigRational,
    pub hi: BigRational,
}

impl Interval {
    pub(super) fn point(x: BigRational) -> Self {
        Interval { lo: x.clone(), hi: x }
    }

    /// The largest `|x − c|` over the interval.
    pub(super) fn farthest(&self, c: &BigRational) -> BigRational {
        let (a, b) = ((&self.lo - c).abs(), (&self.hi - c).abs());
        if a > b { a } else { b }
    }

    fn mid(&self) -> BigRational {
        (&self.lo + &self.hi) / rat(2)
    }

    pub(super) fn plus(&self, o: &Interval) -> Interval {
        Interval { lo: &self.lo + &o.lo, hi: &self.hi + &o.hi }
    }

    pub(super) fn minus(&self, o: &Interval) -> Interval {
        Interval { lo: &self.lo - &o.hi, hi: &self.hi - &o.lo }
    }

    pub(super) fn times(&self, o: &Interval) -> Interval {
        let ps = [&self.lo * &o.lo, &self.lo * &o.hi, &self.hi * &o.lo, &self.hi * &o.hi];
        let lo = ps.iter().min().expect("four products").clone();
        let hi = ps.iter().max().expect("four products").clone();
        Interval { lo, hi }
    }

    pub(super) fn scaled(&self, s: &BigRational) -> Interval {
        let (a, b) = (&self.lo * s, &self.hi * s);
        if a <= b { Interval { lo: a, hi: b } } else { Interval { lo: b, hi: a } }
    }
}

/// Where an exact point lies: a rational box holding it (a point when it is rational).
#[derive(Clone, Debug, PartialEq)]
pub(super) struct Enclosure {
    pub x: Interval,
    pub y: Interval,
}

impl Enclosure {
    /// The exact point when the box is one.
    pub(super) fn rational(&self) -> Option<Point2<BigRational>> {
        (self.x.lo == self.x.hi && self.y.lo == self.y.hi).then(|| Point2::new(self.x.lo.clone(), self.y.lo.clone()))
    }

    /// The square of the largest distance from the grid point `g` to a point of the box: a
    /// bound on the squared displacement of the exact point when it is written as `g`.
    pub(super) fn displacement2(&self, g: [i64; 2]) -> BigRational {
        let dx = self.x.farthest(&rat(g[0]));
        let dy = self.y.farthest(&rat(g[1]));
        &dx * &dx + &dy * &dy
    }
}

/// Width to which irrational parameters and coordinates are narrowed before enclosing.
fn narrow_width() -> BigRational {
    BigRational::new(1.into(), BigInt::from(1) << 48)
}

/// The number narrowed to a tight interval.
pub(super) fn narrowed(x: &RealAlgebraic) -> Interval {
    if let Some(r) = x.to_rational() {
        return Interval::point(r.clone());
    }
    let mut x = x.clone();
    x.refine(&narrow_width());
    let (lo, hi) = x.interval();
    Interval { lo, hi }
}

/// `floor(x + 1/2)`: the nearest integer, halves rounded up, decided exactly.
pub(super) fn nearest_algebraic(x: &RealAlgebraic) -> i64 {
    if let Some(r) = x.to_rational() {
        return nearest_rational(r);
    }
    let f = x.to_f64();
    let mut n = (f + 0.5).floor() as i64;
    let half = || BigRational::new(1.into(), 2.into());
    loop {
        if *x < RealAlgebraic::from(rat(n) - half()) {
            n -= 1;
        } else if *x >= RealAlgebraic::from(rat(n) + half()) {
            n += 1;
        } else {
            return n;
        }
    }
}

/// `floor(r + 1/2)`.
pub(super) fn nearest_rational(r: &BigRational) -> i64 {
    let f = (r + BigRational::new(1.into(), 2.into())).floor().to_integer();
    i64::try_from(f).unwrap_or(i64::MAX)
}

/// The grid points a free point may be written as: `first` (the nearest), then the other grid
/// points of its 3×3 neighbourhood whose displacement bound is at most 1, nearest first; each
/// with its squared displacement bound.
pub(super) fn candidates(e: &Enclosure, first: [i64; 2]) -> Vec<([i64; 2], BigRational)> {
    let mut out = vec![(first, e.displacement2(first))];
    if e.rational().is_some_and(|p| p.x.is_integer() && p.y.is_integer()) {
        return out; // an exact grid point stays where it is
    }
    let one = rat(1);
    let mut others = vec![];
    for dx in -1..=1 {
        for dy in -1..=1 {
            let g = [first[0] + dx, first[1] + dy];
            if g == first {
                continue;
            }
            let d = e.displacement2(g);
            if d <= one {
                others.push((g, d));
            }
        }
    }
    others.sort_by(|a, b| a.1.cmp(&b.1).then(a.0.cmp(&b.0)));
    out.extend(others);
    out
}

/// The nearest grid point to the middle of an enclosure (halves up).
pub(super) fn nearest_to(e: &Enclosure) -> [i64; 2] {
    [nearest_rational(&e.x.mid()), nearest_rational(&e.y.mid())]
}

/// The blossom of the control points at rational arguments (`n` of them for degree `n`):
/// de Casteljau with a new argument at each level.
fn blossom(points: &[Point2<BigRational>], args: &[BigRational]) -> Point2<BigRational> {
    let mut level: Vec<Point2<BigRational>> = points.to_vec();
    for u in args {
        let v = rat(1) - u;
        level = level.windows(2).map(|w| Point2::new(&v * &w[0].x + u * &w[1].x, &v * &w[0].y + u * &w[1].y)).collect();
    }
    level.pop().expect("one point left")
}

/// Enclosures of the inner control points of the sub-segment from `a` to `b` of the segment
/// with control points `points` (exact when `a` and `b` are rational), in order from `a`.
pub(super) fn inner_controls(points: &[Point2<BigRational>], a: &Interval, b: &Interval) -> Vec<Enclosure> {
    let n = points.len() - 1;
    (1..n)
        .map(|i| {
            // slots: n − i copies of a, i copies of b; each slot at either end of its interval
            let slots: Vec<&Interval> = (0..n).map(|k| if k < n - i { a } else { b }).collect();
            let free: Vec<usize> = (0..n).filter(|&k| slots[k].lo != slots[k].hi).collect();
            let mut lo: Option<Point2<BigRational>> = None;
            let mut hi: Option<Point2<BigRational>> = None;
            for mask in 0u32..(1 << free.len()) {
                let args: Vec<BigRational> = (0..n)
                    .map(|k| match free.iter().position(|&f| f == k) {
                        Some(bit) if mask & (1 << bit) != 0 => slots[k].hi.clone(),
                        _ => slots[k].lo.clone(),
                    })
                    .collect();
                let p = blossom(points, &args);
                lo = Some(match lo {
                    None => p.clone(),
                    Some(l) => Point2::new(min(l.x, &p.x), min(l.y, &p.y)),
                });
                hi = Some(match hi {
                    None => p,
                    Some(h) => Point2::new(max(h.x, &p.x), max(h.y, &p.y)),
                });
            }
            let (lo, hi) = (lo.expect("a corner"), hi.expect("a corner"));
            Enclosure { x: Interval { lo: lo.x, hi: hi.x }, y: Interval { lo: lo.y, hi: hi.y } }
        })
        .collect()
}

fn min(a: BigRational, b: &BigRational) -> BigRational {
    if *b < a { b.clone() } else { a }
}

fn max(a: BigRational, b: &BigRational) -> BigRational {
    if *b > a { b.clone() } else { a }
}

/// A rational `r ≥ √x` (`x ≥ 0`): `√x` itself when `x` is the square of a rational with a
/// denominator up to 10⁶, else the least multiple of 10⁻⁶ at or above it.
pub(super) fn sqrt_up(x: &BigRational) -> BigRational {
    if !x.is_positive() {
        return rat(0);
    }
    let (n, d) = (x.numer(), x.denom());
    let (sn, sd) = (n.sqrt(), d.sqrt());
    if &(&sn * &sn) == n && &(&sd * &sd) == d && sd <= BigInt::from(1_000_000) {
        return BigRational::new(sn, sd);
    }
    // s = ⌈√⌈x·10¹²⌉⌉: (s/10⁶)² ≥ ⌈x·10¹²⌉/10¹² ≥ x
    let scale = BigInt::from(10u64.pow(12));
    let scaled = (x * BigRational::from_integer(scale)).ceil().to_integer();
    let mut s = scaled.sqrt();
    if &s * &s < scaled {
        s += 1;
    }
    BigRational::new(s, BigInt::from(10u64.pow(6)))
}

/// Whether the points lie on one line (every point when there are fewer than three).
pub(super) fn collinear(points: &[Point2<BigRational>]) -> bool {
    let Some(a) = points.first() else { return true };
    let Some(b) = points.iter().find(|p| *p != a) else { return true };
    let d = b.sub(a);
    points.iter().all(|p| d.cross(&p.sub(a)).is_zero())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::scalar::ratio;

    #[test]
    fn sqrt_up_is_exact_on_squares_and_above_otherwise() {
        assert_eq!(sqrt_up(&ratio(1, 4)), ratio(1, 2));
        assert_eq!(sqrt_up(&ratio(1, 2)), ratio(707107, 1000000));
        let r = sqrt_up(&rat(2));
        assert!(&r * &r >= rat(2) && r < ratio(1414214, 1000000) + ratio(1, 1000000));
        assert_eq!(sqrt_up(&rat(0)), rat(0));
    }

    #[test]
    fn inner_controls_of_a_rational_piece_are_its_subsegment() {
        let p = |x: i64, y: i64| Point2::new(rat(x), rat(y));
        let pts = [p(0, 0), p(1, 2), p(3, 3), p(4, 0)];
        let e = inner_controls(&pts, &Interval::point(ratio(1, 4)), &Interval::point(ratio(3, 4)));
        let c = crate::curve::BezierCurve::new(
            pts.iter().map(|q| crate::num::Point::new(vec![q.x.clone(), q.y.clone()])).collect(),
        )
        .unwrap()
        .subsegment(&ratio(1, 4), &ratio(3, 4));
        for (i, enc) in e.iter().enumerate() {
            assert_eq!(
                enc.rational().unwrap(),
                Point2::new(c.points()[i + 1].coords[0].clone(), c.points()[i + 1].coords[1].clone())
            );
        }
    }

    #[test]
    fn inner_controls_enclose_the_exact_values() {
        // the quadratic's middle control of [a, 1] is (1 − a)·P1 + a·P2: enclosed for a in [1/3, 1/2]
        let p = |x: i64, y: i64| Point2::new(rat(x), rat(y));
        let pts = [p(0, 0), p(4, 8), p(8, 0)];
        let a = Interval { lo: ratio(1, 3), hi: ratio(1, 2) };
        let e = &inner_controls(&pts, &a, &Interval::point(rat(1)))[0];
        assert_eq!((e.x.lo.clone(), e.x.hi.clone()), (ratio(16, 3), rat(6)));
        assert_eq!((e.y.lo.clone(), e.y.hi.clone()), (rat(4), ratio(16, 3)));
    }

    #[test]
    fn nearest_rounds_halves_up_exactly() {
        let s2 = RealAlgebraic::real_roots(&crate::poly::Poly::new(vec![rat(-2), rat(0), rat(1)]))[1].clone();
        assert_eq!(nearest_algebraic(&s2), 1);
        assert_eq!(nearest_rational(&ratio(5, 2)), 3);
        assert_eq!(nearest_rational(&ratio(-5, 2)), -2);
        let e = Enclosure { x: Interval { lo: ratio(1, 3), hi: ratio(1, 2) }, y: Interval::point(rat(0)) };
        let c = candidates(&e, nearest_to(&e));
        assert_eq!(c[0], ([0, 0], ratio(1, 4)));
        assert!(c.iter().all(|(_, d)| *d <= rat(1)));
    }
}
