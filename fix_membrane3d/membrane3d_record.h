// The restart record of fix membrane3d (no LIGGGHTS: unit-tested in
// tests/unit/membrane3d): its definition, the last detection (the topology over the
// member atoms' IDs and its step; with every auto, the spheres it was made on) and
// the detection counter, and a checksum of the group then (common/group_checksum.h).
// Records of versions 1 (without the spheres), 2 (without the decided step) and 3
// (without the checksum) are read.
#ifndef LIGGGHTS_MEMBRANE_MEMBRANE3D_RECORD_H
#define LIGGGHTS_MEMBRANE_MEMBRANE3D_RECORD_H

#include "atom_id.h"
#include "lateral_surface.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace membrane3d {

// tolerance_given of a record before version 5 that took the default, then a
// multiple of the mean diameter: a definition other than any of this version
constexpr double MEAN_DIAMETER_DEFAULT = -2.0;

struct Membrane3dState {
  double tolerance_given = -1;  // as given, -1 for the default
  int every = 0; // 0: every auto
  double last_detection = -1;   // step
  double decided_step = -1;     // the last step whose detection was decided (version 3)
  double detections = 0;
  std::vector<AtomId> member_tags;
  MembraneTopology topology;    // over the members
  // with every auto: the group's spheres at the detection (by ID) and the platens
  std::vector<AtomId> sample_tags;
  std::vector<Sphere> sample;
  Platens sample_platens{0, 0};
  double window_steps = 0, window_detections = 0, unwatched_until = -1; // DenseDetections
  // the group when the record was written (version 4): a read_restart followed by a
  // delete_atoms that renumbered it must not keep the membrane by atom ID
  Platens detected_platens{0, 0}; // where the last detection found them (version 4)
  bool has_checksum = false;
  std::uint64_t checksum = 0;
};

std::vector<double> write_record(const Membrane3dState &state);

// Empty when `state` was read; else why not (another format, cut or corrupt).
std::string read_record(const double *data, std::size_t n, Membrane3dState &state);

} // namespace membrane3d

#endif
