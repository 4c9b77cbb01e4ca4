#!/usr/bin/env python3
"""Where spt's update of a deforming model goes, from a perf recording (docs/deforming.md, "Benchmark").

    perf record --call-graph dwarf,16384 -F 999 -o fig.data build/bench/deforming_bench --profile-update 400
    perf record --call-graph dwarf,16384 -F 999 -o fbx.data build/bench/deforming_bench --profile-update 1200 --profile-fbx
    python3 bench/deforming/update_profile.py fig.data

Every sample whose call chain passes through DeformingModel::pose_on, CollisionModel::follow_surface
or CollisionModel::measure (the last two are tail calls, so pose_on may be missing from their
chains), and not through the set-up's conversion, counts towards the update; it is put in the
bucket of the first function named below met from the leaf up, or in "the rest".
"""
import collections
import subprocess
import sys

TREE = "exact level: triangle tree rebuilt (build_triangle_tree, fit_obb)"
MEASURE = "CollisionModel::measure (extent, reach, bounds_reach)"
SNAP = "normal snapping (encode_normal, decode_normal)"
BUCKETS = [("fit_obb", TREE), ("Builder::build", TREE), ("build_triangle_tree", TREE),
           ("fit_triangle_spheres", "exact level: triangle spheres (fit_triangle_spheres)"),
           ("measure_triangles", MEASURE), ("CollisionModel::measure", MEASURE),
           ("refit_bounds", "refit of the bounding spheres (CompactTree::refit_bounds)"),
           ("follow_samples", "sphere centres and normals into the layout (CompactTree::follow_samples)"),
           ("angle_weighted_normals", "vertex normals (angle_weighted_normals)"),
           ("encode_normal", SNAP), ("decode_normal", SNAP)]
ROOTS = ("DeformingModel::pose_on", "follow_surface", "CollisionModel::measure")
SET_UP = ("make_document", "CollisionModel::CollisionModel", "DeformingModel::DeformingModel")


def main(path):
    text = subprocess.run(["perf", "script", "-i", path, "-F", "ip,sym"], capture_output=True, text=True,
                          check=True).stdout
    counts, update, every = collections.Counter(), 0, 0
    for block in text.split("\n\n"):
        frames = [line.strip() for line in block.strip().split("\n") if line.strip()]  # leaf first
        if not frames:
            continue
        every += 1
        if not any(r in f for f in frames for r in ROOTS) or any(s in f for f in frames for s in SET_UP):
            continue
        update += 1
        top = max(i for i, f in enumerate(frames) if any(r in f for r in ROOTS))
        label = "pose_on's own loop (samples follow their vertex or face) and the rest"
        for f in frames[:top + 1]:
            hit = next((b for key, b in BUCKETS if key in f), None)
            if hit:
                label = hit
                break
        counts[label] += 1
    print(f"{update} of {every} samples in the update")
    for label, n in counts.most_common():
        print(f"{100.0 * n / update:5.1f}%  {label}")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit("usage: update_profile.py PERF_DATA")
    main(sys.argv[1])
