"""A ufo2ft filter removing overlaps exactly: select it with no change to ufo2ft or fontmake::

    fontmake --keep-overlaps \\
        --filter "casteljau.filters.removeOverlaps::RemoveOverlapsFilter(pre=True)" ...

or in the UFO's lib: ``com.github.googlei18n.ufo2ft.filters``:
``[{"name": "RemoveOverlaps", "namespace": "casteljau.filters", "pre": true}]``.

Each glyph is recorded exactly (coordinates as stored, TrueType implied on-curve points as
exact midpoints, components transformed exactly) and decided by casteljau's overlap removal
(``casteljau::overlaps::decide_glyph``, the ``remove-overlaps`` command's route): a glyph that
needs no change keeps its contours and components; a rewritten glyph gets the certified
integer-grid outline, its components decomposed only where they overlap or share pieces. It
runs on the cubic UFO outlines (before cu2qu), so the outline is decided as drawn; a glyph drawn
with quadratic curves only (a TrueType-flavoured UFO) stays quadratic.
"""

from __future__ import annotations

import logging
from typing import Any, List, Optional

from .. import _core
from ..pathops._path import Path, exchange

log = logging.getLogger(__name__)

try:  # ufo2ft is optional: without it the filter is still a callable class
    from ufo2ft.filters import BaseFilter
except ImportError:  # pragma: no cover
    BaseFilter = object  # type: ignore[misc,assignment]

__all__ = ["RemoveOverlapsFilter"]


def _outline(glyph: Any, glyph_set: Any, transform: Optional[Any] = None) -> list:
    path = Path()
    pen = path.getPen(glyphSet=glyph_set)
    # contours only: components are separate inputs to the decision
    for contour in getattr(glyph, "contours", getattr(glyph, "__iter__", lambda: [])()):
        contour.draw(pen)
    if transform is not None:
        path = path.transform(*transform)
    return exchange(path)


def _component_outline(component: Any, glyph_set: Any) -> list:
    path = Path()
    pen = path.getPen(glyphSet=glyph_set)
    component.draw(pen)
    return exchange(path)


class RemoveOverlapsFilter(BaseFilter):  # type: ignore[misc,valid-type]
    """Exact, certified overlap removal for ufo2ft (options: ``max_work`` per glyph,
    ``ignoreErrors`` (default True: an uncertified glyph is left as it is and logged), and the
    outer contour ``orientation``, ``"ccw"`` for UFO/PostScript outlines)."""

    _kwargs = {"max_work": None, "ignoreErrors": True, "orientation": "ccw"}

    def filter(self, glyph: Any) -> bool:
        glyph_set = self.context.glyphSet
        components: List[list] = []
        own = _outline(glyph, glyph_set)
        if own:
            components.append(own)
        for comp in getattr(glyph, "components", []):
            components.append(_component_outline(comp, glyph_set))
        if not components:
            return False
        flavour = _flavour(components)
        try:
            status, contours, report = _core.decide(
                components, flavour, self.options.orientation, glyph.name, 0, self.options.max_work
            )
        except _core.CasteljauError as e:
            if not self.options.ignoreErrors:
                raise
            log.warning("glyph %r left unchanged: %s", glyph.name, e)
            return False
        if status == "unchanged":
            return False
        if status == "uncertified":
            if not self.options.ignoreErrors:
                raise _core.CasteljauError("glyph %r: %s" % (glyph.name, contours))
            log.warning("glyph %r left unchanged: %s", glyph.name, contours)
            return False
        _write(glyph, contours, "qcurve" if flavour == "quadratic" else "curve")
        return True


def _flavour(components: List[list]) -> str:
    """``"quadratic"`` for outlines whose curves are all quadratic, ``"cubic"`` otherwise."""
    degrees = {len(pts) for outline in components for contour in outline for pts, _ in contour}
    return "quadratic" if 3 in degrees and 4 not in degrees else "cubic"


def _write(glyph: Any, contours: list, curve: str) -> None:
    """Replaces the glyph's outline by grid contours of ``(x, y, on_curve)``, an on-curve point
    after control points starting a segment of type ``curve`` (``"curve"``: two control points
    between on-curve points; ``"qcurve"``: TrueType's quadratic splines)."""
    glyph.clearContours()
    glyph.clearComponents()
    pen = glyph.getPointPen()
    for c in contours:
        pen.beginPath()
        n = len(c)
        # the segment type of an on-curve point: "curve" when control points precede it
        for i, (x, y, on) in enumerate(c):
            if not on:
                pen.addPoint((x, y))
                continue
            prev_on = c[(i - 1) % n][2]
            pen.addPoint((x, y), segmentType="line" if prev_on else curve)
        pen.endPath()
