"""The examples in the package's docstrings run (the native classes' included)."""

import doctest
import importlib
from fractions import Fraction

import pytest

import casteljau

MODULES = [
    "casteljau",
    "casteljau.numbers",
    "casteljau.shape",
    "casteljau.pathops",
    "casteljau.pathops._path",
    "casteljau.pathops._base",
    "casteljau.pathops._exact",
    "casteljau.pathops._ops",
    "casteljau._lint",
    "casteljau._prove",
    "casteljau.oracle",
    "casteljau.pens",
    "casteljau.strategies",
]


@pytest.mark.parametrize("name", MODULES)
def test_module_examples(name):
    module = importlib.import_module(name)
    failures, tried = doctest.testmod(module, extraglobs={"Fraction": Fraction}, optionflags=doctest.ELLIPSIS)
    assert failures == 0


@pytest.mark.parametrize("cls", [casteljau.Algebraic, casteljau.Bezier, casteljau.RationalBezier])
def test_native_class_examples(cls):
    globs = {"Fraction": Fraction, "casteljau": casteljau}
    runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS)
    test = doctest.DocTestParser().get_doctest(cls.__doc__ or "", globs, cls.__name__, None, 0)
    assert test.examples, "no example in the docstring"
    assert runner.run(test).failed == 0
    # and the examples in its methods' docstrings
    for name in dir(cls):
        doc = getattr(getattr(cls, name), "__doc__", None) or ""
        if not name.startswith("__") and ">>>" in doc:
            test = doctest.DocTestParser().get_doctest(doc, dict(globs), cls.__name__ + "." + name, None, 0)
            assert runner.run(test).failed == 0, name


def test_the_readme_example(repo, monkeypatch):
    monkeypatch.chdir(repo)
    failures, tried = doctest.testfile(str(repo / "README.md"), module_relative=False, encoding="utf-8")
    assert tried >= 2 and failures == 0
    failures, tried = doctest.testfile(str(repo / "py" / "README.md"), module_relative=False, encoding="utf-8")
    assert tried >= 2 and failures == 0


def test_the_python_chapter(repo, monkeypatch):
    """docs/python.md: every `>>>` example, with its shown output, from the repository root."""
    monkeypatch.chdir(repo)
    failures, tried = doctest.testfile(
        str(repo / "docs" / "python.md"), module_relative=False, optionflags=doctest.ELLIPSIS, encoding="utf-8"
    )
    assert tried > 20 and failures == 0
