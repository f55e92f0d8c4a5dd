// The outer-face offset of a membrane sphere (lateral_surface.h, Vertices::outer_faces):
// the least-squares solution o of o . n_f = 1 (in radii) over the facets f on the
// sphere, area-weighted, without the directions they hardly constrain. No LIGGGHTS
// here: unit-tested in tests/unit/membrane3d.
#ifndef LIGGGHTS_MEMBRANE_OUTER_FACE_OFFSET_H
#define LIGGGHTS_MEMBRANE_OUTER_FACE_OFFSET_H

#include <Eigen/Core>

#include <array>

namespace membrane3d {

// The normals' matrix M = sum a n n^T and b = sum a n of one sphere's facets, M's six
// entries only (it is symmetric): xx, xy, xz, yy, yz, zz.
struct NormalSums {
  std::array<double, 6> m{};
  Eigen::Vector3d b = Eigen::Vector3d::Zero();

  // a facet of vector area a: a n n^T = a a^T / |a|, a n = a
  void add(const Eigen::Vector3d &a, double area)
  {
    const double s = 1 / area;
    m[0] += s * a.x() * a.x();
    m[1] += s * a.x() * a.y();
    m[2] += s * a.x() * a.z();
    m[3] += s * a.y() * a.y();
    m[4] += s * a.y() * a.z();
    m[5] += s * a.z() * a.z();
    b += a;
  }

  Eigen::Matrix3d matrix() const
  {
    Eigen::Matrix3d out;
    out << m[0], m[1], m[2], m[1], m[3], m[4], m[2], m[4], m[5];
    return out;
  }
};

// The offset o (in radii) from one sphere's sums: M o = b solved where M constrains it
// (an eigenvalue above 1e-3 of the largest); along a flat face's tangent plane or a
// straight edge's direction o has no component. |o| is at most 2 (a triangular
// prism's 60-degree edge; a box's corner is sqrt 3): a fin (beyond 2.5, as for a large
// sphere beside small ones, whose facets' normals span a narrow fan) loses its poorly
// constrained directions (eigenvalue below 10 % of the largest), weakest first, and
// what is still beyond 2 is shortened to 2. Finite
// for the sums of one or more facets of positive area (a sphere on no facet gets no
// offset: the caller's case).
Eigen::Vector3d least_squares_offset(const NormalSums &sums);

} // namespace membrane3d

#endif
