// The 3D fabric tensors (fabric_tensors3d.h) against hand-worked cases and
// against the models they fit, sampled on the icosahedron's six axes (a
// spherical 5-design: the mean over them of any polynomial of degree <= 5 in n
// is its mean over the sphere, so the fits are exact there).
#include "fabric_tensors3d.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;
using fabric::Contact3;
using fabric::ContactSums3;
using fabric::ForceSums3;

void expect_matrix(const Matrix3d &actual, const Matrix3d &expected, double tol)
{
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++)
      EXPECT_NEAR(actual(i, j), expected(i, j), tol) << "component " << i << j;
}

// one contact per axis; its force from the models fn = f0 (1 + An:nn),
// ft = f0 (At n - (n.At n) n)
std::vector<Contact3> sampled(const std::vector<Vector3d> &axes, double f0, const Matrix3d &an,
                              const Matrix3d &at, double length)
{
  std::vector<Contact3> out;
  long tag = 1;
  for (const Vector3d &axis : axes) {
    const Vector3d n = axis.normalized();
    const double fn = f0 * (1.0 + n.dot(an * n));
    const Vector3d ft = f0 * (at * n - n.dot(at * n) * n);
    out.push_back(fabric::make_contact3(tag, tag + 1, length * n, fn * n + ft, length));
    tag += 2;
  }
  return out;
}

std::vector<Vector3d> icosahedron_axes()
{
  const double g = 0.5 * (1.0 + std::sqrt(5.0));
  return {{0, 1, g}, {0, 1, -g}, {1, g, 0}, {1, -g, 0}, {g, 0, 1}, {-g, 0, 1}};
}

struct Fits {
  fabric::Anisotropy3 fabric;
  fabric::ForceAnisotropy3 force;
};

Fits fit(const std::vector<Contact3> &contacts)
{
  ContactSums3 sums;
  for (const Contact3 &c : contacts) sums.add(c);
  Fits r;
  r.fabric = fabric::fabric_anisotropy(sums);
  ForceSums3 forces;
  for (const Contact3 &c : contacts) forces.add(c, r.fabric.a);
  r.force = fabric::force_anisotropy(forces);
  return r;
}

TEST(FabricTensors3d, ContactSplitsTheForceOnB)
{
  const Contact3 c = fabric::make_contact3(3, 8, Vector3d(0, 0, 2), Vector3d(1, 0, 3), 2.0);
  EXPECT_EQ(c.a, 3);
  EXPECT_EQ(c.b, 8);
  EXPECT_EQ(c.n, Vector3d(0, 0, 1));
  EXPECT_EQ(c.fn, 3.0);
  EXPECT_EQ(c.ft, Vector3d(1, 0, 0));
  EXPECT_TRUE(fabric::has_normal(c));
}

TEST(FabricTensors3d, CoincidentCentresHaveNoNormal)
{
  const double nan = std::nan("");
  for (const Vector3d &l : {Vector3d(0, 0, 0), Vector3d(1e-13, 0, 0), Vector3d(nan, 0, 0)}) {
    const Contact3 c = fabric::make_contact3(1, 2, l, Vector3d(nan, nan, nan), 1.0);
    EXPECT_FALSE(fabric::has_normal(c));
    EXPECT_EQ(c.fn, 0.0);
    EXPECT_EQ(c.ft, Vector3d::Zero());
  }
  ContactSums3 sums;
  sums.add(fabric::make_contact3(1, 2, Vector3d::Zero(), Vector3d(1, 1, 1), 1.0));
  sums.add(fabric::make_contact3(1, 3, Vector3d(0, 0, 1), Vector3d(0, 0, 2), 1.0));
  EXPECT_EQ(sums.sum[ContactSums3::CONTACTS].value(), 2.0);
  EXPECT_EQ(sums.sum[ContactSums3::NO_NORMAL].value(), 1.0);
  expect_matrix(sums.phi(), Vector3d(0, 0, 1).asDiagonal().toDenseMatrix(), 0.0);
}

