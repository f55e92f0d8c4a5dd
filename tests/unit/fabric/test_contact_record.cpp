// The contact record (contact_record.h): packing with the smaller tag first,
// and the contact of a record.
#include "contact_record.h"

#include <gtest/gtest.h>

#include <vector>

namespace {

using fabric::ContactRecord;

TEST(PairRecord, SmallerTagFirstIsKept)
{
  const double xi[2] = {1, 2}, xj[2] = {4, 6}, f[2] = {0.5, -1.5};
  const ContactRecord expected = {3, 7, 1, 2, 4, 6, 0.5, -1.5, 2};
  EXPECT_EQ(fabric::pair_record(3, 7, xi, xj, f, 2.0), expected);
}

// The same contact reported from particle 7's side (force on 7 = minus the
// force on 3) gives the same record.
TEST(PairRecord, LargerTagFirstSwapsTheEndsAndTurnsTheForceRound)
{
  const double xi[2] = {4, 6}, xj[2] = {1, 2}, f[2] = {-0.5, 1.5};
  const ContactRecord expected = {3, 7, 1, 2, 4, 6, 0.5, -1.5, 2};
  EXPECT_EQ(fabric::pair_record(7, 3, xi, xj, f, 2.0), expected);
}

TEST(WallRecord, WallIsTagMinusOneAtTheContactPoint)
{
  const double centre[2] = {1, 2}, point[2] = {1, 3}, f[2] = {0, -4};
  const ContactRecord expected = {5, -1, 1, 2, 1, 3, 0, -4, 0.5};
  EXPECT_EQ(fabric::wall_record(5, centre, point, f, 0.5), expected);
}

TEST(RecordContact, ForceOnBIsMinusTheRecordedForceOnA)
{
  const ContactRecord rec = {3, 7, 0, 0, 0, 1.5, 1, -2, 2};
  const fabric::Contact k = fabric::record_contact(rec.data(), 0.0, 1.5);
  EXPECT_EQ(k.a, 3);
  EXPECT_EQ(k.b, 7);
  EXPECT_EQ(k.nx, 0.0);
  EXPECT_EQ(k.ny, 1.0);
  EXPECT_EQ(k.fn, 2.0);
  EXPECT_EQ(k.ft, 1.0);
  EXPECT_EQ(k.lx, 0.0);
  EXPECT_EQ(k.ly, 1.5);
}

// The branch vector is the caller's (here a periodic image), not xb - xa.
TEST(RecordContact, UsesTheGivenBranchVectorAndKeepsTheWall)
{
  const ContactRecord rec = {5, -1, 0.9, 0, 0.1, 0, 3, 0, 0.2};
  const fabric::Contact k = fabric::record_contact(rec.data(), 0.2, 0.0);
  EXPECT_EQ(k.b, -1);
  EXPECT_EQ(k.nx, 1.0);
  EXPECT_EQ(k.fn, -3.0);
  EXPECT_EQ(k.lx, 0.2);
}

// In 3D: the same contact seen from either end is the same contact; the force
// on b is minus the force on a.
TEST(PairContact3, EitherEndGivesTheSameContact)
{
  const double l_37[3] = {0, 0.6, 0.8}, l_73[3] = {0, -0.6, -0.8};
  const double f_on_3[3] = {1, -3, -4}, f_on_7[3] = {-1, 3, 4};
  for (const fabric::Contact3 &k : {fabric::pair_contact3(3, 7, l_37, f_on_3, 1.0),
                                    fabric::pair_contact3(7, 3, l_73, f_on_7, 1.0)}) {
    EXPECT_EQ(k.a, 3);
    EXPECT_EQ(k.b, 7);
    EXPECT_NEAR(k.n.y(), 0.6, 1e-15);
    EXPECT_NEAR(k.n.z(), 0.8, 1e-15);
    EXPECT_NEAR(k.fn, 5.0, 1e-14); // (-1, 3, 4) . (0, 0.6, 0.8)
    EXPECT_NEAR(k.ft.x(), -1.0, 1e-15);
    EXPECT_NEAR(k.l.z(), 0.8, 1e-15);
  }
}

TEST(WallContact3, WallIsTagMinusOneAndPushedByTheParticle)
{
  const double l[3] = {0, 0, -0.5}, f_on_particle[3] = {0, 0, 4};
  const fabric::Contact3 k = fabric::wall_contact3(5, l, f_on_particle, 0.5);
  EXPECT_EQ(k.a, 5);
  EXPECT_EQ(k.b, -1);
  EXPECT_EQ(k.n, Eigen::Vector3d(0, 0, -1));
  EXPECT_EQ(k.fn, 4.0);
  EXPECT_EQ(k.l, Eigen::Vector3d(0, 0, -0.5));
}

} // namespace
