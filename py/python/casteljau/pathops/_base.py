"""The ground floor of ``casteljau.pathops``: skia-pathops' enums and error classes, the float32
bit helpers, and exact numbers and points (reading a coordinate exactly, midpoints, exact
comparisons). Every other module of the package builds on this one and this one on none of them.
"""

from __future__ import annotations

import enum
import struct
from fractions import Fraction
from typing import Any, List, Sequence, Tuple

from .. import _core
from ..numbers import exact

__all__ = [
    "PathVerb",
    "PathOp",
    "FillType",
    "LineCap",
    "LineJoin",
    "ArcSize",
    "Direction",
    "PathOpsError",
    "UnsupportedVerbError",
    "OpenPathError",
    "NumberOfPointsError",
    "ExactOperationError",
    "bits2float",
    "float2bits",
    "decompose_quadratic_segment",
    "fill_rule",
]

Point = Tuple[Any, Any]


class PathOpsError(Exception):
    """An operation on paths failed (skia-pathops' base class)."""


class UnsupportedVerbError(PathOpsError):
    """A verb the operation does not handle."""


class OpenPathError(PathOpsError):
    """An open contour where closed ones are required (``getPen(allow_open_paths=False)``)."""


class NumberOfPointsError(PathOpsError):
    """A pen segment with the wrong number of points."""


class PathVerb(enum.IntEnum):
    """Skia's path verbs."""

    MOVE = 0
    LINE = 1
    QUAD = 2
    CONIC = 3
    CUBIC = 4
    CLOSE = 5


class PathOp(enum.IntEnum):
    """Skia's boolean operations."""

    DIFFERENCE = 0
    INTERSECTION = 1
    UNION = 2
    XOR = 3
    REVERSE_DIFFERENCE = 4


class FillType(enum.IntEnum):
    """Skia's fill types."""

    WINDING = 0
    EVEN_ODD = 1
    INVERSE_WINDING = 2
    INVERSE_EVEN_ODD = 3


class LineCap(enum.IntEnum):
    """Stroke caps (stroking is not supported: ``Path.stroke`` raises)."""

    BUTT_CAP = 0
    ROUND_CAP = 1
    SQUARE_CAP = 2


class LineJoin(enum.IntEnum):
    """Stroke joins (stroking is not supported)."""

    MITER_JOIN = 0
    ROUND_JOIN = 1
    BEVEL_JOIN = 2


class ArcSize(enum.IntEnum):
    """SVG arc size flag (``arcTo`` is not supported: its conics have irrational weights)."""

    SMALL = 0
    LARGE = 1


class Direction(enum.IntEnum):
    """SVG arc sweep direction."""

    CW = 0
    CCW = 1


_POINTS_IN_VERB = {
    PathVerb.MOVE: 1,
    PathVerb.LINE: 1,
    PathVerb.QUAD: 2,
    PathVerb.CONIC: 2,
    PathVerb.CUBIC: 3,
    PathVerb.CLOSE: 0,
}

_VERB_METHODS = {
    PathVerb.MOVE: "moveTo",
    PathVerb.LINE: "lineTo",
    PathVerb.QUAD: "quadTo",
    PathVerb.CONIC: "conicTo",
    PathVerb.CUBIC: "cubicTo",
    PathVerb.CLOSE: "close",
}


def float2bits(x: float) -> int:
    """The bits of ``x`` rounded to float32, unsigned (as skia-pathops).

    >>> hex(float2bits(17.5))
    '0x418c0000'
    >>> hex(float2bits(-10.0))
    '0xc1200000'
    """
    return struct.unpack("<I", struct.pack("<f", x))[0]


def bits2float(float_as_bits: int) -> float:
    """The float32 with these bits (negative ints as their two's complement).

    >>> bits2float(0x418c0000)
    17.5
    >>> bits2float(-0x3ee00000)
    -10.0
    """
    return struct.unpack("<f", struct.pack("<I", float_as_bits & 0xFFFFFFFF))[0]


