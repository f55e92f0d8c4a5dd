// The number-only texts of the stability messages, against the texts the script
// tests (tests/scripts/stability_guard*.in) and the doc page quote.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "stability_messages.h"

using namespace stability;

TEST(UnstableHint, NamesTheTimeStepOnlyAboveTheSafeRatio)
{
  EXPECT_EQ(unstable_hint(2.0), "reduce the time step (now 2 x sqrt(m_min/k_n); 0.15 is safe), "
                                "the servo gain or the loading rate");
  // at 0.15 itself the step is safe (above it, not at it, is too large)
  EXPECT_EQ(unstable_hint(0.15), "the time step is safe (0.15 x sqrt(m_min/k_n), at most 0.15): "
                                 "reduce the servo gain or the loading rate");
  // %.3g of the ratio
  EXPECT_EQ(unstable_hint(0.0036742), "the time step is safe (0.00367 x sqrt(m_min/k_n), at most "
                                      "0.15): reduce the servo gain or the loading rate");
  EXPECT_EQ(unstable_hint(0.0), "reduce the servo gain or the loading rate, or the time step if it "
                                "is above 0.15 x sqrt(m_min/k_n) (not checked: no kn "
                                "peratomtypepair table)");
}

TEST(GuardErrors, NonFiniteAndLost)
{
  EXPECT_EQ(nonfinite_error(3, 1200, 17, 0.0),
            "3 atom(s) have a non-finite position, velocity or force at step 1200 (first: atom "
            "17): the run has gone unstable; reduce the servo gain or the loading rate, or the "
            "time step if it is above 0.15 x sqrt(m_min/k_n) (not checked: no kn peratomtypepair "
            "table)");
  EXPECT_EQ(lost_error(1, 1000, 0.00367),
            "1 atom(s) of the group were lost since the start of the run (at step 1000): particles "
            "left the box through a wall or the membrane; check that walls and platens enclose "
            "the sample, and the time step is safe (0.00367 x sqrt(m_min/k_n), at most 0.15): "
            "reduce the servo gain or the loading rate");
  // steps beyond 32 bits (bigint)
  EXPECT_NE(lost_error(2, 5000000000LL, 0.2).find("(at step 5000000000): particles"),
            std::string::npos);
}

TEST(GuardErrors, InputFaultsAtTheStartOfARun)
{
  EXPECT_EQ(nonfinite_error(6, 0, 5, 0.0861, NonFinite::Velocity, true),
            "6 atom(s) have a non-finite position, velocity or force at step 0 (first: atom 5): "
            "its velocity is not finite at the start of the run, before any step of it: the "
            "input gave it (velocity, set, read_data, displace_atoms or an earlier run; two atoms "
            "at one centre get a non-finite contact force), not an instability; give every atom "
            "a finite position and velocity and its own centre");
  EXPECT_EQ(nonfinite_error(2, 40, 7, 0.0861, NonFinite::Force, false),
            "2 atom(s) have a non-finite position, velocity or force at step 40 (first: atom 7): "
            "its force is not finite; the run has gone unstable; the time step is safe (0.0861 x "
            "sqrt(m_min/k_n), at most 0.15): reduce the servo gain or the loading rate");
  EXPECT_EQ(size_error(1, 0, 14, 0.0, 0.0, true),
            "1 atom(s) of the group have a radius or mass that is not a finite number > 0 at step "
            "0 (first: atom 14, radius 0 m, mass 0 kg): a fault of the input, not an "
            "instability; give every particle a diameter > 0 and a density > 0 (set ... diameter "
            "/ density, create_atoms, read_data)");
  EXPECT_NE(size_error(2, 3, 1, 0.0, 5.0, false).find("(first: atom 1, radius 0 m):"),
            std::string::npos);
  // a NaN diameter: radius and mass NaN, printed without a sign
  const double nan = -std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(size_error(1, 0, 7, nan, nan, true).find("(first: atom 7, radius nan m, mass nan kg)"),
            std::string::npos);
}

TEST(GuardErrors, StepBlownUpOrAboveTheLimit)
{
  EXPECT_EQ(step_error(1, 0.1, 0, 0.05, StepVerdict::BlownUp, 2.0),
            "atom 1 moved 0.1 of its radius in one step at step 0 (limit 0.05; a quasi-static "
            "test moves particles < 0.001): the run has gone unstable (kinetic energy blow-up); "
            "reduce the time step (now 2 x sqrt(m_min/k_n); 0.15 is safe), the servo gain or the "
            "loading rate");
  EXPECT_EQ(
      step_error(1, 0.0200001, 0, 1e-9, StepVerdict::AboveLimit, 0.00367),
      "atom 1 moved 0.02 of its radius in one step at step 0 (limit 1e-09; a quasi-static "
      "test moves particles < 0.001): faster than 'move' allows (unstable runs move particles > "
      "0.05); the time step is safe (0.00367 x sqrt(m_min/k_n), at most 0.15): reduce the "
      "servo gain or the loading rate");
}

