#!/usr/bin/env python3
"""Opt-in benchmark: spt.collide on 100,000 poses in one call against the same C++ batch.

Issue 41's target: the Python call within 1.2x of the C++ batch's time. Both run in this process on
the same pose array, in alternating order round by round (so that a busy machine slows both): the
Python side is spt.collide as a user calls it (array checks and conversion, the batch, the NumPy
answer), the C++ side spt._time_collide_batch, which converts the same array first and then times
query_batch alone inside C++. Prints each side's median and the ratio of the medians
(docs/queries.md, "Python"). Not a test: the figure depends on the machine.

    PYTHONPATH=build/python python3 python/bench_collide.py [--poses N] [--rounds R] [--threads T]
"""
import argparse
import os
import statistics
import time

import numpy as np

import spt

MESHES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "resources", "meshes")


def main():
    """Time both sides and print the figures."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--a", default=os.path.join(MESHES, "torus.obj"), help="object A")
    parser.add_argument("--b", default=os.path.join(MESHES, "figure.obj"), help="object B")
    parser.add_argument("--poses", type=int, default=100_000)
    parser.add_argument("--rounds", type=int, default=11)
    parser.add_argument("--level", default="spheres")
    parser.add_argument("--threads", type=int, default=0, help="0: every core")
    args = parser.parse_args()

    a, b = spt.load(args.a), spt.load(args.b)
    rng = np.random.default_rng(41)
    reach = 0.6 * (a.diagonal + b.diagonal) / 2  # about a quarter of the poses collide
    poses = np.empty((args.poses, 7))
    poses[:, :3] = rng.uniform(-reach, reach, (args.poses, 3))
    q = rng.normal(size=(args.poses, 4))
    poses[:, 3:] = q / np.linalg.norm(q, axis=1, keepdims=True)

    def python_side():
        start = time.perf_counter()
        spt.collide(a, b, poses, args.level, threads=args.threads)
        return time.perf_counter() - start

    def cpp_side():
        return spt._time_collide_batch(a, b, poses, args.level, threads=args.threads)

    hits = spt.collide(a, b, poses, args.level, threads=args.threads)  # warms pool and caches
    cpp_side()
    py_times, cpp_times = [], []
    for r in range(args.rounds):
        if r % 2 == 0:
            py_times.append(python_side())
            cpp_times.append(cpp_side())
        else:
            cpp_times.append(cpp_side())
            py_times.append(python_side())
    py_median, cpp_median = statistics.median(py_times), statistics.median(cpp_times)
    print(f"{args.poses} poses, {int(hits.sum())} colliding, level {args.level}, "
          f"threads {args.threads or 'all'}, {args.rounds} rounds")
    print(f"spt.collide (Python): median {py_median * 1e3:.1f} ms, "
          f"rounds {', '.join(f'{t * 1e3:.1f}' for t in py_times)}")
    print(f"query_batch (C++):    median {cpp_median * 1e3:.1f} ms, "
          f"rounds {', '.join(f'{t * 1e3:.1f}' for t in cpp_times)}")
    print(f"ratio of medians: {py_median / cpp_median:.3f}")


if __name__ == "__main__":
    main()
