"""The exact operations under ``casteljau.pathops``: paths to casteljau shapes and back."""

from __future__ import annotations

import math
from fractions import Fraction
from typing import Any, Dict, List, Optional, Sequence, Tuple

from .. import _core
from ..shape import resolve
from ._path import (
    FillType,
    Path,
    PathOp,
    PathOpsError,
    PathVerb,
    UnsupportedVerbError,
    _collinear,
    _reverse_contour,
    _same,
    _signed_area,
    _POINTS_IN_VERB,
)

Contours = List[List[Tuple[list, Optional[list]]]]


class ExactOperationError(PathOpsError, _core.CasteljauError):
    """An exact operation refused its input or its work budget: both a ``PathOpsError`` (as
    skia-pathops raises) and a ``casteljau.CasteljauError`` (a ``ValueError``) with casteljau's
    message (``max_work`` named when the budget refused)."""


_OPS = {
    PathOp.DIFFERENCE: "difference",
    PathOp.INTERSECTION: "intersection",
    PathOp.UNION: "union",
    PathOp.XOR: "xor",
    PathOp.REVERSE_DIFFERENCE: "difference",
}


def exchange(path: Path) -> Contours:
    """A path's contours as casteljau's exchange form: each contour closed by a line when its
    last point is not its first (Skia fills open contours closed)."""
    out: Contours = []
    segs: List[Tuple[list, Optional[list]]] = []
    pts = path._points
    verbs = path._verbs
    n = len(verbs)
    weights = iter(path._weights)
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
            segs.append(([cur, pts[i], p], [1, next(weights), 1]))
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


def _contour_path(c: List[Tuple[list, Optional[list]]], fill: FillType) -> Path:
    """One closed contour in exchange form as a path, its numbers used as they are (a last
    line back to the start is left to ``close``)."""
    path = Path(fillType=fill)
    verbs, points, weights = path._verbs, path._points, path._weights
    start = tuple(c[0][0][0])
    verbs.append(PathVerb.MOVE)
    points.append(start)
    last = len(c) - 1
    for k, (pts, ws) in enumerate(c):
        n = len(pts)
        if ws is not None:
            if n != 3:
                raise UnsupportedVerbError("a rational segment of degree %d" % (n - 1))
            w = _conic_weight(ws)
            if w == 1:
                verbs.append(PathVerb.QUAD)
            else:
                verbs.append(PathVerb.CONIC)
                weights.append(w)
            points.append(tuple(pts[1]))
            points.append(tuple(pts[2]))
        elif n == 2:
            end = tuple(pts[1])
            if k == last and _same(end, start):
                continue
            verbs.append(PathVerb.LINE)
            points.append(end)
        elif n == 3:
            verbs.append(PathVerb.QUAD)
            points.append(tuple(pts[1]))
            points.append(tuple(pts[2]))
        elif n == 4:
            verbs.append(PathVerb.CUBIC)
            points.append(tuple(pts[1]))
            points.append(tuple(pts[2]))
            points.append(tuple(pts[3]))
        else:
            raise UnsupportedVerbError("a segment of degree %d" % (n - 1))
    verbs.append(PathVerb.CLOSE)
    path._last_move = start
    path._needs_move = True
    return path


def _concatenate(paths: List[Path], fill: FillType) -> Path:
    out = Path(fillType=fill)
    for p in paths:
        out._verbs += p._verbs
        out._points += p._points
        out._weights += p._weights
        out._last_move = p._last_move
        out._needs_move = p._needs_move
    return out


def from_exchange(contours: Contours, fill: FillType) -> Path:
    """Closed contours in exchange form as a path."""
    return _concatenate([_contour_path(c, fill) for c in contours if c], fill)


def _fill_rule(fill: FillType) -> str:
    if fill in (FillType.INVERSE_WINDING, FillType.INVERSE_EVEN_ODD):
        raise PathOpsError("inverse fill types are not supported by the exact operations")
    return "evenodd" if fill == FillType.EVEN_ODD else "nonzero"


def _boolean(op: str, paths: Sequence[Path], orientation: str, max_work: Optional[float]) -> Tuple[Contours, List[Any]]:
    """The exact operation's contours and their signed areas."""
    rules = [_fill_rule(p.fillType) for p in paths]
    inputs = [exchange(p) for p in paths]
    try:
        if len(set(rules)) > 1:
            # different fill rules: each even-odd input as the boundary of its region first
            for i, r in enumerate(rules):
                if r == "evenodd":
                    inputs[i] = resolve(_core.boolean("simplify", [inputs[i]], "evenodd", "ccw", max_work)[0], [inputs[i]])
            rules = ["nonzero"] * len(rules)
        items, _, _, _, areas = _core.boolean(op, inputs, rules[0], orientation, max_work)
        contours = resolve(items, inputs)
    except _core.CasteljauError as e:
        raise ExactOperationError(str(e)) from e
    return contours, areas


