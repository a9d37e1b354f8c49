#!/usr/bin/python3
"""Replays the adversarial campaign against the rotlie binary: extreme values, kills at random moments,
two concurrent runs on one folder, and truncated, garbage or foreign state files; then the surfaces built
after it: `spin` (steps, untrusted runs, tolerances), every writer and reader against links, FIFOs and
devices, the Python package (its calls and its files) and, where it was built, lmp_rotlie.

Each command is judged against what a user must get:
  refused  exit 2 and exactly one line on stderr ("rotlie: error: ..."), and a saved state left unchanged;
  failed   exit 1 and one line (the run failed, said so);
  ok       exit 0 with no non-finite number in the output.
An outcome is a FAILURE when the binary crashes (a signal), hangs (timeout), prints a multi-line error or an
unexpected status, and SILENT when it exits 0 where it had to refuse or fail, prints nan/inf as a result, or
leaves a saved state changed or half written. The summary line gives the counts; the exit status is 1 when
any command failed or was silent.

Usage: replay.py --binary build/release/bin/rotlie [--seed N] [--quick] [--verbose] [--classes LIST]
The Python class imports the package built beside the binary (build/release/python) under /usr/bin/python3;
the LAMMPS class runs build/release/bin/lmp_rotlie; each is skipped, and says so, when absent.
"""
import argparse
import hashlib
import json
import os
import pathlib
import random
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from binary_surface import binary_surface, python_binary, sweep_surface  # noqa: E402
from binary_trust import binary_trust  # noqa: E402

NON_FINITE = re.compile(r"(?<![A-Za-z_])(nan|inf|infinity)(?![A-Za-z_])", re.IGNORECASE)


class Replay:
    def __init__(self, binary, work, rng, verbose):
        self.binary, self.work, self.rng, self.verbose = binary, work, rng, verbose
        self.commands = 0
        self.failures = []
        self.silent = []
        self.by_class = {}

    # -- running ---------------------------------------------------------------------------------
    def run(self, args, timeout=120, cwd=None):
        self.commands += 1
        start = time.monotonic()
        try:
            p = subprocess.run([self.binary, *args], capture_output=True, text=True, timeout=timeout, cwd=cwd,
                               errors="replace")
            return {"rc": p.returncode, "out": p.stdout, "err": p.stderr, "s": time.monotonic() - start}
        except subprocess.TimeoutExpired:
            return {"rc": None, "out": "", "err": "", "s": timeout}

    def start(self, args, cwd=None):
        self.commands += 1
        return subprocess.Popen([self.binary, *args], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                                cwd=cwd, errors="replace")

    def kill_until_done(self, args, longest, attempts, shortest=0.05):
        """Starts args and kills it (SIGKILL) after a random moment, again and again until a run ends by
        itself or the attempts are used up. Returns the unexpected exit statuses (neither 0 nor killed)."""
        unexpected = []
        for _ in range(attempts):
            p = self.start(args)
            time.sleep(self.rng.uniform(shortest, longest))
            if p.poll() is None:
                p.send_signal(signal.SIGKILL)
            p.communicate()
            if p.returncode == 0:
                break
            if p.returncode != -signal.SIGKILL:
                unexpected.append(p.returncode)
        return unexpected

    def resumed_problem(self, r, got, want, folder, keep, differs):
        """Why a resumed run r (its result `got`) is not an uninterrupted run's (`want`), or None; and
        whether that is silent (exit 0 with another result or files left behind in folder)."""
        if r["rc"] != 0:
            return self.error_problem(r, 0), False
        if got != want:
            return differs, True
        left = self.leftovers(folder, keep)
        return (f"files left behind: {left}", True) if left else (None, False)

    # -- judging ---------------------------------------------------------------------------------
    def record(self, cls, what, problem=None, silent=False):
        counts = self.by_class.setdefault(cls, [0, 0, 0])
        counts[0] += 1
        if problem:
            (self.silent if silent else self.failures).append(f"[{cls}] {what}: {problem}")
            counts[2 if silent else 1] += 1
        if self.verbose:
            print(f"[{cls}] {what}: {'SILENT ' if silent and problem else ''}{problem or 'as expected'}", flush=True)

    @staticmethod
    def error_problem(r, status):
        """Why r is not a proper refusal (status 2) or failure (status 1), or None."""
        if r["rc"] is None:
            return "hung (timeout)"
        if r["rc"] < 0:
            return f"killed by signal {-r['rc']}"
        lines = r["err"].strip().splitlines()
        if r["rc"] != status:
            return f"exit {r['rc']} instead of {status}: {r['err'].strip()[:200]!r}"
        if len(lines) != 1 or not lines[0].startswith("rotlie: error: "):
            return f"not one error line: {r['err'][:300]!r}"
        return None

    def expect(self, cls, args, outcome, what=None, timeout=120, cwd=None, allow_non_finite=False):
        """Runs args and judges the outcome ('refused', 'failed', 'ok', or 'refused|ok' for either)."""
        what = what or " ".join(args)
        r = self.run(args, timeout=timeout, cwd=cwd)
        allowed = outcome.split("|")
        if r["rc"] is None or (r["rc"] is not None and r["rc"] < 0):
            self.record(cls, what, self.error_problem(r, 2))
        elif r["rc"] == 0:
            if "ok" not in allowed:
                self.record(cls, what, f"exit 0 where it had to be {outcome}: {r['out'][:200]!r}", silent=True)
            elif not allow_non_finite and NON_FINITE.search(r["out"]):
                self.record(cls, what, f"non-finite number in the output: {NON_FINITE.search(r['out']).group(0)}",
                            silent=True)
            else:
                self.record(cls, what)
        elif (r["rc"] == 2 and "refused" in allowed) or (r["rc"] == 1 and "failed" in allowed):
            self.record(cls, what, self.error_problem(r, r["rc"]))
        else:
            self.record(cls, what, f"exit {r['rc']} where it had to be {outcome}: {r['err'].strip()[:200]!r}")
        return r

    def expect_flagged(self, cls, args, flagged_in):
        """A run that blew up or cannot be trusted: exit 1 in one line, or exit 0 with a flag in its JSON
        (flagged_in(json) true) and a warning on stderr; never a number shown as a plain result."""
        r = self.run(args, timeout=120)
        what = " ".join(args)
        if r["rc"] == 0:
            flagged = flagged_in(json.loads(r["out"]))
            self.record(cls, what, None if flagged and r["err"].strip().startswith("rotlie: warning: ")
                        else "a blown-up run reported without a flag or warning", silent=not flagged)
        else:
            self.record(cls, what, self.error_problem(r, 1))

    # -- files -----------------------------------------------------------------------------------
    @staticmethod
    def digest(path):
        p = pathlib.Path(path)
        return hashlib.sha256(p.read_bytes()).hexdigest() if p.is_file() else None

    def folder(self, name):
        d = self.work / name
        shutil.rmtree(d, ignore_errors=True)
        d.mkdir(parents=True)
        return d

    def python_cases(self, cls, code, timeout):
        """Runs `code` under /usr/bin/python3 with the package built beside the binary; returns the JSON it
        prints, or None (the package is absent: said; the interpreter hung or failed: recorded)."""
        package = pathlib.Path(self.binary).parent.parent / "python"
        if not (package / "rotlie").is_dir():
            print(f"{cls}: skipped (no package at {package})")
            return None
        env = {**os.environ, "PYTHONPATH": str(package), "PYTHONDONTWRITEBYTECODE": "1"}
        self.commands += 1
        try:
            p = subprocess.run(["/usr/bin/python3", "-c", code], capture_output=True, text=True, timeout=timeout, env=env)
        except subprocess.TimeoutExpired:
            self.record(cls, "the Python cases", "hung (timeout)")
            return None
        if p.returncode != 0:
            self.record(cls, "the Python cases", f"the interpreter ended with {p.returncode}: {p.stderr[-300:]!r}")
            return None
        return json.loads(p.stdout)

    @staticmethod
    def leftovers(folder, keep):
        """Files in folder other than the expected ones (temporaries of a killed run)."""
        return sorted(p.name for p in pathlib.Path(folder).iterdir() if p.name not in keep)


