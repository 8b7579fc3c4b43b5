"""fontTools integration: ``removeOverlaps`` with casteljau's certified overlap removal.

``casteljau.fonttools.removeOverlaps`` has the signature of
``fontTools.ttLib.removeOverlaps.removeOverlaps`` and works on a ``TTFont`` in memory: the font
is serialized, each glyph decided exactly (``casteljau::overlaps::decide_glyph``: overlaps,
self-intersections, shared boundary pieces, composites whose components overlap; the result
written back on the integer grid with the rounding re-decided exactly) and the font rewritten
with every other glyph byte-identical; the rewritten tables are loaded back into the same
``TTFont``. To make fontTools (and its instancer) use it::

    import fontTools.ttLib.removeOverlaps, casteljau.fonttools
    fontTools.ttLib.removeOverlaps.removeOverlaps = casteljau.fonttools.removeOverlaps

or ``casteljau.fonttools.install()``.
"""

from __future__ import annotations

import io
import logging
from typing import Any, Iterable, List, Optional

from . import _core

__all__ = ["RemoveOverlapsError", "removeOverlaps", "install", "GlyphResult"]

log = logging.getLogger(__name__)

#: The tables the font writer may rewrite.
_TABLES = ("glyf", "loca", "hmtx", "head", "maxp", "CFF ", "hdmx", "vmtx", "post")


class RemoveOverlapsError(_core.CasteljauError):
    """A glyph could not be decided or certified (with ``ignoreErrors=False``)."""


class GlyphResult(tuple):
    """``(glyph_name, status, detail, report)``: status ``unchanged``, ``rewritten``,
    ``uncertified`` or ``error``."""

    __slots__ = ()

    def __new__(cls, name: str, status: str, detail: Any, report: Any) -> "GlyphResult":
        return super().__new__(cls, (name, status, detail, report))

    name = property(lambda self: self[0])
    status = property(lambda self: self[1])
    detail = property(lambda self: self[2])
    report = property(lambda self: self[3])


def removeOverlaps(
    font: Any,
    glyphNames: Optional[Iterable[str]] = None,
    removeHinting: bool = True,
    ignoreErrors: bool = False,
    *,
    removeUnusedSubroutines: bool = True,
    max_work: Optional[float] = None,
) -> List[GlyphResult]:
    """Removes overlaps from the glyphs of a TrueType (``glyf``) or CFF ``TTFont`` in place,
    exactly and certified (fontTools' signature; ``max_work`` bounds each glyph).

    ``glyphNames``: the glyphs to consider (all by default). ``removeHinting``: drop the
    TrueType instructions of rewritten glyphs (kept otherwise where the writer can).
    ``ignoreErrors``: a glyph that cannot be decided or certified is left unchanged and logged,
    instead of raising ``RemoveOverlapsError``. ``removeUnusedSubroutines``: for CFF, drop
    subroutines no charstring uses any more. Variable fonts are refused (fontTools' instancer
    calls this on the static instance). Returns what happened to each glyph considered.
    """
    from fontTools.ttLib import TTFont

    order = font.getGlyphOrder()
    ids = None
    if glyphNames is not None:
        index = {n: i for i, n in enumerate(order)}
        ids = sorted(index[n] for n in glyphNames)
    buf = io.BytesIO()
    font.save(buf)
    try:
        data, glyphs = _core.remove_overlaps(buf.getvalue(), ids, not removeHinting, max_work)
    except _core.CasteljauError as e:
        raise RemoveOverlapsError(str(e)) from e
    results = [GlyphResult(order[gid] if gid < len(order) else "gid%d" % gid, s, d, r) for gid, s, d, r in glyphs]
    problems = [r for r in results if r.status in ("error", "uncertified")]
    for r in problems:
        msg = "glyph %r: %s (%s)" % (r.name, r.status, r.detail)
        if not ignoreErrors:
            raise RemoveOverlapsError(msg)
        log.warning(msg)
    new = TTFont(io.BytesIO(data))
    for tag in _TABLES:
        if tag in new:
            font[tag] = new[tag]
    if removeUnusedSubroutines and "CFF " in font:
        font["CFF "].cff.remove_unused_subroutines()
    return results


def install() -> None:
    """Makes ``fontTools.ttLib.removeOverlaps.removeOverlaps`` (and so fontTools' instancer
    and ``fonttools ttLib.removeOverlaps``) call casteljau's."""
    import fontTools.ttLib.removeOverlaps as ro

    ro.removeOverlaps = removeOverlaps
    try:
        import fontTools.varLib.instancer as inst

        if hasattr(inst, "removeOverlaps"):
            inst.removeOverlaps = removeOverlaps
    except ImportError:  # pragma: no cover
        pass
