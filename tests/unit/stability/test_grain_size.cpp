#include <gtest/gtest.h>

#include "grain_size.h"

using stability::d50_by_area;

TEST(D50ByArea, HalfOfTheAreaLiesBelow)
{
  // areas ~ d^2: 1, 4, 9, 16 (total 30); cumulative 1, 5, 14, 30 -> half (15) reached at d = 4
  EXPECT_EQ(d50_by_area({3.0, 1.0, 4.0, 2.0}), 4.0);
  // 1 + 1 + 1 + 9 = 12: cumulative 1, 2, 3 < 6, then 12 -> d = 3
  EXPECT_EQ(d50_by_area({1.0, 1.0, 1.0, 3.0}), 3.0);
  // equal sizes: the size itself
  EXPECT_EQ(d50_by_area({2.0, 2.0, 2.0}), 2.0);
  EXPECT_EQ(d50_by_area({}), 0.0);
}
