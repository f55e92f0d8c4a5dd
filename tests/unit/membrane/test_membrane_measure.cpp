#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "membrane_chain.h"

using Eigen::Vector2d;
using membrane::BandSlices;
using membrane::Platens;
using membrane::Polyline;
using membrane::Side;

TEST(MembraneMeasure, RectangleAreaAndWidth)
{
  const Polyline left = {{0, 0}, {0, 2}}, right = {{3, 0}, {3, 2}};
  EXPECT_DOUBLE_EQ(membrane::sample_area(left, right), 6.0);
  EXPECT_DOUBLE_EQ(membrane::width_at(1.0, left, right), 3.0);
  // Sides swapped: the polygon turns inside out and says so by its sign.
  EXPECT_DOUBLE_EQ(membrane::sample_area(right, left), -6.0);
}

TEST(MembraneMeasure, BulgedHexagonAreaAndWidth)
{
  // 3 x 2 rectangle with a triangle of area 1 on each side.
  const Polyline left = {{0, 0}, {-1, 1}, {0, 2}}, right = {{3, 0}, {4, 1}, {3, 2}};
  EXPECT_DOUBLE_EQ(membrane::sample_area(left, right), 8.0);
  EXPECT_DOUBLE_EQ(membrane::width_at(1.0, left, right), 5.0);
  EXPECT_DOUBLE_EQ(membrane::width_at(0.5, left, right), 4.0);
  EXPECT_DOUBLE_EQ(membrane::sample_area(left, right) / 2.0, 4.0); // mean width
  EXPECT_TRUE(std::isnan(membrane::width_at(3.0, left, right)));
}

TEST(MembraneMeasure, OverhangAreaAndOutermostWidth)
{
  const Polyline left = {{0, 0}, {0, 2}};
  const Polyline right = {{3, 0}, {3, 1}, {5, 1}, {5, 0.5}, {6, 0.5}, {6, 2}};
  // [0,3]x[0,2] + [3,5]x[1,2] + [5,6]x[0.5,2]
  EXPECT_DOUBLE_EQ(membrane::sample_area(left, right), 6.0 + 2.0 + 1.5);
  // Three crossings at y = 0.75 (x = 3, 5, 6): the outermost counts.
  EXPECT_DOUBLE_EQ(membrane::width_at(0.75, left, right), 6.0);
  // Horizontal edge exactly at y = 1: its far end counts.
  EXPECT_DOUBLE_EQ(membrane::outermost_x_at(1.0, right, Side::Right), 6.0);
  EXPECT_DOUBLE_EQ(membrane::outermost_x_at(0.25, right, Side::Right), 3.0);
  EXPECT_DOUBLE_EQ(membrane::outermost_x_at(0.25, right, Side::Left), 3.0);
  EXPECT_DOUBLE_EQ(membrane::outermost_x_at(0.75, right, Side::Left), 3.0);
}

TEST(MembraneMeasure, OneSideAgainstStraightWall)
{
  const Polyline right = {{3, 0}, {4, 1}, {3, 2}};
  EXPECT_DOUBLE_EQ(membrane::side_area(right, Side::Right, 0.0), 7.0);
  const Polyline left = {{0, 0}, {-1, 1}, {0, 2}};
  EXPECT_DOUBLE_EQ(membrane::side_area(left, Side::Left, 3.0), 7.0);
  EXPECT_DOUBLE_EQ(membrane::side_area(left, Side::Left, 3.0),
                   membrane::sample_area(left, Polyline{{3, 0}, {3, 2}}));
}

TEST(MembraneMeasure, OutsidePolylineParity)
{
  const Polyline right = {{3, 0}, {3, 1}, {5, 1}, {5, 0.5}, {6, 0.5}, {6, 2}};
  EXPECT_FALSE(membrane::outside_polyline({2.0, 0.75}, right, Side::Right));
  EXPECT_TRUE(membrane::outside_polyline({4.0, 0.75}, right, Side::Right)); // under the overhang
  EXPECT_FALSE(membrane::outside_polyline({5.5, 0.75}, right, Side::Right));
  EXPECT_TRUE(membrane::outside_polyline({7.0, 1.5}, right, Side::Right));
  EXPECT_FALSE(membrane::outside_polyline({4.0, 1.5}, right, Side::Right));
  const Polyline left = {{0, 0}, {-1, 1}, {0, 2}};
  EXPECT_FALSE(membrane::outside_polyline({-0.5, 1.0}, left, Side::Left));
  EXPECT_TRUE(membrane::outside_polyline({-1.5, 1.0}, left, Side::Left));
  // A ray through a vertex is counted once.
  EXPECT_TRUE(membrane::outside_polyline({-2.0, 1.0}, left, Side::Left));
}

TEST(MembraneMeasure, HexBlockAreaFromChains)
{
  // 6 x 10 hexagonal block of unit disks: both chains zigzag identically, 5 apart.
  const double h = std::sqrt(3.0) / 2.0;
  std::vector<membrane::Disk> d;
  for (int row = 0; row < 10; ++row)
    for (int col = 0; col < 6; ++col)
      d.push_back({row * 6 + col + 1, col + (row % 2 ? 0.5 : 0.0), 0.5 + row * h, 0.5});
  const Platens pl{0.0, 1.0 + 9 * h};
  membrane::ChainFinder cf;
  const auto l = cf.find(d, Side::Left, pl, 1e-6);
  const auto r = cf.find(d, Side::Right, pl, 1e-6);
  ASSERT_TRUE(l.ok && r.ok);
  EXPECT_NEAR(membrane::sample_area(l.polyline, r.polyline), 5.0 * (pl.hi - pl.lo), 1e-12);
  EXPECT_NEAR(membrane::width_at(0.5 * (pl.lo + pl.hi), l.polyline, r.polyline), 5.0, 1e-12);
}

