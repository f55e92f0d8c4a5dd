#include "stability_checks.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace stability {

double inertial_number(double strain_rate, double diameter, double density, double pressure)
{
  if (!(pressure > 0.0)) return std::numeric_limits<double>::infinity();
  return std::fabs(strain_rate) * diameter * std::sqrt(density / pressure);
}

double step_fraction(double vx, double vy, double vz, double dt, double radius)
{
  // sqrt, not hypot: no overflow to guard against here, and it runs per particle per step
  return std::sqrt(vx * vx + vy * vy + vz * vz) * dt / radius;
}

double overlap_fraction(double dx, double dy, double dz, double ri, double rj)
{
  return (ri + rj - std::sqrt(dx * dx + dy * dy + dz * dz)) / std::min(ri, rj);
}

namespace {

bool finite3(const double *a)
{
  return std::isfinite(a[0]) && std::isfinite(a[1]) && std::isfinite(a[2]);
}

} // namespace

AtomScan scan_atoms(std::size_t n, const double *const *x, const double *const *v,
                    const double *const *f, const double *radius, const int *mask, int groupbit,
                    double dt, const double *rmass, const int *tag)
{
  AtomScan s;
  // the smaller tag (or index) of i and the atom named so far
  const auto before = [tag](std::size_t i, long named) {
    if (named < 0) return true;
    return tag ? tag[i] < tag[named] : static_cast<long>(i) < named;
  };
  const auto valid_size = [](double value) { return std::isfinite(value) && value > 0.0; };
  for (std::size_t i = 0; i < n; i++) {
    if (!(mask[i] & groupbit)) continue;
    const bool size_ok = valid_size(radius[i]) && (!rmass || valid_size(rmass[i]));
    if (!size_ok) {
      s.bad_size++;
      if (before(i, s.first_bad_size)) s.first_bad_size = static_cast<long>(i);
    }
    const NonFinite kind = !finite3(x[i])   ? NonFinite::Position
                           : !finite3(v[i]) ? NonFinite::Velocity
                           : !finite3(f[i]) ? NonFinite::Force
                                            : NonFinite::None;
    if (kind != NonFinite::None) {
      s.nonfinite++;
      // a position or velocity is named before a force, then the smaller tag
      const bool state = kind != NonFinite::Force;
      const bool named_state = s.first_kind != NonFinite::Force && s.first_kind != NonFinite::None;
      if (s.first_nonfinite < 0 || (state && !named_state) ||
          (state == named_state && before(i, s.first_nonfinite))) {
        s.first_nonfinite = static_cast<long>(i);
        s.first_kind = kind;
      }
      continue;
    }
    if (!size_ok) continue;
    const double frac = step_fraction(v[i][0], v[i][1], v[i][2], dt, radius[i]);
    // of equal fractions the smaller tag: the atom named does not depend on the ranks
    if (s.argmax_step < 0 || frac > s.max_step_fraction ||
        (frac == s.max_step_fraction && before(i, s.argmax_step))) {
      s.max_step_fraction = frac;
      s.argmax_step = static_cast<long>(i);
    }
  }
  return s;
}

StepVerdict judge_step_fraction(double fraction, double limit)
{
  if (!(fraction > limit)) return StepVerdict::Within;
  return fraction > STEP_FRACTION_BLOWN_UP ? StepVerdict::BlownUp : StepVerdict::AboveLimit;
}

long long pair_key(int tag_a, int tag_b)
{
  const long long lo = tag_a < tag_b ? tag_a : tag_b, hi = tag_a < tag_b ? tag_b : tag_a;
  return (lo << 32) | hi;
}

OverlapScan scan_overlaps(int inum, const int *ilist, const int *numneigh,
                          const int *const *firstneigh, int neighmask, const double *const *x,
                          const double *radius, const int *mask, int groupbit, const int *tag)
{
  OverlapScan s;
  for (int ii = 0; ii < inum; ii++) {
    const int i = ilist[ii];
    if (!(mask[i] & groupbit)) continue;
    for (int jj = 0; jj < numneigh[i]; jj++) {
      const int j = firstneigh[i][jj] & neighmask;
      if (!(mask[j] & groupbit)) continue;
      const double frac = overlap_fraction(x[i][0] - x[j][0], x[i][1] - x[j][1], x[i][2] - x[j][2],
                                           radius[i], radius[j]);
      const bool tie_before = tag && frac == s.max_fraction && s.i >= 0 &&
                              pair_key(tag[i], tag[j]) < pair_key(tag[s.i], tag[s.j]);
      if (frac > s.max_fraction || tie_before) s = {frac, i, j};
    }
  }
  return s;
}

bool warn_once_now(double value, double limit, bool warned_before)
{
  return value > limit && !warned_before;
}

InertialCheck check_inertial_number(double strain_rate, double pressure, double diameter,
                                    double density)
{
  if (!(std::isfinite(strain_rate) && strain_rate >= 0.0)) return {InertialStatus::BadRate, 0.0};
  if (!(std::isfinite(pressure) && pressure > 0.0)) return {InertialStatus::BadPressure, 0.0};
  const double value = inertial_number(strain_rate, diameter, density, pressure);
  if (!std::isfinite(value)) return {InertialStatus::Overflow, 0.0};
  return {InertialStatus::Ok, value};
}

} // namespace stability
