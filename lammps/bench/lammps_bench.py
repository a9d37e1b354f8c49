#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Benchmark of rotlie's fix styles inside LAMMPS (not a test).

Rigid TIP3P with lj/cut/coul/long 9 Å and pppm 1e-5 (in.tip3p-bench), 512, 4,096 and 32,768
molecules (the melted 512 of in.tip3p-equilibrate replicated), on 1 and 2 MPI ranks: ms per step
and per force evaluation of rigid/nve/small, rigid/sier2/small and rigid/sier4/small, and their
ΔE/ΔV (rms fluctuation of etotal over that of pe, sampled every step, in per cent: the definition
of rotlie's liquid-water section). At 512 molecules on 1 rank each integrator also runs at several
steps h, for the chart of ΔE/ΔV against CPU time per simulated ps.

Writes into --out (default build/release/lammps-bench; never a source folder):
  lammps_bench.csv   one row per run
  lammps_goals.csv   the issue's goals evaluated on those rows
  lammps_bench.png   ΔE/ΔV against CPU ms per simulated ps (512 molecules, 1 rank)
  summary.md         the table and the goals in markdown
  runs/              LAMMPS's logs

Cost: the default sweep is about 8 minutes of wall time on 2 idle cores (estimated from the CPU time
LAMMPS reported; measured: 18 minutes at a load average of 3.4 to 7.5). --full (1-ps energy runs at
every size, three timing repeats, a finer h grid) about 30 minutes on 2 idle cores, estimated from
the same per-step costs, not run. --floor adds about 7 minutes.
"""
import argparse
import csv
import math
import os
import re
import shutil
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
EXAMPLE_MOLECULE = os.path.join(REPO, "examples", "lammps", "tip3p.mol")

# (name in the CSV, fix style, extra fix keywords, force evaluations per step)
INTEGRATORS = {
    "rigid/nve/small": ("rigid/nve/small", "", 1),
    "rigid/sier2/small": ("rigid/sier2/small", "rotor exact", 1),
    "rigid/sier4/small": ("rigid/sier4/small", "rotor exact", 4),
    "rigid/sier2/small ABCBA2": ("rigid/sier2/small", "rotor ABCBA2:ABC", 1),  # a table rotor: the stages alone
}
# the table's step: the same h/f = 2 fs for all three (equal force evaluations per simulated ps)
TABLE_H = {"rigid/nve/small": 2.0, "rigid/sier2/small": 2.0, "rigid/sier4/small": 8.0, "rigid/sier2/small ABCBA2": 2.0}
REPLICAS = {512: (1, 1, 1), 4096: (2, 2, 2), 32768: (4, 4, 4)}


def fail(message):
    print("lammps_bench: " + message, file=sys.stderr)
    sys.exit(2)


def budget(full):
    """Per size: (force evaluations per timed run, timing repeats, simulated ps of the energy run)."""
    if full:
        return {512: (400, 3, 1.0), 4096: (100, 3, 1.0), 32768: (40, 3, 1.0)}
    return {512: (200, 2, 0.5), 4096: (60, 2, 0.2), 32768: (20, 1, 0.1)}


def chart_steps(full):
    if full:
        return {"rigid/nve/small": [0.5, 0.75, 1, 1.5, 2, 3, 4], "rigid/sier2/small": [0.5, 0.75, 1, 1.5, 2, 3, 4],
                "rigid/sier4/small": [2, 3, 4, 6, 8, 12, 16, 20]}
    return {"rigid/nve/small": [0.5, 1, 2, 3], "rigid/sier2/small": [0.5, 1, 2, 3],
            "rigid/sier4/small": [2, 4, 8, 12, 16]}


def parse_log(path):
    """The loop times, CPU use, Modify times and thermo rows of every `run` in a LAMMPS log."""
    runs, rows, in_thermo = [], [], False
    with open(path, errors="replace") as log:
        for line in log:
            if line.split()[:3] == ["Step", "PotEng", "TotEng"]:
                in_thermo, rows = True, []
                continue
            m = re.match(r"Loop time of (\S+) on (\d+) procs for (\d+) steps", line)
            if m:
                in_thermo = False
                runs.append({"loop": float(m.group(1)), "procs": int(m.group(2)), "steps": int(m.group(3)),
                             "rows": rows, "cpu_use": math.nan, "modify": math.nan})
                continue
            m = re.match(r"\s*([\d.]+)% CPU use with", line)
            if m and runs:
                runs[-1]["cpu_use"] = float(m.group(1))
            m = re.match(r"Modify\s*\|\s*\S+\s*\|\s*(\S+)", line)
            if m and runs:
                runs[-1]["modify"] = float(m.group(1))
            if in_thermo:
                parts = line.split()
                if len(parts) == 3:
                    try:
                        rows.append((int(parts[0]), float(parts[1]), float(parts[2])))
                    except ValueError:
                        in_thermo = False
    return runs


def std(values):
    n = len(values)
    mean = sum(values) / n
    return math.sqrt(sum((v - mean) ** 2 for v in values) / n)


class Runner:
    def __init__(self, args, out):
        self.args, self.out = args, out
        self.logs = os.path.join(out, "runs")
        os.makedirs(self.logs, exist_ok=True)

    def command(self, ranks, lmp_args):
        env_threads = ["-x", "OMP_NUM_THREADS=1"]
        if ranks == 1:
            return [self.args.lmp] + lmp_args
        yield_ = ["--mca", "mpi_yield_when_idle", "1"] if self.args.mpi_yield else []
        return [self.args.mpiexec, "--allow-run-as-root", "--oversubscribe", "--bind-to", "none"] + yield_ + env_threads + \
               ["-np", str(ranks), self.args.lmp] + lmp_args

    def lammps(self, name, ranks, input_file, variables):
        log = os.path.join(self.logs, name + ".log")
        lmp_args = ["-in", input_file, "-log", log, "-screen", "none"]
        for key, value in variables.items():
            lmp_args += ["-var", key, str(value)]
        env = dict(os.environ, OMP_NUM_THREADS="1")
        done = subprocess.run(self.command(ranks, lmp_args), cwd=self.out, env=env, capture_output=True, text=True)
        return done.returncode, log, (done.stdout + done.stderr).strip()


def equilibrate(runner):
    data = os.path.join(runner.out, "start.data")
    print("equilibrating 512 TIP3P (rigid/nvt/small, 2 ps at 1 fs)", flush=True)
    code, log, text = runner.lammps("equilibrate", 1, os.path.join(HERE, "in.tip3p-equilibrate"),
                                    {"mol": EXAMPLE_MOLECULE, "data": data, "equil": 2000})
    if code != 0 or not os.path.exists(data):
        fail("equilibration failed (see %s): %s" % (log, text.splitlines()[-1] if text else "no output"))
    return data


def measure(runner, data, molecules, ranks, integrator, h, timed_evaluations, repeats, energy_ps, purpose, shift="no", kacc="1.0e-5"):
    fix, fix_args, f = INTEGRATORS[integrator]
    tsteps = max(5, round(timed_evaluations / f))
    esteps = max(10, round(energy_ps * 1000 / h))
    rx, ry, rz = REPLICAS[molecules]
    name = "%s-%d-%dr-%s-h%g%s" % (purpose, molecules, ranks, integrator.replace("/", "_"), h,
                                   "" if (shift, kacc) == ("no", "1.0e-5") else "-shift_%s-pppm_%s" % (shift, kacc))
    load_before = os.getloadavg()[0]
    started = time.time()
    code, log, text = runner.lammps(name, ranks, os.path.join(HERE, "in.tip3p-bench"),
                                    {"data": data, "rx": rx, "ry": ry, "rz": rz, "fix": fix, "args": fix_args,
                                     "dt": h, "tsteps": tsteps, "repeats": repeats, "esteps": esteps,
                                     "shift": shift, "kacc": kacc})
    row = {"purpose": purpose, "molecules": molecules, "ranks": ranks, "integrator": integrator, "h_fs": h, "f": f,
           "lj_shift": shift, "pppm_accuracy": kacc,
           "timed_steps": tsteps, "repeats": repeats, "energy_steps": esteps, "load_before": round(load_before, 2)}
    runs = parse_log(log) if os.path.exists(log) else []
    energy = runs[repeats]["rows"] if code == 0 and len(runs) == repeats + 1 else []
    finite = len(energy) == esteps + 1 and all(math.isfinite(e) and math.isfinite(v) for _, v, e in energy)
    if not finite:
        row["status"] = "diverged" if runs else "failed"
        row["message"] = (text.splitlines() or ["no output"])[-1][:200]
    else:
        timed = min(runs[:repeats], key=lambda r: r["loop"])
        wall_ms = 1000 * timed["loop"] / tsteps
        cpu_ms = wall_ms * ranks * timed["cpu_use"] / 100
        pe = [v for _, v, _ in energy]
        etotal = [e for _, _, e in energy]
        row.update({"status": "ok", "wall_ms_per_step": wall_ms, "wall_ms_per_force": wall_ms / f,
                    "modify_ms_per_step": 1000 * timed["modify"] / tsteps,
                    # the fixes' own time per molecule, each rank's share (CPU µs per molecule and step)
                    "modify_us_per_molecule": 1e6 * timed["modify"] / tsteps * ranks / molecules,
                    "cpu_use_percent": timed["cpu_use"],
                    "cpu_ms_per_step": cpu_ms, "cpu_ms_per_ps": cpu_ms * 1000 / h,
                    "std_etotal": std(etotal), "std_pe": std(pe),
                    "dE_over_dV_percent": 100 * std(etotal) / std(pe) if std(pe) > 0 else math.nan,
                    "pe_per_molecule": sum(pe) / len(pe) / molecules})
    row["load_after"] = round(os.getloadavg()[0], 2)
    row["seconds"] = round(time.time() - started, 1)
    print("  %-8s %6d mol %d rank(s) %-18s h=%-4g %-8s %s" % (
        purpose + ("" if (shift, kacc) == ("no", "1.0e-5") else " (shift %s, pppm %s)" % (shift, kacc)), molecules, ranks, integrator, h, row["status"],
        "%.2f ms/step, ΔE/ΔV %.3g %%, load %.1f" % (row["wall_ms_per_step"], row["dE_over_dV_percent"], load_before)
        if row["status"] == "ok" else row.get("message", "")), flush=True)
    return row


def log_interpolate(points, x):
    """log y at log x on the broken line through points (x, y) sorted by x; None outside their range."""
    for (x0, y0), (x1, y1) in zip(points, points[1:]):
        if x0 <= x <= x1:
            t = (math.log(x) - math.log(x0)) / (math.log(x1) - math.log(x0)) if x1 > x0 else 0
            return math.exp(math.log(y0) + t * (math.log(y1) - math.log(y0)))
    return None


def goals(rows):
    out = []
    ok = [r for r in rows if r["status"] == "ok"]

    def find(purpose, molecules, ranks, integrator):
        for r in ok:
            if (r["purpose"], r["molecules"], r["ranks"], r["integrator"]) == (purpose, molecules, ranks, integrator):
                return r
        return None

    # SIER2 per step against rigid/nve/small (goal ≤ 1.05): whole step, and by the integrators' own time
    for molecules in sorted({r["molecules"] for r in ok}):
        for ranks in sorted({r["ranks"] for r in ok}):
            nve, sier2 = find("table", molecules, ranks, "rigid/nve/small"), find("table", molecules, ranks, "rigid/sier2/small")
            if nve and sier2:
                whole = sier2["wall_ms_per_step"] / nve["wall_ms_per_step"]
                cpu = sier2["cpu_ms_per_step"] / nve["cpu_ms_per_step"]
                # same forces, so the step differs by the fix's own (Modify) time only: less noisy
                own = (nve["wall_ms_per_step"] - nve["modify_ms_per_step"] + sier2["modify_ms_per_step"]) / nve["wall_ms_per_step"]
                out.append({"goal": "SIER2 step / rigid/nve/small step <= 1.05", "molecules": molecules, "ranks": ranks,
                            "value": cpu, "alternative": whole, "met": cpu <= 1.05,
                            "note": "value: CPU time (wall x LAMMPS's CPU use x ranks, robust to other load); alternative: "
                                    "wall time; by the fixes' own Modify time: %.3f" % own})
    # the exact rotor's own time against NO_SQUISH's (issue 34: fix time ≤ 1.2, SIER2's whole step ≤ 1.02), and
    # the ABCBA2 table rotor's beside them
    for molecules in sorted({r["molecules"] for r in ok}):
        for ranks in sorted({r["ranks"] for r in ok}):
            nve = find("table", molecules, ranks, "rigid/nve/small")
            for integrator, goal in (("rigid/sier2/small", 1.2), ("rigid/sier2/small ABCBA2", None)):
                other = find("table", molecules, ranks, integrator)
                if not (nve and other and nve["modify_ms_per_step"] > 0):
                    continue
                ratio = other["modify_ms_per_step"] / nve["modify_ms_per_step"]
                out.append({"goal": "%s fix (Modify) time / rigid/nve/small's%s" % (integrator, " <= %g" % goal if goal else " (measured)"),
                            "molecules": molecules, "ranks": ranks, "value": ratio,
                            "alternative": other["modify_us_per_molecule"], "met": ratio <= goal if goal else "n/a",
                            "note": "alternative: its CPU µs per molecule and step (rigid/nve/small: %.3f)" % nve["modify_us_per_molecule"]})
            sier2 = find("table", molecules, ranks, "rigid/sier2/small")
            if nve and sier2:
                whole = (nve["wall_ms_per_step"] - nve["modify_ms_per_step"] + sier2["modify_ms_per_step"]) / nve["wall_ms_per_step"]
                out.append({"goal": "SIER2 whole step / rigid/nve/small's <= 1.02", "molecules": molecules, "ranks": ranks,
                            "value": whole, "alternative": sier2["wall_ms_per_step"] / nve["wall_ms_per_step"], "met": whole <= 1.02,
                            "note": "value: the same forces, the step differing by the fixes' own time; alternative: the wall times' ratio"})
    # SIER4 against rigid/nve/small at equal CPU per ps (goal ≥ 10): each rigid/nve/small point against SIER4's
    # broken line in log-log, within one force field (the chart's, and each of --floor's)
    groups = {}
    for r in ok:
        if r["purpose"] in ("chart", "floor"):
            key = (r["purpose"], r["lj_shift"], r["pppm_accuracy"])
            groups.setdefault(key, {}).setdefault(r["integrator"], []).append((r["cpu_ms_per_ps"], r["dE_over_dV_percent"], r["h_fs"]))
    for (purpose, shift, kacc), chart in groups.items():
        sier4 = sorted((x, y) for x, y, _ in chart.get("rigid/sier4/small", []))
        for x, y, h in sorted(chart.get("rigid/nve/small", [])):
            y4 = log_interpolate(sier4, x)
            out.append({"goal": "nve dE/dV / sier4 dE/dV at equal CPU per ps >= 10", "molecules": 512, "ranks": 1,
                        "value": y / y4 if y4 else math.nan, "alternative": x, "met": (y / y4 >= 10) if y4 else "n/a",
                        "note": "rigid/nve/small at h = %g fs; LJ shifted %s, pppm %s; alternative: its CPU ms per ps%s"
                                % (h, shift, kacc, "" if y4 else " (outside SIER4's measured CPU range)")})
    # 1 -> 2 ranks at 32,768 molecules (goal ≥ 1.8 in wall time)
    for integrator in INTEGRATORS:
        one, two = find("table", 32768, 1, integrator), find("table", 32768, 2, integrator)
        if one and two:
            out.append({"goal": "1 -> 2 ranks wall-time speed-up at 32768 >= 1.8", "molecules": 32768, "ranks": 2,
                        "value": one["wall_ms_per_step"] / two["wall_ms_per_step"],
                        "alternative": two["load_before"], "met": one["wall_ms_per_step"] / two["wall_ms_per_step"] >= 1.8,
                        "note": "%s; alternative: load average before the 2-rank run; CPU use %.0f %% on 1 rank, %.0f %% per rank on 2"
                                % (integrator, one["cpu_use_percent"], two["cpu_use_percent"])})
    return out


TEXT_COLUMNS = {"purpose", "integrator", "status", "message", "lj_shift", "pppm_accuracy"}


def read_rows(path):
    """The rows of a lammps_bench.csv, numbers as numbers (for --render-only)."""
    rows = []
    with open(path, newline="") as f:
        for r in csv.DictReader(f):
            row = {}
            for k, v in r.items():
                if k in TEXT_COLUMNS or v == "":
                    row[k] = v
                else:
                    row[k] = int(v) if re.fullmatch(r"-?\d+", v) else float(v)
            row["lj_shift"] = row.get("lj_shift") or "no"
            row["pppm_accuracy"] = row.get("pppm_accuracy") or "1.0e-5"
            rows.append({k: v for k, v in row.items() if v != ""})
    return rows


def write_csv(path, rows):
    keys = []
    for r in rows:
        keys += [k for k in r if k not in keys]
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=keys)
        w.writeheader()
        for r in rows:
            w.writerow({k: ("%.6g" % v if isinstance(v, float) else v) for k, v in r.items()})


def write_chart(path, rows):
    if not any(r["purpose"] == "chart" and r["status"] == "ok" for r in rows):
        return
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("lammps_bench: matplotlib is missing: no chart", file=sys.stderr)
        return
    fig, ax = plt.subplots(figsize=(7, 5))
    for integrator, marker in zip(INTEGRATORS, "os^v"):
        pts = sorted((r["cpu_ms_per_ps"], r["dE_over_dV_percent"], r["h_fs"]) for r in rows
                     if r["purpose"] == "chart" and r["integrator"] == integrator and r["status"] == "ok")
        if not pts:
            continue
        ax.loglog([p[0] for p in pts], [p[1] for p in pts], marker=marker, label=integrator)
        for x, y, h in pts:
            ax.annotate("%g fs" % h, (x, y), textcoords="offset points", xytext=(4, 4), fontsize=7)
    ax.set_xlabel("CPU time per simulated ps (ms)")
    ax.set_ylabel("ΔE/ΔV (%)")
    ax.set_title("512 rigid TIP3P, lj/cut/coul/long + pppm 1e-5, 1 rank")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(path, dpi=120)


def summary(path, rows, goal_rows, args, seconds, loads):
    def g(r, key, fmt):
        return fmt % r[key] if r.get("status") == "ok" and key in r else r.get("status", "")

    with open(path, "w") as f:
        f.write("# rotlie inside LAMMPS: benchmark\n\n")
        f.write("Rigid TIP3P, lj/cut/coul/long 9 Å, pppm 1e-5; %s; load average (1 min) between %.2f and %.2f during "
                "the runs on %d cores (it counts the benchmark's own 1 or 2 processes).\n\n" % (
                    "rendered again from lammps_bench.csv" if seconds is None else
                    "%s sweep, %.0f s wall" % ("full" if args.full else "default", seconds), min(loads), max(loads), os.cpu_count()))
        f.write("| molecules | ranks | integrator | h (fs) | wall ms/step | ms per force evaluation | fix's own ms/step | "
                "CPU ms per ps | ΔE/ΔV (%) | load |\n|--:|--:|:--|--:|--:|--:|--:|--:|--:|--:|\n")
        for r in rows:
            if r["purpose"] == "table":
                f.write("| %d | %d | %s | %g | %s | %s | %s | %s | %s | %.2f |\n" % (
                    r["molecules"], r["ranks"], r["integrator"], r["h_fs"], g(r, "wall_ms_per_step", "%.2f"),
                    g(r, "wall_ms_per_force", "%.2f"), g(r, "modify_ms_per_step", "%.3f"), g(r, "cpu_ms_per_ps", "%.0f"),
                    g(r, "dE_over_dV_percent", "%.3g"), r["load_before"]))
        floor = [r for r in rows if r["purpose"] in ("floor", "chart") and r["status"] == "ok"]
        if any(r["purpose"] == "floor" for r in floor):
            f.write("\n| integrator | h (fs) | LJ shifted | PPPM accuracy | ΔE/ΔV (%) |\n|:--|--:|:--|--:|--:|\n")
            for r in floor:
                f.write("| %s | %g | %s | %s | %.3g |\n" % (r["integrator"], r["h_fs"], r["lj_shift"], r["pppm_accuracy"],
                                                         r["dE_over_dV_percent"]))
        f.write("\n| goal | molecules | ranks | value | alternative | met | note |\n|:--|--:|--:|--:|--:|:--|:--|\n")
        for r in goal_rows:
            f.write("| %s | %d | %d | %.3g | %.3g | %s | %s |\n" % (r["goal"], r["molecules"], r["ranks"], r["value"],
                                                                 r["alternative"], r["met"], r["note"]))


def main():
    default_build = os.path.join(REPO, "build", "release")
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0], formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--lmp", default=os.path.join(default_build, "bin", "lmp_rotlie"), help="lmp_rotlie to run")
    p.add_argument("--mpiexec", default=shutil.which("mpirun") or "mpirun", help="MPI launcher for 2 ranks")
    p.add_argument("--out", default=os.path.join(default_build, "lammps-bench"), help="output folder (not a source folder)")
    p.add_argument("--sizes", default="512,4096,32768", help="molecule counts among 512, 4096, 32768")
    p.add_argument("--ranks", default="1,2", help="MPI rank counts")
    p.add_argument("--no-chart", action="store_true", help="skip the several-h sweep at 512 molecules")
    p.add_argument("--floor", action="store_true",
                   help="also the energy floor's diagnosis at 512 molecules: the smallest steps with the LJ energy "
                        "shifted to 0 at the cutoff, and with pppm 1e-6 and 1e-7 (about 7 minutes)")
    p.add_argument("--mpi-yield", action="store_true",
                   help="ranks yield the core while they wait (Open MPI's mpi_yield_when_idle; helps on a loaded machine)")
    p.add_argument("--render-only", action="store_true",
                   help="run nothing: the goals, chart and summary again from --out's lammps_bench.csv")
    p.add_argument("--full", action="store_true", help="1-ps energy runs, 3 timing repeats, finer h: about 30 min on 2 idle cores")
    args = p.parse_args()

    out = os.path.abspath(args.out)
    real = os.path.realpath(out)
    if (real + os.sep).startswith(os.path.realpath(REPO) + os.sep) and \
            not (real + os.sep).startswith(os.path.realpath(os.path.join(REPO, "build")) + os.sep):
        fail("--out %s is inside the source tree: give a folder under build/ or outside the repository" % out)
    if not os.access(args.lmp, os.X_OK):
        fail("no lmp_rotlie at %s (build the target lmp_rotlie, or give --lmp)" % args.lmp)
    try:
        sizes = [int(s) for s in args.sizes.split(",")]
        ranks = [int(s) for s in args.ranks.split(",")]
    except ValueError:
        fail("--sizes and --ranks take comma-separated integers")
    if any(s not in REPLICAS for s in sizes) or any(r < 1 for r in ranks):
        fail("--sizes takes 512, 4096, 32768 and --ranks positive integers")
    if any(r > 1 for r in ranks) and not shutil.which(args.mpiexec):
        fail("no MPI launcher %s for more than one rank" % args.mpiexec)
    os.makedirs(out, exist_ok=True)
    if args.render_only:
        if not os.path.exists(os.path.join(out, "lammps_bench.csv")):
            fail("--render-only: no lammps_bench.csv in %s" % out)
        rows = read_rows(os.path.join(out, "lammps_bench.csv"))
        render(out, rows, args, None)
        return

    started = time.time()
    runner = Runner(args, out)
    data = equilibrate(runner)
    b = budget(args.full)
    rows = []
    for molecules in sizes:
        timed, repeats, energy_ps = b[molecules]
        for n in ranks:
            for integrator in INTEGRATORS:
                rows.append(measure(runner, data, molecules, n, integrator, TABLE_H[integrator], timed, repeats, energy_ps, "table"))
    if not args.no_chart:
        timed, repeats, energy_ps = b[512]
        for integrator, steps in chart_steps(args.full).items():
            for h in steps:
                rows.append(measure(runner, data, 512, 1, integrator, h, timed, 1, energy_ps, "chart"))
    if args.floor:
        timed, repeats, energy_ps = b[512]
        for shift, kacc in (("yes", "1.0e-5"), ("yes", "1.0e-6"), ("yes", "1.0e-7")):
            for integrator, h in (("rigid/nve/small", 0.5), ("rigid/nve/small", 1), ("rigid/nve/small", 2), ("rigid/sier4/small", 2),
                                  ("rigid/sier4/small", 4), ("rigid/sier4/small", 8)):
                rows.append(measure(runner, data, 512, 1, integrator, h, timed, 1, energy_ps, "floor", shift, kacc))
    write_csv(os.path.join(out, "lammps_bench.csv"), rows)
    render(out, rows, args, time.time() - started)


def render(out, rows, args, seconds):
    goal_rows = goals(rows)
    write_csv(os.path.join(out, "lammps_goals.csv"), goal_rows)
    write_chart(os.path.join(out, "lammps_bench.png"), rows)
    loads = [r["load_before"] for r in rows] + [r["load_after"] for r in rows]
    summary(os.path.join(out, "summary.md"), rows, goal_rows, args, seconds, loads)
    print("wrote %s/{lammps_bench.csv,lammps_goals.csv,lammps_bench.png,summary.md}%s" % (
        out, "" if seconds is None else " in %.0f s" % seconds))


if __name__ == "__main__":
    main()
