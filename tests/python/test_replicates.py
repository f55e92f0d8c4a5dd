"""The replicate report (biaxial_report.py --samples) on synthetic samples with known
per-sample values: means, 95 % intervals, paired differences, significance, band plot."""
import csv
import math
import os
import subprocess
import sys
import tempfile
import unittest

import numpy as np

from liggghts_membrane import synthetic
from liggghts_membrane import plots, replicates, report_command, stats
from liggghts_membrane.curves import NotMeasurable, ratio_from_friction_angle

SCRIPTS = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", "scripts"))

# four samples: a common sample-to-sample shift of phi (and of E), the membrane 1 deg
# lower in phi than the rigid test of the same sample, E not different on average
SHIFT = [0.4, -0.3, 0.1, -0.2]
PHI = {"rigid": [30.0 + d for d in SHIFT],
       "membrane": [29.0 + d + e for d, e in zip(SHIFT, [0.05, -0.05, 0.02, -0.02])]}
E_MPA = {"rigid": [50.0, 52.0, 48.0, 51.0], "membrane": [51.0, 49.0, 50.0, 50.0]}
T_975_3 = 3.1824463053   # Student t, 0.975, 3 degrees of freedom (tables: 3.182)
COLUMNS = ["step", "ea", "s1", "s3", "s1/s3", "ev", "el"]


def expected(values):
    v = np.asarray(values, float)
    return v.mean(), T_975_3 * v.std(ddof=1) / math.sqrt(len(v))


