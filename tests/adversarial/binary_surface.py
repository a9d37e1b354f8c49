"""The binary, sweep and Python-binary classes of the replay: each defect of issue 46's campaign replayed as a
user meets it (its command, its one-line message, its exit status), beside what must keep working."""
import json
import math
import os
import pathlib
import signal
import time

DIDYMOS = ["binary", "--system", "didymos"]


def _json_of(R, args):
    r = R.run([*args, "--json"])
    return json.loads(r["out"]) if r["rc"] == 0 else None


def _write(path, text):
    pathlib.Path(path).write_text(text)
    return str(path)


def binary_surface(R, quick):
    cls = "binary"
    d = R.folder("binary")
    flagged = lambda j: j.get("unstable") or j.get("inaccurate")  # noqa: E731
    # untrustworthy results: flagged with one warning (the campaign's commands)
    for args in (["--integrator", "SIER2", "--h", "3600", "--T", "86400"],  # the secondary 63 degrees off
                 ["--integrator", "SIER4", "--h", "14400", "--T", "86400"],  # 114 degrees off
                 ["--impulse", "secondary:0,300,0", "--integrator", "RK4", "--h", "43200", "--T", "864000"]):  # hyperbolic, blown up
        R.expect_flagged(cls, [*DIDYMOS, *args, "--json"], flagged)
    accurate = [*DIDYMOS, "--integrator", "SIER4", "--h", "120", "--T", "86400", "--json"]
    r = R.run(accurate)
    R.record(cls, " ".join(accurate) + " (converged: unflagged and quiet)",
             None if r["rc"] == 0 and not flagged(json.loads(r["out"])) and not r["err"].strip() else f"status {r['rc']}: {r['err'][:200]!r}")
    # no number through text: the preset's masses are its documented density's
    preset = _json_of(R, [*DIDYMOS, "--integrator", "SIER4", "--T", "0"])
    given = _json_of(R, [*DIDYMOS, "--density", "2203.111036687207", "--integrator", "SIER4", "--T", "0"])
    same = preset and given and preset["masses"] == given["masses"]
    R.record(cls, "--system didymos's masses equal --density 2203.111036687207's bit for bit", None if same else "they differ", silent=True)
    # the Kepler drift on every conic, at order 0 where the drift is the answer (exit 0, finite)
    GM = 6.6743e-20 * sum(preset["masses"]) if preset else 0
    for name, speed in (("parabolic", math.sqrt(2 * GM / 1.2)), ("hyperbolic", 3 * math.sqrt(2 * GM / 1.2)),
                        ("very hyperbolic", 300 * math.sqrt(2 * GM / 1.2))):
        state = {"r": [1.2, 0, 0], "v": [0, speed, 0], "Q1": [[1, 0, 0], [0, 1, 0], [0, 0, 1]], "Q2": [[1, 0, 0], [0, 1, 0], [0, 0, 1]],
                 "omega1": [0, 0, 7.7e-4], "omega2": [0, 0, 1e-4]}
        f = _write(d / f"{name.replace(' ', '-')}.json", json.dumps(state))
        for h in ("86400", "8640000"):
            R.expect(cls, [*DIDYMOS, "--order", "0", "--state", f, "--integrator", "KEPLER4", "--h", h, "--T", "86400000", "--json"], "ok",
                     what=f"KEPLER4 at order 0 on a {name} orbit, h = {h} s")
    # a contact made by a coarse step is not a physical contact; a converged one is
    r = R.run([*DIDYMOS, "--impulse", "secondary:0,-40,0", "--integrator", "SIER4", "--h", "3600", "--T", "604800"])
    R.record(cls, "SIER4 h = 3600 s, slowed 40 mm/s: the contact is the step's error",
             R.error_problem(r, 1) or (None if "may be the step's error" in r["err"] else f"reported as {r['err'].strip()[:160]!r}"),
             silent=r["rc"] == 0 or "the run stops there" in r["err"])
    r = R.run([*DIDYMOS, "--impulse", "secondary:0,-45,0", "--integrator", "SIER4", "--h", "600", "--T", "604800"])
    R.record(cls, "SIER4 h = 600 s, slowed 45 mm/s: a converged contact stands",
             R.error_problem(r, 1) or (None if "the run stops there" in r["err"] else f"reported as {r['err'].strip()[:160]!r}"))
    # --T 0 evaluates any pose, even one whose orbit would collide
    rest = _write(d / "rest.json", json.dumps({"r": [1.2, 0, 0], "v": [0, 0, 0], "Q1": [[1, 0, 0], [0, 1, 0], [0, 0, 1]],
                                               "Q2": [[1, 0, 0], [0, 1, 0], [0, 0, 1]], "omega1": [0, 0, 0], "omega2": [0, 0, 0]}))
    R.expect(cls, [*DIDYMOS, "--state", rest, "--integrator", "SIER4", "--T", "0", "--json"], "ok", what="--T 0 of a pair at rest")
    R.expect(cls, [*DIDYMOS, "--state", rest, "--integrator", "SIER4", "--h", "60", "--T", "600"], "refused",
             what="a run of a pair at rest (it collides)")
    # numbers out of range in a state file: refused naming the field, never a message with inf
    eye = [[1, 0, 0], [0, 1, 0], [0, 0, 1]]
    base = {"r": [1.2, 0, 0], "v": [0, 1.75e-4, 0], "Q1": eye, "Q2": eye, "omega1": [0, 0, 7.7e-4], "omega2": [0, 0, 1.5e-4]}
    for field, value in (("r", [1e308, 0, 0]), ("v", [0, 1e300, 0]), ("omega1", [0, 0, 1e300]), ("Q1", [[1e200] * 3] * 3),
                         ("Q2", [[0, 0, 0]] * 3), ("Q1", [[74, 0, 0], [0, 1, 0], [0, 0, 1]])):
        f = _write(d / "bad-state.json", json.dumps({**base, field: value}))
        r = R.expect(cls, [*DIDYMOS, "--state", f, "--integrator", "SIER4", "--h", "60", "--T", "600"], "refused",
                     what=f"state with {field} = {json.dumps(value)[:40]}")
        if r["rc"] == 2 and (field not in r["err"] or "inf" in r["err"].replace("info", "")):
            R.record(cls, f"state with {field} = {json.dumps(value)[:40]}: the message names it, finitely", f"{r['err'].strip()[:200]!r}")
    # shape files: out of range, inverted, self-intersecting
    cube = ["v -1 -1 -1", "v 1 -1 -1", "v 1 1 -1", "v -1 1 -1", "v -1 -1 1", "v 1 -1 1", "v 1 1 1", "v -1 1 1"]
    faces = ["f 1 3 2", "f 1 4 3", "f 5 6 7", "f 5 7 8", "f 1 2 6", "f 1 6 5", "f 2 3 7", "f 2 7 6", "f 3 4 8", "f 3 8 7",
             "f 4 1 5", "f 4 5 8"]
    scaled = lambda k: [f"v {' '.join(str(float(x) * k) for x in line.split()[1:])}" for line in cube]  # noqa: E731
    for name, lines in (("huge", scaled(1e200) + faces), ("tiny", scaled(1e-200) + faces),
                        # a cube pierced by a tetrahedron: two closed surfaces crossing each other
                        ("self-intersecting", scaled(0.1) + faces + ["v -0.3 -0.3 -0.3", "v 0.3 -0.3 -0.3", "v 0 0.3 -0.3", "v 0 0 0.3",
                                                                      "f 9 11 10", "f 9 10 12", "f 10 11 12", "f 11 9 12"])):
        f = _write(d / f"{name}.obj", "\n".join(lines) + "\n")
        R.expect(cls, ["binary", "--primary", f"polyhedron:{f}", "--secondary", "ellipsoid:0.01,0.01,0.01", "--density", "2000",
                       "--separation", "1", "--integrator", "SIER4", "--T", "0"], "refused", what=f"a {name} shape model")
    # a valid solid of two cubes sharing an edge (an edge of four facets, its two vertices written once)
    index, verts, tris = {}, [], []

    def vertex(p):
        if p not in index:
            index[p] = len(verts) + 1
            verts.append("v %d %d %d" % p)
        return index[p]

    for x0, y0 in ((0, 0), (1, 1)):
        c = lambda i, j, k: vertex((x0 + i, y0 + j, k))  # noqa: E731
        for a_, b_, c_, e_ in (((0, 0, 0), (0, 1, 0), (1, 1, 0), (1, 0, 0)), ((0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)),
                               ((0, 0, 0), (1, 0, 0), (1, 0, 1), (0, 0, 1)), ((0, 1, 0), (0, 1, 1), (1, 1, 1), (1, 1, 0)),
                               ((0, 0, 0), (0, 0, 1), (0, 1, 1), (0, 1, 0)), ((1, 0, 0), (1, 1, 0), (1, 1, 1), (1, 0, 1))):
            tris += [f"f {c(*a_)} {c(*b_)} {c(*c_)}", f"f {c(*a_)} {c(*c_)} {c(*e_)}"]
    f = _write(d / "two-cubes.obj", "\n".join(verts + tris) + "\n")
    R.expect(cls, ["binary", "--primary", f"polyhedron:{f}", "--secondary", "ellipsoid:0.1,0.1,0.1", "--density", "2000", "--separation", "5",
                   "--integrator", "SIER4", "--T", "0", "--force"], "ok", what="two cubes sharing an edge (a valid solid)")
    # conventions a new user meets
    r = R.run(["--version"])
    R.record(cls, "rotlie --version", None if r["rc"] == 0 and len(r["out"].strip().splitlines()) == 1 else f"status {r['rc']}: {r['err'][:100]!r}")
    r = R.run([*DIDYMOS, "--integrator", "SIER4", "--h", "60", "--T", "600", "--every", "5"])
    mixed = r["rc"] == 0 and any(line.startswith("{") for line in r["out"].splitlines()) and "binary" in r["out"]
    R.record(cls, "--every without --json: the trajectory apart from the text", "JSON lines mixed with the text" if mixed else
             (None if r["rc"] in (0, 2) and (r["rc"] == 0 or not R.error_problem(r, 2)) else R.error_problem(r, 2)), silent=mixed)


