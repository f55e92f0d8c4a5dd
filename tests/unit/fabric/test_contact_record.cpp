// The contact record the ranks exchange (contact_record.h): packing with the
// smaller tag first, the order of the gathered list, and the contact of a record.
#include "contact_record.h"

#include <gtest/gtest.h>

#include <vector>

namespace {

using fabric::ContactRecord;

std::vector<double> concatenated(const std::vector<ContactRecord> &records)
{
  std::vector<double> out;
  for (const ContactRecord &r : records) out.insert(out.end(), r.begin(), r.end());
  return out;
}

// a record of tags (a, b) whose other fields say which one it is
ContactRecord tagged(double a, double b, double marker)
{
  return {a, b, marker, 0, 0, 0, 0, 0, 1};
}

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

TEST(OrderByTags, ByTagAThenTagBWallsLast)
{
  const std::vector<double> records =
      concatenated({tagged(5, 9, 0), tagged(2, -1, 1), tagged(2, 8, 2), tagged(2, 3, 3),
                    tagged(5, -1, 4), tagged(1, 2147483647, 5)});
  const std::vector<int> expected = {5, 3, 2, 1, 0, 4};
  EXPECT_EQ(fabric::order_by_tags(records), expected);
}

// a particle touching two mesh triangles: the same tags twice
TEST(OrderByTags, EqualTagsKeepTheirOrder)
{
  const std::vector<double> records =
      concatenated({tagged(4, -1, 0), tagged(3, 4, 1), tagged(4, -1, 2), tagged(4, -1, 3)});
  const std::vector<int> expected = {1, 0, 2, 3};
  EXPECT_EQ(fabric::order_by_tags(records), expected);
}

TEST(OrderByTags, NoRecords)
{
  EXPECT_TRUE(fabric::order_by_tags({}).empty());
}

// Force on a (1, -2), so on b (-1, 2); n = (0, 1), t = (-1, 0): fn = 2, ft = 1.
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
