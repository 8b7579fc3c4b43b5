"""The exact kernel under ``casteljau.pathops``: a path's verbs and points to casteljau's
exchange form and back, the exact boolean operations, the exact queries (tight bounds, winding,
convexity), and skia-pathops' conventions for a result (contours ordered by area, starting
points restored).

It works on a path's stored lists (verbs, points, conic weights), never on a ``Path``: the
``Path`` class (``_path``) is built on this module, not the other way round.
"""

from __future__ import annotations

import math
from fractions import Fraction
from typing import Any, Dict, Iterable, List, Optional, Sequence, Tuple

from .. import _core
from .._contours import resolve
from ._base import (
    ExactOperationError,
    FillType,
    PathVerb,
    Point,
    UnsupportedVerbError,
    _collinear,
    _same,
)

Contours = List[List[Tuple[list, Optional[list]]]]

#: One closed contour as a path stores it: verbs (``MOVE`` first, ``CLOSE`` last), points, conic
#: weights.
Records = Tuple[List[PathVerb], List[Point], List[Any]]


def contours_of(verbs: Sequence[PathVerb], points: Sequence[Point], weights: Sequence[Any]) -> Contours:
    """A path's contours as casteljau's exchange form: each contour closed by a line when its
    last point is not its first (Skia fills open contours closed)."""
    out: Contours = []
    segs: List[Tuple[list, Optional[list]]] = []
    pts = points
    n = len(verbs)
    ws = iter(weights)
    start = cur = None
    i = 0
    MOVE, LINE, QUAD, CUBIC, CLOSE = PathVerb.MOVE, PathVerb.LINE, PathVerb.QUAD, PathVerb.CUBIC, PathVerb.CLOSE
    for k, v in enumerate(verbs):
        if v == MOVE or v == CLOSE:
            if segs:
                if not _same(cur, start):  # type: ignore[arg-type]
                    segs.append(([cur, start], None))
                out.append(segs)
                segs = []
            if v == MOVE:
                if k == n - 1:
                    break  # a trailing moveTo draws nothing
                start = cur = pts[i]
                i += 1
        elif v == LINE:
            p = pts[i]
            segs.append(([cur, p], None))
            cur = p
            i += 1
        elif v == QUAD:
            p = pts[i + 1]
            segs.append(([cur, pts[i], p], None))
            cur = p
            i += 2
        elif v == CUBIC:
            p = pts[i + 2]
            segs.append(([cur, pts[i], pts[i + 1], p], None))
            cur = p
            i += 3
        else:  # CONIC
            p = pts[i + 1]
            segs.append(([cur, pts[i], p], [1, next(ws), 1]))
            cur = p
            i += 2
    if segs:
        if not _same(cur, start):  # type: ignore[arg-type]
            segs.append(([cur, start], None))
        out.append(segs)
    return out


def _conic_weight(ws: Sequence[Any]) -> Any:
    """The middle weight of ``(w0, w1, w2)`` in Skia's form ``(1, w, 1)``: ``w1/√(w0·w2)``,
    exact when the square root is rational."""
    w0, w1, w2 = ws
    if all(isinstance(w, (int, Fraction)) for w in ws):
        p = Fraction(w0) * Fraction(w2)
        if p <= 0:
            raise UnsupportedVerbError("a rational quadratic with end weights of opposite signs")
        n, d = math.isqrt(p.numerator), math.isqrt(p.denominator)
        if n * n == p.numerator and d * d == p.denominator:
            return Fraction(w1) / Fraction(n, d)
    return float(w1) / math.sqrt(float(w0) * float(w2))


