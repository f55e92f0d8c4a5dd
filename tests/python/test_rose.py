"""Rose diagrams: the fitted curves drawn use the parameters of the OUT file."""
import os
import tempfile
import unittest

import numpy as np

from liggghts_membrane import synthetic
from liggghts_membrane import plots, rose
from liggghts_membrane.report import load_run


class HistogramEstimate(unittest.TestCase):
    def test_exact_histogram_gives_back_a(self):
        centres, counts = synthetic.exact_histogram(0.3, 100.0)
        a, theta = rose.histogram_anisotropy(centres, counts)
        self.assertAlmostEqual(a, 0.3, places=10)
        self.assertAlmostEqual(theta, 100.0, places=8)

    def test_density_integrates_to_one(self):
        centres, counts = synthetic.exact_histogram(0.3, 100.0)
        dens = rose.normal_density(counts, centres)
        self.assertAlmostEqual(dens.sum() * 2 * np.pi / len(centres), 1.0, places=12)


class PlottedParametersComeFromTheFile(unittest.TestCase):
    """The histogram has a = 0.3, the OUT file says a = 0.25 near that step: the
    curve drawn must be the file's (0.25), at the nearest line, not a refit."""

    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        prefix = os.path.join(self.tmp.name, "shear_membrane.txt")
        curve = synthetic.elastoplastic_curve()
        cols = synthetic.full_columns(curve)
        cols["a"] = np.full(len(curve["ea"]), 0.25)
        cols["theta_a"] = np.full(len(curve["ea"]), 80.0)
        cols["f0"] = 30.0 + np.arange(len(curve["ea"]))     # distinct on every line
        synthetic.write_out(prefix, cols, synthetic.FULL_HEADER)
        centres, counts = synthetic.exact_histogram(0.3, 100.0)
        fn = 30.0 * (1 + 0.4 * np.cos(2 * np.radians(centres - 90.0)))
        # blocks slightly off the OUT steps: the nearest OUT line must be used
        steps = [int(s) + 120 for s in curve["step"][::20]]
        write = [(s, centres, counts, fn, np.zeros_like(fn)) for s in steps]
        synthetic.write_rose(prefix + ".rose", write)
        self.run_ = load_run("membrane", prefix, 1.75e-3)
        self.curve = curve

    def tearDown(self):
        self.tmp.cleanup()

    def test_parameters(self):
        drawn = plots.roses([self.run_], os.path.join(self.tmp.name, "roses.png"))
        self.assertTrue(os.path.getsize(os.path.join(self.tmp.name, "roses.png")) > 0)
        self.assertEqual(set(s for _, s in drawn), {"start", "peak", "end"})
        for (_, state), d in drawn.items():
            p = d["params"]
            k = int(np.argmin(np.abs(self.curve["step"] - d["block_step"])))
            self.assertEqual(p["step"], int(self.curve["step"][k]))
            self.assertEqual(p["a"], 0.25)
            self.assertEqual(p["theta_a"], 80.0)
            self.assertEqual(p["f0"], 30.0 + k)
            np.testing.assert_allclose(
                d["E_fit"], rose.model_normal_density(d["theta"], 0.25, 80.0))
            self.assertAlmostEqual(d["a_hist"][0], 0.3, places=8)   # the histogram's own

    def test_peak_block_is_nearest_to_the_peak(self):
        drawn = plots.roses([self.run_], os.path.join(self.tmp.name, "roses.png"))
        peak_step = self.curve["step"][self.run_.curves["peak_index"]]
        have = np.array([b[0] for b in self.run_.roses])
        self.assertEqual(drawn[("membrane", "peak")]["block_step"],
                         have[np.argmin(np.abs(have - peak_step))])


if __name__ == "__main__":
    unittest.main()
