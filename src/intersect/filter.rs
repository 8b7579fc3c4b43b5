//! Certified `f64` filters for [`super`]: decisions made in floating point that are proofs —
//! outward-rounded interval arithmetic ([`Enclosure`]) and Krawczyk's interval Newton operator —
//! and that say "undecided" rather than guess, leaving the exact route to decide.
//!
//! - [`candidate_regions`]: the curves' control polygons, halved (plain `f64` with a proved
//!   error radius), have disjoint bounding boxes everywhere (convex hull property): no
//!   intersection on `[0, 1]²`; or every intersection lies in the boxes left over.
//! - [`solve`]: each candidate box proved empty or holding exactly one transversal crossing
//!   (Krawczyk's operator on the [`System`] `A(σ) − B(τ)`), for the box solver's route.
//! - [`apart`]: two root parameters map to provably different points.
//! - [`proved_common`]: two root parameters map to the same point (a transversal crossing).
//! - [`no_common_root`]: two polynomials with coefficients in `Z[x]` share no root at a real
//!   `x` (a Bézout determinant kept from 0), for the irrationality proof of a point.
//!
//! Written by hand: the interval type is a few outward-rounded operations on `f64` pairs
//! (`next_up`/`next_down` after each operation, portable and dependency-free), where interval
//! crates bring directed-rounding intrinsics of particular processors or a C library (MPFR).

use crate::poly::algebraic::RealAlgebraic;
use num_bigint::BigInt;
use num_rational::BigRational;

/// A closed `f64` interval whose ends are rounded outwards after every operation, so it holds
/// the exact value: a certified filter (a disjointness it shows is a proof; `inf` and `NaN`
/// only ever make it show nothing).
#[derive(Clone, Copy, Debug)]
pub(super) struct Enclosure(f64, f64);

impl Enclosure {
    /// An integer: `to_f64` is within an ulp, widened by two.
    fn of_integer(c: &BigInt) -> Self {
        let f = num_traits::ToPrimitive::to_f64(c).unwrap_or(f64::NAN);
        Enclosure(f.next_down().next_down(), f.next_up().next_up())
    }
    /// `c·2^−shift`: `⌊c/2^shift⌋` enclosed, widened by the one unit the floor dropped.
    fn of_scaled_integer(c: &BigInt, shift: u64) -> Self {
        if shift == 0 {
            return Self::of_integer(c);
        }
        Self::of_integer(&(c >> shift)).add(Enclosure(0.0, 1.0))
    }
    /// `[lo, hi]` (the caller knows it holds the value).
    pub(super) fn new(lo: f64, hi: f64) -> Self {
        Enclosure(lo, hi)
    }
    pub(super) fn add(self, o: Self) -> Self {
        Enclosure((self.0 + o.0).next_down(), (self.1 + o.1).next_up())
    }
    pub(super) fn mul(self, o: Self) -> Self {
        let p = [self.0 * o.0, self.0 * o.1, self.1 * o.0, self.1 * o.1];
        if p.iter().any(|x| x.is_nan()) {
            return Enclosure(f64::NAN, f64::NAN);
        }
        let lo = p.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = p.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        Enclosure(lo.next_down(), hi.next_up())
    }
    /// `self / o` when `o` keeps away from 0 (else nothing is known).
    fn div(self, o: Self) -> Self {
        if !(o.0 > 0.0 || o.1 < 0.0) {
            return Enclosure(f64::NAN, f64::NAN);
        }
        let q = [self.0 / o.0, self.0 / o.1, self.1 / o.0, self.1 / o.1];
        if q.iter().any(|x| x.is_nan()) {
            return Enclosure(f64::NAN, f64::NAN);
        }
        let lo = q.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = q.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        Enclosure(lo.next_down(), hi.next_up())
    }
    pub(super) fn neg(self) -> Self {
        Enclosure(-self.1, -self.0)
    }
    /// Provably no common point (false whenever an end is `NaN`).
    fn apart(self, o: Self) -> bool {
        self.1 < o.0 || o.1 < self.0
    }
}

/// An enclosure of the power form `p` (integer coefficients) over the interval `x`: Horner.
fn enclose(p: &[BigInt], x: Enclosure) -> Enclosure {
    p.iter().rev().fold(Enclosure(0.0, 0.0), |acc, c| acc.mul(x).add(Enclosure::of_integer(c)))
}

/// The interval of `x` in `f64`, widened outwards: it holds `x`.
pub(super) fn outward(x: &RealAlgebraic) -> (f64, f64) {
    let (lo, hi) = x.interval();
    (crate::num::scalar::ratio_to_f64(&lo).next_down(), crate::num::scalar::ratio_to_f64(&hi).next_up())
}

impl Enclosure {
    /// An enclosure of `x` ([`outward`]).
    fn of_number(x: &RealAlgebraic) -> Self {
        let (lo, hi) = outward(x);
        Enclosure(lo, hi)
    }
    /// The common part of two intervals (empty, `lo > hi`, when they miss each other).
    fn meet(self, o: Self) -> Self {
        Enclosure(self.0.max(o.0), self.1.min(o.1))
    }
}

