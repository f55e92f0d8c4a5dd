// The contacts of each particle (particle_contacts.h) on a hand-made list:
// 1-2 along +x, 1-3 along +y, 2 with a wall below, 3-5 with coincident centres.
#include "particle_contacts.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace {

using fabric::Contact;

constexpr double kPi = 3.141592653589793238462643383280;

std::vector<Contact> four_contacts()
{
  return {Contact{1, 2, 1, 0, 1, 0, 2, 0}, Contact{1, 3, 0, 1, 1, 0, 0, 2},
          Contact{2, -1, 0, -1, 1, 0, 0, -1}, Contact{3, 5, 0, 0, 0, 0, 0, 0}};
}

TEST(ParticleContacts, GroupedByTagInContactOrder)
{
  const fabric::ParticleContacts p = fabric::particle_contacts(four_contacts());
  EXPECT_EQ(p.tags, (std::vector<long>{1, 2, 3, 5}));
  EXPECT_EQ(p.first_contact_of, (std::vector<int>{0, 2, 4, 6, 7}));
  ASSERT_EQ(p.angles.size(), 7u);
  EXPECT_EQ(p.angles[0], 0.0);              // 1 -> 2
  EXPECT_DOUBLE_EQ(p.angles[1], kPi / 2);   // 1 -> 3
  EXPECT_DOUBLE_EQ(p.angles[2], kPi);       // 2 -> 1: theta + pi
  EXPECT_DOUBLE_EQ(p.angles[3], -kPi / 2);  // 2 -> wall
  EXPECT_DOUBLE_EQ(p.angles[4], 1.5 * kPi); // 3 -> 1
  EXPECT_TRUE(std::isnan(p.angles[5]));     // 3 -> 5: no normal
  EXPECT_TRUE(std::isnan(p.angles[6]));     // 5 -> 3
}

TEST(ParticleContacts, AnglesOfATag)
{
  const fabric::ParticleContacts p = fabric::particle_contacts(four_contacts());
  const std::vector<double> two = p.angles_of(2);
  ASSERT_EQ(two.size(), 2u);
  EXPECT_DOUBLE_EQ(two[0], kPi);
  EXPECT_DOUBLE_EQ(two[1], -kPi / 2);
  EXPECT_EQ(p.angles_of(5).size(), 1u);
  EXPECT_TRUE(p.angles_of(4).empty()); // between tags with contacts
  EXPECT_TRUE(p.angles_of(0).empty());
  EXPECT_TRUE(p.angles_of(9).empty());
}

TEST(ParticleContacts, CountsThenZerosForParticlesWithoutContacts)
{
  const fabric::ParticleContacts p = fabric::particle_contacts(four_contacts());
  EXPECT_EQ(fabric::contact_counts(p, 6), (std::vector<int>{2, 2, 2, 1, 0, 0}));
  EXPECT_EQ(fabric::contact_counts(p, 4), (std::vector<int>{2, 2, 2, 1}));
}

TEST(ParticleContacts, NoContacts)
{
  const fabric::ParticleContacts p = fabric::particle_contacts({});
  EXPECT_TRUE(p.tags.empty());
  EXPECT_EQ(p.first_contact_of, std::vector<int>{0});
  EXPECT_TRUE(p.angles_of(1).empty());
  EXPECT_EQ(fabric::contact_counts(p, 3), (std::vector<int>{0, 0, 0}));
  EXPECT_TRUE(fabric::contact_counts(p, 0).empty());
}

} // namespace
