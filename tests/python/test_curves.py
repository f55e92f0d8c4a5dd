"""Macro analysis on a synthetic curve with known E, nu, phi and psi."""
import os
import tempfile
import unittest

from liggghts_membrane import synthetic
from liggghts_membrane import curves, readers


class SyntheticCurve(unittest.TestCase):
    """E = 50 MPa, nu = 0.3, phi = 30 deg (peak ratio 3), psi = 10 deg, written in the
    OUT format (every 0.05 % strain, like the shear scripts) and read back."""

    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        path = os.path.join(cls.tmp.name, "shear_rigid.txt")
        cls.curve = synthetic.elastoplastic_curve(E=50e6, nu=0.3, phi=30.0, psi=10.0)
        synthetic.write_out(path, cls.curve, ["step", "ea", "s1", "s3", "s1/s3", "ev", "el"])
        cls.table = readers.read_output(path)
        cls.res = curves.analyse_curves(cls.table)

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_peak(self):
        # tolerance: the 100 Pa noise on q moves the ratio by ~1e-3
        self.assertAlmostEqual(self.res["peak_ratio"], 3.0, delta=0.005)
        self.assertAlmostEqual(self.res["ea_peak"], 0.03, delta=0.0026)

    def test_friction_angle(self):
        self.assertAlmostEqual(self.res["phi_peak"], 30.0, delta=0.3)

    def test_young_modulus(self):
        self.assertAlmostEqual(self.res["E"] / 50e6, 1.0, delta=0.03)   # 3 %
        first, last, lines, fraction = self.res["elastic_window"]
        self.assertEqual(first, 0.0)
        self.assertLessEqual(last, 0.002)  # stays in the elastic range (q < q_peak / 2)
        self.assertGreaterEqual(lines, 4)

    def test_poisson_ratio(self):
        self.assertAlmostEqual(self.res["nu"], 0.3, delta=0.01)

    def test_dilatancy_angle(self):
        self.assertAlmostEqual(self.res["psi"], 10.0, delta=0.5)
        self.assertTrue(0.02 <= self.res["ea_psi"] <= 0.045)

    def test_missing_fabric_columns_are_reported(self):
        for name in ("a", "f0", "gsi", "Zm"):
            self.assertIn(name, self.table.missing)
        self.assertFalse(curves.measured(self.res["f0_end"]))


class FormulaChecks(unittest.TestCase):
    def test_friction_angle_round_trip(self):
        self.assertAlmostEqual(curves.ratio_from_friction_angle(30.0), 3.0, places=12)
        self.assertAlmostEqual(curves.friction_angle(3.0), 30.0, places=12)

    def test_dilatancy_round_trip(self):
        r = curves.volume_rate_from_dilatancy(10.0)
        self.assertLess(r, 0.0)            # dilation: eps_v decreases
        self.assertAlmostEqual(curves.dilatancy_angle(r), 10.0, places=12)
        self.assertAlmostEqual(curves.dilatancy_angle(0.0), 0.0)

    def test_no_peak_when_still_rising(self):
        import numpy as np
        ea = np.linspace(0, 0.05, 50)
        peak = curves.find_peak(ea, 1 + 10 * ea)
        self.assertFalse(curves.measured(peak))
        self.assertIn("still rising", str(peak))


if __name__ == "__main__":
    unittest.main()
