"""DART's beta and Dimorphos's spin: the period change and the secondary's attitude over beta and under the
published uncertainties, as one `rotlie sweep` on MPI ranks.

    python3 dart_beta_sweep.py --out dart-beta [--ranks 2] [--runs 1000] [--seed 2022] [--days 5]
    python3 dart_beta_sweep.py --out dart-beta --scaling 10000 [--scaling-hours 12] [--ranks 2]

The system is `--system didymos` at order 4 (the GUBAS example's ellipsoids, the circular start), stepped by
SIER4 at h = 60 s over --days (5 days: about ten mutual orbits and nine libration periods, so that the mean
period and the libration amplitude are read over whole cycles; at this step the run's own error estimate is
about 1e-8, far within the default accuracy of 1e-3). Dimorphos's mass is set with `--mass M1,M2` (the
primary keeps the named system's mass), DART's push is an `impulse` on the secondary at t = 0:

- a beta grid (--betas, default 1 ... 5 in 17 values) along the secondary's motion, the `beta=` form, at the
  grid's mass (--grid-mass, default 4.3e9 kg: Dimorphos at Cheng et al. 2023's 2,400 kg/m3);
- a Monte Carlo of --runs pushes at --seed: beta from a split normal 3.61 +0.19/-0.25 (Cheng et al. 2023,
  Nature 616, 457), Dimorphos's mass from a normal 4.3e9 +- 0.25e9 kg (the spread assumed), and the push's
  direction tilted from the anti-along-track direction by two normal angles of --direction-sigma degrees (in the orbit plane toward
  the radial, and out of it; the spread is assumed, see docs/binary.md), given as the vector form
  `secondary:dx,dy,dz` (mm/s, inertial) of |dv| = beta m U / M2 (m = 579.4 kg, U = 6.1449 km/s);
- runs without the push at a few masses, for the period before at each mass (interpolated).

All runs go into one input file, run by `mpirun -n RANKS rotlie sweep`. Writes into --out: runs.jsonl and
results.jsonl (the sweep's input and output), dart_beta.csv (one row per run) and dart_beta.json (the
summary), and four charts: period_vs_beta.png (the period change against beta with the observed
-33.0 +- 1.0 min of Thomas et al. 2023, and the beta the model needs), period_histogram.png (the Monte
Carlo's period change), excitation_vs_beta.png (the libration amplitude and the tumbling measure, the angle
of the secondary's angular momentum off its maximum-moment axis) and euler_series.png (the secondary's
roll, pitch and yaw in the orbit frame over --series-days for beta = 3.61, along track and tilted out of the
plane by --direction-sigma, from `rotlie.binary(..., every=...)`).

With --scaling N it instead times a sweep of N runs of --scaling-hours on one rank and on --ranks ranks
and prints the wall times, the speed-up and the load average.
"""
import argparse
import json
import os
import pathlib
import shutil
import subprocess
import time

import matplotlib
import numpy as np

import rotlie

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

DAY = 86400.0
H = 60.0  # s: SIER4's error estimate at this step is ~1e-8, far within the default accuracy (1e-3)
DART_MASS_KG = 579.4  # DART at impact (Cheng et al. 2023)
DART_SPEED_KM_S = 6.1449  # DART's speed relative to Dimorphos (Cheng et al. 2023)
BETA, BETA_PLUS, BETA_MINUS = 3.61, 0.19, 0.25  # Cheng et al. 2023, 1 sigma, equal densities of 2,400 kg/m3
M2_KG, M2_SIGMA_KG = 4.3e9, 0.25e9  # Dimorphos at 2,400 kg/m3 with Daly et al. 2023's volume; the spread assumed
OBSERVED_MIN, OBSERVED_SIGMA_MIN = -33.0, 1.0  # Thomas et al. 2023 (the 1.0 min is 3 sigma)


def run_base(T):
    """The options every run shares (a `rotlie sweep` line's keys)."""
    return {"system": "didymos", "order": 4, "integrator": "SIER4", "h": H, "T": T, "observe": True}


def span(days):
    """days as a whole number of steps, in seconds."""
    return round(days * DAY / H) * H


