"""Bezier and RationalBezier: the exact operations."""

import threading
from fractions import Fraction

import pytest

from casteljau import Algebraic, Bezier, CasteljauError, RationalBezier

F = Fraction


def test_eval_subdivide_elevate_reduce():
    c = Bezier("-1 -1, -1/3 1, 1/3 -1, 1 1")
    left, right = c.subdivide(F(1, 3))
    assert left.points[-1] == right.points[0] == c(F(1, 3)) == (F(-1, 3), F(-1, 27))
    assert left == Bezier("-1 -1, -7/9 -1/3, -5/9 -1/9, -1/3 -1/27")
    e = c.elevate(2)
    assert e.degree == 5 and e.reduce() == c
    assert c.subsegment(0, 1) == c and c.subsegment(1, 0).points == c.points[::-1]
    assert c.eval(0.5) == c(F(1, 2))  # floats taken exactly


def test_power_form_and_derivative():
    c = Bezier([(0, 0), (1, 2), (2, 0)])
    assert c.power_form() == [(0, 0), (2, 4), (0, -4)]
    assert c.derivative() == Bezier([(2, 4), (2, -4)])
    assert c.derivative(2) == Bezier([(0, -8)])
    assert Bezier([(0, 0), (1, 1), (2, 2), (3, 3)]).real_degree == 1


def test_extrema_and_bounds_exact():
    c = Bezier([(0, 0), (3, 1), (-1, 2), (1, 3)])
    xmin, ymin, xmax, ymax = c.bounds()
    assert (xmin, ymin, ymax) == (0, 0, 3)
    assert isinstance(xmax, Algebraic) and str(xmax) == "133/169 + 20/169*sqrt(10)"
    assert float(xmax) == 1.161216291144187
    (axis, t, value), *_ = c.extrema()
    assert axis == 0 and str(t) == "7/13 - 1/13*sqrt(10)" and value == xmax
    assert c(t)[0] == xmax  # evaluation at an algebraic parameter is exact


def test_classify_reports_exact_parameters():
    loop = Bezier("0 0, 3 4, -1 4, 2 0")
    k = loop.classify()
    assert k["node_type"] == "crunode" and k["segment"]["loop"]
    s, t = k["double_point_parameters"]
    assert isinstance(s, (Fraction, Algebraic)) and s < t
    assert loop(s) == loop(t)  # the double point, exactly
    cusp = Bezier("0 0, 1 1, 0 1, 1 0").classify()
    assert cusp["node_type"] == "cusp" and cusp["cusp_parameters"] == [F(1, 2)]


def test_intersections_exact():
    parabola = Bezier([(0, 0), (1, 2), (2, 0)])
    tangent = Bezier([(0, 1), (2, 1)])
    found = parabola.intersect(tangent)
    assert len(found) == 1 and not found.overlaps
    (p,) = found.points
    assert (p.s, p.t, p.point, p.contact_order, p.kind) == (F(1, 2), F(1, 2), (1, 1), 2, "tangent")
    crossing = Bezier([(0, 0), (1, 2), (2, 0)]).intersect(Bezier([(0, F(1, 2)), (2, F(1, 2))]))
    assert [p.contact_order for p in crossing] == [1, 1]
    s0 = crossing.points[0].s
    assert isinstance(s0, Algebraic) and parabola(s0) == crossing.points[0].point


def test_overlaps_and_self_intersections():
    c = Bezier([(0, 0), (1, 2), (3, 3), (4, 0)])
    left = c.subdivide(F(1, 2))[0]
    o = c.intersect(left)
    assert len(o.overlaps) == 1 and o.overlaps[0].s == (0, F(1, 2))
    loop = Bezier("0 0, 3 4, -1 4, 2 0")
    (x,) = loop.self_intersections().points
    assert x.s < x.t and loop(x.s) == loop(x.t)


