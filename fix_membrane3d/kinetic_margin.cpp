#include "kinetic_margin.h"

#include "determinant_margin.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace membrane3d {

namespace {

constexpr double kRoundOff = 1e-10;

} // namespace

namespace {

// The halvings of a reach tried below its largest: it is found within a factor of 2.
constexpr int kHalvings = 12;

struct OrientationBound {
  double det, cross, n1, n2, n3;
  explicit OrientationBound(const std::array<const Sphere *, 4> &p)
  {
    const Eigen::Vector3d q1 = p[1]->x - p[0]->x, q2 = p[2]->x - p[0]->x, q3 = p[3]->x - p[0]->x;
    det = q1.dot(q2.cross(q3));
    cross = q2.cross(q3).norm() + q3.cross(q1).norm() + q1.cross(q2).norm();
    n1 = q1.norm();
    n2 = q2.norm();
    n3 = q3.norm();
  }
  bool holds(double delta) const
  {
    const double e = 2 * delta;
    const double first = e * cross;
    const double rest = e * e * (n1 + n2 + n3) + e * e * e;
    return first + rest + kRoundOff * n1 * n2 * n3 < std::abs(det);
  }
};

} // namespace

bool orientation_margin(const std::array<const Sphere *, 4> &p, double delta)
{
  return OrientationBound(p).holds(delta);
}

double orientation_reach(const std::array<const Sphere *, 4> &p, double most)
{
  const OrientationBound b(p);
  for (int j = 0; j <= kHalvings; ++j, most /= 2)
    if (b.holds(most)) return most;
  return 0;
}

// The 4 x 4 determinant of rows (q_i, (|q_i|^2 - w_i + w_4) / L), q_i = p_i - p_4, the
// lifted column scaled by the longest |q_i| = L (a length like the others).
namespace {

struct PowerBound {
  double det = 0, L = 0;
  std::array<double, 4> c3{}, lin{}, qn{}, row_norm{};
  bool valid = false;
  explicit PowerBound(const std::array<const Sphere *, 5> &p)
  {
    Eigen::Matrix4d a;
    for (int i = 0; i < 4; ++i) L = std::max(L, (p[i]->x - p[4]->x).norm());
    if (!(L > 0)) return;
    const double w4 = p[4]->r * p[4]->r;
    for (int i = 0; i < 4; ++i) {
      const Eigen::Vector3d q = p[i]->x - p[4]->x;
      a.row(i) << q.transpose(), (q.squaredNorm() - p[i]->r * p[i]->r + w4) / L;
    }
    det = a.determinant();
    for (int i = 0; i < 4; ++i) {
      Eigen::Vector4d c; // the cofactors of row i
      for (int j = 0; j < 4; ++j) {
        Eigen::Matrix3d minor;
        for (int r = 0, mr = 0; r < 4; ++r) {
          if (r == i) continue;
          for (int s = 0, ms = 0; s < 4; ++s)
            if (s != j) minor(mr, ms++) = a(r, s);
          ++mr;
        }
        c(j) = ((i + j) % 2 ? -1.0 : 1.0) * minor.determinant();
      }
      const Eigen::Vector3d q = a.row(i).head<3>().transpose();
      lin[i] = (c.head<3>() + (2 / L) * c(3) * q).norm();
      c3[i] = std::abs(c(3));
      qn[i] = q.norm();
      row_norm[i] = a.row(i).norm();
    }
    valid = true;
  }
  // row i moves by (e_i, (2 q . e_i + |e_i|^2) / L): the first-order (cofactor) terms,
  // the Hadamard bound of the rest, the round-off allowance
  bool holds(double delta) const
  {
    if (!valid) return false;
    const double e = 2 * delta;
    double first = 0;
    std::array<double, 4> row_change{};
    for (int i = 0; i < 4; ++i) {
      first += e * lin[i] + e * e * c3[i] / L;
      row_change[i] = e * (1 + (2 * qn[i] + e) / L);
    }
    if (!std::isfinite(first)) return false;
    return determinant_margin(det, first, row_norm, row_change, kRoundOff);
  }
};

} // namespace

// The 4 x 4 determinant of rows (q_i, (|q_i|^2 - w_i + w_4) / L), q_i = p_i - p_4, the
// lifted column scaled by the longest |q_i| = L (a length like the others).
bool power_margin(const std::array<const Sphere *, 5> &p, double delta)
{
  return PowerBound(p).holds(delta);
}

double power_reach(const std::array<const Sphere *, 5> &p, double most)
{
  const PowerBound b(p);
  for (int j = 0; j <= kHalvings; ++j, most /= 2)
    if (b.holds(most)) return most;
  return 0;
}

bool vertical_pairs(const std::array<int, 4> &family)
{
  int pairs = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) pairs += family[i] == family[j];
  return pairs >= 2;
}

bool perturbed_margin(const std::array<const Sphere *, 5> &p, const std::array<int, 5> &family,
                      double delta)
{
  std::array<int, 5> order{0, 1, 2, 3, 4};
  // the order of the points where they shall be (a family on one vertical line): by z
  // within a family, else by x (a tie across families fails the margin below)
  auto less = [&p, &family](int a, int b) {
    return family[a] == family[b] ? p[a]->x.z() < p[b]->x.z() : p[a]->x.x() < p[b]->x.x();
  };
  std::sort(order.begin(), order.end(), less);
  for (int i = 0; i + 1 < 5; ++i) {
    const int a = order[i], b = order[i + 1];
    const int axis = family[a] == family[b] ? 2 : 0;
    if (!(std::abs(p[a]->x[axis] - p[b]->x[axis]) > 2 * delta)) return false;
  }
  for (int i = 4; i > 1; --i) {
    const int q = order[i];
    if (q == 4) return true;
    std::array<int, 4> v{0, 1, 2, 3};
    v[q] = 4; // the orientation with p in place of q
    if (vertical_pairs({family[v[0]], family[v[1]], family[v[2]], family[v[3]]})) continue;
    return orientation_margin({p[v[0]], p[v[1]], p[v[2]], p[v[3]]}, delta);
  }
  return true;
}

} // namespace membrane3d
