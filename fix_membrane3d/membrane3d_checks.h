// The checks of fix membrane3d against the LIGGGHTS state and across the ranks. Each
// stops the run on every rank at once (error->all) with a message that starts with
// `prefix` (common/style_args.h).
#ifndef LIGGGHTS_MEMBRANE_MEMBRANE3D_CHECKS_H
#define LIGGGHTS_MEMBRANE_MEMBRANE3D_CHECKS_H

#include <cstddef>
#include <initializer_list>
#include <string>
#include <vector>

#include "lammps.h"

#include "lateral_surface.h"
#include "membrane3d_gather.h"
#include "scalar_input.h"

namespace LAMMPS_NS {
class Fix;
}

// Every sphere of `g` with a finite centre strictly between the platens and a positive
// radius (else names the atom and the step).
void check_between_platens(LAMMPS_NS::LAMMPS *lmp, const char *prefix, const GatheredSpheres &g,
                           const membrane3d::Platens &platens);

// At least the four spheres of a tetrahedron in the group (named) at a detection.
void check_enough_spheres(LAMMPS_NS::LAMMPS *lmp, const char *prefix, const char *group,
                          std::size_t spheres);

// Warns once (`warned`) when the membrane does not reach a platen: it then closes over
// that end of the sample.
void warn_if_open(LAMMPS_NS::LAMMPS *lmp, const char *prefix,
                  const membrane3d::LateralSurface &membrane, bool &warned);

// The platens in order: zlo below zhi at this step (naming both inputs: either may
// be the variable that moved).
void check_platens_in_order(LAMMPS_NS::LAMMPS *lmp, const char *prefix, const ScalarInput &lo,
                            const ScalarInput &hi, const membrane3d::Platens &platens);

// The tolerance T (as given, `text`) at most `most` mean diameters `d` of the group:
// a wider T bridges the hollows of the sample's surface, and far wider ones (1e11 d)
// leave the regular triangulation's weights to round-off.
void check_tolerance(LAMMPS_NS::LAMMPS *lmp, const char *prefix, const std::string &text,
                     double tolerance, double d, double most, double usual);

// The loads' net force, after checking that they are finite (`pressure` times the
// areas can overflow) and have no lateral part beyond round-off: a closed membrane
// with its rims in the platen planes has none, and a run must not go on with loads
// that have one.
Eigen::Vector3d check_closed(LAMMPS_NS::LAMMPS *lmp, const char *prefix,
                             const std::vector<Eigen::Vector3d> &load, double pressure);

// Warns once (`warned`) when a member of `now` is more than the tolerance from where it
// was when the membrane was found at step `since` (`at`, in the same order; empty after
// a restart: then from now on): that membrane can be out of date.
void warn_if_moved(LAMMPS_NS::LAMMPS *lmp, const char *prefix, const GatheredSpheres &now,
                   std::vector<membrane3d::Sphere> &at, double tolerance, long long since,
                   bool &warned);

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
