"""Hypothesis strategies for exact curves and their hard cases (mirroring the crate's
``casteljau::strategies``), so a Python project can property-test its float code against the
exact oracle.

Every strategy draws ``casteljau.Bezier`` curves whose promised feature is exact by
construction: a cusp exactly at ``τ``, a loop whose double point is reached exactly at ``t0`` and
``t1``, an inflection exactly at an end point, curve pairs touching with a given contact order
or meeting at an end point. The ``binary64`` variants have control points that are exact
``float`` values, so float code sees exactly the curve casteljau decides (``float_points``).

>>> from hypothesis import given
>>> from casteljau import strategies as cs
>>> @given(cs.cusp_at(cs.unit_parameters()))
... def test_cusp(case):
...     curve, tau = case
...     assert curve.classify()["cusp_parameters"] == [tau]
>>> test_cusp()
"""

from __future__ import annotations

from fractions import Fraction
from math import comb
from typing import Any, List, Sequence, Tuple

from hypothesis import strategies as st

from ._core import Bezier

__all__ = [
    "small_rationals",
    "unit_parameters",
    "exact_curves",
    "binary64_curves",
    "dyadic_unit_parameters",
    "cusp_at",
    "loop_between",
    "inflection_at_endpoint",
    "near_cusp",
    "degree_elevated_quadratic",
    "collinear_cubic",
    "coincident_control_points",
    "binary64_cusp_at",
    "binary64_loop_between",
    "tangent_pair",
    "endpoint_hit",
    "overlapping_pair",
    "touching_boxes",
    "float_points",
]

Curve = Bezier


def small_rationals() -> st.SearchStrategy[Fraction]:
    """Small exact rationals ``p/q``, ``|p| ≤ 200``, ``1 ≤ q ≤ 60``."""
    return st.builds(Fraction, st.integers(-200, 200), st.integers(1, 60))


def unit_parameters() -> st.SearchStrategy[Fraction]:
    """Parameters in ``[0, 1]``, the end points ``0`` and ``1`` drawn often."""
    return st.one_of(st.just(Fraction(0)), st.just(Fraction(1)), st.builds(lambda p, q: Fraction(min(p, q), q), st.integers(0, 60), st.integers(1, 60)))


def dyadic_unit_parameters() -> st.SearchStrategy[Fraction]:
    """Dyadic parameters ``k/2^m`` in ``[0, 1]`` (``m ≤ 6``), end points often."""
    return st.one_of(st.just(Fraction(0)), st.just(Fraction(1)), st.builds(lambda k: Fraction(k, 64), st.integers(0, 64)))


def exact_curves(degree: int = 3, dim: int = 2) -> st.SearchStrategy[Curve]:
    """Curves of ``degree`` with small rational control points."""
    point = st.tuples(*([small_rationals()] * dim))
    return st.lists(point, min_size=degree + 1, max_size=degree + 1).map(Bezier)


def binary64_curves(degree: int = 3, bound: float = 1e6) -> st.SearchStrategy[Curve]:
    """Planar curves whose control points are finite floats (taken exactly) in ``[-bound, bound]``."""
    f = st.floats(-bound, bound, allow_nan=False, allow_infinity=False)
    return st.lists(st.tuples(f, f), min_size=degree + 1, max_size=degree + 1).map(Bezier)


def float_points(curve: Curve) -> List[Tuple[float, float]]:
    """The control points as floats; exact for the ``binary64`` strategies' curves (checked)."""
    out = []
    for p in curve.points:
        q = tuple(float(c) for c in p)
        assert all(Fraction(a) == b for a, b in zip(q, p)), "not a binary64 point"
        out.append(q)
    return out


def _affine(offset: int = 50) -> st.SearchStrategy[Tuple[Tuple[int, int, int, int], Tuple[int, int]]]:
    m = st.tuples(*([st.integers(-4, 4)] * 4)).filter(lambda m: m[0] * m[3] - m[1] * m[2] != 0)
    return st.tuples(m, st.tuples(st.integers(-offset, offset), st.integers(-offset, offset)))


def _from_power(x: Sequence[Fraction], y: Sequence[Fraction], m: Sequence[int], o: Sequence[int]) -> Curve:
    """The cubic with power form ``(Σ x_k t^k, Σ y_k t^k)`` mapped by ``v ↦ M v + o``."""
    n = len(x) - 1
    coeffs = []
    for k in range(n + 1):
        ox, oy = (o[0], o[1]) if k == 0 else (0, 0)
        coeffs.append((m[0] * x[k] + m[1] * y[k] + ox, m[2] * x[k] + m[3] * y[k] + oy))
    # b_i = Σ_{j ≤ i} C(i, j)/C(n, j) a_j
    pts = []
    for i in range(n + 1):
        bx = sum(Fraction(comb(i, j), comb(n, j)) * coeffs[j][0] for j in range(i + 1))
        by = sum(Fraction(comb(i, j), comb(n, j)) * coeffs[j][1] for j in range(i + 1))
        pts.append((bx, by))
    return Bezier(pts)


