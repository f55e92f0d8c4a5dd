// The partial sums of compute fabric (fabric_sums.h): hand-worked sums, exact
// summation, the same result from one accumulator or two merged ones (as from
// two MPI ranks), and the fits from the sums against the all-contacts functions
// of fabric_statistics.h / stability_index.h (the path before the reduction).
#include "fabric_sums.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "particle_contacts.h"
#include "stability_index.h"

namespace {

using fabric::Contact;
using fabric::ExactSum;
using fabric::FabricSums;

constexpr double kPi = 3.141592653589793238462643383280;

Contact contact_at(long a, long b, double angle, double fn, double ft, double length)
{
  const double nx = std::cos(angle), ny = std::sin(angle);
  return Contact{a, b, nx, ny, fn, ft, length * nx, length * ny};
}

void expect_rel(double actual, double expected, double rtol)
{
  EXPECT_NEAR(actual, expected, rtol * std::max(1.0, std::fabs(expected)));
}

// contacts of 40 particles, anisotropic in direction and force, some walls
// (b = -1) and one without a normal
std::vector<Contact> random_contacts(unsigned seed, int n)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Contact> contacts;
  for (int k = 0; k < n; k++) {
    double angle = 2.0 * kPi * u(rng);
    angle += 0.3 * std::sin(2.0 * (angle - 0.4)); // fabric anisotropy
    const double fn = 1e3 * (1.0 + 0.5 * std::cos(2.0 * (angle - 0.7))) * (0.5 + u(rng));
    const double ft = 2e2 * (u(rng) - 0.3);
    const long a = static_cast<long>(40 * u(rng));
    const long b = k % 17 == 0 ? -1 : a + 1 + static_cast<long>(10 * u(rng));
    contacts.push_back(contact_at(a, b, angle, fn, ft, 1e-3 * (0.8 + 0.4 * u(rng))));
  }
  contacts.push_back(Contact{3, 4, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0}); // coincident centres
  return contacts;
}

TEST(ExactSum, KeepsWhatADoubleSumLoses)
{
  ExactSum s;
  for (double x : {1e16, 1.0, -1e16}) s.add(x);
  EXPECT_EQ(s.value(), 1.0);
  ExactSum t;
  t.add(0.1);
  t.add(0.2);
  t.add(-0.3);
  // the exact sum of the three doubles is 2^-55 (in doubles 0.1 + 0.2 - 0.3 = 2^-54)
  EXPECT_EQ(t.value(), std::ldexp(1.0, -55));
}

TEST(ExactSum, MergeIsOrderIndependent)
{
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<double> xs;
  for (int k = 0; k < 1000; k++) xs.push_back(u(rng) * std::pow(10.0, 8 * u(rng)));
  ExactSum forward, backward, left, right;
  for (std::size_t k = 0; k < xs.size(); k++) {
    forward.add(xs[k]);
    backward.add(xs[xs.size() - 1 - k]);
    (k % 3 == 0 ? left : right).add(xs[k]);
  }
  right.merge(left);
  EXPECT_EQ(forward.value(), backward.value());
  EXPECT_EQ(forward.value(), right.value());
}

// Hand-worked: 6 bins of 60 deg; c1 along +x (fn 2, ft 0.5, l = (1, 0)), c2
// along +y (fn 3, ft -1, l = (0, 2)), c3 without a normal.
TEST(FabricSums, HandWorkedTwoContacts)
{
  FabricSums s(6);
  s.add(Contact{1, 2, 1.0, 0.0, 2.0, 0.5, 1.0, 0.0});
  s.add(Contact{1, 3, 0.0, 1.0, 3.0, -1.0, 0.0, 2.0});
  s.add(Contact{4, 5, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0});
  EXPECT_EQ(s.contacts.value(), 3.0);
  EXPECT_EQ(s.no_normal.value(), 1.0);
  // 0 deg -> bin 0, 180 -> bin 3, 90 -> bin 1, 270 -> bin 4
  const double count[6] = {1, 1, 0, 1, 1, 0}, fn[6] = {2, 3, 0, 2, 3, 0},
               ft[6] = {0.5, -1, 0, 0.5, -1, 0};
  for (int g = 0; g < 6; g++) {
    EXPECT_EQ(s.bin_count[g].value(), count[g]) << g;
    EXPECT_DOUBLE_EQ(s.bin_fn[g].value(), fn[g]) << g;
    EXPECT_DOUBLE_EQ(s.bin_ft[g].value(), ft[g]) << g;
  }
  EXPECT_DOUBLE_EQ(s.phi_xx.value(), 1.0);
  EXPECT_DOUBLE_EQ(s.phi_yy.value(), 1.0);
  EXPECT_NEAR(s.phi_xy.value(), 0.0, 1e-16);
  // f1 = 2 (1, 0) + 0.5 (0, 1) = (2, 0.5); f2 = 3 (0, 1) - 1 (-1, 0) = (1, 3)
  // sum f l: xx = 2, xy = 0 + 1 * 2 = 2, yx = 0.5, yy = 3 * 2 = 6
  const Eigen::Matrix2d sigma = fabric::love_weber_stress(s, 2.0);
  EXPECT_DOUBLE_EQ(sigma(0, 0), 1.0);
  EXPECT_DOUBLE_EQ(sigma(0, 1), 1.0);
  EXPECT_DOUBLE_EQ(sigma(1, 0), 0.25);
  EXPECT_DOUBLE_EQ(sigma(1, 1), 3.0);
  // two orthogonal normals: isotropic fabric
  EXPECT_NEAR(fabric::normal_anisotropy_tensor(s).a, 0.0, 1e-15);
  const fabric::Histogram h = fabric::histogram_of(s);
  EXPECT_EQ(h.empty_bins, 2);
  EXPECT_DOUBLE_EQ(h.mean_fn[1], 3.0);
  EXPECT_DOUBLE_EQ(h.mean_ft[3], 0.5);
}

