#ifndef LIGGGHTS_MEMBRANE_STABILITY_LIMITS_H
#define LIGGGHTS_MEMBRANE_STABILITY_LIMITS_H
// The numerical-stability limits every style compares with, defined here only
// (doc/fix_stability_guard.md, Description), and the time scale of a contact
// the time step is measured in, with the warning that a step is too large
// (fix stability/guard and fix membrane2d say it alike). No LIGGGHTS.

#include <string>

namespace stability {

// dt / sqrt(m_min/k_n): above it the contacts are poorly resolved (warned)
constexpr double TIME_STEP_POORLY_RESOLVED = 0.3;
// dt / sqrt(m_min/k_n) of the published set-up: what the warnings advise
constexpr double TIME_STEP_SAFE = 0.15;
// the inertial number below which a test is quasi-static (GDR MiDi 2004)
constexpr double INERTIAL_QUASI_STATIC = 1e-3;
// |v| dt / r: a quasi-static test moves particles less than this per step ...
constexpr double STEP_FRACTION_QUASI_STATIC = 1e-3;
// ... and a run that has blown up more than this
constexpr double STEP_FRACTION_BLOWN_UP = 0.05;

// sqrt(m/k): the time scale of a linear contact k on the lightest particle m. Its
// period is 2 pi sqrt(m_eff/k); velocity Verlet is stable below dt = 2 sqrt(m_eff/k)
// for one spring, lower with several contacts per particle. The published set-up
// runs at TIME_STEP_SAFE of it; above TIME_STEP_POORLY_RESOLVED we warn.
// Non-positive input -> 0.
double contact_time(double mass_min, double stiffness_max);

// dt in units of contact_time(); 0 when the contact time is unknown.
double time_step_ratio(double dt, double mass_min, double stiffness_max);

// The largest dt at which time_step_ratio() stays at or below `fraction`.
double safe_time_step(double fraction, double mass_min, double stiffness_max);

// dt exceeds `limit` x contact_time(mass_min, stiffness_max): what the step is,
// and what to use, worded by how large it is: above TIME_STEP_POORLY_RESOLVED
// the run may go unstable; the step to use is min(limit, TIME_STEP_SAFE) x the
// contact time; within TIME_STEP_SAFE it is called safe (only a stricter limit
// is exceeded). Without the style's prefix.
std::string time_step_warning(double dt, double mass_min, double stiffness_max, double limit);

// printf into a string (the messages of the stability checks): a text with long
// numbers is not cut
std::string format(const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 1, 2)))
#endif
    ;

} // namespace stability

#endif