# ------------------------------------------------------------------------------------------------
# 1. Extreme values: every command, values at and beyond the edges.
def extreme_values(R, quick):
    cls = "extreme values"
    refused = [
        ["integrate", "--scheme", "ABCBA2", "--inertia", "water", "--h", h] for h in
        ["0", "-1", "nan", "inf", "-inf", "1e-400", "1e400", "", "0x10", "1/0", "abc"]
    ] + [
        ["integrate", "--scheme", "N2:BAC:2", "--inertia", I, "--h", "0.1"] for I in
        ["1,1,1", "0,1,1", "-1,2,3", "1,2,4", "1,2,nan", "1,2", "1,2,3,4", "1e-400,1,1.5", "water,1"]
    ] + [
        ["integrate", "--scheme", s, "--inertia", "water", "--h", "0.1"] for s in
        ["N8", "P16", "N2:XYZ:1", "N2:BAC:99", "ABCD", "", "ABCBA2:ABC:1", "../../etc/passwd"]
    ] + [
        ["exact", "--inertia", "water", "--T", t] for t in ["nan", "inf", "1e400"]
    ] + [
        ["exact", "--inertia", "water", "--T", "1", "--G0", g] for g in ["nan,1,1", "1,1", "1e400,0,0"]
    ] + [
        ["order", "--scheme", "ABCBA2", "--inertia", "water", "--min-level", a, "--max-level", b] for a, b in
        [("5", "3"), ("-1", "3"), ("1", "100"), ("1.5", "3")]
    ] + [
        ["remainder", "--scheme", w, "--order", k] for w, k in
        [("ABCBA", "0"), ("ABCBA", "10"), ("ABCBA", "-1"), ("AB" * 30 + "C", "3"), ("ABABA", "3"),
         ("ABCBACBCBABCBACBA", "7"), ("N2", "5 ")]
    ] + [
        ["solve", "--family", f, "--inertia", I] + extra for f, I, extra in
        [("X", "water", []), ("N", "water", ["--digits", "9"]), ("N", "water", ["--digits", "301"]),
         ("Q", "water", ["--starts", "0"]), ("Q", "water", ["--scheme", "ABCBA"]), ("N", "water", ["--perm", "ABD"])]
    ] + [
        ["map", "--family", "N", "--grid", g, "--json"] for g in ["1", "0", "-5", "20.9", "4294967316", "1e9", "x"]
    ] + [
        ["md", "--scene", "dipole-field", "--integrator", i, "--h", h] + extra for i, h, extra in
        [("MRDL", "0", []), ("MRDL", "-1", []), ("MRDL", "nan", []), ("NOPE", "1", []), ("MRDL", "1", ["--runs", "0"]),
         ("MRDL", "1", ["--molecules", "512"]), ("MRDL", "1", ["--inertia", "water"]), ("MRDL", "1", ["--T", "-1"]),
         ("SIER2/NOPE", "1", []), ("MRDL", "1", ["--scalar", "float80"])]
    ] + [
        ["spin", "--body", b, "--e", e, "--integrator", i, "--h", h, "--T", T] for b, e, i, h, T in
        [("2,1,3", "0.1", "SIER4", "1/100", "1"), ("moon", "1", "SIER4", "1/100", "1"), ("moon", "-0.1", "SIER4", "1/100", "1"),
         ("moon", "0.1", "SIER4", "0", "1"), ("pluto", "0.1", "SIER4", "1/100", "1"), ("moon", "0.1", "RK4", "1/100", "1"),
         ("moon", "nan", "SIER4", "1/100", "1"), ("moon", "0.1", "SIER4", "1/100", "-1")]
    ] + [
        ["bch", "--series", s, "--degree", d] for s, d in [("bch", "0"), ("bch", "100"), ("nope", "3")]
    ] + [
        ["best", "--inertia", "1,1,2"], ["sixth", "--inertia", "water", "--digits", "39"], ["sixth", "--inertia", "water", "--split", "XY"],
        ["report", "--sections", "nope"], ["report", "--quick", "--full"],
        ["nope"], ["--version-of-nothing"],
    ]
    for args in refused:
        R.expect(cls, args, "refused", timeout=60)
    # values at the edge that must give a finite answer, or a clear refusal, never a silent one
    edge = [
        ["integrate", "--scheme", "N2:BAC:2", "--inertia", "1e-100,1.5e-100,2e-100", "--h", "1e-102", "--T", "1e-100"],
        ["integrate", "--scheme", "ABCBA2", "--inertia", "1e100,1.5e100,2e100", "--h", "1e98", "--T", "1e100"],
        ["integrate", "--scheme", "ABCBA2", "--inertia", "water", "--h", "1e-300", "--T", "1e-299"],
        ["integrate", "--scheme", "ABCBA2", "--inertia", "water", "--h", "1e300"],
        ["exact", "--inertia", "water", "--T", "1e15", "--json"],
        ["exact", "--inertia", "water", "--T", "1", "--G0", "0,0,0", "--json"],
        ["exact", "--inertia", "water", "--T", "1", "--G0", "1e-300,1e-300,1e-300", "--json"],
        ["md", "--scene", "dipole-field", "--integrator", "SIER4", "--h", "1e-50", "--runs", "2", "--T", "0.001"],
        ["md", "--scene", "free-water", "--integrator", "MRDL", "--h", "1e6", "--runs", "2", "--T", "0.01"],
        ["spin", "--body", "moon", "--e", "0.999999", "--integrator", "SIER4", "--h", "1/100", "--T", "1", "--json"],
        ["spin", "--body", "1,1,1", "--e", "0", "--integrator", "SIER4", "--h", "1/100", "--T", "1", "--json"],
        # a flat symmetric top: the dedicated systems defined there are solved, the others named
        ["solve", "--family", "N", "--inertia", "1,1,2", "--json"],
        ["integrate", "--scheme", "N2:BAC:2", "--inertia", "1,1,2", "--h", "0.1"],
    ]
    for args in edge:
        R.expect(cls, args, "ok|refused", timeout=120)
    # blown-up runs: said (exit 1, or exit 0 with a warning and a flag), never a number shown as a result
    blown = [
        ["md", "--scene", "dipole-field", "--integrator", "MRDL", "--h", "8", "--dipole", "1e100", "--runs", "2", "--json"],
        ["md", "--scene", "dipole-field", "--integrator", "MRDL", "--h", "1e8", "--T", "1e6", "--runs", "2", "--json"],
        ["md", "--scene", "free-water", "--integrator", "SIER4", "--h", "1e-50", "--T", "1e-47", "--runs", "2", "--json"],
    ]
    for args in blown:
        R.expect_flagged(cls, args, lambda j: j.get("unstable") or j.get("undefined_runs") or j.get("round_off_floor") or j.get("warnings"))


