"""spt.collide, spt.distance and spt.backtrack give `spt query`'s columns pose by pose."""
import os
import tempfile
import unittest

import numpy as np

import spt
from support import MESHES, SCENES, cli_number, query_cli, random_poses, run_cli

TORUS = os.path.join(MESHES, "torus.obj")
FIGURE = os.path.join(MESHES, "figure.obj")


def matrices(poses):
    """The N x 4 x 4 transforms of N x 7 poses (quaternions normalised first)."""
    q = poses[:, 3:] / np.linalg.norm(poses[:, 3:], axis=1, keepdims=True)
    w, x, y, z = q.T
    m = np.zeros((len(poses), 4, 4))
    m[:, 0, :3] = np.stack([1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)], 1)
    m[:, 1, :3] = np.stack([2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)], 1)
    m[:, 2, :3] = np.stack([2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)], 1)
    m[:, :3, 3] = poses[:, :3]
    m[:, 3, 3] = 1
    return m


def column(rows, name):
    """A column of `spt query`'s CSV as numbers."""
    return [float(r[name]) for r in rows]


def as_written(values):
    """The module's answers as `spt query` writes them."""
    return [cli_number(v) for v in values]


class AnswersOfTheCli(unittest.TestCase):
    """Every answer against the CSV of the built `spt` on the same poses."""

    @classmethod
    def setUpClass(cls):
        cls.a = spt.load(TORUS)
        cls.b = spt.load(FIGURE)
        reach = 0.6 * (cls.a.diagonal + cls.b.diagonal) / 2
        cls.poses = random_poses(400, reach, seed=41)

    def assert_collide_column(self, got, rows):
        self.assertEqual(got.dtype, np.bool_)
        self.assertEqual(got.tolist(), [r["collide"] == "1" for r in rows])

    def test_collide_is_the_collide_column_at_every_level(self):
        for level in ("bounds", "spheres", "exact"):
            with self.subTest(level=level):
                got = spt.collide(self.a, self.b, self.poses, level)
                rows = query_cli(TORUS, FIGURE, self.poses, "--level", level)
                self.assert_collide_column(got, rows)
                self.assertTrue(0 < got.sum() < len(got), "the poses should both hit and miss")

    def test_collide_options_are_the_cli_flags(self):
        got = spt.collide(self.a, self.b, self.poses, surfaces=True, culling=True, cull_angle=45)
        rows = query_cli(TORUS, FIGURE, self.poses, "--surfaces", "--culling", "--cull-angle", "45")
        self.assert_collide_column(got, rows)

    def test_distance_is_the_distance_column_with_its_points(self):
        for level in ("spheres", "bounds", "exact"):
            with self.subTest(level=level):
                dist, pa, pb = spt.distance(self.a, self.b, self.poses, level, return_points=True)
                rows = query_cli(TORUS, FIGURE, self.poses, "--mode", "distance", "--level", level)
                self.assertEqual(dist.dtype, np.float64)
                self.assertEqual(as_written(dist), column(rows, "distance"))
                self.assertEqual([r["collide"] == "1" for r in rows], (dist <= 0).tolist())
                for k, axis in enumerate("xyz"):
                    self.assertEqual(as_written(pa[:, k]), column(rows, "a" + axis))
                    self.assertEqual(as_written(pb[:, k]), column(rows, "b" + axis))
                alone = spt.distance(self.a, self.b, self.poses, level)
                self.assertTrue(np.array_equal(alone, dist))

    def test_beyond_max_distance_is_inf_as_the_cli_writes_it(self):
        limit = 0.01 * self.a.diagonal
        dist, pa, _ = spt.distance(self.a, self.b, self.poses, max_distance=limit,
                                   return_points=True)
        rows = query_cli(TORUS, FIGURE, self.poses, "--mode", "distance",
                         "--max-distance", repr(limit))
        self.assertEqual(as_written(dist), column(rows, "distance"))
        beyond = np.isinf(dist)
        self.assertTrue(beyond.any() and not beyond.all())
        self.assertTrue(np.isnan(pa[beyond]).all())
        self.assertEqual(beyond.tolist(), [r["ax"] == "" for r in rows])

    def test_without_depth_overlaps_are_zero_as_the_cli_writes_them(self):
        dist, pa, _ = spt.distance(self.a, self.b, self.poses, depth=False, return_points=True)
        rows = query_cli(TORUS, FIGURE, self.poses, "--mode", "distance", "--no-depth")
        self.assertEqual(as_written(dist), column(rows, "distance"))
        hit = np.array([r["collide"] == "1" for r in rows])
        self.assertTrue(hit.any() and not hit.all())
        self.assertTrue((dist[hit] == 0).all())
        self.assertTrue(np.isnan(pa[hit]).all())
        self.assertFalse(np.isnan(pa[~hit]).any())

    def test_error_allowances_stay_within_what_they_allow(self):
        full = spt.distance(self.a, self.b, self.poses)
        allowance = 0.02 * self.a.diagonal
        rough = spt.distance(self.a, self.b, self.poses, absolute_error=allowance,
                             relative_error=0.1)
        apart = full > 0
        self.assertTrue(apart.any())
        self.assertTrue((rough[apart] >= full[apart] - 1e-9).all())
        self.assertTrue((rough[apart] * 0.9 - allowance <= full[apart] + 1e-9).all())

    def test_backtrack_is_the_backtrack_column(self):
        rng = np.random.default_rng(7)
        directions = rng.normal(size=(len(self.poses), 3))
        directions[::10] = 0  # no motion: 0, as the CLI says
        rows10 = np.hstack([self.poses, directions])
        for level, rule in (("spheres", "exact"), ("bounds", "exact"), ("spheres", "paper")):
            with self.subTest(level=level, rule=rule):
                got = spt.backtrack(self.a, self.b, self.poses, directions, level, rule=rule)
                rows = query_cli(TORUS, FIGURE, rows10, "--level", level, "--backtrack", rule)
                self.assertEqual(as_written(got), column(rows, "backtrack"))
                self.assertTrue((got > 0).any())

    def test_backtrack_at_the_exact_level_on_a_few_poses(self):
        poses, directions = self.poses[:40], np.tile([1.0, 0.5, 0.0], (40, 1))
        got = spt.backtrack(self.a, self.b, poses, directions, "exact")
        rows = query_cli(TORUS, FIGURE, np.hstack([poses, directions]), "--level", "exact")
        self.assertEqual(as_written(got), column(rows, "backtrack"))

    def test_a_limit_on_the_backtrack_gives_inf_past_it_and_the_same_below(self):
        directions = np.tile([0.0, 0.0, 1.0], (len(self.poses), 1))
        free = spt.backtrack(self.a, self.b, self.poses, directions)
        limit = float(np.median(free[free > 0]))
        limited = spt.backtrack(self.a, self.b, self.poses, directions, max_distance=limit)
        self.assertTrue(np.array_equal(limited[free <= limit], free[free <= limit]))
        self.assertTrue(np.isinf(limited[free > limit]).all())

    def test_transforms_give_the_answers_of_their_quaternions(self):
        m = matrices(self.poses)
        self.assertEqual(spt.collide(self.a, self.b, m).tolist(),
                         spt.collide(self.a, self.b, self.poses).tolist())
        np.testing.assert_allclose(spt.distance(self.a, self.b, m),
                                   spt.distance(self.a, self.b, self.poses), rtol=1e-6, atol=1e-9)

    def test_any_thread_count_gives_the_same_answers(self):
        one = spt.distance(self.a, self.b, self.poses, threads=1)
        self.assertTrue(np.array_equal(spt.distance(self.a, self.b, self.poses, threads=3), one))
        self.assertEqual(spt.collide(self.a, self.b, self.poses, threads=1).tolist(),
                         spt.collide(self.a, self.b, self.poses, threads=3).tolist())

    def test_float32_integers_and_lists_are_read_as_their_values(self):
        p32 = self.poses.astype(np.float32)
        self.assertEqual(spt.collide(self.a, self.b, p32).tolist(),
                         spt.collide(self.a, self.b, p32.astype(np.float64)).tolist())
        ints = [[0, 0, 0, 1, 0, 0, 0], [5, 0, 0, 2, 0, 0, 0]]
        self.assertEqual(spt.collide(self.a, self.a, ints).tolist(), [True, False])
        uint8 = np.array(ints, dtype=np.uint8)
        self.assertEqual(spt.collide(self.a, self.a, uint8).tolist(), [True, False])

    def test_a_non_contiguous_view_reads_its_own_rows(self):
        view = self.poses[::3]
        self.assertFalse(view.flags.c_contiguous)
        self.assertEqual(spt.collide(self.a, self.b, view).tolist(),
                         spt.collide(self.a, self.b, view.copy()).tolist())

    def test_no_poses_give_empty_arrays(self):
        empty = np.zeros((0, 7))
        self.assertEqual(spt.collide(self.a, self.b, empty).shape, (0,))
        self.assertEqual(spt.distance(self.a, self.b, np.zeros((0, 4, 4))).shape, (0,))
        _, pa, pb = spt.distance(self.a, self.b, empty, return_points=True)
        self.assertEqual((pa.shape, pb.shape), ((0, 3), (0, 3)))
        self.assertEqual(spt.backtrack(self.a, self.b, empty, np.zeros((0, 3))).shape, (0,))


