"""Shear-band detection on synthetic displacement fields."""
import unittest

import numpy as np

from liggghts_membrane import synthetic
from liggghts_membrane import field
from liggghts_membrane.curves import measured

D50 = 1.75e-3


def analyse(du_function, **kw):
    x = synthetic.random_sample(n=8000)
    du = du_function(x, **kw)
    G, _ = field.local_gradients(x, du, 3 * D50)
    return field.detect_band(x, field.max_shear_strain(G), D50, G)


class KnownBand(unittest.TestCase):
    """Band at 55 deg from the horizontal, 15 mm thick (tanh step of the slip), in a
    75 x 150 mm box of 8000 random points, with a uniform strain and 10 um noise."""

    def test_angle_and_thickness(self):
        for seed, angle in ((1, 55.0), (2, 55.0), (3, 180.0 - 55.0)):
            with self.subTest(seed=seed, angle=angle):
                band = analyse(synthetic.band_displacement, angle_deg=angle, seed=seed,
                               centre=(0.0375, 0.07 + 0.005 * seed))
                self.assertTrue(measured(band["angle"]), str(band["angle"]))
                self.assertAlmostEqual(band["angle"], 55.0, delta=2.0)
                self.assertTrue(measured(band["thickness"]), str(band["thickness"]))
                self.assertAlmostEqual(band["thickness"] / 0.015, 1.0, delta=0.2)


class NoBand(unittest.TestCase):
    def test_uniform_strain_with_noise(self):
        def uniform(x, noise):
            rng = np.random.default_rng(5)
            return x @ np.array([[5e-4, 0.0], [0.0, -1e-3]]).T + rng.normal(0, noise, x.shape)

        for noise in (0.0, 2e-6, 1e-5):
            with self.subTest(noise=noise):
                band = analyse(uniform, noise=noise)
                self.assertFalse(measured(band["angle"]))
                self.assertFalse(measured(band["thickness"]))
                self.assertIn("not measurable", str(band["angle"]))


class Pieces(unittest.TestCase):
    def test_gradient_of_affine_field_is_exact(self):
        x = synthetic.random_sample(n=2000, seed=4)
        L = np.array([[1e-3, 2e-3], [-5e-4, -3e-3]])
        G, count = field.local_gradients(x, x @ L.T, 3 * D50)
        ok = np.isfinite(G).all(axis=(1, 2))
        self.assertTrue(np.all(count[ok] >= 3))
        self.assertGreater(ok.mean(), 0.99)
        np.testing.assert_allclose(G[ok], np.broadcast_to(L, G[ok].shape), atol=1e-12)

    def test_neighbours_within_the_radius(self):
        # (0,0)-(1,0) and (0,0)-(0,1) are 1 apart (counted: distance <= radius),
        # (1,0)-(0,1) sqrt 2 apart, (5,5) alone
        x = np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0], [5.0, 5.0]])
        G, count = field.local_gradients(x, np.zeros_like(x), 1.0)
        np.testing.assert_array_equal(count, [2, 1, 1, 0])
        self.assertTrue(np.isnan(G).all())   # fewer than 3 neighbours everywhere

    def test_max_shear_strain(self):
        G = np.array([[[1e-3, 0.0], [0.0, -1e-3]], [[0.0, 1e-3], [0.0, 0.0]]])
        np.testing.assert_allclose(field.max_shear_strain(G), [2e-3, 1e-3])

    def test_inclination(self):
        self.assertAlmostEqual(field.inclination_from_horizontal(125.0), 55.0)
        self.assertAlmostEqual(field.inclination_from_horizontal(55.0), 55.0)


if __name__ == "__main__":
    unittest.main()
