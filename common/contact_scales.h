#ifndef LIGGGHTS_MEMBRANE_CONTACT_SCALES_H
#define LIGGGHTS_MEMBRANE_CONTACT_SCALES_H

#include <mpi.h>

#include <algorithm>
#include <string>
#include <vector>

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix_property_global.h"
#include "lammps.h"
#include "modify.h"
#include "update.h"

#include "allgather.h"
#include "grain_size.h"
#include "math_constants.h"
#include "stability_limits.h"
#include "style_error.h"

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

// Grain scales of a group over all ranks: D50 by mass (for one density; the step
// definition of grain_size.h) and the
// mean density: group mass / disk area (per unit thickness) in 2D, / sphere
// volume in 3D.
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
  const int dimension = lmp->domain->dimension;
  double sums[2] = {0.0, 0.0}; // mass, area (2D) or volume (3D)
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    const double r = atom->radius[i];
    diameters.push_back(2.0 * r);
    if (atom->rmass_flag) sums[0] += atom->rmass[i];
    sums[1] +=
        dimension == 3 ? 4.0 / 3.0 * math_constants::PI * r * r * r : math_constants::PI * r * r;
  }
  allgather_doubles(world, diameters, all, counts, displs);
  MPI_Allreduce(MPI_IN_PLACE, sums, 2, MPI_DOUBLE, MPI_SUM, world);
  GrainScales g;
  g.empty = all.empty();
  g.d50 = grains::d50_by_mass(all, dimension); // the step definition (grain_size.h)
  g.density = sums[1] > 0.0 ? sums[0] / sums[1] : 0.0;
  return g;
}

// Warns (on rank 0) when the time step exceeds `limit` x sqrt(m_min/k_n) of
// the group, naming the style through `prefix` (the wording, which depends on
// how large the step is, is stability::time_step_warning); `warned_dt` holds
// the step last warned about, so each run of a script with the same dt does
// not repeat it. Returns dt / sqrt(m_min/k_n), 0 when the contact model has no
// linear stiffness table to check against.
inline double check_time_step(LAMMPS_NS::LAMMPS *lmp, int groupbit, MPI_Comm world,
                              const std::string &prefix, double limit, double &warned_dt)
{
  const double kmax = max_normal_stiffness(lmp, prefix.c_str());
  const double mmin = min_group_mass(lmp, groupbit, world);
  const double dt = lmp->update->dt;
  const double ratio = stability::time_step_ratio(dt, mmin, kmax);
  if (ratio > limit && dt != warned_dt)
    style_warning(lmp, prefix, stability::time_step_warning(dt, mmin, kmax, limit));
  if (ratio > limit) warned_dt = dt;
  return ratio;
}

#endif