# ------------------------------------------------------------------------------------------------
# 2. Kills at random moments, then resume: the result equals an uninterrupted run's, nothing half written.
def kills(R, quick):
    cls = "kills"
    reference = R.folder("map-reference")
    R.expect(cls, ["map", "--family", "N", "--grid", "9", "--out", str(reference)], "ok")
    want = (reference / "map-N.jsonl").read_text()
    for trial in range(3 if quick else 6):
        d = R.folder(f"map-killed-{trial}")
        args = ["map", "--family", "N", "--grid", "9", "--out", str(d), "--resume"]
        for status in R.kill_until_done(args, 1.5, 12):
            R.record(cls, f"map killed run {trial}", f"exit {status}")
        r = R.run(args)
        got = (d / "map-N.jsonl").read_text() if (d / "map-N.jsonl").exists() else ""
        problem, silent = R.resumed_problem(r, got, want, d, {"map-N.jsonl"},
                                            "the resumed map differs from an uninterrupted run")
        R.record(cls, f"map --grid 9 killed at random moments (trial {trial})", problem, silent)

    # sixth: a small scan killed and resumed gives the tables of an uninterrupted scan
    words = ["--words", "ABABABACABCBACABABABA:BCA"]
    base = ["sixth", "--inertia", "water", *words, "--starts", "200", "--best", "1"]
    reference = R.folder("sixth-reference")
    R.expect(cls, [*base, "--out", str(reference)], "ok", timeout=300)
    want = {p.name: p.read_text() for p in reference.iterdir() if p.suffix == ".table"}
    for trial in range(2 if quick else 4):
        d = R.folder(f"sixth-killed-{trial}")
        R.kill_until_done([*base, "--out", str(d)], 3.0, 6, shortest=0.2)
        r = R.run([*base, "--out", str(d)], timeout=300)
        got = {p.name: p.read_text() for p in d.iterdir() if p.suffix == ".table"}
        problem, silent = R.resumed_problem(r, got, want, d, set(want) | {"scan-state.txt"},
                                            "the resumed scan's tables differ from an uninterrupted scan's")
        R.record(cls, f"sixth killed at random moments (trial {trial})", problem, silent)

    # md --state: a killed equilibration leaves no state file, or a complete one that a second run accepts
    for trial in range(2 if quick else 4):
        d = R.folder(f"md-killed-{trial}")
        state = d / "water.state"
        args = ["md", "--scene", "liquid-water", "--integrator", "SIER2", "--h", "2", "--T", "0.02", "--runs", "1",
                "--molecules", "365", "--state", str(state)]
        p = R.start(args)
        time.sleep(R.rng.uniform(0.5, 6.0))
        if p.poll() is None:
            p.send_signal(signal.SIGKILL)
        p.communicate()
        left = R.leftovers(d, {"water.state"})
        problem, silent = None, False
        if left:
            problem, silent = f"files left behind: {left}", True
        elif state.exists():
            r = R.run(args, timeout=300)
            if r["rc"] != 0:
                problem = "a state written by a killed run is not accepted: " + r["err"].strip()[:200]
        R.record(cls, f"md --state killed during the equilibration (trial {trial})", problem, silent)