def sweep_surface(R, quick):
    cls = "sweep"
    d = R.folder("sweep")
    ok_line = json.dumps({"system": "didymos", "integrator": "SIER4", "h": 60, "T": 600})
    # a line nested 60,000 levels: one line, exit 2, no signal
    deep = d / "deep.jsonl"
    deep.write_text(ok_line + "\n" + "[" * 60000 + "]" * 60000 + "\n")
    R.expect(cls, ["sweep", "--in", str(deep), "--out", str(d / "deep.out")], "refused", what="a line nested 60,000 levels")
    # a refused run: the sweep completes with exit 3 and the counts in its last line
    runs = d / "runs.jsonl"
    runs.write_text(ok_line + "\n" + json.dumps({"system": "didymos", "integrator": "NOPE", "h": 60, "T": 600}) + "\n" + ok_line + "\n")
    r = R.run(["sweep", "--in", str(runs), "--out", str(d / "runs.out")])
    last = (r["out"] + r["err"]).strip().splitlines()[-1:] or [""]
    R.record(cls, "a sweep with one refused run", None if r["rc"] == 3 and "refused" in last[0] else f"status {r['rc']}, last line {last[0][:160]!r}",
             silent=r["rc"] == 0)
    # forged result lines are not kept as done runs
    out = d / "runs.out"
    if out.is_file():
        lines = out.read_text().splitlines()
        forged = d / "forged.out"
        forged.write_text("\n".join(lines[:1] + ['{"index":0}']) + "\n")
        before = R.digest(forged)
        R.expect(cls, ["sweep", "--in", str(runs), "--out", str(forged), "--resume"], "refused", what="resume over a forged result line")
        R.record(cls, "the forged results file is left as it was", None if R.digest(forged) == before else "changed", silent=True)
    # two sweeps on one results file through hard links in two folders: one runs, the other is refused
    a, b = R.folder("sweep-a"), R.folder("sweep-b")
    long_line = json.dumps({"system": "didymos", "integrator": "SIER4", "h": 1, "T": 3e5})
    longer = d / "long.jsonl"
    longer.write_text((long_line + "\n") * 3)
    first = R.start(["sweep", "--in", str(longer), "--out", str(a / "results.out")])
    time.sleep(1.0)
    if (a / "results.out").exists():
        os.link(a / "results.out", b / "results.out")
        r = R.run(["sweep", "--in", str(longer), "--out", str(b / "results.out"), "--resume"], timeout=60)
        R.record(cls, "a second sweep on the same results file through a hard link", R.error_problem(r, 1), silent=r["rc"] == 0)
    first.send_signal(signal.SIGKILL)
    first.communicate()


