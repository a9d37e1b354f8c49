"""The dedicated schemes for a body you type, against a reference scheme: error against CPU time.

    python3 solve_and_chart.py "0.4,0.7,1" --out charts      # or a name: water

Solves the N family for the body (Laskar & Vaillant: every real solution, ranked by ||H_R5||), takes the
best few, and measures each with RS4-S5-McLachlan at its three permutations: 64 random initial momenta
integrated to T = 1 at several steps, the largest attitude error against the exact flow, and the CPU
time of the integration. Writes error_vs_cpu.png (and .csv) into --out.
"""
import argparse
import csv
import pathlib
import time

import matplotlib
import numpy as np

import rotlie

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def measure(scheme, body, G0, T, levels):
    _, Q_exact = rotlie.exact_flow(body, G0, t=T)
    points = []
    for level in levels:
        steps = 2**level
        start = time.process_time()
        _, Q = rotlie.integrate(scheme, body, G0, h=f"{T}/{steps}", steps=steps)
        cpu = time.process_time() - start
        points.append((cpu, float(np.max(np.abs(Q - Q_exact)))))
    return points


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("body", help="I1,I2,I3 (decimals or rationals) or a name (water)")
    parser.add_argument("--out", default="rotlie-charts", help="folder of the chart")
    parser.add_argument("--best", type=int, default=3, help="how many of the best N schemes to chart")
    args = parser.parse_args()
    body = rotlie.Body(*args.body.split(",")) if "," in args.body else rotlie.Body.named(args.body)
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)

    schemes = rotlie.solve(body, family="N")[: args.best]
    references = [rotlie.scheme(f"RS4-S5-McLachlan:{p}") for p in ("ABC", "CBA", "BAC")]
    G0 = np.random.default_rng(1).normal(size=(64, 3))
    T, levels = 1, range(4, 10)
    fig, ax = plt.subplots(figsize=(7, 5))
    rows = []
    for s in schemes + references:
        points = measure(s, body, G0, T, levels)
        label = s.name + (f"  ||H_R5|| = {s.remainder_norm:.2e}" if s.remainder_norm is not None else "")
        ax.loglog([p[0] for p in points], [p[1] for p in points], "o-" if s.remainder_norm is not None else "s--",
                  label=label)
        rows += [(s.name, cpu, err) for cpu, err in points]
        print(f"{s.name:24s} error at the finest step {points[-1][1]:.3e}, CPU {points[-1][0]:.3e} s")
    ax.set_xlabel("CPU time (s) for 64 bodies to T = 1")
    ax.set_ylabel("largest attitude error against the exact flow")
    ax.set_title(f"Body {body.text}: dedicated N schemes against RS4 S5 McLachlan")
    ax.legend(fontsize=7)
    fig.savefig(out / "error_vs_cpu.png", dpi=120)
    with open(out / "error_vs_cpu.csv", "w", newline="") as f:
        csv.writer(f).writerows([("scheme", "cpu_s", "error"), *rows])
    print(f"wrote {out / 'error_vs_cpu.png'}")


if __name__ == "__main__":
    main()
