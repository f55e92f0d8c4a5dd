// fix membrane3d's checks and their messages (membrane3d_messages.h): each holds ("")
// or gives its message, the values in it worked by hand.
#include "membrane3d_messages.h"

#include <gtest/gtest.h>

#include <limits>
#include <string>
#include <vector>

namespace {

using Eigen::Vector3d;
using membrane3d::GatheredSpheres;
using membrane3d::Sphere;

TEST(Membrane3dMessages, CentreStrictlyBetweenThePlatens)
{
  const membrane3d::Platens p{0.0, 2.5};
  EXPECT_EQ(membrane3d::platens_problem(12, 0.5, p, 7), "");
  EXPECT_EQ(membrane3d::platens_problem(12, 2.5, p, 7),
            "atom 12 at z = 2.5 is not between zlo = 0 and zhi = 2.5 at step 7; the platens "
            "must enclose every sphere centre of the group");
  EXPECT_NE(membrane3d::platens_problem(12, 0.0, p, 7), "");
  EXPECT_NE(membrane3d::platens_problem(12, -1e-300, p, 7), "");
}

TEST(Membrane3dMessages, AtLeastFourSpheres)
{
  EXPECT_EQ(membrane3d::too_few_spheres("sample", 4, 5), "");
  EXPECT_EQ(membrane3d::too_few_spheres("sample", 3, 5),
            "the group 'sample' has 3 atoms at step 5; a membrane needs a sample of at least "
            "four spheres (were atoms lost from the box?)");
  EXPECT_EQ(membrane3d::too_few_spheres("all", 1, 0).substr(0, 27), "the group 'all' has 1 atom ");
}

TEST(Membrane3dMessages, OpenMembraneNamesThePlaten)
{
  membrane3d::LateralSurface m;
  m.reaches_lo = m.reaches_hi = true;
  EXPECT_EQ(membrane3d::open_warning(m, 3), "");
  m.reaches_hi = false;
  EXPECT_EQ(membrane3d::open_warning(m, 3),
            "the membrane does not reach the upper (zhi) platen at step 3: no sphere is within "
            "the tolerance of it, so the membrane closes over that end of the sample and "
            "presses on it");
  m.reaches_lo = false; // the lower is named first
  EXPECT_EQ(membrane3d::open_warning(m, 3).substr(0, 46),
            "the membrane does not reach the lower (zlo) pl");
}

TEST(Membrane3dMessages, ClosedLoadsHaveNoLateralNetForce)
{
  Vector3d net;
  // (1, 2, 3) + (-1, -2, 1): no lateral part, net (0, 0, 4)
  EXPECT_EQ(membrane3d::closure_problem({Vector3d(1, 2, 3), Vector3d(-1, -2, 1)}, 1.0, 9, net), "");
  EXPECT_EQ(net, Vector3d(0, 0, 4));
  // a lateral round-off of 1e-12 against 2 in all: within 1e-9
  EXPECT_EQ(
      membrane3d::closure_problem({Vector3d(1, 0, 0), Vector3d(-1 + 1e-12, 0, 0)}, 1.0, 9, net),
      "");
  // (3, 0, 0) + (0, 4, 0): lateral 5 of 3 + 4 = 7
  EXPECT_EQ(membrane3d::closure_problem({Vector3d(3, 0, 0), Vector3d(0, 4, 0)}, 1.0, 9, net),
            "the membrane's loads have a lateral net force of 5 N (of 7 N in all) at step 9: "
            "the membrane is not closed; this is a fault of fix membrane3d; please report it "
            "with the input script");
  EXPECT_EQ(net, Vector3d(3, 4, 0));
}

TEST(Membrane3dMessages, LoadsThatAreNotFinite)
{
  const double inf = std::numeric_limits<double>::infinity();
  Vector3d net;
  // a finite pressure whose loads overflow: the input's fault
  EXPECT_EQ(membrane3d::closure_problem({Vector3d(1e308, 0, 0), Vector3d(-1e308, 0, 1e308)}, 1e300,
                                        2, net),
            "the membrane's loads at step 2 are not finite: the pressure 1e+300 times the "
            "facets' areas overflows; give the confining pressure in the units of the box "
            "(force/area)");
  // the pressure itself not finite: a load not finite
  EXPECT_EQ(membrane3d::closure_problem({Vector3d(inf, 0, 0)}, inf, 2, net),
            "the membrane's loads have a lateral net force of inf N (of inf N in all) at step 2: "
            "a load is not finite; this is a fault of fix membrane3d; please report it with the "
            "input script");
}

TEST(Membrane3dMessages, FarthestMovedMember)
{
  GatheredSpheres now;
  now.tags = {5, 6, 7};
  now.spheres = {
      {Vector3d(0, 0.3, 0), 0.5}, {Vector3d(1.3, 0.4, 0), 0.5}, {Vector3d(2, 0, 0.2), 0.5}};
  std::vector<Sphere> at; // after a restart: from now on
  EXPECT_EQ(membrane3d::moved_warning(now, at, 0.4, 10, 12), "");
  ASSERT_EQ(at.size(), 3u);
  EXPECT_EQ(at[1].x, now.spheres[1].x);
  at = {{Vector3d(0, 0, 0), 0.5}, {Vector3d(1, 0, 0), 0.5}, {Vector3d(2, 0, 0), 0.5}};
  // moved 0.3, 0.5 (0.3, 0.4, 0) and 0.2: atom 6 the farthest
  EXPECT_EQ(membrane3d::moved_warning(now, at, 0.4, 10, 12),
            "membrane sphere 6 has moved 0.5 since the membrane was found at step 10, more than "
            "the tolerance 0.4 (at step 12): that membrane can be out of date; find it more "
            "often (a smaller every, or every auto)");
  EXPECT_EQ(membrane3d::moved_warning(now, at, 0.51, 10, 12), "");
  // the same from the farthest member alone (the style finds it over the ranks)
  EXPECT_EQ(membrane3d::moved_warning(6, 0.5, 0.4, 10, 12),
            "membrane sphere 6 has moved 0.5 since the membrane was found at step 10, more than "
            "the tolerance 0.4 (at step 12): that membrane can be out of date; find it more "
            "often (a smaller every, or every auto)");
  EXPECT_EQ(membrane3d::moved_warning(6, 0.4, 0.4, 10, 12), "");
}

TEST(Membrane3dMessages, RanksThatDisagree)
{
  const double same[3] = {10, 20, 55};
  EXPECT_EQ(membrane3d::ranks_disagree(same, same, 3), "");
  const double lo[3] = {10, 20, 55}, hi[3] = {11, 20, 60};
  EXPECT_EQ(membrane3d::ranks_disagree(lo, hi, 3),
            "the ranks found different membranes at step 3 (members 10 to 11, facets 20 to 20); "
            "please report this with the input script");
  const double sum[3] = {10, 20, 56}; // the members' IDs alone differ
  EXPECT_NE(membrane3d::ranks_disagree(same, sum, 3), "");
}

} // namespace
