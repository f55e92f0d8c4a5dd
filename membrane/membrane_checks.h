// The checks both membranes make of their input against the LIGGGHTS state and
// across the ranks. Each stops the run on every rank at once with a message that
// starts with the fix's prefix (doc/messages.md).
#ifndef LIGGGHTS_MEMBRANE_MEMBRANE_CHECKS_H
#define LIGGGHTS_MEMBRANE_MEMBRANE_CHECKS_H

#include <string>

#include "lammps.h"

#include "scalar_input.h"

namespace LAMMPS_NS {
class MembraneFix;
}

// What both membranes need of LIGGGHTS' atoms and box, checked in each fix's
// constructor: the dimension, per-atom radii, atom IDs with a map (the membrane is
// kept by atom ID), and no periodic boundary across the sample. A periodic boundary
// that cuts the sample would give the membrane wrapped positions, two half-samples
// with the membrane's load on the seam inside the sample; periodic along the
// platens' axis, the platens bound nothing.
void check_membrane_setup(LAMMPS_NS::LAMMPS *lmp, const std::string &prefix, int dimension);

// The keyword 'frictionless T': type T must have no friction with any type (checked
// at every run); T = 0 is warned about: `which` keep their friction.
void check_frictionless_type(LAMMPS_NS::LAMMPS *lmp, const std::string &prefix, int type,
                             const char *style, const std::string &which);

// No other fix of the same style shares a particle or a frame file with `self`.
void check_other_membranes(LAMMPS_NS::LAMMPS *lmp, const std::string &prefix,
                           LAMMPS_NS::MembraneFix *self);

// Rank 0's values of the three inputs on every rank (a variable need not give the
// same number on every rank: LIGGGHTS' mesh reference point f_ID[7..9] differs
// between ranks by a step of the mesh's motion, measured; ranks that placed the
// platens differently would find different membranes). Warns once (`warned`) when
// they differ.
void same_on_every_rank(LAMMPS_NS::LAMMPS *lmp, const std::string &prefix,
                        const ScalarInput *const (&inputs)[3], const char *const (&names)[3],
                        double (&v)[3], bool &warned);

// The platens in order at this step (naming both inputs: either may be the
// variable that moved).
void check_platens_in_order(LAMMPS_NS::LAMMPS *lmp, const std::string &prefix,
                            const char *lo_key, const ScalarInput &lo_in, double lo,
                            const char *hi_key, const ScalarInput &hi_in, double hi);

#endif
