#include <gtest/gtest.h>

#include "grain_size.h"

using grains::d50_by_mass;

TEST(D50ByMass, HalfOfTheDiskAreaLiesBelowIn2D)
{
  // areas ~ d^2: 1, 4, 9, 16 (total 30); cumulative 1, 5, 14, 30 -> half (15) reached at d = 4
  EXPECT_EQ(d50_by_mass({3.0, 1.0, 4.0, 2.0}, 2), 4.0);
  // 1 + 1 + 1 + 9 = 12: cumulative 1, 2, 3 < 6, then 12 -> d = 3
  EXPECT_EQ(d50_by_mass({1.0, 1.0, 1.0, 3.0}, 2), 3.0);
  // equal sizes: the size itself
  EXPECT_EQ(d50_by_mass({2.0, 2.0, 2.0}, 2), 2.0);
  EXPECT_EQ(d50_by_mass({}, 2), 0.0);
}

TEST(D50ByMass, HalfOfTheSphereVolumeLiesBelowIn3D)
{
  // 2D and 3D differ: five of d = 1 and one of d = 2. Areas 5 x 1 + 4 (total 9):
  // cumulative 5 >= 4.5 -> d = 1. Volumes 5 x 1 + 8 (total 13): 5 < 6.5 -> d = 2
  EXPECT_EQ(d50_by_mass({1.0, 1.0, 2.0, 1.0, 1.0, 1.0}, 2), 1.0);
  EXPECT_EQ(d50_by_mass({1.0, 1.0, 2.0, 1.0, 1.0, 1.0}, 3), 2.0);
  EXPECT_EQ(d50_by_mass({}, 3), 0.0);
}

TEST(D50ByMass, ExactlyHalfIsEnough)
{
  // the smallest d with at least half of the mass at or below it: areas 1, 1, 2
  // (total 4): cumulative 1, 2 = half -> d = 1, not the next size
  EXPECT_EQ(d50_by_mass({1.0, 1.0, 1.4142135623730951}, 2), 1.0);
  // one grain: itself
  EXPECT_EQ(d50_by_mass({0.7}, 3), 0.7);
}
