"""A fontbakery profile with exact outline checks: ``fontbakery check-profile casteljau.fontbakery
FONT``.

It runs fontbakery's universal profile (and its googlefonts profile when that extra is
installed) with the float outline checks ``outline_direction``, ``outline_colinear_vectors``
and ``overlapping_path_segments`` excluded, and in their place one exact check per kind of
``casteljau lint``: ``casteljau/direction``, ``casteljau/overlaps``,
``casteljau/self_intersections``, ``casteljau/overlapping_segments``, ``casteljau/touching``,
``casteljau/collinear_points``, ``casteljau/zero_length``, ``casteljau/zero_length_handles``,
``casteljau/missing_extrema``, ``casteljau/kinks``, ``casteljau/degenerate_curves``,
``casteljau/cusps``, ``casteljau/loops``, ``casteljau/bbox``. A finding that rounding to the
font's grid explains is reported apart, as INFO.
"""

from __future__ import annotations

from typing import Any, Dict, Iterator, List, Tuple

from fontbakery.prelude import FAIL, INFO, PASS, WARN, Message, check

from ._lint import Finding, lint

#: check id → (lint kinds, status of a finding rounding does not explain, what it is)
CHECKS: Dict[str, Tuple[Tuple[str, ...], Any, str]] = {
    "casteljau/direction": (("direction",), FAIL, "contours oriented wrongly for their nesting depth"),
    "casteljau/overlaps": (("overlap",), WARN, "contours that cross each other"),
    "casteljau/self_intersections": (("self_intersection",), FAIL, "contours that cross themselves"),
    "casteljau/overlapping_segments": (("overlapping_segments",), FAIL, "pieces of outline drawn twice"),
    "casteljau/touching": (("touching",), WARN, "contours that meet without crossing"),
    "casteljau/collinear_points": (("collinear_points",), WARN, "redundant nodes between two lines on one line"),
    "casteljau/zero_length": (("zero_length_segment",), FAIL, "segments of length zero"),
    "casteljau/zero_length_handles": (("zero_length_handle",), WARN, "curve handles of length zero"),
    "casteljau/missing_extrema": (("missing_extremum",), WARN, "horizontal or vertical tangents inside a segment"),
    "casteljau/kinks": (("kink",), WARN, "nodes almost, but not exactly, smooth"),
    "casteljau/degenerate_curves": (("degenerate_curve",), WARN, "curves of lower degree than written"),
    "casteljau/cusps": (("cusp",), WARN, "cusps inside a segment"),
    "casteljau/loops": (("loop",), FAIL, "segments crossing themselves"),
    "casteljau/bbox": (("bbox",), FAIL, "stored bounding boxes that differ from the exact outline's"),
}

_cache: Dict[str, List[Finding]] = {}


def _findings(font: Any) -> List[Finding]:
    path = font.file
    if path not in _cache:
        _cache[path] = lint(path)
    return _cache[path]


def _bullets(found: List[Finding], limit: int = 20) -> str:
    lines = ["* %s: %s" % (f.glyph, f.message) for f in found[:limit]]
    if len(found) > limit:
        lines.append("* … and %d more" % (len(found) - limit))
    return "\n".join(lines)


def _make(check_id: str, kinds: Tuple[str, ...], status: Any, what: str) -> Any:
    def run(font: Any) -> Iterator[Tuple[Any, Any]]:
        found = [f for f in _findings(font) if f.kind in kinds]
        real = [f for f in found if not f.rounding]
        rounded = [f for f in found if f.rounding]
        if real:
            yield status, Message(kinds[0], "%d glyph outline findings (%s), decided exactly:\n\n%s" % (len(real), what, _bullets(real)))
        if rounded:
            yield INFO, Message(
                kinds[0] + "-rounding",
                "%d more explained by rounding to the font's grid:\n\n%s" % (len(rounded), _bullets(rounded, 5)),
            )
        if not real:
            yield PASS, "No %s (decided exactly)." % what

    run.__name__ = "check_" + check_id.replace("/", "_")
    run.__doc__ = "Exact check: %s." % what
    return check(
        id=check_id,
        conditions=["ttFont"],
        rationale="""
            casteljau decides every outline question exactly (rational arithmetic and exact
            algebraic numbers): %s are found with no tolerance, and findings that rounding to
            the font's integer grid explains are reported apart. It replaces fontbakery's
            float outline checks.
        """
        % what,
        proposal="casteljau issue 36",
    )(run)


for _id, (_kinds, _status, _what) in CHECKS.items():
    globals()["check_" + _id.replace("/", "_")] = _make(_id, _kinds, _status, _what)


def _googlefonts_available() -> bool:
    """Whether fontbakery's googlefonts profile loads (its extra, ``fontbakery[googlefonts]``,
    brings the modules its checks import)."""
    try:
        import fontbakery.profiles.googlefonts as gf
        from fontbakery.fonts_profile import checks_by_id, load_all_checks

        if not checks_by_id:
            load_all_checks()
        wanted = [c for checks in gf.PROFILE["sections"].values() for c in checks]
        return all(c in checks_by_id for c in wanted)
    except Exception:  # any import or profile error: the universal profile alone
        return False


PROFILE = {
    "name": "casteljau",
    "include_profiles": ["googlefonts"] if _googlefonts_available() else ["universal"],
    "check_definitions": ["casteljau.fontbakery"],
    "exclude_checks": ["outline_direction", "outline_colinear_vectors", "overlapping_path_segments"],
    "sections": {"casteljau: exact outline checks": list(CHECKS)},
}
