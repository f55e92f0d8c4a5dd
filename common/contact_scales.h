#ifndef LIGGGHTS_MEMBRANE_CONTACT_SCALES_H
#define LIGGGHTS_MEMBRANE_CONTACT_SCALES_H

#include <mpi.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix_property_global.h"
#include "lammps.h"
#include "modify.h"
#include "update.h"

#include "allgather.h"
#include "grain_size.h"
#include "math_const.h"
#include "stability_checks.h"

// The two numbers that set the contact time scale sqrt(m/k) of a linear
// granular contact model: the largest normal stiffness of the per-type-pair
// table `fix property/global kn peratomtypepair` (0 when there is none, e.g. a
// Hertz model) and the smallest disk mass of a group over all ranks (0 when
// the group is empty or atoms carry no per-atom mass).

inline double max_normal_stiffness(LAMMPS_NS::LAMMPS *lmp, const char *caller)
{
  const int ntypes = lmp->atom->ntypes;
  auto *kn = static_cast<LAMMPS_NS::FixPropertyGlobal *>(lmp->modify->find_fix_property(
      "kn", "property/global", "peratomtypepair", ntypes, ntypes, caller, false));
  if (!kn) return 0.0;
  double kmax = 0.0;
  for (int i = 0; i < ntypes; i++)
    for (int j = 0; j < ntypes; j++) kmax = std::max(kmax, kn->compute_array(i, j));
  return kmax;
}

inline double min_group_mass(LAMMPS_NS::LAMMPS *lmp, int groupbit, MPI_Comm world)
{
  LAMMPS_NS::Atom *atom = lmp->atom;
  double mmin = 1e300;
  if (atom->rmass_flag)
    for (int i = 0; i < atom->nlocal; i++)
      if (atom->mask[i] & groupbit) mmin = std::min(mmin, atom->rmass[i]);
  MPI_Allreduce(MPI_IN_PLACE, &mmin, 1, MPI_DOUBLE, MPI_MIN, world);
  return mmin < 1e300 ? mmin : 0.0;
}

// Grain scales of a group over all ranks: D50 by area (= by mass for one
// density) and the mean density (group mass / disk area, per unit thickness).
struct GrainScales {
  double d50 = 0.0;
  double density = 0.0;
  bool empty = true;
};

inline GrainScales group_grain_scales(LAMMPS_NS::LAMMPS *lmp, int groupbit, MPI_Comm world)
{
  LAMMPS_NS::Atom *atom = lmp->atom;
  std::vector<double> diameters, all;
  std::vector<int> counts, displs;
  double sums[2] = {0.0, 0.0}; // mass, area
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    diameters.push_back(2.0 * atom->radius[i]);
    if (atom->rmass_flag) sums[0] += atom->rmass[i];
    sums[1] += LAMMPS_NS::MathConst::MY_PI * atom->radius[i] * atom->radius[i];
  }
  allgather_doubles(world, diameters, all, counts, displs);
  MPI_Allreduce(MPI_IN_PLACE, sums, 2, MPI_DOUBLE, MPI_SUM, world);
  GrainScales g;
  g.empty = all.empty();
  g.d50 = stability::d50_by_area(all);
  g.density = sums[1] > 0.0 ? sums[0] / sums[1] : 0.0;
  return g;
}

// Warns (on rank 0) when the time step exceeds `limit` x sqrt(m_min/k_n) of
// the group, naming the style through `prefix`; `warned_dt` holds the step
// last warned about, so each run of a script with the same dt does not repeat
// it. What it says depends on how large the step is, not only on the limit:
// above 0.3 (poorly resolved contacts) it says to reduce the step to 0.15 of
// sqrt(m_min/k_n) (the published set-up); a step within 0.15 exceeds only a
// stricter limit, and is called safe. Returns dt / sqrt(m_min/k_n), 0 when the
// contact model has no linear stiffness table to check against.
inline double check_time_step(LAMMPS_NS::LAMMPS *lmp, int groupbit, MPI_Comm world,
                              const std::string &prefix, double limit, double &warned_dt)
{
  constexpr double poorly_resolved = stability::TIME_STEP_POORLY_RESOLVED;
  constexpr double safe = stability::TIME_STEP_SAFE;
  const double kmax = max_normal_stiffness(lmp, prefix.c_str());
  const double mmin = min_group_mass(lmp, groupbit, world);
  const double dt = lmp->update->dt;
  const double ratio = stability::time_step_ratio(dt, mmin, kmax);
  if (ratio > limit && dt != warned_dt && lmp->comm->me == 0) {
    const double fraction = std::min(limit, safe);
    const double suggested = stability::safe_time_step(fraction, mmin, kmax);
    char buf[768];
    int n = snprintf(buf, sizeof(buf),
                     "time step %g s is %.2g x sqrt(m_min/k_n) = %.3g s (m_min = %.3g kg, "
                     "k_n = %.3g N/m), above the limit %g",
                     dt, ratio, stability::contact_time(mmin, kmax), mmin, kmax, limit);
    if (n < 0 || n >= static_cast<int>(sizeof(buf))) n = static_cast<int>(sizeof(buf)) - 1;
    const size_t rest = sizeof(buf) - static_cast<size_t>(n);
    if (ratio > poorly_resolved)
      snprintf(buf + n, rest,
               "; above %g the contacts are poorly resolved and the run may go "
               "unstable: reduce it, use timestep <= %.2g (%g x sqrt(m_min/k_n)%s)",
               poorly_resolved, suggested, fraction,
               fraction == safe ? ", the published set-up" : "");
    else if (ratio > safe)
      snprintf(buf + n, rest, ": use timestep <= %.2g (%g x sqrt(m_min/k_n)%s)", suggested,
               fraction, fraction == safe ? ", the published set-up" : "");
    else
      snprintf(buf + n, rest,
               "; it is within %g x sqrt(m_min/k_n), the published set-up, which is "
               "safe: keep it, or use timestep <= %.2g only to stay below the limit",
               safe, suggested);
    lmp->error->warning(FLERR, (prefix + buf).c_str());
  }
  if (ratio > limit) warned_dt = dt;
  return ratio;
}

#endif
