#!/usr/bin/env python3
"""Compare fontbakery's outline checks with `casteljau lint` on one font.

Not part of the test suite: a diagnostic that shows, per category, which
glyphs fontbakery's float heuristics flag, which glyphs casteljau's exact
findings flag, and which glyphs both flag.

Usage:
    python3 scripts/compare_outline_checks.py FONT [--casteljau PATH]
        [--lint-args "ARGS"] [--map CHECK=KIND,KIND] [--examples N]
        [--json-out FILE] [--no-uncap]

Needs fontbakery (>= 0.13; tested with 1.1.0) importable by the Python that
runs this script, e.g. a venv made with `python3 -m venv VENV &&
VENV/bin/pip install fontbakery`, then `VENV/bin/python scripts/...`.
Only the standard library and fontbakery (with its dependencies fontTools and
beziers) are used.

How fontbakery is run: its check functions are called in-process through its
own CheckRunner with a one-section profile holding only the checks below
(their conditions are honoured: a check skipped by fontbakery is reported as
skipped), with full lists on. The glyph names are taken from the check
messages (each item starts with the glyph name). Three checks (alignment
miss, colinear vectors, short segments) pass silently when they find more
than FALSE_POSITIVE_CUTOFF items; for those the script runs the check a
second time with the cutoff lifted, says so, and compares the uncapped list
(--no-uncap keeps fontbakery's verdict).

For testing without the binary, --casteljau-json FILE (not shown by --help)
reads precomputed `casteljau lint --json` output instead of running it.

casteljau: `casteljau lint --json FONT` (JSON Lines, one finding per line).
The binary is --casteljau PATH, else `casteljau` on PATH, else
target/release/casteljau or target/debug/casteljau of this repository.

Exit status: 0 when the comparison (or, without fontbakery, casteljau's
counts alone) was printed; 2 when casteljau's binary is missing or fails
(exit status other than 0 or 1) or its output cannot be read.
"""

import argparse
import json
import os
import re
import shlex
import shutil
import subprocess
import sys
import time
import warnings
from collections import Counter, defaultdict

# fontbakery check id -> casteljau lint kinds it is compared with ([] = no
# exact counterpart: fontbakery's findings are listed as float-only).
# --map CHECK=KIND,KIND overrides an entry.
# The order is fontbakery's googlefonts profile order, which matters: the
# checks share one cached set of beziers paths, and once a segment-based check
# has run, outline_alignment_miss (which asks for nodes) crashes on a glyph
# with a single-point contour (beziers' Segment.toNodelist indexes segments[0]).
CHECKS = [
    ("outline_alignment_miss", []),
    ("outline_colinear_vectors", ["collinear_points", "kink"]),
    ("outline_direction", ["direction"]),
    ("outline_jaggy_segments", ["kink"]),
    ("outline_semi_vertical", []),
    ("outline_short_segments", ["zero_length_segment"]),
    ("overlapping_path_segments", ["overlapping_segments"]),
    ("nested_components", []),
]

