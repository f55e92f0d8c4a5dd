"""liggghts_membrane.params: the variables of hand-written input scripts."""
import os
import tempfile
import textwrap
import unittest

from liggghts_membrane import params

MAIN = """\
# a comment: variable kn index 1
variable out     index shear.txt          # trailing comment
variable kn      index 8.45e7
variable kn      index 1e9                # an index variable keeps its first value
variable rate    equal 0.01
variable rate    equal 0.02               # an equal variable takes the last one
variable label   string "a # b"
variable long    index &
                 2.5
include          setup.inc
include          ${extra}
include          missing.inc
variable dt      index 5e-5               # after the include: setup.inc's 1e-4 wins
"""

SETUP = """\
variable dt      index 1e-4
variable rho     index 2e8
variable kn      index 3                  # the main script's kn came first
include          main.in                  # a cycle is not followed again
"""


class Variables(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        for name, text in (("main.in", MAIN), ("setup.inc", SETUP)):
            with open(os.path.join(self.tmp.name, name), "w") as f:
                f.write(textwrap.dedent(text))
        self.path = os.path.join(self.tmp.name, "main.in")

    def tearDown(self):
        self.tmp.cleanup()

    def test_values(self):
        v = params.read_variables(self.path)
        self.assertEqual(v["out"], "shear.txt")
        self.assertEqual(v["kn"], "8.45e7")
        self.assertEqual(v["rate"], "0.02")
        self.assertEqual(v["label"], "a # b")
        self.assertEqual(v["long"], "2.5")
        self.assertEqual(v["dt"], "1e-4")
        self.assertEqual(v["rho"], "2e8")
        self.assertEqual(sorted(v), ["dt", "kn", "label", "long", "out", "rate", "rho"])

    def test_without_includes(self):
        v = params.read_variables(self.path, follow_includes=False)
        self.assertEqual(v["dt"], "5e-5")
        self.assertNotIn("rho", v)

    def test_numbers(self):
        self.assertEqual(params.numbers(self.path, "kn", "dt", "rho"), [8.45e7, 1e-4, 2e8])
        v = params.read_variables(self.path)
        with self.assertRaises(KeyError):
            params.number(v, "gvisc")
        with self.assertRaises(ValueError):
            params.number(v, "out")

    def test_the_examples_define_what_the_benchmarks_read(self):
        root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
        for script in ("in.shear_rigid", "in.shear_membrane", "in.prepare"):
            v = params.read_variables(os.path.join(root, "examples", "biaxial", script))
            for name in ("kn", "rho", "dt", "sigma", "alpha", "gvisc", "damping", "adamp"):
                self.assertGreaterEqual(params.number(v, name), 0.0, f"{script}: {name}")
        shear = params.read_variables(os.path.join(root, "examples", "biaxial", "in.shear_rigid"))
        for name in ("rate", "vmax"):
            self.assertGreater(params.number(shear, name), 0.0)


if __name__ == "__main__":
    unittest.main()