/// The point of `f` over the isolating interval of `x`.
fn enclose_point(f: &[Vec<BigInt>; 3], x: &RealAlgebraic) -> [Enclosure; 2] {
    let x = Enclosure::of_number(x);
    let w = enclose(&f[2], x);
    [enclose(&f[0], x).div(w), enclose(&f[1], x).div(w)]
}

/// `A(s) ≠ B(t)`, proved by enclosures of both points over the intervals of `s` and `t`
/// (pass copies narrowed by [`RealAlgebraic::narrowed_with_f64`] for tight enclosures); false
/// when they overlap (the exact comparison decides then).
pub(super) fn apart(fa: &[Vec<BigInt>; 3], s: &RealAlgebraic, fb: &[Vec<BigInt>; 3], t: &RealAlgebraic) -> bool {
    let (p, q) = (enclose_point(fa, s), enclose_point(fb, t));
    p[0].apart(q[0]) || p[1].apart(q[1])
}

/// The largest formal degree in `u` for which [`no_common_root`] decides (its determinant is
/// expanded by cofactors).
pub(super) const MAX_BEZOUT_ORDER: usize = 4;

/// The polynomials `f(x, u)` and `g(x, u)` in `u` (coefficients in `Z[x]` given as enclosed
/// [`Coeffs`], lowest first, of
/// formal degree `m ≤` [`MAX_BEZOUT_ORDER`]) provably have no common root `u`, complex ones
/// included, at the real number `x` in the `f64` interval `(lo, hi)` (a tight one: [`outward`]
/// of a copy narrowed by [`RealAlgebraic::narrowed_with_f64`], say): the `m × m` Bézout matrix
/// `B` of `f(x, ·)` and `g(x, ·)` — `f(u)g(v) − f(v)g(u) = (u − v)·Σ B_ij u^i v^j` — enclosed
/// over that interval, has
/// a determinant that keeps away from 0. A common root `u₀` would make the row vector
/// `(u₀^i)` a left null vector of `B` (the left side vanishes for every `v`), so `det B = 0`.
/// False when that is not shown (the exact route decides then).
pub(super) fn no_common_root(f: &[Coeffs], g: &[Coeffs], (lo, hi): (f64, f64)) -> bool {
    let m = f.len().max(g.len()).saturating_sub(1);
    if m == 0 || m > MAX_BEZOUT_ORDER {
        return false;
    }
    let xe = Enclosure(lo, hi);
    let at = |p: &[Coeffs]| -> Vec<Enclosure> { p.iter().map(|c| c.at(xe)).collect() };
    let Some(bz) = super::elimination::bezoutian(&at(f), &at(g), m) else { return false };
    let d = det(&bz);
    d.0 > 0.0 || d.1 < 0.0
}

/// The determinant of a small square matrix of enclosures, by cofactors along the first row.
fn det(m: &[Vec<Enclosure>]) -> Enclosure {
    match m.len() {
        0 => Enclosure(1.0, 1.0),
        1 => m[0][0],
        n => (0..n).fold(Enclosure(0.0, 0.0), |acc, j| {
            let minor: Vec<Vec<Enclosure>> = m[1..]
                .iter()
                .map(|r| r.iter().enumerate().filter(|&(k, _)| k != j).map(|(_, e)| *e).collect())
                .collect();
            let term = m[0][j].mul(det(&minor));
            if j % 2 == 0 { acc.add(term) } else { acc.add(term.neg()) }
        }),
    }
}

/// `A(s) = B(t)` for polynomial curves, proved by Krawczyk's operator ([`System::krawczyk`]) over
/// a small box around an `f64` Newton solution (from `start`, the two parameters rounded) inside
/// the isolating intervals of `s` and `t`: when the operator maps the box into its interior, the
/// system has exactly one zero `(σ*, τ*)` there; then `σ*` is a root of the resultant in `s`'s
/// isolating interval, so `σ* = s`, and likewise `τ* = t`. False when that does not succeed (a
/// tangency, a box outside the intervals): the exact comparison decides then. Every decision it
/// makes is a proof; `f64` only proposes the box.
pub(super) fn proved_common(sys: &System, s: &RealAlgebraic, t: &RealAlgebraic, start: (f64, f64)) -> bool {
    let (mut u, mut v) = start;
    for _ in 0..4 {
        let m = [Enclosure(u, u), Enclosure(v, v)];
        let Some(y) = sys.newton_matrix(m) else { return false };
        let f = sys.f(m).map(|e| (e.0 + e.1) / 2.0);
        u -= y[0][0] * f[0] + y[0][1] * f[1];
        v -= y[1][0] * f[0] + y[1][1] * f[1];
    }
    if !u.is_finite() || !v.is_finite() {
        return false;
    }
    let inside = |e: Enclosure, x: &RealAlgebraic| {
        let (lo, hi) = x.interval();
        match (BigRational::from_float(e.0), BigRational::from_float(e.1)) {
            (Some(a), Some(b)) => lo <= a && b <= hi,
            _ => false,
        }
    };
    // the box: some hundreds of ulps around the Newton point (wider if that fails), inside both
    // isolating intervals
    [256.0, 65536.0, 1.6e7].iter().any(|&ulps| {
        let around = |x: f64| {
            let r = ulps * f64::EPSILON * x.abs().max(1.0);
            Enclosure(x - r, x + r)
        };
        let x = [around(u), around(v)];
        inside(x[0], s) && inside(x[1], t) && sys.krawczyk(x).is_some_and(|k| strictly_inside(k, x))
    })
}

