"""rotlie.binary against `rotlie binary --json`: the same numbers bit for bit, the trajectory's arrays
against the command line's --every lines, typed keywords, the command line's refusals, contact."""
import json
import subprocess

import numpy as np
import pytest

import rotlie

from conftest import cli, cli_error, rotlie_binary


def test_binary_equals_the_command_line_with_its_trajectory():
    args = ["binary", "--system", "didymos", "--order", "4", "--integrator", "KEPLER4", "--h", "120", "--T", "7200", "--every", "20", "--json"]
    r = subprocess.run([rotlie_binary(), *args], capture_output=True, text=True, timeout=600, check=True)
    lines = [json.loads(line) for line in r.stdout.splitlines()]
    samples, j = lines[:-1], lines[-1]
    b = rotlie.binary(system="didymos", order=4, integrator="KEPLER4", h=120, T=7200, every=20)
    assert isinstance(b, rotlie.BinaryResult)
    assert b.r.tolist() == j["r"] and b.v.tolist() == j["v"]
    assert b.Q1.shape == (3, 3) and b.Q1.tolist() == j["Q1"] and b.Q2.tolist() == j["Q2"]
    assert b.omega1.tolist() == j["omega1"] and b.omega2.tolist() == j["omega2"]
    assert (b.energy, b.steps, b.order, b.unstable) == (j["energy"], j["steps"], j["order"], j["unstable"])
    assert b.masses.shape == (2,) and b.moments.shape == (2, 3) and b.mutual == j["mutual"]
    tr = b.trajectory
    assert isinstance(tr, rotlie.BinaryTrajectory) and tr.every == 20
    assert tr.t.shape == (4,) and tr.r.shape == (4, 3) and tr.Q1.shape == (4, 3, 3) and tr.energy.shape == (4,)
    assert tr.t.tolist() == [s["t"] for s in samples]
    for key in ("r", "v", "Q1", "Q2", "omega1", "omega2", "energy"):
        assert getattr(tr, key).tolist() == [s[key] for s in samples], key
    assert np.array_equal(tr.Q2[-1], b.Q2)
    d = b.to_dict()
    d.pop("cpu_s"), j.pop("cpu_s")
    d["error_estimate"].pop("cpu_s"), j["error_estimate"].pop("cpu_s")
    assert d == j
    assert rotlie.binary(system="didymos", integrator="SIER2", T=0).trajectory is None


def test_bodies_states_and_keywords():
    a = rotlie.binary(primary="ellipsoid:0.4,0.38,0.35", secondary="ellipsoid:0.1,0.08,0.06", density=(2000, 2500), separation=1.3,
                      primary_period=2.5, integrator="SIER4", h=60, T=600)
    start = rotlie.binary(primary="ellipsoid:0.4,0.38,0.35", secondary="ellipsoid:0.1,0.08,0.06", density=(2000, 2500), separation=1.3,
                          primary_period=2.5, integrator="SIER4", T=0).to_dict()
    state = {k: start[k] for k in ("r", "v", "Q1", "Q2", "omega1", "omega2")}
    b = rotlie.binary(primary="ellipsoid:0.4,0.38,0.35", secondary="ellipsoid:0.1,0.08,0.06", density=(2000, 2500), state=state,
                      integrator="SIER4", h=60, T=600)
    assert np.max(np.abs(a.r - b.r)) < 1e-14
    assert "separation" in rotlie.binary.__doc__
    with pytest.raises(TypeError):
        rotlie.binary(system="didymos", integrator="SIER2", T=0, nope=1)
    with pytest.raises(TypeError):
        rotlie.binary("didymos")  # keywords only
    with pytest.raises(TypeError, match="every must be an integer"):
        rotlie.binary(system="didymos", integrator="SIER2", h=10, T=100, every=2.5)


def test_refusals_are_the_command_lines_and_contact_raises():
    with pytest.raises(ValueError) as e:
        rotlie.binary(system="didymos", separation=0.4, integrator="SIER2", T=0)
    assert str(e.value) == cli_error("binary", "--system", "didymos", "--separation", "0.4", "--integrator", "SIER2", "--T", "0")
    graze = {"r": [1.0, 0, 0], "v": [0, 7.9e-5, 0], "Q1": np.eye(3).tolist(), "Q2": np.eye(3).tolist(), "omega1": [0, 0, 0], "omega2": [0, 0, 0]}
    with pytest.raises(RuntimeError, match="the bodies touch at t = "):
        rotlie.binary(primary="ellipsoid:0.4,0.3,0.2", secondary="ellipsoid:0.05,0.05,0.05", density=2000, state=graze, integrator="SIER2",
                      h=10, T=20000)


def test_numpy_scalars_paths_results_and_arrays_mean_what_they_obviously_mean(tmp_path):
    """Issue 46: order=np.int64(2), h=np.float32(60), every=np.int32(5) are the numbers they hold; state= takes a
    pathlib.Path, a dict of NumPy arrays, and the result or simulation whose end it is; a float for an integer,
    a bool, or an unrelated object is one line of TypeError."""
    a = rotlie.binary(system="didymos", integrator="SIER4", h=60, T=600, order=2, every=5)
    b = rotlie.binary(system="didymos", integrator="SIER4", h=np.float32(60), T=np.int64(600), order=np.int64(2), every=np.int32(5))
    assert np.array_equal(a.r, b.r) and np.array_equal(a.trajectory.t, b.trajectory.t)
    path = tmp_path / "start.json"
    path.write_text(json.dumps(cli("binary", "--system", "didymos", "--integrator", "SIER4", "--h", "60", "--T", "600", "--order", "2", "--json")))
    sim = rotlie.binary_simulation(system="didymos", integrator="SIER4", h=60)
    sim.integrate(600)
    arrays = {k: getattr(a, k) for k in ("r", "v", "Q1", "Q2", "omega1", "omega2")}
    ends = [rotlie.binary(system="didymos", integrator="SIER4", h=60, T=600, order=2, state=s) for s in (path, a, arrays, sim)]
    for e in ends[1:]:
        assert np.array_equal(e.r, ends[0].r) and np.array_equal(e.Q2, ends[0].Q2)
    for bad, words in ((dict(order=2.0), "order must be an integer, got float"), (dict(order=True), "order must be an integer, got bool"),
                       (dict(state=3), "state must be a file's path")):
        with pytest.raises(TypeError, match=words) as e:
            rotlie.binary(system="didymos", integrator="SIER4", h=60, T=600, **bad)
        assert "\n" not in str(e.value)