PYTHON_BINARY = r"""
import json, signal, threading, time, pathlib, sys
import numpy as np
import rotlie
out = {}
sent = []
threading.Timer(1.0, lambda: (sent.append(time.monotonic()), signal.raise_signal(signal.SIGINT))).start()
try:
    rotlie.binary(system="didymos", integrator="SIER4", order=4, h=1, T=3e7)
    out["interrupt_s"] = None
except KeyboardInterrupt:
    out["interrupt_s"] = time.monotonic() - sent[0]
begin = time.monotonic()
rotlie.binary(system="didymos", integrator="SIER4", h=60, T=600)
out["next_call_s"] = time.monotonic() - begin
for name, kw in (("order=2.0", dict(order=2.0)), ("order=True", dict(order=True)), ("state=3", dict(state=3))):
    try:
        rotlie.binary(system="didymos", integrator="SIER4", h=60, T=600, **kw)
        out[name] = ["returned", ""]
    except (TypeError, ValueError) as e:
        out[name] = [type(e).__name__, str(e)]
a = rotlie.binary(system="didymos", integrator="SIER4", h=60, T=600)
b = rotlie.binary(system="didymos", integrator="SIER4", h=np.float64(60), T=np.int64(600), order=np.int64(2), state=None)
c = rotlie.binary(system="didymos", integrator="SIER4", h=60, T=600, state={k: getattr(a, k) for k in ("r", "v", "Q1", "Q2", "omega1", "omega2")})
d = rotlie.binary(system="didymos", integrator="SIER4", h=60, T=600, state=a)
out["numpy scalars"] = bool(np.array_equal(a.r, b.r))
out["a result's arrays and the result as the start"] = bool(np.array_equal(c.r, d.r))
print(json.dumps(out))
"""


def python_binary(R, quick):
    cls = "python binary"
    out = R.python_cases(cls, PYTHON_BINARY, timeout=120)  # a hang means Ctrl-C did not stop the run
    if out is None:
        return
    s = out.pop("interrupt_s")
    R.record(cls, f"Ctrl-C ends a 3e7-step rotlie.binary ({s if s is None else round(s, 3)} s)", None if s is not None and s < 0.5 else "not within 0.5 s")
    n = out.pop("next_call_s")
    R.record(cls, f"the next call starts at once ({n:.3f} s)", None if n < 0.5 else "held up")
    for name, value in out.items():
        if isinstance(value, bool):
            R.record(cls, name, None if value else "differs")
        elif value[0] == "returned":
            R.record(cls, name, "returned where it had to raise", silent=True)
        else:
            R.record(cls, name, None if value[0] == "TypeError" and "\n" not in value[1] else f"{value[0]}: {value[1][:160]!r}")