TEST(GuardWarnings, OverlapNamesThePairInOrder)
{
  const std::string text =
      "atoms 1 and 2 overlap by 0.2 of the smaller radius at step 0 (limit 0.1): contacts this "
      "soft change the fabric and the volume; raise the contact stiffness (e.g. k_n >= 1000 x "
      "the mean stress x unit thickness) or lower the pressure (warned once; f_ID[2] is the "
      "current value)";
  EXPECT_EQ(overlap_warning(1, 2, 0.2, 0, 0.1, 2), text);
  EXPECT_EQ(overlap_warning(2, 1, 0.2, 0, 0.1, 2), text); // the smaller ID first
  EXPECT_NE(overlap_warning(1, 2, 0.2, 0, 0.1, 3).find("f_ID[3] is"), std::string::npos);
}

TEST(GuardWarnings, InertialNumber)
{
  EXPECT_EQ(inertial_warning(0.0017912, 0.001, 1, 0.05, 1.75e-3, 2e8, 2, 1e5, 4),
            "inertial number I = 0.00179 > 0.001 at step 1 (strain rate 0.05 1/s, d50 0.00175 m, "
            "density 2e+08 kg/m^2 per unit thickness, pressure 1e+05 Pa): the test is not "
            "quasi-static; lower the loading rate (warned once; f_ID[4] is the current value)");
  EXPECT_EQ(inertial_warning(0.00268, 0.001, 1, 0.02, 3e-3, 2650, 3, 1e5, 4),
            "inertial number I = 0.00268 > 0.001 at step 1 (strain rate 0.02 1/s, d50 0.003 m, "
            "density 2.65e+03 kg/m^3, pressure 1e+05 Pa): the test is not quasi-static; lower "
            "the loading rate (warned once; f_ID[4] is the current value)");
  EXPECT_EQ(inertial_overflow(10, 1.0, 1e-300),
            "the inertial number overflows at step 10 (R = 1, P = 1e-300); the pressure is too "
            "small for the rate");
}

namespace {

// a disk of radius 1 mm and density 2e8 (per unit thickness): m = pi 1e-6 2e8 = 628.3 kg;
// with k_n = 8.45e7 N/m the contact time is sqrt(628.3 / 8.45e7) = 2.7268e-3 s
const double MASS = M_PI * 1e-6 * 2e8;
constexpr double KN = 8.45e7;

} // namespace

TEST(TimeStepWarning, WithinTheSafeStepOnlyAStricterLimitIsExceeded)
{
  // dt 1e-5 = 0.00367 x 2.7268e-3; the step that meets limit 1e-9: 1e-9 x 2.7268e-3
  EXPECT_EQ(time_step_warning(1e-5, MASS, KN, 1e-9),
            "time step 1e-05 s is 0.0037 x sqrt(m_min/k_n) = 0.00273 s (m_min = 628 kg, k_n = "
            "8.45e+07 N/m), above the limit 1e-09; it is within 0.15 x sqrt(m_min/k_n), the "
            "published set-up, which is safe: keep it, or use timestep <= 2.7e-12 only to stay "
            "below the limit");
}

TEST(TimeStepWarning, AboveTheSafeStepTheStepToUse)
{
  // dt = 0.2 x 2.7268e-3 = 5.4536e-4 against limit 0.1: use 0.1 x 2.7268e-3 = 2.7e-4
  EXPECT_EQ(time_step_warning(0.2 * 2.72680e-3, MASS, KN, 0.1),
            "time step 0.00054536 s is 0.2 x sqrt(m_min/k_n) = 0.00273 s (m_min = 628 kg, k_n = "
            "8.45e+07 N/m), above the limit 0.1: use timestep <= 0.00027 (0.1 x sqrt(m_min/k_n))");
  // limit 0.2 at 0.25: the safe 0.15 x 2.7268e-3 = 4.1e-4 is what to use
  EXPECT_EQ(time_step_warning(0.25 * 2.72680e-3, MASS, KN, 0.2),
            "time step 0.0006817 s is 0.25 x sqrt(m_min/k_n) = 0.00273 s (m_min = 628 kg, k_n = "
            "8.45e+07 N/m), above the limit 0.2: use timestep <= 0.00041 (0.15 x sqrt(m_min/k_n), "
            "the published set-up)");
}

TEST(TimeStepWarning, AbovePoorlyResolved)
{
  EXPECT_EQ(time_step_warning(0.5 * 2.72680e-3, MASS, KN, 0.3),
            "time step 0.0013634 s is 0.5 x sqrt(m_min/k_n) = 0.00273 s (m_min = 628 kg, k_n = "
            "8.45e+07 N/m), above the limit 0.3; above 0.3 the contacts are poorly resolved and "
            "the run may go unstable: reduce it, use timestep <= 0.00041 (0.15 x "
            "sqrt(m_min/k_n), the published set-up)");
}