def _finish(
    contours: Contours, areas: List[Any], fix_winding: bool, keep_starting_points: bool, first_points: List[Any]
) -> Path:
    fill = FillType.WINDING if fix_winding else FillType.EVEN_ODD
    items = [(c, a) for c, a in zip(contours, areas) if c]
    if fix_winding and len(items) > 1 and all(a is not None for _, a in items):
        # by decreasing absolute area, stable (skia-pathops' winding_from_even_odd)
        items.sort(key=lambda ca: -abs(ca[1]))
    paths = [_contour_path(c, fill) for c, _ in items]
    if keep_starting_points and first_points:
        points = list(first_points)
        for this in paths:
            # skia-pathops tries each point in turn; only an on-curve point of the contour other
            # than its first can move the start (the first one leaves it as it is)
            oncurve = set(_oncurve_points(this))
            first = this._points[0]
            for j, pt in enumerate(points):
                if pt not in oncurve or _same(pt, first):
                    continue
                if _set_contour_start_point(this, pt):
                    del points[j]
                    break
    return _concatenate(paths, fill)


def op(
    one: Path,
    two: Path,
    operator: int,
    fix_winding: bool = True,
    keep_starting_points: bool = True,
    clockwise: bool = False,
    *,
    max_work: Optional[float] = None,
) -> Path:
    """The exact boolean operation ``operator`` (a ``PathOp``) on two paths, each filled by its
    own fill type: the result's contours are the exact boundary of the region (outer contours
    counter-clockwise, or clockwise with ``clockwise=True``; holes the other way), each segment
    an exact piece of an input segment. ``fix_winding`` also orders contours by decreasing area
    (as skia-pathops does); ``keep_starting_points`` starts each contour, where it can, at an
    input contour's first point."""
    operator = PathOp(operator)
    first = (one.firstPoints + two.firstPoints) if keep_starting_points else []
    inputs = [two, one] if operator == PathOp.REVERSE_DIFFERENCE else [one, two]
    contours, areas = _boolean(_OPS[operator], inputs, "cw" if clockwise else "ccw", max_work)
    return _finish(contours, areas, fix_winding, keep_starting_points, first)


def simplify(
    path: Path,
    fix_winding: bool = True,
    keep_starting_points: bool = True,
    clockwise: bool = False,
    *,
    max_work: Optional[float] = None,
) -> Path:
    """The exact boundary of the path's fill (overlaps removed); see ``op``.

    >>> from casteljau.pathops import Path, simplify
    >>> p = Path()
    >>> for x, y in ((0, 0), (5, 5)):
    ...     p.moveTo(x, y); p.lineTo(x + 10, y); p.lineTo(x + 10, y + 10); p.lineTo(x, y + 10); p.close()
    >>> [pts for _, pts in simplify(p)][:3]
    [((0, 0),), ((10, 0),), ((Fraction(10, 1), Fraction(5, 1)),)]
    """
    first = path.firstPoints if keep_starting_points else []
    contours, areas = _boolean("simplify", [path], "cw" if clockwise else "ccw", max_work)
    return _finish(contours, areas, fix_winding, keep_starting_points, first)


class OpBuilder:
    """Boolean operations applied in turn: ``((empty op₁ p₁) op₂ p₂) …``, each exactly."""

    def __init__(
        self,
        fix_winding: bool = True,
        keep_starting_points: bool = True,
        clockwise: bool = False,
        *,
        max_work: Optional[float] = None,
    ) -> None:
        self.fix_winding = fix_winding
        self.keep_starting_points = keep_starting_points
        self.clockwise = clockwise
        self.max_work = max_work
        self.first_points: List[Any] = []
        self._ops: List[Tuple[Path, PathOp]] = []

    def add(self, path: Path, operator: int) -> None:
        self._ops.append((Path(path), PathOp(operator)))
        if self.keep_starting_points:
            self.first_points.extend(path.firstPoints)

    def resolve(self) -> Path:
        orientation = "cw" if self.clockwise else "ccw"
        acc: Contours = []
        areas: List[Any] = []
        for path, operator in self._ops:
            current = from_exchange(acc, FillType.WINDING)
            inputs = [path, current] if operator == PathOp.REVERSE_DIFFERENCE else [current, path]
            acc, areas = _boolean(_OPS[operator], inputs, orientation, self.max_work)
        return _finish(acc, areas, self.fix_winding, self.keep_starting_points, list(self.first_points))


def _oncurve_points(path: Path) -> List[Any]:
    """The last point of each verb (the on-curve points), in order."""
    out = []
    i = 0
    for v in path._verbs:
        n = _POINTS_IN_VERB[v]
        if n:
            i += n
            out.append(path._points[i - 1])
    return out


def restore_starting_points(path: Path, points: List[Any]) -> bool:
    """Starts each contour, where possible, at one of ``points`` (an on-curve point of it,
    exactly), as skia-pathops does after an operation."""
    if not points:
        return False
    points = list(points)
    contours = list(path.contours)
    modified = False
    for this in contours:
        for j, pt in enumerate(points):
            if _set_contour_start_point(this, pt):
                modified = True
                del points[j]
                break
    if not modified:
        return False
    fill = path.fillType
    path.reset()
    for c in contours:
        path.addPath(c)
    path.fillType = fill
    return True