def find_rotlie(given=None):
    """The rotlie binary: --rotlie, $ROTLIE_BINARY, the build tree the module was loaded from, or PATH."""
    candidates = [given, os.environ.get("ROTLIE_BINARY"), str(pathlib.Path(rotlie.__file__).resolve().parents[2] / "bin" / "rotlie"),
                  shutil.which("rotlie")]
    for path in candidates:
        if path and os.access(path, os.X_OK):
            return path
    raise SystemExit("rotlie binary not found: give --rotlie PATH or set ROTLIE_BINARY")


def start_frame(rotlie_bin):
    """The primary's mass and the start's unit vectors (along-track t, radial r, normal n; inertial)."""
    out = subprocess.run([rotlie_bin, "binary", "--system", "didymos", "--order", "4", "--integrator", "SIER4", "--h", "60", "--T", "0", "--json"], check=True,
                         capture_output=True, text=True).stdout
    j = json.loads(out)
    r, v = np.array(j["r"]), np.array(j["v"])
    radial = r / np.linalg.norm(r)
    normal = np.cross(r, v)
    normal /= np.linalg.norm(normal)
    return j["masses"][0], {"t": np.cross(normal, radial), "r": radial, "n": normal}


def num(x):
    """A number as text that reads back to the same double."""
    return repr(float(x))


def dart_dv(beta, m2):
    """|dv| = beta m U / M2 in mm/s."""
    return beta * DART_MASS_KG * DART_SPEED_KM_S * 1e6 / m2


def grid_lines(betas, T, m1, m2):
    """The beta grid: DART's `beta=` form along the secondary's motion, at masses (m1, m2)."""
    return [dict(run_base(T), mass=f"{num(m1)},{num(m2)}", impulse=f"secondary:beta={num(b)},m={DART_MASS_KG},U={DART_SPEED_KM_S}") for b in betas]


def baseline_lines(masses, T, m1):
    """Runs without the push, one per secondary mass: the period before."""
    return [dict(run_base(T), mass=f"{num(m1)},{num(m)}") for m in masses]


def monte_carlo_samples(n, seed, direction_sigma_deg):
    """n draws of (beta, M2, in-plane tilt alpha, out-of-plane tilt delta; angles in degrees)."""
    rng = np.random.default_rng(seed)
    z = rng.standard_normal(n)
    beta = BETA + np.where(z > 0, BETA_PLUS, BETA_MINUS) * z
    m2 = M2_KG + M2_SIGMA_KG * rng.standard_normal(n)
    alpha = direction_sigma_deg * rng.standard_normal(n)
    delta = direction_sigma_deg * rng.standard_normal(n)
    return {"beta": beta, "m2": m2, "alpha_deg": alpha, "delta_deg": delta}


def dv_vector(beta, m2, alpha_deg, delta_deg, frame):
    """The secondary's dv (mm/s, inertial): |dv| against the along-track direction, tilted by alpha toward
    the radial (in the orbit plane) and by delta out of it."""
    a, d = np.radians(alpha_deg), np.radians(delta_deg)
    direction = -np.cos(d) * np.cos(a) * frame["t"] + np.cos(d) * np.sin(a) * frame["r"] + np.sin(d) * frame["n"]
    return dart_dv(beta, m2) * direction


def monte_carlo_lines(samples, frame, T, m1):
    lines = []
    for b, m, a, d in zip(samples["beta"], samples["m2"], samples["alpha_deg"], samples["delta_deg"]):
        dv = dv_vector(b, m, a, d, frame)
        lines.append(dict(run_base(T), mass=f"{num(m1)},{num(m)}", impulse="secondary:" + ",".join(map(num, dv))))
    return lines


def write_jsonl(path, lines):
    path.write_text("".join(json.dumps(line) + "\n" for line in lines))


def mpirun_command(ranks, mpirun=None):
    """mpirun's prefix for RANKS ranks (empty for one rank without MPI)."""
    mpirun = mpirun or shutil.which("mpirun")
    if mpirun is None:
        if ranks > 1:
            raise SystemExit("mpirun not found: install openmpi-bin or run with --ranks 1")
        return []
    root = ["--allow-run-as-root"] if hasattr(os, "geteuid") and os.geteuid() == 0 else []
    return [mpirun, "-n", str(ranks), "--oversubscribe", *root]


