"""skia-pathops' boolean operations on paths, exact: ``op`` and ``OpBuilder`` (``simplify`` is
``Path``'s own, in ``_path``)."""

from __future__ import annotations

from typing import Any, List, Optional, Tuple

from . import _exact
from ._base import FillType, PathOp, fill_rule
from ._path import Path, exchange, finish

__all__ = ["op", "OpBuilder"]

_OPS = {
    PathOp.DIFFERENCE: "difference",
    PathOp.INTERSECTION: "intersection",
    PathOp.UNION: "union",
    PathOp.XOR: "xor",
    PathOp.REVERSE_DIFFERENCE: "difference",
}


def _input(path: Path) -> Tuple[_exact.Contours, str]:
    return exchange(path), fill_rule(path.fillType)


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
    input contour's first point.

    >>> from casteljau.pathops import Path, PathOp, op
    >>> a = Path(); a.moveTo(0, 0); a.lineTo(2, 0); a.lineTo(2, 2); a.lineTo(0, 2); a.close()
    >>> op(a, a.transform(1, 0, 0, 1, 1, 1), PathOp.INTERSECTION).area
    Fraction(1, 1)
    """
    operator = PathOp(operator)
    first = (one.firstPoints + two.firstPoints) if keep_starting_points else []
    paths = [two, one] if operator == PathOp.REVERSE_DIFFERENCE else [one, two]
    inputs = [_input(p) for p in paths]
    contours, areas = _exact.boolean(_OPS[operator], inputs, "cw" if clockwise else "ccw", max_work)
    return finish(contours, areas, fix_winding, keep_starting_points, first)


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
        acc: _exact.Contours = []
        areas: List[Any] = []
        for path, operator in self._ops:
            # the result so far: its contours as they are, filled by the non-zero rule
            current = (acc, fill_rule(FillType.WINDING))
            inputs = [_input(path), current] if operator == PathOp.REVERSE_DIFFERENCE else [current, _input(path)]
            acc, areas = _exact.boolean(_OPS[operator], inputs, orientation, self.max_work)
        return finish(acc, areas, self.fix_winding, self.keep_starting_points, list(self.first_points))