TEST(MembraneBand, SlicesFollowTheEdge)
{
  BandSlices b;
  b.reset(Side::Right, {0.0, 4.0}, 1.0);
  ASSERT_EQ(b.extents().size(), 4u);
  // outer edges per slice: 5, 6, 10 (bulge), 5
  b.add(4.5, 0.5, 0.5);
  b.add(5.5, 1.5, 0.5);
  b.add(9.5, 2.5, 0.5);
  b.add(4.5, 3.5, 0.5);
  b.add(1.0, 3.5, 0.5); // inner disk: does not move the edge
  EXPECT_EQ(b.extents(), (std::vector<double>{5, 6, 10, 5}));
  EXPECT_DOUBLE_EQ(b.outer_edge_near(0.2), 6.0); // slices 0 and 1
  EXPECT_DOUBLE_EQ(b.outer_edge_near(3.2), 10.0);
  EXPECT_FALSE(b.contains(3.6, 0.5, 0.5, 1.0)); // x + r = 4.1 < 6 - 1
  EXPECT_TRUE(b.contains(4.6, 0.5, 0.5, 1.0));  // 5.1 >= 5
  EXPECT_FALSE(b.contains(6.0, 3.5, 0.5, 2.0)); // near slice 2's bulge: 6.5 < 8
  EXPECT_TRUE(b.contains(7.6, 3.5, 0.5, 2.0));
  // Below / above the platens clamp to the end slices.
  EXPECT_EQ(b.slice_of(-3.0), 0);
  EXPECT_EQ(b.slice_of(12.0), 3);
  EXPECT_EQ(b.slice_of(std::numeric_limits<double>::quiet_NaN()), 0);
}

TEST(MembraneBand, LeftSideAndEmptySlices)
{
  BandSlices b;
  b.reset(Side::Left, {0.0, 5.0}, 2.0); // 3 slices, the last one shorter
  ASSERT_EQ(b.extents().size(), 3u);
  b.add(1.0, 0.5, 0.5);
  EXPECT_DOUBLE_EQ(b.extents()[0], 0.5);
  EXPECT_EQ(b.extents()[2], std::numeric_limits<double>::max());
  EXPECT_TRUE(b.contains(1.2, 0.5, 0.5, 0.3));   // 0.7 <= 0.5 + 0.3
  EXPECT_FALSE(b.contains(1.4, 0.5, 0.5, 0.3));  // 0.9 >  0.8
  EXPECT_TRUE(b.contains(100.0, 4.5, 0.5, 0.1)); // empty neighbourhood: never rejects
}

TEST(MembraneBand, ReductionOfPartialExtentsMatchesSerial)
{
  // Two "ranks" each see half of the disks; an element-wise max of their
  // vectors (what MPI_MAX does) equals the serial result.
  const Platens pl{0.0, 10.0};
  BandSlices serial, r0, r1;
  serial.reset(Side::Right, pl, 1.5);
  r0.reset(Side::Right, pl, 1.5);
  r1.reset(Side::Right, pl, 1.5);
  for (int i = 0; i < 50; ++i) {
    const double x = std::sin(i * 1.7) * 3.0, y = i * 0.2, r = 0.3 + 0.01 * i;
    serial.add(x, y, r);
    (i % 2 ? r0 : r1).add(x, y, r);
  }
  for (std::size_t k = 0; k < serial.extents().size(); ++k)
    r0.extents()[k] = std::max(r0.extents()[k], r1.extents()[k]);
  EXPECT_EQ(r0.extents(), serial.extents());
}

// finish() only tabulates outer_edge_near: membership must not change.
TEST(BandSlices, FinishGivesTheSameMembership)
{
  for (Side side : {Side::Left, Side::Right}) {
    BandSlices plain, tabulated;
    plain.reset(side, Platens{0.0, 10.0}, 1.3);
    tabulated.reset(side, Platens{0.0, 10.0}, 1.3);
    std::vector<Vector2d> centres;
    std::vector<double> radii;
    unsigned seed = 12345;
    auto uniform = [&seed]() {
      seed = seed * 1103515245u + 12345u;
      return static_cast<double>((seed >> 8) & 0xFFFF) / 65536.0;
    };
    for (int k = 0; k < 400; ++k) {
      centres.emplace_back(10.0 * uniform(), 10.0 * uniform());
      radii.push_back(0.1 + 0.4 * uniform());
      plain.add(centres.back().x(), centres.back().y(), radii.back());
      tabulated.add(centres.back().x(), centres.back().y(), radii.back());
    }
    tabulated.finish();
    int inside = 0;
    for (std::size_t k = 0; k < centres.size(); ++k) {
      const bool a = plain.contains(centres[k].x(), centres[k].y(), radii[k], 1.5);
      EXPECT_EQ(a, tabulated.contains(centres[k].x(), centres[k].y(), radii[k], 1.5));
      EXPECT_EQ(plain.outer_edge_near(centres[k].y()), tabulated.outer_edge_near(centres[k].y()));
      inside += a;
    }
    EXPECT_GT(inside, 50);  // the band is neither empty ...
    EXPECT_LT(inside, 350); // ... nor everything
  }
}