def run_sweep(rotlie_bin, runs, results, ranks, mpirun=None):
    """Runs the sweep (a results file already there is replaced); returns its wall time in seconds."""
    results.unlink(missing_ok=True)
    start = time.perf_counter()
    r = subprocess.run([*mpirun_command(ranks, mpirun), rotlie_bin, "sweep", "--in", str(runs), "--out", str(results)],
                       capture_output=True, text=True)
    wall = time.perf_counter() - start
    if r.returncode not in (0, 3):
        raise SystemExit(f"rotlie sweep failed ({r.returncode}): {r.stderr.strip()}")
    return wall


def read_results(path):
    """The sweep's result lines in the input's order (the header skipped)."""
    lines = path.read_text().splitlines()[1:]
    results = [json.loads(line) for line in lines if line.strip()]
    results.sort(key=lambda j: j["index"])
    return results


def observed(result):
    """What a run's line says: period (h), libration amplitude, the secondary's largest roll and pitch and
    angle of G off its maximum-moment axis (deg), tumbling, inaccurate."""
    if "observables" not in result:
        raise SystemExit(f"run {result['index']} did not compute: {result.get('status')}: {result.get('error')}")
    o = result["observables"]
    s = o["spin_state"]["secondary"]
    e = o["euler_deg"]["secondary"]
    return {"period_h": o["orbit_period_h"], "libration_deg": o["libration_amplitude_deg"], "roll_max_deg": e["roll_max"],
            "pitch_max_deg": e["pitch_max"], "npa_max_deg": s["npa_angle_max_deg"], "tumbling": bool(s["tumbling"]),
            "inaccurate": bool(result.get("inaccurate", False))}


def period_before(baseline_masses, baseline_periods):
    """The period before the push as a function of the secondary's mass (a quadratic through the runs)."""
    if len(baseline_masses) == 1:
        return lambda m: np.full_like(np.asarray(m, dtype=float), baseline_periods[0])
    coefficients = np.polyfit(np.asarray(baseline_masses) / M2_KG, baseline_periods, min(2, len(baseline_masses) - 1))
    return lambda m: np.polyval(coefficients, np.asarray(m, dtype=float) / M2_KG)


def fit_beta(betas, changes_min, target_min):
    """The beta whose period change is target_min, interpolated along the grid (None outside it). The
    change falls with beta."""
    betas, changes = np.asarray(betas), np.asarray(changes_min)
    if not (changes.min() <= target_min <= changes.max()):
        return None
    order = np.argsort(changes)
    return float(np.interp(target_min, changes[order], betas[order]))


def orbit_frame_euler_deg(r, v, Q):
    """The body's principal axes in the orbit frame (x the line from the primary, z the orbit's normal) as
    1-2-3 angles roll, pitch, yaw (deg), R = F^T Q = Rx(roll) Ry(pitch) Rz(yaw); of the four attitudes a half
    turn about a body axis apart, the one nearest the orbit frame (the axes carry no arrow)."""
    x = r / np.linalg.norm(r, axis=1, keepdims=True)
    z = np.cross(r, v)
    z /= np.linalg.norm(z, axis=1, keepdims=True)
    y = np.cross(z, x)
    F = np.stack([x, y, z], axis=2)  # columns: the orbit frame's axes
    R = np.einsum("nji,njk->nik", F, Q)
    flips = [np.diag(d) for d in ((1, 1, 1), (1, -1, -1), (-1, 1, -1), (-1, -1, 1))]
    candidates = np.stack([R @ D for D in flips])  # (4, n, 3, 3)
    best = np.argmax(np.trace(candidates, axis1=2, axis2=3), axis=0)
    R = candidates[best, np.arange(len(best))]
    pitch = np.arcsin(np.clip(R[:, 0, 2], -1, 1))
    roll = np.arctan2(-R[:, 1, 2], R[:, 2, 2])
    yaw = np.arctan2(-R[:, 0, 1], R[:, 0, 0])
    return np.degrees(np.stack([roll, pitch, yaw], axis=1))


def euler_series(m1, m2, frame, delta_deg, days, every):
    """The secondary's roll, pitch, yaw over `days` for beta = 3.61 at the grid mass, the push tilted by
    delta out of the plane (0: along track, the `beta=` form)."""
    T = span(days)
    if delta_deg == 0:
        push = f"secondary:beta={BETA},m={DART_MASS_KG},U={DART_SPEED_KM_S}"
    else:
        push = "secondary:" + ",".join(map(num, dv_vector(BETA, m2, 0.0, delta_deg, frame)))
    run = rotlie.binary(system="didymos", order=4, mass=f"{num(m1)},{num(m2)}", integrator="SIER4", h=H, T=T, every=every,
                        impulse=push, observe=True)
    tr = run.trajectory
    return tr.t, orbit_frame_euler_deg(tr.r, tr.v, tr.Q2), run


