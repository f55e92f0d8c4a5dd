// The spheres fix membrane3d works with, gathered from every rank (gathered_spheres.h),
// and its checks across the ranks. Each gather checks what it gathered: a sphere that
// is unusable (atom_faults.h) or not strictly between the platens stops the run on
// every rank at once with a message that starts with `prefix`, before anything is
// computed on it.
#ifndef LIGGGHTS_MEMBRANE_MEMBRANE3D_GATHER_H
#define LIGGGHTS_MEMBRANE_MEMBRANE3D_GATHER_H

#include <string>
#include <vector>

#include "atom_id.h"
#include "lammps.h"

#include "gathered_spheres.h"
#include "lateral_surface.h"
#include "membrane3d_auto.h"

struct Membrane3dGather {
  LAMMPS_NS::LAMMPS *lmp;
  const std::string &prefix;
  int groupbit;
  membrane3d::Platens platens; // this step's
  double *received = nullptr;  // the bytes received in the gathers are added here

  // The group's count and measures (collective). Each rank checks its own atoms as a
  // gather does: the lowest ID failing stops the run with its message on every rank.
  struct Totals {
    double atoms = 0, diameter_sum = 0, r_max = 0;
    double x_sum = 0, y_sum = 0, z_lo = 0, z_hi = 0; // of the centres
    double mean_diameter() const { return atoms > 0 ? diameter_sum / atoms : 0.0; }
  };
  Totals totals() const;
  // This rank's atoms of the group: their local indices, spheres and IDs.
  void own(std::vector<int> &index, std::vector<membrane3d::Sphere> &spheres,
           std::vector<AtomId> &tags) const;
  // The atoms with these local indices of every rank, sorted by ID (as group()).
  void some(const std::vector<int> &index, membrane3d::GatheredSpheres &out) const;

  // Every atom of the group.
  void group(membrane3d::GatheredSpheres &out) const;
  // The atoms of the group with these IDs (ascending), and their count: the caller
  // compares it (an atom lost, or no longer in the group).
  std::size_t tags(const std::vector<AtomId> &tags, membrane3d::GatheredSpheres &out) const;
  // The group's signature (collective) and tags(), for every auto.
  membrane3d::Membrane3dAuto::Group for_auto() const;
};

// Every rank found the same members and facets (they computed them from the same
// spheres: a disagreement is a bug, stopped here rather than left to hang the run).
void check_ranks_agree(LAMMPS_NS::LAMMPS *lmp, const std::string &prefix,
                       const std::vector<AtomId> &member_tags, std::size_t facets);

#endif
