#include "fabric_statistics.h"

#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>

#include "math_constants.h"

namespace fabric {
namespace {

using math_constants::PI;
using math_constants::TWO_PI;

// ---- angles -----------------------------------------------------------------

double bin_width(int nbins)
{
  return TWO_PI / nbins;
}

// Orientation of a pi-periodic quantity from its second harmonic
// (c, s) = amplitude * (cos 2theta, sin 2theta).
Anisotropy from_second_harmonic(double c, double s)
{
  double theta = 0.5 * std::atan2(s, c);
  if (theta <= -0.5 * PI) theta += PI; // atan2(-0.0, c < 0) = -pi
  return {std::hypot(c, s), theta};
}

// For a symmetric 2x2 tensor, eigenvalue gap and major-axis direction in closed form.
Anisotropy deviator_of(const Eigen::Matrix2d &m)
{
  return from_second_harmonic(m(0, 0) - m(1, 1), 2.0 * m(0, 1));
}

// ---- histogram checks -------------------------------------------------------

void require_usable_bin_count(int nbins)
{
  if (nbins < 3 || nbins == 4)
    throw std::invalid_argument("fabric: nbins must be >= 3 and != 4, got " +
                                std::to_string(nbins));
}

void require_well_formed(const Histogram &h)
{
  require_usable_bin_count(h.nbins);
  const auto n = static_cast<std::size_t>(h.nbins);
  if (h.count.size() != n || h.mean_fn.size() != n || h.mean_ft.size() != n)
    throw std::invalid_argument("fabric: histogram vectors must have nbins entries");
}

bool is_empty_bin(const Histogram &h, int bin)
{
  return !(h.count[static_cast<std::size_t>(bin)] > 0.0);
}

// Corrects for averaging cos 2theta over a bin instead of reading it at the centre.
double bin_correction(double width, BinCorrection correction)
{
  const double ratio = width / std::sin(width);
  return correction == BinCorrection::Unbiased ? ratio : 1.0 / ratio;
}

// ---- force statistics -------------------------------------------------------

struct BinnedForceSums {
  double f0_numerator = 0.0;         // sum' fn(g) dth
  double covered_angle = 0.0;        // n' dth
  double fn_cos = 0.0, fn_sin = 0.0; // sum' fn(g) {cos,sin} 2theta_g dth
  double ft_cos = 0.0, ft_sin = 0.0; // sum' ft(g) {cos,sin} 2theta_g dth
};

BinnedForceSums sum_non_empty_bins(const Histogram &h)
{
  const double width = bin_width(h.nbins);
  BinnedForceSums sums;
  for (int g = 0; g < h.nbins; ++g) {
    if (is_empty_bin(h, g)) continue;
    const auto i = static_cast<std::size_t>(g);
    const double twice_centre = 2.0 * bin_centre(g, h.nbins);
    sums.f0_numerator += h.mean_fn[i] * width;
    sums.covered_angle += width;
    sums.fn_cos += h.mean_fn[i] * std::cos(twice_centre) * width;
    sums.fn_sin += h.mean_fn[i] * std::sin(twice_centre) * width;
    sums.ft_cos += h.mean_ft[i] * std::cos(twice_centre) * width;
    sums.ft_sin += h.mean_ft[i] * std::sin(twice_centre) * width;
  }
  return sums;
}

// Fabric density relative to isotropy, 1 + a cos 2(theta - theta_a).
double relative_fabric_density(const Contact &c, const Anisotropy &fabric)
{
  const double twice_angle = 2.0 * std::atan2(c.ny, c.nx);
  return 1.0 + fabric.a * std::cos(twice_angle - 2.0 * fabric.theta);
}

// n (x) t with t = (-ny, nx); only its symmetric part carries the a_t rose.
Eigen::Matrix2d symmetric_normal_tangent(const Contact &c)
{
  Eigen::Matrix2d m;
  m(0, 0) = -c.nx * c.ny;
  m(1, 1) = c.nx * c.ny;
  m(0, 1) = m(1, 0) = 0.5 * (c.nx * c.nx - c.ny * c.ny);
  return m;
}

Eigen::Matrix2d normal_dyad(const Contact &c)
{
  Eigen::Matrix2d m;
  m << c.nx * c.nx, c.nx * c.ny, c.nx * c.ny, c.ny * c.ny;
  return m;
}

void add_to_bin(Histogram &h, int bin, const Contact &c)
{
  const auto i = static_cast<std::size_t>(bin);
  h.count[i] += 1.0;
  h.mean_fn[i] += c.fn; // sums for now; turned into means once all are in
  h.mean_ft[i] += c.ft;
}

} // namespace

Contact make_contact(long a, long b, double lx, double ly, double fx, double fy, double radius_sum)
{
  Contact c{a, b, 0.0, 0.0, 0.0, 0.0, lx, ly};
  // hypot has no underflow for |l| ~ 1e-300 but is slow; sqrt is exact to an
  // ulp where the squares neither underflow nor overflow
  const double squared = lx * lx + ly * ly;
  const double length =
      squared > 1e-280 && squared < 1e280 ? std::sqrt(squared) : std::hypot(lx, ly);
  if (!std::isfinite(length) || !(length > kCoincidentFraction * radius_sum)) return c;
  c.nx = lx / length;
  c.ny = ly / length;
  c.fn = fx * c.nx + fy * c.ny;
  c.ft = -fx * c.ny + fy * c.nx;
  return c;
}

bool has_normal(const Contact &c)
{
  return std::isfinite(c.nx) && std::isfinite(c.ny) && (c.nx != 0.0 || c.ny != 0.0);
}

// fmod is exact, and the identity for |angle| < 2 pi (atan2's range): skipped there
double wrap_to_full_turn(double angle)
{
  double wrapped = std::fabs(angle) < TWO_PI ? angle : std::fmod(angle, TWO_PI);
  if (wrapped < 0.0) wrapped += TWO_PI;
  if (wrapped >= TWO_PI) wrapped = 0.0; // -tiny + 2pi can round up to 2pi
  return wrapped;
}

double bin_centre(int bin, int nbins)
{
  return (bin + 0.5) * bin_width(nbins);
}

int angle_bin(double angle, int nbins)
{
  if (!std::isfinite(angle) || nbins < 1) return -1;
  const double wrapped = wrap_to_full_turn(angle);
  const int bin = static_cast<int>(wrapped / bin_width(nbins));
  return bin < nbins ? bin : nbins - 1; // wrapped / width can round up to nbins
}

NormalBins::NormalBins(int nbins) : nbins_(nbins)
{
  if (nbins < 2 || nbins % 2 != 0) throw std::invalid_argument("fabric: NormalBins needs an even nbins");
  for (int k = 0; k < nbins / 2; ++k) {
    edge_x_.push_back(std::cos(k * bin_width(nbins)));
    edge_y_.push_back(std::sin(k * bin_width(nbins)));
  }
}

int NormalBins::bin(double nx, double ny) const
{
  // A unit normal at angle theta and an edge at angle e: cross = sin(theta - e),
  // with an error of a few 1e-16; angle_bin(atan2) is as close to the true
  // bin. Beyond this margin both give the true bin.
  constexpr double kMargin = 1e-12;
  if (!(std::fabs(ny) > kMargin)) return angle_bin(std::atan2(ny, nx), nbins_);
  // the lower half plane is the upper one turned by pi: nbins / 2 bins further
  const bool lower = ny < 0.0;
  const double px = lower ? -nx : nx, py = lower ? -ny : ny;
  int lo = 0, hi = nbins_ / 2; // angle in [lo w, hi w)
  while (hi - lo > 1) {
    const int mid = (lo + hi) / 2;
    const double cross = edge_x_[static_cast<std::size_t>(mid)] * py -
                         edge_y_[static_cast<std::size_t>(mid)] * px;
    if (!(std::fabs(cross) > kMargin)) return angle_bin(std::atan2(ny, nx), nbins_);
    if (cross > 0.0)
      lo = mid;
    else
      hi = mid;
  }
  return lower ? lo + nbins_ / 2 : lo;
}

MissingNormals missing_normals(const std::vector<Contact> &contacts)
{
  MissingNormals missing{0, -1};
  for (std::size_t c = 0; c < contacts.size(); ++c)
    if (!has_normal(contacts[c]) && missing.count++ == 0) missing.first = static_cast<long>(c);
  return missing;
}

Histogram polar_histogram(const std::vector<Contact> &contacts, int nbins)
{
  require_usable_bin_count(nbins);
  const auto n = static_cast<std::size_t>(nbins);
  Histogram h{nbins, std::vector<double>(n, 0.0), std::vector<double>(n, 0.0),
              std::vector<double>(n, 0.0), 0};

  for (const Contact &c : contacts) {
    if (!has_normal(c)) continue;
    for (double angle : {std::atan2(c.ny, c.nx), std::atan2(-c.ny, -c.nx)}) { // same fn, ft
      const int bin = angle_bin(angle, nbins);
      if (bin >= 0) add_to_bin(h, bin, c);
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (h.count[i] > 0.0) {
      h.mean_fn[i] /= h.count[i];
      h.mean_ft[i] /= h.count[i];
    } else {
      ++h.empty_bins;
    }
  }
  return h;
}

Anisotropy normal_anisotropy_histogram(const Histogram &h, BinCorrection correction)
{
  require_well_formed(h);
  const double width = bin_width(h.nbins);
  double total = 0.0, cos_sum = 0.0, sin_sum = 0.0;
  for (int g = 0; g < h.nbins; ++g) {
    const double count = h.count[static_cast<std::size_t>(g)];
    const double twice_centre = 2.0 * bin_centre(g, h.nbins);
    total += count;
    cos_sum += count * std::cos(twice_centre);
    sin_sum += count * std::sin(twice_centre);
  }
  if (!(total > 0.0)) return {0.0, 0.0};
  const double prefactor = 2.0 / total * bin_correction(width, correction);
  return from_second_harmonic(prefactor * cos_sum, prefactor * sin_sum);
}

Anisotropy normal_anisotropy_tensor(const std::vector<Contact> &contacts)
{
  Eigen::Matrix2d phi = Eigen::Matrix2d::Zero();
  long n = 0;
  for (const Contact &c : contacts) {
    if (!has_normal(c)) continue;
    phi += normal_dyad(c);
    ++n;
  }
  if (n == 0) return {0.0, 0.0};
  phi /= static_cast<double>(n);
  const Anisotropy gap = deviator_of(phi);
  return {2.0 * gap.a, gap.theta};
}

ForceAnisotropy force_anisotropy_histogram(const Histogram &h, BinCorrection correction)
{
  require_well_formed(h);
  const BinnedForceSums sums = sum_non_empty_bins(h);
  ForceAnisotropy result{0.0, 0.0, 0.0, 0.0, 0.0, h.empty_bins};
  if (!(sums.covered_angle > 0.0)) return result;
  const double f0 = sums.f0_numerator / sums.covered_angle;
  if (!(f0 > 0.0)) return result;

  const double scale = bin_correction(bin_width(h.nbins), correction) / (PI * f0);
  const Anisotropy normal = from_second_harmonic(scale * sums.fn_cos, scale * sums.fn_sin);
  const Anisotropy tangential = from_second_harmonic(-scale * sums.ft_sin, scale * sums.ft_cos);
  result.an = normal.a;
  result.theta_n = normal.theta;
  result.f0 = f0;
  result.at = tangential.a;
  result.theta_t = tangential.theta;
  return result;
}

ForceAnisotropy force_anisotropy_tensor(const std::vector<Contact> &contacts,
                                        const Anisotropy &fabric)
{
  ForceAnisotropy result{0.0, 0.0, 0.0, 0.0, 0.0, 0};
  Eigen::Matrix2d chi_n = Eigen::Matrix2d::Zero();
  Eigen::Matrix2d chi_t = Eigen::Matrix2d::Zero();
  long with_normal = 0;
  for (const Contact &c : contacts) {
    if (!has_normal(c)) continue;
    ++with_normal;
    const double density = relative_fabric_density(c, fabric);
    if (!model_density_usable(density)) continue;
    chi_n += (c.fn / density) * normal_dyad(c);
    chi_t += (c.ft / density) * symmetric_normal_tangent(c);
  }
  if (with_normal == 0) return result;
  const double n = static_cast<double>(with_normal);
  chi_n /= n;
  chi_t /= n;

  const double f0 = chi_n.trace();
  if (!(f0 > 0.0)) return result;
  return force_anisotropy_of(f0, deviator_of(chi_n), deviator_of(chi_t));
}

ForceAnisotropy force_anisotropy_of(double f0, const Anisotropy &normal,
                                    const Anisotropy &tangential)
{
  return ForceAnisotropy{2.0 * normal.a / f0,     normal.theta,     f0,
                         2.0 * tangential.a / f0, tangential.theta, 0};
}

Anisotropies anisotropies(const std::vector<Contact> &contacts, int nbins, Estimator estimator)
{
  if (estimator == Estimator::Tensor) {
    const Anisotropy fabric = normal_anisotropy_tensor(contacts);
    return {fabric, force_anisotropy_tensor(contacts, fabric)};
  }
  const BinCorrection correction =
      estimator == Estimator::Published ? BinCorrection::Published : BinCorrection::Unbiased;
  const Histogram h = polar_histogram(contacts, nbins);
  return {normal_anisotropy_histogram(h, correction), force_anisotropy_histogram(h, correction)};
}

Coordination coordination(const std::vector<int> &contacts_per_particle)
{
  Coordination result{0.0, 0.0, 0, 0, 0, 0};
  for (int count : contacts_per_particle) {
    if (count < 0) throw std::invalid_argument("fabric: negative contact count");
    result.n_contacts += count;
    if (count == 0) ++result.n0;
    if (count == 1) ++result.n1;
  }
  result.n_particles = static_cast<long>(contacts_per_particle.size());
  if (result.n_particles == 0) return result;

  result.Cn = static_cast<double>(result.n_contacts) / static_cast<double>(result.n_particles);
  const long mechanical_particles = result.n_particles - result.n0 - result.n1;
  if (mechanical_particles > 0)
    result.Zm = static_cast<double>(result.n_contacts - result.n1) /
                static_cast<double>(mechanical_particles);
  return result;
}

Eigen::Matrix2d love_weber_stress(const std::vector<Contact> &contacts, double area)
{
  if (!(area > 0.0)) throw std::invalid_argument("fabric: Love-Weber area must be > 0");
  Eigen::Matrix2d sigma = Eigen::Matrix2d::Zero();
  for (const Contact &c : contacts) {
    if (!has_normal(c)) continue;
    const Eigen::Vector2d normal(c.nx, c.ny);
    const Eigen::Vector2d tangent(-c.ny, c.nx);
    const Eigen::Vector2d force = c.fn * normal + c.ft * tangent;
    sigma += force * Eigen::Vector2d(c.lx, c.ly).transpose();
  }
  return sigma / area;
}

} // namespace fabric
