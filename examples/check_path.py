#!/usr/bin/env python3
"""Check a planned path of the bundled robot arm into a bin with the `spt` module.

The bin (a floor and four sides, as in resources/scenes/robot_arm.json) stands still; the arm
follows straight segments between waypoints, its rotation interpolated by slerp. Every pose is
checked against every part of the bin in one call a part: spt.collide for contact and
spt.distance for the clearance (looked for up to the margin only, as a planner asks), and at the
first contact spt.backtrack says how far back along
the path the arm is free again. Run from the source tree after building:

    PYTHONPATH=build/python python3 examples/check_path.py [--steps N] [--margin M]
"""
import argparse
import os
import sys
import time

import numpy as np

import spt

SCENES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "resources", "scenes")
# The bin's parts: mesh and world pose (position, quaternion w x y z), as robot_arm.json has them.
QUARTER_TURN = (0.7071067811865476, 0.0, 0.7071067811865476, 0.0)
BIN = [
    ("floor", "bin_floor.obj", (0.0, 0.0, 0.0), (1.0, 0.0, 0.0, 0.0)),
    ("side -z", "bin_side.obj", (0.0, 0.3, -0.625), (1.0, 0.0, 0.0, 0.0)),
    ("side +z", "bin_side.obj", (0.0, 0.3, 0.625), (1.0, 0.0, 0.0, 0.0)),
    ("side -x", "bin_side.obj", (-0.625, 0.3, 0.0), QUARTER_TURN),
    ("side +x", "bin_side.obj", (0.625, 0.3, 0.0), QUARTER_TURN),
]
# The arm's waypoints: above the bin, down into it, then across it, turning 30 degrees about y.
WAYPOINTS = [((-0.4, 1.2, -0.2), 0.0), ((-0.4, 0.45, -0.2), 0.0), ((0.3, 0.45, -0.2), 30.0)]


def transform(position, quaternion):
    """4 x 4 rigid transform of a position and a unit quaternion (w x y z)."""
    w, x, y, z = quaternion
    m = np.eye(4)
    m[:3, :3] = [[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                 [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                 [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]]
    m[:3, 3] = position
    return m


def plan(steps):
    """The arm's world transforms along the waypoints, `steps` poses a segment (N x 4 x 4), and
    its motion at each (N x 3, world frame): what a planner would hand over to be checked."""
    poses, motion = [], []
    for (p0, yaw0), (p1, yaw1) in zip(WAYPOINTS, WAYPOINTS[1:]):
        for t in np.linspace(0.0, 1.0, steps, endpoint=False):
            half = np.radians(yaw0 + t * (yaw1 - yaw0)) / 2  # slerp about one axis
            position = (1 - t) * np.array(p0) + t * np.array(p1)
            poses.append(transform(position, (np.cos(half), 0.0, np.sin(half), 0.0)))
            motion.append(np.subtract(p1, p0))
    return np.array(poses), np.array(motion)


def main():
    """Check the path and print a short report."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--steps", type=int, default=200, help="poses a segment of the path")
    parser.add_argument("--margin", type=float, default=0.05, help="clearance wanted, model units")
    args = parser.parse_args()

    arm = spt.load(os.path.join(SCENES, "arm.obj"))
    meshes = {mesh for _, mesh, _, _ in BIN}
    models = {mesh: spt.load(os.path.join(SCENES, mesh)) for mesh in meshes}
    parts = {name: (models[mesh], transform(p, q)) for name, mesh, p, q in BIN}
    world, motion = plan(args.steps)
    n = len(world)

    start = time.perf_counter()
    hits, clearance = np.zeros(n, dtype=bool), np.full(n, np.inf)
    first = None  # (pose, part) of the first contact along the path
    for name, (model, part_pose) in parts.items():
        in_part = np.linalg.inv(part_pose) @ world  # the arm in the part's frame: B in A's
        hit = spt.collide(model, arm, in_part)
        gap = spt.distance(model, arm, in_part, max_distance=args.margin)  # inf beyond it
        hits |= hit
        clearance = np.minimum(clearance, gap)
        if hit.any() and (first is None or hit.argmax() < first[0]):
            first = (int(hit.argmax()), name)
    seconds = time.perf_counter() - start

    print(f"path: {n} poses of arm.obj against {len(parts)} parts of the bin, "
          f"checked in {seconds * 1e3:.1f} ms")
    low = int(clearance.argmin())
    if np.isinf(clearance[low]):
        print(f"smallest clearance: more than the margin {args.margin} everywhere")
    else:
        overlap = " (overlap)" if clearance[low] <= 0 else ""
        print(f"smallest clearance: {clearance[low]:.4f} at pose {low}{overlap}")
    close = int(np.count_nonzero(np.isfinite(clearance) & ~hits))
    print(f"poses closer than the margin {args.margin} but free: {close}")
    if first is None:
        print("the path is free")
        return 0
    pose, name = first
    model, part_pose = parts[name]
    in_part = np.linalg.inv(part_pose) @ world[pose:pose + 1]
    along = np.linalg.inv(part_pose)[:3, :3] @ motion[pose]
    back = spt.backtrack(model, arm, in_part, along[None, :])[0]
    print(f"first contact: pose {pose} with the {name}; free again {back:.4f} back along the path")
    print(f"colliding poses: {int(hits.sum())} of {n}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
