// The outer-face offset of one sphere (fix_membrane3d/outer_face_offset.h) from the
// facets on it, against values worked by hand.
#include "outer_face_offset.h"

#include <gtest/gtest.h>

#include <cmath>

using Eigen::Vector3d;
using membrane3d::least_squares_offset;
using membrane3d::NormalSums;

namespace {

void expect_near(const Vector3d &a, const Vector3d &b, double tol)
{
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(a[k], b[k], tol) << "component " << k;
}

// facets of vector areas `a`
NormalSums sums_of(std::initializer_list<Vector3d> a)
{
  NormalSums s;
  for (const Vector3d &v : a) s.add(v, v.norm());
  return s;
}

} // namespace

// A flat face moves out by r along its normal, a straight edge by r along both faces'
// normals, a cube's corner to its corner; facet areas only weigh the least squares.
TEST(OuterFaceOffset, FaceEdgeAndCorner)
{
  const Vector3d n = Vector3d(1, 2, 2) / 3;
  expect_near(least_squares_offset(sums_of({0.5 * n, 2.0 * n})), n, 1e-15);
  expect_near(least_squares_offset(sums_of({Vector3d(-1, 0, 0), Vector3d(0, -3, 0)})),
              Vector3d(-1, -1, 0), 1e-15);
  expect_near(least_squares_offset(
                  sums_of({Vector3d(2, 0, 0), Vector3d(0, 1, 0), Vector3d(0, 0, 0.5)})),
              Vector3d(1, 1, 1), 1e-15);
}

// The sums of a membrane sphere on a flat face, taken from a run (a cuboid under a
// membrane placed for 386 steps on its positions, bench/in.membrane3d_cuboid_cost):
// M has rank 1 to round-off, and the determinant and the minors, both round-off, once
// made the fast path divide by a determinant of nothing: an offset of inf, loads of
// NaN. The answer is the face's unit normal b / |b|.
TEST(OuterFaceOffset, FlatFaceFromARunIsFinite)
{
  NormalSums s;
  s.m = {2.8679389793370102e-10, -1.4838570013879229e-08, 4.3031094171971994e-08,
         7.6774004483071736e-07, -2.2264068665514122e-06, 6.4564660509798539e-06};
  s.b = Vector3d(-4.5518572873430578e-08, 2.3551077459479444e-06, -6.8296920192603347e-06);
  const Vector3d o = least_squares_offset(s);
  ASSERT_TRUE(o.allFinite());
  expect_near(o, s.b.normalized(), 1e-6);
}

// Nearly flat faces at every orientation and scale: the offset is the unit normal.
TEST(OuterFaceOffset, NearlyFlatFacesAreTheirNormal)
{
  int cases = 0;
  for (double scale : {1e-12, 1e-6, 1.0, 1e6})
    for (int k = 0; k < 200; ++k) {
      const double t = 0.1 * k, u = 0.37 * k;
      const Vector3d n(std::sin(t) * std::cos(u), std::sin(t) * std::sin(u), std::cos(t));
      const Vector3d tilt = 1e-9 * Vector3d(std::cos(3 * u), std::sin(5 * t), 0.3);
      const NormalSums s = sums_of({scale * n, 0.7 * scale * (n + tilt).normalized(),
                                    1.3 * scale * (n - tilt).normalized()});
      const Vector3d o = least_squares_offset(s);
      ASSERT_TRUE(o.allFinite()) << "scale " << scale << " case " << k;
      expect_near(o, n, 1e-6);
      ++cases;
    }
  EXPECT_EQ(cases, 800);
}

// The apex of a cone of three facets whose normals are at angle t from its axis z asks
// for o = z / cos t: past 2 it is not taken. At t = 80 degrees (5.76 asked) the axis is
// poorly constrained (eigenvalue 3 cos^2 t = 0.09 against 1.5 sin^2 t = 1.45, 6 %): no
// offset along it, and none across by symmetry. At t = 63.4 degrees (cos t = 1 / sqrt 5,
// ratio 50 %) the axis is well constrained: the offset sqrt 5 along it is shortened to
// 2. The vertical edge of a triangular prism (normals 120 degrees apart) is 2 exactly.
TEST(OuterFaceOffset, ASharpApexGetsNoFin)
{
  const auto cone = [](double t) {
    NormalSums s;
    for (int k = 0; k < 3; ++k) {
      const double phi = 2 * M_PI * k / 3;
      s.add(Vector3d(std::sin(t) * std::cos(phi), std::sin(t) * std::sin(phi), std::cos(t)), 1);
    }
    return s;
  };
  expect_near(least_squares_offset(cone(80 * M_PI / 180)), Vector3d::Zero(), 1e-12);
  expect_near(least_squares_offset(cone(std::acos(1 / std::sqrt(5.0)))), Vector3d(0, 0, 2),
              1e-12);
  const double c = std::cos(2 * M_PI / 3), s = std::sin(2 * M_PI / 3);
  expect_near(least_squares_offset(sums_of({Vector3d(1, 0, 0), Vector3d(c, s, 0)})),
              Vector3d(1, (1 - c) / s, 0), 1e-12); // |o| = 2
  // at 50 degrees 1 / cos t = 1.556 is within the bound: the outer-face solution
  expect_near(least_squares_offset(cone(50 * M_PI / 180)),
              Vector3d(0, 0, 1 / std::cos(50 * M_PI / 180)), 1e-12);
}

// The sums of a 20 mm ball beside a 2 x 2 column of 1 mm spheres (its membrane vertex
// in a run of the adversarial case ball_beside_column): the least squares
// ask 3.24 r (then cut to 2 r: a fin a radius out of the ball, 10 mm). The weakest
// direction has 3 % of the largest eigenvalue: left out, the offset is (-0.10, 1.00, 0),
// on the ball's surface.
TEST(OuterFaceOffset, ALargeSphereBesideSmallOnesStaysOnIt)
{
  NormalSums s;
  s.m = {1.4386290052569173e-06, -3.484234154078833e-06, -8.4703294725430034e-22,
         3.658445861782775e-05,  0,                      9.9611746295303949e-06};
  s.b = Vector3d(-7.0000000000000007e-06, 3.6750000000000012e-05, 0);
  const Vector3d o = least_squares_offset(s);
  EXPECT_NEAR(o.norm(), 1.0, 0.02);
  EXPECT_GT(o.y(), 0.97);
  EXPECT_NEAR(o.z(), 0, 1e-12);
}