# Where each check's definition lives, as (module, substring of the line to
# quote, what the line means). Quoted from the installed fontbakery with file
# and line number, so the report follows the version in use.
DEFINITIONS = {
    "outline_colinear_vectors": [
        ("fontbakery.checks.outline_colinear_vectors", "len(prev) == 2 and len(this) == 2",
         "only line-line joins are looked at"),
        ("fontbakery.checks.outline_colinear_vectors", "< COLINEAR_EPSILON",
         "the two lines' atan2 directions differ by less than the epsilon (no wrap at +-pi: "
         "two lines heading in the -x direction can differ by ~2pi and are missed)"),
        ("fontbakery.checks.outline_settings", "COLINEAR_EPSILON =", ""),
        ("fontbakery.checks.outline_settings", "FALSE_POSITIVE_CUTOFF =",
         "more findings than this and the check passes silently"),
    ],
    "outline_jaggy_segments": [
        ("fontbakery.checks.outline_jaggy_segments", "if abs(jag_angle) > JAG_ANGLE or jag_angle == 0",
         "angle between the reversed incoming tangent and the outgoing tangent in (0, JAG_ANGLE]: "
         "a spike where the outline nearly doubles back (an exact reversal, 0, is not reported; "
         "a zero-length handle gives a zero tangent and the join is skipped)"),
        ("fontbakery.checks.outline_settings", "JAG_ANGLE =", ""),
    ],
    "outline_semi_vertical": [
        ("fontbakery.checks.outline_semi_vertical", "close_but_not_on(angle, yExpected, 0.5)",
         "a line whose direction is within 0.5 degree of 0/90/180 but not on it"),
        ("fontbakery.checks.outline_semi_vertical", "not is_italic", "skipped for italics"),
    ],
    "outline_alignment_miss": [
        ("fontbakery.checks.outline_alignment_miss", "close_but_not_on(yExpected, node.y, ALIGNMENT_MISS_EPSILON)",
         "an on-curve y within the epsilon of 0, OS/2 sTypoAscender, sTypoDescender, sCapHeight and "
         "(one-letter lowercase glyph names only) sxHeight, but not on it"),
        ("fontbakery.checks.outline_settings", "ALIGNMENT_MISS_EPSILON =", ""),
        ("fontbakery.checks.outline_settings", "FALSE_POSITIVE_CUTOFF =",
         "more findings than this and the check passes silently"),
    ],
    "outline_short_segments": [
        ("fontbakery.checks.outline_short_segments", "math.isclose(seg.length, 0)",
         "a segment of (float) length 0 is always reported"),
        ("fontbakery.checks.outline_short_segments", "seg.length < SHORT_PATH_ABSOLUTE_EPSILON",
         "otherwise: shorter than the absolute epsilon ..."),
        ("fontbakery.checks.outline_short_segments", "or seg.length < SHORT_PATH_EPSILON * outline_length",
         "... or than this fraction of the contour's length ..."),
        ("fontbakery.checks.outline_short_segments", "and (prev_was_line or len(seg) > 2)",
         "... and the segment is a curve or follows a line"),
        ("fontbakery.checks.outline_settings", "SHORT_PATH_ABSOLUTE_EPSILON =", ""),
        ("fontbakery.checks.outline_settings", "SHORT_PATH_EPSILON =", ""),
        ("fontbakery.checks.outline_settings", "FALSE_POSITIVE_CUTOFF =",
         "more findings than this and the check passes silently"),
    ],
    "overlapping_path_segments": [
        ("fontbakery.checks.overlapping_path_segments", "if normal in seen or flipped in seen",
         "two segments of the glyph (any contours) with the same two end points, either way round; "
         "control points are ignored, partial overlaps are not seen"),
    ],
    "outline_direction": [
        ("fontbakery.checks.outline_direction", "and bb1.bottom <= bb2.bottom",
         "'outermost' = bounding box not inside another contour's box (non-strict: "
         "two contours with equal boxes hide each other)"),
        ("fontbakery.checks.outline_direction", "if path.direction == 1:",
         "only outermost contours, only counter-clockwise is reported; inner contours are not checked"),
        ("beziers.path", "flat = self.flatten()",
         "orientation = sign of the area of the flattened contour (a contour without area counts "
         "as counter-clockwise)"),
    ],
    "nested_components": [
        ("fontbakery.checks.nested_components", "if ttFont[\"glyf\"][comp.glyphName].isComposite():",
         "a composite glyph with a component that is itself composite (not an outline property)"),
    ],
}

