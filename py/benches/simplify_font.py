"""Overlap removal over every glyph of a font through the pen protocol: casteljau.pathops
(exact) against skia-pathops (float), one thread each, and the command line's
``casteljau boolean simplify FONT --threads 1`` for the same exact work.

    python py/benches/simplify_font.py [FONT] [--cli target/release/casteljau]

Each route draws every glyph with fontTools' glyph set into a ``Path`` through its pen,
simplifies it (outer contours clockwise, TrueType's convention, as the command line does for a
glyf font) and draws the result into a recording pen. Prints one Markdown table row per route.
"""

from __future__ import annotations

import argparse
import resource
import subprocess
import sys
import time

from fontTools.pens.recordingPen import RecordingPen
from fontTools.ttLib import TTFont


def run(module, glyph_set, names, clockwise):
    errors = 0
    start, cpu = time.perf_counter(), time.process_time()
    for name in names:
        path = module.Path()
        glyph_set[name].draw(path.getPen(glyphSet=glyph_set))
        try:
            result = module.simplify(path, clockwise=clockwise)
        except Exception:  # a float library's failure, or a glyph refused by its budget
            errors += 1
            continue
        result.draw(RecordingPen())
    return time.perf_counter() - start, time.process_time() - cpu, errors


def main() -> None:
    p = argparse.ArgumentParser()
    p.add_argument("font", nargs="?", default="/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf")
    p.add_argument("--cli", default=None, help="the casteljau binary (release build)")
    args = p.parse_args()
    font = TTFont(args.font)
    gs = font.getGlyphSet()
    names = font.getGlyphOrder()
    clockwise = "glyf" in font
    rows = []
    for name in names:
        gs[name]  # decompile every glyph first: both Python routes then draw the same way
    if args.cli:
        start = time.perf_counter()
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        out = subprocess.run(
            [args.cli, "boolean", "simplify", args.font, "--threads", "1", "--json"],
            capture_output=True, text=True,
        )
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        t = time.perf_counter() - start
        cpu = (after.ru_utime + after.ru_stime) - (before.ru_utime + before.ru_stime)
        errors = out.stdout.count('"error"')
        rows.append(("casteljau CLI `boolean simplify FONT --threads 1 --json`", t, cpu, errors))
    from casteljau import pathops as exact

    rows.append(("casteljau.pathops.simplify (Python, pen protocol)",) + run(exact, gs, names, clockwise))
    try:
        import pathops as skia
    except ImportError:
        skia = None
    if skia is not None:
        rows.append(("skia-pathops %s simplify (float)" % getattr(skia, "__version__", ""),) + run(skia, gs, names, clockwise))
    print("%s: %d glyphs" % (args.font, len(names)))
    print("| route | wall s | CPU s | glyphs failed |")
    print("| --- | ---: | ---: | ---: |")
    for name, t, cpu, e in rows:
        print("| %s | %.2f | %.2f | %d |" % (name, t, cpu, e))


if __name__ == "__main__":
    sys.exit(main())
