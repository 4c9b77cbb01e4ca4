#!/usr/bin/env python3
"""Runs distance_bench or pair_bench on pairs of meshes that nobody tuned spt to: assimp's test models.

The accuracy benchmark's meshes and FCL's env/rob are the pairs spt was measured on while it was
written; this sweep pairs every readable model under a folder (sorted, then shuffled with a fixed
seed, so the pairs are the same on every machine with the same models) and runs one benchmark on
each pair at random poses of B in A's box. It writes one markdown table. `--query distance`
(distance_bench): whether `exact` agrees with FCL's distance and `spheres` keeps its bound on
every pose, and each query's time against FCL's in the same run. `--query collide`
(pair_bench): each level's agreement with `exact` (false positives and negatives) and the
`any` query's time against FCL's collide. Opt-in, not in CI; figures and commands:
docs/distance-sweep.md, docs/collide-sweep.md.
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


def median(v):
    v = sorted(v)
    return "-" if not v else f"{v[len(v) // 2]:.2f}"


class DistanceSweep:
    """distance_bench --pair: agreement with FCL's distance and time against it."""
    bench = "distance_bench"
    title = "Distance against FCL on models spt was not written against"
    about = "[queries.md](queries.md), \"Distance against FCL\""

    def __init__(self):
        self.lines, self.exact_apart, self.spheres_apart = [], [], []

    def args(self, a, pa, pb):
        return ["--pair", pa, pb, "--poses", str(a.poses), "--rounds", str(a.rounds)]

    def add(self, pa, pb, out, failed):
        exact, spheres = row(out, "spt exact"), row(out, "spt spheres")
        fast = row(out, "spt exact, max 1%, no depth")
        head = re.search(r"^A: (\d+) triangles, (\d+) samples; B: (\d+) triangles, (\d+) samples; (\d+) poses, "
                         r"(\d+) apart", out, re.M)
        if not (exact and spheres and fast and head):
            return False
        ta, sa, tb, sb, poses, apart = (int(g) for g in head.groups())
        if exact[1] != "100.00%" or spheres[1] != "100.00%":
            failed.append(f"{pa} / {pb}: exact agrees {exact[1]}, spheres within the bound {spheres[1]}")
        if ratio(exact[7]) != "-":
            self.exact_apart.append(float(ratio(exact[7])))
            self.spheres_apart.append(float(ratio(spheres[7])))
        self.lines.append(f"| {pa} ({ta:,} / {sa:,}) | {pb} ({tb:,} / {sb:,}) | {apart} / {poses - apart} | "
                          f"{exact[1]} | {exact[2]} | {ratio(exact[7])} / {ratio(exact[8])} | {spheres[1]} | "
                          f"{ratio(spheres[7])} / {ratio(spheres[8])} | {fast[5]} |")
        return True

    def summary(self, failed):
        e = self.exact_apart
        return [f"- Agreement failures (`exact` off FCL's distance by more than 1e-6 of the diagonal, or "
                f"`spheres` outside its bound), timeouts and crashes: {len(failed)}" + (":" if failed else ""),
                *[f"  - {f}" for f in failed],
                f"- Pairs with apart poses: {len(e)}; FCL's apart median over spt's, median over the pairs: "
                f"`exact` {median(e)}x, `spheres` {median(self.spheres_apart)}x; `exact` faster than FCL on "
                f"{sum(r > 1 for r in e)}, at least 3x on {sum(r >= 3 for r in e)}."]

    def table(self):
        return ["Times are FCL's median over spt's (above 1: spt faster), apart / meeting poses; A and B give "
                "(triangles / samples).", "",
                "| A | B | poses apart / meeting | `exact` agrees | worst / diagonal | `exact` | "
                "`spheres` within bound | `spheres` | `exact`, max 1%, no depth, all poses |",
                "|---|---|---|---|---|---|---|---|---|", *self.lines]


