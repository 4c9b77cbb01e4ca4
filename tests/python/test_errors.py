"""Bad input gives a Python exception naming the argument (and the row), bad files spt.Error with
the message `spt query` prints; nothing crashes."""
import os
import tempfile
import unittest

import numpy as np

import spt
from support import MESHES, SCENES, cli_error, run_cli

TORUS = os.path.join(MESHES, "torus.obj")
CRATE = os.path.join(SCENES, "crate.spt")
IDENTITY = [0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0]


class BadArrays(unittest.TestCase):
    """Poses and directions of the wrong shape, dtype or values."""

    @classmethod
    def setUpClass(cls):
        cls.torus = spt.load(TORUS)

    def assert_refused(self, exception, poses, *words):
        for call in (lambda: spt.collide(self.torus, self.torus, poses),
                     lambda: spt.distance(self.torus, self.torus, poses),
                     lambda: spt.backtrack(self.torus, self.torus, poses, np.zeros((2, 3)))):
            with self.assertRaises(exception) as caught:
                call()
            for word in ("poses",) + words:
                self.assertIn(word, str(caught.exception))

    def test_wrong_shapes_are_value_errors_naming_the_shape(self):
        for shape in ((2, 6), (2, 8), (7,), (2, 4, 3), (2, 3, 4), (2, 2, 7), (2, 4, 4, 1), ()):
            with self.subTest(shape=shape):
                self.assert_refused(ValueError, np.ones(shape), "shape " + str(shape))

    def test_what_is_not_a_number_is_a_type_error_naming_the_dtype(self):
        for poses in (np.ones((2, 7), dtype=bool), np.ones((2, 7), dtype=complex),
                      np.full((2, 7), "1"), np.full((2, 7), None, dtype=object)):
            with self.subTest(dtype=poses.dtype):
                self.assert_refused(TypeError, poses, "dtype")
        ragged = [IDENTITY, [1, 2]]
        self.assert_refused(TypeError, ragged, "expected a NumPy array of numbers")
        self.assert_refused(TypeError, "poses.txt", "dtype")

    def test_a_nan_or_inf_names_the_row_and_the_column(self):
        for value in (np.nan, np.inf, -np.inf):
            for column, name in enumerate(("tx", "ty", "tz", "qw", "qx", "qy", "qz")):
                poses = np.array([IDENTITY] * 3)
                poses[2, column] = value
                with self.subTest(value=value, column=name):
                    self.assert_refused(ValueError, poses, "poses row 2: " + name + " is ")

    def test_a_nan_in_a_transform_names_the_row_and_the_entry(self):
        m = np.tile(np.eye(4), (3, 1, 1))
        m[1, 2, 3] = np.nan
        self.assert_refused(ValueError, m, "poses row 1: [2, 3] is nan")

    def test_a_zero_quaternion_and_a_far_translation_are_refused_as_in_a_pose_file(self):
        poses = np.array([IDENTITY, [0, 0, 0, 0, 0, 0, 0]], dtype=float)
        self.assert_refused(ValueError, poses, "poses row 1: the quaternion (qw qx qy qz) is zero")
        poses = np.array([IDENTITY, [0, 2e16, 0, 1, 0, 0, 0]], dtype=float)
        self.assert_refused(ValueError, poses, "poses row 1: translation y = 2e+16 is beyond 1e16")

    def test_a_transform_that_is_not_rigid_is_refused(self):
        scaled, sheared, mirrored, projective = (np.tile(np.eye(4), (2, 1, 1)) for _ in range(4))
        scaled[1, :3, :3] *= 1.001
        sheared[1, 0, 1] = 0.1
        mirrored[1, 2, 2] = -1
        projective[1, 3, 0] = 0.5
        for m in (scaled, sheared, mirrored, projective):
            self.assert_refused(ValueError, m, "poses row 1: not a rigid transform")
        float32_rotation = np.tile(np.eye(4), (1, 1, 1))
        c, s = np.cos(0.3), np.sin(0.3)
        float32_rotation[0, :2, :2] = np.array([[c, -s], [s, c]], dtype=np.float32)
        spt.collide(self.torus, self.torus, float32_rotation)  # rounding is not scale

    def test_directions_are_checked_like_poses(self):
        poses = np.array([IDENTITY] * 2)
        nan = np.array([[0, 0, 1], [np.nan, 0, 0]])
        for directions, words in ((np.zeros((3, 3)), "with a row for each of the 2 poses"),
                                  (np.zeros((2, 4)), "shape (2, 4)"),
                                  (nan, "directions row 1: dx is nan")):
            with self.assertRaises(ValueError) as caught:
                spt.backtrack(self.torus, self.torus, poses, directions)
            self.assertIn("directions", str(caught.exception))
            self.assertIn(words, str(caught.exception))
        with self.assertRaises(TypeError):
            spt.backtrack(self.torus, self.torus, poses, np.full((2, 3), "x"))

    def test_bad_options_are_value_errors_naming_the_option(self):
        t, poses, up = self.torus, np.array([IDENTITY]), np.ones((1, 3))
        calls = {"level": lambda: spt.collide(t, t, poses, "triangles"),
                 "cull_angle": lambda: spt.collide(t, t, poses, cull_angle=120),
                 "threads": lambda: spt.collide(t, t, poses, threads=-1),
                 "rule": lambda: spt.backtrack(t, t, poses, up, rule="fast"),
                 "max_distance": lambda: spt.backtrack(t, t, poses, up, max_distance=0)}
        for name, call in calls.items():
            with self.subTest(option=name):
                with self.assertRaises(ValueError) as caught:
                    call()
                self.assertTrue(str(caught.exception).startswith(name + ":"), str(caught.exception))

    def test_what_the_library_refuses_is_spt_error_with_its_message(self):
        poses = np.array([IDENTITY])
        for options in ({"max_distance": -1.0}, {"relative_error": 1.5}, {"absolute_error": -1.0}):
            with self.subTest(**options):
                with self.assertRaises(spt.Error) as caught:
                    spt.distance(self.torus, self.torus, poses, **options)
                self.assertEqual(str(caught.exception),
                                 "distance: max_distance must be > 0, relative_error in [0, 1) "
                                 "and absolute_error finite and >= 0")
                self.assertEqual(caught.exception.kind, "usage")
                self.assertIsInstance(caught.exception, RuntimeError)


