"""Ctrl-C during a long call raises KeyboardInterrupt within a second; long calls release the GIL."""
import os
import signal
import subprocess
import sys
import textwrap
import threading
import time

import numpy as np

import rotlie

CHILD = textwrap.dedent("""
    import os, sys, time
    import numpy as np
    import rotlie
    water = rotlie.Body.named("water")
    call = sys.argv[1]
    print("started", flush=True)
    start = None
    try:
        if call == "integrate":
            rotlie.integrate("RS4-S5-McLachlan:CBA", water, np.ones((10, 3)), h=1e-3, steps=10**8)
        else:
            rotlie.solve(water, family="P")
        print("finished", flush=True)
    except KeyboardInterrupt:
        print("interrupted", time.monotonic(), flush=True)
        begin = time.monotonic()   # the next symbolic call waits only for the stopped one's stop point
        rotlie.remainder("ABCBA", order=3)
        print("next", time.monotonic() - begin, flush=True)
    sys.stdout.flush()
    os._exit(0)   # an abandoned symbolic computation would otherwise be waited for at exit
""")


def interrupt_after(call, seconds=1.5):
    env = dict(os.environ)
    p = subprocess.Popen([sys.executable, "-c", CHILD, call], stdout=subprocess.PIPE, text=True, env=env)
    assert p.stdout.readline().strip() == "started"
    time.sleep(seconds)
    sent = time.monotonic()
    p.send_signal(signal.SIGINT)
    out, _ = p.communicate(timeout=30)
    words = out.split()
    assert words[0] == "interrupted" and words[2] == "next", out
    return float(words[1]) - sent, float(words[3])


def test_ctrl_c_stops_a_long_integration_within_a_second():
    assert interrupt_after("integrate")[0] < 1.0


def test_ctrl_c_stops_a_long_solve_within_a_second():
    """The P family takes about 15 s for water; interrupted after 1.5 s, it stops at its next system,
    so the next symbolic call does not wait for the rest of the family."""
    interrupted, next_call = interrupt_after("solve")
    assert interrupted < 1.0
    assert next_call < 1.0


def test_long_calls_release_the_gil():
    ticks = 0
    done = threading.Event()

    def count():
        nonlocal ticks
        while not done.is_set():
            ticks += 1
            time.sleep(0.001)

    t = threading.Thread(target=count)
    t.start()
    start = time.monotonic()
    rotlie.integrate("RS4-S5-McLachlan:CBA", rotlie.Body.named("water"), np.ones((2000, 3)), h=0.01, steps=500)
    elapsed = time.monotonic() - start
    done.set()
    t.join()
    assert elapsed > 0.05 and ticks >= 10 * elapsed, (ticks, elapsed)  # the other thread ran meanwhile
