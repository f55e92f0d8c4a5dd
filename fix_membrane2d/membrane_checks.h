#ifndef LIGGGHTS_MEMBRANE_MEMBRANE_CHECKS_H
#define LIGGGHTS_MEMBRANE_MEMBRANE_CHECKS_H

// The checks of fix membrane2d's input against the LIGGGHTS state. Each stops
// the run on every rank at once (error->all) with a message that starts with
// `prefix` and names the keyword and the value (common/style_args.h).

#include "lammps.h"

#include "membrane_gather.h"
#include "scalar_input.h"

namespace LAMMPS_NS {
class Fix;
}

// What the fix needs of the atoms and the box (2D, sphere, IDs and a map, x not periodic).
void check_atom_setup(LAMMPS_NS::LAMMPS *lmp, const char *prefix);
// The platens (evaluated at this step) are in order.
void check_platens_order(LAMMPS_NS::LAMMPS *lmp, const char *prefix, const ScalarInput &ylo_in,
                         double ylo, double yhi);
// No other fix of the same style shares a disk with `self`.
void check_other_membranes(LAMMPS_NS::LAMMPS *lmp, const char *prefix, LAMMPS_NS::Fix *self,
                           MembraneGather &gather);
// The band width and the gap tolerance are lengths this D50 can use.
void check_lengths(LAMMPS_NS::LAMMPS *lmp, const char *prefix, double band, double tolerance,
                   double d50);
// The platens enclose every disk centre of the group.
void check_platens_enclose(LAMMPS_NS::LAMMPS *lmp, const char *prefix, MembraneGather &gather,
                           const ScalarInput &ylo_in, double ylo, const ScalarInput &yhi_in,
                           double yhi);

#endif