class BadFiles(unittest.TestCase):
    """spt.load raises spt.Error with `spt query`'s message (less its "spt: error: ") and kind."""

    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.poses = os.path.join(cls.tmp.name, "poses.txt")
        with open(cls.poses, "w", encoding="ascii") as f:
            f.write("0 0 0 1 0 0 0\n")

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def file(self, name, data):
        path = os.path.join(self.tmp.name, name)
        with open(path, "wb") as f:
            f.write(data)
        return path

    def assert_cli_message(self, load, cli_args, kind="bad input", code=2):
        with self.assertRaises(spt.Error) as caught:
            load()
        message, exit_code = cli_error(["query"] + cli_args + ["--poses", self.poses])
        self.assertEqual(str(caught.exception), message)
        self.assertEqual((caught.exception.kind, exit_code), (kind, code))

    def test_bad_files_give_the_cli_message_naming_the_file(self):
        with open(CRATE, "rb") as f:
            crate = f.read()
        for path in (os.path.join(self.tmp.name, "missing.spt"),
                     self.file("short.spt", crate[:300]),
                     self.file("flipped.spt", crate[:-10] + bytes(10)),
                     self.file("junk.obj", b"v 1 2\nf 1 2 3 x\n"),
                     self.file("tiny.stl", b"solid")):
            with self.subTest(file=os.path.basename(path)):
                self.assert_cli_message(lambda: spt.load(path), [path, TORUS])
                with self.assertRaises(spt.Error) as caught:
                    spt.load(path)
                self.assertIn(path, str(caught.exception))

    def test_a_missing_tree_gives_the_cli_message(self):
        self.assert_cli_message(lambda: spt.load(CRATE, tree="nope"),
                                [CRATE, CRATE, "--tree", "nope"])
        with self.assertRaises(spt.Error) as caught:
            spt.load(CRATE, tree=3)
        self.assertEqual(str(caught.exception), CRATE + ": no tree at index 3 (the file holds 1)")

    def test_a_mesh_that_is_not_the_files_mesh_is_refused(self):
        self.assert_cli_message(lambda: spt.load(CRATE, mesh=TORUS),
                                [CRATE, CRATE, "--mesh-a", TORUS])

    def test_a_mesh_argument_for_a_mesh_is_refused(self):
        with self.assertRaises(spt.Error) as caught:
            spt.load(TORUS, mesh=TORUS)
        self.assertEqual(caught.exception.kind, "usage")

    def test_the_exact_level_without_triangles_is_a_usage_error(self):
        crate = spt.load(CRATE)
        with self.assertRaises(spt.Error) as caught:
            spt.collide(crate, crate, np.array([IDENTITY]), "exact")
        self.assertEqual(caught.exception.kind, "usage")
        self.assertIn("level 'exact' needs the triangles of both objects", str(caught.exception))
        self.assertEqual(run_cli(["query", CRATE, CRATE, "--poses", self.poses, "--level", "exact"],
                                 check=False)[0], 1)

    def test_arguments_of_the_wrong_type_are_type_errors(self):
        with self.assertRaises(TypeError):
            spt.load(42)
        with self.assertRaises(TypeError):
            spt.load(CRATE, tree=1.5)
        with self.assertRaises(TypeError):
            spt.collide("a", "b", np.array([IDENTITY]))


if __name__ == "__main__":
    unittest.main()
