// Geometrical stability index (doc/compute_fabric.md): its worked values plus
// invariances that any correct implementation must have.
#include "stability_index.h"

#include "particle_contacts.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace {

constexpr double kPi = 3.141592653589793238462643383280;
constexpr double kTol = 1e-12;

std::vector<double> radians(const std::vector<double> &degrees)
{
  std::vector<double> out;
  for (double d : degrees) out.push_back(d * kPi / 180.0);
  return out;
}

double gsi_deg(const std::vector<double> &degrees)
{
  return fabric::stability_index(radians(degrees));
}

// ---- the worked values of doc/compute_fabric.md -------------------------------

TEST(StabilityIndex, ThreeEvenlySpacedContactsAreFullyStable)
{
  EXPECT_NEAR(gsi_deg({0, 120, 240}), 0.0, kTol);
}

TEST(StabilityIndex, TwoContactsAtRightAngleGiveAQuarter)
{
  EXPECT_NEAR(gsi_deg({0, 90}), 0.25, kTol);
}

TEST(StabilityIndex, ThreeContactsOnAHalfCircleGiveSixtyOverThreeSixty)
{
  EXPECT_NEAR(gsi_deg({0, 90, 180}), 60.0 / 360.0, kTol);
}

TEST(StabilityIndex, HexagonalPackingIsFullyStable)
{
  EXPECT_NEAR(gsi_deg({0, 60, 120, 180, 240, 300}), 0.0, kTol);
  EXPECT_NEAR(gsi_deg({30, 90, 150, 210, 270, 330}), 0.0, kTol);
}

// ---- hand-worked cases ------------------------------------------------------

// Contacts 350, 10, 200 deg -> sorted 10, 200, 350; even spacing 120 deg.
//   anchor 10 : ideals 10, 130, 250 vs 10, 200, 350 -> 0 + 70 + 100 = 170
//   anchor 200: ideals 200, 320, 80 vs 200, 350, 10 -> 0 + 30 +  70 = 100
//   anchor 350: ideals 350, 110, 230 vs 350, 10, 200 -> 0 + 100 + 30 = 130
// D = 100 deg, lambda = 100/360 = 5/18. Matching wraps past 360 for two anchors.
TEST(StabilityIndex, HandWorkedCaseAcrossZero)
{
  EXPECT_NEAR(gsi_deg({350, 10, 200}), 100.0 / 360.0, kTol);
}

// Five contacts 72 deg apart, one moved by 7 deg (order unchanged). Anchoring at
// an unmoved contact leaves a single misfit of 7 deg; anchoring at the moved one
// misfits the other four by 7 deg each (28). D = 7 deg.
TEST(StabilityIndex, OneDisplacedContactCostsItsDisplacement)
{
  EXPECT_NEAR(gsi_deg({0, 72, 144 + 7, 216, 288}), 7.0 / 360.0, kTol);
}

// Two contacts at the same point: the best ideal partner is 180 deg away, so
// D = 180 deg and lambda = 0.5, the largest value two contacts can give.
TEST(StabilityIndex, CoincidentPairGivesOneHalf)
{
  EXPECT_NEAR(gsi_deg({40, 40}), 0.5, kTol);
}

// ---- invariances and edge cases ---------------------------------------------

TEST(StabilityIndex, NoOrOneContactIsUnstable)
{
  EXPECT_EQ(fabric::stability_index({}), 1.0);
  EXPECT_EQ(fabric::stability_index({1.234}), 1.0);
}

TEST(StabilityIndex, AcceptsAnglesInAnyRange)
{
  EXPECT_NEAR(gsi_deg({-120, 0, 120}), 0.0, kTol);
  EXPECT_NEAR(gsi_deg({360, 480, 600}), 0.0, kTol);
  EXPECT_NEAR(gsi_deg({-360, 90 - 720}), 0.25, kTol);
}

TEST(StabilityIndex, InvariantUnderRotation)
{
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> angle(0.0, 2.0 * kPi);
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<double> contacts(2 + trial % 6);
    for (double &c : contacts) c = angle(rng);
    const double reference = fabric::stability_index(contacts);
    for (double shift : {-7.0, -1.0, 0.3, 2.0 * kPi, 11.0}) {
      std::vector<double> rotated = contacts;
      for (double &c : rotated) c += shift;
      EXPECT_NEAR(fabric::stability_index(rotated), reference, 1e-12);
    }
  }
}

