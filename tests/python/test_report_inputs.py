"""The report command on bad or short input (issue 32, defect 5): a message naming the
file, not a traceback and not numbers; the linear sliding-window fit against the direct
one; the ParaView collection of a shear that ended before its first frame."""
import contextlib
import io
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

import numpy as np

from liggghts_membrane import synthetic

from liggghts_membrane import curves, readers
from liggghts_membrane.report import load_run

from liggghts_membrane import report_command
from liggghts_membrane import pvd

SCRIPTS = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", "scripts"))
REPORT = os.path.join(SCRIPTS, "biaxial_report.py")


def direct_sliding_slopes(x, y, width):
    """The former quadratic fit: np.polyfit over every window (the reference)."""
    centres, slopes = [], []
    for i in range(len(x)):
        j = np.searchsorted(x, x[i] + width, side="right")
        if x[-1] < x[i] + width - 1e-12:
            break
        if j - i >= 3:
            centres.append(0.5 * (x[i] + x[j - 1]))
            slopes.append(float(np.polyfit(x[i:j], y[i:j], 1)[0]))
    return np.array(centres), np.array(slopes)


class SlidingSlopes(unittest.TestCase):
    def test_same_as_direct_fit(self):
        c = synthetic.elastoplastic_curve(ea_end=0.05, d_ea=0.0005)   # 101 lines, noisy ev
        x, y = c["ea"], c["ev"]
        got_c, got_s = curves.sliding_slopes(x, y, 0.01)
        want_c, want_s = direct_sliding_slopes(x, y, 0.01)
        self.assertEqual(len(got_s), 81)            # 101 lines, windows of 21 lines inside
        np.testing.assert_array_equal(got_c, want_c)
        np.testing.assert_allclose(got_s, want_s, rtol=1e-9, atol=0)

    def test_uneven_spacing_and_repeated_x(self):
        rng = np.random.default_rng(5)
        x = np.sort(np.round(rng.uniform(0.0, 0.03, 300), 4))     # repeats after rounding
        y = 0.3 * x - 40 * x ** 2 + rng.normal(0, 1e-5, len(x))
        got_c, got_s = curves.sliding_slopes(x, y, 0.004)
        want_c, want_s = direct_sliding_slopes(x, y, 0.004)
        np.testing.assert_array_equal(got_c, want_c)
        np.testing.assert_allclose(got_s, want_s, rtol=1e-9, atol=0)

    def test_exact_line(self):
        x = np.linspace(0.0, 0.1, 201)
        _, s = curves.sliding_slopes(x, 2.5 - 0.75 * x, 0.01)
        np.testing.assert_allclose(s, -0.75, rtol=1e-9)

    def test_shorter_than_window(self):
        c, s = curves.sliding_slopes(np.array([0.0, 0.001, 0.002]), np.zeros(3), 0.01)
        self.assertEqual((len(c), len(s)), (0, 0))


