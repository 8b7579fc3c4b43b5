"""Exact numbers: how casteljau reads Python numbers and writes exact answers.

Inputs everywhere accept ``int``, ``fractions.Fraction`` (any ``numbers.Rational``), ``float``
(taken exactly as its binary64 value, as the command line's ``--numbers binary64``: ``0.1`` is
``3602879701896397/36028797018963968``), ``decimal.Decimal`` and ``str`` in the command line's
syntax (``"1/3"``, ``"-0.25"``, ``"2e3"``, ``"0x1.8p-3"``). Rational answers are ``Fraction``s;
irrational ones are ``Algebraic``: exact comparisons, correctly rounded ``float()``.
"""

from __future__ import annotations

from fractions import Fraction
from typing import Any, Union

from . import _core

Algebraic = _core.Algebraic

#: An exact real as casteljau returns it.
Real = Union[Fraction, "_core.Algebraic"]

__all__ = ["Algebraic", "Real", "exact", "to_float"]


def exact(x: Any) -> Fraction:
    """``x`` read exactly as a ``Fraction``.

    >>> exact(0.1)
    Fraction(3602879701896397, 36028797018963968)
    >>> exact("0x1.8p-3"), exact("1/3"), exact(2)
    (Fraction(3, 16), Fraction(1, 3), Fraction(2, 1))
    """
    return _core.rational(x)


def to_float(x: Any) -> float:
    """An exact number (``Fraction`` or ``Algebraic``) correctly rounded to ``float``."""
    return _core.float_of(x)
