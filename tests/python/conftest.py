"""Shared helpers of the Python package's tests: the rotlie command line, for the same numbers."""
import json
import os
import re
import pathlib
import subprocess

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]


def rotlie_binary():
    path = os.environ.get("ROTLIE_BINARY") or str(ROOT / "build" / "release" / "bin" / "rotlie")
    if not os.access(path, os.X_OK):
        pytest.skip(f"the rotlie binary is not built ({path})")
    return path


def cli(*args, expect=0):
    """Runs rotlie with args; returns stdout, parsed as JSON when --json is among the args."""
    r = subprocess.run([rotlie_binary(), *args], capture_output=True, text=True, timeout=600)
    assert r.returncode == expect, r.stderr
    if expect != 0:
        return r.stderr
    return json.loads(r.stdout) if "--json" in args else r.stdout


def cli_error(*args):
    """The one-line message `rotlie` prints for bad arguments (exit status 2), without its prefix, its
    options named as Python names them (--primary-period as primary_period): Python's message."""
    line = cli(*args, expect=2).strip()
    prefix = "rotlie: error: "
    assert line.startswith(prefix) and "\n" not in line, line
    return re.sub(r"--([A-Za-z][A-Za-z0-9]*(?:-[A-Za-z0-9]+)*)", lambda m: m.group(1).replace("-", "_"), line[len(prefix):])


def pytest_sessionfinish(session, exitstatus):
    """Under CTest (ROTLIE_SKIP_EXIT_CODE set) a run that skipped a test and failed none exits with
    that code, which CTest reports as skipped rather than passed."""
    code = os.environ.get("ROTLIE_SKIP_EXIT_CODE")
    reporter = session.config.pluginmanager.get_plugin("terminalreporter")
    if code and exitstatus == 0 and reporter is not None and reporter.stats.get("skipped"):
        session.exitstatus = int(code)
