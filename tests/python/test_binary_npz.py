"""`rotlie binary --out FILE.npz`: numpy.load reads one float64 array per CSV column, under the CSV
header's names, holding the CSV's values; a refused run leaves no archive."""
import csv
import os

import numpy as np

from conftest import cli

RUN = ["binary", "--system", "didymos", "--integrator", "KEPLER2", "--h", "60", "--T", "600", "--every", "5"]


def test_npz_columns_equal_the_csv(tmp_path):
    cli(*RUN, "--out", str(tmp_path / "x.npz"))
    cli(*RUN, "--out", str(tmp_path / "x.csv"))
    with open(tmp_path / "x.csv", newline="") as f:
        rows = list(csv.reader(f))
    header, values = rows[0], rows[1:]
    assert len(header) == 32 and len(values) == 3  # t = 0, 300, 600
    with np.load(tmp_path / "x.npz") as npz:
        assert sorted(npz.files) == sorted(header)
        for k, name in enumerate(header):
            column = npz[name]
            assert column.dtype == np.dtype("<f8") and column.shape == (3,), name
            # the CSV writes each number in its shortest round trip: equal, not close
            assert [float(row[k]) for row in values] == column.tolist(), name
    assert list(np.load(tmp_path / "x.npz")["t"]) == [0.0, 300.0, 600.0]
    assert sorted(os.listdir(tmp_path)) == ["x.csv", "x.npz"]  # no temporary left


def test_a_refused_run_leaves_no_archive(tmp_path):
    bad = [a if a != "600" else "610" for a in RUN]  # not a whole number of steps
    message = cli(*bad, "--out", str(tmp_path / "x.npz"), expect=2)
    assert "--T" in message and message.count("\n") == 1
    assert os.listdir(tmp_path) == []

