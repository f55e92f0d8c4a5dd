#include "stability_limits.h"

#include <cmath>
#include <cstdarg>
#include <cstdio>

namespace stability {

double contact_time(double mass_min, double stiffness_max)
{
  if (!(mass_min > 0.0) || !(stiffness_max > 0.0)) return 0.0;
  return std::sqrt(mass_min / stiffness_max);
}

double time_step_ratio(double dt, double mass_min, double stiffness_max)
{
  const double t = contact_time(mass_min, stiffness_max);
  return t > 0.0 ? dt / t : 0.0;
}

double safe_time_step(double fraction, double mass_min, double stiffness_max)
{
  return fraction * contact_time(mass_min, stiffness_max);
}

std::string format(const char *fmt, ...)
{
  va_list args, again;
  va_start(args, fmt);
  va_copy(again, args);
  const int n = std::vsnprintf(nullptr, 0, fmt, args);
  va_end(args);
  std::string text(n > 0 ? static_cast<std::size_t>(n) : 0, '\0');
  if (n > 0) std::vsnprintf(&text[0], text.size() + 1, fmt, again);
  va_end(again);
  return text;
}

std::string time_step_warning(double dt, double mass_min, double stiffness_max, double limit)
{
  const double ratio = time_step_ratio(dt, mass_min, stiffness_max);
  const double fraction = limit < TIME_STEP_SAFE ? limit : TIME_STEP_SAFE;
  const double suggested = safe_time_step(fraction, mass_min, stiffness_max);
  const char *published = fraction == TIME_STEP_SAFE ? ", the published set-up" : "";
  const std::string what =
      format("time step %g s is %.2g x sqrt(m_min/k_n) = %.3g s (m_min = %.3g "
             "kg, k_n = %.3g N/m), above the limit %g",
             dt, ratio, contact_time(mass_min, stiffness_max), mass_min, stiffness_max, limit);
  if (ratio > TIME_STEP_POORLY_RESOLVED)
    return what + format("; above %g the contacts are poorly resolved and the run may go "
                         "unstable: reduce it, use timestep <= %.2g (%g x sqrt(m_min/k_n)%s)",
                         TIME_STEP_POORLY_RESOLVED, suggested, fraction, published);
  if (ratio > TIME_STEP_SAFE)
    return what + format(": use timestep <= %.2g (%g x sqrt(m_min/k_n)%s)", suggested, fraction,
                         published);
  return what + format("; it is within %g x sqrt(m_min/k_n), the published set-up, which is "
                       "safe: keep it, or use timestep <= %.2g only to stay below the limit",
                       TIME_STEP_SAFE, suggested);
}

} // namespace stability