/// `k` lies in the interior of `x`.
fn strictly_inside(k: Box2, x: Box2) -> bool {
    (0..2).all(|r| k[r].0 > x[r].0 && k[r].1 < x[r].1)
}

/// Interval arithmetic for the shared Bézoutian (never fails: an enclosure that says nothing
/// holds `NaN`, and the caller's test then fails).
impl crate::num::CheckedRing for Enclosure {
    fn zero() -> Self {
        Enclosure(0.0, 0.0)
    }
    fn add(&self, o: &Self) -> Option<Self> {
        Some(Enclosure::add(*self, *o))
    }
    fn sub(&self, o: &Self) -> Option<Self> {
        Some(Enclosure::add(*self, o.neg()))
    }
    fn mul(&self, o: &Self) -> Option<Self> {
        Some(Enclosure::mul(*self, *o))
    }
}

impl Enclosure {
    /// The smallest interval holding both.
    fn hull(self, o: Self) -> Self {
        Enclosure(self.0.min(o.0), self.1.max(o.1))
    }
    fn width(self) -> f64 {
        self.1 - self.0
    }
    /// `[c − r, c + r]`, rounded outwards.
    fn around(c: f64, r: f64) -> Self {
        Enclosure((c - r).next_down(), (c + r).next_up())
    }
}

/// The most control points a curve handed to [`candidate_regions`] has.
const MAX_POINTS: usize = super::MAX_INTERSECT_DEGREE + 1;

/// A bound on the rounding error of `(a + b)·0.5` in `f64` for `|a|, |b| ≤ m`: half an ulp
/// of the sum, halved, below `m·2^−53` (doubled for slack), plus the least subnormal.
fn midpoint_error(m: f64) -> f64 {
    m * f64::EPSILON + f64::from_bits(1)
}

/// A homogeneous control polygon `(wᵢxᵢ, wᵢyᵢ, wᵢ)` in plain `f64`s, the first `len` points,
/// with error radii: every coordinate `wx`, `wy` lies within `r` of the exact piece's, every
/// weight within `rw` (0 while the weights are exactly 1: a polynomial curve, whose halves'
/// weights stay exactly 1). Halving in plain arithmetic and widening once by a proved bound
/// costs far less than interval arithmetic at every step.
/// `N` bounds `len`: the subdivision of two curves of degree ≤ 3 runs on `Polygon<4>`, whose
/// copies are a third of the general one's.
#[derive(Clone, Copy)]
struct Polygon<const N: usize = MAX_POINTS> {
    len: usize,
    points: [[f64; 3]; N],
    r: f64,
    rw: f64,
}

impl<const N: usize> Polygon<N> {
    fn points(&self) -> &[[f64; 3]] {
        &self.points[..self.len]
    }

    /// The same polygon with room for `M` points (`None` when it has more).
    fn resized<const M: usize>(&self) -> Option<Polygon<M>> {
        let mut points = [[0.0; 3]; M];
        points.get_mut(..self.len)?.copy_from_slice(self.points());
        Some(Polygon { len: self.len, points, r: self.r, rw: self.rw })
    }

    /// The two halves at `t = 1/2` (de Casteljau in `f64`). Each level's midpoints add at most
    /// [`midpoint_error`] of the largest coordinate to the error (the exact midpoints of the
    /// exact points lie within the mean of the two radii, and the midpoints stay within the
    /// largest coordinate), so the radii grow by `levels × midpoint_error`.
    fn halves(&self) -> (Self, Self) {
        let (mut left, mut right) = (*self, *self);
        let mut row = self.points;
        let n = self.len;
        left.points[0] = row[0];
        right.points[n - 1] = row[n - 1];
        for level in 1..n {
            for i in 0..n - level {
                row[i] = std::array::from_fn(|k| (row[i][k] + row[i + 1][k]) * 0.5);
            }
            left.points[level] = row[0];
            right.points[n - 1 - level] = row[n - 1 - level];
        }
        let levels = (n - 1) as f64;
        let largest = |k: usize| self.points().iter().map(|p| p[k].abs()).fold(0.0, f64::max);
        let m = largest(0).max(largest(1));
        let r = (self.r + levels * midpoint_error(m)).next_up();
        let unit = self.rw == 0.0 && self.points().iter().all(|p| p[2] == 1.0);
        let rw = if unit { 0.0 } else { (self.rw + levels * midpoint_error(largest(2))).next_up() };
        left.r = r;
        right.r = r;
        left.rw = rw;
        right.rw = rw;
        (left, right)
    }

