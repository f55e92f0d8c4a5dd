// The loads and measures of a triangulated surface (fix_membrane3d/surface_loads.h)
// on hand-worked shapes: the corner tetrahedron, the unit cube, an N-gon prism.
#include "shapes.h"
#include "surface_loads.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

using namespace shapes;

TEST(SurfaceLoads, TetrahedronForcesByHand) {
  // p/3 of each facet's vector area: O has the three axis faces (-1/2 each axis),
  // so F_O = p/6 (1,1,1); e1 has -z/2, -y/2 and (1,1,1)/2: F_e1 = -p/3 (1/2,0,0).
  const double p = 3.0e5;
  const auto f = membrane3d::pressure_forces(corner_tetrahedron(), p);
  ASSERT_EQ(f.size(), 4u);
  expect_vector_near(f[0], Vector3d(p / 6, p / 6, p / 6), 1e-9);
  expect_vector_near(f[1], Vector3d(-p / 6, 0, 0), 1e-9);
  expect_vector_near(f[2], Vector3d(0, -p / 6, 0), 1e-9);
  expect_vector_near(f[3], Vector3d(0, 0, -p / 6), 1e-9);
  EXPECT_NEAR(membrane3d::enclosed_volume(corner_tetrahedron()), 1.0 / 6.0, 1e-15);
}

TEST(SurfaceLoads, ClosedCubeHasNoNetForceAndUnitVolume) {
  const Surface cube = unit_cube(true);
  expect_vector_near(membrane3d::vector_area(cube), Vector3d::Zero(), 1e-15);
  Vector3d sum = Vector3d::Zero();
  for (const auto &f : membrane3d::pressure_forces(cube, 1e5)) sum += f;
  expect_vector_near(sum, Vector3d::Zero(), 1e-10);
  EXPECT_NEAR(membrane3d::enclosed_volume(cube), 1.0, 1e-15);
  EXPECT_NEAR(membrane3d::lateral_volume(cube), 1.0, 1e-15);
}

TEST(SurfaceLoads, LateralCubeVolumeWithoutCaps) {
  // The caps have no flux of (x, y, 0)/2: the four sides alone give the volume.
  EXPECT_NEAR(membrane3d::lateral_volume(unit_cube(false)), 1.0, 1e-15);
  // Moving the sample sideways changes nothing.
  Surface moved = unit_cube(false);
  for (auto &x : moved.points) x += Vector3d(7.25, -3.5, 0.0);
  EXPECT_NEAR(membrane3d::lateral_volume(moved), 1.0, 1e-13);
}

TEST(SurfaceLoads, ForcesSumToPressureTimesVectorArea) {
  // An open surface: the cube without its top; the forces sum to -p N = -p (0,0,-1).
  Surface s = unit_cube(true);
  s.facets.pop_back();
  s.facets.pop_back();
  const double p = 2.5e4;
  const Vector3d n = membrane3d::vector_area(s);
  expect_vector_near(n, Vector3d(0, 0, -1), 1e-15);
  Vector3d sum = Vector3d::Zero();
  for (const auto &f : membrane3d::pressure_forces(s, p)) sum += f;
  expect_vector_near(sum, -p * n, 1e-10);
}

TEST(SurfaceLoads, PrismVolumeAndEquivalentRadius) {
  // V = (N/2) R^2 sin(2 pi / N) H; r_eq = sqrt(V / (pi H)).
  const int n = 12;
  const double r = 0.025, h = 0.1;
  const Surface s = prism(n, r, h);
  const double v = 0.5 * n * r * r * std::sin(2 * M_PI / n) * h;
  EXPECT_NEAR(membrane3d::lateral_volume(s), v, 1e-18);
  EXPECT_NEAR(membrane3d::equivalent_radius(v, h), r * std::sqrt(n * std::sin(2 * M_PI / n) / (2 * M_PI)),
              1e-15);
  // A ring closes on itself: no net force.
  const auto force = membrane3d::pressure_forces(s, 1e5);
  Vector3d sum = Vector3d::Zero();
  for (const auto &f : force) sum += f;
  expect_vector_near(sum, Vector3d::Zero(), 1e-10);
  // Every force points towards the axis.
  for (std::size_t k = 0; k < s.points.size(); ++k)
    EXPECT_LT(force[k].head<2>().dot(s.points[k].head<2>()), 0.0) << "point " << k;
}

TEST(SurfaceLoads, ReversedFacetsFlipSigns) {
  Surface s = corner_tetrahedron();
  for (auto &f : s.facets) std::swap(f[1], f[2]);
  EXPECT_NEAR(membrane3d::enclosed_volume(s), -1.0 / 6.0, 1e-15);
  expect_vector_near(membrane3d::pressure_forces(s, 6.0)[0], Vector3d(-1, -1, -1), 1e-14);
}

TEST(SurfaceLoads, PointOnNoFacetGetsNoForce) {
  Surface s = corner_tetrahedron();
  s.points.emplace_back(5, 5, 5);
  const auto f = membrane3d::pressure_forces(s, 1e5);
  ASSERT_EQ(f.size(), 5u);
  EXPECT_EQ(f[4], Vector3d::Zero());
}

TEST(SurfaceLoads, BadVertexIndexIsNamed) {
  Surface s = corner_tetrahedron();
  s.facets.push_back({1, 2, 4});
  try {
    membrane3d::pressure_forces(s, 1.0);
    FAIL() << "no exception";
  } catch (const std::out_of_range &e) {
    EXPECT_STREQ(e.what(), "facet 4 has vertex 4 of 4 points");
  }
  s.facets.back() = {-1, 0, 1};
  EXPECT_THROW(membrane3d::vector_area(s), std::out_of_range);
}
