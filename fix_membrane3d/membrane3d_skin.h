// The detection from the skin of the last membrane (skin_flood.h) on one process, with
// all the spheres at hand (every auto's detect, the tests; fix membrane3d itself
// gathers the skin only: membrane3d_distributed.h): the
// membrane of all the group's spheres, found from those within SKIN_THICKNESS mean
// diameters of the last detection's members (at a run's first detection: of the
// outermost spheres) when they show it to be the same, else from all of them. No
// LIGGGHTS here: unit-tested in tests/unit/membrane3d.
#ifndef LIGGGHTS_MEMBRANE_MEMBRANE3D_SKIN_H
#define LIGGGHTS_MEMBRANE_MEMBRANE3D_SKIN_H

#include <vector>

#include "atom_id.h"
#include "gathered_spheres.h"
#include "lateral_surface.h"

namespace membrane3d {

// The membrane of `all` (the group's spheres), from the skin around the atoms of
// `member_tags` (ascending; those no longer in `all` are passed over; none: around the
// outermost spheres).
MembraneTopology detect_near_members(const GatheredSpheres &all,
                                     const std::vector<AtomId> &member_tags, const Platens &platens,
                                     double tolerance);

} // namespace membrane3d

#endif
