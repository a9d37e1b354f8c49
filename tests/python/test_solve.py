"""solve: the same schemes, coefficients and ranking as `rotlie solve --json`."""
from fractions import Fraction

import rotlie

from conftest import cli


def test_water_N_family_as_the_command_line():
    expected = cli("solve", "--family", "N", "--inertia", "water", "--json")
    schemes = rotlie.solve(rotlie.Body.named("water"), family="N")
    assert len(schemes) == expected["real_solutions"] == 90
    for s, e in zip(schemes, expected["solutions"]):
        assert s.name == f"{e['scheme']}:{e['perm']}:{e['label']}"
        assert s.remainder_norm == e["analytic_remainder"]
        assert s.word == e["word"]
        named = dict(zip(s.stage_names, (value for _, value in s.stages)))
        assert named == e["coefficients"]
    norms = [s.remainder_norm for s in schemes]
    assert norms == sorted(norms)


def test_one_member_one_permutation_more_digits():
    expected = cli("solve", "--family", "N", "--scheme", "N2", "--perm", "BAC", "--inertia", "0.4,0.7,1",
                   "--digits", "50", "--json")
    schemes = rotlie.solve("0.4,0.7,1", family="N", perm="BAC", scheme="N2", digits=50)
    assert [s.name for s in schemes] == [f"N2:BAC:{e['label']}" for e in expected["solutions"]]
    for s, e in zip(schemes, expected["solutions"]):
        assert dict(zip(s.stage_names, (v for _, v in s.stages))) == e["coefficients"]
    assert all(len(v.split("e")[0].replace("-", "").replace(".", "")) >= 50 for s in schemes for _, v in s.stages)
    # a solved scheme by its name is the same table as solve's at the default 40 digits
    at_40 = rotlie.solve("0.4,0.7,1", family="N", perm="BAC", scheme="N2")
    assert rotlie.scheme(at_40[0].name, rotlie.Body("0.4", "0.7", "1")) == at_40[0]


def test_water_QRS_family_as_the_command_line():
    """The two-parameter search (Q, QRS): the same systems, minima and coefficients as the CLI."""
    expected = cli("solve", "--family", "QRS", "--inertia", "water", "--starts", "12", "--seed", "7", "--json")
    schemes = rotlie.solve("water", family="QRS", starts=12, seed=7)
    polished = [e for e in expected["systems"] if e["polished"]]
    assert len(schemes) == len(polished) > 0
    for s, e in zip(schemes, polished):
        assert s.name == e["name"]
        assert s.remainder_norm == e["remainder"]
        assert s.order == 4
        assert dict(zip(s.stage_names, (value for _, value in s.stages))) == e["coefficients"]


def test_a_two_parameter_scheme_is_of_order_four():
    """A Q scheme leaves H_R2 and H_R3 at its written digits (LV eq. 52) and converges at order 4 (a second method)."""
    best = rotlie.solve("water", family="Q", scheme="ABACBABABCABA", perm="ABC", starts=8)[0]
    assert best.name == "Q:ABACBABABCABA:ABC"
    r = rotlie.remainder(best, order=5)
    assert r.free == []
    assert all(abs(Fraction(c)) < Fraction(1, 10**35) for k in (2, 3) for c in r.terms[k].values())
    assert any(abs(Fraction(c)) > Fraction(1, 10**6) for c in r.terms[5].values())
    measured = rotlie.order(best, "water", scalar="float128", min_level=2, max_level=5)
    assert abs(measured["slope"] - 4) < 0.1
