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

} // namespace
