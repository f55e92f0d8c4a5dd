#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "stability_checks.h"

using namespace stability;

TEST(ContactTime, PublishedSmallestDisk)
{
  // d = 0.5 mm, rho = 2e8: m = pi (0.25 mm)^2 2e8 = 39.27 kg; k_n = 8.45e7 N/m
  const double m = M_PI * 0.25e-3 * 0.25e-3 * 2e8;
  EXPECT_NEAR(contact_time(m, 8.45e7), 6.8171e-4, 1e-8);
  EXPECT_NEAR(time_step_ratio(1e-4, m, 8.45e7), 0.146690, 1e-6);
  EXPECT_NEAR(safe_time_step(0.3, m, 8.45e7), 2.04513e-4, 1e-9);
}

TEST(ContactTime, UnknownScalesGiveZero)
{
  EXPECT_EQ(contact_time(0.0, 1e7), 0.0);
  EXPECT_EQ(contact_time(1.0, 0.0), 0.0);
  EXPECT_EQ(time_step_ratio(1e-4, 1.0, 0.0), 0.0);
}

TEST(InertialNumber, HandWorked)
{
  // 0.01 /s * 1.75 mm * sqrt(2e8 / 1e5) = 1.75e-5 * 44.7214 = 7.8262e-4
  EXPECT_NEAR(inertial_number(0.01, 1.75e-3, 2e8, 1e5), 7.82624e-4, 1e-9);
  EXPECT_NEAR(inertial_number(-0.01, 1.75e-3, 2e8, 1e5), 7.82624e-4, 1e-9); // sign of the rate
  EXPECT_EQ(inertial_number(0.01, 1e-3, 2e8, 0.0), std::numeric_limits<double>::infinity());
}

TEST(StepFraction, HandWorked)
{
  // |(3, 4)| m/s * 1e-5 s / 1 mm = 0.05
  EXPECT_NEAR(step_fraction(3.0, 4.0, 1e-5, 1e-3), 0.05, 1e-15);
}

TEST(OverlapFraction, HandWorked)
{
  // radii 1 and 0.5 mm, centres 1.4 mm apart: overlap 0.1 mm / 0.5 mm = 0.2
  EXPECT_NEAR(overlap_fraction(1.4e-3, 0.0, 1e-3, 0.5e-3), 0.2, 1e-12);
  // apart by 0.6 * sqrt(2)... along a diagonal: distance 1.6 mm -> gap 0.1 mm -> -0.2
  EXPECT_NEAR(overlap_fraction(1.6e-3 / std::sqrt(2.0), 1.6e-3 / std::sqrt(2.0), 1e-3, 0.5e-3),
              -0.2, 1e-12);
}

namespace {

// n atoms in LIGGGHTS' array-of-rows layout
struct Atoms {
  explicit Atoms(int n)
    : xs(n, {0, 0, 0}), vs(n, {0, 0, 0}), fs(n, {0, 0, 0}), r(n, 1e-3), mask(n, 1)
  {
    for (int i = 0; i < n; i++) {
      x.push_back(xs[i].data());
      v.push_back(vs[i].data());
      f.push_back(fs[i].data());
    }
  }
  std::vector<std::array<double, 3>> xs, vs, fs;
  std::vector<double *> x, v, f;
  std::vector<double> r;
  std::vector<int> mask;
  AtomScan scan(double dt) const
  {
    return scan_atoms(r.size(), x.data(), v.data(), f.data(), r.data(), mask.data(), 1, dt);
  }
};

} // namespace

TEST(ScanAtoms, FastestDiskOfTheGroup)
{
  Atoms a(4);
  a.vs[1] = {1.0, 0.0, 0.0};  // 1 m/s, r 1 mm, dt 1e-5 -> 0.01
  a.vs[2] = {0.0, -2.0, 0.0}; // 0.02
  a.r[3] = 0.5e-3;
  a.vs[3] = {3.0, 0.0, 0.0}; // 0.06, but outside the group
  a.mask[3] = 2;
  const AtomScan s = a.scan(1e-5);
  EXPECT_EQ(s.nonfinite, 0);
  EXPECT_EQ(s.first_nonfinite, -1);
  EXPECT_EQ(s.argmax_step, 2);
  EXPECT_NEAR(s.max_step_fraction, 0.02, 1e-15);
}

TEST(ScanAtoms, NonFiniteValuesAreCountedNotMeasured)
{
  Atoms a(5);
  a.vs[0] = {0.5, 0.0, 0.0};
  a.xs[1][0] = std::numeric_limits<double>::quiet_NaN();
  a.vs[2][1] = std::numeric_limits<double>::infinity();
  a.fs[3][2] = -std::numeric_limits<double>::infinity();
  a.mask[4] = 0;
  a.vs[4][0] = std::numeric_limits<double>::quiet_NaN(); // outside the group: ignored
  const AtomScan s = a.scan(1e-5);
  EXPECT_EQ(s.nonfinite, 3);
  EXPECT_EQ(s.first_nonfinite, 1);
  EXPECT_EQ(s.argmax_step, 0);
  EXPECT_NEAR(s.max_step_fraction, 0.005, 1e-15);
}

TEST(ScanAtoms, EmptyGroup)
{
  Atoms a(2);
  a.mask = {0, 0};
  const AtomScan s = a.scan(1e-5);
  EXPECT_EQ(s.argmax_step, -1);
  EXPECT_EQ(s.max_step_fraction, 0.0);
}
