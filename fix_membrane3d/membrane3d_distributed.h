// fix membrane3d's detection from a skin gathered from the ranks, certified by each rank
// on its own spheres: no rank gathers or loops over the whole group (but for the last
// resort, counted).
//
// 1. Seeds: the last members (their atoms gathered); at a run's first detection the
//    outermost spheres, found collectively (outermost_spheres of skin_flood.h: the axis
//    from a sum, each bin's farthest reach from a reduction, each rank picking its own).
//    Any seeds are safe, since the certificate decides: the round-off of the axis and
//    of the mean diameter (the skin's thickness, the bins' size), sums over the ranks
//    whose last bits depend on their number, can change the skin, never the membrane.
// 2. The skin: each rank's own atoms of the group within the skin's thickness of a
//    seed, gathered to every rank sorted by ID (as all the atoms were before), mirrored
//    with the band of the whole group (its largest radius, reduced).
// 3. The certificate (skin_flood.h): every rank floods the same skin; each tests its
//    own left-out spheres and their images; the failures are counted over the ranks.
// 4. A failure: the left-out spheres that failed join the skin (gathered, they are
//    few) and it is certified again; after every ROUNDS_PER_THICKNESS such rounds the
//    thickness doubles; after MOST_ROUNDS, or for a skin that shows nothing (flat, its
//    shell no larger than another dry group), the last resort: all the spheres
//    gathered and flooded, as before (counted).
// The membrane is that of all the group's spheres in every case (skin_flood.h), so it
// does not depend on the number of ranks.
#ifndef LIGGGHTS_MEMBRANE_MEMBRANE3D_DISTRIBUTED_H
#define LIGGGHTS_MEMBRANE_MEMBRANE3D_DISTRIBUTED_H

#include <vector>

#include "distributed_skin.h"
#include "membrane3d_gather.h"

namespace membrane3d {

constexpr int ROUNDS_PER_THICKNESS = 4, MOST_ROUNDS = 8;

// The membrane of the group's spheres (collective), its topology over `skin`: the
// spheres it was found from, sorted by ID (the members among them). `totals`: the
// group's (Membrane3dGather::totals, which checked every atom). Throws what
// detect_membrane throws.
MembraneTopology detect_distributed(const Membrane3dGather &gather,
                                    const std::vector<AtomId> &member_tags, double tolerance,
                                    const Membrane3dGather::Totals &totals, GatheredSpheres &skin,
                                    SkinCounters &counters);

} // namespace membrane3d

#endif
