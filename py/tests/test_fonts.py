"""Fonts: lint, the fontbakery profile, overlap removal for fontTools and ufo2ft, exact glyph
recording."""

import io
import os
import subprocess
import sys
from fractions import Fraction

import pytest
from fontTools.ttLib import TTFont

import casteljau
from casteljau import CasteljauError, Shape
from casteljau.pens import ExactPen



def test_lint_findings_of_a_font(tuffy):
    findings = casteljau.lint(tuffy, glyphs=["peseta", "aogonekalt", "exclam"])
    kinds = {(f.glyph, f.kind) for f in findings if not f.rounding}
    assert ("peseta", "overlap") in kinds and ("aogonekalt", "overlap") in kinds
    overlap = next(f for f in findings if f.glyph == "peseta" and f.kind == "overlap")
    assert overlap.severity == "warning" and overlap.contours == (0, 1)
    assert "cross" in overlap.message and len(overlap.at) == 2
    kink = next(f for f in findings if f.kind == "kink")
    assert kink.glyph == "exclam" and kink.segment is not None and kink.point is not None


def test_lint_of_a_ttfont_in_memory_and_of_a_glyph_set(tuffy):
    font = TTFont(tuffy)
    from_font = casteljau.lint(font, glyphs=["peseta"], kinds=["overlap"])
    assert [f.kind for f in from_font] == ["overlap"]
    # a glyph set drawn exactly, outer contours clockwise as TrueType stores them
    from_set = casteljau.lint(font.getGlyphSet(), glyphs=["peseta"], kinds=["overlap"], orientation="cw")
    assert [(f.kind, f.at) for f in from_set] == [(f.kind, f.at) for f in from_font]


def test_lint_refuses_unknown_kinds(tuffy):
    with pytest.raises(CasteljauError, match="unknown lint kind"):
        casteljau.lint(tuffy, kinds=["wobbly"])


def test_exact_pen_records_implied_points_exactly(tuffy):
    font = TTFont(tuffy)
    gs = font.getGlyphSet()
    pen = ExactPen(gs)
    gs["a"].draw(pen)
    pts = [p for _, ps in pen.path for p in ps]
    assert any(isinstance(c, Fraction) and c.denominator == 2 for p in pts for c in p)
    assert Shape.from_glyph(gs, "a") == pen.shape()
    # the same outline as the font reader's own exact reading
    assert Shape.from_glyph(gs, "a").simplify().area == Shape(casteljau._core.font_glyph(open(tuffy, "rb").read(), "a")).simplify().area


def test_fontbakery_profile_excludes_the_float_checks():
    from fontbakery.fonts_profile import profile_factory

    import casteljau.fontbakery as profile

    p = profile_factory(profile)
    ids = {c.id for s in p.sections for c in s.checks}
    assert {"outline_direction", "outline_colinear_vectors", "overlapping_path_segments"}.isdisjoint(ids)
    assert {"casteljau/direction", "casteljau/overlaps", "casteljau/self_intersections", "casteljau/bbox"} <= ids


def test_fontbakery_runs_the_exact_checks(tuffy):
    run = subprocess.run(
        [sys.executable, "-m", "fontbakery", "check-profile", "casteljau.fontbakery", tuffy, "-c", "casteljau/direction", "-c", "casteljau/overlaps"],
        capture_output=True,
        text=True,
        timeout=300,
    )
    out = run.stdout
    assert "casteljau/overlaps" in out and "peseta" in out
    assert "FAIL: 1" in out and "WARN: 1" in out and "ERROR: 0" in out


def test_remove_overlaps_on_a_ttfont(tuffy):
    import casteljau.fonttools

    font = TTFont(tuffy)
    results = casteljau.fonttools.removeOverlaps(font, ["peseta", "aogonekalt"])
    assert {r.name: r.status for r in results} == {"peseta": "rewritten", "aogonekalt": "rewritten"}
    buf = io.BytesIO()
    font.save(buf)
    assert not [f for f in casteljau.lint(buf.getvalue(), glyphs=["peseta", "aogonekalt"], kinds=["overlap"]) if not f.rounding]