WHY = {
    "outline_colinear_vectors":
        "fontbakery compares float angles of line-line joins with a tolerance; casteljau's "
        "collinear_points is exact collinearity and kink an exact angle test (--kink-angle), "
        "curves included. A fontbakery-only glyph usually has two lines a little off collinear "
        "(within the epsilon but beyond --kink-angle) or turns at the +-pi wrap; a casteljau-only "
        "glyph usually involves a curve.",
    "outline_jaggy_segments":
        "fontbakery's jaggy segment is a spike (the outline turns back by more than 180-14.3 "
        "degrees), while a kink is a join that is almost, but not exactly, smooth: the two "
        "definitions look at opposite ends of the turning angle, so little overlap is expected; "
        "the mapping (--map) may be better as cusp.",
    "outline_semi_vertical":
        "no exact counterpart: a near-but-not-exactly axis-aligned line is a design heuristic, "
        "float-only.",
    "outline_alignment_miss":
        "no exact counterpart: points near, not on, vertical metrics; float-only.",
    "outline_short_segments":
        "fontbakery flags segments shorter than a length threshold; casteljau's "
        "zero_length_segment is exact zero length, so fontbakery-only glyphs are expected "
        "(short but not zero). A casteljau-only glyph would be a zero-length segment fontbakery "
        "does not see (beziers drops a closing segment whose end equals the start) or the cutoff.",
    "overlapping_path_segments":
        "fontbakery matches end points only (two different curves between the same two points "
        "count; a partial overlap does not); casteljau finds coincident pieces exactly.",
    "outline_direction":
        "fontbakery checks only the outermost contours (by bounding box) and only reports "
        "counter-clockwise ones; the orientation is the sign of a flattened area. casteljau checks "
        "every contour against --direction exactly. Single-point contours: fontbakery reports each "
        "as 'a path with no bounds' and also, by construction, as a counter-clockwise outer contour; "
        "such spurious items are subtracted before comparing (see the note).",
    "nested_components":
        "no counterpart: casteljau lint checks outlines, not component structure.",
}

# Checks that pass silently above FALSE_POSITIVE_CUTOFF findings.
CUTOFF_CHECKS = {"outline_alignment_miss", "outline_colinear_vectors", "outline_short_segments"}

COORD_RE = re.compile(r"<(-?[0-9.]+(?:e[-+]?[0-9]+)?),(-?[0-9.]+(?:e[-+]?[0-9]+)?)>")
XY_RE = re.compile(r"X=(-?[0-9.]+),Y=(-?[0-9.]+)")


def die(msg, code=2):
    print(f"compare_outline_checks: {msg}", file=sys.stderr)
    sys.exit(code)


# ---------------------------------------------------------------- casteljau


def find_casteljau(explicit):
    if explicit:
        if os.path.isfile(explicit) and os.access(explicit, os.X_OK):
            return explicit
        die(f"casteljau binary not found or not executable: {explicit}")
    found = shutil.which("casteljau")
    if found:
        return found
    repo = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    for profile in ("release", "debug"):
        cand = os.path.join(repo, "target", profile, "casteljau")
        if os.path.isfile(cand) and os.access(cand, os.X_OK):
            return cand
    die("casteljau binary not found (give --casteljau PATH, put it on PATH, "
        "or build target/release/casteljau)")


def parse_jsonl(text, source):
    records = []
    for n, line in enumerate(text.splitlines(), 1):
        line = line.strip()
        if not line:
            continue
        try:
            rec = json.loads(line)
        except json.JSONDecodeError as e:
            die(f"{source}:{n}: not JSON ({e})")
        if not isinstance(rec, dict) or "kind" not in rec:
            die(f"{source}:{n}: not a lint finding (no 'kind')")
        records.append(rec)
    return records


def this_font(records, font, source):
    """The findings for font (precomputed output may hold several files or
    another spelling of the path)."""
    files = {r.get("file") for r in records}
    if font in files:
        return [r for r in records if r.get("file") == font]
    base = os.path.basename(font)
    same = [r for r in records if os.path.basename(str(r.get("file"))) == base]
    if same:
        return same
    if len(files) > 1:
        die(f"{source} holds findings for {sorted(map(str, files))}, none is {font}")
    return records


def load_casteljau(args):
    """Returns (records, description, seconds)."""
    if args.casteljau_json:
        try:
            with open(args.casteljau_json, encoding="utf-8") as f:
                text = f.read()
        except OSError as e:
            die(f"cannot read {args.casteljau_json}: {e}")
        records = this_font(parse_jsonl(text, args.casteljau_json), args.font, args.casteljau_json)
        return records, f"precomputed `{args.casteljau_json}`", None
    binary = find_casteljau(args.casteljau)
    cmd = [binary, "lint", "--json"] + shlex.split(args.lint_args or "") + [args.font]
    t0 = time.monotonic()
    try:
        proc = subprocess.run(cmd, capture_output=True, text=True)
    except OSError as e:
        die(f"cannot run {binary}: {e}")
    secs = time.monotonic() - t0
    if proc.returncode not in (0, 1):
        die(f"`{' '.join(map(shlex.quote, cmd))}` exited with {proc.returncode}:\n{proc.stderr.strip()}")
    records = this_font(parse_jsonl(proc.stdout, "casteljau lint output"), args.font, "casteljau lint output")
    return records, "`" + " ".join(map(shlex.quote, cmd)) + "`", secs


