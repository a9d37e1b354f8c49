"""best, bch, map_line, order and md: typed results holding the command line's JSON, the same numbers."""
import inspect
import pydoc
import json
from fractions import Fraction

import numpy as np
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
    # the body (1, 3, 4): its P systems solve in a third of water's time; water's best (N2:BAC:2, LV
    # section 4.3) is the command line's own test (map_cli_test)
    r = rotlie.best("1,3,4", analytic_only=True)
    e = cli("best", "--inertia", "1,3,4", "--analytic-only", "--json")
    timing = {"cpu_seconds", "seconds"}
    assert {k: v for k, v in r.items() if k not in timing} == {k: v for k, v in e.items() if k not in timing}
    assert isinstance(r, rotlie.BestResult) and r.to_dict() == dict(r)
    assert r.N["best"] == r["N"]["best"] and r.P["best"] == r["P"]["best"]
    with pytest.raises(ValueError):
        rotlie.best("1,1,1")  # a symmetric top is outside the maps


def test_map_line_as_the_command_line(tmp_path):
    cli("map", "--family", "N", "--grid", "4", "--out", str(tmp_path))
    lines = [json.loads(line) for line in (tmp_path / "map-N.jsonl").read_text().splitlines()[1:]]
    for s, t in [(Fraction(1, 4), Fraction(1, 2)), (Fraction(3, 4), Fraction(0))]:
        expected = next(line for line in lines if line["s"] == str(s) and line["t"] == str(t))
        line = rotlie.map_line("N", s, t, 4)
        assert line == expected and line.to_dict() == expected and line.best == expected["best"]
    with pytest.raises(ValueError):
        rotlie.map_line("N", Fraction(1, 3), 0, 4)  # not a grid point
    with pytest.raises(ValueError):
        rotlie.map_line("Z", 0, 0, 4)


def test_map_line_by_the_exact_solver_agrees():
    fast = rotlie.map_line("N", Fraction(1, 4), Fraction(1, 2), 4)
    exact = rotlie.map_line("N", Fraction(1, 4), Fraction(1, 2), 4, exact=True)
    assert exact["best"] == fast["best"] and exact["real_solutions"] == fast["real_solutions"]
    assert abs(exact["remainder"] - fast["remainder"]) <= 1e-12 * fast["remainder"]


def without_cpu(d):
    return {k: v for k, v in d.items() if k != "cpu_s_per_ps"}


def test_md_as_the_command_line():
    r = rotlie.md("free-water", "SIER2/N2:BAC:2", 8, runs=3)
    e = cli("md", "--scene", "free-water", "--integrator", "SIER2/N2:BAC:2", "--h", "8", "--runs", "3", "--json")
    assert without_cpu(r) == without_cpu(e)
    r = rotlie.md("dipole-field", "SIER4", 16.8, T=2, runs=2, scalar="long-double")
    e = cli("md", "--scene", "dipole-field", "--integrator", "SIER4", "--h", "16.8", "--T", "2", "--runs", "2",
            "--scalar", "long-double", "--json")
    assert without_cpu(r) == without_cpu(e)
    assert r["dLz_over_Lz"][0] < 1e-12  # L_z is conserved by the splitting (vZS Table I: at round-off)
    # an option of another scene is refused before anything runs, as by the command line
    for bad in [dict(scene="gas"), dict(integrator="XYZ"), dict(h=-1), dict(scalar="half"), dict(scene="dipole-field", temperature=300),
                dict(dipole=2), dict(molecules=512)]:
        args = dict(scene="free-water", integrator="MRDL", h=1.66) | bad
        with pytest.raises(ValueError):
            rotlie.md(args.pop("scene"), args.pop("integrator"), args.pop("h"), runs=1, **args)


def test_remainder_as_the_command_line():
    r = rotlie.remainder("N2", order=3, body=WATER, perm="BAC", coeffs={"a1": "1/20", "a2": Fraction(3, 20)})
    e = cli("remainder", "--scheme", "N2", "--perm", "BAC", "--inertia", "water", "--coeffs", "a1=1/20,a2=3/20",
            "--order", "3", "--json")
    assert r.json == e
    assert r.latex() == cli("remainder", "--scheme", "N2", "--perm", "BAC", "--inertia", "water", "--coeffs",
                            "a1=1/20,a2=3/20", "--order", "3", "--latex")
    with pytest.raises(ValueError):
        rotlie.remainder("N2", order=12)


def test_remainder_of_a_solved_scheme():
    """A dedicated scheme solves H_R3 = 0 (LV eq. 52): its written 40-digit coefficients leave ~1e-38."""
    s = rotlie.scheme("N2:BAC:2", WATER)
    r = rotlie.remainder(s, order=5)
    assert r.free == [] and all(abs(Fraction(c)) < Fraction(1, 10**35) for c in r.terms[3].values())
    assert any(abs(Fraction(c)) > Fraction(1, 10**6) for c in r.terms[5].values())


