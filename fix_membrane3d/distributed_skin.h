// The parts of fix membrane3d's distributed detection (membrane3d_distributed.h) that
// each rank computes on its own spheres: the bins of the outermost spheres, and the
// counters of the rounds (which of its spheres are near the seeds: near_seeds,
// skin_flood.h). No LIGGGHTS here: unit-tested in
// tests/unit/membrane3d.
#ifndef LIGGGHTS_MEMBRANE_DISTRIBUTED_SKIN_H
#define LIGGGHTS_MEMBRANE_DISTRIBUTED_SKIN_H

#include <Eigen/Core>

#include <string>
#include <vector>

#include "exterior_flood.h"
#include "skin_flood.h"

namespace membrane3d {

// The bins of outermost_spheres (skin_flood.h), computed from reduced values so that
// every rank has the same: slabs `diameter` high from z_lo, sectors about `diameter`
// wide at the outer radius around the axis (at most MOST_BINS in all, the sectors
// fewer when needed). A rank's outermost spheres: those whose reach is within `depth`
// of the farthest in their bin (the bins' farthest: a reduction of the rank's).
struct OutermostBins {
  static constexpr long MOST_BINS = 1L << 18;
  Eigen::Vector2d axis = Eigen::Vector2d::Zero();
  double z_lo = 0, diameter = 1;
  long sectors = 8, slabs = 1;

  // z_hi: the highest centre, outer: the largest reach
  OutermostBins(const Eigen::Vector2d &axis, double z_lo, double z_hi, double outer,
                double diameter);
  std::size_t count() const { return static_cast<std::size_t>(sectors * slabs); }
  double reach(const Sphere &s) const { return (s.x.head<2>() - axis).norm() + s.r; }
  std::size_t bin(const Eigen::Vector3d &x) const;
};

// What the distributed detections did, for the benchmarks (summed over the run's
// detections from the skin; the same on every rank).
struct SkinCounters {
  double detections = 0;   // from the skin
  double rounds = 0;       // certificates that failed and were made again
  double joined = 0;       // left-out spheres that joined the skin after failing
  double doublings = 0;    // of the thickness
  double last_resorts = 0; // all the spheres gathered and triangulated
  double bytes = 0;        // received by this rank's gathers
  double last_bytes = 0;   // of the last detection
  double last_skin = 0;    // spheres in the last detection's skin

  // the counts since `then` (the last ones kept)
  SkinCounters operator-(const SkinCounters &then) const;
};

// A run's counts said in a line when a certificate failed or the last resort was
// taken, else "".
std::string skin_run_note(const SkinCounters &run);

} // namespace membrane3d

#endif