# --------------------------------------------------------------- fontbakery


class FontbakeryUnavailable(Exception):
    pass


def source_quote(modname, needle):
    """'path:line' and the stripped line of the first line holding needle."""
    import importlib
    try:
        mod = importlib.import_module(modname)
        path = mod.__file__
        with open(path, encoding="utf-8") as f:
            lines = f.read().splitlines()
    except Exception:  # noqa: BLE001 - a missing quote must not stop the report
        return None, None
    top = modname.split(".")[0]
    rel = path[path.rfind(os.sep + top + os.sep) + 1:] if (os.sep + top + os.sep) in path else path
    for i, line in enumerate(lines, 1):
        if needle in line:
            return f"{rel}:{i}", line.strip()
    return f"{rel}", None


def status_name(status):
    name = getattr(status, "name", None)
    if isinstance(name, str):
        return name
    return str(status).replace("<Status ", "").rstrip(">")


def split_items(check_id, text):
    """The bullet items of a fontbakery finding list."""
    start = text.find("\t* ")
    if start < 0:
        return []
    body = text[start + 3:]
    items = [s.strip() for s in re.split(r"\n+\t\* ", body) if s.strip()]
    if check_id == "nested_components":
        # pretty_print_list joins the last two names with " and ".
        out = []
        for it in items:
            out.extend(t for t in it.split(" and ") if t)
        items = out
    return items


def item_glyph(item, names):
    """Longest glyph name that the item starts with (then ' ', ':' or end)."""
    best = None
    for m in re.finditer(r"[ :]|$", item):
        cand = item[: m.start()]
        if cand in names:
            best = cand
    return best


def item_coords(item):
    xy = XY_RE.findall(item)
    if xy:
        return [[float(x), float(y)] for x, y in xy]
    return [[float(x), float(y)] for x, y in COORD_RE.findall(item)]


