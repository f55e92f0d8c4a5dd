#include "outer_face_offset.h"
#include "math_constants.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <utility>

namespace membrane3d {

namespace {

// An eigenvalue of the normals' matrix below this fraction of the largest is a
// direction the facets do not constrain (along an edge, or the whole tangent plane
// of a flat face): the offset has no component there.
constexpr double kUnconstrained = 1e-3;
// det(M) below this fraction of trace(M)^3 is round-off for the fast path's bound
// (a well-conditioned M, every eigenvalue above kUnconstrained of the largest, has
// det above 3.7e-8 trace^3)
constexpr double kRoundOffDet = 1e-9;
// The farthest a vertex may lie from its sphere's centre, in radii: the vertical edge
// of a prism whose corner is 60 degrees (a triangle's; a box's corner is sqrt 3). A
// longer offset is shortened to it.
constexpr double kMostOffset = 2.0;
// Beyond this the least squares have run out along a direction the facets hardly
// constrain (a fin: 3.2 r for a large sphere beside a column of small ones, whose
// facets' normals span a narrow fan): the poorly constrained directions are left out
// first. Well above the sharpest corners of a packing (2 r and a little for a
// tetrahedron's under a platen, which are only shortened).
constexpr double kFin = 2.5;
// A direction whose eigenvalue of the normals' matrix is below this fraction of the
// largest is poorly constrained: where the offset is a fin it is left out there (the
// 20 mm ball beside 1 mm spheres: 3 %; the apex of a cone of three facets at 80 degrees
// from its axis: 6 %, at 63 degrees: 50 %, only shortened).
constexpr double kPoorlyConstrained = 0.1;

// The eigenvalues of a symmetric positive semi-definite 3 x 3 matrix in closed form
// (Smith 1961), smallest and largest: accurate to round-off of the largest.
std::pair<double, double> eigenvalue_range(const Eigen::Matrix3d &m)
{
  const double q = m.trace() / 3;
  const Eigen::Matrix3d shifted = m - q * Eigen::Matrix3d::Identity();
  const double p = std::sqrt(shifted.squaredNorm() / 6);
  if (p == 0) return {q, q};
  const double half_det = std::clamp((shifted / p).determinant() / 2, -1.0, 1.0);
  const double phi = std::acos(half_det) / 3;
  return {q + 2 * p * std::cos(phi + math_constants::TWO_PI / 3), q + 2 * p * std::cos(phi)};
}

// M's cofactors (the inverse times det: M is symmetric, so is it), det and the sum of
// the principal 2 x 2 minors.
struct Cofactors {
  double c00, c01, c02, c11, c12, c22, det, minors;

  explicit Cofactors(const std::array<double, 6> &m)
    : c00(m[3] * m[5] - m[4] * m[4]), c01(m[2] * m[4] - m[1] * m[5]),
      c02(m[1] * m[4] - m[2] * m[3]), c11(m[0] * m[5] - m[2] * m[2]),
      c12(m[1] * m[2] - m[0] * m[4]), c22(m[0] * m[3] - m[1] * m[1]),
      det(m[0] * c00 + m[1] * c01 + m[2] * c02), minors(c00 + c11 + c22)
  {
  }

  Eigen::Vector3d solve(const Eigen::Vector3d &b) const
  {
    return Eigen::Vector3d(c00 * b.x() + c01 * b.y() + c02 * b.z(),
                           c01 * b.x() + c11 * b.y() + c12 * b.z(),
                           c02 * b.x() + c12 * b.y() + c22 * b.z()) /
           det;
  }
};

// The unit eigenvector of symmetric m for its simple eigenvalue lambda: normal to the
// rows of m - lambda I, the largest cross product of two of them.
Eigen::Vector3d eigenvector(const Eigen::Matrix3d &m, double lambda)
{
  const Eigen::Matrix3d a = m - lambda * Eigen::Matrix3d::Identity();
  const std::array<Eigen::Vector3d, 3> c = {a.row(0).cross(a.row(1)), a.row(0).cross(a.row(2)),
                                            a.row(1).cross(a.row(2))};
  const Eigen::Vector3d &v = *std::max_element(
      c.begin(), c.end(),
      [](const Eigen::Vector3d &x, const Eigen::Vector3d &y) { return x.squaredNorm() < y.squaredNorm(); });
  return v.normalized();
}

} // namespace

// The least-squares solution of o . n_f = 1 over the facets, M o = b, without the
// directions M hardly constrains (eigenvalue at most kUnconstrained of the largest).
// Most membrane spheres have none: M's inverse from its cofactors (a 3 x 3 per membrane
// sphere and step); the others, on flat faces and straight edges, solve in the
// directions left.
Eigen::Vector3d unbounded_offset(const NormalSums &sums)
{
  const std::array<double, 6> &m = sums.m;
  const Cofactors cofactors(m);
  // lambda_min = det / (lambda_mid lambda_max) >= det / (the minors' sum) and
  // lambda_max <= tr: a large determinant shows every direction constrained without
  // the closed form (its acos and cos)
  const double trace = m[0] + m[3] + m[5];
  // ... but only with det above its round-off: at a flat face M has rank 1, det and the
  // minors are round-off of either sign, and a det > 0 over minors <= 0 passed the test
  // and divided by it (an offset of inf: seen on a membrane kept 386 steps)
  if (cofactors.det > kRoundOffDet * trace * trace * trace &&
      cofactors.det > 2 * kUnconstrained * trace * cofactors.minors)
    return cofactors.solve(sums.b);
  const Eigen::Matrix3d matrix = sums.matrix();
  const std::pair<double, double> range = eigenvalue_range(matrix);
  const double smallest = range.first, largest = range.second;
  if (smallest > kUnconstrained * largest) return cofactors.solve(sums.b);
  if (trace - smallest - largest <= kUnconstrained * largest) {
    // one direction constrained (a flat face)
    const Eigen::Vector3d v = eigenvector(matrix, largest);
    return (v.dot(sums.b) / largest) * v;
  }
  // two constrained (an edge): M's inverse in the plane normal to the third direction v
  // is that of M with v's eigenvalue raised to the trace, applied to b without its v part
  const Eigen::Vector3d v = eigenvector(matrix, smallest);
  const Eigen::Matrix3d raised = matrix + (trace - smallest) * v * v.transpose();
  const std::array<double, 6> r = {raised(0, 0), raised(0, 1), raised(0, 2),
                                   raised(1, 1), raised(1, 2), raised(2, 2)};
  return Cofactors(r).solve(sums.b - v.dot(sums.b) * v);
}

// The offset within kMostOffset: a fin (beyond kFin) loses its poorly constrained
// directions one by one, weakest first; what is still beyond kMostOffset is shortened.
Eigen::Vector3d least_squares_offset(const NormalSums &sums)
{
  const Eigen::Vector3d o = unbounded_offset(sums);
  if (o.norm() <= kMostOffset) return o;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen;
  eigen.computeDirect(sums.matrix()); // ascending eigenvalues
  const Eigen::Vector3d lambda = eigen.eigenvalues();
  const Eigen::Matrix3d v = eigen.eigenvectors();
  Eigen::Vector3d out = o;
  for (int weak = 0; weak < 2 && out.norm() > kFin &&
                     lambda[weak] < kPoorlyConstrained * lambda[2];
       ++weak) {
    out.setZero();
    for (int k = weak + 1; k < 3; ++k) out += v.col(k).dot(sums.b) / lambda[k] * v.col(k);
  }
  return out.norm() <= kMostOffset ? out : out * (kMostOffset / out.norm());
}

} // namespace membrane3d
