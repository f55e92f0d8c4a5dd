// fix membrane3d's every auto: the membrane is found again only when it can have
// changed (detection_watch.h), with the result of a detection at every step. This
// class keeps the watch of the last detection and decides each step from what the
// style gathers for it; where the membrane changes at most steps it detects for a
// while without building the watch (dense_detections.h). A restart carries the
// detection's spheres, from which the watch is built again, and that schedule, so that
// a split run detects when one straight through does. No LIGGGHTS here: unit-tested
// in tests/unit/membrane3d.
#ifndef LIGGGHTS_MEMBRANE_MEMBRANE3D_AUTO_H
#define LIGGGHTS_MEMBRANE_MEMBRANE3D_AUTO_H

#include <functional>
#include <vector>

#include "atom_id.h"
#include "dense_detections.h"
#include "detection_watch.h"
#include "gathered_spheres.h"
#include "membrane3d_record.h"

namespace membrane3d {

// What is checked of the group each step before the watch: the same atoms (their
// count and the sum of their IDs) and the same largest radius (the image band) as at
// the detection.
struct GroupSignature {
  double atoms = 0.0, id_sum = 0.0, largest = 0.0;
  void add(AtomId tag, double r);
  bool operator==(const GroupSignature &o) const
  {
    return atoms == o.atoms && id_sum == o.id_sum && largest == o.largest;
  }
};

class Membrane3dAuto {
 public:
  // The group now, as the style gathers it (collective: every rank calls them alike).
  struct Group {
    std::function<GroupSignature()> signature;
    // the group's atoms with these IDs (ascending), those no longer in it left out
    std::function<void(const std::vector<AtomId> &tags, GatheredSpheres &out)> gather;
  };

  Membrane3dAuto(); // its dense schedule (membrane3d_tuning.h)

  // A detection on the group's spheres `all` (the whole topology, over all), without a
  // watch from the skin of the last members (membrane3d_skin.h); d50: the group's D50,
  // the watch's budget in WATCH_BUDGET.
  MembraneTopology detect(const GatheredSpheres &all, const std::vector<AtomId> &member_tags,
                          const Platens &platens, double tolerance, double d50, long long step);
  // Whether this step's detection builds the watch (from all the group's spheres, with
  // detect); when not, the caller detects from the skin and calls unwatched().
  bool builds_watch(long long step) const { return !dense.unwatched(step); }
  // A detection without the watch (dense schedule), at these platens.
  void unwatched(const Platens &at);
  // its members (indices into all, ascending: members_only)
  void set_members(const std::vector<int> &members);

  // This step: whether the membrane found last can have changed; when not, `members`
  // holds the member atoms now. Checks the group's signature against the detection's,
  // then gathers the watched atoms.
  bool can_have_changed(const Group &group, const Platens &platens, double tolerance, double d50,
                        long long step, GatheredSpheres &members);

  // restart: the detection's spheres and platens, the schedule
  void save(Membrane3dState &state) const;
  void restore(const Membrane3dState &state);

  double memory_usage() const;

 private:
  DetectionWatch watch;
  bool built = false;
  DenseDetections dense;
  GatheredSpheres sample;        // the group at the detection
  Platens platens{0.0, 0.0};     // at the detection
  std::vector<AtomId> watched_tags; // of watch.spheres
  std::vector<int> member_entry; // per member: its entry of watch.spheres
  GatheredSpheres watched;       // this step
  GroupSignature signature;      // the sample's

  MembraneTopology build(double tolerance, double d50);
};

} // namespace membrane3d

#endif