class TreesAndFiles(unittest.TestCase):
    """spt.load reads what `spt query` reads: .spt files, their trees, their meshes."""

    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.spt_file = os.path.join(cls.tmp.name, "figure.spt")
        run_cli(["convert", FIGURE, "-o", cls.spt_file])
        run_cli(["convert", FIGURE, "-o", cls.spt_file, "--append", "--tree-name", "walk",
                 "--leaf-size", "4"])
        cls.poses = random_poses(200, 0.5, seed=3)

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_a_tree_by_name_or_index_is_the_cli_tree(self):
        by_name = spt.load(self.spt_file, tree="walk")
        by_index = spt.load(self.spt_file, tree=1)
        first = spt.load(self.spt_file)
        self.assertEqual((by_name.tree, by_index.tree, first.tree), ("walk", "walk", "default"))
        # --tree names the tree of both files
        rows = query_cli(self.spt_file, self.spt_file, self.poses, "--tree", "walk",
                         "--mode", "distance")
        for model in (by_name, by_index):
            got = spt.distance(model, model, self.poses)
            self.assertEqual(as_written(got), column(rows, "distance"))

    def test_a_spt_file_with_its_mesh_answers_at_the_exact_level(self):
        plain = spt.load(self.spt_file)
        self.assertFalse(plain.has_triangles)
        with_mesh = spt.load(self.spt_file, mesh=FIGURE)
        self.assertTrue(with_mesh.has_triangles)
        got = spt.collide(with_mesh, with_mesh, self.poses, "exact")
        rows = query_cli(self.spt_file, self.spt_file, self.poses, "--level", "exact",
                         "--mesh-a", FIGURE, "--mesh-b", FIGURE)
        self.assertEqual(got.tolist(), [r["collide"] == "1" for r in rows])

    def test_a_bundled_spt_file_loads(self):
        crate = spt.load(os.path.join(SCENES, "crate.spt"))
        self.assertIn("crate.spt", repr(crate))
        self.assertGreater(crate.spheres, 0)


if __name__ == "__main__":
    unittest.main()
