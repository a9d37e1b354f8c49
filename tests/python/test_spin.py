"""rotlie.spin against `rotlie spin --json`: the same numbers bit for bit, the trajectory's arrays
included, typed keywords, and the command line's refusals."""
from fractions import Fraction
import inspect
import warnings

import numpy as np
import pytest

import rotlie

from conftest import cli, cli_error


def test_spin_equals_the_command_line_with_its_trajectory():
    j = cli("spin", "--body", "Mercury", "--e", "0.2056", "--omega0", "1.5", "--integrator", "SIER4", "--h", "1/200", "--T", "2",
            "--obliquity", "0.1", "--every", "50", "--json")
    r = rotlie.spin("Mercury", e=0.2056, integrator="SIER4", h=Fraction(1, 200), T=2, omega0=1.5, obliquity=0.1, every=50)
    assert isinstance(r, rotlie.SpinResult)
    assert r.Q.shape == (3, 3) and r.Q.tolist() == j["Q"]
    assert r.omega_body.tolist() == j["omega_body"]
    assert (r.theta, r.h, r.steps, r.unstable) == (j["theta"], j["h"], j["steps"], j["unstable"])
    tr = r.trajectory
    assert isinstance(tr, rotlie.SpinTrajectory) and tr.every == 50
    assert tr.t.shape == (9,) and tr.Q.shape == (9, 3, 3) and tr.omega_body.shape == (9, 3) and tr.energy.shape == (9,)
    assert tr.t.tolist() == j["trajectory"]["t"]
    assert tr.Q.tolist() == j["trajectory"]["Q"]
    assert tr.omega_body.tolist() == j["trajectory"]["omega_body"]
    assert tr.energy.tolist() == j["trajectory"]["energy"]
    assert tr.t[0] == 0 and tr.t[-1] == 2 and np.array_equal(tr.Q[-1], r.Q)
    d = r.to_dict()
    d.pop("cpu_s"), j.pop("cpu_s")
    d["error_estimate"].pop("cpu_s"), j["error_estimate"].pop("cpu_s")
    assert d == j
    assert r.trajectory is not None and rotlie.spin("Hyperion", 0.1, "SIER2", "1/100", 1).trajectory is None


def test_bodies_and_steps_of_every_kind():
    named = rotlie.spin("Hyperion", 0.1, "SIER2", "1/100", 1)
    moments = named.to_dict()["moments"]
    as_text = rotlie.spin("34021/57125,49096/57125,1", 0.1, "SIER2", 0.01, 1)
    as_body = rotlie.spin(rotlie.Body("34021/57125", "49096/57125", "1"), 0.1, "SIER2", Fraction(1, 100), 1)
    as_tuple = rotlie.spin((Fraction(34021, 57125), Fraction(49096, 57125), 1), 0.1, "SIER2", "0.01", 1)
    for r in (as_text, as_body, as_tuple):
        assert r.Q.tolist() == named.Q.tolist() and r.to_dict()["moments"] == moments


def test_keywords_are_typed_and_documented():
    doc = rotlie.spin.__doc__
    assert "every" in doc and "Hyperion" in doc
    with pytest.raises(TypeError):
        rotlie.spin("Moon", 0.05, "SIER2", 1j, 1)
    with pytest.raises(TypeError):
        rotlie.spin("Moon", 0.05, "SIER2", "1/100", 1, nope=3)
    with pytest.raises(TypeError, match="every must be an integer"):
        rotlie.spin("Moon", 0.05, "SIER2", "1/100", 1, every=1.5)  # once truncated to 1


def test_refusals_and_flags_are_the_command_lines():
    with pytest.raises(ValueError) as e:
        rotlie.spin("Hyperion", 0.1, "SIER2", 0.4, 1)
    assert str(e.value) == cli_error("spin", "--body", "Hyperion", "--e", "0.1", "--integrator", "SIER2", "--h", "0.4", "--T", "1")
    with pytest.warns(UserWarning, match="Jacobi integral"):
        r = rotlie.spin("Hyperion", 0, "SIER2", 1, 50)
    assert r.unstable and r.conserved["quantity"] == "jacobi"


def test_a_phase_error_is_flagged_by_the_estimate_at_twice_the_step():
    """Issue 46: three SIER4 steps an orbit end Hyperion's spin at 1.757 rad against the converged 0.432,
    the Jacobi integral bounded; the runs alongside (at 2h and 4h, then at h/2 since the 4h run ends a radian
    away) flag it, as `rotlie spin` does."""
    with pytest.warns(UserWarning, match="estimated error"):
        r = rotlie.spin("Hyperion", 0, "SIER4", "1/3", 30, omega0=2)
    assert r.inaccurate and not r.unstable
    e = r.error_estimate
    assert e["order"] == 4 and e["step_ratio"] == 0.5 and e["attitude_rad"] > 1e-2 and e == r.to_dict()["error_estimate"]
    j = cli("spin", "--body", "Hyperion", "--e", "0", "--integrator", "SIER4", "--h", "1/3", "--T", "30", "--omega0", "2", "--json")
    assert (j["inaccurate"], j["error_estimate"]["attitude_rad"]) == (True, e["attitude_rad"])
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        converged = rotlie.spin("Hyperion", 0, "SIER4", "1/200", 30, omega0=2)
        skipped = rotlie.spin("Hyperion", 0, "SIER4", "1/3", 30, omega0=2, no_error_estimate=True)
        loose = rotlie.spin("Hyperion", 0, "SIER4", "1/3", 30, omega0=2, accuracy=(10, 10))
    assert not converged.inaccurate and converged.error_estimate["attitude_rad"] < 1e-6
    assert skipped.error_estimate is None and not skipped.inaccurate and skipped.theta == r.theta
    assert not loose.inaccurate and loose.to_dict()["accuracy"] == {"relative": 10, "angle_rad": 10}
    assert rotlie.spin("Hyperion", 0, "SIER4", "1/3", 30, omega0=2, accuracy="1e-3", no_error_estimate=True).to_dict()["accuracy"]["angle_rad"] == 1e-2
    with pytest.raises(ValueError, match="accuracy takes REL or REL,RAD"):
        rotlie.spin("Hyperion", 0, "SIER4", "1/3", 30, accuracy=(1, 2, 3))


def test_conserved_is_an_owned_dictionary():
    """SpinResult.conserved once returned an item of a dictionary already freed (a use after free that
    crashed the interpreter about one run in ten): each access is a dictionary of its own that lives on."""
    r = rotlie.spin("Moon", 0.0549, "SIER4", "1/100", 1)
    kept = [r.conserved for _ in range(200)]
    churn = [{"x": [float(i)] * 8} for i in range(20000)]  # reuse freed memory
    assert all(c == r.to_dict()["conserved"] for c in kept) and len(churn) == 20000
    assert kept[0] is not kept[1] and kept[0]["quantity"] == "extended_hamiltonian"