// Hand-worked: particles with 0, 1, 2 and 3 contacts, lambda 0.25 and 0 for the
// last two: C_n = 6/4, Z_m = (6 - 1)/(4 - 2), mean lambda 0.125, with rattlers
// (0.25 + 0 + 1 + 1)/4.
TEST(ParticleSums, HandWorked)
{
  fabric::ParticleSums s;
  s.add(0, 0.7); // lambda of a rattler is not used
  s.add(1, 0.7);
  s.add(2, 0.25);
  s.add(3, 0.0);
  const fabric::Coordination c = fabric::coordination(s);
  EXPECT_DOUBLE_EQ(c.Cn, 1.5);
  EXPECT_DOUBLE_EQ(c.Zm, 2.5);
  EXPECT_EQ(c.n0, 1);
  EXPECT_EQ(c.n1, 1);
  EXPECT_DOUBLE_EQ(fabric::mean_stability_index(s, false), 0.125);
  EXPECT_DOUBLE_EQ(fabric::mean_stability_index(s, true), 0.5625);
  EXPECT_EQ(fabric::mean_stability_index(fabric::ParticleSums(), true), 0.0);
}

// contacts on bin edges (hexagonal angles, 20-degree bins): the bin of -n is
// the bin of n plus nbins/2, so the rose is point-symmetric exactly
TEST(FabricSums, PointSymmetricOnBinEdges)
{
  FabricSums s(18);
  for (int k = 0; k < 6; k++) s.add(contact_at(1, 2, k * kPi / 3.0, 1.0 + k, 0.0, 1.0));
  for (int g = 0; g < 9; g++) {
    EXPECT_EQ(s.bin_count[g].value(), s.bin_count[g + 9].value()) << g;
    EXPECT_EQ(s.bin_fn[g].value(), s.bin_fn[g + 9].value()) << g;
  }
  double total = 0.0;
  for (const ExactSum &c : s.bin_count) total += c.value();
  EXPECT_EQ(total, 12.0);
}

// one rank's sums, or two ranks' merged: the same to round-off (here exactly)
TEST(FabricSums, SplitAndMergedEqualsOneAccumulator)
{
  const std::vector<Contact> contacts = random_contacts(11, 500);
  FabricSums all(18), first(18), second(18);
  for (std::size_t k = 0; k < contacts.size(); k++) {
    all.add(contacts[k]);
    (k % 2 == 0 || k > 400 ? first : second).add(contacts[k]);
  }
  second.merge(first);
  const std::vector<double> a = all.pack(), b = second.pack();
  ASSERT_EQ(a.size(), b.size());
  ASSERT_EQ(static_cast<int>(a.size()), 2 * all.pairs());
  for (std::size_t k = 0; k < a.size(); k += 2)
    EXPECT_NEAR(a[k] + a[k + 1], b[k] + b[k + 1], 1e-15 * std::fabs(a[k])) << k;

  fabric::ForceTensorSums t_all, t_first, t_second;
  const fabric::Anisotropy fabric_fit{0.3, 0.4};
  for (std::size_t k = 0; k < contacts.size(); k++) {
    t_all.add(contacts[k], fabric_fit);
    (k < 123 ? t_first : t_second).add(contacts[k], fabric_fit);
  }
  t_first.merge(t_second);
  const fabric::ForceAnisotropy x = fabric::force_anisotropy_tensor(t_all),
                                y = fabric::force_anisotropy_tensor(t_first);
  expect_rel(y.an, x.an, 1e-15);
  expect_rel(y.f0, x.f0, 1e-15);
  expect_rel(y.at, x.at, 1e-15);
}

TEST(FabricSums, PackUnpackIsExact)
{
  FabricSums s(12), back(12);
  for (const Contact &c : random_contacts(3, 50)) s.add(c);
  back.unpack(s.pack().data());
  EXPECT_EQ(back.pack(), s.pack());
  fabric::ParticleSums p, q;
  p.add(3, 0.1);
  q.unpack(p.pack().data());
  EXPECT_EQ(q.pack(), p.pack());
}

