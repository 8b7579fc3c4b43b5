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
    """Overlapping squares, overlapping cubic circles (PostScript direction), and composites:
    one whose components overlap, one whose components are apart."""
    import ufoLib2
    from ufoLib2.objects import Component

    ufo = ufoLib2.Font()
    ufo.info.familyName, ufo.info.styleName, ufo.info.unitsPerEm = "Overlap", "Regular", 1000
    ufo.info.ascender, ufo.info.descender, ufo.info.xHeight, ufo.info.capHeight = 800, -200, 500, 700
    g = ufo.newGlyph("square")
    g.width, g.unicodes = 600, [0x41]
    pen = g.getPen()
    for x, y in ((100, 100), (300, 300)):
        pen.moveTo((x, y)); pen.lineTo((x, y + 300)); pen.lineTo((x + 300, y + 300)); pen.lineTo((x + 300, y)); pen.closePath()
    g = ufo.newGlyph("rings")
    g.width, g.unicodes = 700, [0x4F]
    pen = g.getPen()
    for cx in (250, 400):
        cy, r, k = 350, 200, 110
        pen.moveTo((cx + r, cy))
        pen.curveTo((cx + r, cy + k), (cx + k, cy + r), (cx, cy + r))
        pen.curveTo((cx - k, cy + r), (cx - r, cy + k), (cx - r, cy))
        pen.curveTo((cx - r, cy - k), (cx - k, cy - r), (cx, cy - r))
        pen.curveTo((cx + k, cy - r), (cx + r, cy - k), (cx + r, cy))
        pen.closePath()
    for name, pts in (("bar", ((250, 0), (350, 0), (350, 700), (250, 700))), ("acute", ((250, 650), (350, 650), (450, 800), (350, 800)))):
        g = ufo.newGlyph(name)
        g.width = 600
        pen = g.getPen()
        pen.moveTo(pts[0]); pen.lineTo(pts[1]); pen.lineTo(pts[2]); pen.lineTo(pts[3]); pen.closePath()
    g = ufo.newGlyph("baracute")  # the accent overlaps the bar
    g.width, g.unicodes = 600, [0x100]
    g.components += [Component("bar"), Component("acute")]
    g = ufo.newGlyph("barhigh")  # the accent stands apart
    g.width, g.unicodes = 600, [0x101]
    g.components += [Component("bar"), Component("acute", transformation=(1, 0, 0, 1, 0, 300))]
    ufo.newGlyph(".notdef").width = 500
    ufo.glyphOrder = [".notdef", "square", "rings", "bar", "acute", "baracute", "barhigh"]
    return ufo


def _check_built_font(path):
    """Every outline lint-clean; composites decomposed only where their components overlap."""
    assert [str(f) for f in casteljau.lint(str(path))] == []
    glyf = TTFont(str(path))["glyf"]
    assert [c.glyphName for c in glyf["barhigh"].components] == ["bar", "acute"]
    assert not glyf["baracute"].isComposite() and glyf["baracute"].numberOfContours == 1
    assert glyf["square"].numberOfContours == 1 and glyf["rings"].numberOfContours == 1


def _fontmake(src, out, *extra):
    run = subprocess.run(
        [sys.executable, "-m", "fontmake", "-u", str(src), "-o", "ttf", "--keep-overlaps", "--output-path", str(out), *extra],
        capture_output=True, text=True, timeout=300,
    )
    if run.returncode != 0:
        raise CasteljauError(run.stderr.strip().splitlines()[-1])


def test_ufo2ft_selects_the_filter_by_its_lib_key():
    from ufo2ft.filters import loadFilters

    from casteljau.filters.removeOverlaps import RemoveOverlapsFilter

    ufo = _overlapping_ufo()
    ufo.lib["com.github.googlei18n.ufo2ft.filters"] = [{"name": "RemoveOverlaps", "namespace": "casteljau.filters", "pre": True}]
    pre, post = loadFilters(ufo)
    assert [type(f) for f in pre] == [RemoveOverlapsFilter] and not post


