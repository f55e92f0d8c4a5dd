// Which fixes may follow fix damping/local, and the warning about one that may not.
#include "damping_order.h"

#include <gtest/gtest.h>

using damping::adds_no_force;
using damping::order_warning;

TEST(DampingOrder, ConstraintsAndReadersAddNoForce)
{
  for (const char *style : {"enforce2d", "freeze", "setforce", "lineforce", "planeforce",
                            "store/force", "heat/gran", "sph/mixidx"})
    EXPECT_TRUE(adds_no_force(style)) << style;
}

TEST(DampingOrder, ForceFixesAndNearNamesDo)
{
  for (const char *style : {"addforce", "gravity", "wall/gran", "membrane2d", "damping/local",
                            "viscous", "Freeze", "setforce/spin", "enforce", ""})
    EXPECT_FALSE(adds_no_force(style)) << style;
}

TEST(DampingOrder, WarningOfAForceFixDefinedAfter)
{
  EXPECT_EQ(order_warning("d", "damping/local", "fc", "addforce", 1),
            "fix fc (addforce) is defined after fix d and acts in post_force on 1 atom(s) that "
            "fix d damps: forces it adds to them are not damped; define fix d after fix fc");
}

TEST(DampingOrder, WarningOfASecondDamping)
{
  EXPECT_EQ(order_warning("d", "damping/local", "d3", "damping/local", 12),
            "fix d3 (damping/local) also damps 12 atom(s) that fix d damps: their force is damped "
            "twice; give the two fixes groups without common atoms");
}
