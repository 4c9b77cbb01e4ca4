"""examples/check_path.py runs and its report holds: so that the example cannot rot."""
import os
import re
import subprocess
import sys
import unittest

import numpy as np

import spt
from support import SOURCE_DIR

EXAMPLES = os.path.join(SOURCE_DIR, "examples")
sys.path.insert(0, EXAMPLES)
import check_path  # noqa: E402  (the example itself, for its path and its bin)


class CheckPathExample(unittest.TestCase):
    """The script as a user runs it, then its first contact checked pose by pose."""

    def test_the_report_names_the_first_contact_of_the_path(self):
        script = os.path.join(EXAMPLES, "check_path.py")
        done = subprocess.run([sys.executable, script, "--steps", "100"],
                              capture_output=True, text=True, check=False)
        self.assertEqual(done.returncode, 0, done.stderr)
        report = done.stdout
        self.assertRegex(report, r"path: 200 poses of arm.obj against 5 parts of the bin, checked")
        self.assertRegex(report, r"smallest clearance: -[0-9.]+ at pose \d+ \(overlap\)")
        found = re.search(r"first contact: pose (\d+) with the (.+); free again ([0-9.]+) back",
                          report)
        self.assertIsNotNone(found, report)
        pose, part, back = int(found[1]), found[2], float(found[3])
        self.assertGreater(back, 0)

        world, _ = check_path.plan(100)
        arm = spt.load(os.path.join(check_path.SCENES, "arm.obj"))
        hit_at = {}
        for name, mesh, position, quaternion in check_path.BIN:
            in_part = np.linalg.inv(check_path.transform(position, quaternion)) @ world
            hit = spt.collide(spt.load(os.path.join(check_path.SCENES, mesh)), arm, in_part)
            hit_at[name] = int(hit.argmax()) if hit.any() else len(world)
        self.assertEqual(min(hit_at.values()), pose)
        self.assertEqual(hit_at[part], pose)


if __name__ == "__main__":
    unittest.main()