class BadTables(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.cols = synthetic.full_columns(synthetic.elastoplastic_curve())

    def tearDown(self):
        self.tmp.cleanup()

    def path(self, name):
        return os.path.join(self.tmp.name, name)

    def write(self, name, cols):
        synthetic.write_out(self.path(name), cols)
        return self.path(name)

    def refused(self, path, *texts):
        with self.assertRaises(readers.InputError) as cm:
            load_run("r", path, 1.75e-3)
        for t in (path,) + texts:
            self.assertIn(t, str(cm.exception))

    def test_header_only(self):
        with open(self.path("h"), "w") as f:
            f.write("# run\n# " + " ".join(self.cols) + "\n")
        self.refused(self.path("h"), "no data line after the header")

    def test_empty(self):
        open(self.path("e"), "w").close()
        self.refused(self.path("e"), "no header line")

    def test_wrong_columns(self):
        p = self.write("w", {"step": self.cols["step"], "x": self.cols["ea"]})
        self.refused(p, "lacks the column(s) ea s1 s3 ev el", "it names: step x")

    def test_nan_column(self):
        cols = dict(self.cols, s1=np.full(len(self.cols["ea"]), np.nan))
        self.refused(self.write("n", cols), "line 3: s1 = nan at step 0 (201 of 201 lines)")

    def test_inf_in_one_line(self):
        ev = self.cols["ev"].copy()
        ev[40] = np.inf
        self.refused(self.write("i", dict(self.cols, ev=ev)), "line 43: ev = inf at step 20000 (1 of 201")

    def test_rows_out_of_order(self):
        perm = np.arange(len(self.cols["ea"]))
        perm[[10, 20]] = [20, 10]
        p = self.write("o", {k: v[perm] for k, v in self.cols.items()})
        self.refused(p, "line 14: step 5500 after step 10000: the steps must increase")

    def test_zero_lateral_stress(self):
        self.refused(self.write("z", dict(self.cols, s3=0 * self.cols["s3"])),
                     "s3 = 0 at step 0: the lateral stress must be positive")

    def test_optional_nan_column_not_measurable(self):
        run = load_run("r", self.write("f", dict(self.cols, f0=np.full(201, np.nan))), 1.75e-3)
        self.assertEqual(str(run.curves["f0_end"]), "not measurable (no f0 column)")

    def test_two_rows(self):
        run = load_run("r", self.write("t", {k: v[:2] for k, v in self.cols.items()}), 1.75e-3)
        for key in ("peak_ratio", "E", "nu", "psi", "E50"):
            self.assertFalse(curves.measured(run.curves[key]), key)
        self.assertIn("has 2 data line(s)", run.notes[0])

    def test_no_peak(self):
        run = load_run("r", self.write("p", {k: v[:40] for k, v in self.cols.items()}), 1.75e-3)
        self.assertIn("still rising at the end", str(run.curves["peak_ratio"]))
        self.assertIn("no peak", str(run.curves["E50"]))

    def test_no_axial_strain(self):
        run = load_run("r", self.write("a", dict(self.cols, ea=0 * self.cols["ea"])), 1.75e-3)
        self.assertEqual(str(run.curves["peak_ratio"]),
                         "not measurable (eps_11 does not change: no axial strain)")


class CutFiles(unittest.TestCase):
    """A .rose and a .dump cut mid-write: the complete blocks and frames, and a note."""

    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.prefix = os.path.join(cls.tmp.name, "run.txt")
        synthetic.write_band_run(cls.prefix, synthetic.elastoplastic_curve(), n=300, every=20)

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def cut_copy(self, ext, keep):
        """A copy of the run whose ext file keeps `keep` of its bytes."""
        dst = os.path.join(self.tmp.name, f"cut{ext.replace('.', '_')}{keep}.txt")
        for e in ("", ".rose", ".dump"):
            shutil.copy(self.prefix + e, dst + e)
        with open(dst + ext, "rb") as f:
            data = f.read()
        with open(dst + ext, "wb") as f:
            f.write(data[:keep] if keep > 0 else data[:len(data) + keep])
        return dst

    def test_dump_cut_mid_line(self):
        full = readers.dump_steps(self.prefix + ".dump")
        self.assertEqual(len(full), 11)
        p = self.cut_copy(".dump", -7)                  # the last line cut
        notes = []
        index = readers.dump_steps(p + ".dump", notes)
        self.assertEqual(index, full[:10])
        self.assertIn("frame(s) of step 100000 cut short", notes[0])
        run = load_run("r", p, 1.75e-3)
        self.assertTrue(any("10 complete frame(s) used" in n for n in run.notes))

    def test_dump_cut_in_header(self):
        full = readers.dump_steps(self.prefix + ".dump")
        p = self.cut_copy(".dump", full[3][1] + 30)     # inside the 4th frame's header
        notes = []
        self.assertEqual(readers.dump_steps(p + ".dump", notes), full[:3])
        self.assertEqual(len(notes), 1)

    def test_rose_cut(self):
        blocks = readers.read_rose(self.prefix + ".rose")
        self.assertEqual(len(blocks), 11)
        for keep in (-3, -30, -700):
            notes = []
            p = self.cut_copy(".rose", keep)
            got = readers.read_rose(p + ".rose", notes)
            self.assertLess(len(got), 11)
            self.assertEqual([s for s, _ in got], [s for s, _ in blocks[:len(got)]])
            self.assertIn("cut short or unreadable", notes[0])


class Command(unittest.TestCase):
    """The command's exit status and message (no traceback)."""

    def run_report(self, *args, cwd=None):
        r = subprocess.run([sys.executable, REPORT, *args], capture_output=True, text=True,
                           cwd=cwd, timeout=120)
        return r.returncode, r.stdout + r.stderr

    def test_messages(self):
        with tempfile.TemporaryDirectory() as d:
            cols = synthetic.full_columns(synthetic.elastoplastic_curve())
            synthetic.write_out(os.path.join(d, "a.txt"), cols)
            with open(os.path.join(d, "h.txt"), "w") as f:
                f.write("# " + " ".join(cols) + "\n")
            os.makedirs(os.path.join(d, "s"))
            for args, text in ((["h.txt"], "h.txt: no data line"),
                               (["nothing.txt"], "no OUT table nothing.txt"),
                               (["a.txt", "./a.txt", "--names", "x", "y"], "given twice"),
                               (["--samples", "s", "s/"], "--samples folder s/ is given twice"),
                               (["a.txt", "--d50", "-1"], "--d50 = -1.0: needs a positive")):
                rc, out = self.run_report(*args, cwd=d)
                self.assertEqual(rc, 2, args)
                self.assertIn(text, out)
                self.assertNotIn("Traceback", out)

    def test_parse_args_same_run_twice(self):
        with tempfile.TemporaryDirectory() as d:
            p = os.path.join(d, "a.txt")
            open(p, "w").close()
            err = io.StringIO()
            with self.assertRaises(SystemExit), contextlib.redirect_stderr(err):
                report_command.parse_args(["--rigid", p, "--membrane", p])
            self.assertIn("is given twice", err.getvalue())


class ParaviewCollection(unittest.TestCase):
    def test_no_frame_is_a_note(self):
        """A shear that ended before the first frame: a note, exit 0, no run.pvd."""
        with tempfile.TemporaryDirectory() as d:
            err = io.StringIO()
            with contextlib.redirect_stderr(err):
                rc = pvd.main(["paraview_collection.py", d])
            self.assertEqual(rc, 0)
            self.assertIn("no particles_<step>.vtp", err.getvalue())
            self.assertFalse(os.path.exists(os.path.join(d, "run.pvd")))

    def test_missing_folder_is_an_error(self):
        err = io.StringIO()
        with tempfile.TemporaryDirectory() as d, contextlib.redirect_stderr(err):
            rc = pvd.main(["paraview_collection.py", os.path.join(d, "none")])
        self.assertEqual(rc, 1)
        self.assertIn("no folder", err.getvalue())


if __name__ == "__main__":
    unittest.main()