class ReplicateReport(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.folders = []
        for k in range(4):
            folder = os.path.join(cls.tmp.name, f"sample_{100 + k}")
            os.makedirs(folder)
            for case in replicates.CASES:
                curve = synthetic.elastoplastic_curve(E=E_MPA[case][k] * 1e6, phi=PHI[case][k],
                                                      noise=False, ea_end=0.05)
                synthetic.write_out(os.path.join(folder, f"shear_{case}.txt"), curve, COLUMNS)
            cls.folders.append(folder)
        cls.outdir = os.path.join(cls.tmp.name, "report")
        script = os.path.join(SCRIPTS, "biaxial_report.py")
        cls.proc = subprocess.run([sys.executable, script, "--samples", *cls.folders,
                                   "--outdir", cls.outdir], capture_output=True, text=True)
        with open(os.path.join(cls.outdir, "summary.csv")) as f:
            cls.rows = {r["quantity"]: r for r in csv.DictReader(f)}

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_runs_and_writes(self):
        self.assertEqual(self.proc.returncode, 0, self.proc.stderr)
        self.assertIn("n = 4 samples (sample_100, sample_101, sample_102, sample_103)",
                      self.proc.stdout)
        self.assertIn("| quantity | rigid | membrane | rigid − membrane (paired) | significant |",
                      self.proc.stdout)
        self.assertGreater(os.path.getsize(os.path.join(self.outdir, "stress_strain.png")), 10000)
        for folder in self.folders:    # each sample also gets its own report
            self.assertTrue(os.path.exists(os.path.join(folder, "summary.md")))
        with open(os.path.join(self.outdir, "samples.csv")) as f:
            per_sample = {(r[0], r[1]): r[2:] for r in csv.reader(f)}
        peaks = [float(x) for x in per_sample[("peak s1/s3", "rigid")]]
        np.testing.assert_allclose(peaks, [ratio_from_friction_angle(p) for p in PHI["rigid"]],
                                   rtol=1e-9)

    def check(self, quantity, prefix, values, delta):
        mean, half = expected(values)
        row = self.rows[quantity]
        self.assertEqual(row[prefix + "_n"], "4")
        self.assertAlmostEqual(float(row[prefix + "_mean"]), mean, delta=delta)
        self.assertAlmostEqual(float(row[prefix + "_half_width"]), half, delta=delta)

    def test_means_and_intervals(self):
        for case in replicates.CASES:
            self.check("phi from peak [deg]", case, PHI[case], 1e-9)
            self.check("peak s1/s3", case, [ratio_from_friction_angle(p) for p in PHI[case]], 1e-9)
            self.check("E, initial [MPa]", case, E_MPA[case], 1e-6)

    def test_paired_differences_and_significance(self):
        d_phi = np.subtract(PHI["rigid"], PHI["membrane"])
        self.check("phi from peak [deg]", "difference", d_phi, 1e-9)
        self.assertEqual(self.rows["phi from peak [deg]"]["significant"], "yes")
        self.check("E, initial [MPa]", "difference", np.subtract(E_MPA["rigid"], E_MPA["membrane"]),
                   1e-6)
        self.assertEqual(self.rows["E, initial [MPa]"]["significant"], "no")
        # unpaired, the phi intervals of the two cases overlap; paired, 1 deg is clear
        r, m = (float(self.rows["phi from peak [deg]"][k]) for k in ("rigid_half_width",
                                                                     "membrane_half_width"))
        self.assertGreater(r + m, 1.0)

    def test_not_measurable_cells(self):
        row = self.rows["f0 at the end [N]"]
        self.assertEqual((row["rigid_n"], row["significant"]), ("0", ""))
        self.assertIn("| f0 at the end [N] | not measurable in any of the 4 samples "
                      "(the first: no f0 column) |", self.proc.stdout)

    def test_markdown_cells(self):
        mean, half = expected(PHI["rigid"])
        self.assertIn(f"| phi from peak [deg] | {mean:.2f} ± {half:.2f} |", self.proc.stdout)

    def test_band_plot(self):
        samples = [{c: r for c, r in s.items()}
                   for s in (report_command.load_sample(f, 1.75e-3)
                             for f in self.folders)]
        drawn = plots.stress_strain_band(samples, os.path.join(self.outdir, "band.png"))
        grid, mean, half, n = drawn[("rigid", "s1/s3")]
        self.assertAlmostEqual(grid[-1], 5.0)
        k = int(np.argmin(abs(grid - 3.0)))          # the peak, eps_11 = 3 %
        m, h = expected([ratio_from_friction_angle(p) for p in PHI["rigid"]])
        self.assertAlmostEqual(mean[k], m, places=9)
        self.assertAlmostEqual(half[k], h, places=9)
        self.assertTrue(np.all(n == 4))


class FakeRun:
    def __init__(self, peak):
        self.curves = {"peak_ratio": peak}


class MissingAndSingle(unittest.TestCase):
    def row(self, peaks_rigid, peaks_membrane):
        samples = [{"rigid": FakeRun(a), "membrane": FakeRun(b)}
                   for a, b in zip(peaks_rigid, peaks_membrane)]
        label, value, fmt = replicates.QUANTITIES[0]
        self.assertEqual(label, "peak s1/s3")
        return replicates.Row(label, fmt, {c: [value(s[c]) for s in samples]
                                           for c in replicates.CASES})

    def test_a_sample_without_peak(self):
        row = self.row([2.8, 2.9, 2.7], [2.6, NotMeasurable("s1/s3 still rising"), 2.5])
        self.assertEqual((row.per_case["rigid"].n, row.per_case["membrane"].n), (3, 2))
        self.assertEqual(row.difference.n, 2)
        text = replicates.interval_text(row.per_case["membrane"], row.fmt, 3,
                                        row.reason("membrane"))
        self.assertTrue(text.endswith(" (n = 2 of 3)"), text)
        self.assertEqual(replicates.missing_notes([row], ["s1", "s2", "s3"]),
                         ["peak s1/s3, membrane, s2: not measurable (s1/s3 still rising)"])
        self.assertIn("Left out of a mean (n = k of N):\n- peak s1/s3, membrane, s2: ",
                      replicates.to_markdown([row], ["s1", "s2", "s3"]))

    def test_one_sample(self):
        row = self.row([2.8], [2.72])
        header, cells = replicates.build_table([row])
        self.assertEqual(cells[0], ["peak s1/s3", "2.800", "2.720", "+0.080", "– (n = 1)"])
        self.assertIn("n = 1 sample (seed_12345): single values, no confidence interval",
                      replicates.preamble(["seed_12345"]))

    def test_no_minus_zero(self):
        iv = stats.Interval(-0.001, 0.0123, 3)
        self.assertEqual(replicates.interval_text(iv, 2, 3, sign=True), "+0.00 ± 0.01")
        self.assertEqual(replicates.interval_text(stats.Interval(-2.6, math.nan, 1), 1, 1),
                         "-2.6")


if __name__ == "__main__":
    unittest.main()
