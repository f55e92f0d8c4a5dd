#include "fabric_sums.h"

#include <cmath>
#include <cstddef>
#include <stdexcept>

#include "math_constants.h"

namespace fabric {
namespace {

using math_constants::PI;

// the sums of each struct in one fixed order, for merge / pack / unpack
template <class F> void each_sum(FabricSums &s, F f)
{
  for (ExactSum *x : {&s.contacts, &s.no_normal, &s.phi_xx, &s.phi_xy, &s.phi_yy, &s.f_l_xx,
                      &s.f_l_xy, &s.f_l_yx, &s.f_l_yy})
    f(*x);
  for (auto *v : {&s.bin_count, &s.bin_fn, &s.bin_ft})
    for (ExactSum &x : *v) f(x);
}

template <class F> void each_sum(ForceTensorSums &s, F f)
{
  for (ExactSum *x : {&s.with_normal, &s.chi_n_xx, &s.chi_n_xy, &s.chi_n_yy, &s.chi_t_xx,
                      &s.chi_t_xy, &s.chi_t_yy})
    f(*x);
}

template <class F> void each_sum(ParticleSums &s, F f)
{
  for (ExactSum *x : {&s.particles, &s.contact_ends, &s.rattlers0, &s.rattlers1, &s.lambda}) f(*x);
}

template <class S> std::vector<double> pack_sums(const S &sums)
{
  std::vector<double> out;
  out.reserve(2 * static_cast<std::size_t>(sums.pairs()));
  each_sum(const_cast<S &>(sums), [&](ExactSum &x) {
    out.push_back(x.hi);
    out.push_back(x.lo);
  });
  return out;
}

template <class S> void unpack_sums(S &sums, const double *packed)
{
  each_sum(sums, [&](ExactSum &x) {
    x.hi = *packed++;
    x.lo = *packed++;
  });
}

template <class S> void merge_sums(S &into, const S &from)
{
  const std::vector<double> other = pack_sums(from);
  std::size_t k = 0;
  each_sum(into, [&](ExactSum &x) {
    x.merge({other[k], other[k + 1]});
    k += 2;
  });
}

// as deviator_of in fabric_statistics.cpp
Anisotropy major_axis(double xx, double xy, double yy)
{
  const double c = xx - yy, s = 2.0 * xy;
  double theta = 0.5 * std::atan2(s, c);
  if (theta <= -0.5 * PI) theta += PI; // atan2(-0.0, c < 0) = -pi
  return {std::hypot(c, s), theta};
}

} // namespace

void ExactSum::add(double x)
{
  const double s = hi + x;
  const double b = s - hi;
  lo += (hi - (s - b)) + (x - b);
  hi = s;
}

void ExactSum::merge(const ExactSum &other)
{
  add(other.hi);
  add(other.lo);
}

FabricSums::FabricSums(int n)
  : nbins(n), bin_count(static_cast<std::size_t>(n)), bin_fn(static_cast<std::size_t>(n)),
    bin_ft(static_cast<std::size_t>(n))
{
  if (n < 3 || n == 4)
    throw std::invalid_argument("fabric: nbins must be >= 3 and != 4"); // as polar_histogram
  if (n % 2 == 0) normal_bins.emplace(n);
}

void FabricSums::add(const Contact &c)
{
  if (!normal_bins || !has_normal(c)) return add(c, std::atan2(c.ny, c.nx));
  contacts.add(1.0);
  const int bin = normal_bins->bin(c.nx, c.ny);
  add_to_bins(c, bin, (bin + nbins / 2) % nbins);
}

void FabricSums::add(const Contact &c, double theta)
{
  contacts.add(1.0);
  if (!has_normal(c)) {
    no_normal.add(1.0);
    return;
  }
  const int bin = angle_bin(theta, nbins);
  const int opposite = nbins % 2 == 0 ? (bin < 0 ? -1 : (bin + nbins / 2) % nbins)
                                      : angle_bin(std::atan2(-c.ny, -c.nx), nbins);
  add_to_bins(c, bin, opposite);
}

void FabricSums::add_to_bins(const Contact &c, int bin, int opposite)
{
  for (int b : {bin, opposite}) {
    if (b < 0) continue;
    bin_count[static_cast<std::size_t>(b)].add(1.0);
    bin_fn[static_cast<std::size_t>(b)].add(c.fn);
    bin_ft[static_cast<std::size_t>(b)].add(c.ft);
  }
  phi_xx.add(c.nx * c.nx);
  phi_xy.add(c.nx * c.ny);
  phi_yy.add(c.ny * c.ny);
  const double fx = c.fn * c.nx - c.ft * c.ny, fy = c.fn * c.ny + c.ft * c.nx; // f = fn n + ft t
  f_l_xx.add(fx * c.lx);
  f_l_xy.add(fx * c.ly);
  f_l_yx.add(fy * c.lx);
  f_l_yy.add(fy * c.ly);
}

template <class S> void PackedSums<S>::merge(const S &other)
{
  merge_sums(static_cast<S &>(*this), other);
}

template <class S> std::vector<double> PackedSums<S>::pack() const
{
  return pack_sums(static_cast<const S &>(*this));
}

template <class S> void PackedSums<S>::unpack(const double *packed)
{
  unpack_sums(static_cast<S &>(*this), packed);
}

template struct PackedSums<FabricSums>;
template struct PackedSums<ForceTensorSums>;
template struct PackedSums<ParticleSums>;

void FabricSums::merge(const FabricSums &other)
{
  if (other.nbins != nbins) throw std::invalid_argument("fabric: merging sums of other bins");
  PackedSums<FabricSums>::merge(other);
}

int FabricSums::pairs() const
{
  return 9 + 3 * nbins;
}

void ForceTensorSums::add(const Contact &c, const Anisotropy &fabric)
{
  add(c, fabric, std::atan2(c.ny, c.nx));
}

void ForceTensorSums::add(const Contact &c, const Anisotropy &fabric, double theta)
{
  if (!has_normal(c)) return;
  with_normal.add(1.0);
  const double density = 1.0 + fabric.a * std::cos(2.0 * theta - 2.0 * fabric.theta);
  if (!model_density_usable(density)) return;
  const double wn = c.fn / density, wt = c.ft / density;
  chi_n_xx.add(wn * (c.nx * c.nx));
  chi_n_xy.add(wn * (c.nx * c.ny));
  chi_n_yy.add(wn * (c.ny * c.ny));
  // sym(n (x) t), t = (-ny, nx)
  chi_t_xx.add(wt * (-c.nx * c.ny));
  chi_t_xy.add(wt * (0.5 * (c.nx * c.nx - c.ny * c.ny)));
  chi_t_yy.add(wt * (c.nx * c.ny));
}

void ParticleSums::add(long n, double lambda_value)
{
  particles.add(1.0);
  contact_ends.add(static_cast<double>(n));
  if (n == 0) rattlers0.add(1.0);
  if (n == 1) rattlers1.add(1.0);
  if (n >= 2) lambda.add(lambda_value);
}

Histogram histogram_of(const FabricSums &sums)
{
  const auto n = static_cast<std::size_t>(sums.nbins);
  Histogram h{sums.nbins, std::vector<double>(n, 0.0), std::vector<double>(n, 0.0),
              std::vector<double>(n, 0.0), 0};
  for (std::size_t i = 0; i < n; ++i) {
    h.count[i] = sums.bin_count[i].value();
    if (h.count[i] > 0.0) {
      h.mean_fn[i] = sums.bin_fn[i].value() / h.count[i];
      h.mean_ft[i] = sums.bin_ft[i].value() / h.count[i];
    } else {
      ++h.empty_bins;
    }
  }
  return h;
}

Anisotropy normal_anisotropy_tensor(const FabricSums &sums)
{
  const double n = sums.contacts.value() - sums.no_normal.value();
  if (!(n > 0.0)) return {0.0, 0.0};
  const Anisotropy gap =
      major_axis(sums.phi_xx.value() / n, sums.phi_xy.value() / n, sums.phi_yy.value() / n);
  return {2.0 * gap.a, gap.theta};
}

ForceAnisotropy force_anisotropy_tensor(const ForceTensorSums &sums)
{
  ForceAnisotropy result{0.0, 0.0, 0.0, 0.0, 0.0, 0};
  const double n = sums.with_normal.value();
  if (!(n > 0.0)) return result;
  const double nxx = sums.chi_n_xx.value() / n, nxy = sums.chi_n_xy.value() / n,
               nyy = sums.chi_n_yy.value() / n;
  const double f0 = nxx + nyy;
  if (!(f0 > 0.0)) return result;
  return force_anisotropy_of(
      f0, major_axis(nxx, nxy, nyy),
      major_axis(sums.chi_t_xx.value() / n, sums.chi_t_xy.value() / n, sums.chi_t_yy.value() / n));
}

Anisotropies anisotropies(const FabricSums &sums, const ForceTensorSums &tensor,
                          Estimator estimator)
{
  if (estimator == Estimator::Tensor)
    return {normal_anisotropy_tensor(sums), force_anisotropy_tensor(tensor)};
  const BinCorrection correction =
      estimator == Estimator::Published ? BinCorrection::Published : BinCorrection::Unbiased;
  const Histogram h = histogram_of(sums);
  return {normal_anisotropy_histogram(h, correction), force_anisotropy_histogram(h, correction)};
}

Eigen::Matrix2d love_weber_stress(const FabricSums &sums, double area)
{
  if (!(area > 0.0)) throw std::invalid_argument("fabric: Love-Weber area must be > 0");
  Eigen::Matrix2d sigma;
  sigma << sums.f_l_xx.value(), sums.f_l_xy.value(), sums.f_l_yx.value(), sums.f_l_yy.value();
  return sigma / area;
}

Coordination coordination(const ParticleSums &sums)
{
  Coordination r{0.0,
                 0.0,
                 static_cast<long>(sums.contact_ends.value()),
                 static_cast<long>(sums.particles.value()),
                 static_cast<long>(sums.rattlers0.value()),
                 static_cast<long>(sums.rattlers1.value())};
  if (r.n_particles == 0) return r;
  r.Cn = static_cast<double>(r.n_contacts) / static_cast<double>(r.n_particles);
  const long mechanical = r.n_particles - r.n0 - r.n1;
  if (mechanical > 0)
    r.Zm = static_cast<double>(r.n_contacts - r.n1) / static_cast<double>(mechanical);
  return r;
}

double mean_stability_index(const ParticleSums &sums, bool with_rattlers)
{
  const double rattlers = sums.rattlers0.value() + sums.rattlers1.value();
  double total = sums.lambda.value(), n = sums.particles.value() - rattlers;
  if (with_rattlers) {
    total += rattlers;
    n = sums.particles.value();
  }
  return n > 0.0 ? total / n : 0.0;
}

} // namespace fabric