def run_fontbakery(font, check_ids, uncap):
    """Runs the checks; returns (version, {check_id: result}, glyph_order, composites)."""
    warnings.simplefilter("ignore")
    try:
        import importlib
        import importlib.metadata
        from fontbakery.checkrunner import CheckRunner
        from fontbakery.configuration import Configuration
        from fontbakery.fonts_profile import (ITERARGS, checks_by_id, load_all_checks,
                                              load_checks_from_module, setup_context)
        from fontbakery.profile import Profile, Section
        import fontbakery.checks.conditions  # noqa: F401 - registers outlines_dict & co.
    except Exception as e:  # noqa: BLE001
        raise FontbakeryUnavailable(f"fontbakery (>= 0.13) is not importable by {sys.executable}: {e}")
    try:
        version = importlib.metadata.version("fontbakery")
    except Exception:  # noqa: BLE001
        version = "unknown"

    modules = {}
    for cid in check_ids:
        try:
            modules[cid] = importlib.import_module(f"fontbakery.checks.{cid}")
            load_checks_from_module(modules[cid])
        except ImportError:
            pass
    if any(c not in checks_by_id for c in check_ids):
        try:
            load_all_checks()
        except Exception:  # noqa: BLE001
            pass
    available = [c for c in check_ids if c in checks_by_id]
    results = {c: {"available": False} for c in check_ids if c not in checks_by_id}

    try:
        context = setup_context([font])
    except Exception as e:  # noqa: BLE001
        raise FontbakeryUnavailable(f"fontbakery cannot open {font}: {e}")
    fonts = [t for t in context.testables if hasattr(t, "ttFont")]
    if not fonts:
        raise FontbakeryUnavailable(f"fontbakery does not take {font} as a font")
    context.testables[:] = fonts[:1]
    ttfont = fonts[0].ttFont
    glyph_order = ttfont.getGlyphOrder()
    composites = set()
    if "glyf" in ttfont:
        glyf = ttfont["glyf"]
        composites = {g for g in glyph_order if glyf[g].isComposite()}

    if not available:
        return version, results, glyph_order, composites

    profile = Profile(name="outline-compare", iterargs=ITERARGS,
                      sections=[Section(name="Outline checks", checks=[checks_by_id[c] for c in available])])
    runner = CheckRunner(profile, context, Configuration(explicit_checks=available, full_lists=True))
    names = set(glyph_order)

    def run_one(identity):
        t0 = time.monotonic()
        res = runner._run_check(identity)  # pylint: disable=protected-access
        return res.results, time.monotonic() - t0

    def errored(subresults):
        return any(status_name(s.status) == "ERROR" for s in subresults)

    for identity in runner.order:
        cid = identity.check.id
        subresults, secs = run_one(identity)
        entry = {"available": True, "seconds": secs, "capped": False, "notes": []}
        if errored(subresults):
            # Retry once on freshly built outlines (see the note on CHECKS).
            first_error = next(str(getattr(s.message, "message", s.message)) for s in subresults
                               if status_name(s.status) == "ERROR")
            fonts[0].__dict__.pop("outlines_dict", None)
            subresults, secs2 = run_one(identity)
            entry["seconds"] += secs2
            entry["notes"].append("fontbakery crashed on the outlines shared with the checks run before it "
                                  + ("and again on fresh ones" if errored(subresults) else
                                     "and passed on fresh ones (results below)")
                                  + ": " + first_error.strip().splitlines()[0])
        statuses = [(status_name(s.status), getattr(s.message, "code", None), str(getattr(s.message, "message", s.message)))
                    for s in subresults]
        entry["statuses"] = statuses
        cutoff_hit = any(st == "PASS" and txt.startswith("So many") for st, _, txt in statuses)
        if cutoff_hit and uncap and cid in CUTOFF_CHECKS and hasattr(modules.get(cid), "FALSE_POSITIVE_CUTOFF"):
            old = modules[cid].FALSE_POSITIVE_CUTOFF
            modules[cid].FALSE_POSITIVE_CUTOFF = float("inf")
            try:
                subresults, secs2 = run_one(identity)
            finally:
                modules[cid].FALSE_POSITIVE_CUTOFF = old
            entry["capped"] = True
            entry["cutoff"] = old
            entry["seconds"] += secs2
        elif cutoff_hit:
            entry["capped"] = True
        items, notes, unparsed = [], entry["notes"], []
        for s in subresults:
            st = status_name(s.status)
            code = getattr(s.message, "code", None)
            txt = str(getattr(s.message, "message", s.message))
            if st in ("SKIP", "ERROR", "FATAL"):
                entry.setdefault("skipped" if st == "SKIP" else "error", []).append(txt)
                continue
            its = split_items(cid, txt) if st in ("WARN", "FAIL") else []
            if not its:
                if st in ("WARN", "FAIL", "INFO"):
                    notes.append(f"{st} {code}: {txt}")
                continue
            for it in its:
                g = item_glyph(it, names)
                if g is None:
                    unparsed.append(it)
                    continue
                items.append({"glyph": g, "text": it, "coords": item_coords(it)})
        entry.update(items=items, notes=notes, unparsed=unparsed)
        results[cid] = entry
    return version, results, glyph_order, composites


def fontbakery_glyphs(cid, entry):
    """Glyph -> list of items counted for the comparison; plus excluded glyphs (direction)."""
    per = defaultdict(list)
    for it in entry.get("items", []):
        per[it["glyph"]].append(it)
    excluded = {}
    if cid == "outline_direction":
        # Every single-point contour gives one 'no bounds' item AND one ccw-outer
        # item (its empty area has sign +1 and nothing contains it), so the real
        # ccw outer contours of a glyph are (ccw items - no-bounds items).
        kept = {}
        for g, its in per.items():
            ccw = [i for i in its if "counter-clockwise" in i["text"]]
            nob = [i for i in its if "no bounds" in i["text"]]
            if len(ccw) > len(nob):
                kept[g] = ccw
            else:
                excluded[g] = its
        per = kept
    return dict(per), excluded


# ----------------------------------------------------------------- report


def fmt_names(names, n):
    shown = ", ".join(f"`{g}`" for g in names[:n])
    return shown + (", ..." if len(names) > n else "") if names else "-"


