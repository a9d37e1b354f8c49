"""examples/python/dart_beta_sweep.py's pieces on a tiny study: a sweep of three betas over one orbit on two
MPI ranks (one without mpirun) against facts computed apart: the period change falls with beta, one grid
line's result is the single `rotlie binary` run's JSON, the vector form along the track is the beta= form,
the Monte Carlo's lines are those of its seed, and the script's orbit-frame angles are the observables'."""
import importlib.util
import json
import pathlib
import shutil

import numpy as np

from conftest import cli, rotlie_binary

SCRIPT = pathlib.Path(__file__).resolve().parents[2] / "examples" / "python" / "dart_beta_sweep.py"


def load_script():
    spec = importlib.util.spec_from_file_location("dart_beta_sweep", SCRIPT)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def without_timing(j):
    j = dict(j)
    j.pop("cpu_s", None)
    j.pop("index", None)
    if isinstance(j.get("error_estimate"), dict):
        j["error_estimate"] = {k: v for k, v in j["error_estimate"].items() if k != "cpu_s"}
    return j


def cli_args(line):
    """A sweep line as `rotlie binary` options."""
    args = ["binary"]
    for key, value in line.items():
        if value is True:
            args.append(f"--{key}")
        else:
            args += [f"--{key}", str(value)]
    return args + ["--json"]


def test_a_tiny_sweep_against_single_runs(tmp_path):
    s = load_script()
    binary = rotlie_binary()
    ranks = 2 if shutil.which("mpirun") else 1
    m1, frame = s.start_frame(binary)
    T = s.span(0.5)  # one mutual orbit
    betas = [2.0, 3.5, 5.0]
    mass = s.M2_KG
    base = s.baseline_lines([mass], T, m1)
    grid = s.grid_lines(betas, T, m1, mass)
    along = dict(s.run_base(T), mass=f"{s.num(m1)},{s.num(mass)}",
                 impulse="secondary:" + ",".join(map(s.num, s.dv_vector(3.5, mass, 0.0, 0.0, frame))))
    s.write_jsonl(tmp_path / "runs.jsonl", base + grid + [along])
    s.run_sweep(binary, tmp_path / "runs.jsonl", tmp_path / "results.jsonl", ranks)
    results = s.read_results(tmp_path / "results.jsonl")
    assert [r["index"] for r in results] == list(range(5))
    before = s.observed(results[0])["period_h"]
    change = [(s.observed(r)["period_h"] - before) * 60 for r in results[1:4]]
    assert change[0] < 0 and all(b < a for a, b in zip(change, change[1:])), change  # falls with beta

    # the middle beta: the sweep's line is the single run's JSON, and so is its period change
    alone = cli(*cli_args(grid[1]))
    assert without_timing(results[2]) == without_timing(alone)
    alone_before = cli(*cli_args(base[0]))
    assert (alone["observables"]["orbit_period_h"] - alone_before["observables"]["orbit_period_h"]) * 60 == change[1]

    # the vector form with no tilt is the beta= form: the same push, to rounding
    r_beta, r_vector = np.array(results[2]["r"]), np.array(results[4]["r"])
    assert np.linalg.norm(r_vector - r_beta) < 1e-12 * np.linalg.norm(r_beta)
    dv = np.linalg.norm(s.dv_vector(3.5, mass, 1.5, -2.0, frame))
    assert abs(dv - 3.5 * 579.4 * 6.1449e6 / mass) < 1e-12 * dv  # beta m U / M in mm/s, whatever the tilt


def test_the_monte_carlo_lines_are_those_of_their_seed():
    s = load_script()
    frame = {"t": np.array([0.0, 1, 0]), "r": np.array([1.0, 0, 0]), "n": np.array([0.0, 0, 1])}
    lines = lambda seed: s.monte_carlo_lines(s.monte_carlo_samples(40, seed, 3.0), frame, 3600.0, 5.5e11)
    first = json.dumps(lines(2022))
    assert first == json.dumps(lines(2022))
    assert first != json.dumps(lines(2023))
    # the draws follow the stated distributions
    big = s.monte_carlo_samples(20000, 7, 3.0)
    assert abs(np.median(big["beta"]) - 3.61) < 0.01
    above, below = big["beta"][big["beta"] > 3.61] - 3.61, 3.61 - big["beta"][big["beta"] <= 3.61]
    assert abs(np.sqrt(np.mean(above ** 2)) - 0.19) < 0.01 and abs(np.sqrt(np.mean(below ** 2)) - 0.25) < 0.01
    assert abs(big["m2"].mean() - 4.3e9) < 0.01e9 and abs(big["m2"].std() - 0.25e9) < 0.01e9
    assert abs(big["delta_deg"].std() - 3.0) < 0.1


def test_the_orbit_frame_angles_are_the_observables():
    s = load_script()
    import rotlie
    binary = rotlie_binary()
    m1, frame = s.start_frame(binary)
    push = "secondary:" + ",".join(map(s.num, s.dv_vector(3.61, s.M2_KG, 2.0, 3.0, frame)))
    run = rotlie.binary(system="didymos", order=4, mass=f"{s.num(m1)},{s.num(s.M2_KG)}", integrator="SIER4", h=60, T=21600,
                        every=1, impulse=push, observe=True)
    angles = s.orbit_frame_euler_deg(run.trajectory.r, run.trajectory.v, run.trajectory.Q2)
    e = run.observables["euler_deg"]["secondary"]
    largest = np.abs(angles).max(axis=0)
    assert np.allclose(largest, [e["roll_max"], e["pitch_max"], e["yaw_max"]], rtol=1e-9, atol=1e-12), (largest, e)
    assert np.allclose(angles[-1], [e["roll_end"], e["pitch_end"], e["yaw_end"]], rtol=1e-9, atol=1e-12)
    assert largest[0] > 0.01  # out of the plane: a roll to see
