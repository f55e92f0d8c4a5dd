// Fabric statistics (doc/compute_fabric.md) against exact cases: model-exact
// binned data, quadratures on which the trigonometric sums vanish exactly,
// hand-worked lattices, and an independent eigen-solver route.
#include "fabric_statistics.h"

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

namespace {

using fabric::BinCorrection;
using fabric::Contact;

constexpr double kPi = 3.141592653589793238462643383280;
constexpr double kTol = 1e-12;

double deg(double degrees)
{
  return degrees * kPi / 180.0;
}

// Contact of particle 0 with particle 1 in direction `angle`, branch length `length`.
Contact contact_at(double angle, double fn, double ft = 0.0, double length = 1.0)
{
  const double nx = std::cos(angle), ny = std::sin(angle);
  return Contact{0, 1, nx, ny, fn, ft, length * nx, length * ny};
}

// Orientations of pi-periodic quantities are equal modulo pi.
void expect_same_axis(double actual, double expected, double tol)
{
  EXPECT_NEAR(std::remainder(actual - expected, kPi), 0.0, tol)
      << "actual " << actual << " expected " << expected;
}

void expect_in_half_open_range(double theta)
{
  EXPECT_GT(theta, -kPi / 2);
  EXPECT_LE(theta, kPi / 2);
}

// Exact bin integrals of E(th) = (1/2pi)[1 + a cos 2(th - th_a)] times N.
fabric::Histogram model_count_histogram(int nbins, double total, double a, double theta_a)
{
  const double width = 2.0 * kPi / nbins;
  fabric::Histogram h{
      nbins, {}, std::vector<double>(nbins, 1.0), std::vector<double>(nbins, 0.0), 0};
  for (int g = 0; g < nbins; ++g) {
    const double centre = (g + 0.5) * width;
    h.count.push_back(total / (2.0 * kPi) *
                      (width + a * std::sin(width) * std::cos(2.0 * (centre - theta_a))));
  }
  return h;
}

// The same N contacts, uniformly spaced over the half circle (their -n copies fill
// the other half): (j + 1/2) pi / N. With N a multiple of nbins/2 every bin holds
// the same number of contacts placed symmetrically about its centre.
std::vector<double> uniform_half_circle(int n)
{
  std::vector<double> angles;
  for (int j = 0; j < n; ++j) angles.push_back((j + 0.5) * kPi / n);
  return angles;
}

// Integer multiplicities 4 [1 + a cos 2(th - th_a)] at th_a + k 30 deg for a = 1/2:
// a six-point quadrature of E(th) on which sum cos 2th_k and sum cos 4th_k vanish,
// so the tensors of these contacts equal those of the continuous model exactly.
std::vector<double> model_fabric_angles(double theta_a)
{
  const int multiplicity[6] = {6, 5, 3, 2, 3, 5};
  std::vector<double> angles;
  for (int k = 0; k < 6; ++k)
    for (int copy = 0; copy < multiplicity[k]; ++copy) angles.push_back(theta_a + deg(30.0 * k));
  return angles;
}

double model_normal_force(double angle, double f0, double an, double theta_n)
{
  return f0 * (1.0 + an * std::cos(2.0 * (angle - theta_n)));
}

double model_tangential_force(double angle, double f0, double at, double theta_t)
{
  return -f0 * at * std::sin(2.0 * (angle - theta_t));
}

// ---- polar histogram --------------------------------------------------------

TEST(PolarHistogram, ContactFillsItsBinAndTheOppositeOne)
{
  const fabric::Histogram h = fabric::polar_histogram({contact_at(deg(10), 2.0, 0.5)}, 18);
  ASSERT_EQ(h.nbins, 18);
  ASSERT_EQ(h.count.size(), 18u);
  EXPECT_EQ(h.count[0], 1.0);
  EXPECT_EQ(h.count[9], 1.0); // 190 deg
  for (int bin : {0, 9}) {
    EXPECT_EQ(h.mean_fn[bin], 2.0);
    EXPECT_EQ(h.mean_ft[bin], 0.5); // the -n copy keeps ft (see Contact::ft)
  }
  EXPECT_EQ(h.empty_bins, 16);
}

TEST(PolarHistogram, BinsHoldMeanForces)
{
  const fabric::Histogram h = fabric::polar_histogram(
      {contact_at(deg(5), 1.0, -1.0), contact_at(deg(15), 3.0, 2.0), contact_at(deg(100), 7.0)},
      18);
  EXPECT_EQ(h.count[0], 2.0);
  EXPECT_DOUBLE_EQ(h.mean_fn[0], 2.0);
  EXPECT_DOUBLE_EQ(h.mean_ft[0], 0.5);
  EXPECT_EQ(h.count[5], 1.0);  // 100 deg
  EXPECT_EQ(h.count[14], 1.0); // 280 deg
  EXPECT_EQ(h.mean_fn[14], 7.0);
  EXPECT_EQ(h.empty_bins, 14);
}

TEST(PolarHistogram, RejectsBinCountsThatCannotSeeTheFabric)
{
  for (int nbins : {-1, 0, 1, 2, 4})
    EXPECT_THROW(fabric::polar_histogram({}, nbins), std::invalid_argument) << nbins;
  EXPECT_NO_THROW(fabric::polar_histogram({}, 3));
}

// ---- normal anisotropy: histogram --------------------------------------------

TEST(NormalAnisotropyHistogram, UnbiasedRecoversTheModelFromExactBinIntegrals)
{
  for (double theta_a : {deg(20), deg(-70), deg(90)}) {
    const fabric::Histogram h = model_count_histogram(18, 1000.0, 0.3, theta_a);
    const fabric::Anisotropy f = fabric::normal_anisotropy_histogram(h, BinCorrection::Unbiased);
    EXPECT_NEAR(f.a, 0.3, kTol);
    expect_same_axis(f.theta, theta_a, kTol);
    expect_in_half_open_range(f.theta);
  }
}

TEST(NormalAnisotropyHistogram, UnbiasedIsTheDefault)
{
  const fabric::Histogram h = model_count_histogram(18, 1000.0, 0.3, deg(20));
  EXPECT_EQ(fabric::normal_anisotropy_histogram(h).a,
            fabric::normal_anisotropy_histogram(h, BinCorrection::Unbiased).a);
}

// Published prefactor 2 sin(dth)/(N dth) vs unbiased 2 dth/(N sin dth): ratio
// (sin dth / dth)^2. For 18 bins dth = 20 deg: (0.3420201/0.3490659)^2 = 0.960038,
// i.e. a is 4.0 % low; the orientation is unaffected.
TEST(NormalAnisotropyHistogram, PublishedPrefactorIsLowBySquaredSincOfBinWidth)
{
  const double width = deg(20);
  const double ratio = std::pow(std::sin(width) / width, 2);
  EXPECT_NEAR(ratio, 0.960038, 1e-6);

  const fabric::Histogram h = model_count_histogram(18, 1000.0, 0.3, deg(20));
  const fabric::Anisotropy published =
      fabric::normal_anisotropy_histogram(h, BinCorrection::Published);
  EXPECT_NEAR(published.a, 0.3 * ratio, kTol);
  expect_same_axis(published.theta, deg(20), kTol);
}

TEST(NormalAnisotropyHistogram, WorksForOddBinCounts)
{
  const fabric::Histogram h = model_count_histogram(7, 500.0, 0.45, deg(-33));
  const fabric::Anisotropy f = fabric::normal_anisotropy_histogram(h);
  EXPECT_NEAR(f.a, 0.45, kTol);
  expect_same_axis(f.theta, deg(-33), kTol);
}

TEST(NormalAnisotropyHistogram, RejectsMalformedHistograms)
{
  fabric::Histogram h = model_count_histogram(18, 10.0, 0.0, 0.0);
  h.count.pop_back();
  EXPECT_THROW(fabric::normal_anisotropy_histogram(h), std::invalid_argument);
  fabric::Histogram four = model_count_histogram(4, 10.0, 0.0, 0.0);
  EXPECT_THROW(fabric::normal_anisotropy_histogram(four), std::invalid_argument);
}

// ---- normal anisotropy: tensor -----------------------------------------------

TEST(NormalAnisotropyTensor, ModelQuadratureGivesExactAnisotropy)
{
  for (double theta_a : {deg(20), deg(-50), deg(90)}) {
    std::vector<Contact> contacts;
    for (double angle : model_fabric_angles(theta_a)) contacts.push_back(contact_at(angle, 1.0));
    const fabric::Anisotropy f = fabric::normal_anisotropy_tensor(contacts);
    EXPECT_NEAR(f.a, 0.5, kTol);
    expect_same_axis(f.theta, theta_a, kTol);
    expect_in_half_open_range(f.theta);
  }
}

// Independent route: build phi, solve with Eigen, a = 2 (lambda_max - lambda_min).
TEST(NormalAnisotropyTensor, RandomContactsMatchAnEigenSolver)
{
  std::mt19937 rng(20240611);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::vector<Contact> contacts;
  while (contacts.size() < 500) { // rejection-sample E with a = 0.4, th_a = 35 deg
    const double angle = 2.0 * kPi * uniform(rng);
    if (1.4 * uniform(rng) < 1.0 + 0.4 * std::cos(2.0 * (angle - deg(35))))
      contacts.push_back(contact_at(angle, 1.0));
  }
  Eigen::Matrix2d phi = Eigen::Matrix2d::Zero();
  for (const Contact &c : contacts) {
    const Eigen::Vector2d n(c.nx, c.ny);
    phi += n * n.transpose();
  }
  phi /= static_cast<double>(contacts.size());
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> solver(phi);
  const double expected_a = 2.0 * (solver.eigenvalues()(1) - solver.eigenvalues()(0));
  const Eigen::Vector2d major = solver.eigenvectors().col(1);

  const fabric::Anisotropy f = fabric::normal_anisotropy_tensor(contacts);
  EXPECT_NEAR(f.a, expected_a, kTol);
  expect_same_axis(f.theta, std::atan2(major.y(), major.x()), 1e-10);
  EXPECT_NEAR(f.a, 0.4, 0.15); // sanity: the sample looks like its density
}

// With the bin width -> 0 the histogram estimate becomes the tensor one. Reading
// cos 2th at the bin centre instead of at th errs by at most dth per entry and
// the prefactor dth/sin dth by O(dth^2), so |a_hist - a_tensor| <= 2 dth (loose).
TEST(NormalAnisotropyTensor, IsTheFineBinLimitOfTheHistogram)
{
  std::mt19937 rng(99);
  std::uniform_real_distribution<double> angle(0.0, 2.0 * kPi);
  std::vector<Contact> contacts;
  for (int i = 0; i < 300; ++i) contacts.push_back(contact_at(angle(rng), 1.0));
  const int nbins = 3600;
  const fabric::Anisotropy binned =
      fabric::normal_anisotropy_histogram(fabric::polar_histogram(contacts, nbins));
  const fabric::Anisotropy tensor = fabric::normal_anisotropy_tensor(contacts);
  EXPECT_NEAR(binned.a, tensor.a, 2.0 * 2.0 * kPi / nbins);
  expect_same_axis(binned.theta, tensor.theta, 0.05);
}

// ---- force anisotropy ---------------------------------------------------------

// Hexagonal packing under isotropic load, contacts at the 6-bin centres 30, 90,
// 150 deg (+ copies at 210, 270, 330): one entry per bin, all fn equal.
TEST(ForceAnisotropy, HexagonalPackingUnderIsotropicLoad)
{
  const double fn = 5.0;
  const std::vector<Contact> contacts = {contact_at(deg(30), fn), contact_at(deg(90), fn),
                                         contact_at(deg(150), fn)};
  const fabric::Histogram h = fabric::polar_histogram(contacts, 6);
  for (int g = 0; g < 6; ++g) EXPECT_EQ(h.count[g], 1.0) << g;
  const fabric::ForceAnisotropy binned = fabric::force_anisotropy_histogram(h);
  EXPECT_NEAR(binned.an, 0.0, kTol);
  EXPECT_NEAR(binned.f0, fn, kTol);
  EXPECT_NEAR(binned.at, 0.0, kTol);
  EXPECT_EQ(binned.empty_bins, 0);

  const fabric::Anisotropy fabric_tensor = fabric::normal_anisotropy_tensor(contacts);
  EXPECT_NEAR(fabric_tensor.a, 0.0, kTol);
  EXPECT_NEAR(fabric::normal_anisotropy_histogram(h).a, 0.0, kTol);
  const fabric::ForceAnisotropy tensor = fabric::force_anisotropy_tensor(contacts, fabric_tensor);
  EXPECT_NEAR(tensor.an, 0.0, kTol);
  EXPECT_NEAR(tensor.f0, fn, kTol);
  EXPECT_NEAR(tensor.at, 0.0, kTol);
}

// 1800 contacts spaced 0.1 deg over the half circle carry the model roses.
// Histogram (18 bins): each bin holds m = 200 points spaced h = dth/m
// symmetrically about its centre, so a bin mean holds cos 2(th_g - th_n) times
// the discrete average sin(dth)/(m sin h) instead of the continuous sin(dth)/dth;
// the unbiased estimate is therefore an * h / sin h (exact), i.e. an to a relative
// h^2/6 = 5.1e-7. Orientation and f0 are unaffected (sums over whole periods).
// Tensor: the discrete sums over these points are exact, so all five values are.
TEST(ForceAnisotropy, DenseUniformSetRecoversTheModelRoses)
{
  const double f0 = 2.5, an = 0.4, theta_n = deg(25), at = 0.15, theta_t = deg(-35);
  const int n = 1800, nbins = 18;
  std::vector<Contact> contacts;
  for (double angle : uniform_half_circle(n))
    contacts.push_back(contact_at(angle, model_normal_force(angle, f0, an, theta_n),
                                  model_tangential_force(angle, f0, at, theta_t)));

  const double step = (2.0 * kPi / nbins) / (n / (nbins / 2));
  const double discrete_factor = step / std::sin(step);
  EXPECT_LT(discrete_factor - 1.0, 6e-7);
  const fabric::ForceAnisotropy binned =
      fabric::force_anisotropy_histogram(fabric::polar_histogram(contacts, nbins));
  EXPECT_EQ(binned.empty_bins, 0);
  EXPECT_NEAR(binned.f0, f0, kTol);
  EXPECT_NEAR(binned.an, an * discrete_factor, kTol);
  EXPECT_NEAR(binned.an, an, 1e-6 * an);
  expect_same_axis(binned.theta_n, theta_n, kTol);
  EXPECT_NEAR(binned.at, at * discrete_factor, kTol);
  EXPECT_NEAR(binned.at, at, 1e-6 * at);
  expect_same_axis(binned.theta_t, theta_t, kTol);

  const fabric::Anisotropy fabric_tensor = fabric::normal_anisotropy_tensor(contacts);
  EXPECT_NEAR(fabric_tensor.a, 0.0, kTol);
  const fabric::ForceAnisotropy tensor = fabric::force_anisotropy_tensor(contacts, fabric_tensor);
  EXPECT_NEAR(tensor.f0, f0, kTol);
  EXPECT_NEAR(tensor.an, an, kTol);
  expect_same_axis(tensor.theta_n, theta_n, kTol);
  EXPECT_NEAR(tensor.at, at, kTol);
  expect_same_axis(tensor.theta_t, theta_t, kTol);
  expect_in_half_open_range(tensor.theta_n);
  expect_in_half_open_range(tensor.theta_t);
}

// Anisotropic fabric (a = 1/2, quadrature above) carrying the model roses: the
// 1/(1 + a cos 2(th - th_a)) weight makes the force tensor see the mean-force rose
// exactly; without it the fabric leaks into an.
TEST(ForceAnisotropy, TensorRemovesTheFabricFromTheForceRose)
{
  const double f0 = 1.7, an = 0.3, theta_n = deg(50), at = 0.1, theta_t = deg(10);
  std::vector<Contact> contacts;
  for (double angle : model_fabric_angles(deg(20)))
    contacts.push_back(contact_at(angle, model_normal_force(angle, f0, an, theta_n),
                                  model_tangential_force(angle, f0, at, theta_t)));
  const fabric::Anisotropy fabric_tensor = fabric::normal_anisotropy_tensor(contacts);
  ASSERT_NEAR(fabric_tensor.a, 0.5, kTol);

  const fabric::ForceAnisotropy tensor = fabric::force_anisotropy_tensor(contacts, fabric_tensor);
  EXPECT_NEAR(tensor.f0, f0, kTol);
  EXPECT_NEAR(tensor.an, an, kTol);
  expect_same_axis(tensor.theta_n, theta_n, kTol);
  EXPECT_NEAR(tensor.at, at, kTol);
  expect_same_axis(tensor.theta_t, theta_t, kTol);

  const fabric::ForceAnisotropy uncorrected = fabric::force_anisotropy_tensor(contacts, {0.0, 0.0});
  EXPECT_GT(std::fabs(uncorrected.an - an), 0.05);
}

// Model bin means f(g) = f0 [1 + an (sin dth/dth) cos 2(th_g - th_n)] (the exact
// bin average of the rose); published correction is low by (sin dth/dth)^2.
TEST(ForceAnisotropy, HistogramCorrectionsOnExactBinMeans)
{
  const int nbins = 18;
  const double width = 2.0 * kPi / nbins, sinc = std::sin(width) / width;
  const double f0 = 3.0, an = 0.5, theta_n = deg(-40);
  fabric::Histogram h{
      nbins, std::vector<double>(nbins, 4.0), {}, std::vector<double>(nbins, 0.0), 0};
  for (int g = 0; g < nbins; ++g)
    h.mean_fn.push_back(f0 * (1.0 + an * sinc * std::cos(2.0 * ((g + 0.5) * width - theta_n))));

  const fabric::ForceAnisotropy unbiased = fabric::force_anisotropy_histogram(h);
  EXPECT_NEAR(unbiased.f0, f0, kTol);
  EXPECT_NEAR(unbiased.an, an, kTol);
  expect_same_axis(unbiased.theta_n, theta_n, kTol);
  const fabric::ForceAnisotropy published =
      fabric::force_anisotropy_histogram(h, BinCorrection::Published);
  EXPECT_NEAR(published.an, an * sinc * sinc, kTol);
}

// One empty bin among 18 equal ones: left out, and f0 normalised by the 17 bins'
// angle, so f0 stays the common mean (not 17/18 of it).
TEST(ForceAnisotropy, EmptyBinsAreLeftOutAndReported)
{
  const int nbins = 18;
  fabric::Histogram h{nbins, std::vector<double>(nbins, 10.0), std::vector<double>(nbins, 3.0),
                      std::vector<double>(nbins, 0.0), 1};
  h.count[4] = 0.0;
  h.mean_fn[4] = 0.0;
  const fabric::ForceAnisotropy f = fabric::force_anisotropy_histogram(h);
  EXPECT_EQ(f.empty_bins, 1);
  EXPECT_NEAR(f.f0, 3.0, kTol);
  EXPECT_TRUE(std::isfinite(f.an));
  EXPECT_TRUE(std::isfinite(f.theta_n));
}

TEST(ForceAnisotropy, ZeroForcesGiveZerosNotNaN)
{
  const std::vector<Contact> contacts = {contact_at(deg(10), 0.0), contact_at(deg(70), 0.0)};
  const fabric::ForceAnisotropy binned =
      fabric::force_anisotropy_histogram(fabric::polar_histogram(contacts, 18));
  const fabric::ForceAnisotropy tensor =
      fabric::force_anisotropy_tensor(contacts, fabric::normal_anisotropy_tensor(contacts));
  for (const fabric::ForceAnisotropy &f : {binned, tensor}) {
    EXPECT_EQ(f.an, 0.0);
    EXPECT_EQ(f.f0, 0.0);
    EXPECT_EQ(f.at, 0.0);
    EXPECT_EQ(f.theta_n, 0.0);
  }
}

// ---- coordination -------------------------------------------------------------

// {0,1,3,3,3,2}: sum 12 over 6 particles -> Cn = 2; one with 0 and one with 1
// contact -> Zm = (12 - 1)/(6 - 1 - 1) = 2.75.
TEST(Coordination, HandWorkedExampleWithRattlers)
{
  const fabric::Coordination c = fabric::coordination({0, 1, 3, 3, 3, 2});
  EXPECT_DOUBLE_EQ(c.Cn, 2.0);
  EXPECT_DOUBLE_EQ(c.Zm, 2.75);
  EXPECT_EQ(c.n_contacts, 12);
  EXPECT_EQ(c.n_particles, 6);
  EXPECT_EQ(c.n0, 1);
  EXPECT_EQ(c.n1, 1);
}

TEST(Coordination, OnlyRattlersGiveZeroMechanicalCoordination)
{
  const fabric::Coordination c = fabric::coordination({0, 0, 1});
  EXPECT_DOUBLE_EQ(c.Cn, 1.0 / 3.0);
  EXPECT_EQ(c.Zm, 0.0);
}

TEST(Coordination, RejectsNegativeCounts)
{
  EXPECT_THROW(fabric::coordination({2, -1}), std::invalid_argument);
}

// ---- Love-Weber stress --------------------------------------------------------

// Square lattice of disks radius r, spacing 2r: per particle one cell of area 4r^2
// and two owned contacts (+x, +y) with branch 2r and force F:
// sigma_xx = sigma_yy = F 2r / 4r^2 = F/(2r) = 3000 for F = 3, r = 0.5e-3.
TEST(LoveWeber, SquareLatticeUnderEqualContactForces)
{
  const double r = 0.5e-3, force = 3.0;
  const Eigen::Matrix2d sigma = fabric::love_weber_stress(
      {contact_at(0.0, force, 0.0, 2 * r), contact_at(deg(90), force, 0.0, 2 * r)}, 4 * r * r);
  EXPECT_NEAR(sigma(0, 0), 3000.0, 1e-9);
  EXPECT_NEAR(sigma(1, 1), 3000.0, 1e-9);
  EXPECT_NEAR(sigma(0, 1), 0.0, 1e-9);
  EXPECT_NEAR(sigma(1, 0), 0.0, 1e-9);
}

// Hexagonal packing: per particle a cell of area 2 sqrt(3) r^2 and three owned
// contacts at 0, 60, 120 deg. sum n n^T over them = (3/2) I, so
// sigma = F 2r (3/2) / (2 sqrt(3) r^2) I = sqrt(3) F / (2 r) I.
TEST(LoveWeber, HexagonalCellIsIsotropic)
{
  const double r = 2.0, force = 7.0;
  const std::vector<Contact> contacts = {contact_at(0.0, force, 0.0, 2 * r),
                                         contact_at(deg(60), force, 0.0, 2 * r),
                                         contact_at(deg(120), force, 0.0, 2 * r)};
  const Eigen::Matrix2d sigma = fabric::love_weber_stress(contacts, 2.0 * std::sqrt(3.0) * r * r);
  const double expected = std::sqrt(3.0) * force / (2.0 * r);
  EXPECT_NEAR(sigma(0, 0), expected, kTol);
  EXPECT_NEAR(sigma(1, 1), expected, kTol);
  EXPECT_NEAR(sigma(0, 1), 0.0, kTol);
  EXPECT_NEAR(sigma(1, 0), 0.0, kTol);
}

// Row index = force, column = branch: a contact along x with a tangential force
// ft (along +y) gives sigma_yx = ft L / A and sigma_xy = 0.
TEST(LoveWeber, ForceIsTheRowIndex)
{
  const Eigen::Matrix2d sigma = fabric::love_weber_stress({contact_at(0.0, 2.0, 0.5, 3.0)}, 1.5);
  EXPECT_NEAR(sigma(0, 0), 2.0 * 3.0 / 1.5, kTol);
  EXPECT_NEAR(sigma(1, 0), 0.5 * 3.0 / 1.5, kTol);
  EXPECT_NEAR(sigma(0, 1), 0.0, kTol);
  EXPECT_NEAR(sigma(1, 1), 0.0, kTol);
}

TEST(LoveWeber, CentralForcesGiveASymmetricTensor)
{
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> angle(0.0, 2.0 * kPi), magnitude(0.1, 2.0);
  std::vector<Contact> contacts;
  for (int i = 0; i < 100; ++i)
    contacts.push_back(contact_at(angle(rng), magnitude(rng), 0.0, magnitude(rng)));
  const Eigen::Matrix2d sigma = fabric::love_weber_stress(contacts, 10.0);
  EXPECT_NEAR(sigma(0, 1), sigma(1, 0), 1e-12 * sigma.norm());
  EXPECT_GT(sigma.trace(), 0.0); // repulsive contacts: compression positive
}

// A column of disks (radius r, period 2r in y) between walls at x = +-r pushing
// with F each, and vertical contacts carrying P. Wall contacts use the branch to
// the contact point (length r). Cell area 4r^2:
//   sigma_xx = 2 F r / 4r^2 = F/(2r): the wall force per unit height, as it must;
//   sigma_yy = P 2r / 4r^2 = P/(2r).
// A branch of 2r (to a mirror centre) would double sigma_xx.
TEST(LoveWeber, WallContactsGiveTheWallTraction)
{
  const double r = 0.25, wall_force = 4.0, vertical_force = 1.0;
  const Contact right_wall{0, -1, 1.0, 0.0, wall_force, 0.0, r, 0.0};
  const Contact left_wall{0, -1, -1.0, 0.0, wall_force, 0.0, -r, 0.0};
  const Contact above{0, 1, 0.0, 1.0, vertical_force, 0.0, 0.0, 2 * r};
  const Eigen::Matrix2d sigma =
      fabric::love_weber_stress({right_wall, left_wall, above}, 4 * r * r);
  EXPECT_NEAR(sigma(0, 0), wall_force / (2 * r), kTol);
  EXPECT_NEAR(sigma(1, 1), vertical_force / (2 * r), kTol);
  EXPECT_NEAR(sigma(0, 1), 0.0, kTol);
}

TEST(LoveWeber, RejectsNonPositiveArea)
{
  EXPECT_THROW(fabric::love_weber_stress({}, 0.0), std::invalid_argument);
  EXPECT_THROW(fabric::love_weber_stress({}, -1.0), std::invalid_argument);
}

// ---- contacts without a normal (coincident centres) ----------------------------

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(AngleBin, NonFiniteAnglesHaveNoBin)
{
  for (double angle : {kNaN, kInf, -kInf}) EXPECT_EQ(fabric::angle_bin(angle, 18), -1) << angle;
  EXPECT_EQ(fabric::angle_bin(0.5, 0), -1);
}

TEST(AngleBin, AnyFiniteAngleIsInRange)
{
  EXPECT_EQ(fabric::angle_bin(0.0, 18), 0);
  EXPECT_EQ(fabric::angle_bin(deg(10), 18), 0);
  EXPECT_EQ(fabric::angle_bin(deg(190), 18), 9);
  EXPECT_EQ(fabric::angle_bin(deg(-10), 18), 17);
  EXPECT_EQ(fabric::angle_bin(2.0 * kPi, 18), 0);
  EXPECT_EQ(fabric::angle_bin(-1e-17, 18), 0); // -tiny + 2 pi rounds to 2 pi
  EXPECT_EQ(fabric::angle_bin(std::nextafter(2.0 * kPi, 0.0), 18), 17);
  for (double angle : {1e300, -1e300, 1e-300, -1e-300, 4.0 * kPi + 0.1, -7.5}) {
    const int bin = fabric::angle_bin(angle, 36);
    EXPECT_GE(bin, 0) << angle;
    EXPECT_LT(bin, 36) << angle;
  }
}

// NormalBins must give angle_bin(atan2) bit for bit: random normals, normals
// on and a few ulps beside every bin edge, the axes and signed zeros.
TEST(NormalBins, SameBinAsAngleBinOfAtan2)
{
  std::mt19937_64 rng(20261202);
  std::uniform_real_distribution<double> angle(-kPi, kPi);
  for (int nbins : {2, 6, 8, 12, 18, 36, 72, 360}) {
    const fabric::NormalBins bins(nbins);
    std::vector<double> angles;
    for (int k = 0; k < 20000; ++k) angles.push_back(angle(rng));
    for (int k = -nbins; k <= nbins; ++k) {
      double edge = k * (2.0 * kPi / nbins);
      for (int step = 0; step < 4; ++step) {
        angles.push_back(edge);
        angles.push_back(-edge);
        edge = std::nextafter(edge, 10.0);
      }
      for (double off : {1e-13, 1e-12, 2e-12, 1e-9})
        for (double sign : {-1.0, 1.0}) angles.push_back(k * (2.0 * kPi / nbins) + sign * off);
    }
    for (double a : angles) {
      const double nx = std::cos(a), ny = std::sin(a);
      ASSERT_EQ(bins.bin(nx, ny), fabric::angle_bin(std::atan2(ny, nx), nbins))
          << nbins << " bins, angle " << a;
    }
    for (double nx : {1.0, -1.0, 0.0, -0.0})
      for (double ny : {1.0, -1.0, 0.0, -0.0})
        if (nx != 0.0 || ny != 0.0) {
          EXPECT_EQ(bins.bin(nx, ny), fabric::angle_bin(std::atan2(ny, nx), nbins))
              << nbins << " bins, " << nx << " " << ny;
        }
  }
}

TEST(NormalBins, OnlyForAnEvenNumberOfBins)
{
  EXPECT_THROW(fabric::NormalBins(7), std::invalid_argument);
  EXPECT_THROW(fabric::NormalBins(0), std::invalid_argument);
}

TEST(MakeContact, NormalAndForceComponents)
{
  // l along +y, force on b (3, 4): fn = f.n = 4, ft = f.t with t = (-1, 0): -3
  const Contact c = fabric::make_contact(1, 2, 0.0, 0.002, 3.0, 4.0, 0.002);
  EXPECT_EQ(c.a, 1);
  EXPECT_EQ(c.b, 2);
  EXPECT_EQ(c.nx, 0.0);
  EXPECT_EQ(c.ny, 1.0);
  EXPECT_EQ(c.fn, 4.0);
  EXPECT_EQ(c.ft, -3.0);
  EXPECT_EQ(c.lx, 0.0);
  EXPECT_EQ(c.ly, 0.002);
  EXPECT_TRUE(fabric::has_normal(c));
}

TEST(MakeContact, CoincidentCentresHaveNoNormal)
{
  // |l| <= 1e-12 (r_a + r_b), whatever the force (LIGGGHTS gives NaN there)
  const double radius_sum = 0.002;
  for (double d : {0.0, 1e-300, 1e-20, 1e-12 * radius_sum}) {
    const Contact c = fabric::make_contact(1, 2, d, 0.0, kNaN, kNaN, radius_sum);
    EXPECT_FALSE(fabric::has_normal(c)) << d;
    EXPECT_EQ(c.nx, 0.0);
    EXPECT_EQ(c.ny, 0.0);
    EXPECT_EQ(c.fn, 0.0);
    EXPECT_EQ(c.ft, 0.0);
    EXPECT_EQ(c.lx, d);
  }
  for (double bad : {kNaN, kInf})
    EXPECT_FALSE(fabric::has_normal(fabric::make_contact(1, 2, bad, 0.0, 1.0, 0.0, radius_sum)));
  EXPECT_FALSE(fabric::has_normal(fabric::make_contact(1, 2, 1.0, 0.0, 1.0, 0.0, kNaN)));
}

TEST(MakeContact, NearlyCoincidentCentresStillHaveANormal)
{
  // 1e-14 is 5e-12 of the radius sum: the direction is still well defined
  const Contact c = fabric::make_contact(1, 2, 1e-14, 0.0, 169000.0, 0.0, 0.002);
  EXPECT_TRUE(fabric::has_normal(c));
  EXPECT_EQ(c.nx, 1.0);
  EXPECT_EQ(c.ny, 0.0);
  EXPECT_EQ(c.fn, 169000.0);
  EXPECT_EQ(c.ft, 0.0);
  // without radii (point particles) only exactly coincident centres lack a normal
  EXPECT_TRUE(fabric::has_normal(fabric::make_contact(1, 2, 0.0, -1e-300, 0.0, 0.0, 0.0)));
  EXPECT_FALSE(fabric::has_normal(fabric::make_contact(1, 2, 0.0, 0.0, 0.0, 0.0, 0.0)));
}

TEST(HasNormal, NaNOrZeroNormals)
{
  EXPECT_TRUE(fabric::has_normal(contact_at(deg(30), 1.0)));
  EXPECT_FALSE(fabric::has_normal(Contact{0, 1, kNaN, 0.0, 1.0, 0.0, 0.0, 0.0}));
  EXPECT_FALSE(fabric::has_normal(Contact{0, 1, 0.0, kInf, 1.0, 0.0, 0.0, 0.0}));
  EXPECT_FALSE(fabric::has_normal(Contact{0, 1, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0}));
}

// A contact with NaN normal and forces (as computed from coincident centres
// before the guard), and one without a normal as make_contact returns it.
std::vector<Contact> with_normal_less_contacts(std::vector<Contact> good)
{
  good.push_back(Contact{0, 2, kNaN, kNaN, kNaN, kNaN, 0.0, 0.0});
  good.push_back(fabric::make_contact(1, 2, 0.0, 0.0, kNaN, kNaN, 0.002));
  return good;
}

TEST(NoNormal, LeftOutOfTheHistogram)
{
  const std::vector<Contact> good = {contact_at(deg(10), 2.0, 0.5), contact_at(deg(100), 1.0)};
  const fabric::Histogram expected = fabric::polar_histogram(good, 18);
  const fabric::Histogram h = fabric::polar_histogram(with_normal_less_contacts(good), 18);
  EXPECT_EQ(h.count, expected.count);
  EXPECT_EQ(h.mean_fn, expected.mean_fn);
  EXPECT_EQ(h.mean_ft, expected.mean_ft);
  EXPECT_EQ(h.empty_bins, 14);
}

TEST(NoNormal, LeftOutOfTheTensorsAndTheStress)
{
  const std::vector<Contact> good = {contact_at(deg(0), 2.0, 0.5, 0.002),
                                     contact_at(deg(90), 1.0, 0.0, 0.002)};
  const std::vector<Contact> all = with_normal_less_contacts(good);
  const fabric::Anisotropy fa = fabric::normal_anisotropy_tensor(all);
  EXPECT_NEAR(fa.a, 0.0, kTol); // phi = diag(1/2, 1/2): two contacts, not four
  const fabric::ForceAnisotropy ft = fabric::force_anisotropy_tensor(all, fa);
  // chi_n = diag(2, 1)/2: f0 = 1.5, an = 2 (1 - 1/2) / 1.5 = 2/3 along x
  EXPECT_NEAR(ft.f0, 1.5, kTol);
  EXPECT_NEAR(ft.an, 2.0 / 3.0, kTol);
  EXPECT_NEAR(ft.theta_n, 0.0, kTol);
  const Eigen::Matrix2d sigma = fabric::love_weber_stress(all, 1e-4);
  EXPECT_TRUE(sigma.allFinite());
  EXPECT_NEAR(sigma(0, 0), 2.0 * 0.002 / 1e-4, 1e-9);
  EXPECT_NEAR(sigma(1, 1), 1.0 * 0.002 / 1e-4, 1e-9);
  EXPECT_NEAR(sigma(1, 0), 0.5 * 0.002 / 1e-4, 1e-9); // ft = 0.5 along +y on l along x
  EXPECT_NEAR(sigma(0, 1), 0.0, 1e-9);
}

TEST(NoNormal, OnlyContactsWithoutNormalGiveZeros)
{
  const std::vector<Contact> none = with_normal_less_contacts({});
  const fabric::Histogram h = fabric::polar_histogram(none, 18);
  EXPECT_EQ(h.empty_bins, 18);
  for (const fabric::Anisotropy &f :
       {fabric::normal_anisotropy_histogram(h), fabric::normal_anisotropy_tensor(none)}) {
    EXPECT_EQ(f.a, 0.0);
    EXPECT_EQ(f.theta, 0.0);
  }
  for (const fabric::ForceAnisotropy &f :
       {fabric::force_anisotropy_histogram(h), fabric::force_anisotropy_tensor(none, {0.0, 0.0})}) {
    EXPECT_EQ(f.an, 0.0);
    EXPECT_EQ(f.f0, 0.0);
    EXPECT_EQ(f.at, 0.0);
  }
  EXPECT_TRUE(fabric::love_weber_stress(none, 1.0).isZero(0.0));
}

// ---- all contacts in one bin --------------------------------------------------

// Two contacts along +x: bins 0 and 9 (centres 10 and 190 deg) hold 2 entries each.
// Fabric: N = 4, sum N_g cos 2th_g = 4 cos 20 deg, so a = (2c/4) 4 = 2c at 10 deg,
// c = dth/sin dth (the histogram cannot resolve inside a bin); tensor: a = 2 at 0.
// Forces: f0 = 5, an = (c/(pi f0)) |2 f0 e^(i 20 deg) dth| = 2 c dth / pi at 10 deg.
TEST(OneBin, AllContactsAlongOneDirection)
{
  const std::vector<Contact> contacts = {contact_at(0.0, 5.0), contact_at(0.0, 5.0)};
  const fabric::Histogram h = fabric::polar_histogram(contacts, 18);
  EXPECT_EQ(h.count[0], 2.0);
  EXPECT_EQ(h.count[9], 2.0);
  EXPECT_EQ(h.empty_bins, 16);
  const double width = deg(20), c = width / std::sin(width);
  const fabric::Anisotropy binned = fabric::normal_anisotropy_histogram(h);
  EXPECT_NEAR(binned.a, 2.0 * c, kTol);
  EXPECT_NEAR(binned.theta, deg(10), kTol);
  const fabric::Anisotropy tensor = fabric::normal_anisotropy_tensor(contacts);
  EXPECT_NEAR(tensor.a, 2.0, kTol);
  EXPECT_NEAR(tensor.theta, 0.0, kTol);
  const fabric::ForceAnisotropy forces = fabric::force_anisotropy_histogram(h);
  EXPECT_NEAR(forces.f0, 5.0, kTol);
  EXPECT_NEAR(forces.an, 2.0 * c * width / kPi, kTol);
  EXPECT_NEAR(forces.theta_n, deg(10), kTol);
  EXPECT_EQ(forces.at, 0.0);
  EXPECT_EQ(forces.empty_bins, 16);
  // tensor: a = 2 makes w = 1 + 2 cos 2(th) = 3 at th = 0: chi_n = diag(5/3, 0)
  const fabric::ForceAnisotropy ft = fabric::force_anisotropy_tensor(contacts, tensor);
  EXPECT_NEAR(ft.f0, 5.0 / 3.0, kTol);
  EXPECT_NEAR(ft.an, 2.0, kTol);
}

// ---- no contacts at all ---------------------------------------------------------

TEST(NoContacts, EverythingIsZeroAndFinite)
{
  const std::vector<Contact> none;
  const fabric::Histogram h = fabric::polar_histogram(none, 18);
  EXPECT_EQ(h.empty_bins, 18);
  for (int g = 0; g < 18; ++g) {
    EXPECT_EQ(h.count[g], 0.0);
    EXPECT_EQ(h.mean_fn[g], 0.0);
    EXPECT_EQ(h.mean_ft[g], 0.0);
  }
  for (const fabric::Anisotropy &f :
       {fabric::normal_anisotropy_histogram(h), fabric::normal_anisotropy_tensor(none)}) {
    EXPECT_EQ(f.a, 0.0);
    EXPECT_EQ(f.theta, 0.0);
  }
  const fabric::ForceAnisotropy binned = fabric::force_anisotropy_histogram(h);
  const fabric::ForceAnisotropy tensor = fabric::force_anisotropy_tensor(none, {0.0, 0.0});
  EXPECT_EQ(binned.empty_bins, 18);
  EXPECT_EQ(tensor.empty_bins, 0);
  for (const fabric::ForceAnisotropy &f : {binned, tensor}) {
    EXPECT_EQ(f.an, 0.0);
    EXPECT_EQ(f.theta_n, 0.0);
    EXPECT_EQ(f.f0, 0.0);
    EXPECT_EQ(f.at, 0.0);
    EXPECT_EQ(f.theta_t, 0.0);
  }
  const fabric::Coordination c = fabric::coordination({});
  EXPECT_EQ(c.Cn, 0.0);
  EXPECT_EQ(c.Zm, 0.0);
  EXPECT_EQ(c.n_contacts, 0);
  EXPECT_EQ(c.n_particles, 0);
  EXPECT_TRUE(fabric::love_weber_stress(none, 1.0).isZero(0.0));
}

// ---- what compute fabric calls ---------------------------------------------

TEST(MissingNormals, CountAndFirst)
{
  const Contact none{1, 2, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  const std::vector<Contact> contacts = {contact_at(deg(10), 1.0), none, contact_at(deg(20), 1.0),
                                         none};
  const fabric::MissingNormals missing = fabric::missing_normals(contacts);
  EXPECT_EQ(missing.count, 2);
  EXPECT_EQ(missing.first, 1);
  const fabric::MissingNormals all_there = fabric::missing_normals({contact_at(deg(10), 1.0)});
  EXPECT_EQ(all_there.count, 0);
  EXPECT_EQ(all_there.first, -1);
}

TEST(BinCentre, MiddleOfTheBin)
{
  EXPECT_NEAR(fabric::bin_centre(0, 18), deg(10), kTol);
  EXPECT_NEAR(fabric::bin_centre(17, 18), deg(350), kTol);
  EXPECT_NEAR(fabric::bin_centre(2, 6), deg(150), kTol);
}

// Contacts at 30 and 90 deg (fn = 1) in 6 bins of 60 deg: bins 0, 1, 3, 4 hold
// one entry each (centres 30, 90, 210, 270), bins 2 and 5 are empty. With
// c the bin correction, sum N_g cos 2th_g = -1 and sin 2th_g = sqrt 3, N = 4:
//   a cos 2th_a = (2c/4)(-1), a sin 2th_a = (2c/4) sqrt 3 -> a = c, th_a = 60 deg
//   f0 = 1; an (cos, sin) 2th_n = c/pi (-1, sqrt 3) pi/3 -> an = 2c/3, th_n = 60 deg
void expect_thirty_and_ninety(const fabric::Anisotropies &an, double c)
{
  EXPECT_NEAR(an.fabric.a, c, kTol);
  EXPECT_NEAR(an.fabric.theta, deg(60), kTol);
  EXPECT_NEAR(an.force.f0, 1.0, kTol);
  EXPECT_NEAR(an.force.an, 2.0 * c / 3.0, kTol);
  EXPECT_NEAR(an.force.theta_n, deg(60), kTol);
  EXPECT_NEAR(an.force.at, 0.0, kTol);
  EXPECT_EQ(an.force.empty_bins, 2);
}

TEST(Anisotropies, HistogramEstimatorsUseTheirBinCorrection)
{
  const std::vector<Contact> contacts = {contact_at(deg(30), 1.0), contact_at(deg(90), 1.0)};
  const double width = kPi / 3;
  expect_thirty_and_ninety(fabric::anisotropies(contacts, 6, fabric::Estimator::Unbiased),
                           width / std::sin(width)); // 2 pi / (3 sqrt 3)
  expect_thirty_and_ninety(fabric::anisotropies(contacts, 6, fabric::Estimator::Published),
                           std::sin(width) / width);
}

// Two contacts at 0 deg, one at 90 deg, fn = 1: phi = diag(2/3, 1/3), a = 2/3,
// th_a = 0; w = 5/3 at 0 deg and 1/3 at 90 deg, so
// chi_n = (1/3) [2 diag(1, 0) / (5/3) + diag(0, 1) / (1/3)] = diag(0.4, 1):
// f0 = 1.4, an = 2 (1 - 0.4) / 1.4 = 6/7 along 90 deg. No bins, none empty.
TEST(Anisotropies, TensorEstimatorDividesTheForcesByTheTensorFabric)
{
  const std::vector<Contact> contacts = {contact_at(deg(0), 1.0), contact_at(deg(0), 1.0),
                                         contact_at(deg(90), 1.0)};
  const fabric::Anisotropies an = fabric::anisotropies(contacts, 6, fabric::Estimator::Tensor);
  EXPECT_NEAR(an.fabric.a, 2.0 / 3.0, kTol);
  EXPECT_NEAR(an.fabric.theta, 0.0, kTol);
  EXPECT_NEAR(an.force.f0, 1.4, kTol);
  EXPECT_NEAR(an.force.an, 6.0 / 7.0, kTol);
  expect_same_axis(an.force.theta_n, deg(90), kTol);
  EXPECT_EQ(an.force.empty_bins, 0);
}

} // namespace