# ------------------------------------------------------------------------------------------------
# 3. Two runs on one folder: the second is refused at once, in one line, and the first's result is whole.
def concurrent(R, quick):
    cls = "two concurrent runs"
    cases = [
        ("map", lambda d: ["map", "--family", "N", "--grid", "10", "--out", str(d), "--resume"], "map-N.jsonl"),
        ("sixth", lambda d: ["sixth", "--inertia", "water", "--words", "ABABABACABCBACABABABA:BCA", "--starts", "200",
                             "--best", "1", "--out", str(d)], "scan-state.txt"),
        ("md --state", lambda d: ["md", "--scene", "liquid-water", "--integrator", "SIER2", "--h", "2", "--T", "0.02",
                                  "--runs", "1", "--molecules", "365", "--state", str(d / "w.state")], None),
        ("report", lambda d: ["report", "--quick", "--sections", "accuracy", "--out", str(d)], None),
    ]
    for name, make, _ in cases:
        d = R.folder("concurrent-" + name.replace(" ", "-").replace("--", ""))
        first = R.start(make(d))
        time.sleep(0.3)
        second = R.run(make(d), timeout=60)
        if first.poll() is not None:  # the first had ended: the two did not overlap, nothing was tested
            first.communicate()
            R.record(cls, f"two {name} runs on one folder", "the first run ended before the second started (no overlap)")
            continue
        first_out, first_err = first.communicate(timeout=900)
        problem = R.error_problem(second, 1)  # a busy folder is a failed run (exit 1), the command itself is right
        silent = second["rc"] == 0
        if not problem and "in use" not in second["err"] and "another" not in second["err"]:
            problem = "refused for another reason: " + second["err"].strip()[:200]
        if not problem and first.returncode != 0:
            problem = f"the first run failed: {first_err.strip()[:200]}"
        R.record(cls, f"two {name} runs on one folder", problem, silent)