def test_ufo2ft_filter_removes_the_overlap():
    from casteljau.filters.removeOverlaps import RemoveOverlapsFilter

    ufo = _overlapping_ufo()
    f = RemoveOverlapsFilter(pre=True, ignoreErrors=False)
    modified = f(ufo)
    assert modified == {"square", "rings", "baracute"}
    assert len(ufo["square"].contours) == 1 and len(ufo["rings"].contours) == 1
    # cubic outlines stay cubic (the filter runs before cu2qu)
    assert {p.segmentType for c in ufo["rings"].contours for p in c} == {None, "curve"}
    assert [c.baseGlyph for c in ufo["barhigh"].components] == ["bar", "acute"]
    assert not casteljau.lint({"square": ufo["square"], "rings": ufo["rings"]}, kinds=["overlap"])


def test_ufo2ft_filter_keeps_a_quadratic_glyph_quadratic():
    import ufoLib2

    from casteljau.filters.removeOverlaps import RemoveOverlapsFilter

    ufo = ufoLib2.Font()
    g = ufo.newGlyph("rings")
    pen = g.getPen()
    for cx in (250, 400):  # two overlapping TrueType rings, on-curve points at the extrema
        pen.moveTo((cx + 200, 350))
        pen.qCurveTo((cx + 200, 550), (cx, 550))
        pen.qCurveTo((cx - 200, 550), (cx - 200, 350))
        pen.qCurveTo((cx - 200, 150), (cx, 150))
        pen.qCurveTo((cx + 200, 150), (cx + 200, 350))
        pen.closePath()
    assert RemoveOverlapsFilter(pre=True, ignoreErrors=False)(ufo) == {"rings"}
    (contour,) = g.contours
    assert {p.segmentType for p in contour} == {None, "qcurve"}
    assert casteljau.lint({"rings": g}) == []


def test_fontmake_with_the_filter_option_builds_a_lint_clean_font(tmp_path):
    src = tmp_path / "Overlap.ufo"
    _overlapping_ufo().save(src)
    out = tmp_path / "Overlap.ttf"
    _fontmake(src, out, "--filter", "casteljau.filters.removeOverlaps::RemoveOverlapsFilter(pre=True)")
    _check_built_font(out)


def test_fontmake_with_the_ufo_lib_key_builds_a_lint_clean_font(tmp_path):
    ufo = _overlapping_ufo()
    ufo.lib["com.github.googlei18n.ufo2ft.filters"] = [{"name": "RemoveOverlaps", "namespace": "casteljau.filters", "pre": True}]
    src = tmp_path / "Overlap.ufo"
    ufo.save(src)
    out = tmp_path / "Overlap.ttf"
    _fontmake(src, out)
    _check_built_font(out)


def test_lint_of_a_ufo_path(tmp_path):
    ufo = _overlapping_ufo()
    src = tmp_path / "Overlap.ufo"
    ufo.save(src)
    from_path = casteljau.lint(src)
    # the squares run clockwise: outer contours of a UFO (PostScript) run counter-clockwise
    assert {(f.glyph, f.kind) for f in from_path} == {
        ("square", "overlap"), ("square", "direction"), ("rings", "overlap"), ("baracute", "overlap")
    }
    assert sorted(map(str, from_path)) == sorted(map(str, casteljau.lint(ufo)))


def test_fontmake_without_the_filter_keeps_the_overlaps(tmp_path):
    """The control: the same UFO built with --keep-overlaps alone is not lint-clean."""
    src = tmp_path / "Overlap.ufo"
    _overlapping_ufo().save(src)
    out = tmp_path / "Overlap.ttf"
    _fontmake(src, out)
    kinds = {(f.glyph, f.kind) for f in casteljau.lint(str(out))}
    assert {("square", "overlap"), ("rings", "overlap"), ("baracute", "overlap")} <= kinds


def test_install_replaces_fonttools_remove_overlaps():
    import fontTools.ttLib.removeOverlaps as ro

    import casteljau.fonttools

    saved = ro.removeOverlaps
    try:
        casteljau.fonttools.install()
        assert ro.removeOverlaps is casteljau.fonttools.removeOverlaps
    finally:
        ro.removeOverlaps = saved
