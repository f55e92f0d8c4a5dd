#include "stability_messages.h"

#include <cmath>
#include <cstdio>

namespace stability {

std::string unstable_hint(double time_step_ratio)
{
  if (!(time_step_ratio > 0.0))
    return format("reduce the servo gain or the loading rate, or the time step if it is above "
                  "%g x sqrt(m_min/k_n) (not checked: no kn peratomtypepair table)",
                  TIME_STEP_SAFE);
  if (time_step_ratio > TIME_STEP_SAFE)
    return format("reduce the time step (now %.3g x sqrt(m_min/k_n); %g is safe), the servo gain "
                  "or the loading rate",
                  time_step_ratio, TIME_STEP_SAFE);
  return format("the time step is safe (%.3g x sqrt(m_min/k_n), at most %g): reduce the servo "
                "gain or the loading rate",
                time_step_ratio, TIME_STEP_SAFE);
}

std::string nonfinite_error(long count, long long step, int first, double time_step_ratio,
                            NonFinite kind, bool at_start)
{
  const char *what = kind == NonFinite::Position   ? "position"
                     : kind == NonFinite::Velocity ? "velocity"
                     : kind == NonFinite::Force    ? "force"
                                                   : nullptr;
  std::string text = format("%ld atom(s) have a non-finite position, velocity or force at step "
                            "%lld (first: atom %d): ",
                            count, step, first);
  if (what) text += format("its %s is not finite", what);
  if (at_start)
    return text + (what ? " " : "") +
           "at the start of the run, before any step of it: the input gave it (velocity, set, "
           "read_data, displace_atoms or an earlier run; two atoms at one centre get a "
           "non-finite contact force), not an instability; give every atom a finite position "
           "and velocity and its own centre";
  return text + (what ? "; " : "") + "the run has gone unstable; " + unstable_hint(time_step_ratio);
}

std::string size_error(long count, long long step, int tag, double radius, double mass,
                       bool has_mass)
{
  // NaN without its sign: "nan", never "-nan"
  const auto unsigned_nan = [](double x) { return std::isnan(x) ? std::fabs(x) : x; };
  const std::string size =
      has_mass ? format("radius %g m, mass %g kg", unsigned_nan(radius), unsigned_nan(mass))
               : format("radius %g m", unsigned_nan(radius));
  return format("%ld atom(s) of the group have a radius or mass that is not a finite number > 0 "
                "at step %lld (first: atom %d, %s): a fault of the input, not an instability; "
                "give every particle a diameter > 0 and a density > 0 (set ... diameter / "
                "density, create_atoms, read_data)",
                count, step, tag, size.c_str());
}

std::string step_error(int tag, double fraction, long long step, double limit, StepVerdict verdict,
                       double time_step_ratio)
{
  const std::string what =
      verdict == StepVerdict::BlownUp
          ? std::string("the run has gone unstable (kinetic energy blow-up)")
          : format("faster than 'move' allows (unstable runs move particles > %g)",
                   STEP_FRACTION_BLOWN_UP);
  return format("atom %d moved %.3g of its radius in one step at step %lld (limit %g; a "
                "quasi-static test moves particles < %g): ",
                tag, fraction, step, limit, STEP_FRACTION_QUASI_STATIC) +
         what + "; " + unstable_hint(time_step_ratio);
}

std::string lost_error(long long lost, long long step, double time_step_ratio)
{
  return format("%lld atom(s) of the group were lost since the start of the run (at step %lld): "
                "particles left the box through a wall or the membrane; check that walls and "
                "platens enclose the sample, and ",
                lost, step) +
         unstable_hint(time_step_ratio);
}

std::string overlap_warning(int tag_a, int tag_b, double fraction, long long step, double limit,
                            int vector_entry)
{
  return format("atoms %d and %d overlap by %.3g of the smaller radius at step %lld (limit %g): "
                "contacts this soft change the fabric and the volume; raise the contact "
                "stiffness (e.g. k_n >= 1000 x the mean stress x unit thickness) or lower the "
                "pressure (warned once; f_ID[%d] is the current value)",
                tag_a < tag_b ? tag_a : tag_b, tag_a < tag_b ? tag_b : tag_a, fraction, step, limit,
                vector_entry);
}

std::string inertial_warning(double inertial, double limit, long long step, double strain_rate,
                             double d50, double density, int dimension, double pressure,
                             int vector_entry)
{
  return format("inertial number I = %.3g > %g at step %lld (strain rate %.3g 1/s, d50 %.3g m, "
                "density %.3g %s, pressure %.3g Pa): the test is not quasi-static; lower the "
                "loading rate (warned once; f_ID[%d] is the current value)",
                inertial, limit, step, strain_rate, d50, density,
                dimension == 3 ? "kg/m^3" : "kg/m^2 per unit thickness", pressure, vector_entry);
}

std::string inertial_overflow(long long step, double strain_rate, double pressure)
{
  return format("the inertial number overflows at step %lld (R = %g, P = %g); the pressure is "
                "too small for the rate",
                step, strain_rate, pressure);
}

} // namespace stability