// the fits from the reduced sums against the old all-contacts path
TEST(FabricSums, FitsEqualTheAllContactsPath)
{
  const std::vector<Contact> contacts = random_contacts(5, 2000);
  for (int nbins : {6, 18, 36}) {
    FabricSums s(nbins);
    for (const Contact &c : contacts) s.add(c);
    const fabric::Histogram h = fabric::histogram_of(s),
                            old = fabric::polar_histogram(contacts, nbins);
    EXPECT_EQ(h.empty_bins, old.empty_bins);
    for (int g = 0; g < nbins; g++) {
      EXPECT_EQ(h.count[g], old.count[g]);
      expect_rel(h.mean_fn[g], old.mean_fn[g], 1e-12);
      expect_rel(h.mean_ft[g], old.mean_ft[g], 1e-12);
    }
    for (auto corr : {fabric::BinCorrection::Unbiased, fabric::BinCorrection::Published}) {
      const fabric::ForceAnisotropy x = fabric::force_anisotropy_histogram(h, corr),
                                    y = fabric::force_anisotropy_histogram(old, corr);
      expect_rel(x.an, y.an, 1e-12);
      expect_rel(x.theta_n, y.theta_n, 1e-12);
      expect_rel(x.f0, y.f0, 1e-12);
      expect_rel(x.at, y.at, 1e-12);
      expect_rel(x.theta_t, y.theta_t, 1e-12);
    }
  }
  FabricSums s(18);
  for (const Contact &c : contacts) s.add(c);
  const fabric::Anisotropy a = fabric::normal_anisotropy_tensor(s),
                           a_old = fabric::normal_anisotropy_tensor(contacts);
  EXPECT_GT(a.a, 0.1);
  expect_rel(a.a, a_old.a, 1e-12);
  expect_rel(a.theta, a_old.theta, 1e-12);

  fabric::ForceTensorSums t;
  for (const Contact &c : contacts) t.add(c, a);
  const fabric::ForceAnisotropy f = fabric::force_anisotropy_tensor(t),
                                f_old = fabric::force_anisotropy_tensor(contacts, a_old);
  EXPECT_GT(f.an, 0.1);
  expect_rel(f.an, f_old.an, 1e-12);
  expect_rel(f.theta_n, f_old.theta_n, 1e-12);
  expect_rel(f.f0, f_old.f0, 1e-12);
  expect_rel(f.at, f_old.at, 1e-12);
  expect_rel(f.theta_t, f_old.theta_t, 1e-12);

  for (auto estimator :
       {fabric::Estimator::Unbiased, fabric::Estimator::Published, fabric::Estimator::Tensor}) {
    const fabric::Anisotropies x = fabric::anisotropies(s, t, estimator),
                               y = fabric::anisotropies(contacts, 18, estimator);
    expect_rel(x.fabric.a, y.fabric.a, 1e-12);
    expect_rel(x.fabric.theta, y.fabric.theta, 1e-12);
    expect_rel(x.force.an, y.force.an, 1e-12);
    expect_rel(x.force.theta_n, y.force.theta_n, 1e-12);
    expect_rel(x.force.f0, y.force.f0, 1e-12);
    expect_rel(x.force.at, y.force.at, 1e-12);
    expect_rel(x.force.theta_t, y.force.theta_t, 1e-12);
    EXPECT_EQ(x.force.empty_bins, y.force.empty_bins);
  }

  const Eigen::Matrix2d sigma = fabric::love_weber_stress(s, 0.02),
                        sigma_old = fabric::love_weber_stress(contacts, 0.02);
  for (int i = 0; i < 2; i++)
    for (int j = 0; j < 2; j++) expect_rel(sigma(i, j), sigma_old(i, j), 1e-12);

  // per particle: the contact angles of each particle (as each rank collects
  // them for its owned disks), 60 particles of which some have no contact
  const fabric::ParticleContacts pc = fabric::particle_contacts(contacts);
  const long n_particles = 60;
  fabric::ParticleSums p;
  for (std::size_t p_t = 0; p_t + 1 < pc.first_contact_of.size(); p_t++) {
    const std::vector<double> angles(pc.angles.begin() + pc.first_contact_of[p_t],
                                     pc.angles.begin() + pc.first_contact_of[p_t + 1]);
    p.add(static_cast<long>(angles.size()), fabric::stability_index(angles));
  }
  for (long k = static_cast<long>(pc.tags.size()); k < n_particles; k++) p.add(0, 1.0);
  const fabric::Coordination c = fabric::coordination(p),
                             c_old = fabric::coordination(fabric::contact_counts(pc, n_particles));
  EXPECT_EQ(c.Cn, c_old.Cn);
  EXPECT_EQ(c.Zm, c_old.Zm);
  EXPECT_EQ(c.n0, c_old.n0);
  EXPECT_EQ(c.n1, c_old.n1);
  for (bool rattlers : {false, true})
    expect_rel(fabric::mean_stability_index(p, rattlers),
               fabric::mean_stability_index(pc, n_particles, rattlers), 1e-14);
}

} // namespace
