"""skia-pathops' ``Path`` and ``PathPen`` with exact numbers.

A ``Path`` stores its verbs and points as Skia's ``SkPath`` does, but every coordinate is an
exact number: ints, floats (their binary64 value, not rounded to float32 as Skia does) and
``Fraction``s are kept as given; strings such as ``"1/3"`` are read exactly. Points computed by
an operation are ``Fraction``s when rational and correctly rounded floats when irrational.
Geometric decisions (is a point the midpoint, do two points coincide) are exact comparisons,
where Skia compares within ``SK_ScalarNearlyZero``.
"""

from __future__ import annotations

import itertools
from fractions import Fraction
from typing import Any, Iterator, List, Optional, Sequence, Tuple

from . import _exact
from ._base import (
    _POINTS_IN_VERB,
    _VERB_METHODS,
    FillType,
    NumberOfPointsError,
    OpenPathError,
    PathVerb,
    Point,
    UnsupportedVerbError,
    _halves,
    _is_middle,
    _mid,
    _num,
    _pt,
    _q,
    _same,
    decompose_quadratic_segment,
    fill_rule,
    float2bits,
)

__all__ = ["Path", "PathPen", "exchange", "from_contours", "simplify"]


class Path:
    """An exact mirror of skia-pathops' ``Path``: verbs and exact points.

    >>> from casteljau.pathops import Path, PathVerb
    >>> p = Path()
    >>> p.moveTo(0, 0); p.lineTo(10, 0); p.lineTo(0, 10); p.close()
    >>> p.area
    Fraction(50, 1)
    >>> list(p)[:2]
    [(<PathVerb.MOVE: 0>, ((0, 0),)), (<PathVerb.LINE: 1>, ((10, 0),))]
    """

    __slots__ = ("_verbs", "_points", "_weights", "_fill", "_last_move", "_needs_move")
    __hash__ = None  # type: ignore[assignment]  # mutable, as skia-pathops' Path

    def __init__(self, other: Any = None, fillType: Optional[int] = None) -> None:
        self._verbs: List[PathVerb] = []
        self._points: List[Point] = []
        self._weights: List[Any] = []
        self._fill = FillType.WINDING
        self._last_move: Point = (0, 0)
        self._needs_move = True
        if other is not None:
            if isinstance(other, Path):
                self._copy_from(other)
            else:
                other.draw(self.getPen())
        if fillType is not None:
            self.fillType = fillType

    def _copy_from(self, other: "Path") -> None:
        self._verbs = list(other._verbs)
        self._points = list(other._points)
        self._weights = list(other._weights)
        self._fill = other._fill
        self._last_move = other._last_move
        self._needs_move = other._needs_move

    def copy(self) -> "Path":
        """A copy."""
        return Path(self)

    @classmethod
    def _from_records(cls, fill: FillType, contours: Sequence[_exact.Records]) -> "Path":
        """A path of closed contours given as their verbs, points and conic weights."""
        out = cls(fillType=fill)
        for verbs, points, weights in contours:
            out._verbs += verbs
            out._points += points
            out._weights += weights
            out._last_move = points[0]
        return out

    # -- building ---------------------------------------------------------------------------

    def getPen(self, glyphSet: Any = None, allow_open_paths: bool = True) -> "PathPen":
        """A fontTools segment pen drawing into this path."""
        return PathPen(self, glyphSet=glyphSet, allow_open_paths=allow_open_paths)

    def _ensure_move(self) -> None:
        if self._needs_move:
            self._move(self._last_move)

    def _move(self, p: Point) -> None:
        if self._verbs and self._verbs[-1] == PathVerb.MOVE:
            # consecutive moveTo collapse (Skia m143+): the second replaces the first
            self._points[-1] = p
        else:
            self._verbs.append(PathVerb.MOVE)
            self._points.append(p)
        self._last_move = p
        self._needs_move = False

    def moveTo(self, x: Any, y: Any) -> None:
        self._move((_num(x), _num(y)))

    def lineTo(self, x: Any, y: Any) -> None:
        self._ensure_move()
        self._verbs.append(PathVerb.LINE)
        self._points.append((_num(x), _num(y)))

    def quadTo(self, x1: Any, y1: Any, x2: Any, y2: Any) -> None:
        self._ensure_move()
        self._verbs.append(PathVerb.QUAD)
        self._points.append((_num(x1), _num(y1)))
        self._points.append((_num(x2), _num(y2)))

    def conicTo(self, x1: Any, y1: Any, x2: Any, y2: Any, w: Any) -> None:
        """A conic: the rational quadratic with weights ``(1, w, 1)``, exact (skia-pathops
        passes ``y2`` for ``y1`` here; this does not)."""
        self._ensure_move()
        w = _num(w)
        if w == 1:  # Skia stores a conic of weight 1 as a quad
            self.quadTo(x1, y1, x2, y2)
            return
        self._verbs.append(PathVerb.CONIC)
        self._points.append((_num(x1), _num(y1)))
        self._points.append((_num(x2), _num(y2)))
        self._weights.append(w)

    def cubicTo(self, x1: Any, y1: Any, x2: Any, y2: Any, x3: Any, y3: Any) -> None:
        self._ensure_move()
        self._verbs.append(PathVerb.CUBIC)
        self._points.append((_num(x1), _num(y1)))
        self._points.append((_num(x2), _num(y2)))
        self._points.append((_num(x3), _num(y3)))

    def arcTo(self, rx: Any, ry: Any, xAxisRotate: Any, largeArc: Any, sweep: Any, x: Any, y: Any) -> None:
        """Not supported: an SVG arc is a conic whose weight is a cosine, irrational in general."""
        raise NotImplementedError(
            "casteljau.pathops: arcTo makes conics with irrational weights (cos of half the sweep); "
            "give the arc as conicTo with exact weights"
        )

    def close(self) -> None:
        if self._verbs and self._verbs[-1] != PathVerb.CLOSE:
            self._verbs.append(PathVerb.CLOSE)
        self._needs_move = True

    def reset(self) -> None:
        fill = self._fill
        self.__init__()  # type: ignore[misc]
        self._fill = fill

    def rewind(self) -> None:
        """Deprecated alias for ``reset()``."""
        self.reset()

    def add(self, verb: int, *pts: Any) -> None:
        """Appends one verb with its points (a conic: two points and the weight)."""
        verb = PathVerb(verb)
        if verb == PathVerb.MOVE:
            self.moveTo(*pts[0])
        elif verb == PathVerb.LINE:
            self.lineTo(*pts[0])
        elif verb == PathVerb.QUAD:
            self.quadTo(*pts[0], *pts[1])
        elif verb == PathVerb.CONIC:
            self.conicTo(*pts[0], *pts[1], pts[2])
        elif verb == PathVerb.CUBIC:
            self.cubicTo(*pts[0], *pts[1], *pts[2])
        elif verb == PathVerb.CLOSE:
            self.close()
        else:  # pragma: no cover
            raise UnsupportedVerbError(verb)

    def addPath(self, path: "Path") -> None:
        """Appends the contours of ``path`` (its numbers are exact already: taken as they are)."""
        verbs, points = path._verbs, path._points
        if verbs and verbs[-1] == PathVerb.MOVE:  # a trailing moveTo draws nothing
            verbs, points = verbs[:-1], points[:-1]
        if not verbs:
            return
        if self._verbs and self._verbs[-1] == PathVerb.MOVE:  # consecutive moveTo collapse
            self._verbs.pop()
            self._points.pop()
        self._verbs += verbs
        self._points += points
        self._weights += path._weights
        i = len(points)
        for v in reversed(verbs):
            i -= _POINTS_IN_VERB[v]
            if v == PathVerb.MOVE:
                self._last_move = points[i]
                break
        self._needs_move = verbs[-1] == PathVerb.CLOSE

    # -- reading ----------------------------------------------------------------------------

    def _records(self) -> Iterator[Tuple[PathVerb, Tuple[Point, ...]]]:
        """Verbs with their own points (conics without the weight); trailing moveTo stripped."""
        i = 0
        n = len(self._verbs)
        for k, verb in enumerate(self._verbs):
            c = _POINTS_IN_VERB[verb]
            if verb == PathVerb.MOVE and k == n - 1:
                return
            yield verb, tuple(self._points[i : i + c])
            i += c

    def __iter__(self) -> Iterator[Tuple[PathVerb, tuple]]:
        w = iter(self._weights)
        for verb, pts in self._records():
            if verb == PathVerb.CONIC:
                yield verb, pts + (next(w),)
            else:
                yield verb, pts

    def __len__(self) -> int:
        return sum(1 for v, _ in self._records() if v == PathVerb.MOVE)

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Path):
            return NotImplemented
        return (
            self._fill == other._fill
            and self._verbs == other._verbs
            and self._points == other._points
            and self._weights == other._weights
        )

    def __ne__(self, other: object) -> bool:
        eq = self.__eq__(other)
        return eq if eq is NotImplemented else not eq

    def __repr__(self) -> str:
        return "<casteljau.pathops.Path object at %s: %d contours>" % (hex(id(self)), len(self))

    def _to_string(self, as_hex: bool = False) -> str:
        if not self._verbs:
            return ""

        def coords_to_string(fs: Sequence[Any]) -> str:
            if as_hex:
                return "".join("\n    bits2float(%s),  # %g" % (hex(float2bits(float(f))), f) for f in fs) + "\n"
            return ", ".join(str(f) for f in fs)

        lines = ["path.fillType = %s" % self.fillType]
        for verb, pts in self:
            suffix = ""
            if verb == PathVerb.CONIC:
                suffix = "[%s]" % coords_to_string([pts[-1]])
                pts = pts[:-1]
            lines.append("path.%s(%s)%s" % (_VERB_METHODS[verb], coords_to_string(list(itertools.chain(*pts))), suffix))
        return "\n".join(lines)

    def __str__(self) -> str:
        return self._to_string()

    def dump(self, cpp: bool = False, as_hex: bool = False) -> None:
        """Prints the path as Python code."""
        print(self._to_string(as_hex=as_hex))

    @property
    def fillType(self) -> FillType:
        return self._fill

    @fillType.setter
    def fillType(self, value: int) -> None:
        self._fill = FillType(value)

    @property
    def verbs(self) -> List[PathVerb]:
        return list(self._verbs)

    @property
    def points(self) -> List[Point]:
        return list(self._points)

    @property
    def firstPoints(self) -> List[Point]:
        """The first point of each contour."""
        return [pts[0] for v, pts in self._records() if v == PathVerb.MOVE]

    @property
    def contours(self) -> Iterator["Path"]:
        """Each contour as a ``Path``."""
        temp = Path(fillType=self._fill)
        w = iter(self._weights)
        for verb, pts in self._records():
            if verb == PathVerb.MOVE:
                if temp._verbs:
                    yield temp
                    temp = Path(fillType=self._fill)
                temp.moveTo(*pts[0])
            elif verb == PathVerb.CLOSE:
                temp.close()
                yield temp
                temp = Path(fillType=self._fill)
            elif verb == PathVerb.CONIC:
                temp.conicTo(*pts[0], *pts[1], next(w))
            else:
                temp.add(verb, *pts)
        if temp._verbs:
            yield temp

    @property
    def segments(self) -> Iterator[Tuple[str, tuple]]:
        """The path as fontTools segment-pen calls: TrueType quadratic splines joined where the
        on-curve point is exactly the midpoint, ``endPath`` for open contours, and an
        on-curve-less closed spline as ``qCurveTo(..., None)``."""
        calls = list(_segment_pen_calls(self))
        n = len(calls)
        k = 0
        while k < n:
            call = calls[k]
            if call[0] == "moveTo" and k + 2 < n and calls[k + 1][0] == "qCurveTo" and calls[k + 2][0] == "closePath":
                q = calls[k + 1][1]
                if len(q) > 2 and _same(call[1][0], q[-1]) and _is_middle(q[-2], q[-1], q[0]):
                    # the moveTo is the spline's implied on-curve point: drawn as fontTools does
                    yield ("qCurveTo", q[:-1] + (None,))
                    k += 2
                    continue
            yield call
            k += 1

    def draw(self, pen: Any) -> None:
        """Draws the path with a fontTools segment pen."""
        for method, pts in self.segments:
            getattr(pen, method)(*pts)

    # -- geometry ---------------------------------------------------------------------------

    @property
    def area(self) -> Fraction:
        """The absolute value of the signed area (open contours closed), exact."""
        return abs(_signed_area(self))

    @property
    def clockwise(self) -> bool:
        """Whether the signed area is negative (y up: clockwise)."""
        return _signed_area(self) < 0

    @clockwise.setter
    def clockwise(self, value: bool) -> None:
        if self.clockwise != value:
            self.reverse()

    @property
    def bounds(self) -> Tuple[Any, Any, Any, Any]:
        """The exact tight bounds ``(xMin, yMin, xMax, yMax)``: curve extrema included, each a
        number as stored, a ``Fraction`` or an ``Algebraic``."""
        return _exact.tight_bounds(self._records(), self._weights)

    @property
    def controlPointBounds(self) -> Tuple[Any, Any, Any, Any]:
        """The bounds of every stored point."""
        pts = [p for _, ps in self._records() for p in ps]
        if not pts:
            return (0, 0, 0, 0)
        xs = [p[0] for p in pts]
        ys = [p[1] for p in pts]
        return (min(xs), min(ys), max(xs), max(ys))

    @property
    def isConvex(self) -> bool:
        """Whether the path is one convex contour of lines (exact turns; curves are decided by
        their control polygons, as Skia does)."""
        return _exact.is_convex(exchange(self))

    def contains(self, pt: Tuple[Any, Any]) -> bool:
        """Whether the point is inside the path's fill (exact; a point on the boundary counts as
        inside, as Skia's ``contains``)."""
        return _exact.contains(exchange(self), self._fill, pt)

    def reverse(self) -> None:
        """Reverses every contour in place (the last point becomes the first)."""
        out = Path(fillType=self._fill)
        for contour in self.contours:
            _reverse_contour(contour)
            out.addPath(contour)
        self._copy_from(out)
        self._fill = out._fill

    def simplify(self, fix_winding: bool = True, keep_starting_points: bool = True, clockwise: bool = False) -> None:
        """Removes overlaps in place (the exact region; see ``casteljau.pathops.simplify``)."""
        self._copy_from(
            simplify(self, fix_winding=fix_winding, keep_starting_points=keep_starting_points, clockwise=clockwise)
        )

    def convertConicsToQuads(self, tolerance: float = 0.25) -> None:
        """Not supported exactly: a conic is not a sequence of quadratics."""
        if PathVerb.CONIC not in self._verbs:
            return
        raise NotImplementedError(
            "casteljau.pathops: a conic is not a union of quadratic Béziers; convertConicsToQuads is "
            "Skia's float approximation. The exact operations take conics as they are."
        )

    def stroke(self, width: float, cap: int, join: int, miter_limit: float, dash_array: Any = None, dash_offset: float = 0) -> None:
        """Not supported: stroking is Skia's float stroker, outside casteljau's exact scope."""
        raise NotImplementedError(
            "casteljau.pathops: stroking (Skia's float stroker) is out of scope; offset curves of "
            "Béziers are not Béziers"
        )

    def transform(
        self,
        scaleX: Any = 1,
        skewY: Any = 0,
        skewX: Any = 0,
        scaleY: Any = 1,
        translateX: Any = 0,
        translateY: Any = 0,
        perspectiveX: Any = 0,
        perspectiveY: Any = 0,
        perspectiveBias: Any = 1,
    ) -> "Path":
        """The path mapped by the affine matrix ``[a b c d e f]`` (SVG order), exactly: the
        numbers given (floats as their binary64 values) with no rounding. Perspective is not
        supported (it would turn segments into rational curves)."""
        if perspectiveX != 0 or perspectiveY != 0 or perspectiveBias != 1:
            raise NotImplementedError("casteljau.pathops: perspective transforms are not supported")
        a, b, c, d, e, f = (_q(_num(v)) for v in (scaleX, skewY, skewX, scaleY, translateX, translateY))
        # ints and Fractions compute exactly as they are; floats become their exact Fractions
        if a == 1 and d == 1 and b == 0 and c == 0:

            def m(p: Point) -> Point:
                return (_q(p[0]) + e, _q(p[1]) + f)

        else:

            def m(p: Point) -> Point:
                x, y = _q(p[0]), _q(p[1])
                return (a * x + c * y + e, b * x + d * y + f)

        out = Path(self)
        out._points = [m(p) for p in self._points]
        out._last_move = m(self._last_move)
        return out


