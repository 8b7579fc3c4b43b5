"""The Hypothesis strategies keep their promises (checked by the exact oracle)."""

from fractions import Fraction

from hypothesis import given, settings

from casteljau import strategies as cs

FEW = settings(max_examples=15, deadline=None)


@FEW
@given(cs.cusp_at(cs.unit_parameters()))
def test_cusp_at(case):
    curve, tau = case
    k = curve.classify()
    assert k["node_type"] == "cusp" and k["cusp_parameters"] == [tau]


@FEW
@given(cs.loop_between())
def test_loop_between(case):
    curve, (t0, t1) = case
    assert curve(t0) == curve(t1)
    assert curve.classify()["double_point_parameters"] == [t0, t1]


@FEW
@given(cs.inflection_at_endpoint())
def test_inflection_at_endpoint(case):
    curve, at = case
    assert at in curve.classify()["inflection_parameters"]


@FEW
@given(cs.near_cusp(range(1, 12)))
def test_near_cusp_is_never_a_cusp(case):
    curve, _ = case
    assert curve.classify()["node_type"] in ("crunode", "acnode")


@FEW
@given(cs.binary64_cusp_at())
def test_binary64_cusp(case):
    curve, tau = case
    pts = cs.float_points(curve)  # exact floats
    assert len(pts) == 4 and curve.classify()["cusp_parameters"] == [tau]


@FEW
@given(cs.tangent_pair(2))
def test_tangent_pairs(case):
    a, b, (s, t) = case
    cs.float_points(a), cs.float_points(b)
    found = a.intersect(b)
    assert [(p.s, p.t, p.contact_order) for p in found] == [(s, t, 2)]


@FEW
@given(cs.endpoint_hit())
def test_endpoint_hits(case):
    a, b, tau = case
    assert any(p.s == tau and p.t == 0 for p in a.intersect(b)) or a.intersect(b).overlaps


@FEW
@given(cs.overlapping_pair())
def test_overlapping_pairs(case):
    a, b, u = case
    o = a.intersect(b).overlaps
    assert o and o[0].s == (0, u)


@FEW
@given(cs.touching_boxes())
def test_touching_boxes_do_not_meet(case):
    a, b = case
    assert not a.intersect(b).points


@FEW
@given(cs.degree_elevated_quadratic(), cs.collinear_cubic(), cs.coincident_control_points())
def test_degenerate_cubics(q, line, twin):
    assert q.real_degree <= 2
    assert line.classify()["collinear"]
    assert twin.degree == 3
