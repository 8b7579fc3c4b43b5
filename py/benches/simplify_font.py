"""Overlap removal over every glyph of a font through the pen protocol: casteljau.pathops
(exact) against skia-pathops (float), one thread each, and the command line's
``casteljau boolean simplify FONT --threads 1`` for the same exact work; with ``--peers``, in
the same run, linesweeper's simplify (it has no Python binding: the bench crate's example
``path_ops_peers`` runs it in Rust on the same glyphs, one thread, and prints its wall time).

    cargo build --release                                             # the command line
    cargo build -p casteljau-bench --release --example path_ops_peers   # linesweeper, in Rust
    python py/benches/simplify_font.py [FONT] --cli target/release/casteljau \
        --peers target/release/examples/path_ops_peers

Each route draws every glyph with fontTools' glyph set into a ``Path`` through its pen,
simplifies it (outer contours clockwise, TrueType's convention, as the command line does for a
glyf font) and draws the result into a recording pen. Prints one Markdown table row per route.
"""

from __future__ import annotations

import argparse
import re
import resource
import subprocess
import sys
import tempfile
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
    p.add_argument("--peers", default=None, help="the bench crate's path_ops_peers example (release build)")
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
    if args.peers:
        rows += peers(args.peers, args.font)
    print("%s: %d glyphs" % (args.font, len(names)))
    print("| route | wall s | CPU s | vs the command line (CPU) | glyphs failed |")
    print("| --- | ---: | ---: | ---: | ---: |")
    cli_cpu = rows[0][2] if args.cli else None
    for name, t, cpu, e in rows:
        ratio = "%.2f×" % (cpu / cli_cpu) if cli_cpu and cpu is not None else ""
        print("| %s | %.2f | %s | %s | %d |" % (name, t, "" if cpu is None else "%.2f" % cpu, ratio, e))


def peers(binary, font):
    """linesweeper's (and flo_curves') simplify of every glyph, timed by the example itself (its
    table rows ``| peer | wall time | glyphs | errors | of which panics |``); its hard cases go
    to a temporary folder."""
    with tempfile.TemporaryDirectory() as tmp:
        out = subprocess.run(
            [binary, font, "--out", tmp, "--hard", tmp + "/hard.txt"], capture_output=True, text=True, check=True
        ).stdout
    rows = []
    for peer, label in (("linesweeper", "linesweeper 0.5 simplify (Rust, float: no Python binding)"),
                        ("flo_curves", "flo_curves 0.8 simplify (Rust, float, even-odd)")):
        m = re.search(r"^\| %s \| ([0-9.]+) ?(ms|s) \| \d+ \| (\d+) \|" % peer, out, re.M)
        if m:
            t = float(m.group(1)) / (1000 if m.group(2) == "ms" else 1)
            rows.append((label, t, None, int(m.group(3))))
    return rows


if __name__ == "__main__":
    sys.exit(main())
