"""skia-pathops' ``pathops.operations``: boolean operations on fontTools contours (objects
with a ``draw(pen)`` method), drawing the exact result to a pen."""

from __future__ import annotations

from functools import partial
from typing import Any, Iterable

from ._base import PathOp
from ._ops import op
from ._path import Path

__all__ = ["difference", "intersection", "reverse_difference", "union", "xor"]


def _draw(contours: Iterable[Any]) -> Path:
    path = Path()
    pen = path.getPen()
    for contour in contours:
        contour.draw(pen)
    return path


def union(contours: Any, outpen: Any, fix_winding: bool = True, keep_starting_points: bool = True, clockwise: bool = False) -> None:
    """Draws the exact union (overlaps removed) of ``contours`` to ``outpen``."""
    if not contours:
        return
    path = _draw(contours)
    path.simplify(fix_winding=fix_winding, keep_starting_points=keep_starting_points, clockwise=clockwise)
    path.draw(outpen)


def _do(
    operator: PathOp,
    subject_contours: Any,
    clip_contours: Any,
    outpen: Any,
    fix_winding: bool = True,
    keep_starting_points: bool = True,
    clockwise: bool = False,
) -> None:
    one = _draw(subject_contours)
    two = _draw(clip_contours)
    result = op(one, two, operator, fix_winding=fix_winding, keep_starting_points=keep_starting_points, clockwise=clockwise)
    result.draw(outpen)


difference = partial(_do, PathOp.DIFFERENCE)
difference.__doc__ = "Draws subject − clip (exact) to ``outpen``."
intersection = partial(_do, PathOp.INTERSECTION)
intersection.__doc__ = "Draws subject ∩ clip (exact) to ``outpen``."
xor = partial(_do, PathOp.XOR)
xor.__doc__ = "Draws subject △ clip (exact) to ``outpen``."
reverse_difference = partial(_do, PathOp.REVERSE_DIFFERENCE)
reverse_difference.__doc__ = "Draws clip − subject (exact) to ``outpen``."
