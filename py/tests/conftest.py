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


def pytest_sessionfinish(session, exitstatus):
    """Under CI no test may be skipped: a skip fails the run."""
    if os.environ.get("CI"):
        reporter = session.config.pluginmanager.get_plugin("terminalreporter")
        if reporter is not None and reporter.stats.get("skipped"):
            reporter.write_line("CI: %d tests were skipped; under CI every test runs" % len(reporter.stats["skipped"]), red=True)
            session.exitstatus = 1
