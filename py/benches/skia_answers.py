#!/usr/bin/env python3
"""skia-pathops' simplify of every glyph of a font, as JSON Lines for `--against`.

    python py/benches/skia_answers.py FONT > skia.jsonl
    casteljau boolean simplify FONT --against skia.jsonl

One line per glyph: {"glyph": name, "path": SVG path data} (coordinates as Python's repr of
the binary64 values Skia returns, read back exactly), or {"glyph", "error"} where Skia raises.
Outer contours clockwise, as the command line writes a TrueType font's glyphs. Coordinates are
the font's stored ones, as casteljau reads them: fontTools (like FreeType) draws a `glyf` glyph
whose left side bearing is not its `xMin` shifted by the difference (a simple glyph; fontTools
leaves composites as stored), which is taken off here.
"""

import json
import sys

import pathops
from fontTools.pens.transformPen import TransformPen
from fontTools.ttLib import TTFont


def path_data(path):
    out = []
    for verb, pts in path:
        name = verb.name
        if name == "MOVE":
            out.append("M%r %r" % pts[0])
        elif name == "LINE":
            out.append("L%r %r" % pts[0])
        elif name == "QUAD":
            out.append("Q%r %r %r %r" % (*pts[0], *pts[1]))
        elif name == "CUBIC":
            out.append("C%r %r %r %r %r %r" % (*pts[0], *pts[1], *pts[2]))
        elif name == "CLOSE":
            out.append("Z")
        else:
            raise ValueError(f"unexpected verb {name}")
    return " ".join(out)


def main():
    font = TTFont(sys.argv[1])
    glyphs = font.getGlyphSet()
    glyf = font["glyf"] if "glyf" in font else None
    for name in font.getGlyphOrder():
        path = pathops.Path()
        shift = 0
        if glyf is not None and glyf[name].numberOfContours > 0:  # composites are drawn unshifted
            shift = font["hmtx"][name][1] - glyf[name].xMin
        glyphs[name].draw(TransformPen(path.getPen(glyphSet=glyphs), (1, 0, 0, 1, -shift, 0)))
        try:
            result = pathops.simplify(path, fix_winding=True, clockwise=True)
            line = {"glyph": name, "path": path_data(result)}
        except pathops.PathOpsError as e:
            line = {"glyph": name, "error": str(e)}
        print(json.dumps(line))


if __name__ == "__main__":
    main()
