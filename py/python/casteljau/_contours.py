"""The exchange form of contours shared by ``casteljau.Shape`` and ``casteljau.pathops``: a
contour is a list of segments ``(points, weights)`` (``weights`` ``None`` for a polynomial
segment), as the native module takes and gives them."""

from __future__ import annotations

from typing import Any, Optional, Sequence, Tuple

from . import _core

__all__ = ["resolve", "segment_exchange"]


def segment_exchange(seg: Any) -> Tuple[list, Optional[list]]:
    """A ``Bezier``, a ``RationalBezier`` or a ``(points, weights)`` pair as ``(points, weights)``."""
    if isinstance(seg, _core.RationalBezier):
        return (list(seg.points), list(seg.weights))
    if isinstance(seg, _core.Bezier):
        return (list(seg.points), None)
    pts, ws = seg
    return (list(pts), None if ws is None else list(ws))


def resolve(contours: list, inputs: Sequence[list]) -> list:
    """The native ``boolean``'s result contours in exchange form: a whole input segment
    ``(input, contour, segment, reversed)`` is taken from ``inputs`` (its numbers as given), a
    part ``(points, weights)`` is used as it is."""
    out = []
    for c in contours:
        segs = []
        for item in c:
            if len(item) == 4:
                i, k, s, rev = item
                pts, ws = inputs[i][k][s]
                if rev:
                    pts = pts[::-1]
                    ws = ws[::-1] if ws is not None else None
                segs.append((pts, ws))
            else:
                segs.append(item)
        out.append(segs)
    return out
