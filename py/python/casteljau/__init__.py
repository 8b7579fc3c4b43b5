"""casteljau: exact Bézier-curve geometry in process.

Rationals are ``fractions.Fraction``; irrational answers are ``Algebraic`` (exact comparisons,
correctly rounded ``float()``). Every exact operation releases the GIL and takes a work budget
``max_work=`` (work units, about a nanosecond each; default ``1e10``): an input whose estimated
work exceeds it is refused with ``CasteljauError`` naming ``max_work``. Errors are
``CasteljauError`` (a ``ValueError``) with the command line's message; no Rust panic reaches
Python.

>>> import casteljau
>>> from fractions import Fraction
>>> c = casteljau.Bezier([(0, 0), (3, 1), (-1, 2), (1, 3)])
>>> xmax = c.bounds()[2]
>>> xmax, float(xmax)
(Algebraic('133/169 + 20/169*sqrt(10)'), 1.161216291144187)
"""

from __future__ import annotations

from ._core import (
    DEFAULT_MAX_WORK,
    Algebraic,
    Bezier,
    CasteljauError,
    Intersection,
    Intersections,
    Overlap,
    RationalBezier,
)
from .numbers import exact, to_float
from .shape import Shape

__version__ = "0.1.0"

__all__ = [
    "DEFAULT_MAX_WORK",
    "Algebraic",
    "Bezier",
    "CasteljauError",
    "Intersection",
    "Intersections",
    "Overlap",
    "RationalBezier",
    "Shape",
    "exact",
    "to_float",
    "lint",
    "Finding",
    "prove",
    "Verdict",
]


def __getattr__(name: str):  # lazy: lint and prove import more of the package
    if name in ("lint", "Finding"):
        from . import _lint

        return getattr(_lint, name)
    if name in ("prove", "Verdict"):
        from . import _prove

        return getattr(_prove, name)
    raise AttributeError("module 'casteljau' has no attribute %r" % (name,))
