import os
import pathlib

import pytest

REPO = pathlib.Path(__file__).resolve().parents[2]
DEJAVU = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"


@pytest.fixture
def repo():
    return REPO


@pytest.fixture
def tuffy():
    """A small TrueType font in the repository's test data."""
    return str(REPO / "tests" / "data" / "fonts" / "Tuffy.ttf")