def exchange(path: Path) -> _exact.Contours:
    """A path's contours as casteljau's exchange form: each contour closed by a line when its
    last point is not its first (Skia fills open contours closed)."""
    return _exact.contours_of(path._verbs, path._points, path._weights)


def from_contours(contours: _exact.Contours, fill: FillType = FillType.WINDING) -> Path:
    """Closed contours in exchange form as a path (their numbers as they are)."""
    return Path._from_records(fill, [_exact.records_of(c) for c in contours if c])


def finish(contours: _exact.Contours, areas: List[Any], fix_winding: bool, keep_starting_points: bool, first_points: List[Any]) -> Path:
    """An operation's result as skia-pathops gives it (see ``_exact.result_records``)."""
    fill, records = _exact.result_records(contours, areas, fix_winding, keep_starting_points, first_points)
    return Path._from_records(fill, records)


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
    inputs = [(exchange(path), fill_rule(path.fillType))]
    contours, areas = _exact.boolean("simplify", inputs, "cw" if clockwise else "ccw", max_work)
    return finish(contours, areas, fix_winding, keep_starting_points, first)


def _segment_pen_calls(path: Path) -> Iterator[Tuple[str, tuple]]:
    """skia-pathops' SegmentPenIterator, with exact comparisons."""
    verbs, pts = path._verbs, path._points
    n = len(verbs)
    if n and verbs[-1] == PathVerb.MOVE:  # a trailing moveTo draws nothing
        n -= 1
    MOVE, LINE, QUAD, CUBIC, CLOSE = PathVerb.MOVE, PathVerb.LINE, PathVerb.QUAD, PathVerb.CUBIC, PathVerb.CLOSE
    closed = True
    i = k = 0
    while k < n:
        verb = verbs[k]
        if verb == LINE:
            yield ("lineTo", (pts[i],))
            i += 1
        elif verb == QUAD:
            # join a TrueType spline: the next quad continues it when this quad's on-curve
            # point is exactly the midpoint of the two off-curve points
            off, on = pts[i], pts[i + 1]
            i += 2
            points = [off]
            while k + 1 < n and verbs[k + 1] == QUAD and _is_middle(off, on, pts[i]):
                k += 1
                off, on = pts[i], pts[i + 1]
                i += 2
                points.append(off)
            points.append(on)
            yield ("qCurveTo", tuple(points))
        elif verb == CUBIC:
            yield ("curveTo", (pts[i], pts[i + 1], pts[i + 2]))
            i += 3
        elif verb == MOVE:
            if not closed:
                yield ("endPath", ())
            closed = False
            yield ("moveTo", (pts[i],))
            i += 1
        elif verb == CLOSE:
            closed = True
            yield ("closePath", ())
        else:
            raise UnsupportedVerbError("CONIC")
        k += 1
    if not closed:
        yield ("endPath", ())


