"""liggghts_membrane.stats: the Student-t factor (scipy.stats) against tables, and the coverage of the 95 %
intervals (single quantity and paired difference) by simulation."""
import math
import unittest

import numpy as np

from liggghts_membrane import stats


class TCritical(unittest.TestCase):
    def test_table_values(self):
        # two-sided 95 % factors t_{0.975, n-1}, standard t tables (e.g. NIST/SEMATECH
        # e-Handbook, 1.3.6.7.2): n values have n - 1 degrees of freedom
        for df, t in ((1, 12.706), (2, 4.303), (4, 2.776), (9, 2.262), (29, 2.045),
                      (100, 1.984), (10 ** 6, 1.960)):
            with self.subTest(df=df):
                self.assertAlmostEqual(stats.t_critical(df + 1), t, delta=5e-4)
        self.assertAlmostEqual(stats.t_critical(math.inf), 1.9599640, delta=1e-6)

    def test_more_digits_and_other_levels(self):
        self.assertAlmostEqual(stats.t_critical(2), 12.7062047, delta=1e-6)
        self.assertAlmostEqual(stats.t_critical(5), 2.7764451, delta=1e-6)
        self.assertAlmostEqual(stats.t_critical(4, 0.99), 5.8409093, delta=1e-6)
        self.assertAlmostEqual(stats.t_critical(2, 0.8), 3.0776835, delta=1e-6)  # tan(0.4 pi)

    def test_bad_arguments(self):
        for n, c in ((1, 0.95), (0, 0.95), (5, 1.0), (5, 0.0)):
            with self.assertRaises(ValueError):
                stats.t_critical(n, c)


class Intervals(unittest.TestCase):
    def test_hand_worked(self):
        iv = stats.mean_interval([1, 2, 3, 4, 5])        # s = sqrt(2.5), n = 5, t = 2.7764
        self.assertEqual(iv.n, 5)
        self.assertAlmostEqual(iv.mean, 3.0)
        self.assertAlmostEqual(iv.half_width, 2.7764451 * math.sqrt(2.5) / math.sqrt(5), places=6)
        self.assertTrue(iv.significant)

    def test_one_value_has_no_interval(self):
        iv = stats.mean_interval([2.5, math.nan])
        self.assertEqual((iv.n, iv.mean), (1, 2.5))
        self.assertFalse(iv.has_interval)
        self.assertIsNone(iv.significant)
        self.assertEqual(stats.mean_interval([]).n, 0)

    def test_paired_skips_missing_pairs(self):
        iv = stats.paired_difference([3.0, 5.0, math.nan, 4.0], [1.0, 2.0, 7.0, math.nan])
        self.assertEqual(iv.n, 2)
        self.assertAlmostEqual(iv.mean, 2.5)
        self.assertAlmostEqual(iv.half_width, 12.7062047 * 0.5, places=5)   # s = 0.5 sqrt 2
        self.assertFalse(iv.significant)

    def test_band(self):
        xs = [np.linspace(0, 0.02, 41), np.linspace(0, 0.021, 30)]
        ys = [1 + 10 * xs[0], 1.2 + 10 * xs[1]]
        grid = stats.common_grid(xs)
        self.assertEqual((grid[0], grid[-1], len(grid)), (0.0, 0.02, 41))
        mean, half, n = stats.mean_band(xs, ys, grid)
        np.testing.assert_allclose(mean, 1.1 + 10 * grid)
        np.testing.assert_allclose(half, 12.7062047 * 0.1 * math.sqrt(2) / math.sqrt(2), rtol=1e-6)
        self.assertTrue(np.all(n == 2))


class Coverage(unittest.TestCase):
    """M = 4000 synthetic sample sets for each n; the 95 % interval must cover the true
    mean in 95 % of them within 3 binomial standard deviations, 3 sqrt(0.95 x 0.05 / M)
    = 1.03 %. The seed is fixed, so the test is deterministic."""
    M = 4000
    TOLERANCE = 3.0 * math.sqrt(0.95 * 0.05 / M)

    def check(self, covered, label):
        rate = np.mean(covered)
        self.assertLess(abs(rate - 0.95), self.TOLERANCE, f"{label}: coverage {rate:.4f}")

    def test_single_quantity(self):
        rng = np.random.RandomState(20261201)
        for n in (3, 5, 10):
            with self.subTest(n=n):
                sets = rng.normal(2.7, 0.15, (self.M, n))
                self.check([stats.mean_interval(s).covers(2.7) for s in sets], f"n = {n}")

    def test_paired_difference(self):
        # each sample shifts both cases by a common amount (the sample-to-sample scatter,
        # sd 0.2) and each test adds its own noise (sd 0.05): the true difference is 0.08
        rng = np.random.RandomState(11)
        for n in (3, 5, 10):
            with self.subTest(n=n):
                common = rng.normal(0.0, 0.2, (self.M, n))
                rigid = 2.80 + common + rng.normal(0.0, 0.05, (self.M, n))
                membrane = 2.72 + common + rng.normal(0.0, 0.05, (self.M, n))
                paired = [stats.paired_difference(r, m) for r, m in zip(rigid, membrane)]
                self.check([iv.covers(0.08) for iv in paired], f"paired, n = {n}")
                # pairing removes the common scatter: narrower than the unpaired interval
                unpaired = [math.hypot(stats.mean_interval(r).half_width,
                                       stats.mean_interval(m).half_width)
                            for r, m in zip(rigid, membrane)]
                self.assertLess(np.median([iv.half_width for iv in paired]),
                                0.5 * np.median(unpaired))


if __name__ == "__main__":
    unittest.main()
