"""Shapes: exact boolean operations, winding numbers, the --against oracle."""

from fractions import Fraction

import pytest

from casteljau import CasteljauError, RationalBezier, Bezier, Shape, pathops


def square(x, y, s=2):
    return Shape.from_svg_path("M%s %s h%s v%s h-%s Z" % (x, y, s, s, s))


def test_boolean_operations_are_exact():
    a, b = square(0, 0), square(1, 1)
    assert a.union(b).area == 7
    assert a.intersection(b).area == 1
    assert a.difference(b).area == 3
    assert a.xor(b).area == 6
    assert a.union(b).to_svg_path() == "M0 0L2 0L2 1L3 1L3 3L1 3L1 2L0 2Z"
    assert a.union(b, orientation="cw").to_svg_path() != a.union(b).to_svg_path()


def test_irrational_crossings_are_rounded_correctly():
    disc = Shape.from_contours(
        [
            [
                RationalBezier([(1, 0), (1, 1), (0, 1)], [1, 1, 2]),
                RationalBezier([(0, 1), (-1, 1), (-1, 0)], [2, 1, 1]),
                Bezier([(-1, 0), (1, 0)]),
            ]
        ]
    )
    half = disc.intersection(square(0, 0, 2))
    # the quarter disc x, y ≥ 0: bounded by the arc and the two radii
    assert half.winding((Fraction(1, 2), Fraction(1, 2))) == 1
    assert half.winding((1, 1)) == 0


def test_svg_errors_name_the_token():
    with pytest.raises(CasteljauError, match=r'bad number "x"'):
        Shape.from_svg_path("M0 0 L1 x")


def test_winding_and_contains():
    eight = Shape.from_svg_path("M0 0 L2 2 L2 0 L0 2 Z")
    assert eight.winding((Fraction(1, 2), 1)) in (1, -1)
    assert eight.winding((1, 1)) is None  # the crossing point is on the boundary
    assert eight.contains((5, 5)) is False
    assert eight.simplify().area == 2
    assert eight.would_remove_overlap()
    assert not square(0, 0).would_remove_overlap()


def test_bounds_are_exact():
    s = Shape.from_svg_path("M0 0 C3 1 -1 2 1 3 Z")
    xmin, ymin, xmax, ymax = s.bounds
    assert (xmin, ymin, ymax) == (0, 0, 3) and str(xmax) == "133/169 + 20/169*sqrt(10)"


def test_check_against_finds_a_witness():
    a = pathops.Path()
    a.moveTo(0, 0); a.lineTo(2, 0); a.lineTo(2, 2); a.lineTo(0, 2); a.close()
    b = a.transform(1, 0, 0, 1, 1, 1)
    exact = pathops.op(a, b, pathops.PathOp.UNION)
    assert pathops.check_against([a, b], pathops.PathOp.UNION, exact, 1e-9)
    # a float answer that forgot the overlap: the intersection instead of the union
    wrong = pathops.op(a, b, pathops.PathOp.INTERSECTION)
    v = pathops.check_against([a, b], "union", wrong, Fraction(1, 1000))
    assert not v and v.witness is not None
    assert v.witness.inside_exact and not v.witness.inside_found
    assert all(isinstance(c, Fraction) for c in v.witness.point)


def test_max_work_is_named_when_refused():
    a, b = square(0, 0), square(1, 1)
    with pytest.raises(CasteljauError, match="max_work"):
        a.union(b, max_work=1)
