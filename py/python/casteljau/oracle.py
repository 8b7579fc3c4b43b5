"""Float routines checked against the exact answers, for other projects' test suites.

>>> from fontTools.misc import bezierTools
>>> from casteljau import oracle
>>> a = [(0, 0), (3, 1), (-1, 2), (1, 3)]
>>> b = [(0, 3), (1, 0), (1, 0), (2, 3)]
>>> found = bezierTools.curveCurveIntersections(a, b)
>>> for d in oracle.check_intersections(a, b, found, tol=1e-6):
...     print(d)
spurious: the library's (0.2734375, 0.6015625) is no intersection
spurious: the library's (0.2890625, 0.6015625) is no intersection
missed: s = root 1 of 4563*t^6 - 14742*t^5 + 18225*t^4 - 10912*t^3 + 3306*t^2 - 498*t + 31 in [1/4, 5/16], t = root 1 of 351*t^6 - 1053*t^5 + 1215*t^4 - 677*t^3 + 183*t^2 - 21*t + 1 in [9/16, 5/8] (≈ (0.28306652693427004, 0.6049865498278549))
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, List, Sequence, Tuple

from . import _core

__all__ = ["Disagreement", "check_intersections", "check_bounds", "assert_agrees"]


@dataclass(frozen=True)
class Disagreement:
    """One disagreement between a float answer and the exact one: ``kind`` (``missed``,
    ``spurious``, ``duplicate``, ``mismatch``), ``what`` it is about, the ``exact`` answer
    (exact text), the library's value ``found`` and ``exact_float`` (the exact answer
    correctly rounded)."""

    kind: str
    what: str
    exact: str
    found: Any
    exact_float: Any

    def __str__(self) -> str:
        if self.kind == "spurious":
            return "spurious: the library's %r is no intersection" % (self.found,)
        if self.kind == "missed":
            return "missed: %s (≈ %r)" % (self.exact, self.exact_float)
        return "%s: %s = %s (≈ %r), the library's %r" % (self.kind, self.what, self.exact, self.exact_float, self.found)


def _params(found: Sequence[Any]) -> List[Tuple[float, float]]:
    out = []
    for f in found:
        if hasattr(f, "t1") and hasattr(f, "t2"):  # fontTools' Intersection
            out.append((float(f.t1), float(f.t2)))
        else:
            s, t = f
            out.append((float(s), float(t)))
    return out


def check_intersections(a: Sequence[Any], b: Sequence[Any], found: Sequence[Any], tol: float = 1e-9, domain: str = "unit") -> List[Disagreement]:
    """A float library's intersections of two curves (binary64 control points) against the
    exact ones: ``found`` pairs ``(s, t)`` or fontTools ``Intersection``s (``t1``, ``t2``). A pair
    matches an exact intersection when both parameters are within ``tol`` (decided exactly).
    Returns the disagreements: exact intersections missed, spurious pairs, duplicates."""
    pa = [(float(p[0]), float(p[1])) for p in a]
    pb = [(float(p[0]), float(p[1])) for p in b]
    rows = _core.check_intersections(pa, pb, _params(found), float(tol), domain)
    out = []
    for r in rows:
        exact = "s = %s, t = %s" % (r["s"], r["t"]) if r["s"] != "" else ""
        out.append(
            Disagreement(
                kind=r["kind"],
                what="(s, t)",
                exact=exact,
                found=tuple(r["float"]) if r["float"] is not None else None,
                exact_float=tuple(r["exact_float"]) if r["exact_float"] is not None else None,
            )
        )
    return out


def check_bounds(curve: Sequence[Any], found: Sequence[Any], tol: Any = 0) -> List[Disagreement]:
    """A float library's bounding box ``(xMin, yMin, xMax, yMax)`` of a curve against the exact
    one: each value must lie within ``tol`` of the exact bound (decided exactly; ``tol=0``: the
    value must be exact, which a float can only be when the bound is rational — use a ``tol``
    of a few ulps for a correctly rounding library)."""
    from .numbers import exact as _exact

    exact_box = _core.Bezier(list(curve)).bounds()
    names = ("xMin", "yMin", "xMax", "yMax")
    tol = _exact(tol)
    out = []
    for name, e, f in zip(names, exact_box, found):
        v = _exact(f)
        if not (v - tol <= e <= v + tol):
            out.append(Disagreement("mismatch", name, str(e), f, float(e)))
    return out


def assert_agrees(disagreements: Sequence[Disagreement]) -> None:
    """Raises ``AssertionError`` listing every disagreement (pytest prints it)."""
    if disagreements:
        raise AssertionError("the float answer disagrees with the exact one:\n" + "\n".join("  " + str(d) for d in disagreements))