def test_remove_overlaps_names_the_problem(tuffy):
    import casteljau.fonttools

    font = TTFont(tuffy)
    try:
        casteljau.fonttools.removeOverlaps(font, ["peseta"])
    except casteljau.fonttools.RemoveOverlapsError as e:
        assert isinstance(e, CasteljauError) and str(e)
    # the signature is fontTools'
    import inspect

    from fontTools.ttLib.removeOverlaps import removeOverlaps as theirs

    ours = inspect.signature(casteljau.fonttools.removeOverlaps).parameters
    assert list(inspect.signature(theirs).parameters)[:4] == list(ours)[:4]
    assert "removeUnusedSubroutines" in ours


def _overlapping_ufo():
    import ufoLib2

    ufo = ufoLib2.Font()
    ufo.info.familyName, ufo.info.styleName, ufo.info.unitsPerEm = "Overlap", "Regular", 1000
    ufo.info.ascender, ufo.info.descender, ufo.info.xHeight, ufo.info.capHeight = 800, -200, 500, 700
    g = ufo.newGlyph("square")
    g.width, g.unicodes = 600, [0x41]
    pen = g.getPen()
    for x, y in ((100, 100), (300, 300)):
        pen.moveTo((x, y)); pen.lineTo((x, y + 300)); pen.lineTo((x + 300, y + 300)); pen.lineTo((x + 300, y)); pen.closePath()
    ufo.newGlyph(".notdef").width = 500
    ufo.glyphOrder = [".notdef", "square"]
    return ufo


def test_ufo2ft_selects_the_filter_by_its_lib_key():
    import ufo2ft

    from casteljau.filters.removeOverlaps import RemoveOverlapsFilter

    ufo = _overlapping_ufo()
    ufo.lib["com.github.googlei18n.ufo2ft.filters"] = [{"name": "RemoveOverlaps", "namespace": "casteljau.filters", "pre": True}]
    from ufo2ft.filters import loadFilters

    pre, post = loadFilters(ufo)
    assert [type(f) for f in pre] == [RemoveOverlapsFilter]
    font = ufo2ft.compileTTF(ufo)  # runs the filter (an uncertified glyph is left as it is)
    assert "square" in font.getGlyphOrder()


def test_ufo2ft_filter_removes_the_overlap():
    from casteljau.filters.removeOverlaps import RemoveOverlapsFilter

    ufo = _overlapping_ufo()
    f = RemoveOverlapsFilter(pre=True, ignoreErrors=False)
    modified = f(ufo)
    assert modified == {"square"}
    assert len(ufo["square"].contours) == 1
    assert not casteljau.lint({"square": ufo["square"]}, kinds=["overlap"])


def test_fontmake_builds_a_font_lint_finds_clean(tmp_path):
    ufo = _overlapping_ufo()
    src = tmp_path / "Overlap.ufo"
    ufo.save(src)
    out = tmp_path / "Overlap.ttf"
    run = subprocess.run(
        [sys.executable, "-m", "fontmake", "-u", str(src), "-o", "ttf", "--keep-overlaps", "--output-path", str(out),
         "--filter", "casteljau.filters.removeOverlaps::RemoveOverlapsFilter(pre=True, ignoreErrors=False)"],
        capture_output=True, text=True, timeout=300,
    )
    if run.returncode != 0:
        raise CasteljauError(run.stderr.strip().splitlines()[-1])
    assert not [f for f in casteljau.lint(str(out)) if f.fails]


def test_install_replaces_fonttools_remove_overlaps():
    import fontTools.ttLib.removeOverlaps as ro

    import casteljau.fonttools

    saved = ro.removeOverlaps
    try:
        casteljau.fonttools.install()
        assert ro.removeOverlaps is casteljau.fonttools.removeOverlaps
    finally:
        ro.removeOverlaps = saved