    /// The bounding box of the projected control points `(wx/w, wy/w)`, their errors
    /// included: it holds the curve when every weight is positive (convex hull property).
    /// `None` when an enclosure says nothing.
    fn bounding_box(&self) -> Option<[Enclosure; 2]> {
        if self.rw == 0.0 && self.points().iter().all(|p| p[2] == 1.0) {
            // the hull of the points' enclosures `around(p, r)`: rounding is monotone, so it is
            // the extreme coordinates widened once
            let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
            for p in self.points() {
                for k in 0..2 {
                    lo[k] = lo[k].min(p[k]);
                    hi[k] = hi[k].max(p[k]);
                }
            }
            let b = [0, 1].map(|k| Enclosure((lo[k] - self.r).next_down(), (hi[k] + self.r).next_up()));
            return b.iter().all(|e| e.0.is_finite() && e.1.is_finite()).then_some(b);
        }
        let mut out: Option<[Enclosure; 2]> = None;
        for p in self.points() {
            let q = if self.rw == 0.0 && p[2] == 1.0 {
                [Enclosure::around(p[0], self.r), Enclosure::around(p[1], self.r)]
            } else {
                let w = Enclosure::around(p[2], self.rw);
                [Enclosure::around(p[0], self.r).div(w), Enclosure::around(p[1], self.r).div(w)]
            };
            if q.iter().any(|e| !e.0.is_finite() || !e.1.is_finite()) {
                return None;
            }
            out = Some(match out {
                None => q,
                Some(b) => [b[0].hull(q[0]), b[1].hull(q[1])],
            });
        }
        out
    }
}

/// At most this many pairs of pieces are compared by [`candidate_regions`].
const PIECE_PAIRS: usize = 128;

/// A pair of pieces both this deep (parameter intervals of `2^−7`) is left as a candidate box
/// rather than halved further: near a crossing, halving goes on pair by pair until
/// [`PIECE_PAIRS`] comparisons are spent, where the solver's Krawczyk steps ([`solve`]) converge
/// quadratically on a box this small.
const HANDOFF_DEPTH: u32 = 7;

/// Pieces are halved at most this often, so that their ends `k/2^d` are exact `f64`s.
const MAX_DEPTH: u32 = 52;

/// A parameter interval `[k/2^d, (k+1)/2^d]` of a curve, its control polygon and bounding box,
/// and its halves once made (indices into the same arena).
struct Piece<const N: usize> {
    polygon: Polygon<N>,
    bbox: Option<[Enclosure; 2]>,
    k: u64,
    d: u32,
    halves: Option<(usize, usize)>,
}

impl<const N: usize> Piece<N> {
    fn new(polygon: Polygon<N>, k: u64, d: u32) -> Self {
        Piece { bbox: polygon.bounding_box(), polygon, k, d, halves: None }
    }

    fn size(&self) -> f64 {
        self.bbox.map_or(f64::INFINITY, |b| b[0].width().max(b[1].width()))
    }

    /// `[k/2^d, (k+1)/2^d]`, exactly.
    fn ends(&self) -> [f64; 2] {
        let scale = (1u64 << self.d) as f64;
        [self.k as f64 / scale, (self.k + 1) as f64 / scale]
    }
}

/// The halves of `arena[i]`, made on first use.
fn halves_of<const N: usize>(arena: &mut Vec<Piece<N>>, i: usize) -> (usize, usize) {
    if let Some(h) = arena[i].halves {
        return h;
    }
    let (l, r) = arena[i].polygon.halves();
    let (k, d) = (arena[i].k, arena[i].d);
    arena.push(Piece::new(l, 2 * k, d + 1));
    arena.push(Piece::new(r, 2 * k + 1, d + 1));
    let h = (arena.len() - 2, arena.len() - 1);
    arena[i].halves = Some(h);
    h
}

/// What the subdivision filter found about two curves on `[0, 1]²`.
#[derive(Debug)]
pub(super) enum Regions {
    /// No common point (every pair of pieces ended with disjoint bounding boxes).
    Apart,
    /// Every common point `(s, t)` lies in one of the closed `boxes` (`[s_lo, s_hi, t_lo,
    /// t_hi]`, exact dyadic `f64`s).
    Within {
        /// The boxes.
        boxes: Vec<[f64; 4]>,
    },
    /// Nothing proved (a weight not provably positive, or an enclosure that says nothing).
    Anywhere,
}

