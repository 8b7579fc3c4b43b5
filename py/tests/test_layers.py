"""The package's modules import one way, lowest first: no module imports one above it, at the
top or inside a function (a deferred import is still a loop)."""

import ast
import pathlib

import casteljau

PACKAGE = pathlib.Path(casteljau.__file__).parent

# each module and the package modules it may import (besides the native ``_core`` and ``numbers``)
LAYERS = {
    "_contours": set(),
    "pathops._base": set(),
    "pathops._exact": {"_contours", "pathops._base"},
    "pathops._path": {"pathops._base", "pathops._exact"},
    "pathops._ops": {"pathops._base", "pathops._exact", "pathops._path"},
    "pathops.operations": {"pathops._base", "pathops._ops", "pathops._path"},
    "shape": {"_contours", "pathops._base", "pathops._path"},
}


def _imports(module: str) -> set:
    parts = module.split(".")
    tree = ast.parse((PACKAGE / pathlib.Path(*parts)).with_suffix(".py").read_text(encoding="utf-8"))
    found = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom) and node.level:
            base = parts[: len(parts) - node.level]
            target = base + (node.module.split(".") if node.module else [])
            names = [".".join(target)] if node.module else [".".join(target + [a.name]) for a in node.names]
            found.update(n for n in names if n)
    return found - {"_core", "numbers"}


def test_modules_import_only_lower_layers():
    for module, allowed in LAYERS.items():
        assert _imports(module) <= allowed, module
