"""best, bch and map_line: the command line's JSON as Python objects, the same numbers."""
import json
from fractions import Fraction

import pytest

import rotlie

from conftest import cli

WATER = rotlie.Body.named("water")


def test_bch_as_the_command_line_and_the_literature():
    terms = rotlie.bch("XY", 5)
    expected = cli("bch", "--series", "XY", "--degree", "5", "--json")["terms"]
    assert terms == [(t["word"], Fraction(t["coefficient"])) for t in expected]
    c = dict(terms)
    # log(e^X e^Y) = X + Y + [X,Y]/2 + [X,[X,Y]]/12 + [[X,Y],Y]/12 + … (Lyndon basis, standard bracketing)
    assert (c["A"], c["B"], c["AB"], c["AAB"], c["ABB"]) == (1, 1, Fraction(1, 2), Fraction(1, 12), Fraction(1, 12))
    with pytest.raises(ValueError):
        rotlie.bch("XQ", 3)
    with pytest.raises(ValueError):
        rotlie.bch("XY", 0)


def test_best_as_the_command_line():
    r = rotlie.best(WATER, analytic_only=True)
    e = cli("best", "--inertia", "water", "--analytic-only", "--json")
    timing = {"cpu_seconds", "seconds"}
    assert {k: v for k, v in r.items() if k not in timing} == {k: v for k, v in e.items() if k not in timing}
    assert r["N"]["best"] == "N2:BAC:2"  # LV section 4.3: the best N integrator for water
    with pytest.raises(ValueError):
        rotlie.best("1,1,1")  # a symmetric top is outside the maps


def test_map_line_as_the_command_line(tmp_path):
    cli("map", "--family", "N", "--grid", "4", "--out", str(tmp_path))
    lines = [json.loads(line) for line in (tmp_path / "map-N.jsonl").read_text().splitlines()[1:]]
    for s, t in [(Fraction(1, 4), Fraction(1, 2)), (Fraction(3, 4), Fraction(0))]:
        expected = next(line for line in lines if line["s"] == str(s) and line["t"] == str(t))
        assert rotlie.map_line("N", s, t, 4) == expected
    with pytest.raises(ValueError):
        rotlie.map_line("N", Fraction(1, 3), 0, 4)  # not a grid point
    with pytest.raises(ValueError):
        rotlie.map_line("Z", 0, 0, 4)


def test_map_line_by_the_exact_solver_agrees():
    fast = rotlie.map_line("N", Fraction(1, 4), Fraction(1, 2), 4)
    exact = rotlie.map_line("N", Fraction(1, 4), Fraction(1, 2), 4, exact=True)
    assert exact["best"] == fast["best"] and exact["real_solutions"] == fast["real_solutions"]
    assert abs(exact["remainder"] - fast["remainder"]) <= 1e-12 * fast["remainder"]
