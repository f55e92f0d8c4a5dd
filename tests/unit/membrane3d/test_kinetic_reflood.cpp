// The local update of the kinetic flood's flood (kinetic_exterior.h): a pocket closed
// off by a sphere that comes down into its mouth, opened again as it leaves, and the
// sample cut in two of which the larger is kept; at every step the boundary is
// exterior_boundary() from scratch, and the steps where the flood changes so are
// updated locally (not by the whole flood).
#include "kinetic_flood.h"
#include "packings.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace {

using Eigen::Vector3d;
using membrane3d::Boundary;
using membrane3d::KineticFlood;
using membrane3d::Side;
using membrane3d::Sphere;

constexpr double kTolerance = 0.8; // links unit neighbours and the square and cube diagonals

bool same(const Boundary &a, const Boundary &b)
{
  return a.facets == b.facets && a.side == b.side;
}

void jitter(std::vector<Sphere> &s, double by, unsigned seed)
{
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> move(-by, by);
  for (Sphere &x : s)
    for (int d = 0; d < 3; ++d) x.x[d] += move(random);
}

// Advances through `frames`, each compared with the fresh flood; per frame whether the
// fresh boundary changed and whether the flood was updated locally.
struct Steps {
  int changed = 0, changed_locally = 0;
  std::vector<Boundary> fresh;
};

Steps advance(KineticFlood &flood, const std::vector<std::vector<Sphere>> &frames,
            const std::vector<bool> &sealed)
{
  Steps run;
  Boundary last = flood.boundary();
  for (std::size_t f = 0; f < frames.size(); ++f) {
    const long kept = flood.stats().floods_kept;
    flood.advance(frames[f]);
    const Boundary fresh = membrane3d::exterior_boundary(frames[f], sealed, kTolerance);
    EXPECT_TRUE(same(flood.boundary(), fresh)) << "frame " << f;
    if (!same(fresh, last)) {
      ++run.changed;
      run.changed_locally += flood.stats().floods_kept > kept;
    }
    last = fresh;
    run.fresh.push_back(fresh);
  }
  return run;
}

// A 5 x 5 x 4 block without the sphere at the middle of its top (a pit the flood enters)
// and a lid sphere that comes down from above into the pit's mouth and goes back: the
// pit is closed off (its cells dry, joined to the sample) and opened again.
TEST(KineticReflood, ClosesAndOpensAPocket)
{
  std::vector<Sphere> s;
  for (const Sphere &x : packings::simple_cubic(5, 5, 4))
    if (!(x.x.x() == 2 && x.x.y() == 2 && x.x.z() == 3)) s.push_back(x);
  jitter(s, 0.01, 5);
  const std::size_t lid = s.size();
  s.push_back({Vector3d(2.003, 1.998, 6.0), 0.5});
  const std::vector<bool> sealed(s.size(), false);
  KineticFlood flood(s, sealed, kTolerance, 0.01);
  std::vector<std::vector<Sphere>> frames;
  for (int step = 1; step <= 60; ++step) { // down by 0.1 a step to z = 3, then up again
    const double z = step <= 30 ? 6.0 - 0.1 * step : 3.0 + 0.1 * (step - 30);
    s[lid].x.z() = z;
    frames.push_back(s);
  }
  const Steps run = advance(flood, frames, sealed);
  // the lid on the membrane while it closes the pit, outside before and after
  EXPECT_EQ(run.fresh.front().side[lid], Side::outside);
  EXPECT_EQ(run.fresh[29].side[lid], Side::surface);
  EXPECT_EQ(run.fresh.back().side[lid], Side::outside);
  EXPECT_GE(run.changed, 4);
  EXPECT_EQ(run.changed_locally, run.changed);
}

// A 9 x 3 x 3 bar whose last five layers move away from its first four: the flood cuts
// through between them, the sample is the five layers (the larger group), the four are
// outside; and back together, one sample again.
TEST(KineticReflood, KeepsTheLargerOfTwoGroupsWhenTheSampleSplits)
{
  std::vector<Sphere> s = packings::simple_cubic(9, 3, 3);
  jitter(s, 0.01, 7);
  const std::vector<Sphere> start = s;
  const std::vector<bool> sealed(s.size(), false);
  KineticFlood flood(s, sealed, kTolerance, 0.01);
  std::vector<std::vector<Sphere>> frames;
  for (int step = 1; step <= 40; ++step) { // apart by 0.05 a step to 1.0, then back
    const double d = step <= 20 ? 0.05 * step : 0.05 * (40 - step);
    for (std::size_t i = 0; i < s.size(); ++i)
      s[i].x.x() = start[i].x.x() + (start[i].x.x() > 3.5 ? d : 0.0);
    frames.push_back(s);
  }
  const Steps run = advance(flood, frames, sealed);
  std::size_t small = 0, large = 0; // a middle sphere of each part
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (std::abs(start[i].x.x() - 1) < 0.1 && std::abs(start[i].x.y() - 1) < 0.1 &&
        std::abs(start[i].x.z() - 1) < 0.1)
      small = i;
    if (std::abs(start[i].x.x() - 6) < 0.1 && std::abs(start[i].x.y() - 1) < 0.1 &&
        std::abs(start[i].x.z() - 1) < 0.1)
      large = i;
  }
  EXPECT_EQ(run.fresh.front().side[small], Side::inside);
  EXPECT_EQ(run.fresh[19].side[small], Side::outside); // the four layers left out
  EXPECT_EQ(run.fresh[19].side[large], Side::inside);
  EXPECT_EQ(run.fresh.back().side[small], Side::inside);
  EXPECT_GE(run.changed, 2);
  EXPECT_EQ(run.changed_locally, run.changed);
}

// The same with the cut the other way (the larger part first in the spheres' order and
// in CGAL's storage): the larger is kept, whichever group the old sample's label follows.
TEST(KineticReflood, KeepsTheLargerGroupWhicheverSideIsFirst)
{
  std::vector<Sphere> s = packings::simple_cubic(9, 3, 3);
  jitter(s, 0.01, 9);
  const std::vector<Sphere> start = s;
  const std::vector<bool> sealed(s.size(), false);
  KineticFlood flood(s, sealed, kTolerance, 0.01);
  std::vector<std::vector<Sphere>> frames;
  for (int step = 1; step <= 20; ++step) {
    for (std::size_t i = 0; i < s.size(); ++i)
      s[i].x.x() = start[i].x.x() + (start[i].x.x() > 4.5 ? 0.05 * step : 0.0);
    frames.push_back(s);
  }
  const Steps run = advance(flood, frames, sealed);
  EXPECT_GE(run.changed, 1);
  EXPECT_EQ(run.changed_locally, run.changed);
}

} // namespace
