// What fix membrane3d checks of its spheres and its membrane, and the message of each
// check that fails ("" when it holds); the style raises them (membrane3d_gather.h,
// fix_membrane3d.cpp) with its prefix. No LIGGGHTS here: unit-tested in
// tests/unit/membrane3d.
#ifndef LIGGGHTS_MEMBRANE_MEMBRANE3D_MESSAGES_H
#define LIGGGHTS_MEMBRANE_MEMBRANE3D_MESSAGES_H

#include <cstddef>
#include <string>
#include <vector>

#include "atom_id.h"
#include "gathered_spheres.h"
#include "lateral_surface.h"

namespace membrane3d {

// Atom `tag`'s centre at height z strictly between the platens at `step`.
std::string platens_problem(AtomId tag, double z, const Platens &platens, long long step);

// At least the four spheres of a tetrahedron in the group (named) at a detection.
std::string too_few_spheres(const std::string &group, std::size_t spheres, long long step);

// The membrane reaches both platens (else it closes over that end of the sample).
std::string open_warning(const LateralSurface &membrane, long long step);

// The loads' net force into `net`, and whether they are finite (`pressure` times the
// areas can overflow) and have no lateral part beyond CLOSURE_ROUND_OFF: a closed
// membrane with its rims in the platen planes has none, and a run must not go on with
// loads that have one.
std::string closure_problem(const std::vector<Eigen::Vector3d> &load, double pressure,
                            long long step, Eigen::Vector3d &net);
// The same from the loads' sum and the sum of their norms (summed over ranks).
std::string closure_problem(const Eigen::Vector3d &net, double magnitude, double pressure,
                            long long step);

// A member of `now` more than the tolerance from where it was when the membrane was
// found at step `since` (`at`, in the same order; of another size after a restart:
// then `at` becomes `now`, measured from now on): that membrane can be out of date.
std::string moved_warning(const GatheredSpheres &now, std::vector<Sphere> &at, double tolerance,
                          long long since, long long step);
// The same for the member `tag` found farthest, `moved` from where it was ("" when
// not more than the tolerance).
std::string moved_warning(AtomId tag, double moved, double tolerance, long long since,
                          long long step);

// The ranks found the same members and facets: `lo` and `hi` the least and most of
// (members, facets, sum of the member IDs) over the ranks.
std::string ranks_disagree(const double (&lo)[3], const double (&hi)[3], long long step);

} // namespace membrane3d

#endif
