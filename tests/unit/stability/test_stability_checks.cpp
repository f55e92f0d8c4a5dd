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
  EXPECT_NEAR(step_fraction(3.0, 4.0, 0.0, 1e-5, 1e-3), 0.05, 1e-15);
  // in 3D vz counts: |(2, 3, 6)| = 7 m/s * 1e-5 s / 1 mm = 0.07
  EXPECT_NEAR(step_fraction(2.0, 3.0, 6.0, 1e-5, 1e-3), 0.07, 1e-15);
}

TEST(OverlapFraction, HandWorked)
{
  // radii 1 and 0.5 mm, centres 1.4 mm apart: overlap 0.1 mm / 0.5 mm = 0.2
  EXPECT_NEAR(overlap_fraction(1.4e-3, 0.0, 0.0, 1e-3, 0.5e-3), 0.2, 1e-12);
  // apart by 0.6 * sqrt(2)... along a diagonal: distance 1.6 mm -> gap 0.1 mm -> -0.2
  EXPECT_NEAR(overlap_fraction(1.6e-3 / std::sqrt(2.0), 1.6e-3 / std::sqrt(2.0), 0.0, 1e-3, 0.5e-3),
              -0.2, 1e-12);
  // in 3D along (2, 3, 6)/7: distance 1.4 mm -> overlap 0.1 mm -> 0.2
  EXPECT_NEAR(overlap_fraction(0.4e-3, 0.6e-3, 1.2e-3, 1e-3, 0.5e-3), 0.2, 1e-12);
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
  AtomScan scan(double dt, const int *tag = nullptr) const
  {
    return scan_atoms(r.size(), x.data(), v.data(), f.data(), r.data(), mask.data(), 1, dt, nullptr, tag);
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

TEST(ScanAtoms, MotionAlongZCountsIn3D)
{
  Atoms a(2);
  a.vs[0] = {0.0, 2.0, 0.0};  // 0.02
  a.vs[1] = {0.0, 0.0, -3.0}; // 0.03: a sphere falling along z
  const AtomScan s = a.scan(1e-5);
  EXPECT_EQ(s.argmax_step, 1);
  EXPECT_NEAR(s.max_step_fraction, 0.03, 1e-15);
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

TEST(ScanAtoms, NamesTheCauseByTagNotItsNeighbours)
{
  // a NaN velocity (tag 9) gives its neighbours (tags 2 and 30) NaN contact forces:
  // the velocity is named, whatever the order of the atoms on the rank
  Atoms a(3);
  const int tags[3] = {30, 9, 2};
  a.fs[0][0] = std::numeric_limits<double>::quiet_NaN();
  a.vs[1][2] = std::numeric_limits<double>::quiet_NaN();
  a.fs[2][1] = std::numeric_limits<double>::quiet_NaN();
  AtomScan s = scan_atoms(3, a.x.data(), a.v.data(), a.f.data(), a.r.data(), a.mask.data(), 1, 1e-5,
                          nullptr, tags);
  EXPECT_EQ(s.nonfinite, 3);
  EXPECT_EQ(s.first_nonfinite, 1);
  EXPECT_EQ(s.first_kind, NonFinite::Velocity);
  // forces only: the smallest tag, not the first index
  a.vs[1][2] = 0.0;
  a.fs[1][2] = std::numeric_limits<double>::infinity();
  s = scan_atoms(3, a.x.data(), a.v.data(), a.f.data(), a.r.data(), a.mask.data(), 1, 1e-5, nullptr,
                 tags);
  EXPECT_EQ(s.first_nonfinite, 2);
  EXPECT_EQ(s.first_kind, NonFinite::Force);
  // a position is named as such, before the velocity of the same atom
  a.xs[0][1] = std::numeric_limits<double>::infinity();
  a.vs[0][1] = std::numeric_limits<double>::quiet_NaN();
  s = scan_atoms(3, a.x.data(), a.v.data(), a.f.data(), a.r.data(), a.mask.data(), 1, 1e-5, nullptr,
                 tags);
  EXPECT_EQ(s.first_nonfinite, 0);
  EXPECT_EQ(s.first_kind, NonFinite::Position);
}

TEST(ScanAtoms, EqualStepFractionsNameTheSmallestTag)
{
  Atoms a(3);
  const int tags[3] = {8, 2, 5};
  for (auto &v : a.vs) v = {0.0, 0.0, 3.0}; // all alike: 0.03
  const AtomScan s = scan_atoms(3, a.x.data(), a.v.data(), a.f.data(), a.r.data(), a.mask.data(), 1,
                                1e-5, nullptr, tags);
  EXPECT_EQ(s.argmax_step, 1);
  EXPECT_NEAR(s.max_step_fraction, 0.03, 1e-15);
}

TEST(ScanAtoms, RadiusOrMassThatIsNotPositiveIsAnInputFault)
{
  // a zero radius would make |v| dt / r infinite (a moving sphere) or NaN (at
  // rest): counted apart and left out of the largest step fraction
  Atoms a(4);
  const int tags[4] = {4, 3, 2, 1};
  std::vector<double> mass(4, 1e-6);
  a.vs[0] = {1.0, 0.0, 0.0}; // 0.01
  a.r[1] = 0.0;
  a.vs[1] = {0.0, 0.0, 1.0};
  mass[2] = 0.0; // density 0
  a.r[3] = std::numeric_limits<double>::quiet_NaN();
  a.mask[3] = 0; // outside the group: ignored
  AtomScan s = scan_atoms(4, a.x.data(), a.v.data(), a.f.data(), a.r.data(), a.mask.data(), 1, 1e-5,
                          mass.data(), tags);
  EXPECT_EQ(s.bad_size, 2);
  EXPECT_EQ(s.first_bad_size, 2); // tag 2 < tag 3
  EXPECT_EQ(s.argmax_step, 0);
  EXPECT_NEAR(s.max_step_fraction, 0.01, 1e-15);
  // without per-atom masses only the radius is checked
  s = scan_atoms(4, a.x.data(), a.v.data(), a.f.data(), a.r.data(), a.mask.data(), 1, 1e-5);
  EXPECT_EQ(s.bad_size, 1);
  EXPECT_EQ(s.first_bad_size, 1);
}

TEST(ScanAtoms, EmptyGroup)
{
  Atoms a(2);
  a.mask = {0, 0};
  const AtomScan s = a.scan(1e-5);
  EXPECT_EQ(s.argmax_step, -1);
  EXPECT_EQ(s.max_step_fraction, 0.0);
}

TEST(JudgeStepFraction, AgainstTheLimitAndTheBlowUp)
{
  // the default limit is the blow-up fraction 0.05: only a blown-up run is stopped
  EXPECT_EQ(judge_step_fraction(0.05, 0.05), StepVerdict::Within); // not above: within
  EXPECT_EQ(judge_step_fraction(0.051, 0.05), StepVerdict::BlownUp);
  // a stricter limit stops a run that need not be unstable
  EXPECT_EQ(judge_step_fraction(0.02, 1e-9), StepVerdict::AboveLimit);
  EXPECT_EQ(judge_step_fraction(0.05, 0.01), StepVerdict::AboveLimit); // 0.05 is not > 0.05
  EXPECT_EQ(judge_step_fraction(0.1, 0.01), StepVerdict::BlownUp);
  // a looser limit lets a fast disk through
  EXPECT_EQ(judge_step_fraction(0.5, 1.0), StepVerdict::Within);
  EXPECT_EQ(judge_step_fraction(0.0, 0.05), StepVerdict::Within);
}

namespace {

// disks at x[i] with radii r[i] and a full neighbour list given as pairs
struct Contacts {
  Contacts(std::vector<std::array<double, 3>> centres, std::vector<double> radii,
           std::vector<std::vector<int>> neighbours)
    : xs(std::move(centres)), r(std::move(radii)), lists(std::move(neighbours)), mask(r.size(), 1)
  {
    for (auto &c : xs) x.push_back(c.data());
    for (std::size_t i = 0; i < lists.size(); i++) {
      ilist.push_back(static_cast<int>(i));
      numneigh.push_back(static_cast<int>(lists[i].size()));
      first.push_back(lists[i].data());
    }
  }
  std::vector<std::array<double, 3>> xs;
  std::vector<double *> x;
  std::vector<double> r;
  std::vector<std::vector<int>> lists;
  std::vector<int> mask, ilist, numneigh;
  std::vector<int *> first;
  OverlapScan scan(int neighmask = ~0, const int *tag = nullptr) const
  {
    return scan_overlaps(static_cast<int>(ilist.size()), ilist.data(), numneigh.data(),
                         first.data(), neighmask, x.data(), r.data(), mask.data(), 1, tag);
  }
};

} // namespace

TEST(ScanOverlaps, LargestOverlapOfTheGroup)
{
  // radius 1 mm each; 0-1 at 1.9 mm: (2 - 1.9) / 1 = 0.1; 1-2 at 1.7 mm: 0.3; 2-3 apart (2.5 mm)
  Contacts c({{0, 0, 0}, {1.9e-3, 0, 0}, {3.6e-3, 0, 0}, {6.1e-3, 0, 0}}, {1e-3, 1e-3, 1e-3, 1e-3},
             {{1}, {2}, {3}, {}});
  OverlapScan s = c.scan();
  EXPECT_NEAR(s.max_fraction, 0.3, 1e-12);
  EXPECT_EQ(s.i, 1);
  EXPECT_EQ(s.j, 2);
  // atom 2 outside the group: the 0-1 pair is the largest left
  c.mask[2] = 2;
  s = c.scan();
  EXPECT_NEAR(s.max_fraction, 0.1, 1e-12);
  EXPECT_EQ(s.i, 0);
  EXPECT_EQ(s.j, 1);
}

TEST(ScanOverlaps, EqualOverlapsNameTheSmallestPairOfTags)
{
  // 1, 2 and 3 around 0 at 1.9 mm (x, y, -y): equal overlaps 0.1; tags 7, 9, 3, 1 give the
  // pairs (7, 9), (3, 7), (1, 7): the smallest, (1, 7), whatever the list order
  Contacts c({{0, 0, 0}, {1.9e-3, 0, 0}, {0, 1.9e-3, 0}, {0, -1.9e-3, 0}}, {1e-3, 1e-3, 1e-3, 1e-3},
             {{1, 2, 3}, {}, {}, {}});
  const int tags[4] = {7, 9, 3, 1};
  const OverlapScan s =
      scan_overlaps(static_cast<int>(c.ilist.size()), c.ilist.data(), c.numneigh.data(),
                    c.first.data(), ~0, c.x.data(), c.r.data(), c.mask.data(), 1, tags);
  EXPECT_NEAR(s.max_fraction, 0.1, 1e-12);
  EXPECT_EQ(s.i, 0);
  EXPECT_EQ(s.j, 3);
  EXPECT_EQ(pair_key(7, 1), (1LL << 32) | 7);
  // without tags: the first found
  EXPECT_EQ(c.scan().j, 1);
}

TEST(ScanOverlaps, SpheresStackedAlongZ)
{
  // radius 1 mm each, 0-1 at 1.9 mm along x (0.1) and 0-2 at 1.6 mm along z (0.4): a
  // measure in the xy plane alone would see 0-2 as the same point (overlap 2)
  Contacts c({{0, 0, 0}, {1.9e-3, 0, 0}, {0, 0, 1.6e-3}}, {1e-3, 1e-3, 1e-3}, {{1, 2}, {}, {}});
  const OverlapScan s = c.scan();
  EXPECT_NEAR(s.max_fraction, 0.4, 1e-12);
  EXPECT_EQ(s.i, 0);
  EXPECT_EQ(s.j, 2);
}

TEST(ScanOverlaps, NeighbourMaskAndNoContact)
{
  // special-bond bits above the mask are stripped: 1 | (1 << 30) is neighbour 1;
  // radii 1 and 0.5 mm 1.4 mm apart: 0.1 mm / 0.5 mm = 0.2
  Contacts c({{0, 0, 0}, {1.4e-3, 0, 0}}, {1e-3, 0.5e-3}, {{1 | (1 << 30)}, {}});
  OverlapScan s = c.scan(0x3FFFFFFF);
  EXPECT_NEAR(s.max_fraction, 0.2, 1e-12);
  EXPECT_EQ(s.i, 0);
  EXPECT_EQ(s.j, 1);
  // 1.6 mm apart, a gap of 0.1 mm: no overlap, nothing found
  c.xs[1][0] = 1.6e-3;
  s = c.scan(0x3FFFFFFF);
  EXPECT_EQ(s.max_fraction, 0.0);
  EXPECT_EQ(s.i, -1);
  EXPECT_EQ(s.j, -1);
}

TEST(WarnOnceNow, AboveTheLimitTheFirstTime)
{
  EXPECT_TRUE(warn_once_now(0.2, 0.1, false));
  EXPECT_FALSE(warn_once_now(0.2, 0.1, true));  // warned before
  EXPECT_FALSE(warn_once_now(0.1, 0.1, false)); // at the limit is within
  EXPECT_FALSE(warn_once_now(0.05, 0.1, false));
  EXPECT_FALSE(warn_once_now(std::numeric_limits<double>::quiet_NaN(), 0.1, false));
}

TEST(CheckInertialNumber, ValidInputsGiveTheNumber)
{
  // as InertialNumber.HandWorked: 0.01 /s, 1.75 mm, 2e8, 1e5 Pa -> 7.82624e-4
  const InertialCheck c = check_inertial_number(0.01, 1e5, 1.75e-3, 2e8);
  EXPECT_EQ(c.status, InertialStatus::Ok);
  EXPECT_NEAR(c.value, 7.82624e-4, 1e-9);
  EXPECT_EQ(check_inertial_number(0.0, 1e5, 1.75e-3, 2e8).status, InertialStatus::Ok);
  EXPECT_EQ(check_inertial_number(0.0, 1e5, 1.75e-3, 2e8).value, 0.0);
}

TEST(CheckInertialNumber, WhatIsWrongWithRAndP)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (double rate : {-0.01, nan, inf, -inf})
    EXPECT_EQ(check_inertial_number(rate, 1e5, 1e-3, 2e8).status, InertialStatus::BadRate);
  for (double pressure : {0.0, -1e5, nan, inf, -inf})
    EXPECT_EQ(check_inertial_number(0.01, pressure, 1e-3, 2e8).status, InertialStatus::BadPressure);
  // the rate is judged first
  EXPECT_EQ(check_inertial_number(-1.0, 0.0, 1e-3, 2e8).status, InertialStatus::BadRate);
  // R = 1, P = 1e-300: 1 * 1e-3 * sqrt(2e8 / 1e-300) = sqrt(2e308) overflows
  const InertialCheck c = check_inertial_number(1.0, 1e-300, 1e-3, 2e8);
  EXPECT_EQ(c.status, InertialStatus::Overflow);
  EXPECT_EQ(c.value, 0.0);
}