# ------------------------------------------------------------------------------------------------
# 4. Saved states: truncated, garbage or another problem's: refused unchanged, or resumed correctly.
def state_files(R, quick):
    cls = "state files"
    reference = R.folder("state-map-reference")
    R.expect(cls, ["map", "--family", "N", "--grid", "6", "--out", str(reference)], "ok")
    full = (reference / "map-N.jsonl").read_text()
    lines = full.splitlines(keepends=True)
    header = json.loads(lines[0])
    body = json.loads(lines[3])

    def with_file(text, name="map-N.jsonl"):
        d = R.folder("state-map")
        (d / name).write_text(text)
        return d

    bad_maps = {
        "garbage line": lines[0] + "garbage\n" + "".join(lines[1:3]),
        "line without a result": lines[0] + json.dumps({"s": body["s"], "t": body["t"], "family": "N"}) + "\n",
        "grid 20.9 in the header": json.dumps({**header, "grid": 20.9}) + "\n",
        "grid 2^32 + 20 in the header": json.dumps({**header, "grid": 4294967316}) + "\n",
        "family P header in map-N": json.dumps({**header, "family": "P"}) + "\n",
        "another grid's header": json.dumps({**header, "grid": 7, "bodies": 42}) + "\n",
        "a field of the wrong type": lines[0] + json.dumps({**body, "remainder": "small"}) + "\n",
        "a body off the grid": lines[0] + json.dumps({**body, "s": "1/7"}) + "\n",
        "binary garbage": "\x00\xff\x01" * 100,
        "binary garbage after the header": lines[0] + "\x00\xff\x01" * 100,
    }
    for what, text in bad_maps.items():
        d = with_file(text)
        before = R.digest(d / "map-N.jsonl")
        r = R.expect(cls, ["map", "--family", "N", "--grid", "6", "--out", str(d), "--resume"], "refused",
                     what=f"map --resume on a map file with {what}")
        if R.digest(d / "map-N.jsonl") != before:
            R.record(cls, f"map file with {what} left unchanged", "the refused file was changed", silent=True)
    # an empty file (a kill before the header was written) holds nothing to lose: a fresh map, or a refusal
    d = with_file("")
    R.expect(cls, ["map", "--family", "N", "--grid", "6", "--out", str(d), "--resume"], "ok|refused",
             what="map --resume on an empty map file")
    # a last line cut by a kill is repaired by --resume
    d = with_file(full[:-25])
    r = R.run(["map", "--family", "N", "--grid", "6", "--out", str(d), "--resume"])
    problem = R.error_problem(r, 0) if r["rc"] != 0 else None
    if not problem and (d / "map-N.jsonl").read_text() != full:
        problem = "the repaired map differs from an uninterrupted run"
    R.record(cls, "map --resume on a map file whose last line a kill cut", problem, silent=bool(problem and r["rc"] == 0))

    # sixth: a scan state of another body, or damaged, is refused unchanged
    d = R.folder("state-sixth")
    base = ["sixth", "--words", "ABABABACABCBACABABABA:BCA", "--starts", "200", "--best", "1", "--out", str(d)]
    R.expect(cls, [*base, "--inertia", "water"], "ok", timeout=300)
    state = d / "scan-state.txt"
    good = state.read_text()
    variants = {"another body": None}
    root_lines = [i for i, l in enumerate(good.splitlines()) if l.startswith("root ")]
    if root_lines:
        k = root_lines[0]
        ls = good.splitlines()
        parts = ls[k].split()
        variants["a root line with 9 more values"] = "\n".join(ls[:k] + [ls[k] + " 1" * 9] + ls[k + 1:]) + "\n"
        variants["a root line with one value"] = "\n".join(ls[:k] + [" ".join(parts[:2])] + ls[k + 1:]) + "\n"
        variants["a root of 1e300"] = "\n".join(ls[:k] + [" ".join(parts[:-1] + ["1e300"])] + ls[k + 1:]) + "\n"
        variants["garbage"] = good[: len(good) // 2] + "\x00garbage\n"
    for what, text in variants.items():
        if text is not None:
            state.write_text(text)
        before = R.digest(state)
        inertia = "0.4,0.7,1" if what == "another body" else "water"
        R.expect(cls, [*base, "--inertia", inertia], "refused", what=f"sixth --out with a scan state of {what}", timeout=300)
        if R.digest(state) != before:
            R.record(cls, f"scan state of {what} left unchanged", "the refused state was changed", silent=True)
        state.write_text(good)

    # md --state: damaged or foreign water states are refused before any work
    d = R.folder("state-md")
    s = d / "w.state"
    args = ["md", "--scene", "liquid-water", "--integrator", "SIER2", "--h", "2", "--T", "0.02", "--runs", "1",
            "--molecules", "365", "--state", str(s)]
    r = R.expect(cls, args, "ok", what="md --state writes an equilibrated state", timeout=600)
    if s.exists():
        good = s.read_text()
        ls = good.splitlines()
        damaged = {
            "molecules 365junk": good.replace("molecules 365", "molecules 365junk", 1),
            "time_fs nan": re.sub(r"time_fs \S+", "time_fs nan", good, count=1),
            "a row of 19 columns": "\n".join(ls[:-1] + [ls[-1] + " 0"]) + "\n",
            "a row cut short": "\n".join(ls[:-1] + [" ".join(ls[-1].split()[:5])]) + "\n",
            "a momentum of 1e300": "\n".join(ls[:-1] + [" ".join(ls[-1].split()[:-1] + ["1e300"])]) + "\n",
            "another molecule count": good.replace("molecules 365", "molecules 512", 1),
        }
        for what, text in damaged.items():
            s.write_text(text)
            before = R.digest(s)
            r = R.run(args, timeout=300)
            label = f"md --state with {what}"
            if r["rc"] == 0:
                R.record(cls, label, "accepted: " + r["out"].strip().splitlines()[0][:150] if r["out"].strip() else "accepted",
                         silent=True)
            else:
                R.record(cls, label, R.error_problem(r, r["rc"] if r["rc"] in (1, 2) else 2))
            if R.digest(s) != before:
                R.record(cls, f"{label}: left unchanged", "the refused state was changed", silent=True)
        s.write_text(good)
    for what, path in {"/dev/zero": "/dev/zero", "a folder": str(d)}.items():
        R.expect(cls, args[:-1] + [path], "refused", what=f"md --state {what}")


# ------------------------------------------------------------------------------------------------
# 5. spin: the step asked for or a refusal, untrusted runs flagged, tolerances within the scalar's reach.
def spin_surface(R, quick):
    cls = "spin"
    base = ["spin", "--body", "Hyperion", "--e", "0.1"]
    refused = [
        [*base, "--integrator", "SIER2", "--h", "0.4", "--T", "1"],          # 2.5 steps
        [*base, "--integrator", "SIER2", "--h", "2", "--T", "1"],            # half a step
        [*base, "--integrator", "SIER2", "--h", "1/3", "--T", "1/2"],
        [*base, "--integrator", "odeint-rkf78:1e-30", "--h", "1/100", "--T", "1"],  # 66 days an orbit
        [*base, "--integrator", "odeint-rkf78:1e-16", "--h", "1/100", "--T", "1"],  # below 10 eps of double
        [*base, "--integrator", "odeint-dopri5:1e-19", "--h", "1/100", "--T", "1", "--scalar", "long-double"],
        [*base, "--integrator", "SIER4/Strang-TV", "--h", "1/100", "--T", "1"],     # a TV table as the rotor
        [*base, "--integrator", "SIER2", "--h", "1e-12", "--T", "1e4"],             # beyond 2e9 steps
    ]
    for args in refused:
        R.expect(cls, args, "refused", timeout=60)
    # the JSON's h is the step taken
    r = R.run([*base, "--integrator", "SIER2", "--h", "1/3", "--T", "1", "--json"])
    j = json.loads(r["out"]) if r["rc"] == 0 else {}
    R.record(cls, "spin --h 1/3 --T 1 reports the step it took",
             None if j.get("steps") == 3 and abs(j.get("h", 0) - 1 / 3) < 1e-16 else f"status {r['rc']}, {j.get('h')}, {j.get('steps')}",
             silent=r["rc"] == 0)
    # runs whose answer cannot be trusted: exit 0 with "unstable" and one warning, never silently
    blown = [
        ["spin", "--body", "Hyperion", "--e", "0", "--integrator", "SIER2", "--h", "1", "--T", "50", "--json"],
        ["spin", "--body", "Moon", "--e", "0.99", "--integrator", "SIER4", "--h", "1/1000", "--T", "1", "--json"],
        ["spin", "--body", "Moon", "--e", "0.9", "--integrator", "MRDL", "--h", "1/20", "--T", "20", "--json"],
        ["spin", "--body", "Hyperion", "--e", "0.5", "--integrator", "SIER4", "--h", "1/2", "--T", "40", "--json"],
    ]
    for args in blown:
        R.expect_flagged(cls, args, lambda j: j.get("unstable"))
    # accurate runs stay unflagged and quiet
    for args in (["spin", "--body", "Mercury", "--e", "0.2056", "--omega0", "1.5", "--integrator", "SIER4", "--h", "1/500", "--T", "4", "--json"],
                 ["spin", "--body", "Moon", "--e", "0.0549", "--integrator", "odeint-rkf78:1e-13", "--h", "1/50", "--T", "2", "--json"]):
        r = R.run(args, timeout=120)
        ok = r["rc"] == 0 and not json.loads(r["out"]).get("unstable") and not r["err"].strip()
        R.record(cls, " ".join(args) + " (accurate: not flagged)", None if ok else f"status {r['rc']}: {r['err'][:200]!r}")


# ------------------------------------------------------------------------------------------------
# 6. Files: every writer refuses a FIFO, a device or a folder (and keeps it), writes through a link to a
# regular file; every reader of a user's file refuses a FIFO at once (no hang) and a file too large.
def files_surface(R, quick):
    cls = "files"
    d = R.folder("files")
    fifo = d / "fifo"
    os.mkfifo(fifo)
    (d / "target.txt").write_text("old\n")
    (d / "link.scheme").symlink_to("target.txt")
    (d / "dangling").symlink_to("missing")
    # readers: a FIFO must not be waited on
    R.expect(cls, ["integrate", "--scheme", str(fifo), "--inertia", "water", "--h", "0.1"], "refused", timeout=20)
    mapdir = R.folder("files-map")
    os.mkfifo(mapdir / "map-N.jsonl")
    R.expect(cls, ["map", "--family", "N", "--grid", "4", "--out", str(mapdir), "--resume"], "refused|failed", timeout=20,
             what="map --resume on a FIFO named map-N.jsonl")
    R.expect(cls, ["map", "--family", "N", "--grid", "4", "--out", str(mapdir)], "refused|failed", timeout=20,
             what="map into a folder whose map-N.jsonl is a FIFO")
    R.record(cls, "the map's FIFO is kept", None if (mapdir / "map-N.jsonl").is_fifo() else "replaced", silent=True)
    big = d / "big.scheme"
    big.write_bytes(b"#" * (1 << 20) + b"\n")
    R.expect(cls, ["integrate", "--scheme", str(big), "--inertia", "water", "--h", "0.1"], "refused", timeout=20)
    # resume headers that contradict the map
    ref = R.folder("files-map-ref")
    R.run(["map", "--family", "N", "--grid", "5", "--out", str(ref)])
    lines = (ref / "map-N.jsonl").read_text().splitlines(keepends=True)
    header = json.loads(lines[0])
    for what, h in {"a body count of 7": {**header, "bodies": 7}, "another reference scheme": {**header, "reference": "ABCBA2"},
                    "a neighbour check over half a map": {**header, "neighbour_check": {"probes": 1, "replaced": 0, "passes": 1}}}.items():
        m = R.folder("files-map-header")
        (m / "map-N.jsonl").write_text(json.dumps(h) + "\n" + "".join(lines[1:4]))
        before = R.digest(m / "map-N.jsonl")
        R.expect(cls, ["map", "--family", "N", "--grid", "5", "--out", str(m), "--resume"], "refused", what=f"map --resume with {what}")
        if R.digest(m / "map-N.jsonl") != before:
            R.record(cls, f"map header with {what} left unchanged", "changed", silent=True)
    # writers: solve --out tables, md --state
    out = R.folder("files-solve")
    os.mkfifo(out / "N2_BAC_2.scheme")
    R.expect(cls, ["solve", "--family", "N", "--scheme", "N2", "--perm", "BAC", "--inertia", "water", "--out", str(out)], "failed|refused",
             timeout=120, what="solve --out over a FIFO")
    R.record(cls, "solve's FIFO is kept", None if (out / "N2_BAC_2.scheme").is_fifo() else "replaced", silent=True)
    R.expect(cls, ["md", "--scene", "liquid-water", "--integrator", "SIER2", "--h", "2", "--T", "0.02", "--runs", "1",
                   "--molecules", "365", "--state", str(d / "dangling")], "refused", timeout=60, what="md --state on a link to nothing")
    R.record(cls, "md's dangling link is kept", None if (d / "dangling").is_symlink() and not (d / "missing").exists() else "replaced",
             silent=True)


# ------------------------------------------------------------------------------------------------
# 7. Python: bad calls raise one-line ValueError/TypeError, files keep the writer's rules, nothing crashes.
PYTHON_CASES = r"""
import json, os, stat, sys, tempfile
import numpy as np
import rotlie
W = rotlie.Body.named("water")
cases = {
    "save over a FIFO": lambda d: (os.mkfifo(d + "/f"), rotlie.scheme("ABCBA2").save(d + "/f")),
    # a device node of the replay's own (as root): a faulty save must not replace the machine's /dev/null
    "save over a device": lambda d: (os.mknod(d + "/null", 0o666 | stat.S_IFCHR, os.makedev(1, 3)), rotlie.scheme("ABCBA2").save(d + "/null"))
    if os.geteuid() == 0 else rotlie.scheme("ABCBA2").save("/"),
    "save through a link to nothing": lambda d: (os.symlink("none", d + "/l"), rotlie.scheme("ABCBA2").save(d + "/l")),
    "load_table of a FIFO": lambda d: (os.mkfifo(d + "/g"), rotlie.load_table(d + "/g")),
    "load_table of 1 MB": lambda d: (open(d + "/big", "wb").write(b"#" * (1 << 20) + b"\n"), rotlie.load_table(d + "/big")),
    "Q0 not a rotation": lambda d: rotlie.exact_flow(W, [1, 1, 1], 2 * np.eye(3), t=1),
    "Q0 a reflection": lambda d: rotlie.integrate("ABCBA2", W, [1, 1, 1], np.diag([1.0, 1, -1]), h=0.1, steps=1),
    "complex G0": lambda d: rotlie.exact_flow(W, [1 + 1j, 1, 1], t=1),
    "steps 10**30": lambda d: rotlie.integrate("ABCBA2", W, [1, 1, 1], h=0.1, steps=10**30),
    "digits 2**70": lambda d: rotlie.solve(W, digits=2**70),
    "G0 1e-200": lambda d: rotlie.exact_flow(W, [1e-200, 0, 0], t=1),
    "G0 1.7e150": lambda d: rotlie.exact_flow(W, [1.7e150, 0, 0], t=1),
    "h = 0": lambda d: rotlie.integrate("ABCBA2", W, [1, 1, 1], h=0, steps=1),
    "unknown scheme": lambda d: rotlie.scheme("Nope", W),
    "symmetric top": lambda d: rotlie.best("1,1,2"),
}
out = {}
for name, call in cases.items():
    with tempfile.TemporaryDirectory() as d:
        try:
            call(d)
            out[name] = ["returned", ""]
        except (ValueError, TypeError, RuntimeError, OSError) as e:
            out[name] = [type(e).__name__, str(e)]
print(json.dumps(out))
"""


def python_surface(R, quick):
    cls = "python"
    out = R.python_cases(cls, PYTHON_CASES, timeout=300)
    if out is None:
        return
    for name, (kind, message) in out.items():
        if kind == "returned":
            R.record(cls, name, "returned where it had to raise", silent=True)
        elif "\n" in message.strip() or not message:
            R.record(cls, name, f"{kind} not in one line: {message[:200]!r}")
        else:
            R.record(cls, name)


# ------------------------------------------------------------------------------------------------
# 8. LAMMPS (lmp_rotlie beside the binary, LAMMPS's examples from lammps-examples): bodies rigid/small takes
# run with every rotor; a bad rotor is one ERROR line and a non-zero exit; nothing hangs.
EXAMPLES = pathlib.Path("/usr/share/lammps/examples")


def lammps_run(R, folder, text, timeout=300):
    (folder / "in.replay").write_text(text)
    R.commands += 1
    start = time.monotonic()
    try:
        p = subprocess.run([str(pathlib.Path(R.binary).parent / "lmp_rotlie"), "-in", "in.replay", "-log", "none"], cwd=folder,
                           capture_output=True, text=True, timeout=timeout, errors="replace", env={**os.environ, "OMP_NUM_THREADS": "1"})
        return {"rc": p.returncode, "out": p.stdout, "err": p.stderr, "s": time.monotonic() - start}
    except subprocess.TimeoutExpired:
        return {"rc": None, "out": "", "err": "", "s": timeout}


def lammps_surface(R, quick):
    cls = "lammps"
    if not (pathlib.Path(R.binary).parent / "lmp_rotlie").exists() or not (EXAMPLES / "rigid" / "data.rigid").exists():
        print("lammps: skipped (no lmp_rotlie beside the binary, or no lammps-examples)")
        return

    def judged_ok(what, r, limit=None):
        problem = None
        if r["rc"] is None:
            problem = "hung (timeout)"
        elif r["rc"] != 0:
            problem = f"exit {r['rc']}: {(r['out'] + r['err']).strip().splitlines()[-1:]!r}"
        elif limit and r["s"] > limit:
            problem = f"took {r['s']:.0f} s, over {limit} s"
        R.record(cls, what, problem)

    def judged_error(what, r):
        errors = [l for l in (r["out"] + r["err"]).splitlines() if l.startswith("ERROR")]
        if r["rc"] is None:
            R.record(cls, what, "hung (timeout)")
        elif r["rc"] == 0:
            R.record(cls, what, "ran where it had to stop with an ERROR", silent=True)
        elif r["rc"] < 0:
            R.record(cls, what, f"killed by signal {-r['rc']}")
        else:
            R.record(cls, what, None if len(set(errors)) == 1 else f"{len(set(errors))} distinct ERROR lines")

    clumps = (EXAMPLES / "rigid" / "in.rigid.atomvar").read_text()
    for rotor in ("exact", "auto", "ABCBA2:ABC", "RS4-S5-McLachlan:CBA"):
        d = R.folder("lammps-clumps-" + rotor.replace(":", "-"))
        shutil.copy(EXAMPLES / "rigid" / "data.rigid", d)
        text = clumps.replace("fix 1 all rigid custom v_bodies", f"fix 1 all rigid/sier2/small custom v_bodies rotor {rotor}")
        text = text[:text.rindex("run")] + "run 500\n"
        judged_ok(f"clumps example, rotor {rotor} (a symmetric top among its bodies)", lammps_run(R, d, text), limit=60)
    micelle = (EXAMPLES / "micelle" / "in.micelle-rigid").read_text()
    d = R.folder("lammps-micelle")
    shutil.copy(EXAMPLES / "micelle" / "data.micelle", d)
    text = micelle.replace("fix\t\t5 solute rigid/small molecule", "fix\t\t5 solute rigid/sier2/small molecule rotor auto")
    judged_ok("2-d micelle (150 shapes), rotor auto", lammps_run(R, d, text), limit=120)
    # bad rotor values and files
    d = R.folder("lammps-bad")
    shutil.copy(EXAMPLES / "rigid" / "data.rigid", d)
    os.mkfifo(d / "fifo.scheme")
    (d / "big.scheme").write_bytes(b"#" * (1 << 20) + b"\n")
    for rotor in ("NOPE", "Strang-TV", "N2:XYZ:2", "fifo.scheme", "big.scheme", "P1:BAC:99"):
        text = clumps.replace("fix 1 all rigid custom v_bodies", f"fix 1 all rigid/sier2/small custom v_bodies rotor {rotor}")
        judged_error(f"clumps example, rotor {rotor}", lammps_run(R, d, text[:text.rindex("run")] + "run 10\n", timeout=120))


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--binary", required=True)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--quick", action="store_true", help="fewer kill trials")
    parser.add_argument("--verbose", action="store_true")
    parser.add_argument("--classes", default="extreme,kills,concurrent,state,spin,files,python,lammps,trust,binary,sweep,python-binary")
    a = parser.parse_args()
    binary = str(pathlib.Path(a.binary).resolve())
    with tempfile.TemporaryDirectory(prefix="rotlie-replay-") as work:
        R = Replay(binary, pathlib.Path(work), random.Random(a.seed), a.verbose)
        begin = time.monotonic()
        steps = {"extreme": extreme_values, "kills": kills, "concurrent": concurrent, "state": state_files,
                 "spin": spin_surface, "files": files_surface, "python": python_surface, "lammps": lammps_surface,
                 "trust": binary_trust, "binary": binary_surface, "sweep": sweep_surface, "python-binary": python_binary}
        for name in a.classes.split(","):
            steps[name](R, a.quick)
        for cls, (n, failed, silent) in R.by_class.items():
            print(f"{cls:22s} {n:4d} checks  {failed} failures  {silent} silent")
        for line in R.failures:
            print("FAILURE " + line)
        for line in R.silent:
            print("SILENT  " + line)
        print(f"replay: {R.commands} commands, {sum(v[0] for v in R.by_class.values())} checks, {len(R.failures)} failures, "
              f"{len(R.silent)} silent, {time.monotonic() - begin:.0f} s (seed {a.seed})")
    return 1 if R.failures or R.silent else 0


if __name__ == "__main__":
    sys.exit(main())