def split_results(results, counts):
    """The sweep's lines cut into the input's parts (baseline, grid, Monte Carlo), in order."""
    parts, at = [], 0
    for n in counts:
        parts.append(results[at:at + n])
        at += n
    return parts


def fmt(beta):
    return "outside the grid" if beta is None else f"{beta:.3f}"


def load_average():
    return os.getloadavg() if hasattr(os, "getloadavg") else (float("nan"),) * 3


def scaling(args, rotlie_bin, out):
    """Times N short runs on one rank and on --ranks ranks."""
    m1, _ = start_frame(rotlie_bin)
    T = span(args.scaling_hours / 24)
    betas = np.linspace(1, 5, args.scaling)
    lines = grid_lines(betas, T, m1, args.grid_mass)
    for line in lines:
        line["observe"] = False
    runs = out / "scaling_runs.jsonl"
    write_jsonl(runs, lines)
    rows = []
    for ranks in sorted({1, args.ranks}):
        before = load_average()
        wall = run_sweep(rotlie_bin, runs, out / f"scaling_results_{ranks}.jsonl", ranks, args.mpirun)
        rows.append({"ranks": ranks, "wall_s": wall, "load_before": before[0], "load_after": load_average()[0]})
        print(f"{args.scaling} runs of {T:.0f} s on {ranks} rank(s): {wall:.1f} s wall "
              f"(load average {before[0]:.2f} before, {rows[-1]['load_after']:.2f} after)")
    if len(rows) == 2:
        print(f"speed-up on {args.ranks} ranks: {rows[0]['wall_s'] / rows[1]['wall_s']:.2f}x")
        a = read_results(out / "scaling_results_1.jsonl")
        b = read_results(out / f"scaling_results_{args.ranks}.jsonl")
        same = all(x["r"] == y["r"] and x["v"] == y["v"] for x, y in zip(a, b)) and len(a) == len(b)
        print(f"the two results files' final states {'equal' if same else 'DIFFER'} run for run")
    (out / "scaling.json").write_text(json.dumps({"runs": args.scaling, "T_s": T, "rows": rows}, indent=1) + "\n")


