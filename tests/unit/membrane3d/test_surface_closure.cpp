// Closing a lateral surface at its rims and the winding number
// (fix_membrane3d/surface_closure.h), on the unit cube and a prism.
#include "shapes.h"
#include "surface_closure.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

using namespace shapes;

TEST(SurfaceClosure, CubeSidesHaveTwoRimsOfFour) {
  auto loops = membrane3d::boundary_loops(unit_cube(false));
  ASSERT_EQ(loops.size(), 2u);
  for (auto &loop : loops) std::rotate(loop.begin(), std::min_element(loop.begin(), loop.end()), loop.end());
  std::sort(loops.begin(), loops.end());
  // bottom rim runs against the cap's outward order (0,2,3,1): 0 -> 1 -> 3 -> 2;
  // top rim against (4,5,7,6): 4 -> 6 -> 7 -> 5
  EXPECT_EQ(loops[0], (std::vector<int>{0, 1, 3, 2}));
  EXPECT_EQ(loops[1], (std::vector<int>{4, 6, 7, 5}));
  EXPECT_TRUE(membrane3d::boundary_loops(unit_cube(true)).empty());
}

TEST(SurfaceClosure, CapsCloseTheCube) {
  const Surface closed = membrane3d::close_with_caps(unit_cube(false));
  ASSERT_EQ(closed.points.size(), 10u);   // two rim centroids added
  EXPECT_EQ(closed.points[8], Vector3d(0.5, 0.5, 0.0));
  EXPECT_EQ(closed.points[9], Vector3d(0.5, 0.5, 1.0));
  ASSERT_EQ(closed.facets.size(), 16u);   // 8 side triangles + 4 per cap
  EXPECT_TRUE(membrane3d::boundary_loops(closed).empty());
  expect_vector_near(membrane3d::vector_area(closed), Vector3d::Zero(), 1e-15);
  EXPECT_NEAR(membrane3d::enclosed_volume(closed), 1.0, 1e-15);
  // the caps take the platens' share: the forces of the closed surface sum to zero
  Vector3d sum = Vector3d::Zero();
  for (const auto &f : membrane3d::pressure_forces(closed, 1e5)) sum += f;
  expect_vector_near(sum, Vector3d::Zero(), 1e-10);
}

TEST(SurfaceClosure, PrismClosedVolumeEqualsLateralVolume) {
  const Surface s = prism(9, 0.02, 0.08);
  const Surface closed = membrane3d::close_with_caps(s);
  const double v = 0.5 * 9 * 0.02 * 0.02 * std::sin(2 * M_PI / 9) * 0.08;
  EXPECT_NEAR(membrane3d::enclosed_volume(closed), v, 1e-18);
  EXPECT_NEAR(membrane3d::lateral_volume(s), v, 1e-18);
}

TEST(SurfaceClosure, WindingNumberInsideOutsideAndEscaped) {
  const Surface closed = membrane3d::close_with_caps(unit_cube(false));
  EXPECT_NEAR(membrane3d::winding_number(closed, Vector3d(0.5, 0.5, 0.5)), 1.0, 1e-12);
  EXPECT_NEAR(membrane3d::winding_number(closed, Vector3d(0.01, 0.98, 0.02)), 1.0, 1e-12);
  EXPECT_NEAR(membrane3d::winding_number(closed, Vector3d(1.02, 0.5, 0.5)), 0.0, 1e-12);
  EXPECT_NEAR(membrane3d::winding_number(closed, Vector3d(-3.0, 7.0, 0.5)), 0.0, 1e-12);
  // reversed facets (inside out) count -1
  Surface reversed = closed;
  for (auto &f : reversed.facets) std::swap(f[1], f[2]);
  EXPECT_NEAR(membrane3d::winding_number(reversed, Vector3d(0.5, 0.5, 0.5)), -1.0, 1e-12);
}

TEST(SurfaceClosure, PinchedRimIsRefused) {
  // two triangles that meet at one vertex only: vertex 0 starts two rim edges
  Surface bowtie{{Vector3d(0, 0, 0), Vector3d(1, 0, 0), Vector3d(0, 1, 0), Vector3d(-1, 0, 0),
                  Vector3d(0, -1, 0)},
                 {{0, 1, 2}, {0, 3, 4}}};
  try {
    membrane3d::boundary_loops(bowtie);
    FAIL() << "no exception";
  } catch (const std::invalid_argument &e) {
    EXPECT_STREQ(e.what(), "vertex 0 starts two rim edges");
  }
}
