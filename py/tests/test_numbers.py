"""Exact numbers: inputs read exactly, Fraction out, Algebraic for irrationals."""

import decimal
import math
from fractions import Fraction

import pytest

import casteljau
from casteljau import Algebraic, CasteljauError, exact


def test_inputs_are_read_exactly():
    assert exact(3) == Fraction(3)
    assert exact(0.1) == Fraction(3602879701896397, 36028797018963968)
    assert exact("1/3") == Fraction(1, 3)
    assert exact("0x1.8p-3") == Fraction(3, 16)
    assert exact("-0.25") == Fraction(-1, 4)
    assert exact(Fraction(2, 6)) == Fraction(1, 3)
    assert exact(decimal.Decimal("0.1")) == Fraction(1, 10)
    assert exact(10**40) == 10**40


def test_bad_inputs_raise_with_the_token():
    with pytest.raises(CasteljauError, match=r'bad number "1/0"'):
        exact("1/0")
    with pytest.raises(CasteljauError, match="not a finite number"):
        exact(math.inf)
    with pytest.raises(TypeError, match="expected a number"):
        exact(object())
    assert issubclass(CasteljauError, ValueError)


def test_sqrt2_compares_exactly():
    minus, plus = Algebraic.roots([-2, 0, 1])
    assert str(plus) == "sqrt(2)" and str(minus) == "-sqrt(2)"
    assert float(plus) == math.sqrt(2)
    # exact comparisons with floats (their binary64 value), Fractions, ints and Algebraics
    assert plus > 1.4142135623730950 and plus < 1.4142135623730952
    assert plus != math.sqrt(2) and plus > Fraction(7, 5) and plus < 2
    assert minus < plus and minus == -plus and abs(minus) == plus
    assert plus < math.inf and plus > -math.inf and not (plus == math.nan)
    assert sorted([Fraction(3, 2), plus, 1, minus]) == [minus, 1, plus, Fraction(3, 2)]
    assert plus.sign == 1 and minus.sign == -1


def test_polynomial_and_intervals():
    (cbrt2,) = Algebraic.roots([-2, 0, 0, 1])
    assert cbrt2.polynomial == [-2, 0, 0, 1]
    assert all(isinstance(c, Fraction) for c in cbrt2.polynomial)
    lo, hi = cbrt2.isolating_interval
    assert lo < cbrt2 < hi and lo**3 < 2 < hi**3
    lo, hi = cbrt2.interval(60)
    assert hi - lo < Fraction(1, 2**60) and lo**3 < 2 < hi**3
    assert float(cbrt2) == 2 ** (1 / 3)
    assert "%.3f" % float(cbrt2) == format(cbrt2, ".3f") == "1.260"


def test_rational_roots_are_fractions():
    roots = Algebraic.roots([3, -6, -1, 2])  # (2t - 1)(t² - 3)
    assert roots[1] == Fraction(1, 2) and isinstance(roots[1], Fraction)
    assert Algebraic.roots([-2, 0, 1], lo=0, hi=2) == [Algebraic.roots([-2, 0, 1])[1]]


def test_hash_is_consistent_with_equality():
    a = Algebraic.roots([-2, 0, 1])[1]
    b = Algebraic.roots([-4, 0, 0, 0, 1])[1]  # √2 as a root of t⁴ − 4
    assert a == b and hash(a) == hash(b)
    assert len({a, b}) == 1


def test_zero_polynomial_is_refused():
    with pytest.raises(CasteljauError, match="zero polynomial"):
        Algebraic.roots([0, 0])


def test_version_and_budget_default():
    assert casteljau.__version__ == "0.1.0"
    assert casteljau.DEFAULT_MAX_WORK == 1e10