TEST(StabilityIndex, InvariantUnderContactOrder)
{
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> angle(-10.0, 10.0);
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<double> contacts(2 + trial % 7);
    for (double &c : contacts) c = angle(rng);
    const double reference = fabric::stability_index(contacts);
    for (int shuffle = 0; shuffle < 5; ++shuffle) {
      std::shuffle(contacts.begin(), contacts.end(), rng);
      EXPECT_NEAR(fabric::stability_index(contacts), reference, 1e-12);
    }
  }
}

// lambda is not bounded by 1: six coincident contacts misfit by
// 0 + 60 + 120 + 180 + 120 + 60 = 540 deg, lambda = 1.5. So the value 1 given to
// particles with 0 or 1 contact is a convention, not the worst case.
TEST(StabilityIndex, ClusteredContactsCanExceedOne)
{
  EXPECT_NEAR(gsi_deg({0, 0, 0, 0, 0, 0}), 1.5, kTol);
}

TEST(StabilityIndex, IsNonNegativeAndFinite)
{
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> angle(0.0, 2.0 * kPi);
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<double> contacts(2 + trial % 9);
    for (double &c : contacts) c = angle(rng);
    const double lambda = fabric::stability_index(contacts);
    EXPECT_TRUE(std::isfinite(lambda));
    EXPECT_GE(lambda, 0.0);
  }
}

// A contact without a normal (coincident centres) has a NaN angle: it has no
// place on the circle and is left out, never turning lambda into NaN or inf.
TEST(StabilityIndex, NonFiniteAnglesAreLeftOut)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> three = radians({0, 120, 240});
  three.push_back(nan);
  EXPECT_NEAR(fabric::stability_index(three), 0.0, kTol);
  EXPECT_EQ(fabric::stability_index({0.0, nan}), 1.0); // one contact with a place
  EXPECT_EQ(fabric::stability_index({nan, inf, -inf}), 1.0);
  std::vector<double> quarter = radians({0, 90});
  quarter.insert(quarter.begin() + 1, nan);
  EXPECT_NEAR(fabric::stability_index(quarter), 0.25, kTol);
}

// ---- sample mean (compute fabric's vector entry 13) ---------------------------

// Particle 1: contacts at 0 and 90 deg (lambda 1/4); 2: at 0, 120, 240 (0);
// 3: one contact (a rattler); 4: two contacts, one without a normal (1).
fabric::ParticleContacts four_particles()
{
  fabric::ParticleContacts p;
  p.tags = {1, 2, 3, 4};
  p.first_contact_of = {0, 2, 5, 6, 8};
  const double nan = std::numeric_limits<double>::quiet_NaN();
  p.angles = {0.0, kPi / 2, 0.0, 2 * kPi / 3, 4 * kPi / 3, 0.0, 0.0, nan};
  return p;
}

TEST(MeanStabilityIndex, OverParticlesWithTwoOrMoreContacts)
{
  // (1/4 + 0 + 1) / 3; particle 3 and the 6 - 4 without contacts are left out
  EXPECT_NEAR(fabric::mean_stability_index(four_particles(), 6, false), 1.25 / 3, kTol);
}

TEST(MeanStabilityIndex, RattlersCountAsOne)
{
  // (1/4 + 0 + 1 + 3 rattlers: particle 3 and the two without contacts) / 6
  EXPECT_NEAR(fabric::mean_stability_index(four_particles(), 6, true), 4.25 / 6, kTol);
}

TEST(MeanStabilityIndex, ZeroWhenNoParticleQualifies)
{
  fabric::ParticleContacts one_contact;
  one_contact.tags = {7};
  one_contact.first_contact_of = {0, 1};
  one_contact.angles = {0.0};
  EXPECT_EQ(fabric::mean_stability_index(one_contact, 1, false), 0.0);
  EXPECT_EQ(fabric::mean_stability_index(one_contact, 1, true), 1.0);
  EXPECT_EQ(fabric::mean_stability_index(fabric::ParticleContacts{}, 0, true), 0.0);
}

} // namespace
