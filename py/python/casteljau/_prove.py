"""``casteljau.prove``: the verdicts of claim files (the command line's ``prove``)."""

from __future__ import annotations

import os
from dataclasses import dataclass
from typing import Any, List, Optional, Sequence, Union

from . import _core

__all__ = ["Verdict", "prove"]


@dataclass(frozen=True)
class Verdict:
    """The verdict on one claim: ``verdict`` found (``holds``, ``fails-as-printed``,
    ``fails``) against ``expected``; ``passed`` when they agree; ``method`` and ``detail`` (the
    evidence), ``corrected`` (the evidence for the corrected statement), ``seconds``."""

    id: str
    source: str
    statement: str
    expected: str
    verdict: str
    passed: bool
    method: str
    detail: str
    corrected: Optional[str]
    seconds: float

    def __bool__(self) -> bool:
        return self.passed


def prove(path_or_text: Union[str, "os.PathLike[str]", Sequence[Any]], *, max_work: Optional[float] = None) -> List[Verdict]:
    """Checks claim files exactly: ``path_or_text`` a claim file or a directory of ``*.toml``
    claim files (or a list of them), or the TOML text of claims itself. Each claim's work is
    bounded by ``max_work``; a malformed file raises ``CasteljauError`` naming file and line.

    >>> from casteljau import prove
    >>> text = '''
    ... seed = "a-doctest.txt"
    ... [[claim]]
    ... id = "demo"
    ... source = "a doctest"
    ... statement = "B_0^1 + B_1^1 = 1"
    ... expect = "holds"
    ... kind = "identity"
    ... lhs = "B(0, 1, t) + B(1, 1, t)"
    ... rhs = "1"
    ... vars = ["t"]
    ... '''
    >>> [(v.id, v.verdict, v.passed) for v in prove(text)]
    [('demo', 'holds', True)]
    """
    if isinstance(path_or_text, (list, tuple)):
        rows = _core.prove([os.fspath(p) for p in path_or_text], None, "<text>", max_work)
    elif isinstance(path_or_text, os.PathLike) or (
        isinstance(path_or_text, str) and "\n" not in path_or_text and os.path.exists(path_or_text)
    ):
        rows = _core.prove([os.fspath(path_or_text)], None, "<text>", max_work)
    else:
        rows = _core.prove(None, path_or_text, "<text>", max_work)
    return [
        Verdict(
            id=r["id"],
            source=r["source"],
            statement=r["statement"],
            expected=r["expected"],
            verdict=r["verdict"],
            passed=r["passed"],
            method=r["method"],
            detail=r["detail"],
            corrected=r["corrected"],
            seconds=r["seconds"],
        )
        for r in rows
    ]