def study(args, rotlie_bin, out):
    T = span(args.days)
    m1, frame = start_frame(rotlie_bin)
    betas = np.linspace(args.beta_min, args.beta_max, args.betas)
    samples = monte_carlo_samples(args.runs, args.seed, args.direction_sigma)
    masses = np.concatenate([samples["m2"], [args.grid_mass]])
    baseline_masses = np.linspace(masses.min(), masses.max(), args.baselines) if args.baselines > 1 else np.array([args.grid_mass])
    parts = [baseline_lines(baseline_masses, T, m1), grid_lines(betas, T, m1, args.grid_mass), monte_carlo_lines(samples, frame, T, m1)]
    write_jsonl(out / "runs.jsonl", [line for part in parts for line in part])
    load = load_average()
    wall = run_sweep(rotlie_bin, out / "runs.jsonl", out / "results.jsonl", args.ranks, args.mpirun)
    print(f"{sum(map(len, parts))} runs of {T / DAY:g} days on {args.ranks} rank(s): {wall:.1f} s wall (load average {load[0]:.2f})")
    base, grid, mc = (list(map(observed, p)) for p in split_results(read_results(out / "results.jsonl"), map(len, parts)))
    before = period_before(baseline_masses, [b["period_h"] for b in base])
    grid_change = [(g["period_h"] - float(before(args.grid_mass))) * 60 for g in grid]
    mc_change = np.array([(r["period_h"] - float(before(m))) * 60 for r, m in zip(mc, samples["m2"])])

    fit = {f"{t:+.1f}": fit_beta(betas, grid_change, t) for t in (OBSERVED_MIN - OBSERVED_SIGMA_MIN, OBSERVED_MIN, OBSERVED_MIN + OBSERVED_SIGMA_MIN)}
    beta_fit = fit[f"{OBSERVED_MIN:+.1f}"]
    summary = {
        "setup": {"system": "didymos", "order": 4, "integrator": "SIER4", "h_s": H, "T_s": T, "primary_mass_kg": m1,
                  "grid_mass_kg": args.grid_mass, "betas": betas.tolist(), "runs": args.runs, "seed": args.seed,
                  "direction_sigma_deg": args.direction_sigma, "ranks": args.ranks, "wall_s": wall, "load_average": load[0]},
        "period_before_h": float(before(args.grid_mass)),
        "beta_fit": {"for_min": fit, "beta": beta_fit, "dv_mm_s": dart_dv(beta_fit, args.grid_mass) if beta_fit else None},
        "monte_carlo_min": {"mean": float(mc_change.mean()), "std": float(mc_change.std(ddof=1)) if len(mc_change) > 1 else 0.0,
                            "p5": float(np.percentile(mc_change, 5)), "p95": float(np.percentile(mc_change, 95)),
                            "within_observed": float(np.mean(np.abs(mc_change - OBSERVED_MIN) <= OBSERVED_SIGMA_MIN))},
        "excitation": {"grid_libration_deg": [g["libration_deg"] for g in grid],
                       "grid_npa_max_deg": [g["npa_max_deg"] for g in grid],
                       "grid_tumbling": sum(g["tumbling"] for g in grid),
                       "mc_tumbling": sum(r["tumbling"] for r in mc),
                       "mc_npa_max_deg": {"median": float(np.median([r["npa_max_deg"] for r in mc])),
                                          "max": float(max(r["npa_max_deg"] for r in mc))},
                       "mc_libration_deg": {"median": float(np.median([r["libration_deg"] for r in mc]))}},
        "inaccurate": sum(r["inaccurate"] for r in base + grid + mc),
    }
    write_table(out / "dart_beta.csv", baseline_masses, base, betas, args.grid_mass, grid, grid_change, samples, mc, mc_change, frame)
    (out / "dart_beta.json").write_text(json.dumps(summary, indent=1) + "\n")

    print(f"period before {summary['period_before_h']:.4f} h at M2 = {args.grid_mass:.3g} kg")
    for b, c, g in zip(betas, grid_change, grid):
        print(f"beta {b:5.2f}: {c:+7.2f} min, libration {g['libration_deg']:5.2f} deg, npa {g['npa_max_deg']:.2g} deg")
    band = fit[f"{OBSERVED_MIN - OBSERVED_SIGMA_MIN:+.1f}"], fit[f"{OBSERVED_MIN + OBSERVED_SIGMA_MIN:+.1f}"]
    if beta_fit is not None:
        print(f"beta for {OBSERVED_MIN:+.1f} min: {beta_fit:.3f} (dv {dart_dv(beta_fit, args.grid_mass):.3f} mm/s; "
              f"{OBSERVED_MIN:+.1f} -+ {OBSERVED_SIGMA_MIN:.1f} min: beta {fmt(band[1])} to {fmt(band[0])})")
    else:
        print(f"beta for {OBSERVED_MIN:+.1f} min: outside the grid")
    s = summary["monte_carlo_min"]
    print(f"Monte Carlo ({args.runs} runs, seed {args.seed}): {s['mean']:+.2f} +- {s['std']:.2f} min, 5-95 % "
          f"{s['p5']:+.2f} to {s['p95']:+.2f}; {100 * s['within_observed']:.1f} % within {OBSERVED_MIN:+.1f} +- {OBSERVED_SIGMA_MIN:.1f}")
    e = summary["excitation"]
    print(f"tumbling (G > 1 deg off the maximum-moment axis): {e['grid_tumbling']} of {len(grid)} grid runs, "
          f"{e['mc_tumbling']} of {len(mc)} Monte Carlo runs (their largest angle: median {e['mc_npa_max_deg']['median']:.3g}, "
          f"max {e['mc_npa_max_deg']['max']:.3g} deg); inaccurate runs: {summary['inaccurate']}")

    charts(out, args, betas, grid_change, grid, samples, mc, mc_change, beta_fit, band)
    t, planar, _ = euler_series(m1, args.grid_mass, frame, 0.0, args.series_days, args.every)
    _, tilted, tilted_run = euler_series(m1, args.grid_mass, frame, args.direction_sigma, args.series_days, args.every)
    state = tilted_run.observables["spin_state"]["secondary"]
    print(f"beta = {BETA} over {args.series_days:g} days: along track roll {np.abs(planar[:, 0]).max():.2g}, pitch "
          f"{np.abs(planar[:, 1]).max():.2g}, yaw {np.abs(planar[:, 2]).max():.2f} deg; tilted {args.direction_sigma:g} deg out of "
          f"the plane roll {np.abs(tilted[:, 0]).max():.2f}, pitch {np.abs(tilted[:, 1]).max():.2f}, yaw {np.abs(tilted[:, 2]).max():.2f} deg, "
          f"G {state['npa_angle_max_deg']:.2f} deg off C ({'tumbling' if state['tumbling'] else 'not tumbling'})")
    series_chart(out / "euler_series.png", t, planar, tilted, args.direction_sigma)
    return summary