def _num(v: Any) -> Any:
    """A coordinate kept exactly: int, float and Fraction as they are, others read exactly."""
    t = type(v)
    if t is int or t is Fraction:
        return v
    if t is float:
        if v != v or v in (float("inf"), float("-inf")):
            raise _core.CasteljauError("not a finite number: %r" % v)
        return v
    if isinstance(v, bool):
        return int(v)
    return exact(v)


def _pt(p: Sequence[Any]) -> Point:
    return (_num(p[0]), _num(p[1]))


def _half(a: Any, b: Any) -> Any:
    """The exact midpoint of two coordinates (an int when it is one)."""
    if type(a) is int and type(b) is int:
        s = a + b
        return s >> 1 if not s & 1 else Fraction(s, 2)
    m = (Fraction(a) + Fraction(b)) / 2
    return m.numerator if m.denominator == 1 else m


_HALVES: dict = {}


def _halves(s: int) -> Fraction:
    """``Fraction(s, 2)`` for an odd ``s``, made once per value (TrueType's implied points)."""
    f = _HALVES.get(s)
    if f is None:
        f = _HALVES[s] = Fraction(s, 2)
        if len(_HALVES) > 1 << 16:
            _HALVES.clear()
            _HALVES[s] = f
    return f


def _mid(p: Point, q: Point) -> Point:
    return (_half(p[0], q[0]), _half(p[1], q[1]))


def decompose_quadratic_segment(points: Sequence[Point]) -> List[Tuple[Point, Point]]:
    """A TrueType quadratic spline as quadratic segments ``(off, on)``, the implied on-curve
    points the exact midpoints of consecutive off-curve points.

    >>> decompose_quadratic_segment(((0, 0), (1, 1), (2, 1)))
    [((0, 0), (Fraction(1, 2), Fraction(1, 2))), ((1, 1), (2, 1))]
    """
    points = tuple(points)
    n = len(points) - 1
    assert n > 0
    quads = []
    for i in range(n - 1):
        quads.append((points[i], _mid(points[i], points[i + 1])))
    quads.append((points[-2], points[-1]))
    return quads


def _same(p: Point, q: Point) -> bool:
    return p[0] == q[0] and p[1] == q[1]


def _q(v: Any) -> Any:
    """An int or Fraction (exact arithmetic), a float as its exact Fraction."""
    return Fraction(v) if type(v) is float else v


def _is_middle(p1: Point, p2: Point, p3: Point) -> bool:
    """``p2`` is exactly the midpoint of ``p1`` and ``p3``."""
    return 2 * _q(p2[0]) == _q(p1[0]) + _q(p3[0]) and 2 * _q(p2[1]) == _q(p1[1]) + _q(p3[1])


def _collinear(p1: Point, p2: Point, p3: Point) -> bool:
    """The three points lie on one line, exactly (ints and Fractions as they are, floats as their
    exact Fractions)."""
    x1, y1, x2, y2, x3, y3 = _q(p1[0]), _q(p1[1]), _q(p2[0]), _q(p2[1]), _q(p3[0]), _q(p3[1])
    return x1 * (y2 - y3) + x2 * (y3 - y1) + x3 * (y1 - y2) == 0


class ExactOperationError(PathOpsError, _core.CasteljauError):
    """An exact operation refused its input or its work budget: both a ``PathOpsError`` (as
    skia-pathops raises) and a ``casteljau.CasteljauError`` (a ``ValueError``) with casteljau's
    message (``max_work`` named when the budget refused)."""


def fill_rule(fill: FillType) -> str:
    """casteljau's fill rule (``"nonzero"`` or ``"evenodd"``) of a Skia fill type; the inverse
    fill types raise ``PathOpsError``."""
    if fill in (FillType.INVERSE_WINDING, FillType.INVERSE_EVEN_ODD):
        raise PathOpsError("inverse fill types are not supported by the exact operations")
    return "evenodd" if fill == FillType.EVEN_ODD else "nonzero"
