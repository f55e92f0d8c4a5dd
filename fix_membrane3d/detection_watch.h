// What a detection of fix membrane3d depends on (every auto), so that the membrane
// is found again only when it can have changed, and is then the membrane a detection
// at every step would find. No LIGGGHTS here: unit-tested in tests/unit/membrane3d.
//
// A detection (lateral_surface.h) mirrors the spheres near the platens and floods the
// triangulation of spheres and images (exterior_flood.h). Its result holds while the
// flood's watch holds (flood_watch.h: the watched certificates, and no point of the
// buffer moved by the budget since the detection, an image moving with its sphere and
// twice its platen), every watched sphere keeps its radius and its images (which
// platens it is within the image band of), and no other sphere was added, lost or
// resized (the caller's part: the image band depends on the largest radius).
#ifndef LIGGGHTS_MEMBRANE_DETECTION_WATCH_H
#define LIGGGHTS_MEMBRANE_DETECTION_WATCH_H

#include "flood_watch.h"
#include "lateral_surface.h"

#include <array>
#include <vector>

namespace membrane3d {

struct DetectionWatch {
  FloodWatch flood;
  std::vector<int> spheres;                // the detection's spheres watched, ascending
  std::vector<MembraneVertex> points;      // per flood point: its entry of `spheres`, its image
  std::vector<Sphere> at_detection;        // per entry of `spheres`
  std::vector<std::array<char, 2>> imaged; // per entry: imaged below, above
  Platens platens{0.0, 0.0};
  double band = 0.0, budget = 0.0, grid = 0.0; // grid: height_grid
};

// detect_membrane (lateral_surface.h) with the watch of its result for motions of
// less than `budget`.
MembraneTopology detect_watched_membrane(const std::vector<Sphere> &spheres, const Platens &platens,
                                         double tolerance, double budget, DetectionWatch &watch);

// Whether the membrane can have changed, `now` holding the watched spheres (in the
// order of watch.spheres) at their present positions between `platens`.
bool membrane_can_have_changed(const DetectionWatch &watch, const std::vector<Sphere> &now,
                               const Platens &platens);

} // namespace membrane3d

#endif
