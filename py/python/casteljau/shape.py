"""``casteljau.Shape``: a filled region bounded by closed contours of exact Bézier segments,
and its exact boolean operations, winding numbers and bounds."""

from __future__ import annotations

from fractions import Fraction
from typing import Any, Iterable, List, Optional, Sequence, Tuple

from . import _core
from ._contours import resolve, segment_exchange
from .pathops._base import fill_rule
from .pathops._path import Path, exchange

__all__ = ["Shape"]


class Shape:
    """A filled shape: closed contours of exact (rational) Bézier segments under a fill rule
    (``"nonzero"`` or ``"evenodd"``).

    >>> from casteljau import Shape
    >>> a = Shape.from_svg_path("M0 0 H2 V2 H0 Z")
    >>> b = Shape.from_svg_path("M1 1 H3 V3 H1 Z")
    >>> u = a.union(b)
    >>> u.area, len(u.contours)
    (Fraction(7, 1), 1)
    >>> u.to_svg_path()
    'M0 0L2 0L2 1L3 1L3 3L1 3L1 2L0 2Z'
    >>> a.winding((Fraction(1, 2), 1)), a.winding((2, 1))
    (1, None)
    """

    __slots__ = ("_contours", "fill")

    def __init__(self, contours: Iterable[Iterable[Any]] = (), fill: str = "nonzero") -> None:
        if fill not in ("nonzero", "evenodd"):
            raise _core.CasteljauError('the fill rule is "nonzero" or "evenodd", not %r' % (fill,))
        self._contours = [[segment_exchange(s) for s in c] for c in contours]
        self.fill = fill

    # -- construction -----------------------------------------------------------------------

    @classmethod
    def from_svg_path(cls, d: str, fill: str = "nonzero") -> "Shape":
        """SVG path data read exactly (open subpaths closed by a line, as SVG fills them); a bad
        token raises ``CasteljauError`` naming it and its position."""
        return cls(_core.svg_path(d), fill)

    @classmethod
    def from_contours(cls, contours: Iterable[Iterable[Any]], fill: str = "nonzero") -> "Shape":
        """Closed contours, each a sequence of ``Bezier``/``RationalBezier`` segments."""
        return cls(contours, fill)

    @classmethod
    def from_polygons(cls, polygons: Iterable[Sequence[Any]], fill: str = "nonzero") -> "Shape":
        """Closed polygons, each a sequence of vertices (the closing side implied)."""
        contours = []
        for poly in polygons:
            pts = [tuple(p) for p in poly]
            contours.append([([pts[i], pts[(i + 1) % len(pts)]], None) for i in range(len(pts))])
        return cls(contours, fill)

    @classmethod
    def from_path(cls, path: Any) -> "Shape":
        """A ``casteljau.pathops.Path`` (its fill type's rule; open contours closed)."""
        return cls(exchange(path), fill_rule(path.fillType))

    @classmethod
    def from_pen_drawing(cls, draw: Any, glyph_set: Any = None, fill: str = "nonzero") -> "Shape":
        """The shape of whatever ``draw(pen)`` draws with a fontTools segment pen (implied
        on-curve points at exact midpoints, components decomposed through ``glyph_set``)."""
        path = Path()
        draw(path.getPen(glyphSet=glyph_set))
        return cls(exchange(path), fill)

    @classmethod
    def from_glyph(cls, glyph_set: Any, name: str, fill: str = "nonzero") -> "Shape":
        """Glyph ``name`` of a fontTools glyph set (``TTFont.getGlyphSet()``, a UFO layer, a
        dict of objects with ``draw``), recorded exactly: TrueType implied on-curve points are
        exact midpoints, components are decomposed with exact transforms."""
        return cls.from_pen_drawing(glyph_set[name].draw, glyph_set, fill)

    # -- reading ----------------------------------------------------------------------------

    @property
    def contours(self) -> List[List[Any]]:
        """The contours as lists of ``Bezier``/``RationalBezier`` segments."""
        out = []
        for c in self._contours:
            segs = []
            for pts, ws in c:
                segs.append(_core.Bezier(pts) if ws is None else _core.RationalBezier(pts, ws))
            out.append(segs)
        return out

    def exchange(self) -> list:
        """The contours in the native module's exchange form (lists of ``(points, weights)``)."""
        return self._contours

    def __repr__(self) -> str:
        return "Shape(<%d contours>, fill=%r)" % (len(self._contours), self.fill)

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Shape) and self.fill == other.fill and self._contours == other._contours

    __hash__ = None  # type: ignore[assignment]

    def draw(self, pen: Any) -> None:
        """Draws the contours with a fontTools segment pen (``Fraction`` coordinates where
        rational; rational segments of degree 2 as ``qCurveTo`` is impossible, so they raise)."""
        for c in self._contours:
            if not c:
                continue
            pen.moveTo(tuple(c[0][0][0]))
            for k, (pts, ws) in enumerate(c):
                if ws is not None:
                    raise _core.CasteljauError("a rational segment cannot be drawn with a segment pen")
                if len(pts) == 2:
                    if k == len(c) - 1 and tuple(pts[1]) == tuple(c[0][0][0]):
                        continue
                    pen.lineTo(tuple(pts[1]))
                elif len(pts) == 3:
                    pen.qCurveTo(tuple(pts[1]), tuple(pts[2]))
                else:
                    pen.curveTo(*(tuple(p) for p in pts[1:]))
            pen.closePath()

    def to_svg_path(self) -> str:
        """SVG path data, numbers as ``str(Fraction)`` when rational (``1/3``) — exact, not
        SVG's float syntax — and ``repr(float)`` otherwise."""

        def num(v: Any) -> str:
            if isinstance(v, Fraction) and v.denominator == 1:
                return str(v.numerator)
            if isinstance(v, float) and v.is_integer():
                return str(int(v))
            return str(v)

        out = []
        for c in self._contours:
            if not c:
                continue
            start = c[0][0][0]
            out.append("M%s %s" % (num(start[0]), num(start[1])))
            for k, (pts, ws) in enumerate(c):
                if ws is not None:
                    raise _core.CasteljauError("a rational segment has no SVG path data")
                if len(pts) == 2 and k == len(c) - 1 and tuple(pts[1]) == tuple(start):
                    continue
                letter = {2: "L", 3: "Q", 4: "C"}[len(pts)]
                out.append(letter + " ".join("%s %s" % (num(p[0]), num(p[1])) for p in pts[1:]))
            out.append("Z")
        return "".join(out)

    # -- exact answers ----------------------------------------------------------------------

    def _op(self, op: str, others: Sequence["Shape"], orientation: str, max_work: Optional[float]) -> "Shape":
        inputs = [self._contours] + [o._contours for o in others]
        contours = _core.boolean(op, inputs, self.fill, orientation, max_work)[0]
        return Shape(resolve(contours, inputs), "nonzero")

    def simplify(self, *, orientation: str = "ccw", max_work: Optional[float] = None) -> "Shape":
        """The exact boundary of the fill: overlaps removed, outer contours ``orientation``
        (``"ccw"`` or ``"cw"``), holes the other way."""
        return self._op("simplify", [], orientation, max_work)

    def union(self, other: "Shape", *, orientation: str = "ccw", max_work: Optional[float] = None) -> "Shape":
        """The exact union (both filled by this shape's fill rule)."""
        return self._op("union", [other], orientation, max_work)

    def intersection(self, other: "Shape", *, orientation: str = "ccw", max_work: Optional[float] = None) -> "Shape":
        """The exact intersection."""
        return self._op("intersection", [other], orientation, max_work)

    def difference(self, other: "Shape", *, orientation: str = "ccw", max_work: Optional[float] = None) -> "Shape":
        """The exact difference ``self − other``."""
        return self._op("difference", [other], orientation, max_work)

    def xor(self, other: "Shape", *, orientation: str = "ccw", max_work: Optional[float] = None) -> "Shape":
        """The exact symmetric difference."""
        return self._op("xor", [other], orientation, max_work)

    @property
    def area(self) -> Optional[Fraction]:
        """The exact area of the filled region (overlaps counted once), or ``None`` when the
        boundary has rational (weighted) pieces or pieces with irrational ends."""
        return _core.boolean("simplify", [self._contours], self.fill, "ccw", None)[1]

    @property
    def bounds(self) -> Tuple[Any, Any, Any, Any]:
        """The exact tight bounds ``(xMin, yMin, xMax, yMax)`` of the contours (``Fraction`` or
        ``Algebraic`` each)."""
        xs: List[Any] = []
        ys: List[Any] = []
        for c in self._contours:
            for pts, ws in c:
                b = (_core.Bezier(pts) if ws is None else _core.RationalBezier(pts, ws)).bounds()
                xs += [b[0], b[2]]
                ys += [b[1], b[3]]
        if not xs:
            return (Fraction(0), Fraction(0), Fraction(0), Fraction(0))
        return (min(xs), min(ys), max(xs), max(ys))

    def winding(self, point: Tuple[Any, Any], *, max_work: Optional[float] = None) -> Optional[int]:
        """The winding number of the contours around a rational point (counter-clockwise
        positive), or ``None`` when the point is on a contour."""
        return _core.winding(self._contours, point, max_work)

    def contains(self, point: Tuple[Any, Any], *, max_work: Optional[float] = None) -> Optional[bool]:
        """Whether the point is inside the fill (``None`` on the boundary)."""
        w = self.winding(point, max_work=max_work)
        if w is None:
            return None
        return w % 2 == 1 if self.fill == "evenodd" else w != 0

    def would_remove_overlap(self, *, max_work: Optional[float] = None) -> bool:
        """Whether ``simplify`` changes the outline other than by contour directions."""
        return _core.changes(self._contours, self.fill, "ccw", max_work, ignore_direction=True)
