// The spheres fix membrane3d works with, gathered from every rank (membrane3d_gather.h)
// and sorted by atom ID, so that every rank finds the same membrane whatever the number
// of ranks and the processor grid. No LIGGGHTS here: unit-tested in tests/unit/membrane3d.
#ifndef LIGGGHTS_MEMBRANE_GATHERED_SPHERES_H
#define LIGGGHTS_MEMBRANE_GATHERED_SPHERES_H

#include <vector>

#include "atom_id.h"
#include "exterior_flood.h"

namespace membrane3d {

struct GatheredSpheres {
  std::vector<AtomId> tags;    // ascending
  std::vector<Sphere> spheres; // in the same order
  std::vector<int> types;      // their atom types now
};

// The spheres' mean diameter (0 for none).
double mean_diameter(const GatheredSpheres &g);

// The entry of atom `tag` in g, -1 when g does not hold it.
int index_of(const GatheredSpheres &g, AtomId tag);

// The entries `index` of g, in that order.
GatheredSpheres subset(const GatheredSpheres &g, const std::vector<int> &index);

} // namespace membrane3d

#endif