TEST(FabricTensors3d, CoordinateAxesAreIsotropic)
{
  const Fits r =
      fit(sampled({{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, 2.0, Matrix3d::Zero(), Matrix3d::Zero(), 1.0));
  expect_matrix(r.fabric.a, Matrix3d::Zero(), 1e-15);
  EXPECT_NEAR(r.fabric.invariant, 0.0, 1e-15);
  EXPECT_NEAR(r.force.f0, 2.0, 1e-15);
  EXPECT_NEAR(r.force.normal.invariant, 0.0, 1e-15);
}

TEST(FabricTensors3d, AllNormalsAlongZ)
{
  // phi = diag(0, 0, 1): a = 15/2 diag(-1/3, -1/3, 2/3), magnitude sqrt(3/2 * 37.5)
  const Fits r =
      fit(sampled({{0, 0, 1}, {0, 0, -1}}, 1.0, Matrix3d::Zero(), Matrix3d::Zero(), 1.0));
  expect_matrix(r.fabric.a, Vector3d(-2.5, -2.5, 5.0).asDiagonal().toDenseMatrix(), 1e-15);
  EXPECT_NEAR(r.fabric.invariant, 7.5, 1e-14);
}

TEST(FabricTensors3d, WeightsByTheFabricDensityByHand)
{
  // two contacts along z and one along x, all fn = F: phi = diag(1/3, 0, 2/3),
  // a = diag(0, -2.5, 2.5), weights w_z = 3.5, w_x = 1:
  // chi_n = (1/3) (2 F zz / 3.5 + F xx) -> f0 = F (1/3 + 4/21)
  const double F = 7.0;
  const Fits r =
      fit(sampled({{0, 0, 1}, {0, 0, -1}, {1, 0, 0}}, F, Matrix3d::Zero(), Matrix3d::Zero(), 1.0));
  expect_matrix(r.fabric.a, Vector3d(0.0, -2.5, 2.5).asDiagonal().toDenseMatrix(), 1e-14);
  const Matrix3d chi = Vector3d(F / 3.0, 0.0, 2.0 * F / 10.5).asDiagonal();
  const double f0 = F * (1.0 / 3.0 + 4.0 / 21.0);
  EXPECT_NEAR(r.force.f0, f0, 1e-13);
  const Matrix3d dev = chi - chi.trace() / 3.0 * Matrix3d::Identity();
  expect_matrix(r.force.normal.a, 7.5 * dev / f0, 1e-13);
  EXPECT_EQ(r.force.skipped, 0);
}

TEST(FabricTensors3d, RecoversTheForceModelsOnTheIcosahedron)
{
  Matrix3d an, at;
  an << 0.3, 0.1, -0.05, 0.1, -0.5, 0.2, -0.05, 0.2, 0.2;
  at << -0.1, 0.04, 0.03, 0.04, -0.15, -0.02, 0.03, -0.02, 0.25;
  const Fits r = fit(sampled(icosahedron_axes(), 11.0, an, at, 0.003));
  expect_matrix(r.fabric.a, Matrix3d::Zero(), 1e-14);
  EXPECT_NEAR(r.force.f0, 11.0, 1e-13);
  expect_matrix(r.force.normal.a, an, 1e-14);
  expect_matrix(r.force.tangential.a, at, 1e-14);
  EXPECT_NEAR(r.force.normal.invariant, std::sqrt(1.5 * an.squaredNorm()), 1e-14);
}

TEST(FabricTensors3d, SkipsContactsOutsideTheModel)
{
  // nine contacts along z, one along x: phi_xx = 0.1, a_xx = 7.5 (0.1 - 1/3) = -1.75,
  // w_x = -0.75: left out of the force sums, counted in N and in skipped
  std::vector<Vector3d> axes(9, Vector3d(0, 0, 1));
  axes.push_back(Vector3d(1, 0, 0));
  const Fits r = fit(sampled(axes, 1.0, Matrix3d::Zero(), Matrix3d::Zero(), 1.0));
  EXPECT_NEAR(r.fabric.a(0, 0), -1.75, 1e-14);
  EXPECT_EQ(r.force.skipped, 1);
  // chi_n = (1/10) 9 zz / w_z, w_z = 1 + a_zz = 1 + 7.5 (0.9 - 1/3)
  EXPECT_NEAR(r.force.f0, 0.9 / (1.0 + 7.5 * (0.9 - 1.0 / 3.0)), 1e-14);
}

TEST(FabricTensors3d, DensityZeroUpToRoundOffIsOutsideTheModel)
{
  // four contacts along z, one along x: a_xx = 7.5 (1/5 - 1/3) = -1 exactly, w_x = 0,
  // which comes out as +2.2e-16: weighted by 1/w it made f0 = 9e13 N. Skipped as w <= 0.
  std::vector<Vector3d> axes(4, Vector3d(0, 0, 1));
  axes.push_back(Vector3d(1, 0, 0));
  const Fits r = fit(sampled(axes, 0.1, Matrix3d::Zero(), Matrix3d::Zero(), 1e-3));
  EXPECT_NEAR(r.fabric.a(0, 0), -1.0, 1e-14);
  EXPECT_EQ(r.force.skipped, 1);
  // chi_n = (1/5) 4 x 0.1 zz / w_z, w_z = 1 + 7.5 (4/5 - 1/3) = 4.5: f0 = 0.08/4.5
  EXPECT_NEAR(r.force.f0, 0.08 / 4.5, 1e-15);
  // all the force along z: a_n = 15/2 dev(zz) = diag(-2.5, -2.5, 5)
  EXPECT_NEAR(r.force.normal.a(2, 2), 5.0, 1e-12);
  EXPECT_NEAR(r.force.normal.invariant, 7.5, 1e-12);
  EXPECT_TRUE(fabric::model_density_usable(1e-9));
  EXPECT_FALSE(fabric::model_density_usable(2.2e-16));
}

TEST(FabricTensors3d, TensileMeanForceGivesNoForceAnisotropy)
{
  // one contact in tension along x (f_n = -0.1) and a weaker compressive one along z:
  // f0 = tr chi_n = (-0.1/w_x + 0.05/w_z)/2 < 0: f0, a_n, a_t are 0 (as in 2D), not
  // a_n scaled by a negative or vanishing f0
  std::vector<Contact3> contacts = {
      fabric::make_contact3(1, 2, Vector3d(1e-3, 0, 0), Vector3d(-0.1, 0, 0.02), 1e-3),
      fabric::make_contact3(3, 4, Vector3d(0, 0, 1e-3), Vector3d(0, 0, 0.05), 1e-3)};
  const Fits r = fit(contacts);
  EXPECT_EQ(r.force.f0, 0.0);
  EXPECT_EQ(r.force.normal.invariant, 0.0);
  EXPECT_EQ(r.force.tangential.invariant, 0.0);
  EXPECT_NEAR(r.fabric.invariant, 3.75, 1e-12); // the fabric is there
}

TEST(FabricTensors3d, NonFiniteForceIsNotHiddenAsZero)
{
  // a NaN velocity gives its contacts NaN forces: f0 and a_n are NaN, not 0
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<Contact3> contacts = {
      fabric::make_contact3(1, 2, Vector3d(1e-3, 0, 0), Vector3d(nan, 0, 0), 1e-3),
      fabric::make_contact3(3, 4, Vector3d(0, 0, 1e-3), Vector3d(0, 0, 0.05), 1e-3)};
  const Fits r = fit(contacts);
  EXPECT_TRUE(std::isnan(r.force.f0));
  EXPECT_TRUE(std::isnan(r.force.normal.invariant));
}

TEST(FabricTensors3d, LoveWeberStressByHand)
{
  // a compressed pair along x (force 5 on b, branch 0.002) and a sphere on a wall
  // below it (the force on the wall (0, 1, -3), branch to the contact point -0.001 z)
  ContactSums3 sums;
  sums.add(fabric::make_contact3(1, 2, Vector3d(0.002, 0, 0), Vector3d(5, 0, 0), 0.002));
  sums.add(fabric::make_contact3(1, -1, Vector3d(0, 0, -0.001), Vector3d(0, 1, -3), 0.001));
  Matrix3d expected = Matrix3d::Zero();
  expected(0, 0) = 5 * 0.002 / 2e-6;
  expected(2, 2) = 3 * 0.001 / 2e-6;
  expected(1, 2) = -1 * 0.001 / 2e-6;
  expect_matrix(fabric::love_weber_stress(sums, 2e-6), expected, 1e-9);
  EXPECT_THROW(fabric::love_weber_stress(sums, 0.0), std::invalid_argument);
  const fabric::Components c = fabric::components(fabric::love_weber_stress(sums, 2e-6));
  EXPECT_NEAR(c[5], -250.0, 1e-9); // yz: the symmetric part
}

TEST(FabricTensors3d, MergedSumsEqualOneSum)
{
  std::mt19937 rng(7);
  std::normal_distribution<double> g(0.0, 1.0);
  std::vector<Contact3> contacts;
  for (int k = 0; k < 300; k++) {
    const Vector3d l(g(rng), g(rng), 2.0 * g(rng));
    contacts.push_back(fabric::make_contact3(k, k + 1, 0.003 * l.normalized(),
                                             Vector3d(g(rng), g(rng), 5.0 + g(rng)), 0.003));
  }
  ContactSums3 all, first, second;
  for (size_t k = 0; k < contacts.size(); k++) {
    all.add(contacts[k]);
    (k % 3 == 0 ? first : second).add(contacts[k]);
  }
  ContactSums3 unpacked;
  unpacked.unpack(second.pack().data());
  first.merge(unpacked);
  const fabric::Components a = fabric::components(fabric::fabric_anisotropy(all).a);
  const fabric::Components b = fabric::components(fabric::fabric_anisotropy(first).a);
  for (int k = 0; k < 6; k++) EXPECT_DOUBLE_EQ(a[k], b[k]);
  EXPECT_DOUBLE_EQ(fabric::love_weber_stress(all, 1.0)(2, 2),
                   fabric::love_weber_stress(first, 1.0)(2, 2));
}

} // namespace
