// The checks of fix membrane3d against the LIGGGHTS state and across the ranks. Each
// stops the run on every rank at once (error->all) with a message that starts with
// `prefix` (common/style_args.h).
#ifndef LIGGGHTS_MEMBRANE_MEMBRANE3D_CHECKS_H
#define LIGGGHTS_MEMBRANE_MEMBRANE3D_CHECKS_H

#include <cstddef>
#include <string>
#include <vector>

#include "lammps.h"

#include "lateral_surface.h"
#include "membrane3d_gather.h"

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

// Every rank found the same members and facets (they computed them from the same
// spheres: a disagreement is a bug, stopped here rather than left to hang the run).
void check_ranks_agree(LAMMPS_NS::LAMMPS *lmp, const char *prefix,
                       const std::vector<int> &member_tags, std::size_t facets);

#endif
