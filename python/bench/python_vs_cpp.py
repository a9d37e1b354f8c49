"""The Python package's cost against the same loops in C++ (loop_bench): rotlie.integrate of 10^5
water bodies × 100 steps and rotlie.exact_flow of 10^6 states, the least CPU time of five runs each
(the C++ program measures the same way), and their ratios.

    python3 python/bench/python_vs_cpp.py build/release/python/bench/rotlie_python_loop_bench
(with PYTHONPATH=build/release/python). The states are the C++ program's (the same sequence), and
the first entries of the results are checked equal, so that both sides compute the same thing.
"""
import json
import subprocess
import sys
import time

import numpy as np

import rotlie


def momenta(n):
    """The C++ program's sequence: a 64-bit linear congruential generator, top 53 bits in [-1, 1)."""
    a, c, mask = 6364136223846793005, 1442695040888963407, (1 << 64) - 1
    state, out = 12345, []
    for _ in range(3 * n):
        state = (state * a + c) & mask
        out.append(state >> 11)
    return (np.array(out, dtype=np.float64) * 2.0**-53 * 2 - 1).reshape(n, 3)


def best_seconds(f, repeats=5):
    """The least CPU time of the process (every thread: the extension computes on a worker) over repeats."""
    best = float("inf")
    for _ in range(repeats):
        start = time.process_time()
        result = f()
        best = min(best, time.process_time() - start)
    return best, result


def main():
    cpp = json.loads(subprocess.run([sys.argv[1]], capture_output=True, text=True, check=True).stdout)
    water = rotlie.Body.named("water")
    scheme = rotlie.scheme("RS4-S5-McLachlan:CBA")
    G0 = momenta(100_000)
    integrate_s, (G, Q) = best_seconds(lambda: rotlie.integrate(scheme, water, G0, h=0.01, steps=100))
    E0 = momenta(1_000_000)
    exact_s, (EG, EQ) = best_seconds(lambda: rotlie.exact_flow(water, E0, t=1.0))
    check = G[0, 0] + Q[0, 2, 2] + EG[0, 0] + EQ[0, 2, 2]
    if check != cpp["check"]:
        raise SystemExit(f"the Python and C++ loops disagree: {check!r} against {cpp['check']!r}")
    print(f"integrate 1e5 bodies x 100 steps: Python {integrate_s:.3f} s, C++ {cpp['integrate_s']:.3f} s, "
          f"ratio {integrate_s / cpp['integrate_s']:.3f}")
    print(f"exact_flow 1e6 states:            Python {exact_s:.3f} s, C++ {cpp['exact_flow_s']:.3f} s, "
          f"ratio {exact_s / cpp['exact_flow_s']:.3f}")


if __name__ == "__main__":
    main()
