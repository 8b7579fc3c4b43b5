"""``casteljau.lint``: outline QA decided exactly (the command line's ``lint``)."""

from __future__ import annotations

import io
import os
from dataclasses import dataclass, field
from typing import Any, Dict, Iterable, List, Optional, Tuple

from . import _core

__all__ = ["Finding", "lint", "KINDS"]

#: Every lint kind: ``{"kind", "severity", "denied_by_default"}``.
KINDS: List[Dict[str, Any]] = _core.lint_kinds()

_PLACE = ("kind", "severity", "rounding", "contour", "contours", "index", "point", "at", "at_float", "parameters", "message")


@dataclass(frozen=True)
class Finding:
    """One exact finding.

    ``kind`` (``direction``, ``self_intersection``, ``overlap``, ``touching``,
    ``overlapping_segments``, ``missing_extremum``, ``kink``, ``collinear_points``,
    ``zero_length_segment``, ``zero_length_handle``, ``degenerate_curve``, ``cusp``, ``loop``,
    ``bbox``), ``severity`` (``error``/``warning``/``info``), ``rounding`` (explained by rounding
    to the font's grid: reported apart, severity ``info``), the place (``glyph``, ``glyph_id``,
    ``contour``, ``contours`` for pairs, ``segment``, ``point``), the exact points ``at``
    (``Fraction``s, or the exact spelling of an irrational coordinate) with ``at_float``, exact
    ``parameters``, the kind's own ``evidence`` (a dict) and the one-line ``message``.
    """

    kind: str
    severity: str
    rounding: bool
    message: str
    glyph: Optional[str] = None
    glyph_id: Optional[int] = None
    contour: Optional[int] = None
    contours: Optional[Tuple[int, int]] = None
    segment: Optional[int] = None
    point: Optional[int] = None
    at: List[Tuple[Any, Any]] = field(default_factory=list)
    at_float: List[Tuple[float, float]] = field(default_factory=list)
    parameters: List[Any] = field(default_factory=list)
    evidence: Dict[str, Any] = field(default_factory=dict)

    @property
    def fails(self) -> bool:
        """Whether the finding fails a run by default (its kind is denied by default and
        rounding does not explain it), as ``casteljau lint`` exits 1."""
        return not self.rounding and any(k["kind"] == self.kind and k["denied_by_default"] for k in KINDS)

    def __str__(self) -> str:
        where = self.glyph if self.glyph is not None else "outline"
        return "%s: %s (%s%s): %s" % (
            where,
            self.kind,
            self.severity,
            ", rounding" if self.rounding else "",
            self.message,
        )


def _finding(d: Dict[str, Any], glyph: Optional[str] = None, glyph_id: Optional[int] = None) -> Finding:
    c = d.get("contours")
    return Finding(
        kind=d["kind"],
        severity=d["severity"],
        rounding=d["rounding"],
        message=d["message"],
        glyph=glyph,
        glyph_id=glyph_id,
        contour=d.get("contour"),
        contours=tuple(c) if c is not None else None,
        segment=d.get("index"),
        point=d.get("point"),
        at=[tuple(p) for p in d.get("at", [])],
        at_float=[tuple(p) for p in d.get("at_float", [])],
        parameters=list(d.get("parameters", [])),
        evidence={k: v for k, v in d.items() if k not in _PLACE},
    )


def _font_bytes(font: Any) -> Optional[bytes]:
    if isinstance(font, (bytes, bytearray, memoryview)):
        return bytes(font)
    if isinstance(font, (str, os.PathLike)) and not os.path.isdir(font):
        with open(font, "rb") as f:
            return f.read()
    if hasattr(font, "reader") and hasattr(font, "save") and hasattr(font, "getGlyphOrder"):  # a TTFont
        buf = io.BytesIO()
        font.save(buf)
        return buf.getvalue()
    return None


def lint(
    font_or_path: Any,
    glyphs: Optional[Iterable[str]] = None,
    kinds: Optional[Iterable[str]] = None,
    *,
    orientation: Optional[str] = None,
    kink_angle: Optional[float] = None,
    face: int = 0,
    max_work: Optional[float] = None,
) -> List[Finding]:
    """Every exact finding of a font's outlines.

    ``font_or_path``: a font file path or its bytes, a fontTools ``TTFont`` (saved to bytes
    first, so in-memory edits count), a UFO's path (its default layer, read with fontTools'
    ``ufoLib``), or a UFO font/layer or any mapping of glyph names to objects with
    ``draw(pen)`` (outer contours counter-clockwise unless ``orientation="cw"``).
    ``glyphs``: names to check (all by default); ``kinds``: the kinds to decide (all by
    default); ``max_work``: the budget of each glyph's arrangement. A glyph that cannot be read
    or decided raises ``CasteljauError`` naming it.

    >>> import casteljau
    >>> found = casteljau.lint({"square": casteljau.Shape.from_svg_path("M0 0 H5 H10 V10 H0 Z")})
    >>> [(f.glyph, f.kind, f.at) for f in found]
    [('square', 'collinear_points', [(Fraction(5, 1), Fraction(0, 1))])]
    """
    kinds = list(kinds) if kinds is not None else None
    data = _font_bytes(font_or_path)
    out: List[Finding] = []
    if data is not None:
        names = list(glyphs) if glyphs is not None else None
        for name, gid, findings, error in _core.lint_font(data, names, kinds, max_work, face, kink_angle):
            if error is not None:
                raise _core.CasteljauError("glyph %s (id %d): %s" % (name, gid, error))
            out.extend(_finding(d, name, gid) for d in findings)
        return out
    # a glyph set: draw each glyph exactly
    from .shape import Shape

    glyph_set = font_or_path
    if isinstance(glyph_set, (str, os.PathLike)):  # a UFO folder
        from fontTools.ufoLib import UFOReader

        glyph_set = UFOReader(os.fspath(glyph_set)).getGlyphSet()
    names = list(glyphs) if glyphs is not None else list(glyph_set.keys())
    for name in names:
        g = glyph_set[name]
        if isinstance(g, Shape):
            contours = g.exchange()
        else:
            contours = Shape.from_pen_drawing(g.draw, glyph_set).exchange()
        try:
            findings = _core.lint_contours(contours, orientation or "ccw", kinds, max_work, kink_angle)
        except _core.CasteljauError as e:
            raise _core.CasteljauError("glyph %s: %s" % (name, e)) from e
        out.extend(_finding(d, name) for d in findings)
    return out