def _reverse_contour(path: Path) -> None:
    """Reverses a one-contour path in place (skia-pathops' reverse_contour; conics too)."""
    records = list(path._records())
    if not records:
        return
    weights = list(path._weights)
    out = Path(fillType=path._fill)
    # the start point of each record
    starts: List[Point] = []
    cur: Point = records[0][1][0]
    for verb, pts in records:
        starts.append(cur)
        if pts:
            cur = pts[-1]
    out.moveTo(*path._points[-1])
    closed = False
    wi = len(weights)
    for (verb, pts), start in zip(reversed(records[1:]), reversed(starts[1:])):
        if verb == PathVerb.LINE:
            out.lineTo(*start)
        elif verb == PathVerb.QUAD:
            out.quadTo(*pts[0], *start)
        elif verb == PathVerb.CONIC:
            wi -= 1
            out.conicTo(*pts[0], *start, weights[wi])
        elif verb == PathVerb.CUBIC:
            out.cubicTo(*pts[1], *pts[0], *start)
        elif verb == PathVerb.CLOSE:
            closed = True
    if closed:
        out.close()
    path._copy_from(out)


def _signed_area(path: Path) -> Fraction:
    """fontTools' AreaPen formula, exactly (open contours closed)."""
    value = Fraction(0)
    p0: Point = (0, 0)
    start: Point = (0, 0)
    need_close = False

    def line(a: Point, b: Point) -> Fraction:
        return -(Fraction(b[0]) - Fraction(a[0])) * (Fraction(b[1]) + Fraction(a[1])) / 2

    for verb, pts in path._records():
        if verb == PathVerb.MOVE:
            if need_close:
                value += line(p0, start)
            p0 = start = pts[0]
            need_close = True
        elif verb == PathVerb.LINE:
            value += line(p0, pts[0])
            p0 = pts[0]
        elif verb == PathVerb.QUAD:
            x0, y0 = Fraction(p0[0]), Fraction(p0[1])
            x1, y1 = Fraction(pts[0][0]) - x0, Fraction(pts[0][1]) - y0
            x2, y2 = Fraction(pts[1][0]) - x0, Fraction(pts[1][1]) - y0
            value -= (x2 * y1 - x1 * y2) / 3
            value += line(p0, pts[1])
            p0 = pts[1]
        elif verb == PathVerb.CUBIC:
            x0, y0 = Fraction(p0[0]), Fraction(p0[1])
            x1, y1 = Fraction(pts[0][0]) - x0, Fraction(pts[0][1]) - y0
            x2, y2 = Fraction(pts[1][0]) - x0, Fraction(pts[1][1]) - y0
            x3, y3 = Fraction(pts[2][0]) - x0, Fraction(pts[2][1]) - y0
            value -= (x1 * (-y2 - y3) + x2 * (y1 - 2 * y3) + x3 * (y1 + 2 * y2)) * Fraction(3, 20)
            value += line(p0, pts[2])
            p0 = pts[2]
        elif verb == PathVerb.CONIC:
            raise UnsupportedVerbError("CONIC")
        elif verb == PathVerb.CLOSE:
            value += line(p0, start)
            p0 = start = (0, 0)
            need_close = False
    if need_close:
        value += line(p0, start)
    return value


