"""Ctrl-C during a long spin or md run, the exact flow's batch, or a held simulation's integrate:
KeyboardInterrupt within half a second, the next call (which takes the lock every scene's symbolic
setup takes) at once, and the interpreter's exit at once: the interrupted run stops, it is not left
running in the background (before, spin and md ran whole under that lock and went on after Ctrl-C)."""
import os
import signal
import subprocess
import sys
import textwrap
import time

import pytest

CHILD = textwrap.dedent("""
    import signal, sys, time, warnings
    import numpy as np
    import rotlie
    signal.signal(signal.SIGINT, signal.default_int_handler)  # even when started with Ctrl-C ignored
    warnings.simplefilter("ignore")
    LONG = {
        "spin": lambda: rotlie.spin("Hyperion", 0.1, "SIER4", h="1/1000", T=10**6),
        "spin-float128": lambda: rotlie.spin("Hyperion", 0.1, "SIER6", h="1/1000", T=10**5, scalar="float128"),
        "free-water": lambda: rotlie.md("free-water", "SIER2", h=1, T=10**6, runs=1),
        "dipole-field": lambda: rotlie.md("dipole-field", "SIER4", h=1, T=10**6, runs=1),
        "liquid-water": lambda: rotlie.md("liquid-water", "SIER2", h=2, T=100, runs=1, molecules=400),
        "spin-orbit": lambda: rotlie.md("spin-orbit", "SIER4", h="1/1000", T=10**6, body="Hyperion", e=0.1),
        "exact_flow": lambda: rotlie.exact_flow("water", np.ones((10**6, 3)), t=np.full(10**6, 1e3), scalar="float128"),
        "spin_simulation": lambda: HELD.integrate(10**6),
        "md_simulation": lambda: HELD.integrate(10**6),
    }
    call = sys.argv[1]
    if call == "spin_simulation":
        HELD = rotlie.spin_simulation("Hyperion", 0.1, "SIER4", "1/1000")
    elif call == "md_simulation":
        HELD = rotlie.md_simulation("free-water", "SIER2", 1, runs=8)
    print("started", flush=True)
    try:
        LONG[call]()
        print("finished", flush=True)
    except KeyboardInterrupt:
        print("interrupted", time.monotonic(), flush=True)
        begin = time.monotonic()
        rotlie.md("free-water", "SIER2", h=10, T=1, runs=2)
        rotlie.spin("Hyperion", 0, "SIER4", h="1/100", T=1)
        if call.endswith("_simulation"):  # held at the end of a step, and it goes on from there
            steps = HELD.steps
            HELD.integrate(HELD.t + 10 * HELD.h / (1000 if call == "md_simulation" else 1))
            assert HELD.steps == steps + 10, (steps, HELD.steps)
        print("next", time.monotonic() - begin, flush=True)
    print("exiting", time.monotonic(), flush=True)
""")

CALLS = ["spin", "spin-float128", "free-water", "dipole-field", "liquid-water", "spin-orbit", "exact_flow", "spin_simulation",
         "md_simulation"]


def interrupt_after(call, seconds=1.0):
    """(Ctrl-C to KeyboardInterrupt, the next calls, exit after the last line), in seconds."""
    p = subprocess.Popen([sys.executable, "-c", CHILD, call], stdout=subprocess.PIPE, text=True, env=dict(os.environ))
    try:
        assert p.stdout.readline().strip() == "started"
        time.sleep(seconds)
        sent = time.monotonic()
        p.send_signal(signal.SIGINT)
        out, _ = p.communicate(timeout=20)
        ended = time.monotonic()
    except subprocess.TimeoutExpired:
        p.kill()
        p.communicate()
        pytest.fail(f"{call}: still running 20 s after Ctrl-C (the next call or the exit waited for the interrupted run)")
    lines = dict(line.split(maxsplit=1) for line in out.splitlines())
    assert "interrupted" in lines and "next" in lines and "exiting" in lines, out
    return float(lines["interrupted"]) - sent, float(lines["next"]), ended - float(lines["exiting"])


@pytest.mark.parametrize("call", CALLS)
def test_ctrl_c_ends_a_long_run_at_once_and_frees_the_next_call(call):
    interrupted, next_calls, exit_after = interrupt_after(call)
    print(f"{call}: KeyboardInterrupt {interrupted:.3f} s after Ctrl-C, next calls {next_calls:.3f} s, exit {exit_after:.3f} s")
    assert interrupted < 0.5
    assert next_calls < 1.0
    assert exit_after < 1.0
