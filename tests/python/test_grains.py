"""liggghts_membrane.grains.d50_by_mass: the step definition of the C++ styles
(common/grain_size.cpp), not an interpolation of the mass distribution."""
import math
import unittest

import numpy as np

from liggghts_membrane.grains import d50_by_mass


class D50ByMass(unittest.TestCase):
    def test_step_not_interpolated(self):
        # disks 1, 2, 3, 4 mm: masses ~ d^2 = 1, 4, 9, 16 (total 30, half 15); cumulative
        # 1, 5, 14, 30: d <= 3 holds 14 < 15, d <= 4 holds 30 >= 15 -> D50 = 4 mm.
        # Interpolating the cumulative mass linearly in d would give
        # 3 + (15 - 14) / (30 - 14) = 3.0625 mm: the definitions differ, we give the step.
        d = [3.0, 1.0, 4.0, 2.0]
        self.assertEqual(d50_by_mass(d, 2), 4.0)
        sd = np.sort(d)
        interpolated = float(np.interp(15.0, np.cumsum(sd ** 2), sd))
        self.assertAlmostEqual(interpolated, 3.0625)
        self.assertNotEqual(d50_by_mass(d, 2), interpolated)

    def test_cases_of_the_cpp_unit_test(self):
        # tests/unit/common/test_grain_size.cpp, the same inputs and answers
        self.assertEqual(d50_by_mass([1.0, 1.0, 1.0, 3.0], 2), 3.0)   # 1+1+1 < 6, then 12
        self.assertEqual(d50_by_mass([2.0, 2.0, 2.0], 2), 2.0)
        # five of d = 1 and one of d = 2: areas 5 + 4 (5 >= 4.5 -> 1), volumes 5 + 8 (5 < 6.5 -> 2)
        six = [1.0, 1.0, 2.0, 1.0, 1.0, 1.0]
        self.assertEqual(d50_by_mass(six, 2), 1.0)
        self.assertEqual(d50_by_mass(six, 3), 2.0)

    def test_half_exactly_reached_takes_that_grain(self):
        # masses 1, 1, 1, 1: half (2) reached exactly by the second grain -> its diameter
        self.assertEqual(d50_by_mass([1.0, 1.0, 1.0, 1.0], 2), 1.0)
        # 1 (d=1) and 1 (d=1) then 4 (d=2): total 6, half 3; cumulative 1, 2, 6 -> 2
        self.assertEqual(d50_by_mass([2.0, 1.0, 1.0], 2), 2.0)

    def test_empty_and_bad_dimension(self):
        self.assertTrue(math.isnan(d50_by_mass([], 2)))
        with self.assertRaises(ValueError):
            d50_by_mass([1.0], 1)


if __name__ == "__main__":
    unittest.main()
