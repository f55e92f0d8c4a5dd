// Local (PFC) damping: F_d,k = -alpha |F_k| sign(v_k), hand-worked values.
#include "local_damping.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace {

constexpr double kTol = 1e-15;

// F = (3, -4, 0), v = (-1, 2, 0), alpha = 0.7:
//   F_d,x = -0.7 * |3|  * sign(-1) = -0.7 * 3 * (-1) = +2.1
//   F_d,y = -0.7 * |-4| * sign(2)  = -0.7 * 4 * (+1) = -2.8
//   F_d,z = -0.7 * |0|  * sign(0)  = 0
// damped force F + F_d = (3 + 2.1, -4 - 2.8, 0) = (5.1, -6.8, 0):
// In both components the force already opposes the motion (F_x > 0 with v_x < 0,
// F_y < 0 with v_y > 0), so the damping makes it 1.7 times larger.
TEST(LocalDamping, HandWorkedForce)
{
  const double f[3] = {3.0, -4.0, 0.0};
  const double v[3] = {-1.0, 2.0, 0.0};
  double fd[3];
  damping::local_damping_force(f, v, 3, 0.7, fd);
  EXPECT_NEAR(fd[0], 2.1, kTol);
  EXPECT_NEAR(fd[1], -2.8, kTol);
  EXPECT_EQ(fd[2], 0.0);

  double g[3] = {3.0, -4.0, 0.0};
  damping::apply_local_damping(g, v, 3, 0.7);
  EXPECT_NEAR(g[0], 5.1, kTol);
  EXPECT_NEAR(g[1], -6.8, kTol);
  EXPECT_EQ(g[2], 0.0);
}

// F = (3, -4, 0), v = (1, -2, 0), alpha = 0.7: the force drives the motion in
// both components and is reduced to 30 %:
//   F_d = (-0.7 * 3 * 1, -0.7 * 4 * (-1), 0) = (-2.1, 2.8, 0),  F + F_d = (0.9, -1.2, 0)
TEST(LocalDamping, HandWorkedDrivingForceIsReduced)
{
  double f[3] = {3.0, -4.0, 0.0};
  const double v[3] = {1.0, -2.0, 0.0};
  damping::apply_local_damping(f, v, 3, 0.7);
  EXPECT_NEAR(f[0], 0.9, kTol);
  EXPECT_NEAR(f[1], -1.2, kTol);
  EXPECT_EQ(f[2], 0.0);
}

// A component that does not move is not damped: sign(0) = 0.
// F = (3, -4, 5), v = (0, 2, -0.0), alpha = 0.7 -> F_d = (0, -2.8, 0)
TEST(LocalDamping, ZeroVelocityComponentIsNotDamped)
{
  const double f[3] = {3.0, -4.0, 5.0};
  const double v[3] = {0.0, 2.0, -0.0};
  double fd[3];
  damping::local_damping_force(f, v, 3, 0.7, fd);
  EXPECT_EQ(fd[0], 0.0);
  EXPECT_FALSE(std::signbit(fd[0])); // +0.0, not -0.0
  EXPECT_NEAR(fd[1], -2.8, kTol);
  EXPECT_EQ(fd[2], 0.0);
  EXPECT_EQ(damping::sign(0.0), 0.0);
  EXPECT_EQ(damping::sign(-0.0), 0.0);
  EXPECT_EQ(damping::sign(std::numeric_limits<double>::quiet_NaN()), 0.0);
  EXPECT_EQ(damping::sign(-1e-300), -1.0);
  EXPECT_EQ(damping::sign(1e-300), 1.0);
}

// alpha = 0: the force is unchanged, bit for bit.
TEST(LocalDamping, AlphaZeroLeavesForceUnchanged)
{
  double f[3] = {3.0, -4.0, 0.125};
  const double v[3] = {-1.0, 2.0, 7.0};
  damping::apply_local_damping(f, v, 3, 0.0);
  EXPECT_EQ(f[0], 3.0);
  EXPECT_EQ(f[1], -4.0);
  EXPECT_EQ(f[2], 0.125);
}

// The torque uses the same rule with the angular velocity:
// T_z = -0.05, omega_z = 10, alpha = 0.7 -> T_d,z = -0.7 * 0.05 * 1 = -0.035, T + T_d = -0.085
TEST(LocalDamping, TorqueWithAngularVelocity)
{
  double t[3] = {0.0, 0.0, -0.05};
  const double w[3] = {0.0, 0.0, 10.0};
  damping::apply_local_damping(t, w, 3, 0.7);
  EXPECT_EQ(t[0], 0.0);
  EXPECT_EQ(t[1], 0.0);
  EXPECT_NEAR(t[2], -0.085, kTol);
}

// Only n components are touched.
TEST(LocalDamping, OnlyNComponents)
{
  double f[3] = {3.0, -4.0, 5.0};
  const double v[3] = {1.0, 1.0, 1.0};
  damping::apply_local_damping(f, v, 2, 0.5);
  EXPECT_NEAR(f[0], 1.5, kTol);
  EXPECT_NEAR(f[1], -6.0, kTol);
  EXPECT_EQ(f[2], 5.0);
}

// The damping force always opposes the
// velocity (F_d . v <= 0 component by component) and |F_d,k| = alpha |F_k|.
TEST(LocalDamping, OpposesMotionWithSizeAlphaF)
{
  const double fs[] = {-2.5, -1.0, 0.0, 0.5, 3.0};
  const double vs[] = {-4.0, -0.1, 0.0, 0.3, 2.0};
  for (double f : fs)
    for (double v : vs) {
      const double fd = damping::local_damping_component(f, v, 0.3);
      EXPECT_LE(fd * v, 0.0);
      EXPECT_NEAR(std::fabs(fd), v == 0.0 ? 0.0 : 0.3 * std::fabs(f), kTol);
    }
}

} // namespace
