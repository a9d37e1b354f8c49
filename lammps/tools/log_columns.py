#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""The thermo blocks of a LAMMPS log (or screen output) as CSV columns, for plotting.

A thermo block starts with the header line LAMMPS prints before a run's rows (its first word is
`Step`) and ends at the run's `Loop time of ...` line (or at the end of an unfinished log). Rows are
the lines of as many numbers as the header has names; anything else between them (warnings, a
neighbour-list note) is skipped. Blocks whose headers differ keep their own columns: the CSV has the
union of the names, empty where a block has no such column.

    log_columns.py log.lammps                  # every block, one CSV on standard output
    log_columns.py log.lammps --block -1       # the last block only (blocks count from 0)
    log_columns.py log.lammps -o thermo.csv --columns Step,TotEng,f_r
    log_columns.py log.lammps --list           # the blocks: their rows and columns

The first CSV column, `block`, is the block's number (the run's, in input order). Only the standard
library is used.
"""
import argparse
import csv
import sys


def thermo_blocks(lines):
    """The log's thermo blocks: a list of (columns, rows), rows as lists of the numbers' text."""
    blocks = []
    current = None
    for line in lines:
        words = line.split()
        if not words:
            continue
        if words[0] == "Step":
            current = (words, [])
            blocks.append(current)
            continue
        if current is None:
            continue
        if line.startswith("Loop time of"):
            current = None
            continue
        if len(words) != len(current[0]):
            continue
        try:
            for w in words:
                float(w)
        except ValueError:
            continue
        current[1].append(words)
    return blocks


def write_csv(blocks, out, chosen=None, columns=None):
    """Writes the blocks (indices `chosen`, all when None) as CSV to the file object `out`."""
    indices = range(len(blocks)) if chosen is None else chosen
    names = []
    for i in indices:
        for c in blocks[i][0]:
            if c not in names:
                names.append(c)
    if columns:
        missing = [c for c in columns if c not in names]
        if missing:
            raise ValueError("no column %s in the chosen blocks (they have %s)" % (", ".join(missing), ", ".join(names)))
        names = columns
    w = csv.writer(out, lineterminator="\n")
    w.writerow(["block"] + names)
    for i in indices:
        header, rows = blocks[i]
        where = {c: k for k, c in enumerate(header)}
        for r in rows:
            w.writerow([i] + [r[where[c]] if c in where else "" for c in names])


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("log", help="a LAMMPS log file (or its screen output); - for standard input")
    p.add_argument("--block", type=int, action="append", help="a block's number (from 0; negative from the end); repeatable")
    p.add_argument("--columns", help="comma-separated column names (LAMMPS's header words), in this order")
    p.add_argument("-o", "--output", help="the CSV file (default: standard output)")
    p.add_argument("--list", action="store_true", help="list the blocks instead")
    args = p.parse_args(argv)
    try:
        text = sys.stdin.read() if args.log == "-" else open(args.log, encoding="utf-8", errors="replace").read()
    except OSError as e:
        print("log_columns: cannot read %s: %s" % (args.log, e.strerror), file=sys.stderr)
        return 2
    blocks = thermo_blocks(text.splitlines())
    if not blocks:
        print("log_columns: %s has no thermo block (no header line starting with Step)" % args.log, file=sys.stderr)
        return 1
    if args.list:
        for i, (header, rows) in enumerate(blocks):
            first = rows[0][0] if rows else "-"
            last = rows[-1][0] if rows else "-"
            print("block %d: %d rows (Step %s to %s): %s" % (i, len(rows), first, last, " ".join(header)))
        return 0
    chosen = None
    if args.block:
        chosen = []
        for b in args.block:
            if not -len(blocks) <= b < len(blocks):
                print("log_columns: no block %d (the log has %d, 0 to %d)" % (b, len(blocks), len(blocks) - 1), file=sys.stderr)
                return 1
            chosen.append(b % len(blocks))
    columns = [c for c in args.columns.split(",") if c] if args.columns else None
    out = open(args.output, "w", newline="") if args.output else sys.stdout
    try:
        write_csv(blocks, out, chosen, columns)
    except ValueError as e:
        print("log_columns: %s" % e, file=sys.stderr)
        return 1
    finally:
        if args.output:
            out.close()
    return 0


if __name__ == "__main__":
    sys.exit(main())
