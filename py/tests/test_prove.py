"""casteljau.prove: claim files checked exactly."""

import pytest

from casteljau import CasteljauError, prove

CLAIMS = '''
seed = "a-test.txt"

[[claim]]
id = "partition-of-unity"
source = "a test"
statement = "the cubic Bernstein polynomials sum to 1"
expect = "holds"
kind = "identity"
vars = ["t"]
lhs = "B(0, 3, t) + B(1, 3, t) + B(2, 3, t) + B(3, 3, t)"
rhs = "1"

[[claim]]
id = "a-misprint"
source = "a test"
statement = "B(1, 2, t) = t(1 - t)"
expect = "fails-as-printed"
kind = "identity"
vars = ["t"]
lhs = "B(1, 2, t)"
rhs = "t*(1 - t)"
[claim.corrected]
note = "the binomial coefficient 2 is missing"
lhs = "B(1, 2, t)"
rhs = "2*t*(1 - t)"
'''


def test_prove_text():
    verdicts = prove(CLAIMS)
    assert [(v.id, v.verdict, v.passed) for v in verdicts] == [("partition-of-unity", "holds", True), ("a-misprint", "fails-as-printed", True)]
    assert all(verdicts) and verdicts[1].detail


def test_prove_a_claim_file(repo):
    verdicts = prove(repo / "proofs" / "000_rational_bezier.toml")
    assert verdicts and all(v.passed for v in verdicts)


def test_malformed_claims_name_the_line():
    with pytest.raises(CasteljauError, match="<text>"):
        prove("[[claim]]\nid = 3\n")


def test_the_budget_is_named():
    with pytest.raises(CasteljauError, match="max_work"):
        prove(CLAIMS, max_work=1)
