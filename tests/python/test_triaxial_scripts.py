"""The triaxial example's scripts: plot_triaxial.py on hand-written tables (a plot from a
table still being written, one clear line, no traceback, for each table it cannot
plot), and run_triaxial.sh's options refused before anything runs."""
import os
import subprocess
import tempfile
import unittest

EXAMPLE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "examples",
                       "triaxial")
SCRIPT = os.path.join(EXAMPLE, "plot_triaxial.py")
HEADER = "# step e1 q[Pa] p[Pa] ev R_out[m] membrane_spheres escaped detections\n"
ROWS = ("60500 0.0015 6000 102000 0.001 0.0244 1575 0 210\n"
        "61000 0.0031 15000 105000 0.002 0.0245 1575 0 220\n")


def run(*args):
    done = subprocess.run(["/usr/bin/python3", SCRIPT, *args], capture_output=True, text=True)
    return done.returncode, done.stdout + done.stderr


class PlotTriaxial(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()
        self.addCleanup(self.dir.cleanup)

    def table(self, name, text):
        path = os.path.join(self.dir.name, name)
        with open(path, "w") as f:
            f.write(text)
        return path

    def test_a_growing_table_is_plotted_beside_it(self):
        path = self.table("t.txt", HEADER + ROWS + "61500 0.0046 2")  # the last line cut
        rc, out = run(path)
        self.assertEqual(rc, 0, out)
        self.assertTrue(os.path.getsize(os.path.join(self.dir.name, "t.png")) > 1000)

    def test_gaps_are_warned(self):
        path = self.table("t.txt", HEADER + ROWS.replace("102000", "0").replace("15000", "nan"))
        rc, out = run(path)
        self.assertEqual(rc, 0, out)
        self.assertIn("warning: 2 rows have values that are not finite (or p = 0)", out)

    def test_what_cannot_be_plotted_is_said_in_one_line(self):
        cases = [
            ((os.path.join(self.dir.name, "none.txt"),), "no file"),
            ((self.table("empty.txt", ""),), "no header line"),
            ((self.table("header.txt", HEADER),), "no complete data row yet"),
            ((self.table("other.txt", "# step e1 q\n1 2 3\n"),), "the header lacks q[Pa] p[Pa] ev"),
            ((self.table("rows.txt", ROWS),), "data before any '#' header line"),
            ((self.table("same.txt", HEADER + ROWS), os.path.join(self.dir.name, "same.txt")),
             "would overwrite the table"),
            ((self.table("t.txt", HEADER + ROWS), "/nonexistent_dir/x.png"), "no folder"),
        ]
        for args, said in cases:
            rc, out = run(*args)
            self.assertEqual(rc, 1, out)
            self.assertIn(said, out)
            self.assertNotIn("Traceback", out)

    def test_a_png_named_table_is_not_overwritten(self):
        path = self.table("same.png", HEADER + ROWS)
        rc, out = run(path)
        self.assertEqual(rc, 0, out)
        self.assertIn("same.png.png", out)
        with open(path) as f:
            self.assertEqual(f.read(), HEADER + ROWS)

    def test_usage(self):
        self.assertEqual(run()[0], 2)
        rc, out = run("--help")
        self.assertEqual(rc, 0)
        self.assertIn("usage: plot_triaxial.py OUT.txt [PNG]", out)


class RunTriaxialOptions(unittest.TestCase):
    def test_bad_options_stop_before_any_run(self):
        # --np 0 would run on every slot (Open MPI), the full-size sample
        for args in (["--np"], ["--np", "0"], ["--np", "-1"], ["--np", "1.5"], ["--quick", "--np"],
                     ["--bogus"]):
            done = subprocess.run(["bash", os.path.join(EXAMPLE, "run_triaxial.sh"), *args],
                                  capture_output=True, text=True, timeout=20)
            self.assertEqual(done.returncode, 2, args)
            self.assertIn("usage:" if args == ["--bogus"] else "--np needs an integer >= 1",
                          done.stderr)
            self.assertNotIn("mpirun", done.stdout + done.stderr)


if __name__ == "__main__":
    unittest.main()
