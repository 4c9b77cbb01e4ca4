#!/usr/bin/env python3
"""deforming_bench's CSVs parse as CSV: every row has the header's field count, a row's name
with a comma in it ("spt spheres, 2 threads") is one field, and the per-frame columns are plain
names; the work file has a row for each spt library and frame of the case asked for with
--case, and no other case. Runs the bench on a few frames of one case (not a timing: only the
files' shape is checked).

usage: deforming_bench_csv.py DEFORMING_BENCH OUT_DIR
"""
import csv
import os
import re
import subprocess
import sys


def rows_of(path):
    with open(path, newline="") as f:
        return list(csv.reader(f))


def main():
    bench, out_dir = sys.argv[1], sys.argv[2]
    os.makedirs(out_dir, exist_ok=True)
    frames = 4
    subprocess.run([bench, "--frames", str(frames), "--rounds", "1", "--case", "figure-floor", "--out-dir", out_dir,
                    "--stem", "shape"], check=True, stdout=subprocess.DEVNULL)
    failures = []
    for name in ("shape.csv", "shape-frames.csv", "shape-work.csv"):
        rows = rows_of(os.path.join(out_dir, name))
        header = rows[0]
        if len(rows) < 2:
            failures.append(f"{name}: no rows under the header")
        for i, row in enumerate(rows[1:], start=2):
            if len(row) != len(header):
                failures.append(f"{name} line {i}: {len(row)} fields under a header of {len(header)}")
        if len(set(header)) != len(header):
            failures.append(f"{name}: a column name repeats: {header}")
        for column in header:
            if not re.fullmatch(r"[A-Za-z0-9_]+", column):
                failures.append(f"{name}: column {column!r} is not a plain name")
    libraries = {row[1] for row in rows_of(os.path.join(out_dir, "shape.csv"))[1:]}
    if "spt spheres, 2 threads" not in libraries:
        failures.append(f"shape.csv: no library 'spt spheres, 2 threads' among {sorted(libraries)}")
    frames_header = rows_of(os.path.join(out_dir, "shape-frames.csv"))[0]
    if "spt_spheres_2_threads_median_us" not in frames_header:
        failures.append(f"shape-frames.csv: no column spt_spheres_2_threads_median_us in {frames_header}")
    work = rows_of(os.path.join(out_dir, "shape-work.csv"))
    if work[0] != ["case", "frame", "library", "collide", "node_pairs", "leaf_tests"]:
        failures.append(f"shape-work.csv: header {work[0]}")
    cases = {row[0] for row in work[1:]} | {row[0] for row in rows_of(os.path.join(out_dir, "shape.csv"))[1:]}
    if cases != {"figure-floor"}:
        failures.append(f"--case figure-floor ran the cases {sorted(cases)}")
    work_libraries = {row[2] for row in work[1:]}
    for library in ("spt spheres, 2 threads", "spheres query, lazy tight", "spheres query, rigid"):
        frames_of = sorted(int(row[1]) for row in work[1:] if row[2] == library)
        if frames_of != list(range(frames)):
            failures.append(f"shape-work.csv: library {library!r} has frames {frames_of}")
    if any(name.startswith(("FCL", "Bullet")) for name in work_libraries):
        failures.append(f"shape-work.csv: a library without counts among {sorted(work_libraries)}")
    for row in work[1:]:
        if row[3] not in ("0", "1") or not row[4].isdigit() or int(row[4]) < 1 or not row[5].isdigit():
            failures.append(f"shape-work.csv: row {row}")
            break
    unknown = subprocess.run([bench, "--case", "no-such-case"], capture_output=True, text=True)
    if unknown.returncode != 1 or "no-such-case" not in unknown.stderr:
        failures.append(f"--case no-such-case: exit {unknown.returncode}, {unknown.stderr!r}")
    for f in failures:
        print(f, file=sys.stderr)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
