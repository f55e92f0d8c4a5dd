// Hand-worked shapes for the membrane3d unit tests: the corner tetrahedron, the unit
// cube with and without its caps, the lateral surface of a regular prism.
#ifndef LIGGGHTS_MEMBRANE_TEST_SHAPES_H
#define LIGGGHTS_MEMBRANE_TEST_SHAPES_H

#include "surface_loads.h"

#include <gtest/gtest.h>

#include <cmath>

namespace shapes {

using membrane3d::Surface;
using Eigen::Vector3d;

// O, e1, e2, e3; faces counter-clockwise from outside: -z, -y, -x and the slanted one.
inline Surface corner_tetrahedron() {
  return {{Vector3d(0, 0, 0), Vector3d(1, 0, 0), Vector3d(0, 1, 0), Vector3d(0, 0, 1)},
          {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}};
}

// The unit cube [0,1]^3, two triangles per face; `with_caps` false leaves out the
// bottom (z = 0) and top (z = 1) faces: the lateral surface of a square sample.
inline Surface unit_cube(bool with_caps) {
  Surface s;
  for (int k = 0; k < 8; ++k) s.points.emplace_back(k & 1, (k >> 1) & 1, (k >> 2) & 1);
  // each face as a quadrilateral counter-clockwise from outside
  const int lateral[4][4] = {{0, 1, 5, 4}, {1, 3, 7, 5}, {3, 2, 6, 7}, {2, 0, 4, 6}};
  const int caps[2][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}};
  auto add = [&s](const int q[4]) {
    s.facets.push_back({q[0], q[1], q[2]});
    s.facets.push_back({q[0], q[2], q[3]});
  };
  for (const auto &q : lateral) add(q);
  if (with_caps)
    for (const auto &q : caps) add(q);
  return s;
}

// The lateral surface of a regular N-gon prism of circumradius R between z = 0 and H.
inline Surface prism(int n, double r, double h) {
  Surface s;
  for (int i = 0; i < n; ++i) {
    const double t = 2 * M_PI * i / n;
    s.points.emplace_back(r * std::cos(t), r * std::sin(t), 0.0);
    s.points.emplace_back(r * std::cos(t), r * std::sin(t), h);
  }
  for (int i = 0; i < n; ++i) {
    const int b0 = 2 * i, t0 = b0 + 1, b1 = 2 * ((i + 1) % n), t1 = b1 + 1;
    s.facets.push_back({b0, b1, t1});
    s.facets.push_back({b0, t1, t0});
  }
  return s;
}

inline void expect_vector_near(const Vector3d &a, const Vector3d &b, double tol) {
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(a[k], b[k], tol) << "component " << k;
}

} // namespace shapes

#endif