def _compose(c: Sequence[Any], alpha: Fraction, beta: Fraction) -> List[Fraction]:
    """``Σ c_k s^k`` with ``s = α t + β``, as power coefficients in ``t``."""
    out = [Fraction(0)] * len(c)
    for k, ck in enumerate(c):
        for j in range(k + 1):
            out[j] += Fraction(ck) * comb(k, j) * alpha**j * beta ** (k - j)
    return out


def cusp_at(tau: st.SearchStrategy[Fraction]) -> st.SearchStrategy[Tuple[Curve, Fraction]]:
    """A cusp exactly at ``t = τ``: an affine image of ``(s², s³)``, ``s = t − τ``."""

    def build(t: Fraction, a: Any) -> Tuple[Curve, Fraction]:
        m, o = a
        x = _compose([0, 0, 1, 0], Fraction(1), -t)
        y = _compose([0, 0, 0, 1], Fraction(1), -t)
        return _from_power(x, y, m, o), t

    return st.builds(build, tau, _affine())


def loop_between() -> st.SearchStrategy[Tuple[Curve, Tuple[Fraction, Fraction]]]:
    """A loop whose double point is reached exactly at ``t0 < t1`` (from ``{0, 1}`` and
    ``[0, 2]``): an affine image of the crunode ``(s² − 1, s³ − s)``, ``s(t0) = −1``, ``s(t1) = 1``."""
    end = st.one_of(st.just(Fraction(0)), st.just(Fraction(1)), st.builds(lambda p: Fraction(p, 20), st.integers(0, 40)))

    def build(a: Fraction, b: Fraction, aff: Any) -> Tuple[Curve, Tuple[Fraction, Fraction]]:
        t0, t1 = min(a, b), max(a, b)
        alpha = 2 / (t1 - t0)
        beta = -1 - alpha * t0
        x = _compose([-1, 0, 1, 0], alpha, beta)
        y = _compose([0, -1, 0, 1], alpha, beta)
        return _from_power(x, y, *aff), (t0, t1)

    return st.tuples(end, end, _affine()).filter(lambda v: v[0] != v[1]).map(lambda v: build(*v))


def inflection_at_endpoint() -> st.SearchStrategy[Tuple[Curve, Fraction]]:
    """An inflection exactly at ``t = 0`` or ``t = 1``: an affine image of ``(s, s³)``."""

    def build(at: Fraction, scale: int, aff: Any) -> Tuple[Curve, Fraction]:
        alpha = Fraction(scale)
        beta = -alpha * at
        x = _compose([0, 1, 0, 0], alpha, beta)
        y = _compose([0, 0, 0, 1], alpha, beta)
        return _from_power(x, y, *aff), at

    return st.builds(build, st.sampled_from([Fraction(0), Fraction(1)]), st.integers(1, 5), _affine())


def near_cusp(exponents: Sequence[int] = range(1, 16)) -> st.SearchStrategy[Tuple[Curve, int]]:
    """The cusp ``(0,0) (1,1) (0,1) (1,0)`` with ``P1.y`` moved by ``±10^-k``: exactly a crunode
    or an acnode, never a cusp."""

    def build(k: int, sign: int) -> Tuple[Curve, int]:
        return Bezier([(0, 0), (1, 1 + sign * Fraction(1, 10**k)), (0, 1), (1, 0)]), k

    return st.builds(build, st.sampled_from(list(exponents)), st.sampled_from([-1, 1]))


def degree_elevated_quadratic() -> st.SearchStrategy[Curve]:
    """A quadratic with thirds in its coordinates written as a cubic."""
    return exact_curves(2).map(lambda q: q.elevate(1))


def collinear_cubic() -> st.SearchStrategy[Curve]:
    """Four control points on one line (random positions along it)."""

    def build(c: Fraction, d: Tuple[int, int], s: List[Fraction]) -> Curve:
        return Bezier([(c + si * d[0], si * d[1]) for si in s])

    return st.builds(build, small_rationals(), st.tuples(st.integers(-3, 3), st.integers(-3, 3)), st.lists(small_rationals(), min_size=4, max_size=4))


def coincident_control_points() -> st.SearchStrategy[Curve]:
    """A cubic with one control point copied onto the next (P0 = P1, P1 = P2 or P2 = P3)."""

    def build(c: Curve, i: int) -> Curve:
        p = list(c.points)
        p[i + 1] = p[i]
        return Bezier(p)

    return st.builds(build, exact_curves(3), st.integers(0, 2))


def _is_binary64(c: Curve) -> bool:
    return all(Fraction(float(v)) == v for p in c.points for v in p)


