"""fontTools' float routines checked against casteljau, as another project's test suite would
(``casteljau.oracle``): the exact disagreement is printed when a check fails."""

from fractions import Fraction

import pytest
from fontTools.misc import bezierTools

from casteljau import Bezier, oracle


def test_curve_curve_intersections_against_exact():
    a = [(0, 0), (3, 1), (-1, 2), (1, 3)]
    b = [(0, 3), (1, 0), (1, 0), (2, 3)]
    found = bezierTools.curveCurveIntersections(a, b)
    disagreements = oracle.check_intersections(a, b, found, tol=1e-6)
    print("\n".join(map(str, disagreements)))
    # fontTools reports two nearby points for the one exact crossing, neither within 1e-6
    assert [d.kind for d in disagreements] == ["spurious", "spurious", "missed"]
    with pytest.raises(AssertionError, match="missed: s = root 1 of"):
        oracle.assert_agrees(disagreements)
    # within fontTools' own tolerance (its bisection stops at 1e-3 in the parameters) the
    # first pair matches and the second is a duplicate of the same crossing
    loose = oracle.check_intersections(a, b, found, tol=1e-2)
    assert [d.kind for d in loose] == ["duplicate"]


def test_line_curve_intersections_agree():
    line = [(0, 1), (2, 1)]
    curve = [(0, 0), (1, 4), (1, -2), (2, 2)]
    found = bezierTools.curveLineIntersections(curve, line)
    pairs = [(i.t1, i.t2) for i in found]
    # fontTools rounds the curve parameters to 6 decimals: at 1e-9 both crossings are missed
    # (the exact ones are 1/2 ∓ √15/10), within 1e-6 they agree
    strict = oracle.check_intersections(curve, line, pairs, tol=1e-9)
    print("\n".join(map(str, strict)))
    assert sorted(d.kind for d in strict) == ["missed", "missed", "spurious", "spurious"]
    assert "1/2 - 1/10*sqrt(15)" in str(strict[2]) + str(strict[3])
    oracle.assert_agrees(oracle.check_intersections(curve, line, pairs, tol=1e-6))


def test_calc_cubic_bounds_against_exact():
    a = [(0, 0), (3, 1), (-1, 2), (1, 3)]
    found = bezierTools.calcCubicBounds(*a)
    exact = Bezier(a).bounds()
    print("exact:", [str(v) for v in exact], "fontTools:", found)
    # the x maximum is irrational: no float equals it; fontTools' value is the correctly
    # rounded one, so it agrees within one ulp
    assert [d.what for d in oracle.check_bounds(a, found)] == ["xMax"]
    oracle.assert_agrees(oracle.check_bounds(a, found, tol=2.0**-52))


def test_calc_quadratic_bounds_exact():
    q = [(0, 0), (1, 2), (2, 0)]
    assert bezierTools.calcQuadraticBounds(*q) == tuple(Bezier(q).bounds()) == (0, 0, 2, 1)