/// The subdivision filter on curves with homogeneous control points `a` and `b` (weights
/// positive): pairs of pieces are compared by bounding boxes (which hold the pieces, by the
/// convex hull property), breadth first, the larger piece halved while they overlap (each piece
/// halved once, its halves shared by every pair it is in). Pairs with disjoint boxes hold no
/// common point; after [`PIECE_PAIRS`] comparisons the pairs left over (and those handed off at
/// [`HANDOFF_DEPTH`]) hold every one. Boxes that touch do not count as disjoint, so hits at ends
/// are never filtered out.
pub(super) fn candidate_regions(a: &[[BigRational; 3]], b: &[[BigRational; 3]]) -> Regions {
    // the plane scaled by a power of two (the parameters of the common points unchanged) when
    // the coordinates lie far outside f64's comfortable range (10^±180, about)
    let shift = plane_shift(a.iter().chain(b).flat_map(|row| &row[..2]));
    let scale = |x: &BigRational| -> BigRational {
        match shift {
            0 => x.clone(),
            k if k > 0 => x * BigRational::from_integer(BigInt::from(1) << k),
            k => x / BigRational::from_integer(BigInt::from(1) << k.unsigned_abs()),
        }
    };
    let enclosed = |rows: &[[BigRational; 3]]| -> Option<Polygon> {
        if rows.is_empty() || rows.len() > MAX_POINTS {
            return None;
        }
        let mut p = Polygon { len: rows.len(), points: [[0.0; 3]; MAX_POINTS], r: 0.0, rw: 0.0 };
        for (q, row) in p.points.iter_mut().zip(rows) {
            for k in 0..3 {
                // an integer below 2^53 converts exactly (and without num-rational's general route)
                let scaled;
                let x = if k < 2 && shift != 0 {
                    scaled = scale(&row[k]);
                    &scaled
                } else {
                    &row[k]
                };
                let small = x.is_integer().then(|| num_traits::ToPrimitive::to_i64(x.numer())).flatten();
                let f = match small {
                    Some(v) if v.unsigned_abs() < 1 << 53 => v as f64,
                    _ => crate::num::scalar::ratio_to_f64(x),
                };
                if !f.is_finite() {
                    return None;
                }
                // nearest: within half an ulp; exact for integers below 2^53
                let exact = x.is_integer() && f.abs() < 9007199254740992.0;
                let err = if exact { 0.0 } else { midpoint_error(f.abs()) };
                if k < 2 {
                    p.r = p.r.max(err);
                } else {
                    p.rw = p.rw.max(err);
                }
                q[k] = f;
            }
        }
        // weights provably positive
        if p.points().iter().any(|q| (q[2] - p.rw).partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater)) {
            return None;
        }
        Some(p)
    };
    let (Some(a), Some(b)) = (enclosed(a), enclosed(b)) else {
        return Regions::Anywhere;
    };
    regions_of(a, b)
}

/// [`candidate_regions`] for polynomial curves with integer control points below `2^53` in
/// magnitude (exact in `f64`): the same polygons, made without conversions.
pub(super) fn candidate_regions_integer(a: &[[i64; 2]], b: &[[i64; 2]]) -> Regions {
    let polygon = |points: &[[i64; 2]]| -> Option<Polygon> {
        if points.is_empty() || points.len() > MAX_POINTS {
            return None;
        }
        let mut p = Polygon { len: points.len(), points: [[0.0; 3]; MAX_POINTS], r: 0.0, rw: 0.0 };
        for (q, c) in p.points.iter_mut().zip(points) {
            if c.iter().any(|v| v.unsigned_abs() >= 1 << 53) {
                return None;
            }
            *q = [c[0] as f64, c[1] as f64, 1.0];
        }
        Some(p)
    };
    let (Some(a), Some(b)) = (polygon(a), polygon(b)) else { return Regions::Anywhere };
    regions_of(a, b)
}

/// The subdivision of [`candidate_regions`] on two control polygons (on `Polygon<4>` when both
/// have at most 4 points).
fn regions_of(a: Polygon, b: Polygon) -> Regions {
    match (a.resized::<4>(), b.resized::<4>()) {
        (Some(a), Some(b)) => subdivide(a, b),
        _ => subdivide(a, b),
    }
}

/// [`regions_of`] on polygons of room `N`.
fn subdivide<const N: usize>(a: Polygon<N>, b: Polygon<N>) -> Regions {
    let mut arena = vec![Piece::new(a, 0, 0), Piece::new(b, 0, 0)];
    let mut queue = std::collections::VecDeque::from([(0usize, 1usize)]);
    let mut left: Vec<(usize, usize)> = vec![];
    let mut compared = 0;
    while let Some((i, j)) = queue.pop_front() {
        compared += 1;
        let (Some(ba), Some(bb)) = (arena[i].bbox, arena[j].bbox) else { return Regions::Anywhere };
        if ba[0].apart(bb[0]) || ba[1].apart(bb[1]) {
            continue;
        }
        let split_a = arena[i].size() >= arena[j].size();
        let depth = if split_a { arena[i].d } else { arena[j].d };
        let handed_off = arena[i].d.min(arena[j].d) >= HANDOFF_DEPTH;
        if compared >= PIECE_PAIRS || depth >= MAX_DEPTH || handed_off {
            left.push((i, j));
            continue;
        }
        if split_a {
            let (l, r) = halves_of(&mut arena, i);
            queue.extend([(l, j), (r, j)]);
        } else {
            let (l, r) = halves_of(&mut arena, j);
            queue.extend([(i, l), (i, r)]);
        }
    }
    if left.is_empty() {
        return Regions::Apart;
    }
    let boxes = left
        .iter()
        .map(|&(i, j)| {
            let (s, t) = (arena[i].ends(), arena[j].ends());
            [s[0], s[1], t[0], t[1]]
        })
        .collect();
    Regions::Within { boxes }
}

