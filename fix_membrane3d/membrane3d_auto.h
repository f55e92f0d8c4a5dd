// fix membrane3d's every auto: the membrane is found again only when it can have
// changed (detection_watch.h), with the result of a detection at every step. This
// class keeps the watch of the last detection, gathers the atoms it needs each step
// and decides; where the membrane changes at most steps it detects for a while
// without building the watch (dense_detections.h). A restart carries the detection's
// spheres, from which the watch is built again, and that schedule, so that a split
// run detects when one straight through does.
#ifndef LIGGGHTS_MEMBRANE_MEMBRANE3D_AUTO_H
#define LIGGGHTS_MEMBRANE_MEMBRANE3D_AUTO_H

#include <vector>

#include "lammps.h"

#include "dense_detections.h"
#include "detection_watch.h"
#include "membrane3d_gather.h"
#include "membrane3d_record.h"

class Membrane3dAuto {
 public:
  Membrane3dAuto(); // its dense schedule (membrane3d_auto.cpp)

  // a detection on the group's spheres `all` (the whole topology, over all), without a
  // watch from the skin of the last members (membrane3d_skin.h)
  membrane3d::MembraneTopology detect(const GatheredSpheres &all,
                                      const std::vector<int> &member_tags,
                                      const membrane3d::Platens &platens, double tolerance,
                                      long long step);
  // its members (indices into all, ascending: members_only)
  void set_members(const std::vector<int> &members);

  // This step (collective): whether the membrane found last can have changed; when
  // not, `members` holds the member atoms now. Checks the group (its atoms, their
  // IDs and largest radius) against the detection's.
  bool can_have_changed(LAMMPS_NS::LAMMPS *lmp, int groupbit, const membrane3d::Platens &platens,
                        double tolerance, long long step, GatheredSpheres &members);

  // restart: the detection's spheres and platens, the schedule
  void save(membrane3d::Membrane3dState &state) const;
  void restore(const membrane3d::Membrane3dState &state);

  double memory_usage() const;

 private:
  membrane3d::DetectionWatch watch;
  bool built = false;
  DenseDetections dense;
  GatheredSpheres sample;                // the group at the detection
  membrane3d::Platens platens{0.0, 0.0}; // at the detection
  std::vector<int> watched_tags;         // of watch.spheres
  std::vector<int> member_entry;         // per member: its entry of watch.spheres
  GatheredSpheres watched;               // this step
  double signature[3] = {0.0, 0.0, 0.0}; // atoms, sum of IDs, largest radius

  membrane3d::MembraneTopology build(double tolerance);
};

#endif
