// The halo's plan (member_halo_plan.h): the members within k rings, hand-worked on a
// strip of triangles, and the send lists of every rank equal to the receive lists of
// their receivers.
#include "member_halo_plan.h"

#include <gtest/gtest.h>

#include <stdexcept>

using membrane::HaloPlan;
using membrane::MemberCells;

namespace {

// A strip of triangles over members 0..n-1: (0 1 2), (1 2 3), (2 3 4), ...; member m
// shares a cell with m-2 .. m+2.
MemberCells strip(int n)
{
  std::vector<int> cells;
  for (int m = 0; m + 2 < n; ++m) cells.insert(cells.end(), {m, m + 1, m + 2});
  return {static_cast<std::size_t>(n), cells, 3};
}

} // namespace

TEST(MemberCells, RingsOfAStrip)
{
  const MemberCells cells = strip(12);
  EXPECT_EQ(cells.within({5}, 0), (std::vector<int>{5}));
  EXPECT_EQ(cells.within({5}, 1), (std::vector<int>{3, 4, 5, 6, 7}));
  EXPECT_EQ(cells.within({5}, 2), (std::vector<int>{1, 2, 3, 4, 5, 6, 7, 8, 9}));
  EXPECT_EQ(cells.within({0, 11}, 1), (std::vector<int>{0, 1, 2, 9, 10, 11}));
  EXPECT_EQ(cells.cells_on({0}), (std::vector<int>{0}));
  EXPECT_EQ(cells.cells_on({5}), (std::vector<int>{3, 4, 5}));
}

TEST(MemberCells, RepeatedMemberInACellCountsOnce)
{
  // a sphere and its image in one facet
  const MemberCells cells(3, {0, 0, 1, 1, 2, 0}, 3);
  EXPECT_EQ(std::vector<int>(cells.cells_begin(0), cells.cells_end(0)), (std::vector<int>{0, 1}));
  EXPECT_EQ(cells.within({2}, 1), (std::vector<int>{0, 1, 2}));
}

TEST(MemberCells, IndexOutOfRangeThrows)
{
  EXPECT_THROW(MemberCells(2, {0, 1, 2}, 3), std::invalid_argument);
  EXPECT_THROW(MemberCells(3, {0, 1}, 3), std::invalid_argument);
}

// Three ranks own blocks of four: rank 1 (members 4..7) needs 2..9 at one ring, gets 2, 3
// from rank 0 and 8, 9 from rank 2; every send list is its receiver's receive list.
TEST(HaloPlan, SendListsAreTheReceiversLists)
{
  const MemberCells cells = strip(12);
  std::vector<int> owner(12);
  for (int m = 0; m < 12; ++m) owner[m] = m / 4;
  std::vector<HaloPlan> plan;
  for (int r = 0; r < 3; ++r) plan.push_back(membrane::plan_halo(cells, owner, r, 1));
  EXPECT_EQ(plan[1].owned, (std::vector<int>{4, 5, 6, 7}));
  EXPECT_EQ(plan[1].needed, (std::vector<int>{2, 3, 4, 5, 6, 7, 8, 9}));
  EXPECT_EQ(plan[1].from, (std::vector<int>{0, 2}));
  EXPECT_EQ(plan[1].recv[0], (std::vector<int>{2, 3}));
  EXPECT_EQ(plan[1].recv_slot[0], (std::vector<int>{0, 1}));
  EXPECT_EQ(plan[1].recv[1], (std::vector<int>{8, 9}));
  EXPECT_EQ(plan[1].own_slot, (std::vector<int>{2, 3, 4, 5}));
  EXPECT_EQ(plan[0].to, (std::vector<int>{1}));
  EXPECT_EQ(plan[0].send[0], (std::vector<int>{2, 3}));
  EXPECT_EQ(plan[0].send_slot[0], (std::vector<int>{2, 3}));
  for (int s = 0; s < 3; ++s)
    for (std::size_t k = 0; k < plan[s].to.size(); ++k) {
      const HaloPlan &r = plan[plan[s].to[k]];
      std::size_t j = 0;
      while (j < r.from.size() && r.from[j] != s) ++j;
      ASSERT_LT(j, r.from.size());
      EXPECT_EQ(plan[s].send[k], r.recv[j]);
    }
  // at two rings rank 1 needs all twelve
  EXPECT_EQ(membrane::plan_halo(cells, owner, 1, 2).needed.size(), 12u);
}

// A member no rank owns is reported missing, never expected from a rank.
TEST(HaloPlan, LostMemberIsMissing)
{
  const MemberCells cells = strip(8);
  std::vector<int> owner{0, 0, 0, 0, -1, 1, 1, 1};
  const HaloPlan plan = membrane::plan_halo(cells, owner, 0, 1);
  EXPECT_EQ(plan.missing, (std::vector<int>{4}));
  EXPECT_EQ(plan.from, (std::vector<int>{1}));
  EXPECT_EQ(plan.recv[0], (std::vector<int>{5}));
}
