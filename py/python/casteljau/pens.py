"""fontTools pens that record outlines exactly."""

from __future__ import annotations

from typing import Any, Optional

from .pathops._path import Path, PathPen, exchange
from .shape import Shape

__all__ = ["ExactPen"]


class ExactPen(PathPen):
    """A segment pen that records a glyph exactly: coordinates as given (ints, floats as their
    binary64 values, ``Fraction``s), TrueType implied on-curve points at their exact midpoints
    (``Fraction(1, 2)``, not fontTools' float ``0.5 * (a + b)``), components decomposed through
    ``glyphSet`` with exact transforms. ``shape()`` is the recorded ``casteljau.Shape``.

    >>> from casteljau.pens import ExactPen
    >>> pen = ExactPen()
    >>> pen.qCurveTo((0, 0), (1, 1), (3, 0), None)
    >>> pen.path.firstPoints
    [(Fraction(3, 2), 0)]
    """

    def __init__(self, glyphSet: Any = None, path: Optional[Path] = None) -> None:
        super().__init__(path if path is not None else Path(), glyphSet=glyphSet)

    def shape(self, fill: str = "nonzero") -> Any:
        return Shape(exchange(self.path), fill)