def records_of(c: List[Tuple[list, Optional[list]]]) -> Records:
    """One closed contour in exchange form as a path's records, its numbers used as they are (a
    last line back to the start is left to ``CLOSE``)."""
    start = tuple(c[0][0][0])
    verbs: List[PathVerb] = [PathVerb.MOVE]
    points: List[Point] = [start]  # type: ignore[list-item]
    weights: List[Any] = []
    add_verb, add_points = verbs.append, points.extend
    LINE, QUAD, CUBIC = PathVerb.LINE, PathVerb.QUAD, PathVerb.CUBIC
    last = len(c) - 1
    for k, (pts, ws) in enumerate(c):
        n = len(pts)
        if ws is not None:
            if n != 3:
                raise UnsupportedVerbError("a rational segment of degree %d" % (n - 1))
            w = _conic_weight(ws)
            if w == 1:
                add_verb(QUAD)
            else:
                add_verb(PathVerb.CONIC)
                weights.append(w)
        elif n == 2:
            if k == last and _same(pts[1], start):
                continue
            add_verb(LINE)
        elif n == 3:
            add_verb(QUAD)
        elif n == 4:
            add_verb(CUBIC)
        else:
            raise UnsupportedVerbError("a segment of degree %d" % (n - 1))
        rest = pts[1:]
        add_points(rest if type(rest[0]) is tuple else [tuple(p) for p in rest])
    verbs.append(PathVerb.CLOSE)
    return verbs, points, weights


def boolean(
    op: str, inputs: Sequence[Tuple[Contours, str]], orientation: str, max_work: Optional[float]
) -> Tuple[Contours, List[Any]]:
    """The exact operation ``op`` on ``(contours, fill rule)`` inputs: the result's contours in
    exchange form and their signed areas. Casteljau's errors are raised as
    ``ExactOperationError``."""
    rules = [r for _, r in inputs]
    shapes = [c for c, _ in inputs]
    try:
        if len(set(rules)) > 1:
            # different fill rules: each even-odd input as the boundary of its region first
            for i, r in enumerate(rules):
                if r == "evenodd":
                    shapes[i] = resolve(_core.boolean("simplify", [shapes[i]], "evenodd", "ccw", max_work)[0], [shapes[i]])
            rules = ["nonzero"] * len(rules)
        items, _, _, _, areas = _core.boolean(op, shapes, rules[0] if rules else "nonzero", orientation, max_work)
        contours = resolve(items, shapes)
    except _core.CasteljauError as e:
        raise ExactOperationError(str(e)) from e
    return contours, areas


def result_records(
    contours: Contours, areas: List[Any], fix_winding: bool, keep_starting_points: bool, first_points: List[Any]
) -> Tuple[FillType, List[Records]]:
    """skia-pathops' conventions for an operation's result: the fill type (winding with
    ``fix_winding``, else even-odd), contours by decreasing absolute area with ``fix_winding``,
    and each contour started, where it can be, at one of ``first_points``."""
    fill = FillType.WINDING if fix_winding else FillType.EVEN_ODD
    items = [(c, a) for c, a in zip(contours, areas) if c]
    if fix_winding and len(items) > 1 and all(a is not None for _, a in items):
        # by decreasing absolute area, stable (skia-pathops' winding_from_even_odd)
        items.sort(key=lambda ca: -abs(ca[1]))
    out = []
    points = list(first_points) if keep_starting_points else []
    for c, _ in items:
        if points:
            # skia-pathops tries each point in turn: the first that is an on-curve point of the
            # contour other than its start moves the start there
            ends: Dict[Any, int] = {}
            for k in range(len(c) - 2, -1, -1):
                ends[tuple(c[k][0][-1])] = k
            for j, pt in enumerate(points):
                k = ends.get(tuple(pt))
                if k is not None and not _same(pt, c[0][0][0]):
                    c = _started_after(c, k)
                    del points[j]
                    break
        out.append(records_of(c))
    return fill, out