/// Enclosures of an integer polynomial's coefficients (lowest first), made once so that
/// evaluations convert nothing.
pub(super) struct Coeffs(Vec<Enclosure>);

impl Coeffs {
    pub(super) fn new(p: &[BigInt]) -> Self {
        Coeffs(p.iter().map(Enclosure::of_integer).collect())
    }

    /// The enclosed coefficients of an integer polynomial given in words (exact below `2^53`).
    pub(super) fn from_words(p: &[i128]) -> Self {
        let enclose = |v: &i128| {
            let f = *v as f64; // nearest
            if v.unsigned_abs() < 1 << 53 { Enclosure(f, f) } else { Enclosure(f.next_down(), f.next_up()) }
        };
        Coeffs(p.iter().map(enclose).collect())
    }

    /// The enclosed coefficients of `p·2^−shift`.
    pub(super) fn scaled(p: &[BigInt], shift: u64) -> Self {
        Coeffs(p.iter().map(|c| Enclosure::of_scaled_integer(c, shift)).collect())
    }

    /// The enclosed coefficients of `p′·2^−shift` (`k·c_k·2^−shift`), without forming it.
    pub(super) fn derivative_of(p: &[BigInt], shift: u64) -> Self {
        let k = |k: usize| Enclosure(k as f64, k as f64);
        Coeffs(p.iter().enumerate().skip(1).map(|(i, c)| Enclosure::of_scaled_integer(c, shift).mul(k(i))).collect())
    }

    /// An enclosure of the polynomial over `x` (Horner).
    fn at(&self, x: Enclosure) -> Enclosure {
        self.0.iter().rev().fold(Enclosure(0.0, 0.0), |acc, &c| acc.mul(x).add(c))
    }

    /// The polynomial provably keeps away from 0 on `[lo, hi]`.
    pub(super) fn nonzero_on(&self, lo: f64, hi: f64) -> bool {
        let v = self.at(Enclosure(lo.next_down(), hi.next_up()));
        v.0 > 0.0 || v.1 < 0.0
    }
}

/// `F(σ, τ) = (X_A(σ)·w_B − X_B(τ)·w_A, Y_A(σ)·w_B − Y_B(τ)·w_A)` for two polynomial curves
/// (constant weights `w_A`, `w_B` of the integer forms), whose zeros are the intersections, as
/// enclosures: the four polynomials and their derivatives.
pub(super) struct System {
    /// `X_A·w_B`, `Y_A·w_B` (in σ), `X_B·w_A`, `Y_B·w_A` (in τ).
    p: [Coeffs; 4],
    /// Their derivatives.
    d: [Coeffs; 4],
}

/// The bit length of the largest coefficient of [`System`]'s polynomials once scaled: far
/// inside `f64`'s range (`2^±1022`) both ways, so that Newton's matrix (about the inverse of
/// the coefficients) and the products of Krawczyk's operator neither overflow nor underflow.
const SYSTEM_BITS: u64 = 400;

/// The power of two (an exponent) that brings the largest of `coordinates` to about `2^400`
/// when it lies beyond `2^±600` (else 0): a uniform scaling of the plane.
fn plane_shift<'a>(coordinates: impl IntoIterator<Item = &'a BigRational>) -> i64 {
    let top = coordinates
        .into_iter()
        .filter(|x| !num_traits::Zero::is_zero(*x))
        .map(|x| x.numer().bits() as i64 - x.denom().bits() as i64)
        .max();
    match top {
        Some(e) if !(-600..=600).contains(&e) => 400 - e,
        _ => 0,
    }
}

/// The power of two that brings the largest of `coefficients` to about [`SYSTEM_BITS`] bits
/// (0 when it is smaller): a positive factor changes no zero and no sign.
pub(super) fn range_shift<'a>(coefficients: impl IntoIterator<Item = &'a BigInt>) -> u64 {
    coefficients.into_iter().map(BigInt::bits).max().unwrap_or(0).saturating_sub(SYSTEM_BITS)
}

/// A box `[σ, τ]`.
pub(super) type Box2 = [Enclosure; 2];

impl System {
    /// `None` for curves with a weight that is not constant.
    pub(super) fn new(fa: &[Vec<BigInt>; 3], fb: &[Vec<BigInt>; 3]) -> Option<Self> {
        if fa[2].len() != 1 || fb[2].len() != 1 {
            return None;
        }
        let (wa, wb) = (&fa[2][0], &fb[2][0]);
        let scaled = |p: &[BigInt], w: &BigInt| -> Vec<BigInt> { p.iter().map(|c| c * w).collect() };
        let polys = if num_traits::One::is_one(wa) && num_traits::One::is_one(wb) {
            [fa[0].clone(), fa[1].clone(), fb[0].clone(), fb[1].clone()]
        } else {
            [scaled(&fa[0], wb), scaled(&fa[1], wb), scaled(&fb[0], wa), scaled(&fb[1], wa)]
        };
        // each equation of F scaled by a power of two (same zeros, the same proofs) so that its
        // largest coefficient has about SYSTEM_BITS bits: curves far from 1 in size (coordinates
        // near 10^±300 or beyond, 1000-bit integers, or x and y of very different sizes) stay
        // inside f64's range
        let shifts = [0, 1].map(|e| range_shift(polys[e].iter().chain(&polys[e + 2])));
        Some(System {
            p: std::array::from_fn(|k| Coeffs::scaled(&polys[k], shifts[k % 2])),
            d: std::array::from_fn(|k| Coeffs::derivative_of(&polys[k], shifts[k % 2])),
        })
    }