class CollideSweep:
    """pair_bench: each level's agreement with `exact` and the `any` query's time against FCL's."""
    bench = "pair_bench"
    title = "Collision against FCL on models spt was not written against"
    about = "[queries.md](queries.md), \"What the measurements say\""

    def __init__(self):
        self.lines, self.below, self.exact_x, self.spheres_x = [], [], [], []

    def args(self, a, pa, pb):
        return [pa, pb, "--poses", str(a.poses), "--repeat", str(a.rounds)]

    def add(self, pa, pb, out, failed):
        levels = {name: row(out, name) for name in ("exact", "spheres", "bounds", "FCL (OBBRSS)")}
        head = re.search(r"^A: .* \((\d+) triangles, (\w+), (\d+) samples\); B: .* \((\d+) triangles, (\w+), "
                         r"(\d+) samples\)", out, re.M)
        colliding = re.search(r"(\d+) random poses .*?, (\d+) colliding", out)
        speed = re.search(r"exact ([0-9.]+)x (faster|slower), spheres ([0-9.]+)x (faster|slower)", out)
        if not (all(levels.values()) and head and colliding and speed):
            return False
        ta, ca, sa, tb, cb, sb = head.groups()
        poses, hits = colliding.groups()
        sp, bo, fcl = (levels[k] for k in ("spheres", "bounds", "FCL (OBBRSS)"))
        if float(sp[1].rstrip("%")) < 99:
            self.below.append(f"{pa} / {pb}: `spheres` {sp[1]} ({sp[2]} false positives, {sp[3]} false negatives)")
        times = lambda k: float(speed.group(k)) if speed.group(k + 1) == "faster" else 1 / float(speed.group(k))
        self.exact_x.append(times(1))
        self.spheres_x.append(times(3))
        self.lines.append(f"| {pa} ({int(ta):,}, {ca}, {int(sa):,}) | {pb} ({int(tb):,}, {cb}, {int(sb):,}) | "
                          f"{hits} / {poses} | {sp[1]} ({sp[2]} / {sp[3]}) | {bo[1]} ({bo[2]} / {bo[3]}) | "
                          f"{fcl[1]} ({fcl[2]} / {fcl[3]}) | {times(1):.2f} | {times(3):.2f} |")
        return True

    def summary(self, failed):
        e, s = self.exact_x, self.spheres_x
        return [f"- Timeouts and crashes: {len(failed)}" + (":" if failed else ""), *[f"  - {f}" for f in failed],
                f"- Pairs where `spheres` agrees with `exact` on less than 99% of the poses: {len(self.below)}"
                + (":" if self.below else ""), *[f"  - {b}" for b in self.below],
                f"- FCL's median time over spt's, median over the pairs: `exact` {median(e)}x, `spheres` "
                f"{median(s)}x; `spheres` faster than FCL on {sum(r > 1 for r in s)} of {len(s)} pairs, at least 10x "
                f"on {sum(r >= 10 for r in s)}."]

    def table(self):
        return ["Agreement with `exact` (which counts a model inside another's closed part as colliding; FCL "
                "does not), false positives / negatives; times are FCL's median over spt's (above 1: spt "
                "faster). A and B give (triangles, closed or open, samples).", "",
                "| A | B | colliding / poses | `spheres` agrees | `bounds` agrees | FCL agrees | `exact` | "
                "`spheres` |", "|---|---|---|---|---|---|---|---|", *self.lines]


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--query", choices=("distance", "collide"), default="distance",
                   help="distance: distance_bench; collide: pair_bench")
    p.add_argument("--bench", help="the benchmark's binary (default: build/bench/distance_bench or pair_bench)")
    p.add_argument("--models", default="/usr/share/assimp/models", help="folder of meshes (assimp-testmodels)")
    p.add_argument("--poses", type=int, default=40, help="random poses a pair")
    p.add_argument("--rounds", type=int, default=1, help="interleaved rounds (distance) or repeats (collide) a pair")
    p.add_argument("--largest", type=int, default=3_000_000, help="skip files of this many bytes or more")
    p.add_argument("--timeout", type=int, default=300, help="seconds a pair may take")
    p.add_argument("-o", "--output", default="-", help="markdown file (default: stdout)")
    a = p.parse_args()
    sweep = (DistanceSweep if a.query == "distance" else CollideSweep)()
    bench = a.bench or f"build/bench/{sweep.bench}"
    if not os.access(bench, os.X_OK):
        sys.exit(f"model_sweep: {bench}: not an executable (build it: ninja -C build bench/{sweep.bench})")
    files = models(a.models, a.largest)
    if len(files) < 2:
        sys.exit(f"model_sweep: {a.models}: fewer than two meshes")
    unreadable, failed, checked = [], [], 0
    for i in range(0, len(files) - 1, 2):
        pa, pb = files[i], files[i + 1]
        try:
            run = subprocess.run([bench, *sweep.args(a, os.path.join(a.models, pa), os.path.join(a.models, pb))],
                                 capture_output=True, text=True, timeout=a.timeout)
        except subprocess.TimeoutExpired:
            failed.append(f"{pa} / {pb}: over {a.timeout} s")
            continue
        if run.returncode == 2:  # bad input: a model assimp reads without triangles, or cannot read
            unreadable.append(run.stderr.strip().splitlines()[-1] if run.stderr.strip() else f"{pa} / {pb}")
            continue
        if run.returncode != 0 or not sweep.add(pa, pb, run.stdout, failed):
            failed.append(f"{pa} / {pb}: exit {run.returncode}: {run.stderr.strip()[-200:]}")
            continue
        checked += 1
    command = "python3 bench/model_sweep.py " + " ".join(sys.argv[1:])
    when = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    out = [f"# {sweep.title}", "",
           f"Generated by `{command.strip()}` (bench/model_sweep.py), {when}, {cpu()}; what the columns mean: "
           f"{sweep.about}.", "",
           f"Pairs of `{a.models}`: {checked} pairs checked, {a.poses} random poses each "
           f"(`{' '.join([sweep.bench, *sweep.args(a, 'A', 'B')])}`).", "",
           *sweep.summary(failed),
           f"- Not read ({sweep.bench}'s exit 2 and message): {len(unreadable)}", *[f"  - {u}" for u in unreadable],
           "", *sweep.table()]
    text = "\n".join(out) + "\n"
    if a.output == "-":
        sys.stdout.write(text)
    else:
        with open(a.output, "w") as f:
            f.write(text)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