def _started_after(c: List[Tuple[list, Optional[list]]], k: int) -> List[Tuple[list, Optional[list]]]:
    """A closed contour (exchange form) started at the end of its segment ``k``, as skia-pathops'
    ``set_contour_start_point`` does it: the old start stays a corner, unless the lines on both
    sides of it lie on one line, which become one line (skia-pathops #12)."""
    last, first = c[-1], c[0]
    if (
        last[1] is None
        and first[1] is None
        and len(last[0]) == 2
        and len(first[0]) == 2
        and _collinear(last[0][0], first[0][0], first[0][1])
    ):
        joined = ([last[0][0], first[0][1]], None)
        if k == 0:
            return c[1:-1] + [joined]
        return c[k + 1 : -1] + [joined] + c[1 : k + 1]
    return c[k + 1 :] + c[: k + 1]


def tight_bounds(records: Iterable[Tuple[PathVerb, Tuple[Point, ...]]], weights: Sequence[Any]) -> Tuple[Any, Any, Any, Any]:
    """Exact tight bounds of a path's records ``(verb, points)`` (conic weights apart): end
    points, and each curve's exact box where its control points leave the box of its ends."""
    xs: List[Any] = []
    ys: List[Any] = []
    cur: Any = None
    ws = iter(weights)
    for verb, pts in records:
        if verb == PathVerb.CLOSE:
            continue
        if verb in (PathVerb.MOVE, PathVerb.LINE):
            cur = pts[0]
            xs.append(cur[0])
            ys.append(cur[1])
            continue
        ctrl = [cur] + list(pts)
        w = next(ws) if verb == PathVerb.CONIC else None
        end = ctrl[-1]
        xs.append(end[0])
        ys.append(end[1])
        lo_x, hi_x = min(cur[0], end[0]), max(cur[0], end[0])
        lo_y, hi_y = min(cur[1], end[1]), max(cur[1], end[1])
        if any(not (lo_x <= p[0] <= hi_x and lo_y <= p[1] <= hi_y) for p in ctrl[1:-1]):
            if w is None:
                b = _core.Bezier(ctrl).bounds()
            else:
                b = _core.RationalBezier(ctrl, [1, w, 1]).bounds()
            xs += [b[0], b[2]]
            ys += [b[1], b[3]]
        cur = end
    if not xs:
        return (0, 0, 0, 0)
    return (min(xs), min(ys), max(xs), max(ys))


def contains(contours: Contours, fill: FillType, pt: Tuple[Any, Any]) -> bool:
    """Whether ``pt`` is in the fill of ``contours`` under a Skia fill type, exactly (on the
    boundary: inside)."""
    w = _core.winding(contours, pt)
    inverse = fill in (FillType.INVERSE_WINDING, FillType.INVERSE_EVEN_ODD)
    if w is None:
        return True
    inside = (w % 2 == 1) if fill in (FillType.EVEN_ODD, FillType.INVERSE_EVEN_ODD) else w != 0
    return inside != inverse


def is_convex(contours: Contours) -> bool:
    """One contour whose control polygon turns one way, once around (exact cross products)."""
    if len(contours) > 1:
        return False
    if not contours:
        return True
    pts: List[Any] = []
    for seg, _ in contours[0]:
        for p in seg[1:]:
            if not pts or not _same(pts[-1], p):
                pts.append(p)
    if len(pts) > 1 and _same(pts[0], pts[-1]):
        pts.pop()
    n = len(pts)
    if n < 3:
        return True
    sign = 0
    x_changes = 0
    last_dx = 0
    for i in range(n):
        a, b, c = pts[i], pts[(i + 1) % n], pts[(i + 2) % n]
        ux, uy = Fraction(b[0]) - Fraction(a[0]), Fraction(b[1]) - Fraction(a[1])
        vx, vy = Fraction(c[0]) - Fraction(b[0]), Fraction(c[1]) - Fraction(b[1])
        cross = ux * vy - uy * vx
        s = (cross > 0) - (cross < 0)
        if s:
            if sign and s != sign:
                return False
            sign = s
        dx = (ux > 0) - (ux < 0)
        if dx:
            if last_dx and dx != last_dx:
                x_changes += 1
            last_dx = dx
    return x_changes <= 2
