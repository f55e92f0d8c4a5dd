// The checks of fix membrane3d against the LIGGGHTS state and across the ranks. Each
// stops the run on every rank at once (error->all) with a message that starts with
// `prefix` (common/style_args.h).
#ifndef LIGGGHTS_MEMBRANE_MEMBRANE3D_CHECKS_H
#define LIGGGHTS_MEMBRANE_MEMBRANE3D_CHECKS_H

#include <cstddef>
#include <initializer_list>
#include <vector>

#include "lammps.h"

#include "lateral_surface.h"
#include "membrane3d_gather.h"
#include "scalar_input.h"

namespace LAMMPS_NS {
class Fix;
}

// Every sphere centre of `g` strictly between the platens (else names the atom).
void check_between_platens(LAMMPS_NS::LAMMPS *lmp, const char *prefix, const GatheredSpheres &g,
                           const membrane3d::Platens &platens);

// No other membrane3d shares a sphere or the vtk file with `self`.
void check_other_membranes(LAMMPS_NS::LAMMPS *lmp, const char *prefix, LAMMPS_NS::Fix *self);

// Every rank found the same members and facets (they computed them from the same
// spheres: a disagreement is a bug, stopped here rather than left to hang the run).
void check_ranks_agree(LAMMPS_NS::LAMMPS *lmp, const char *prefix,
                       const std::vector<int> &member_tags, std::size_t facets);

// Rank 0's values of three inputs on every rank (a variable need not give the same
// number on every rank: LIGGGHTS' mesh reference point f_ID[7..9] differs between
// ranks by a step of the mesh's motion, measured; ranks that placed the platens
// differently would find different membranes). Warns once (`warned`) when they differ.
void same_on_every_rank(LAMMPS_NS::LAMMPS *lmp, const char *prefix, const ScalarInput *const (&inputs)[3],
                        std::initializer_list<const char *> names, double (&v)[3], bool &warned);

#endif