def test_rational_curves():
    quarter = RationalBezier([(1, 0), (1, 1), (0, 1)], [1, 1, 2])
    x, y = quarter(F(1, 3))
    assert x * x + y * y == 1
    assert quarter.bounds() == (0, 0, 1, 1)
    assert quarter.elevate().degree == 3 and quarter.weights == [1, 1, 2]
    hits = quarter.intersect(Bezier([(0, 0), (1, 1)]))
    (p,) = hits.points
    assert p.point[0] == p.point[1] == Algebraic.roots([-1, 0, 2])[1]  # (√2/2, √2/2)
    folium = RationalBezier([(0, 0), (1, 0), (2, 1), (F(3, 2), F(3, 2))], [1, 1, 1, 2])
    assert folium.classify()["node_type"] == "crunode"
    with pytest.raises(CasteljauError, match="weights"):
        RationalBezier([(0, 0), (1, 1)], [1])


def test_rational_reduction_power_form_subsegment():
    quarter = RationalBezier([(1, 0), (1, 1), (0, 1)], [1, 1, 2])
    assert quarter.elevate(3).reduce() == quarter
    # x = (1 - t²)/(1 + t²), y = 2t/(1 + t²): numerator coordinates, then the denominator
    assert quarter.power_form() == [(1, 0, 1), (0, 2, 0), (-1, 0, 1)]
    piece = quarter.subsegment(F(1, 4), F(3, 4))
    assert piece(F(1, 2)) == quarter(F(1, 2)) and piece(0) == quarter(F(1, 4))
    assert quarter.homogeneous == Bezier([(1, 0, 1), (1, 1, 1), (0, 2, 2)])
    assert RationalBezier.from_homogeneous(quarter.homogeneous) == quarter


def test_a_point_at_infinity_is_none_not_a_panic():
    # weights 1, -1, 1 vanish at t = 1/2: the left half ends at a point at infinity
    left, _ = RationalBezier([(0, 0), (1, 1), (2, 0)], [1, -1, 1]).subdivide(F(1, 2))
    assert left.weights == [1, 0, 0]
    assert left.points == [(0, 0), None, None]
    assert repr(left).startswith("RationalBezier.from_homogeneous(")
    assert RationalBezier.from_homogeneous(left.homogeneous) == left
    with pytest.raises(CasteljauError, match="zero vector"):
        RationalBezier.from_homogeneous([(0, 0, 0), (1, 1, 1)])


def test_work_budget_refusal_names_max_work():
    c = Bezier([(0, 0), (1, 1), (2, 0)])
    with pytest.raises(CasteljauError, match=r"max_work=\d"):
        c.elevate(200, max_work=1000)
    assert c.elevate(200, max_work=float("inf")).degree == 202


def test_errors_carry_the_command_lines_message():
    with pytest.raises(CasteljauError, match=r'bad number "x" at column'):
        Bezier("0 0, 1 x")
    with pytest.raises(CasteljauError, match="degree to intersect 11 exceeds the limit 10"):
        Bezier([(i, i * i) for i in range(12)]).intersect(Bezier([(0, 0), (1, 1)]))
    with pytest.raises(CasteljauError, match="the domain is"):
        Bezier([(0, 0), (1, 1)]).intersect(Bezier([(0, 1), (1, 0)]), domain="nowhere")


def test_long_work_releases_the_gil():
    # a thread keeps counting while an exact intersection runs: it could not if the GIL were held
    a = Bezier([(0, 0), (F(1, 3), 7), (F(5, 7), -3), (F(11, 13), 5), (1, F(1, 17)), (2, 3)])
    b = Bezier([(0, 1), (F(2, 3), -5), (F(4, 5), 6), (F(9, 11), -4), (2, 0)])
    ticks = []
    done = threading.Event()

    def count():
        while not done.is_set():
            ticks.append(1)

    t = threading.Thread(target=count)
    t.start()
    before = len(ticks)
    a.intersect(b, domain="all")
    during = len(ticks) - before
    done.set()
    t.join()
    assert during > 0
