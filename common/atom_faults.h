// A sphere the input has made unusable for a membrane: a position that is not finite
// (the run went unstable before the membrane saw it) or a radius that is not positive.
// Both membranes name it by atom ID and step and say the input is at fault, in the
// same words (doc/messages.md), never "a fault of fix membrane...".
#ifndef LIGGGHTS_MEMBRANE_ATOM_FAULTS_H
#define LIGGGHTS_MEMBRANE_ATOM_FAULTS_H

#include <mpi.h>

#include <climits>
#include <cmath>
#include <string>

#include "atom.h"
#include "lammps.h"
#include "update.h"

#include "number_text.h"
#include "rank_choice.h"

// True when a sphere of `dims` coordinates x and radius r cannot be used.
inline bool atom_is_faulty(const double *x, int dims, double r)
{
  for (int d = 0; d < dims; d++)
    if (!std::isfinite(x[d])) return true;
  return !(r > 0) || !std::isfinite(r);
}

// What is wrong with atom `tag` (atom_is_faulty, or its velocity v not finite) at
// `step`, and what to do.
inline std::string atom_fault_text(long tag, const double *x, int dims, double r, long long step,
                                   const double *v = nullptr)
{
  bool finite = true, moving = true;
  std::string where, speed;
  for (int d = 0; d < dims; d++) {
    finite = finite && std::isfinite(x[d]);
    where += (d ? ", " : "") + number_text(x[d]);
    if (!v) continue;
    moving = moving && std::isfinite(v[d]);
    speed += (d ? ", " : "") + number_text(v[d]);
  }
  const bool radius = finite && moving;
  return "atom " + std::to_string(tag) + " has " +
         (!finite   ? "a position that is not finite (" + where + ")"
          : !moving ? "a velocity that is not finite (" + speed + ")"
                    : "radius " + number_text(r)) +
         " at step " + std::to_string(step) + "; the input is at fault, not the membrane: " +
         (radius ? "every sphere of the group needs a positive radius"
                 : "the run went unstable before (check the time step, the stiffness and the "
                   "pressure)");
}

// The message for the group's atom of lowest ID whose position, velocity or radius is
// unusable, on any rank; "" when there is none (collective; the same text on every rank).
inline std::string group_atom_fault(LAMMPS_NS::LAMMPS *lmp, int groupbit, int dims)
{
  const LAMMPS_NS::Atom *atom = lmp->atom;
  int mine = -1;
  for (int i = 0; i < atom->nlocal; i++)
    if ((atom->mask[i] & groupbit) &&
        (atom_is_faulty(atom->x[i], dims, atom->radius[i]) || atom_is_faulty(atom->v[i], dims, 1)) &&
        (mine < 0 || atom->tag[i] < atom->tag[mine]))
      mine = i;
  int any = mine >= 0 ? 1 : 0;
  MPI_Allreduce(MPI_IN_PLACE, &any, 1, MPI_INT, MPI_MAX, lmp->world);
  if (!any) return "";
  double record[7] = {0, 0, 0, 0, 0, 0, 0}; // x, v, r of that atom, from its rank
  if (mine >= 0) {
    for (int d = 0; d < 3; d++) {
      record[d] = atom->x[mine][d];
      record[3 + d] = atom->v[mine][d];
    }
    record[6] = atom->radius[mine];
  }
  const int tag = rank_choice::name_first(lmp->world, mine >= 0 ? atom->tag[mine] : LLONG_MAX,
                                          record, 7);
  return atom_fault_text(tag, record, dims, record[6], lmp->update->ntimestep, record + 3);
}

#endif