    fn f(&self, x: Box2) -> [Enclosure; 2] {
        [self.p[0].at(x[0]).add(self.p[2].at(x[1]).neg()), self.p[1].at(x[0]).add(self.p[3].at(x[1]).neg())]
    }

    fn jacobian(&self, x: Box2) -> [[Enclosure; 2]; 2] {
        [[self.d[0].at(x[0]), self.d[2].at(x[1]).neg()], [self.d[1].at(x[0]), self.d[3].at(x[1]).neg()]]
    }

    /// An `f64` inverse of the Jacobian at the point `m` (the midpoints of its enclosures):
    /// Newton's matrix. `None` when it cannot be inverted.
    fn newton_matrix(&self, m: Box2) -> Option<[[f64; 2]; 2]> {
        let jm = self.jacobian(m);
        let c = |e: Enclosure| (e.0 + e.1) / 2.0;
        let (a, b, cc, d) = (c(jm[0][0]), c(jm[0][1]), c(jm[1][0]), c(jm[1][1]));
        let det = a * d - b * cc;
        let y = [[d / det, -b / det], [-cc / det, a / det]];
        (det != 0.0 && y.iter().flatten().all(|v| v.is_finite())).then_some(y)
    }

    /// Krawczyk's operator on the box `x`: `K = m − Y·F(m) + (I − Y·J(x))·(x − m)`, `m` the
    /// midpoint, `Y` an `f64` inverse of `J(m)` (any matrix keeps the proof valid). Every zero of
    /// `F` in `x` lies in `K`; `K` inside the interior of `x` proves exactly one zero there (and
    /// a non-singular Jacobian at it). `None` when `J(m)` cannot be inverted.
    fn krawczyk(&self, x: Box2) -> Option<Box2> {
        let mid = |e: Enclosure| {
            let m = e.0 + (e.1 - e.0) / 2.0;
            Enclosure(m, m)
        };
        let m = [mid(x[0]), mid(x[1])];
        let fm = self.f(m);
        let y = self.newton_matrix(m)?;
        let yk = |r: usize, k: usize| Enclosure(y[r][k], y[r][k]);
        let j = self.jacobian(x);
        let dx = [x[0].add(m[0].neg()), x[1].add(m[1].neg())];
        let k: Box2 = std::array::from_fn(|r| {
            let yf = yk(r, 0).mul(fm[0]).add(yk(r, 1).mul(fm[1]));
            let mut k_r = m[r].add(yf.neg());
            for (col, dxk) in dx.iter().enumerate() {
                let yj = yk(r, 0).mul(j[0][col]).add(yk(r, 1).mul(j[1][col]));
                let delta = Enclosure(f64::from(u8::from(r == col)), f64::from(u8::from(r == col)));
                k_r = k_r.add(delta.add(yj.neg()).mul(*dxk));
            }
            k_r
        });
        (!k.iter().any(|e| e.0.is_nan() || e.1.is_nan())).then_some(k)
    }
}

/// At most this many boxes are examined by [`solve`] (random font-like pairs need up to about
/// 20; a tangency never settles, so the budget is what it costs before the exact route).
const SOLVER_STEPS: usize = 32;

