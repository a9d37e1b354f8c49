#!/usr/bin/python3
"""Replays the adversarial campaign against the rotlie binary: extreme values, kills at random moments,
two concurrent runs on one folder, and truncated, garbage or foreign state files.

Each command is judged against what a user must get:
  refused  exit 2 and exactly one line on stderr ("rotlie: error: ..."), and a saved state left unchanged;
  failed   exit 1 and one line (the run failed, said so);
  ok       exit 0 with no non-finite number in the output.
An outcome is a FAILURE when the binary crashes (a signal), hangs (timeout), prints a multi-line error or an
unexpected status, and SILENT when it exits 0 where it had to refuse or fail, prints nan/inf as a result, or
leaves a saved state changed or half written. The summary line gives the counts; the exit status is 1 when
any command failed or was silent.

Usage: replay.py --binary build/release/bin/rotlie [--seed N] [--quick] [--verbose]
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
        r = R.run(args, timeout=120)
        what = " ".join(args)
        if r["rc"] == 1:
            R.record(cls, what, R.error_problem(r, 1))
        elif r["rc"] == 0:
            j = json.loads(r["out"])
            flagged = j.get("unstable") or j.get("undefined_runs") or j.get("round_off_floor") or j.get("warnings")
            R.record(cls, what, None if flagged and r["err"].strip() else "a blown-up run reported without a flag or warning",
                     silent=not flagged)
        else:
            R.record(cls, what, R.error_problem(r, 1))


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


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--binary", required=True)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--quick", action="store_true", help="fewer kill trials")
    parser.add_argument("--verbose", action="store_true")
    parser.add_argument("--classes", default="extreme,kills,concurrent,state")
    a = parser.parse_args()
    binary = str(pathlib.Path(a.binary).resolve())
    with tempfile.TemporaryDirectory(prefix="rotlie-replay-") as work:
        R = Replay(binary, pathlib.Path(work), random.Random(a.seed), a.verbose)
        begin = time.monotonic()
        steps = {"extreme": extreme_values, "kills": kills, "concurrent": concurrent, "state": state_files}
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