def binary64_cusp_at() -> st.SearchStrategy[Tuple[Curve, Fraction]]:
    """``cusp_at`` with dyadic ``τ`` and control points that are exact floats."""
    return cusp_at(dyadic_unit_parameters()).map(lambda v: (Bezier([tuple(3 * c for c in p) for p in v[0].points]), v[1])).filter(
        lambda v: _is_binary64(v[0])
    )


def binary64_loop_between() -> st.SearchStrategy[Tuple[Curve, Tuple[Fraction, Fraction]]]:
    """``loop_between`` with control points that are exact floats."""
    return loop_between().map(lambda v: (Bezier([tuple(3 * c for c in p) for p in v[0].points]), v[1])).filter(lambda v: _is_binary64(v[0]))


def _map(c: Curve, m: Sequence[int], o: Sequence[int]) -> Curve:
    return Bezier([(m[0] * x + m[1] * y + o[0], m[2] * x + m[3] * y + o[1]) for x, y in c.points])


def _monomial(k: int, tau: Fraction) -> Curve:
    """``(u, u^k)``, ``u = s − τ``, as a Bézier curve of degree ``k`` on ``s ∈ [0, 1]``."""
    x = [Fraction(0)] * (k + 1)
    x[0], x[1] = -tau, Fraction(1)
    y = [comb(k, j) * (-tau) ** (k - j) for j in range(k + 1)]
    return _from_power(x, y, (1, 0, 0, 1), (0, 0))


def tangent_pair(k: int = 2) -> st.SearchStrategy[Tuple[Curve, Curve, Tuple[Fraction, Fraction]]]:
    """Two curves touching with contact order ``k`` (2: a parabola and its tangent; 3: a cubic
    and its inflection tangent) at ``s = τ`` (dyadic, end points often) and ``t = λ/(λ + μ)``;
    control points exact floats. Yields the curves and ``(τ, t)``."""
    lengths = st.sampled_from([(1, 1), (1, 3), (3, 1), (1, 7), (2, 2)])

    def build(tau: Fraction, lm: Tuple[int, int], aff: Any) -> Any:
        l, m = lm
        a = _map(_monomial(k, tau), *aff)
        b = _map(Bezier([(-l, 0), (m, 0)]), *aff)
        return a, b, (tau, Fraction(l, l + m))

    return st.builds(build, dyadic_unit_parameters(), lengths, _affine(40)).filter(lambda v: _is_binary64(v[0]) and _is_binary64(v[1]))


def endpoint_hit() -> st.SearchStrategy[Tuple[Curve, Curve, Fraction]]:
    """A cubic and a line starting exactly on it at ``A(τ)`` (``τ`` dyadic); exact floats."""
    ints = st.integers(-64, 64)
    cubic = st.lists(st.tuples(ints, ints), min_size=4, max_size=4).map(Bezier)

    def build(a: Curve, tau: Fraction, d: Tuple[int, int]) -> Any:
        p = a(tau)
        return a, Bezier([p, (p[0] + d[0], p[1] + d[1])]), tau

    return st.builds(build, cubic, dyadic_unit_parameters(), st.tuples(ints, ints)).filter(
        lambda v: v[1].points[0] != v[1].points[1] and _is_binary64(v[1])
    )


def overlapping_pair() -> st.SearchStrategy[Tuple[Curve, Curve, Fraction]]:
    """A cubic (control points off one line) and its own left piece up to ``u ∈ {1/4, 1/2,
    3/4}``: an overlap on ``[0, u]``."""
    ints = st.integers(-64, 64)
    cubic = st.lists(st.tuples(ints, ints), min_size=4, max_size=4).map(Bezier)

    def build(a: Curve, u: Fraction) -> Any:
        return a, a.subdivide(u)[0], u

    def off_line(c: Curve) -> bool:
        (x0, y0), *rest = c.points
        return any((x1 - x0) * (y2 - y0) != (y1 - y0) * (x2 - x0) for (x1, y1) in rest for (x2, y2) in rest)

    # off a line: a curve on a line that turns back overlaps its piece in several arcs
    return st.builds(build, cubic, st.sampled_from([Fraction(1, 4), Fraction(1, 2), Fraction(3, 4)])).filter(
        lambda v: off_line(v[0]) and _is_binary64(v[1])
    )


def touching_boxes() -> st.SearchStrategy[Tuple[Curve, Curve]]:
    """Two arches whose bounding boxes touch along a line without the curves meeting."""

    def build(h: int, k: int, aff: Any) -> Tuple[Curve, Curve]:
        a = Bezier([(0, 0), (1, k), (2, 0)])
        b = Bezier([(2, h), (3, h + k), (4, h)])
        return _map(a, *aff), _map(b, *aff)

    return st.builds(build, st.integers(1, 8), st.integers(1, 8), _affine(40))
