#!/usr/bin/env python3
"""Runs distance_bench on pairs of meshes that nobody tuned spt to: assimp's test models.

The accuracy benchmark's meshes and FCL's env/rob are the pairs spt was measured on while it was
written; this sweep pairs every readable model under a folder (sorted, then shuffled with a fixed
seed, so the pairs are the same on every machine with the same models) and asks distance_bench
for each pair at random poses of B in A's box. It writes one markdown table: whether `exact`
agrees with FCL's distance and `spheres` keeps its bound on every pose, and each query's time
against FCL's in the same run. Opt-in, not in CI; figures and command: docs/distance-vs-fcl.md.
"""
import argparse
import datetime
import os
import random
import re
import subprocess
import sys

EXTENSIONS = (".obj", ".stl", ".ply", ".off", ".3ds", ".dae", ".glb", ".fbx", ".x", ".ac", ".ase", ".lwo", ".ms3d",
              ".nff")


def models(root, largest):
    found = []
    for folder, _, files in os.walk(root):
        for name in files:
            path = os.path.join(folder, name)
            if name.lower().endswith(EXTENSIONS) and 3_000 < os.path.getsize(path) < largest:
                found.append(os.path.relpath(path, root))
    found.sort()
    random.Random(1).shuffle(found)
    return found


def cpu():
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return "unknown CPU"


def cells(line):
    return [c.strip() for c in line.strip().strip("|").split("|")]


def row(text, name):
    for line in text.splitlines():
        if line.startswith("| " + name + " |"):
            return cells(line)
    return None


def ratio(cell):
    """'75.5 µs, 1.25' -> '1.25'; '-' where the bench had no pose of that kind."""
    value = cell.split(",")[-1].strip()
    return "-" if value in ("-nan", "nan", "inf") else value


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--bench", default="build/bench/distance_bench", help="distance_bench binary")
    p.add_argument("--models", default="/usr/share/assimp/models", help="folder of meshes (assimp-testmodels)")
    p.add_argument("--poses", type=int, default=40, help="random poses a pair")
    p.add_argument("--rounds", type=int, default=1, help="interleaved rounds a pair")
    p.add_argument("--largest", type=int, default=3_000_000, help="skip files of this many bytes or more")
    p.add_argument("--timeout", type=int, default=300, help="seconds a pair may take")
    p.add_argument("-o", "--output", default="-", help="markdown file (default: stdout)")
    a = p.parse_args()
    if not os.access(a.bench, os.X_OK):
        sys.exit(f"distance_sweep: {a.bench}: not an executable (build it: ninja -C build bench/distance_bench)")
    files = models(a.models, a.largest)
    if len(files) < 2:
        sys.exit(f"distance_sweep: {a.models}: fewer than two meshes")
    lines, unreadable, checked, failed = [], [], 0, []
    exact_apart, spheres_apart = [], []
    for i in range(0, len(files) - 1, 2):
        pa, pb = files[i], files[i + 1]
        try:
            run = subprocess.run([a.bench, "--pair", os.path.join(a.models, pa), os.path.join(a.models, pb),
                                  "--poses", str(a.poses), "--rounds", str(a.rounds)], capture_output=True,
                                 text=True, timeout=a.timeout)
        except subprocess.TimeoutExpired:
            failed.append(f"{pa} / {pb}: over {a.timeout} s")
            continue
        if run.returncode == 2:  # bad input: a model assimp reads without triangles, or cannot read
            unreadable.append(run.stderr.strip().splitlines()[-1] if run.stderr.strip() else f"{pa} / {pb}")
            continue
        exact, spheres = row(run.stdout, "spt exact"), row(run.stdout, "spt spheres")
        fast = row(run.stdout, "spt exact, max 1%, no depth")
        head = re.search(r"^A: (\d+) triangles, (\d+) samples; B: (\d+) triangles, (\d+) samples; (\d+) poses, "
                         r"(\d+) apart", run.stdout, re.M)
        if run.returncode != 0 or not (exact and spheres and fast and head):
            failed.append(f"{pa} / {pb}: exit {run.returncode}: {run.stderr.strip()[-200:]}")
            continue
        checked += 1
        ta, sa, tb, sb, poses, apart = (int(g) for g in head.groups())
        if exact[1] != "100.00%" or spheres[1] != "100.00%":
            failed.append(f"{pa} / {pb}: exact agrees {exact[1]}, spheres within the bound {spheres[1]}")
        if ratio(exact[7]) != "-":
            exact_apart.append(float(ratio(exact[7])))
            spheres_apart.append(float(ratio(spheres[7])))
        lines.append(f"| {pa} ({ta:,} / {sa:,}) | {pb} ({tb:,} / {sb:,}) | {apart} / {poses - apart} | {exact[1]} | "
                     f"{exact[2]} | {ratio(exact[7])} / {ratio(exact[8])} | {spheres[1]} | "
                     f"{ratio(spheres[7])} / {ratio(spheres[8])} | {fast[5]} |")

    def median(v):
        v = sorted(v)
        return "-" if not v else f"{v[len(v) // 2]:.2f}"

    command = "python3 bench/distance/distance_sweep.py " + " ".join(sys.argv[1:])
    when = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    out = ["# Distance against FCL on models spt was not written against", "",
           f"Generated by `{command.strip()}` ({__file__.split('/')[-1]}), {when}, {cpu()}; what the columns "
           "mean: [queries.md](queries.md), \"Distance against FCL\".", "",
           f"Pairs of `{a.models}`: {checked} pairs checked, {a.poses} random poses each "
           f"(`distance_bench --pair A B --poses {a.poses} --rounds {a.rounds}`).",
           "",
           f"- Agreement failures (`exact` off FCL's distance by more than 1e-6 of the diagonal, or `spheres` "
           f"outside its bound), timeouts and crashes: {len(failed)}" + ("" if not failed else ":"),
           *[f"  - {f}" for f in failed],
           f"- Pairs with apart poses: {len(exact_apart)}; FCL's apart median over spt's, median over the pairs: "
           f"`exact` {median(exact_apart)}x, `spheres` {median(spheres_apart)}x; `exact` faster than FCL on "
           f"{sum(r > 1 for r in exact_apart)}, at least 3x on {sum(r >= 3 for r in exact_apart)}.",
           f"- Not read (distance_bench's exit 2 and message): {len(unreadable)}",
           *[f"  - {u}" for u in unreadable],
           "",
           "Times are FCL's median over spt's (above 1: spt faster), apart / meeting poses; A and B give "
           "(triangles / samples).",
           "",
           "| A | B | poses apart / meeting | `exact` agrees | worst / diagonal | `exact` | `spheres` within bound | "
           "`spheres` | `exact`, max 1%, no depth, all poses |",
           "|---|---|---|---|---|---|---|---|---|",
           *lines]
    text = "\n".join(out) + "\n"
    if a.output == "-":
        sys.stdout.write(text)
    else:
        with open(a.output, "w") as f:
            f.write(text)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