def _all_int(points: Sequence[Any]) -> bool:
    for x, y in points:
        if type(x) is not int or type(y) is not int:
            return False
    return True


class PathPen:
    """A fontTools segment pen drawing into a ``Path`` (skia-pathops' ``PathPen``), with the
    implied on-curve points of TrueType splines at their exact midpoints."""

    def __init__(self, path: Path, glyphSet: Any = None, allow_open_paths: bool = True) -> None:
        self.path = path
        self.glyphSet = glyphSet
        self.allow_open_paths = allow_open_paths

    def moveTo(self, pt: Sequence[Any]) -> None:
        self.path.moveTo(pt[0], pt[1])

    def lineTo(self, pt: Sequence[Any]) -> None:
        x, y = pt
        if type(x) is int and type(y) is int and not self.path._needs_move:
            self.path._verbs.append(PathVerb.LINE)
            self.path._points.append((x, y))
            return
        self.path.lineTo(x, y)

    def curveTo(self, *points: Sequence[Any]) -> None:
        n = len(points) - 1
        if n == 2:
            p1, p2, p3 = points
            self.path.cubicTo(p1[0], p1[1], p2[0], p2[1], p3[0], p3[1])
        elif n == 1:
            p1, p2 = points
            self.path.quadTo(p1[0], p1[1], p2[0], p2[1])
        elif n == 0:
            self.path.lineTo(points[0][0], points[0][1])
        else:
            raise NumberOfPointsError("curveTo requires between 1 and 3 points; got %d" % len(points))

    def qCurveTo(self, *points: Any) -> None:
        n = len(points) - 1
        if n > 0 and points[-1] is not None and _all_int(points):
            # integer points (TrueType): the implied on-curve points straight into the path
            path = self.path
            path._ensure_move()
            verbs, pts = path._verbs, path._points
            for i in range(n - 1):
                (x, y), (nx, ny) = points[i], points[i + 1]
                sx, sy = x + nx, y + ny
                verbs.append(PathVerb.QUAD)
                pts.append((x, y))
                pts.append((sx >> 1 if not sx & 1 else _halves(sx), sy >> 1 if not sy & 1 else _halves(sy)))
            verbs.append(PathVerb.QUAD)
            pts.append(tuple(points[-2]))
            pts.append(tuple(points[-1]))
            return
        if n > 0:
            oncurveless = points[-1] is None
            pts = tuple(_pt(p) for p in points[:-1]) + ((None,) if oncurveless else (_pt(points[-1]),))
            if oncurveless:
                implied = _mid(pts[-2], pts[0])
                self.moveTo(implied)
                pts = pts[:-1] + (implied,)
            for p1, p2 in decompose_quadratic_segment(pts):
                self.path.quadTo(p1[0], p1[1], p2[0], p2[1])
            if oncurveless:
                self.closePath()
        elif n == 0:
            self.lineTo(points[0])
        else:
            raise NumberOfPointsError("qCurveTo requires at least 1 point; got 0")

    def closePath(self) -> None:
        self.path.close()

    def endPath(self) -> None:
        if not self.allow_open_paths:
            raise OpenPathError()

    def addComponent(self, glyphName: str, transformation: Sequence[Any]) -> None:
        if self.glyphSet is None:
            raise TypeError("Missing required glyphSet; can't decompose components")
        base = self.glyphSet[glyphName]
        base_path = Path()
        base.draw(base_path.getPen(glyphSet=self.glyphSet))
        if tuple(transformation) != (1, 0, 0, 1, 0, 0):
            base_path = base_path.transform(*transformation)
        self.path.addPath(base_path)

    def addVarComponent(self, glyphName: str, transformation: Any, location: Any) -> None:
        raise TypeError("variable components are not supported")

