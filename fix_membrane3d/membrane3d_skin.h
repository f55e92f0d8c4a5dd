// fix membrane3d's detection from the skin of its last membrane (skin_flood.h): the
// membrane of all the group's spheres, found from those within a mean diameter of the
// last detection's members (at a run's first detection: of the outermost spheres) when
// they show it to be the same, else from all of them.
#ifndef LIGGGHTS_MEMBRANE_MEMBRANE3D_SKIN_H
#define LIGGGHTS_MEMBRANE_MEMBRANE3D_SKIN_H

#include <vector>

#include "lateral_surface.h"
#include "membrane3d_gather.h"

// The membrane of `all` (the group's spheres), from the skin around the atoms of
// `member_tags` (ascending; those no longer in `all` are passed over; none: around the
// outermost spheres).
membrane3d::MembraneTopology detect_near_members(const GatheredSpheres &all,
                                                 const std::vector<int> &member_tags,
                                                 const membrane3d::Platens &platens,
                                                 double tolerance);

#endif
