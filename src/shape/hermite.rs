//! The Hermite fit of rational pieces for the rounded rendering: four cubics through the points
//! and tangents of a rational sub-curve (an approximation for SVG path data, which has no
//! rational segments; the exact answer keeps the rational piece).

use super::segment::Seg;

/// Four cubics through the points and tangents of a rational piece (rounded).
pub(super) fn hermite(s: &Seg, a: f64, b: f64, p0: [f64; 2], p1: [f64; 2]) -> Vec<Vec<[f64; 2]>> {
    let (dx, dy, dw) = (s.x().derivative(), s.y().derivative(), s.w().derivative());
    let point = |t: f64| {
        let w = s.w().eval_f64(t);
        [s.x().eval_f64(t) / w, s.y().eval_f64(t) / w]
    };
    let tangent = |t: f64| {
        let (x, y, w) = (s.x().eval_f64(t), s.y().eval_f64(t), s.w().eval_f64(t));
        let (xp, yp, wp) = (dx.eval_f64(t), dy.eval_f64(t), dw.eval_f64(t));
        [(xp * w - x * wp) / (w * w), (yp * w - y * wp) / (w * w)]
    };
    let k = 4;
    (0..k)
        .map(|i| {
            let (t0, t1) = (a + (b - a) * i as f64 / k as f64, a + (b - a) * (i + 1) as f64 / k as f64);
            let (q0, q1) = (if i == 0 { p0 } else { point(t0) }, if i + 1 == k { p1 } else { point(t1) });
            let (d0, d1) = (tangent(t0), tangent(t1));
            let h = (t1 - t0) / 3.0;
            vec![q0, [q0[0] + d0[0] * h, q0[1] + d0[1] * h], [q1[0] - d1[0] * h, q1[1] - d1[1] * h], q1]
        })
        .collect()
}
