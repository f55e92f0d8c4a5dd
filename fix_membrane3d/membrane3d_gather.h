// The spheres fix membrane3d works with, the same on every rank and sorted by atom ID,
// so that every rank finds the same membrane whatever the number of ranks and the
// processor grid.
#ifndef LIGGGHTS_MEMBRANE_MEMBRANE3D_GATHER_H
#define LIGGGHTS_MEMBRANE_MEMBRANE3D_GATHER_H

#include <vector>

#include "lammps.h"

#include "exterior_flood.h"

struct GatheredSpheres {
  std::vector<int> tags;                   // ascending
  std::vector<membrane3d::Sphere> spheres; // in the same order
  std::vector<int> types;                  // their atom types now
};

// The spheres' mean diameter (0 for none).
double mean_diameter(const GatheredSpheres &g);

// Every atom of the group.
void gather_group(LAMMPS_NS::LAMMPS *lmp, int groupbit, GatheredSpheres &out);

// The atoms of the group with these IDs (ascending), and their count: the caller
// compares it (an atom lost, or no longer in the group).
std::size_t gather_tags(LAMMPS_NS::LAMMPS *lmp, int groupbit, const std::vector<int> &tags,
                 GatheredSpheres &out);

#endif