def write_table(path, baseline_masses, base, betas, grid_mass, grid, grid_change, samples, mc, mc_change, frame):
    head = ("kind,beta,m2_kg,alpha_deg,delta_deg,dv_x_mm_s,dv_y_mm_s,dv_z_mm_s,period_h,period_change_min,libration_deg,"
            "roll_max_deg,pitch_max_deg,npa_max_deg,tumbling,inaccurate")
    rows = [head]

    def row(kind, beta, m2, a, d, dv, r, change):
        return (f"{kind},{beta:.6g},{m2:.6g},{a:.6g},{d:.6g},{dv[0]:.9g},{dv[1]:.9g},{dv[2]:.9g},{r['period_h']:.9f},{change:.6f},"
                f"{r['libration_deg']:.6g},{r['roll_max_deg']:.6g},{r['pitch_max_deg']:.6g},{r['npa_max_deg']:.6g},{int(r['tumbling'])},"
                f"{int(r['inaccurate'])}")
    for m, r in zip(baseline_masses, base):
        rows.append(row("baseline", 0, m, 0, 0, (0, 0, 0), r, 0))
    for b, r, c in zip(betas, grid, grid_change):
        rows.append(row("grid", b, grid_mass, 0, 0, dv_vector(b, grid_mass, 0, 0, frame), r, c))
    for k, (r, c) in enumerate(zip(mc, mc_change)):
        b, m, a, d = (samples[key][k] for key in ("beta", "m2", "alpha_deg", "delta_deg"))
        rows.append(row("monte_carlo", b, m, a, d, dv_vector(b, m, a, d, frame), r, c))
    path.write_text("\n".join(rows) + "\n")


