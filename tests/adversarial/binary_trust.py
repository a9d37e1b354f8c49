"""The trust class of the replay: `rotlie binary` at coarse steps, each run's final state against a converged
reference of the same start, and whether the run said how far to trust it (issue 46).

A run is wrong by its largest error relative to --accuracy's bounds (position and velocity relative to 1e-3,
attitudes to 1e-2 rad). It is flagged when it exits 0 with "inaccurate" or "unstable" and a warning, or exits 1
in one line (a failed implicit step, a contact that may be the step's). The promises checked:
  every run wrong by more than 10x the accuracy is flagged (a miss is SILENT);
  at most 5 % of the runs within the accuracy are flagged (false alarms).
The grid: 4 starts x 9 fixed-step integrators x 6 steps from 300 s to 4 h, one day each (216 runs, about 30 s).
"""
import json
import math

STARTS = {
    "didymos, order 2": ["--system", "didymos"],
    "didymos, order 4": ["--system", "didymos", "--order", "4"],
    "after DART's impulse (beta 3.6)": ["--system", "didymos", "--impulse", "secondary:beta=3.6,m=579.4,U=6.1449"],
    "eccentric (slowed 30 mm/s)": ["--system", "didymos", "--impulse", "secondary:0,-30,0"],
}
INTEGRATORS = ["SIER2", "SIER4", "SIER6", "KEPLER2", "KEPLER4", "KEPLER6", "RK4", "LGVI", "MRDL"]
STEPS = ["300", "900", "1800", "3600", "7200", "14400"]
T = "86400"
REFERENCE = ["--integrator", "odeint-rkf78:1e-13", "--h", "600"]
ACCURACY_REL, ACCURACY_RAD = 1e-3, 1e-2


def _distance(a, b):
    return math.sqrt(sum((x - y) ** 2 for x, y in zip(a, b)))


def _angle(A, B):
    """The angle of the rotation A^T B (rows as the JSON writes them)."""
    R = [[sum(A[k][i] * B[k][j] for k in range(3)) for j in range(3)] for i in range(3)]
    c = (R[0][0] + R[1][1] + R[2][2] - 1) / 2
    s = math.sqrt((R[2][1] - R[1][2]) ** 2 + (R[0][2] - R[2][0]) ** 2 + (R[1][0] - R[0][1]) ** 2) / 2
    return math.atan2(s, c)


def wrongness(run, ref):
    """The final state's error in units of the accuracy asked for (inf for a state that is not finite)."""
    try:
        parts = [_distance(run["r"], ref["r"]) / math.hypot(*ref["r"]) / ACCURACY_REL,
                 _distance(run["v"], ref["v"]) / math.hypot(*ref["v"]) / ACCURACY_REL,
                 _angle(run["Q1"], ref["Q1"]) / ACCURACY_RAD, _angle(run["Q2"], ref["Q2"]) / ACCURACY_RAD]
    except (TypeError, ValueError, OverflowError):
        return math.inf
    return max(p if math.isfinite(p) else math.inf for p in parts)


def binary_trust(R, quick):
    cls = "binary trust"
    within, within_flagged, beyond, beyond_flagged, between, between_flagged = 0, 0, 0, 0, 0, 0
    rows = []
    for start, start_args in STARTS.items():
        r = R.run(["binary", *start_args, *REFERENCE, "--T", T, "--json"], timeout=300)
        if r["rc"] != 0:
            R.record(cls, f"reference of {start}", f"exit {r['rc']}: {r['err'][:200]!r}")
            continue
        ref = json.loads(r["out"])
        for integrator in INTEGRATORS:
            for h in STEPS:
                args = ["binary", *start_args, "--integrator", integrator, "--h", h, "--T", T, "--json"]
                r = R.run(args, timeout=120)
                what = " ".join(args)
                if r["rc"] == 0:
                    run = json.loads(r["out"])
                    flagged = bool(run.get("inaccurate") or run.get("unstable"))
                    if flagged and not r["err"].strip().startswith("rotlie: warning: "):
                        R.record(cls, what, "flagged without a warning")
                    wrong = wrongness(run, ref)
                elif r["rc"] == 1:
                    problem = R.error_problem(r, 1)
                    if problem:
                        R.record(cls, what, problem)
                        continue
                    flagged, wrong = True, math.inf  # a failure said so: nothing to compare
                else:
                    R.record(cls, what, R.error_problem(r, 1))
                    continue
                rows.append((start, integrator, h, wrong, flagged))
                if wrong > 10:
                    beyond += 1
                    beyond_flagged += flagged
                    R.record(cls, what, None if flagged else f"wrong by {wrong:.3g}x the accuracy and not flagged", silent=not flagged)
                elif wrong <= 1:
                    within += 1
                    within_flagged += flagged
                else:
                    between += 1
                    between_flagged += flagged
    rate = within_flagged / within if within else 0.0
    R.record(cls, f"false alarms: {within_flagged} of {within} runs within the accuracy flagged ({100 * rate:.1f} %, at most 5 %)",
             None if rate <= 0.05 else "too many false alarms")
    print(f"binary trust: {len(rows)} runs; wrong by more than 10x the accuracy: {beyond}, flagged {beyond_flagged}; "
          f"within it: {within}, flagged {within_flagged}; between: {between}, flagged {between_flagged}")
    if R.verbose:
        for start, integrator, h, wrong, flagged in rows:
            print(f"  {start:34s} {integrator:8s} h = {h:>5s}: wrong {wrong:10.3g}x  {'flagged' if flagged else ''}")