def _set_contour_start_point(path: Path, pt: Any) -> bool:
    """skia-pathops' set_contour_start_point, with exact comparisons."""
    verbs = list(path._verbs)
    pts = list(path._points)
    vc, pc = len(verbs), len(pts)
    if vc == 0:
        return False
    closed = PathVerb.CLOSE in verbs[1:]
    # conic weights by verb index
    weights: Dict[int, Any] = {}
    wi = iter(path._weights)
    for i, v in enumerate(verbs):
        if v == PathVerb.CONIC:
            weights[i] = next(wi)
    pt_index = verb_index = -1
    seen = 0
    for i, v in enumerate(verbs):
        n = _POINTS_IN_VERB[v]
        if n == 0:
            continue
        j = seen + n - 1
        if _same(pts[j], pt):
            pt_index, verb_index = j, i
            break
        seen += n
    if pt_index <= 0 or (not closed and pt_index != pc - 1):
        return False
    if not closed:
        _reverse_contour(path)
        return True
    # the contour rebuilt from the new start, straight into the lists
    out_verbs: List[PathVerb] = [PathVerb.MOVE]
    first_verb = verbs[verb_index]
    first_pt = pts[pt_index]
    out_pts: List[Any] = [first_pt]
    out_weights: List[Any] = []
    vi = (verb_index + 1) % vc
    pi = (pt_index + 1) % pc
    last = first_pt
    MOVE, LINE, QUAD, CONIC, CUBIC, CLOSE = (
        PathVerb.MOVE, PathVerb.LINE, PathVerb.QUAD, PathVerb.CONIC, PathVerb.CUBIC, PathVerb.CLOSE,
    )
    for _ in range(1, vc):
        v = verbs[vi]
        n = _POINTS_IN_VERB[v]
        if v == MOVE:
            # the old start becomes a lineTo, unless it repeats the last point or lies between it
            # and the next line on one line (skia-pathops #12)
            if not (
                _same(last, pts[pi])
                or (verbs[(vi + 1) % vc] == LINE and _collinear(last, pts[pi], pts[(pi + 1) % pc]))
            ):
                out_verbs.append(LINE)
                out_pts.append(pts[pi])
                last = pts[pi]
        elif v == LINE:
            # the original contour's last line back to its old start is left to close
            if not (verbs[(vi + 1) % vc] == CLOSE and _same(pts[pi], pts[(pi + 1) % pc])):
                out_verbs.append(LINE)
                out_pts.append(pts[pi])
                last = pts[pi]
        elif v == QUAD or v == CONIC:
            out_verbs.append(v)
            out_pts += (pts[pi], pts[pi + 1])
            if v == CONIC:
                out_weights.append(weights[vi])
            last = pts[pi + 1]
        elif v == CUBIC:
            out_verbs.append(v)
            out_pts += (pts[pi], pts[pi + 1], pts[pi + 2])
            last = pts[pi + 2]
        vi = (vi + 1) % vc
        pi = (pi + n) % pc
    if first_verb in (QUAD, CONIC):
        out_verbs.append(first_verb)
        out_pts += (pts[pi], pts[pi + 1])
        if first_verb == CONIC:
            out_weights.append(weights[verb_index])
    elif first_verb == CUBIC:
        out_verbs.append(first_verb)
        out_pts += (pts[pi], pts[pi + 1], pts[pi + 2])
    out_verbs.append(CLOSE)
    path._verbs, path._points, path._weights = out_verbs, out_pts, out_weights
    path._last_move = first_pt
    path._needs_move = True
    return True


def tight_bounds(path: Path) -> Tuple[Any, Any, Any, Any]:
    """Exact tight bounds: end points, and each curve's exact box where its control points
    leave the box of its ends."""
    xs: List[Any] = []
    ys: List[Any] = []
    cur = None
    weights = iter(path._weights)
    for verb, pts in path._records():
        if verb == PathVerb.CLOSE:
            continue
        if verb in (PathVerb.MOVE, PathVerb.LINE):
            cur = pts[0]
            xs.append(cur[0])
            ys.append(cur[1])
            continue
        ctrl = [cur] + list(pts)
        w = next(weights) if verb == PathVerb.CONIC else None
        end = ctrl[-1]
        xs.append(end[0])
        ys.append(end[1])
        lo_x, hi_x = min(cur[0], end[0]), max(cur[0], end[0])  # type: ignore[index]
        lo_y, hi_y = min(cur[1], end[1]), max(cur[1], end[1])  # type: ignore[index]
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


def contains(path: Path, pt: Tuple[Any, Any]) -> bool:
    """Whether ``pt`` is in the path's fill, exactly (on the boundary: inside)."""
    w = _core.winding(exchange(path), pt)
    inverse = path.fillType in (FillType.INVERSE_WINDING, FillType.INVERSE_EVEN_ODD)
    if w is None:
        return True
    inside = (w % 2 == 1) if path.fillType in (FillType.EVEN_ODD, FillType.INVERSE_EVEN_ODD) else w != 0
    return inside != inverse


def is_convex(path: Path) -> bool:
    """One contour whose control polygon turns one way, once around (exact cross products)."""
    contours = exchange(path)
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