def charts(out, args, betas, grid_change, grid, samples, mc, mc_change, beta_fit, band):
    fig, ax = plt.subplots(figsize=(7, 4.5))
    ax.axhspan(OBSERVED_MIN - OBSERVED_SIGMA_MIN, OBSERVED_MIN + OBSERVED_SIGMA_MIN, color="tab:orange", alpha=0.3,
               label="observed -33.0 ± 1.0 min (Thomas et al. 2023)")
    ax.scatter(samples["beta"], mc_change, s=4, color="0.6", label=f"Monte Carlo ({len(mc)} runs)")
    ax.plot(betas, grid_change, "o-", color="tab:blue", label=f"along track, M2 = {args.grid_mass:.3g} kg")
    if beta_fit is not None:
        ax.axvline(beta_fit, color="tab:red", lw=1, label=f"β = {beta_fit:.2f} for -33.0 min")
        if None not in band:
            ax.axvspan(band[1], band[0], color="tab:red", alpha=0.15)
    ax.set_xlabel("β")
    ax.set_ylabel("orbit period change (min)")
    ax.set_title(f"Didymos, order 4, SIER4 h = {H:.0f} s over {args.days:g} days")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out / "period_vs_beta.png", dpi=120)
    plt.close(fig)

    fig, ax = plt.subplots(figsize=(7, 4.5))
    ax.hist(mc_change, bins=40, color="tab:blue", alpha=0.8)
    ax.axvspan(OBSERVED_MIN - OBSERVED_SIGMA_MIN, OBSERVED_MIN + OBSERVED_SIGMA_MIN, color="tab:orange", alpha=0.3, label="observed")
    mean, std = mc_change.mean(), (mc_change.std(ddof=1) if len(mc_change) > 1 else 0.0)
    p5, p95 = np.percentile(mc_change, [5, 95])
    ax.axvline(mean, color="k", label=f"mean {mean:+.2f} ± {std:.2f} min")
    for p in (p5, p95):
        ax.axvline(p, color="k", ls="--", lw=0.8)
    ax.set_xlabel("orbit period change (min)")
    ax.set_ylabel("runs")
    ax.set_title(f"{len(mc)} pushes: β 3.61 +0.19/−0.25, M2 4.3 ± 0.25e9 kg, direction ± {args.direction_sigma:g}°; 5–95 % dashed",
                 fontsize=9)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out / "period_histogram.png", dpi=120)
    plt.close(fig)

    fig, (top, bottom) = plt.subplots(2, 1, figsize=(7, 6.5), sharex=True)
    top.scatter(samples["beta"], [r["libration_deg"] for r in mc], s=4, color="0.6", label="Monte Carlo")
    top.plot(betas, [g["libration_deg"] for g in grid], "o-", color="tab:blue", label="along track")
    top.set_ylabel("libration amplitude (deg)")
    top.legend(fontsize=8)
    delta = np.abs(samples["delta_deg"])
    sc = bottom.scatter(samples["beta"], [max(r["npa_max_deg"], 1e-6) for r in mc], s=5, c=delta, cmap="viridis",
                        label="Monte Carlo (colour: |out-of-plane tilt|, deg)")
    fig.colorbar(sc, ax=bottom)
    bottom.plot(betas, [max(g["npa_max_deg"], 1e-6) for g in grid], "o-", color="tab:blue", label="along track (0: planar)")
    bottom.axhline(1.0, color="tab:red", lw=1, label="tumbling threshold 1°")
    bottom.set_yscale("log")
    bottom.set_ylabel("G off the max-moment axis, largest (deg)")
    bottom.set_xlabel("β")
    bottom.legend(fontsize=8)
    top.set_title(f"Dimorphos's attitude over {args.days:g} days after the push")
    fig.tight_layout()
    fig.savefig(out / "excitation_vs_beta.png", dpi=120)
    plt.close(fig)


def series_chart(path, t, planar, tilted, sigma):
    fig, axes = plt.subplots(3, 1, figsize=(8, 7), sharex=True)
    days = t / DAY
    for k, (ax, name) in enumerate(zip(axes, ("roll", "pitch", "yaw"))):
        ax.plot(days, planar[:, k], lw=0.6, label="along track")
        ax.plot(days, tilted[:, k], lw=0.6, label=f"tilted {sigma:g}° out of the plane")
        ax.set_ylabel(f"{name} (deg)")
    axes[0].legend(fontsize=8)
    axes[0].set_title(f"Dimorphos in the orbit frame after DART, β = {BETA}")
    axes[-1].set_xlabel("days")
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def parser():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--out", default="dart-beta")
    p.add_argument("--ranks", type=int, default=2)
    p.add_argument("--runs", type=int, default=1000, help="Monte Carlo runs")
    p.add_argument("--seed", type=int, default=2022)
    p.add_argument("--days", type=float, default=5)
    p.add_argument("--betas", type=int, default=17, help="grid values from --beta-min to --beta-max")
    p.add_argument("--beta-min", type=float, default=1.0)
    p.add_argument("--beta-max", type=float, default=5.0)
    p.add_argument("--grid-mass", type=float, default=M2_KG, help="Dimorphos's mass for the grid (kg)")
    p.add_argument("--baselines", type=int, default=5, help="runs without the push, over the masses")
    p.add_argument("--direction-sigma", type=float, default=3.0, help="each tilt's standard deviation (deg; assumed)")
    p.add_argument("--series-days", type=float, default=30)
    p.add_argument("--every", type=int, default=10, help="the time series' sampling in steps")
    p.add_argument("--scaling", type=int, default=0, help="time N runs on 1 and --ranks ranks instead")
    p.add_argument("--scaling-hours", type=float, default=12)
    p.add_argument("--rotlie", help="the rotlie binary")
    p.add_argument("--mpirun", help="the mpirun command")
    return p


def main(argv=None):
    args = parser().parse_args(argv)
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    rotlie_bin = find_rotlie(args.rotlie)
    if args.scaling:
        scaling(args, rotlie_bin, out)
        return
    study(args, rotlie_bin, out)
    print(f"wrote {out / 'dart_beta.csv'}, {out / 'dart_beta.json'} and four charts in {out}")


if __name__ == "__main__":
    main()
