"""Secant modulus E50 and the particle strain, against hand-worked values."""
import unittest

import numpy as np

from liggghts_membrane import curves, particle_strain
from liggghts_membrane.curves import measured


class HalfRise(unittest.TestCase):
    # q rises 0, 10, 30, 60, 100 (peak), 90; half the rise = 50, between 30 (ea 0.2)
    # and 60 (ea 0.3): ea50 = 0.2 + (50 - 30)/(60 - 30) * 0.1 = 0.2666...
    ea = np.array([0.0, 0.1, 0.2, 0.3, 0.4, 0.5])
    q = np.array([5.0, 15.0, 35.0, 65.0, 105.0, 95.0])   # q0 = 5: the rise is q - 5

    def test_interpolated_half_rise(self):
        self.assertAlmostEqual(curves.half_rise_strain(self.ea, self.q, 4), 0.2 + 2.0 / 30.0, places=14)

    def test_secant(self):
        ea50 = curves.half_rise_strain(self.ea, self.q, 4)
        el = -0.25 * self.ea                   # lateral expansion, nu = 0.25 throughout
        E50, nu50 = curves.secant_constants(self.ea, self.q, el, ea50)
        self.assertAlmostEqual(E50, 50.0 / ea50, places=10)
        self.assertAlmostEqual(nu50, 0.25, places=14)

    def test_no_peak(self):
        r = curves.half_rise_strain(self.ea, self.q, curves.NotMeasurable("no peak"))
        self.assertFalse(measured(r))
        E50, nu50 = curves.secant_constants(self.ea, self.q, self.ea, r)
        self.assertFalse(measured(E50) or measured(nu50))


class Correlation(unittest.TestCase):
    class Table(dict):
        def has(self, k):
            return k in self

    def test_exact_line_and_anti_line(self):
        t = self.Table(gsi=np.array([0.1, 0.2, 0.3, 0.5]), a=np.array([1.0, 3.0, 5.0, 9.0]))
        self.assertAlmostEqual(curves.correlation(t, "gsi", "a"), 1.0, places=14)
        t["a"] = -t["a"]
        self.assertAlmostEqual(curves.correlation(t, "gsi", "a"), -1.0, places=14)

    def test_hand_worked(self):
        # x = 1, 2, 3; y = 1, 3, 2: cov = 0.5, var x = var y = 1 -> r = 0.5
        t = self.Table(gsi=np.array([1.0, 2.0, 3.0]), a=np.array([1.0, 3.0, 2.0]))
        self.assertAlmostEqual(curves.correlation(t, "gsi", "a"), 0.5, places=14)

    def test_missing_column(self):
        self.assertFalse(measured(curves.correlation(self.Table(a=np.ones(3)), "gsi", "a")))


class AffineStrain(unittest.TestCase):
    def test_exact_affine_field(self):
        rng = np.random.default_rng(1)
        x0 = rng.uniform(0, 1, size=(200, 2))
        G = np.array([[0.004, 0.001], [-0.002, -0.01]])     # du_i/dx_j
        du = (x0 - 0.3) @ G.T + np.array([1e-3, -2e-3])
        exx, eyy = particle_strain.affine_strain(x0, du)
        self.assertAlmostEqual(exx, -0.004, places=14)
        self.assertAlmostEqual(eyy, 0.01, places=14)

    def test_noise_averages_out(self):
        rng = np.random.default_rng(2)
        x0 = rng.uniform(0, 1, size=(20000, 2))
        du = x0 @ np.diag([0.002, -0.005]) + rng.normal(0, 1e-4, size=x0.shape)
        exx, eyy = particle_strain.affine_strain(x0, du)
        # standard error of the slope: 1e-4 / (sqrt(n) * 0.289) = 2.4e-6
        self.assertAlmostEqual(exx, -0.002, delta=1.2e-5)
        self.assertAlmostEqual(eyy, 0.005, delta=1.2e-5)


if __name__ == "__main__":
    unittest.main()
