#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Thermostatted rigid TIP3P at 300 K against the time step: LAMMPS's rigid/nvt/small and rigid/small
langevin against rotlie's rigid/sier2/nvt/small, rigid/sier2/small langevin, rigid/sier4/nvt/small and
rigid/sier4/small langevin, at h = 1, 2, 4, 6, 8 fs (--steps).

The system: --molecules TIP3P molecules (n³; default 216) on a simple cubic lattice at 0.9973 g/cm³,
lj/cut/coul/long 9 Å with PPPM 1e-5 (as examples/lammps/in.tip3p-pppm), melted once for --melt steps
of 1 fs under rigid/nvt/small and written as a data file. Each run starts from it: --equil ps to settle
at the run's step, then --sample ps measured every 20 fs. Thermostats: Tdamp = Tperiod = 100 fs;
langevin seed 4711.

For each run the table gives: the potential energy per molecule (kcal/mol; PPPM's, the intramolecular
pairs excluded), the translational and rotational temperatures at the step's end from compute ke/rigid
and erotate/rigid (2E/(3 N k_B)), and the CPU time per step (LAMMPS's loop time over the sampled
steps; SIER4 makes 4 force evaluations per step, the others 1). A run that LAMMPS stops (lost atoms, a
non-finite energy) is marked `failed`. Temperatures are those LAMMPS's thermo sees: under BAOAB
(rigid/sierN/small langevin) the step-end rotational temperature is low by about (hω)²/4 for the
librations ω (3.6 % at 4 fs), while the mid-step one (the fix's f_ID[2]) is unbiased: the table gives
it too (T_rot mid) for the langevin runs of the SIER fixes.

Cost: the runs are independent LAMMPS processes on one rank each (--ranks to change), --jobs at a
time. With the defaults (216 molecules, 1 ps + 4 ps per run, 30 runs) 10,208 steps per fix, 122,000
force evaluations in all (SIER4 makes 4 a step): 9.5 min wall (7.5 min CPU) on one core of a 2-core
machine shared with other work. With --dsf --melt 20000 --equil 1 --sample 10 --ref-sample 20 --jobs 2 (216
molecules; 31 runs, 1 ps + 10 ps each, the reference 1 ps + 20 ps at 0.5 fs; 312,000 force evaluations)
22 min wall and 21 min of LAMMPS's CPU time on a 2-core machine shared with other work (load average
3.6–5.4), plus the shared melt (20,000 steps of 1 fs: 3.5 min wall) and lammps_tconf (about 6 s a run:
209 frames, five force evaluations each). Not run by ctest.

