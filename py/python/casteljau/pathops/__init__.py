"""skia-pathops' interface with exact answers: ``from casteljau import pathops`` in place of
``import pathops``.

Paths keep their coordinates exactly (ints, floats as their binary64 values, ``Fraction``s);
``op``, ``simplify``, ``OpBuilder`` and ``pathops.operations`` compute the exact boundary of the
result region with casteljau's arrangement (``casteljau.shape``), every output segment an exact
piece of an input segment (``Fraction`` coordinates where rational, correctly rounded floats
where a crossing point is irrational). Stroking, ``arcTo`` and ``convertConicsToQuads`` (float
approximations in Skia) raise ``NotImplementedError``.

Beyond skia-pathops: ``would_remove_overlap(path)`` and ``check_against(inputs, op,
float_result, tol)``, the command line's ``--against`` oracle with its witness.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, List, Optional, Sequence, Union

from .. import _core
from ._base import (
    ArcSize,
    Direction,
    ExactOperationError,
    FillType,
    LineCap,
    LineJoin,
    NumberOfPointsError,
    OpenPathError,
    PathOp,
    PathOpsError,
    PathVerb,
    UnsupportedVerbError,
    bits2float,
    decompose_quadratic_segment,
    fill_rule,
    float2bits,
)
from ._ops import OpBuilder, op
from ._path import Path, PathPen, exchange, simplify
from .operations import difference, intersection, reverse_difference, union, xor

__all__ = [
    "PathPen",
    "Path",
    "PathVerb",
    "PathOp",
    "FillType",
    "LineCap",
    "LineJoin",
    "ArcSize",
    "Direction",
    "op",
    "simplify",
    "OpBuilder",
    "PathOpsError",
    "UnsupportedVerbError",
    "OpenPathError",
    "NumberOfPointsError",
    "ExactOperationError",
    "bits2float",
    "float2bits",
    "decompose_quadratic_segment",
    "union",
    "difference",
    "intersection",
    "xor",
    "reverse_difference",
    "would_remove_overlap",
    "check_against",
    "Agreement",
    "Witness",
]

__version__ = "0.1.0"


def would_remove_overlap(path: Path, *, max_work: Optional[float] = None) -> bool:
    """Whether removing overlaps (``simplify``) would change the outline other than by the
    directions of its contours: an overlap, a self-intersection, a shared piece of boundary, a
    contour that bounds nothing under the fill rule. Decided exactly (skia-pathops #55).

    >>> from casteljau.pathops import Path, would_remove_overlap
    >>> p = Path(); p.moveTo(0, 0); p.lineTo(2, 0); p.lineTo(2, 2); p.lineTo(0, 2); p.close()
    >>> would_remove_overlap(p)
    False
    >>> p.moveTo(1, 1); p.lineTo(3, 1); p.lineTo(3, 3); p.lineTo(1, 3); p.close()
    >>> would_remove_overlap(p)
    True
    """
    try:
        return _core.changes(exchange(path), fill_rule(path.fillType), "ccw", max_work, ignore_direction=True)
    except _core.CasteljauError as e:
        raise ExactOperationError(str(e)) from e


@dataclass(frozen=True)
class Witness:
    """A rational point inside one region and outside the other, farther than ``tol`` from the
    exact boundary."""

    point: tuple
    point_float: tuple
    inside_exact: bool
    inside_found: bool


@dataclass(frozen=True)
class Agreement:
    """The verdict on a float result (truthy when it agrees): contour counts, sorted nesting
    depths, a witness point where the regions differ, an upper bound on the distance between
    the boundaries (binary64), and the problems in words."""

    agree: bool
    contours: int
    contours_found: int
    depths: List[int]
    depths_found: List[int]
    witness: Optional[Witness]
    distance_bound: float
    problems: List[str] = field(default_factory=list)

    def __bool__(self) -> bool:
        return self.agree


_OP_NAMES = {
    PathOp.DIFFERENCE: "difference",
    PathOp.INTERSECTION: "intersection",
    PathOp.UNION: "union",
    PathOp.XOR: "xor",
}


def check_against(
    inputs: Sequence[Path],
    op: Union[PathOp, str, None],
    float_result: Path,
    tol: Any,
    *,
    max_work: Optional[float] = None,
) -> Agreement:
    """Decides a float library's result of ``op`` on ``inputs`` against the exact one (the
    command line's ``boolean --against``): ``op`` a ``PathOp`` or ``"simplify"``/``None`` for one
    input; ``tol`` the distance below which boundaries count as equal. Inputs are filled by the
    first input's fill type.

    >>> from casteljau import pathops
    >>> a = pathops.Path(); a.moveTo(0, 0); a.lineTo(2, 0); a.lineTo(2, 2); a.lineTo(0, 2); a.close()
    >>> b = a.transform(1, 0, 0, 1, 1, 1)
    >>> v = pathops.check_against([a, b], pathops.PathOp.UNION, pathops.op(a, b, pathops.PathOp.UNION), 1e-9)
    >>> bool(v), v.problems, v.witness
    (True, [], None)
    """
    if op is None or op == "simplify":
        name = "simplify"
        paths = list(inputs)
    else:
        o = PathOp[op.upper()] if isinstance(op, str) else PathOp(op)
        paths = list(inputs)
        if o == PathOp.REVERSE_DIFFERENCE:
            o, paths = PathOp.DIFFERENCE, paths[::-1]
        name = _OP_NAMES[o]
    fill = fill_rule(paths[0].fillType) if paths else "nonzero"
    try:
        d = _core.check_against(name, [exchange(p) for p in paths], exchange(float_result), tol, fill, max_work)
    except _core.CasteljauError as e:
        raise ExactOperationError(str(e)) from e
    w = d.get("witness")
    witness = None
    if w:
        witness = Witness(tuple(w["point"]), tuple(w["point_float"]), w["inside_exact"], w["inside_found"])
    return Agreement(
        agree=d["agree"],
        contours=d["contours"],
        contours_found=d["contours_found"],
        depths=d["depths"],
        depths_found=d["depths_found"],
        witness=witness,
        distance_bound=d["distance_bound"],
        problems=d["problems"],
    )
