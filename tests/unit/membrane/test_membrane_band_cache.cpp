// BandCandidates (membrane_band_cache.h) on a square block of 20 x 20 unit
// disks (r = 0.5, centres at x, y = 0.5 ... 19.5) between platens at y = 0
// and 20, band width 2 (10 slices of height 2), margin 2: by hand, the left
// band reaches x - r <= 2 and the candidates x - r <= 4 (columns 0-4), the
// right band x + r >= 18 and the candidates x + r >= 16 (columns 15-19); the
// others (columns 5-14) have x - r >= 5 and x + r <= 15.
#include "membrane_band_cache.h"

#include <gtest/gtest.h>

#include <vector>

using membrane::BandCandidates;
using membrane::BandDisk;
using membrane::BandSlices;
using membrane::Platens;
using membrane::Side;

namespace {

constexpr double kWidth = 2.0, kMargin = 2.0;

std::vector<BandDisk> block()
{
  std::vector<BandDisk> disks;
  for (int row = 0; row < 20; ++row)
    for (int col = 0; col < 20; ++col)
      disks.push_back({20 * row + col, col + 0.5, row + 0.5, 0.5});
  return disks;
}

// slices of the block with every extent set (left: smallest x - r, right: largest x + r)
BandSlices slices(Side side, const std::vector<double> &extents)
{
  BandSlices s;
  s.reset(side, Platens{0.0, 20.0}, kWidth);
  s.extents() = extents;
  s.finish();
  return s;
}

BandSlices left(double extent) { return slices(Side::Left, std::vector<double>(10, extent)); }
BandSlices right(double extent) { return slices(Side::Right, std::vector<double>(10, extent)); }

BandCandidates built(double motion)
{
  BandCandidates c;
  const BandSlices l = left(0.0), r = right(20.0);
  c.build(block(), &l, &r, kWidth, kMargin, motion, -1.0, 21.0);
  return c;
}

} // namespace

TEST(BandCandidates, TheDisksWithinBandAndMarginOfEitherSide)
{
  const BandCandidates c = built(0.1);
  ASSERT_EQ(c.candidates().size(), 200u); // columns 0-4 and 15-19 of 20 rows
  for (int index : c.candidates()) {
    const int col = index % 20;
    EXPECT_TRUE(col <= 4 || col >= 15) << index;
  }
}

TEST(BandCandidates, CoverTheBandsWhileTheOthersCannotReachThem)
{
  const BandCandidates c = built(0.1);
  const BandSlices l = left(0.0), r = right(20.0);
  EXPECT_TRUE(c.still_covers(&l, &r));
  EXPECT_TRUE(c.still_covers(&l, nullptr));
  // the left edge moved in by 2.8: the band reaches 4.8 < 5 - 0.1
  const BandSlices in28 = left(2.8);
  EXPECT_TRUE(c.still_covers(&in28, &r));
  // by 3.0: it reaches 5.0, and a non-candidate may have moved to 4.9
  const BandSlices in30 = left(3.0);
  EXPECT_FALSE(c.still_covers(&in30, &r));
  // right: edge in from 20 to 17.2 reaches 15.2 > 15 + 0.1; to 17.0: 15.0
  const BandSlices r172 = right(17.2), r170 = right(17.0);
  EXPECT_TRUE(c.still_covers(&l, &r172));
  EXPECT_FALSE(c.still_covers(&l, &r170));
}

TEST(BandCandidates, TheMotionBoundCountsInFull)
{
  const BandSlices l = left(0.0), r = right(20.0);
  EXPECT_TRUE(built(2.9).still_covers(&l, &r));  // 5 - 2.9 = 2.1 > 2
  EXPECT_FALSE(built(3.1).still_covers(&l, &r)); // 1.9 < 2
}

TEST(BandCandidates, ASliceEdgeFromItsNeighboursOrItsOwnExtent)
{
  const BandCandidates c = built(0.1);
  const BandSlices r = right(20.0);
  // slice 5 alone deeper (extent 4.5): its band reaches max(4.5, 0 + 2) = 4.5 < 4.9
  std::vector<double> e(10, 0.0);
  e[5] = 4.5;
  const BandSlices notch = slices(Side::Left, e);
  EXPECT_TRUE(c.still_covers(&notch, &r));
  // slice 5 at 4.95: a non-candidate at 4.9 would be its outermost disk
  e[5] = 4.95;
  const BandSlices deeper = slices(Side::Left, e);
  EXPECT_FALSE(c.still_covers(&deeper, &r));
  // slices 4-6 at 3: the edge near slice 5 is 3, its band reaches 5
  e = std::vector<double>(10, 0.0);
  e[4] = e[5] = e[6] = 3.0;
  const BandSlices wide = slices(Side::Left, e);
  EXPECT_FALSE(c.still_covers(&wide, &r));
}

TEST(BandCandidates, AnEmptySliceOrNoBuildNeverCovers)
{
  const BandCandidates c = built(0.1);
  const BandSlices r = right(20.0);
  std::vector<double> e(10, 0.0);
  BandSlices probe;
  probe.reset(Side::Left, Platens{0.0, 20.0}, kWidth);
  e[7] = probe.extents()[7]; // the empty value of a slice no disk reached
  const BandSlices empty = slices(Side::Left, e);
  EXPECT_FALSE(c.still_covers(&empty, &r));
  BandCandidates none;
  const BandSlices l = left(0.0);
  EXPECT_FALSE(none.still_covers(&l, &r));
  BandCandidates cleared = built(0.1);
  cleared.clear();
  EXPECT_FALSE(cleared.still_covers(&l, &r));
}
