"""The whole command line on two synthetic runs: a complete rigid run with a band,
and a membrane run with no peak, no fabric columns, no rose and no dump."""
import csv
import math
import os
import subprocess
import sys
import tempfile
import unittest

from liggghts_membrane import synthetic

SCRIPTS = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", "scripts"))


class Report(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        d = cls.tmp.name
        cls.rigid = os.path.join(d, "shear_rigid.txt")
        synthetic.write_band_run(cls.rigid, synthetic.elastoplastic_curve())
        cls.membrane = os.path.join(d, "shear_membrane.txt")
        rising = synthetic.elastoplastic_curve(ea_end=0.025)     # stops before the peak
        synthetic.write_out(cls.membrane, rising, ["step", "ea", "s1", "s3", "s1/s3", "ev", "el"])
        cls.outdir = os.path.join(d, "report")
        script = os.path.join(SCRIPTS, "biaxial_report.py")
        cls.proc = subprocess.run(
            [sys.executable, script, "--rigid", cls.rigid, "--membrane", cls.membrane,
             "--outdir", cls.outdir], capture_output=True, text=True)
        with open(os.path.join(cls.outdir, "summary.csv")) as f:
            rows = list(csv.reader(f))
        cls.header = rows[0]
        cls.cells = {r[0]: dict(zip(rows[0][1:], r[1:])) for r in rows[1:]}

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def cell(self, quantity, run):
        return self.cells[quantity][run]

    def test_runs(self):
        self.assertEqual(self.proc.returncode, 0, self.proc.stderr)
        self.assertEqual(self.header, ["quantity", "rigid", "membrane"])
        self.assertIn("| quantity | rigid | membrane |", self.proc.stdout)
        with open(os.path.join(self.outdir, "summary.md")) as f:
            self.assertIn("| peak s1/s3 |", f.read())

    def test_figures(self):
        for name in ("stress_strain.png", "fabric.png", "roses.png", "field_rigid.png"):
            self.assertGreater(os.path.getsize(os.path.join(self.outdir, name)), 10000, name)
        self.assertFalse(os.path.exists(os.path.join(self.outdir, "field_membrane.png")))

    def test_rigid_values(self):
        self.assertAlmostEqual(float(self.cell("peak s1/s3", "rigid")), 3.0, delta=0.005)
        self.assertAlmostEqual(float(self.cell("phi from peak [deg]", "rigid")), 30.0, delta=0.3)
        self.assertAlmostEqual(float(self.cell("psi, max dilation [deg]", "rigid")), 10.0, delta=0.5)
        self.assertAlmostEqual(float(self.cell("E, initial [MPa]", "rigid")), 50.0, delta=1.5)
        self.assertAlmostEqual(float(self.cell("nu, initial", "rigid")), 0.3, delta=0.01)
        angle = float(self.cell("band inclination, measured [deg from horizontal]", "rigid"))
        # the band is at 55 deg in the initial configuration; the increment's reference
        # is the frame at the peak (3 %), stretched by (1 + 0.3 ea, 1 - ea)
        expected = math.degrees(math.atan(math.tan(math.radians(55.0)) * 0.97 / 1.009))
        self.assertAlmostEqual(angle, expected, delta=2.0)
        thick = float(self.cell("band thickness, measured [mm]", "rigid"))
        self.assertAlmostEqual(thick / 15.0, 1.0, delta=0.2)
        self.assertAlmostEqual(float(self.cell("45 + phi/2 (Mohr-Coulomb) [deg]", "rigid")), 60.0,
                               delta=0.2)
        d50 = float(self.cell("D50 [mm]", "rigid").split()[0])
        self.assertAlmostEqual(d50, 1.75, delta=0.05)
        self.assertAlmostEqual(float(self.cell("f0 at the end [N]", "rigid")), 33.0, delta=1e-6)

    def test_membrane_not_measurable(self):
        for q in ("peak s1/s3", "phi from peak [deg]", "45 + phi/2 (Mohr-Coulomb) [deg]",
                  "band inclination, measured [deg from horizontal]", "f0 at the end [N]"):
            self.assertTrue(self.cell(q, "membrane").startswith("not measurable ("), q)
        self.assertIn("still rising", self.cell("peak s1/s3", "membrane"))
        self.assertIn("no dump", self.cell("band thickness, measured [mm]", "membrane"))
        self.assertIn("columns missing", self.proc.stdout)

    def test_single_run(self):
        out = os.path.join(self.tmp.name, "only_membrane")
        script = os.path.join(SCRIPTS, "biaxial_report.py")
        proc = subprocess.run([sys.executable, script, "--membrane", self.membrane,
                               "--outdir", out], capture_output=True, text=True)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        with open(os.path.join(out, "summary.csv")) as f:
            self.assertEqual(next(csv.reader(f)), ["quantity", "membrane"])


    def report(self, *args):
        script = os.path.join(SCRIPTS, "biaxial_report.py")
        return subprocess.run([sys.executable, script] + list(args), capture_output=True, text=True)

    def test_any_runs_named_by_their_files(self):
        out = os.path.join(self.tmp.name, "by_file")
        proc = self.report(self.membrane, self.rigid, "--outdir", out)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        with open(os.path.join(out, "summary.csv")) as f:
            rows = {r[0]: r[1:] for r in csv.reader(f)}
        self.assertEqual(rows["quantity"], ["shear_membrane", "shear_rigid"])
        # the same analysis as under --rigid/--membrane, column for column
        self.assertEqual(rows["peak s1/s3"][1], self.cell("peak s1/s3", "rigid"))
        self.assertEqual(rows["E, initial [MPa]"][0], self.cell("E, initial [MPa]", "membrane"))
        self.assertTrue(os.path.exists(os.path.join(out, "field_shear_rigid.png")))

    def test_names_given(self):
        out = os.path.join(self.tmp.name, "named")
        proc = self.report(self.rigid, "--names", "dense", "--outdir", out)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertIn("| quantity | dense |", proc.stdout)

    def test_bad_command_lines(self):
        other = os.path.join(self.tmp.name, "other")
        os.makedirs(other, exist_ok=True)
        twin = os.path.join(other, "shear_rigid.txt")
        synthetic.write_band_run(twin, synthetic.elastoplastic_curve())
        for args, said in (([], "none was given"),
                           ([self.rigid, "--rigid", self.rigid], "not both OUT and --rigid/--membrane"),
                           ([self.rigid, "--names", "a", "b"], "--names gives 2 names for 1 OUT tables"),
                           ([self.rigid, twin], "two runs are named alike (shear_rigid shear_rigid)"),
                           ([os.path.join(other, "nosuch.txt")], "no OUT table")):
            proc = self.report(*args)
            self.assertEqual(proc.returncode, 2, args)
            self.assertIn(said, proc.stderr, args)

    def test_help(self):
        proc = self.report("--help")
        self.assertEqual(proc.returncode, 0)
        self.assertIn("usage: liggghts-membrane-report", proc.stdout)
        self.assertIn("doc/report.md", proc.stdout)


if __name__ == "__main__":
    unittest.main()