def cj_glyph(rec, glyph_order):
    gid = rec.get("glyph_id")
    if isinstance(gid, int) and glyph_order and 0 <= gid < len(glyph_order):
        return glyph_order[gid]
    return rec.get("glyph") or rec.get("element") or "?"


def fmt_cj(rec):
    at = rec.get("at_float") or []
    where = " at " + ", ".join(f"({x:g}, {y:g})" for x, y in at[:3]) if at else ""
    rnd = " [rounding]" if rec.get("rounding") else ""
    loc = []
    for key in ("contour", "index", "point"):
        if key in rec:
            loc.append(f"{key} {rec[key]}")
    return f"{rec.get('kind')}{rnd}{where}{' (' + ', '.join(loc) + ')' if loc else ''}: {rec.get('message', '')}"


def shorten(s, n=160):
    s = " ".join(s.split())
    return s if len(s) <= n else s[: n - 3] + "..."


def main():
    ap = argparse.ArgumentParser(description="Compare fontbakery's outline checks with casteljau lint on one font.")
    ap.add_argument("font")
    ap.add_argument("--casteljau", metavar="PATH", help="the casteljau binary")
    ap.add_argument("--casteljau-json", metavar="FILE", help=argparse.SUPPRESS)
    ap.add_argument("--lint-args", metavar="ARGS", help="extra arguments for casteljau lint (one string)")
    ap.add_argument("--map", action="append", default=[], metavar="CHECK=KIND,KIND",
                    help="compare CHECK with these lint kinds (empty: float-only)")
    ap.add_argument("--examples", type=int, default=5, help="example glyph names per cell (5)")
    ap.add_argument("--json-out", metavar="FILE", help="write both sides' per-glyph findings as JSON")
    ap.add_argument("--no-uncap", action="store_true",
                    help="keep fontbakery's verdict when a check passes because of its false-positive cutoff")
    args = ap.parse_args()

    mapping = dict(CHECKS)
    for m in args.map:
        cid, _, kinds = m.partition("=")
        if cid not in mapping:
            die(f"--map: unknown check {cid} (one of {', '.join(mapping)})")
        mapping[cid] = [k for k in kinds.split(",") if k]
    check_ids = [c for c, _ in CHECKS]

    if not os.path.isfile(args.font):
        die(f"no such font: {args.font}")

    # casteljau first: a missing binary is reported before the slow part.
    records, cj_desc, cj_secs = load_casteljau(args)

    t0 = time.monotonic()
    fb_error = None
    try:
        fb_version, fb, glyph_order, composites = run_fontbakery(args.font, check_ids, not args.no_uncap)
    except FontbakeryUnavailable as e:
        fb_error, fb_version, fb, glyph_order, composites = str(e), None, {}, [], set()
        try:
            from fontTools.ttLib import TTFont
            tt = TTFont(args.font, lazy=True)
            glyph_order = tt.getGlyphOrder()
        except Exception:  # noqa: BLE001
            pass
    fb_secs = time.monotonic() - t0

    cj_by_kind = defaultdict(lambda: defaultdict(list))
    for rec in records:
        cj_by_kind[rec["kind"]][cj_glyph(rec, glyph_order)].append(rec)
    order_ix = {g: i for i, g in enumerate(glyph_order)}

    def in_order(gs):
        return sorted(gs, key=lambda g: (order_ix.get(g, len(order_ix)), g))

    out = []
    w = out.append
    w(f"# Outline checks: fontbakery vs casteljau lint: `{args.font}`")
    w("")
    w(f"- fontbakery: {('version ' + fb_version) if fb_version else 'unavailable'}"
      f"{'' if fb_error else f', {fb_secs:.1f} s (checks called in-process through its CheckRunner, full lists)'}")
    w(f"- casteljau: {cj_desc}, {len(records)} findings"
      f"{f', {cj_secs:.1f} s' if cj_secs is not None else ''}")
    if glyph_order:
        w(f"- glyphs: {len(glyph_order)}" + (f" ({len(composites)} composite; fontbakery decomposes "
                                               f"composites, so a composite repeats its components' findings)"
                                               if composites else ""))
    w("")

    if fb_error:
        w(f"**fontbakery is unavailable**: {fb_error}")
        w("")
        w("casteljau's findings only:")
        w("")
        w("| kind | findings | glyphs | rounding |")
        w("|---|---:|---:|---:|")
        for kind in sorted(cj_by_kind):
            per = cj_by_kind[kind]
            n = sum(len(v) for v in per.values())
            r = sum(1 for v in per.values() for x in v if x.get("rounding"))
            w(f"| {kind} | {n} | {len(per)} | {r} |")
        print("\n".join(out))
        return 0

    # Summary.
    w("## Summary")
    w("")
    w("| fontbakery check | fontbakery result | fb items | fb glyphs | casteljau kinds | cj glyphs | both | fb only | cj only |")
    w("|---|---|---:|---:|---|---:|---:|---:|---:|")
    sections = []
    dump = {"font": args.font, "fontbakery_version": fb_version, "casteljau": cj_desc, "checks": {}}
    for cid in check_ids:
        entry = fb.get(cid, {"available": False})
        kinds = mapping[cid]
        cj = defaultdict(list)
        for k in kinds:
            for g, recs in cj_by_kind.get(k, {}).items():
                cj[g].extend(recs)
        kinds_txt = ", ".join(kinds) if kinds else "none"
        if not entry.get("available"):
            w(f"| `{cid}` | not in this fontbakery | - | - | {kinds_txt} | {len(cj) if kinds else '-'} | - | - | - |")
            sections.append((cid, entry, None, None, cj, kinds))
            continue
        if entry.get("skipped") or entry.get("error"):
            why = "; ".join(t.strip().splitlines()[0] for t in entry.get("skipped", []) + entry.get("error", []))
            label = "SKIP" if entry.get("skipped") else "ERROR"
            w(f"| `{cid}` | {label}: {shorten(why, 80)} | - | - | {kinds_txt} | {len(cj) if kinds else '-'} | - | - | - |")
            sections.append((cid, entry, None, None, cj, kinds))
            continue
        fbg, excluded = fontbakery_glyphs(cid, entry)
        worst = [st for st, _, _ in entry["statuses"]]
        verdict = "FAIL" if "FAIL" in worst else "WARN" if "WARN" in worst else (worst[-1] if worst else "PASS")
        if entry.get("capped"):
            verdict = (f"PASS by cutoff (> {entry.get('cutoff', '?')}); uncapped list used"
                       if not args.no_uncap else "PASS by cutoff")
        both = set(fbg) & set(cj)
        if kinds:
            w(f"| `{cid}` | {verdict} | {len(entry['items'])} | {len(fbg)} | {kinds_txt} | {len(cj)} | "
              f"{len(both)} | {len(set(fbg) - set(cj))} | {len(set(cj) - set(fbg))} |")
        else:
            w(f"| `{cid}` | {verdict} | {len(entry['items'])} | {len(fbg)} | {kinds_txt} | - | - | {len(fbg)} | - |")
        sections.append((cid, entry, fbg, excluded, cj, kinds))
        dump["checks"][cid] = {
            "casteljau_kinds": kinds, "fontbakery_result": verdict, "seconds": round(entry["seconds"], 3),
            "fontbakery": {g: [{"text": i["text"], "coords": i["coords"]} for i in its] for g, its in fbg.items()},
            "fontbakery_excluded": {g: [i["text"] for i in its] for g, its in excluded.items()},
            "casteljau": {g: recs for g, recs in cj.items()},
        }
    mapped = {k for ks in mapping.values() for k in ks}
    other = {k: v for k, v in cj_by_kind.items() if k not in mapped}
    w("")

    for cid, entry, fbg, excluded, cj, kinds in sections:
        w(f"## `{cid}` vs {', '.join(f'`{k}`' for k in kinds) if kinds else 'no casteljau kind'}")
        w("")
        if not entry.get("available"):
            w(f"fontbakery {fb_version} has no check `{cid}`; casteljau: {len(cj)} glyphs.")
            w("")
            continue
        if fbg is None:
            why = "; ".join(entry.get("skipped", []) + entry.get("error", []))
            w(f"fontbakery did not run it ({shorten(why, 300)}); casteljau: {len(cj)} glyphs"
              + (f" ({fmt_names(in_order(cj), args.examples)})." if cj else "."))
            w("")
            continue
        w(f"fontbakery's definition ({entry['seconds']:.2f} s):")
        w("")
        for mod, needle, meaning in DEFINITIONS.get(cid, []):
            where, line = source_quote(mod, needle)
            if line is None:
                w(f"- {where or mod}: line with `{needle}` not found in this version")
            else:
                w(f"- {where}: `{line}`" + (f" ({meaning})" if meaning else ""))
        w("")
        if entry.get("capped") and not args.no_uncap:
            w(f"fontbakery itself passes this check because it found more than {entry.get('cutoff')} items; "
              "the lists below come from a second run with the cutoff lifted.")
            w("")
        fset, cset = set(fbg), set(cj)
        rows = []
        if kinds:
            rows.append(("both", in_order(fset & cset)))
            rows.append(("fontbakery only", in_order(fset - cset)))
            rows.append(("casteljau only", in_order(cset - fset)))
        else:
            rows.append(("fontbakery (no casteljau counterpart)", in_order(fset)))
        w("| | glyphs | examples |")
        w("|---|---:|---|")
        for label, gs in rows:
            extra = []
            nc = sum(1 for g in gs if g in composites)
            if nc:
                extra.append(f"{nc} composite")
            if label == "casteljau only":
                nr = sum(1 for g in gs if all(r.get("rounding") for r in cj[g]))
                if nr:
                    extra.append(f"{nr} rounding-only")
            w(f"| {label} | {len(gs)}{' (' + ', '.join(extra) + ')' if extra else ''} | {fmt_names(gs, args.examples)} |")
        w("")
        detail = []
        for label, gs in rows:
            if not gs:
                continue
            g = gs[0]
            if g in fbg:
                detail.append(f"- {label}, `{g}`, fontbakery: {shorten(fbg[g][0]['text'])}"
                              + (f" (+{len(fbg[g]) - 1} more)" if len(fbg[g]) > 1 else ""))
            if g in cj:
                detail.append(f"- {label}, `{g}`, casteljau: {shorten(fmt_cj(cj[g][0]))}"
                              + (f" (+{len(cj[g]) - 1} more)" if len(cj[g]) > 1 else ""))
        if detail:
            w("First example of each row:")
            w("")
            out.extend(detail)
            w("")
        if excluded:
            w(f"Note: {len(excluded)} glyphs are flagged by fontbakery only through single-point contours "
              f"('no bounds' + the spurious counter-clockwise item each one produces) and are left out "
              f"above: {fmt_names(in_order(excluded), args.examples)}.")
            w("")
        for note in entry.get("notes", []):
            w(f"Note: {shorten(note, 300)}")
            w("")
        if entry.get("unparsed"):
            w(f"{len(entry['unparsed'])} fontbakery items without a recognisable glyph name, e.g. "
              f"`{shorten(entry['unparsed'][0], 120)}`.")
            w("")
        w(f"Why they differ: {WHY.get(cid, '')}")
        w("")

    if other:
        w("## casteljau findings with no fontbakery outline check")
        w("")
        w("| kind | findings | glyphs | rounding | examples |")
        w("|---|---:|---:|---:|---|")
        for kind in sorted(other):
            per = other[kind]
            n = sum(len(v) for v in per.values())
            r = sum(1 for v in per.values() for x in v if x.get("rounding"))
            w(f"| {kind} | {n} | {len(per)} | {r} | {fmt_names(in_order(per), args.examples)} |")
        w("")
        dump["casteljau_other"] = {k: dict(v) for k, v in other.items()}

    unknown = Counter(rec.get("glyph") for rec in records
                      if isinstance(rec.get("glyph_id"), int) and glyph_order
                      and 0 <= rec["glyph_id"] < len(glyph_order)
                      and rec.get("glyph") not in (None, glyph_order[rec["glyph_id"]]))
    if unknown:
        w(f"Note: {sum(unknown.values())} casteljau findings name a glyph differently from fontTools' "
          f"glyph order for the same glyph_id (the glyph_id was used), e.g. `{next(iter(unknown))}`.")
        w("")

    print("\n".join(out))
    if args.json_out:
        with open(args.json_out, "w", encoding="utf-8") as f:
            json.dump(dump, f, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main())
