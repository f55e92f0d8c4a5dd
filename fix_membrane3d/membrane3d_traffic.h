// fix membrane3d's figures of a run, like fix membrane2d's (membrane_gather.h): the
// bytes the busiest rank received from the fix, per step and per detection, the
// detections, and the seconds the fix and its detections took on the slowest rank.
// Printed at the end of each run to LIGGGHTS' screen and log, as a sentence and as a
// `membrane3d_traffic key=value ...` line for programs (bench/scaling3d.py). The small
// collectives (a rank's "detection due", the checks) are not counted: a few numbers
// each.
#ifndef LIGGGHTS_MEMBRANE_MEMBRANE3D_TRAFFIC_H
#define LIGGGHTS_MEMBRANE_MEMBRANE3D_TRAFFIC_H

#include <string>

#include "lammps.h"
#include "lmptype.h"

#include "scoped_seconds.h"

class Membrane3dTraffic {
 public:
  double received = 0.0;    // bytes received in the fix's gathers (Membrane3dGather adds them)
  double fix_seconds = 0.0; // the fix's pre_force and post_force (a ScopedSeconds each)

  // A run starts: the counts from 0, the fix's detections so far.
  void start(LAMMPS_NS::bigint step, double detections);

  // The scope of one detection: its seconds and the bytes received in it.
  class Detection {
   public:
    explicit Detection(Membrane3dTraffic &t)
      : traffic_(t), before_(t.received), timing_(t.detection_seconds_)
    {
    }
    ~Detection() { traffic_.detection_bytes_ += traffic_.received - before_; }
    Detection(const Detection &) = delete;
    Detection &operator=(const Detection &) = delete;

   private:
    Membrane3dTraffic &traffic_;
    double before_;
    ScopedSeconds timing_;
  };

  // A run ends (collective: the slowest rank's seconds): rank 0 prints the figures,
  // each line starting with `prefix` ("Fix membrane3d (id mem): ") but the key=value one.
  void report(LAMMPS_NS::LAMMPS *lmp, const std::string &prefix, const char *id,
              LAMMPS_NS::bigint step, double detections) const;

 private:
  double detection_bytes_ = 0.0, detection_seconds_ = 0.0;
  LAMMPS_NS::bigint first_step_ = 0;
  double first_detections_ = 0.0;
};

#endif
