#include "fabric_tensors3d.h"

#include <Eigen/Dense>

#include <cmath>
#include <stdexcept>

namespace fabric {

static_assert(ContactSums3::FIELDS == ContactSums3::pairs(), "ContactSums3: one sum per field");
static_assert(ForceSums3::FIELDS == ForceSums3::pairs(), "ForceSums3: one sum per field");

namespace {

// the components of the symmetric part, xx yy zz xy xz yz
constexpr int kRow[6] = {0, 1, 2, 0, 0, 1};
constexpr int kCol[6] = {0, 1, 2, 1, 2, 2};

Eigen::Matrix3d deviator(const Eigen::Matrix3d &t)
{
  return t - t.trace() / 3.0 * Eigen::Matrix3d::Identity();
}

void add_symmetric(ExactSum *sums, const Eigen::Vector3d &u, const Eigen::Vector3d &v,
                   double weight)
{
  for (int k = 0; k < 6; k++) sums[k].add(weight * u(kRow[k]) * v(kCol[k]));
}

void add_full(ExactSum *sums, const Eigen::Vector3d &u, const Eigen::Vector3d &v, double weight)
{
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++) sums[3 * i + j].add(weight * u(i) * v(j));
}

Eigen::Matrix3d symmetric_of(const ExactSum *sums)
{
  Eigen::Matrix3d t;
  for (int k = 0; k < 6; k++) t(kRow[k], kCol[k]) = t(kCol[k], kRow[k]) = sums[k].value();
  return t;
}

Eigen::Matrix3d full_of(const ExactSum *sums)
{
  Eigen::Matrix3d t;
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++) t(i, j) = sums[3 * i + j].value();
  return t;
}

} // namespace

Contact3 make_contact3(long a, long b, const Eigen::Vector3d &l, const Eigen::Vector3d &f,
                       double radius_sum)
{
  Contact3 c{a, b, Eigen::Vector3d::Zero(), 0.0, Eigen::Vector3d::Zero(), l};
  const double length = l.norm();
  if (!std::isfinite(length) || !(length > kCoincidentFraction * radius_sum)) return c;
  c.n = l / length;
  c.fn = f.dot(c.n);
  c.ft = f - c.fn * c.n;
  return c;
}

bool has_normal(const Contact3 &c)
{
  return c.n.allFinite() && !c.n.isZero(0.0);
}

Components components(const Eigen::Matrix3d &t)
{
  Components out;
  for (int k = 0; k < 6; k++) out[k] = 0.5 * (t(kRow[k], kCol[k]) + t(kCol[k], kRow[k]));
  return out;
}

Anisotropy3 anisotropy_of(const Eigen::Matrix3d &deviator_tensor)
{
  Anisotropy3 r;
  r.a = deviator_tensor;
  r.invariant = std::sqrt(1.5 * deviator_tensor.squaredNorm());
  return r;
}

template <int N> void FieldSums<N>::merge(const FieldSums &other)
{
  for (int k = 0; k < N; k++) sum[k].merge(other.sum[k]);
}

template <int N> std::vector<double> FieldSums<N>::pack() const
{
  std::vector<double> out;
  out.reserve(2 * N);
  for (const ExactSum &x : sum) {
    out.push_back(x.hi);
    out.push_back(x.lo);
  }
  return out;
}

template <int N> void FieldSums<N>::unpack(const double *packed)
{
  for (ExactSum &x : sum) {
    x.hi = *packed++;
    x.lo = *packed++;
  }
}

template struct FieldSums<17>;

void ContactSums3::add(const Contact3 &c)
{
  sum[CONTACTS].add(1.0);
  if (!has_normal(c)) {
    sum[NO_NORMAL].add(1.0);
    return;
  }
  add_symmetric(&sum[PHI], c.n, c.n, 1.0);
  add_full(&sum[FL], c.fn * c.n + c.ft, c.l, 1.0);
}

Eigen::Matrix3d ContactSums3::phi() const
{
  const double n = sum[CONTACTS].value() - sum[NO_NORMAL].value();
  return n > 0.0 ? Eigen::Matrix3d(symmetric_of(&sum[PHI]) / n) : Eigen::Matrix3d::Zero();
}

Eigen::Matrix3d ContactSums3::f_l() const
{
  return full_of(&sum[FL]);
}

void ForceSums3::add(const Contact3 &c, const Eigen::Matrix3d &fabric)
{
  if (!has_normal(c)) return;
  sum[WITH_NORMAL].add(1.0);
  const double w = 1.0 + c.n.dot(fabric * c.n);
  if (!model_density_usable(w)) { // w <= 0 up to round-off
    sum[SKIPPED].add(1.0);
    return;
  }
  add_symmetric(&sum[CHI_N], c.n, c.n, c.fn / w);
  add_full(&sum[CHI_T], c.ft, c.n, 1.0 / w);
}

Anisotropy3 fabric_anisotropy(const ContactSums3 &sums)
{
  if (sums.sum[ContactSums3::CONTACTS].value() - sums.sum[ContactSums3::NO_NORMAL].value() <= 0.0)
    return {};
  return anisotropy_of(7.5 * deviator(sums.phi()));
}

ForceAnisotropy3 force_anisotropy(const ForceSums3 &sums)
{
  ForceAnisotropy3 r;
  r.skipped = static_cast<long>(sums.sum[ForceSums3::SKIPPED].value());
  const double n = sums.sum[ForceSums3::WITH_NORMAL].value();
  if (!(n > 0.0)) return r;
  const Eigen::Matrix3d chi_n = symmetric_of(&sums.sum[ForceSums3::CHI_N]) / n;
  const Eigen::Matrix3d chi_t = full_of(&sums.sum[ForceSums3::CHI_T]) / n;
  const double f0 = chi_n.trace();
  // no compressive mean force (no force, or tension: the viscous part of separating
  // contacts): no force anisotropy to scale by it, and f0 = 0, as in 2D. A NaN (a
  // contact force from a NaN velocity) is not hidden as 0: it goes on to the outputs
  if (f0 <= 0.0) return r;
  r.f0 = f0;
  r.normal = anisotropy_of(7.5 * deviator(chi_n) / r.f0);
  r.tangential = anisotropy_of(2.5 * (chi_t + chi_t.transpose()) / r.f0);
  return r;
}

Eigen::Matrix3d love_weber_stress(const ContactSums3 &sums, double volume)
{
  if (!(volume > 0.0)) throw std::invalid_argument("fabric: love_weber_stress needs volume > 0");
  return sums.f_l() / volume;
}

} // namespace fabric