--dsf: the interaction is lj/cut/coul/dsf (α = --dsf-alpha, 0.2 /Å as rotlie's lammps_dsf; cutoff
--dsf-cutoff, 9 Å by default since rotlie's minimum image needs a box longer than twice the cutoff:
rotlie's own 11 Å needs 512 molecules or more), the Lennard-Jones shifted to zero there, the
intramolecular pairs excluded from the neighbour list (`neigh_modify exclude molecule/intra`, as
lammps_water_pair_lines; `special_bonds` 0 alone would leave LAMMPS's DSF a constant −erf(αr)/r term
per intramolecular pair: the dynamics are the same, V is not rotlie's). The start is melted under it
(its own data file). During sampling the site positions and per-atom energies are dumped every
--dump-every fs (the nearest whole number of steps), and bench's lammps_tconf (--tconf) reads each
dump: V per molecule checked against LAMMPS's pe frame by frame (1e-6 relative, else the run is
marked), and the configurational temperatures T_conf,trans and T_conf,rot with standard errors from 10
blocks of the sample. A reference run is added (--reference, default rigid/sier2/small langevin at
0.5 fs, sampled for --ref-sample ps) and every row's V per molecule and configurational temperatures
are given as differences from it in units of their combined standard error (z). V per molecule
includes LAMMPS's DSF self energy (a constant, −41.04 kcal/mol per molecule at α = 0.2, 9 Å). The CPU
column is LAMMPS's loop time times its `% CPU use`, per step; the wall column the loop time per step.

Writes --out (default build/release/thermostat-sweep, build/release/thermostat-sweep-dsf with --dsf):
the inputs, LAMMPS's logs, sweep.csv, sweep.md.
"""
import argparse
import concurrent.futures
import csv
import math
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
BOLTZ = 0.0019872067  # LAMMPS's k_B in units real (kcal/mol/K)

FIXES = [
    ("rigid/nvt/small", "rigid/nvt/small molecule temp 300 300 100", False),
    ("rigid/small langevin", "rigid/small molecule langevin 300 300 100 4711", False),
    ("rigid/sier2/nvt/small", "rigid/sier2/nvt/small molecule temp 300 300 100", False),
    ("rigid/sier2/small langevin", "rigid/sier2/small molecule langevin 300 300 100 4711", True),
    ("rigid/sier4/nvt/small", "rigid/sier4/nvt/small molecule temp 300 300 100", False),
    ("rigid/sier4/small langevin", "rigid/sier4/small molecule langevin 300 300 100 4711", True),
]

SYSTEM = """units           real
atom_style      full
boundary        p p p
{start}
bond_style      zero
bond_coeff      1 0.9572
angle_style     zero
angle_coeff     1 104.52
special_bonds   lj/coul 0.0 0.0 0.0
{pair}neighbor        2.0 bin
neigh_modify    {exclude}every 1 delay 0 check yes
"""

PAIR_PPPM = """pair_style      lj/cut/coul/long 9.0
pair_coeff      1 1 0.1521 3.1507
pair_coeff      * 2 0.0 1.0
kspace_style    pppm 1.0e-5
"""

PAIR_DSF = """pair_style      lj/cut/coul/dsf {alpha!r} {cutoff!r}
pair_coeff      1 1 0.1521 3.1507
pair_coeff      * 2 0.0 1.0
pair_modify     shift yes
"""


def system(args, start):
    if args.dsf:
        return SYSTEM.format(start=start, pair=PAIR_DSF.format(alpha=args.dsf_alpha, cutoff=args.dsf_cutoff),
                             exclude="exclude molecule/intra all ")
    return SYSTEM.format(start=start, pair=PAIR_PPPM, exclude="")

LATTICE = """lattice         sc 3.1043
region          box block 0 {n} 0 {n} 0 {n}
create_box      2 box bond/types 1 angle/types 1 extra/bond/per/atom 2 extra/angle/per/atom 1 extra/special/per/atom 2
mass            1 15.9994
mass            2 1.008
molecule        water {mol}
create_atoms    0 box mol water 4928459"""


def melt_input(args, n, mol, steps, data):
    return (system(args, LATTICE.format(n=n, mol=mol)) +
            "velocity all create 300.0 12345 mom yes rot yes dist gaussian\n"
            "fix start all rigid/nvt/small molecule temp 300.0 300.0 100.0\n"
            "timestep 1.0\nthermo 500\nrun %d\nwrite_data %s nocoeff\n" % (steps, data))


def run_input(args, data, fix, dt, equil, sample, mid, dump=None):
    every = max(1, int(round(20 / dt)))
    columns = "step temp pe c_kt c_kr" + (" f_r[2]" if mid else "")
    text = (system(args, "read_data %s" % data) +
            "fix r all %s\n" % fix +
            "compute kt all ke/rigid r\ncompute kr all erotate/rigid r\n"
            "thermo_style custom %s\nthermo_modify format float %%.10g\n" % columns +
            "timestep %g\nthermo %d\nrun %d\n" % (dt, every, int(round(equil * 1000 / dt))))
    if dump:
        text += ("compute pa all pe/atom\ndump d all custom %d %s id type xu yu zu c_pa\n"
                 "dump_modify d sort id format float %%.17g\n" % (max(1, int(round(args.dump_every / dt))), dump))
    return text + "run %d\n" % int(round(sample * 1000 / dt))


def last_block(text):
    """The last thermo block's columns and rows, and the loop time and steps of its run."""
    blocks, current = [], None
    for line in text.splitlines():
        w = line.split()
        if w and w[0] == "Step":
            current = (w, [])
            blocks.append(current)
        elif current is not None and line.startswith("Loop time of"):
            m = re.match(r"Loop time of (\S+) on \d+ procs for (\d+) steps", line)
            current[1].append(("loop", float(m.group(1)), int(m.group(2))) if m else None)
            current = None
        elif current is not None and len(w) == len(current[0]):
            try:
                current[1].append([float(x) for x in w])
            except ValueError:
                pass
    if not blocks:
        return None
    header, rows = blocks[-1]
    loop = [r for r in rows if isinstance(r, tuple)]
    return header, [r for r in rows if isinstance(r, list)], (loop[0] if loop else None)


def mean(xs):
    return sum(xs) / len(xs) if xs else float("nan")


def blocked(xs, blocks=10):
    """The mean of xs and its standard error from `blocks` blocks of consecutive values."""
    n = len(xs)
    if n < blocks:
        return mean(xs), float("nan")
    b = [mean(xs[k * n // blocks:(k + 1) * n // blocks]) for k in range(blocks)]
    m = mean(b)
    return m, math.sqrt(sum((x - m) ** 2 for x in b) / (blocks - 1) / blocks)


def tconf(args, dump):
    """lammps_tconf's line for one dump as a dict, or None when it fails (its message on stderr)."""
    cmd = [args.tconf, "--cutoff", repr(args.dsf_cutoff), "--alpha", repr(args.dsf_alpha), dump]
    proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if proc.returncode != 0:
        sys.stderr.write("lammps_tconf failed on %s: %s" % (dump, proc.stderr))
        return None
    lines = [l for l in proc.stdout.splitlines() if l and not l.startswith("#")]
    w = lines[-1].split()
    keys = ["file", "frames", "molecules", "V", "V_err", "Tt", "Tt_err", "Tr", "Tr_err", "rel", "misfit"]
    return dict(zip(keys, w))


def measure(args, label, fix, dt, mid, molecules, data, sample=None):
    sample = args.sample if sample is None else sample
    name = "%s_%gfs" % (re.sub(r"[^A-Za-z0-9]+", "-", label), dt)
    folder = os.path.join(args.out, "runs")
    path = os.path.join(folder, "in." + name)
    dump = os.path.join(folder, "dump." + name) if args.dsf else None
    with open(path, "w") as f:
        f.write(run_input(args, data, fix, dt, args.equil, sample, mid, dump))
    launcher = ["mpirun"] + (["--allow-run-as-root"] if os.geteuid() == 0 else []) + ["-np", str(args.ranks)] if args.ranks > 1 else []
    proc = subprocess.run(launcher + [args.lmp, "-in", path, "-log", os.path.join(folder, "log." + name), "-screen", "none"],
                          cwd=folder, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=dict(os.environ, OMP_NUM_THREADS="1"))
    row = {"fix": label, "dt_fs": dt, "status": "failed", "pe_per_molecule": "", "T_trans": "", "T_rot": "", "T_rot_mid": "",
           "cpu_ms_per_step": ""}
    if args.dsf:
        row.update({k: "" for k in DSF_FIELDS})
    try:
        text = open(os.path.join(folder, "log." + name)).read()
    except OSError:
        return row
    block = last_block(text)
    if proc.returncode != 0 or block is None or block[2] is None:
        return row
    header, rows, loop = block
    col = {c: k for k, c in enumerate(header)}
    pe = [r[col["PotEng"]] for r in rows]
    if not all(math.isfinite(x) for x in pe):
        return row
    dof = 3 * molecules
    row.update(status="ok", pe_per_molecule="%.4f" % (mean(pe) / molecules),
               T_trans="%.1f" % (2 * mean([r[col["c_kt"]] for r in rows]) / (dof * BOLTZ)),
               T_rot="%.1f" % (2 * mean([r[col["c_kr"]] for r in rows]) / (dof * BOLTZ)),
               cpu_ms_per_step="%.2f" % (1000 * loop[1] / max(loop[2], 1)))
    if mid and "f_r[2]" in col:
        row["T_rot_mid"] = "%.1f" % mean([r[col["f_r[2]"]] for r in rows])
    if args.dsf:
        pe, pe_err = blocked([r[col["PotEng"]] / molecules for r in rows])
        tt = blocked([2 * r[col["c_kt"]] / (dof * BOLTZ) for r in rows])
        tr = blocked([2 * r[col["c_kr"]] / (dof * BOLTZ) for r in rows])
        cpu = re.search(r"([0-9.]+)% CPU use", text.split("Loop time of")[-1])
        share = float(cpu.group(1)) / 100 if cpu else float("nan")
        row.update(pe_per_molecule="%.4f" % pe, pe_err="%.4f" % pe_err, T_trans="%.1f" % tt[0], T_trans_err="%.1f" % tt[1],
                   T_rot="%.1f" % tr[0], T_rot_err="%.1f" % tr[1], wall_ms_per_step=row["cpu_ms_per_step"],
                   cpu_ms_per_step="%.2f" % (1000 * loop[1] * share / max(loop[2], 1)))
        t = tconf(args, dump)
        if t is None:
            row["status"] = "tconf-failed"
            return row
        row.update(frames=t["frames"], V_tconf=t["V"], V_rel_diff=t["rel"], Tconf_trans="%.1f" % float(t["Tt"]),
                   Tconf_trans_err="%.1f" % float(t["Tt_err"]), Tconf_rot="%.1f" % float(t["Tr"]), Tconf_rot_err="%.1f" % float(t["Tr_err"]))
        if not args.keep_dumps:
            os.remove(dump)
    return row


DSF_FIELDS = ["pe_err", "T_trans_err", "T_rot_err", "frames", "V_tconf", "V_rel_diff", "Tconf_trans", "Tconf_trans_err", "Tconf_rot",
              "Tconf_rot_err", "z_V", "z_Tconf_trans", "z_Tconf_rot", "wall_ms_per_step"]


def z_against(row, ref, key, err):
    """(row − reference) / √(σ² + σ_ref²), as text; empty when either is missing."""
    try:
        d = float(row[key]) - float(ref[key])
        s = math.hypot(float(row[err]), float(ref[err]))
        return "%+.1f" % (d / s)
    except (ValueError, KeyError, ZeroDivisionError):
        return ""


def write_dsf_tables(args, rows, ref):
    for r in rows:
        if ref is not None and r["status"] == "ok" and ref["status"] == "ok":
            r["z_V"] = z_against(r, ref, "pe_per_molecule", "pe_err")
            r["z_Tconf_trans"] = z_against(r, ref, "Tconf_trans", "Tconf_trans_err")
            r["z_Tconf_rot"] = z_against(r, ref, "Tconf_rot", "Tconf_rot_err")
    everything = rows + ([ref] if ref is not None else [])
    fields = ["fix", "dt_fs", "status", "pe_per_molecule", "pe_err", "z_V", "Tconf_trans", "Tconf_trans_err", "z_Tconf_trans", "Tconf_rot",
              "Tconf_rot_err", "z_Tconf_rot", "T_trans", "T_trans_err", "T_rot", "T_rot_err", "T_rot_mid", "cpu_ms_per_step", "wall_ms_per_step",
              "frames", "V_tconf", "V_rel_diff"]
    with open(os.path.join(args.out, "sweep.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields, lineterminator="\n", extrasaction="ignore")
        w.writeheader()
        w.writerows(everything)
    with open(os.path.join(args.out, "sweep.md"), "w") as f:
        f.write("| fix | h (fs) | V/molecule (kcal/mol) | z | T_conf,trans (K) | z | T_conf,rot (K) | z | T_trans (K) | T_rot (K) | T_rot mid (K) "
                "| CPU/step (ms) |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n")
        for r in everything:
            h = "%g" % r["dt_fs"] + (" (reference)" if r is ref else "")
            if r["status"] != "ok":
                f.write("| %s | %s | %s | | | | | | | | | |\n" % (r["fix"], h, r["status"]))
                continue
            f.write("| %s | %s | %s ± %s | %s | %s ± %s | %s | %s ± %s | %s | %s ± %s | %s ± %s | %s | %s |\n" %
                    (r["fix"], h, r["pe_per_molecule"], r["pe_err"], r.get("z_V", ""), r["Tconf_trans"], r["Tconf_trans_err"],
                     r.get("z_Tconf_trans", ""), r["Tconf_rot"], r["Tconf_rot_err"], r.get("z_Tconf_rot", ""), r["T_trans"], r["T_trans_err"],
                     r["T_rot"], r["T_rot_err"], r["T_rot_mid"], r["cpu_ms_per_step"]))


def main():
    build = os.path.join(REPO, "build", "release")
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--lmp", default=os.path.join(build, "bin", "lmp_rotlie"), help="lmp_rotlie")
    p.add_argument("--out", help="default build/release/thermostat-sweep (-dsf with --dsf)")
    p.add_argument("--dsf", action="store_true", help="lj/cut/coul/dsf instead of PPPM, with configurational temperatures")
    p.add_argument("--dsf-alpha", type=float, default=0.2, help="DSF damping α (1/Å)")
    p.add_argument("--dsf-cutoff", type=float, default=9.0, help="DSF and LJ cutoff (Å); the box must exceed twice it")
    p.add_argument("--dump-every", type=float, default=48.0, help="fs between dumped frames (--dsf)")
    p.add_argument("--tconf", default=os.path.join(build, "bench", "lammps_tconf"), help="bench's lammps_tconf (--dsf)")
    p.add_argument("--reference", default="3:0.5", help="FIX:H, the reference run (--dsf; index into the list, h in fs), or none")
    p.add_argument("--ref-sample", type=float, default=None, help="ps sampled by the reference (default 2 × --sample)")
    p.add_argument("--keep-dumps", action="store_true")
    p.add_argument("--molecules", type=int, default=216, help="a cube n³ (default 216 = 6³)")
    p.add_argument("--melt", type=int, default=2000, help="steps of 1 fs of the shared start's melt")
    p.add_argument("--equil", type=float, default=1.0, help="ps at the run's own step before sampling")
    p.add_argument("--sample", type=float, default=4.0, help="ps sampled")
    p.add_argument("--steps", default="1,2,4,6,8", help="time steps in fs, comma-separated")
    p.add_argument("--fixes", default=",".join(str(k) for k in range(len(FIXES))),
                   help="which rows of the list (0 rigid/nvt/small ... 5 rigid/sier4/small langevin)")
    p.add_argument("--ranks", type=int, default=1)
    p.add_argument("--jobs", type=int, default=1, help="runs at once")
    args = p.parse_args()
    if args.out is None:
        args.out = os.path.join(build, "thermostat-sweep-dsf" if args.dsf else "thermostat-sweep")
    n = round(args.molecules ** (1 / 3))
    if n ** 3 != args.molecules:
        sys.exit("thermostat_sweep: --molecules must be a cube (27, 64, 125, 216, 343, 512, ...)")
    if not os.path.exists(args.lmp):
        sys.exit("thermostat_sweep: no lmp_rotlie at %s (build the target lmp_rotlie)" % args.lmp)
    if args.dsf:
        side = n * 3.1043
        if not side > 2 * args.dsf_cutoff:
            sys.exit("thermostat_sweep: the box (%.2f Å) must be longer than twice --dsf-cutoff for lammps_tconf" % side)
        if not os.path.exists(args.tconf):
            sys.exit("thermostat_sweep: no lammps_tconf at %s (build the target lammps_tconf)" % args.tconf)
    mol = os.path.join(REPO, "examples", "lammps", "tip3p.mol")
    os.makedirs(os.path.join(args.out, "runs"), exist_ok=True)
    data = os.path.join(args.out, "runs", "start%d%s.data" % (args.molecules, "_dsf_%g_%g" % (args.dsf_alpha, args.dsf_cutoff) if args.dsf else ""))
    if not os.path.exists(data):
        melt = os.path.join(args.out, "runs", "in.melt")
        with open(melt, "w") as f:
            f.write(melt_input(args, n, mol, args.melt, data))
        print("melting %d molecules (%d steps of 1 fs) ..." % (args.molecules, args.melt), flush=True)
        subprocess.run([args.lmp, "-in", melt, "-log", os.path.join(args.out, "runs", "log.melt"), "-screen", "none"], check=True,
                       cwd=os.path.join(args.out, "runs"))
    steps = [float(x) for x in args.steps.split(",") if x]
    chosen = [FIXES[int(k)] for k in args.fixes.split(",") if k]
    jobs = [(label, fix, dt, mid) for (label, fix, mid) in chosen for dt in steps]
    rows = []
    ref = None
    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        ref_future = None
        if args.dsf and args.reference != "none":
            k, h = args.reference.split(":")
            label, fix, mid = FIXES[int(k)]
            # the longest run first, so that it does not finish alone at the end
            ref_future = pool.submit(measure, args, label, fix, float(h), mid, args.molecules, data,
                                     args.ref_sample if args.ref_sample is not None else 2 * args.sample)
        futures = [pool.submit(measure, args, label, fix, dt, mid, args.molecules, data) for (label, fix, dt, mid) in jobs]
        for f in futures + ([ref_future] if ref_future else []):
            r = f.result()
            if f is ref_future:
                ref = r
            else:
                rows.append(r)
            print("%-28s %4g fs  %-6s  pe/mol %9s  T_trans %6s  T_rot %6s  T_rot mid %6s  %8s ms/step" %
                  (r["fix"], r["dt_fs"], r["status"], r["pe_per_molecule"], r["T_trans"], r["T_rot"], r["T_rot_mid"] or "-",
                   r["cpu_ms_per_step"]) +
                  ("  T_conf %s ± %s / %s ± %s" % (r["Tconf_trans"], r["Tconf_trans_err"], r["Tconf_rot"], r["Tconf_rot_err"]) if args.dsf else "")
                  + (" (reference)" if f is ref_future else ""), flush=True)
    if args.dsf:
        write_dsf_tables(args, rows, ref)
        print("wrote %s/sweep.{csv,md}" % args.out)
        return
    fields = ["fix", "dt_fs", "status", "pe_per_molecule", "T_trans", "T_rot", "T_rot_mid", "cpu_ms_per_step"]
    with open(os.path.join(args.out, "sweep.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields, lineterminator="\n")
        w.writeheader()
        w.writerows(rows)
    with open(os.path.join(args.out, "sweep.md"), "w") as f:
        f.write("| fix | h (fs) | PE/molecule (kcal/mol) | T_trans (K) | T_rot (K) | T_rot mid (K) | CPU/step (ms) |\n")
        f.write("|---|---|---|---|---|---|---|\n")
        for r in rows:
            if r["status"] != "ok":
                f.write("| %s | %g | failed | | | | |\n" % (r["fix"], r["dt_fs"]))
            else:
                f.write("| %s | %g | %s | %s | %s | %s | %s |\n" % (r["fix"], r["dt_fs"], r["pe_per_molecule"], r["T_trans"], r["T_rot"],
                                                                   r["T_rot_mid"] or "", r["cpu_ms_per_step"]))
    print("wrote %s/sweep.{csv,md}" % args.out)


if __name__ == "__main__":
    main()