def test_remainder_symbolic_in_sympy():
    sympy = pytest.importorskip("sympy")
    r = rotlie.remainder("ABCBA", order=3)  # Strang: symbolic in I1, I2, I3
    I1, I2, I3 = sympy.symbols("I1 I2 I3")
    h3 = r.sympy()[3]
    # the symbolic coefficients at water's moments are the ones computed for water exactly
    at_water = rotlie.remainder("ABCBA", order=3, body=WATER).terms[3]
    values = dict(zip((I1, I2, I3), (sympy.Rational(m.numerator, m.denominator) for m in WATER.moments)))
    assert set(h3) == set(at_water)
    assert all(sympy.simplify(c.subs(values) - sympy.Rational(at_water[m])) == 0 for m, c in h3.items())
    assert r.hamiltonian(3) != 0


def test_md_trajectory_as_the_command_line():
    """md(..., every=K): the first run's samples as arrays, equal to `rotlie md --every K --json`'s."""
    for scene, integrator, h, extra in [("free-water", "MRDL", 8, ["--T", "0.2"]), ("dipole-field", "SIER4", 16.8, ["--T", "0.5"])]:
        r = rotlie.md(scene, integrator, h, T=extra[1], runs=2, every=5)
        e = cli("md", "--scene", scene, "--integrator", integrator, "--h", str(h), "--runs", "2", "--every", "5", *extra, "--json")
        assert isinstance(r, rotlie.MdResult) and r.scene == scene and r.unstable is False
        tr, te = r.trajectory, e["trajectory"]
        steps = e["steps"]
        assert tr.every == 5 and len(tr.t_ps) == steps // 5 + 1
        assert np.array_equal(tr.t_ps, te["t_ps"]) and np.array_equal(tr.Q, np.array(te["Q"]))
        assert np.array_equal(tr.G, np.array(te["G"])) and np.array_equal(tr.energy, te["energy"])
        assert tr.Q.shape == (len(tr.t_ps), 3, 3) and tr.G.shape == (len(tr.t_ps), 3)
        # each sampled attitude is a rotation, and the energy is conserved to the integrator's accuracy
        for Q in tr.Q:
            assert np.allclose(Q.T @ Q, np.eye(3), atol=1e-12)
        assert np.ptp(tr.energy) < 1e-3 * max(1.0, abs(tr.energy[0]))
    assert rotlie.md("free-water", "MRDL", 8, T=0.1, runs=1).trajectory is None


def test_md_keywords_are_typed_and_are_the_scenes_options():
    sig = inspect.signature(rotlie.md)
    keywords = {n for n, p in sig.parameters.items() if p.kind is inspect.Parameter.KEYWORD_ONLY} | {"T"}
    assert keywords == rotlie._commands.md_keywords()  # a new scene option needs its keyword here
    assert all(p.annotation is not inspect.Parameter.empty for n, p in sig.parameters.items())
    assert str(sig.parameters["every"].annotation) == "int | None" and sig.parameters["every"].default is None
    assert "runs: 'int | None' = None" in pydoc.render_doc(rotlie.md)  # what help(rotlie.md) shows
    with pytest.raises(TypeError):
        rotlie.md("free-water", "SIER2", 8, runs=1.5)


def test_order_is_typed():
    r = rotlie.order("ABCBA2", WATER, max_level=4)
    assert isinstance(r, rotlie.OrderResult) and r.declared_order == 2
    assert np.array_equal(r.h, [p["h"] for p in r.points]) and r.error.shape == (4,)


def test_spin_orbit_is_a_scene_of_md():
    """The spin-orbit scene through md() is rotlie.spin's run and `rotlie spin`'s JSON (the registry holds it)."""
    r = rotlie.md("spin-orbit", "SIER4", "1/200", T=1, body="Moon", e=0.0549, obliquity=0.1, every=20)
    s = rotlie.spin("Moon", e=0.0549, integrator="SIER4", h="1/200", T=1, obliquity=0.1, every=20)
    e = cli("spin", "--body", "Moon", "--e", "0.0549", "--integrator", "SIER4", "--h", "1/200", "--T", "1",
            "--obliquity", "0.1", "--every", "20", "--json")
    timing = {"cpu_s", "scene"}

    def untimed(d):  # the error estimate's companion run has its own CPU time
        return {k: ({**v, "cpu_s": None} if k == "error_estimate" else v) for k, v in d.items() if k not in timing}
    assert untimed(r) == untimed(e) and e["error_estimate"]["order"] == 4
    assert r.scene == "spin-orbit" and r.theta == s.theta and np.array_equal(r.trajectory.Q, s.trajectory.Q)
    assert np.array_equal(r.trajectory.omega_body, s.trajectory.omega_body) and r.trajectory.t[-1] == 1.0
    with pytest.raises(ValueError):
        rotlie.md("spin-orbit", "SIER4", "1/200", T=1, e=0.1)  # no body
    with pytest.raises(ValueError):
        rotlie.md("spin-orbit", "SIER4", "1/200", T=1, body="Moon", e=0.1, runs=3)  # an option of another scene