/// Every zero of the system in the closed `boxes` (`[σ_lo, σ_hi, τ_lo, τ_hi]`, the
/// [`Regions::Within`] ones): each box is proved empty (`F` keeps away from 0 on it, or
/// Krawczyk's operator misses it), proved to hold exactly one zero (the operator maps it into
/// its interior; `K(x)`, which holds that zero, is returned: [`shrink`] narrows it further
/// where a caller needs that), or halved.
/// The returned boxes each hold exactly one zero, at which the curves cross transversally (two
/// boxes may hold the same zero, when it lies on an edge they share). `None` when
/// [`SOLVER_STEPS`] examinations do not settle every box (a tangency, a zero on an edge of the
/// square): the exact route decides then.
pub(super) fn solve(sys: &System, boxes: &[[f64; 4]]) -> Option<Vec<Box2>> {
    let mut stack: Vec<Box2> = boxes.iter().map(|b| [Enclosure(b[0], b[1]), Enclosure(b[2], b[3])]).collect();
    // a zero on an edge of the square (a hit at an end of a curve) is never inside a box: when
    // F may vanish on an edge a box touches, leave the pair to the exact route at once
    for x in &stack {
        for r in 0..2 {
            for end in [0.0, 1.0] {
                if x[r].0 <= end && end <= x[r].1 {
                    let mut edge = *x;
                    edge[r] = Enclosure(end, end);
                    if may_vanish_on_edge(sys, edge, 1 - r, EDGE_PIECES) {
                        return None;
                    }
                }
            }
        }
    }
    let mut zeros = vec![];
    let mut steps = 0;
    while let Some(x) = stack.pop() {
        steps += 1;
        if steps > SOLVER_STEPS {
            return None;
        }
        let f = sys.f(x);
        if f.iter().any(|e| e.0 > 0.0 || e.1 < 0.0) {
            continue; // F keeps away from 0
        }
        let k = sys.krawczyk(x);
        if let Some(k) = k {
            if k[0].apart(x[0]) || k[1].apart(x[1]) {
                continue; // no zero
            }
            if strictly_inside(k, x) {
                zeros.push(k);
                continue;
            }
        }
        // halve the wider side (of x ∩ K, which holds every zero of x)
        let y: Box2 = match k {
            Some(k) => std::array::from_fn(|r| x[r].meet(k[r])),
            None => x,
        };
        let r = usize::from(y[1].width() > y[0].width());
        let m = y[r].0 + (y[r].1 - y[r].0) / 2.0;
        if y[r].0.partial_cmp(&m) != Some(std::cmp::Ordering::Less)
            || m.partial_cmp(&y[r].1) != Some(std::cmp::Ordering::Less)
        {
            return None; // cannot be halved in f64
        }
        let (mut lo, mut hi) = (y, y);
        lo[r] = Enclosure(y[r].0, m);
        hi[r] = Enclosure(m, y[r].1);
        stack.extend([hi, lo]);
    }
    Some(zeros)
}

/// The edge test of [`solve`] halves an edge segment this often (into at most `2^4` pieces)
/// before it gives up.
const EDGE_PIECES: u32 = 4;

/// `F` may vanish on the segment `edge` (a box whose side `1 − free` is a point): its
/// enclosures over the segment, halved up to `depth` times where they hold 0, do not rule it
/// out.
fn may_vanish_on_edge(sys: &System, edge: Box2, free: usize, depth: u32) -> bool {
    if sys.f(edge).iter().any(|e| e.0 > 0.0 || e.1 < 0.0) {
        return false;
    }
    let (lo, hi) = edge[free].ends();
    let m = lo + (hi - lo) / 2.0;
    if depth == 0 || !(lo < m && m < hi) {
        return true;
    }
    let (mut a, mut b) = (edge, edge);
    a[free] = Enclosure(lo, m);
    b[free] = Enclosure(m, hi);
    may_vanish_on_edge(sys, a, free, depth - 1) || may_vanish_on_edge(sys, b, free, depth - 1)
}

/// A box holding exactly one zero, shrunk by `x ← K(x) ∩ x` (every zero of `x` lies in `K(x)`)
/// while that gains.
pub(super) fn shrink(sys: &System, mut x: Box2) -> Box2 {
    for _ in 0..8 {
        let Some(k) = sys.krawczyk(x) else { break };
        let y: Box2 = std::array::from_fn(|r| x[r].meet(k[r]));
        if y.iter().any(|e| e.0.partial_cmp(&e.1).is_none_or(|o| o == std::cmp::Ordering::Greater)) {
            break;
        }
        let gain = y[0].width() < x[0].width() * 0.5 || y[1].width() < x[1].width() * 0.5;
        x = y;
        if !gain {
            break;
        }
    }
    x
}

impl Enclosure {
    /// The ends.
    pub(super) fn ends(self) -> (f64, f64) {
        (self.0, self.1)
    }
}

/// [`divided_difference`](super::elimination::divided_difference) with each coefficient (a polynomial in `s`) enclosed in `f64`, for
/// [`no_common_root`]: from words when the coefficients allow
/// (no big integers), else from the big-integer route.
pub(super) fn divided_difference_enclosed(f: &[BigInt], w: &[BigInt]) -> Vec<Coeffs> {
    let n = f.len().max(w.len());
    let words = |p: &[BigInt]| p.iter().map(num_traits::ToPrimitive::to_i128).collect::<Option<Vec<i128>>>();
    let Some(q) = words(f).zip(words(w)).and_then(|(f, w)| super::elimination::bezoutian(&f, &w, n)) else {
        return super::elimination::divided_difference(f, w).iter().map(|c| Coeffs::new(c)).collect();
    };
    // as divided_difference: column j trimmed, empty columns at the end dropped
    let column = |j: usize| -> Vec<i128> {
        let mut c: Vec<i128> = (0..n).map(|i| q[i][j]).collect();
        while c.last() == Some(&0) {
            c.pop();
        }
        c
    };
    let mut out: Vec<Vec<i128>> = (0..n).map(column).collect();
    while out.last().is_some_and(Vec::is_empty) {
        out.pop();
    }
    out.iter().map(|c| Coeffs::from_words(c)).collect()
}
