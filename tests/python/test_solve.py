"""solve: the same schemes, coefficients and ranking as `rotlie solve --json`."""
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
