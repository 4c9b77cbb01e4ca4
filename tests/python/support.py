"""What the Python module's tests share: paths, random poses, and `spt query` run on them."""
import csv
import io
import os
import subprocess
import tempfile

import numpy as np

SOURCE_DIR = os.environ["SPT_SOURCE_DIR"]
CLI = os.environ["SPT_CLI"]
MESHES = os.path.join(SOURCE_DIR, "resources", "meshes")
SCENES = os.path.join(SOURCE_DIR, "resources", "scenes")


def random_poses(n, reach, seed):
    """N x 7 poses within `reach` of A's origin, quaternions of random length (the module and
    the pose file both normalise them)."""
    rng = np.random.default_rng(seed)
    poses = np.empty((n, 7))
    poses[:, :3] = rng.uniform(-reach, reach, (n, 3))
    q = rng.normal(size=(n, 4))
    poses[:, 3:] = q * rng.uniform(0.5, 2.0, (n, 1)) / np.linalg.norm(q, axis=1, keepdims=True)
    return poses


def run_cli(args, check=True):
    """Run `spt ARGS`; its exit code, stdout and stderr."""
    done = subprocess.run([CLI] + args, capture_output=True, text=True, check=False)
    if check and done.returncode != 0:
        raise AssertionError(f"spt {' '.join(args)}: exit {done.returncode}\n{done.stderr}")
    return done.returncode, done.stdout, done.stderr


def query_cli(a, b, rows, *options):
    """`spt query A B --poses FILE OPTIONS` on `rows` (7 or 10 numbers each, written exactly as
    17 significant digits): its CSV rows as dicts."""
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "poses.txt")
        np.savetxt(path, np.asarray(rows), fmt="%.17g")
        args = ["query", a, b, "--poses", path, "--repeat", "1", "--threads", "2", *options]
        _, out, _ = run_cli(args)
    return list(csv.DictReader(io.StringIO(out)))


def cli_number(x):
    """How `spt query` writes a double (%.9g), read back: what to compare a module's answer with."""
    return float("%.9g" % x)


def cli_error(args):
    """The message `spt ARGS` ends with, without its "spt: error: " prefix, and its exit code."""
    code, _, err = run_cli(args, check=False)
    prefix = "spt: error: "
    assert err.startswith(prefix), err
    return err[len(prefix):].rstrip("\n"), code
