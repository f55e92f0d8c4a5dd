// The snapshots of a LIGGGHTS dump "id radius x y z" (sorted by id, the same atoms in
// each), for the membrane3d benches (membrane3d_steps.cpp, membrane3d_kinetic.cpp).
#ifndef LIGGGHTS_MEMBRANE_BENCH_DUMP_SNAPSHOTS_H
#define LIGGGHTS_MEMBRANE_BENCH_DUMP_SNAPSHOTS_H

#include "exterior_flood.h"

#include <cstddef>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace bench {

struct Snapshot {
  long step = 0;
  std::vector<membrane3d::Sphere> spheres;
};

// The next snapshot of `in`; false at the end or on a short one.
inline bool read_snapshot(std::ifstream &in, Snapshot &s)
{
  std::string line;
  if (!std::getline(in, line)) return false; // ITEM: TIMESTEP
  in >> s.step;
  std::getline(in, line);
  std::getline(in, line); // ITEM: NUMBER OF ATOMS
  std::size_t n = 0;
  in >> n;
  std::getline(in, line);
  for (int k = 0; k < 5; ++k) std::getline(in, line); // box bounds, ITEM: ATOMS
  s.spheres.clear();
  double id, r, x, y, z;
  for (std::size_t k = 0; k < n && in >> id >> r >> x >> y >> z; ++k)
    s.spheres.push_back({Eigen::Vector3d(x, y, z), r});
  std::getline(in, line);
  return s.spheres.size() == n && n > 0;
}

// All snapshots of the dump at `path`; false (said on std::cerr) when fewer than two.
inline bool read_snapshots(const char *path, std::vector<Snapshot> &snapshots)
{
  std::ifstream in(path);
  snapshots.clear();
  for (Snapshot s; read_snapshot(in, s);) snapshots.push_back(s);
  if (snapshots.size() < 2) {
    std::cerr << "fewer than two snapshots in " << path << "\n";
    return false;
  }
  return true;
}

} // namespace bench

#endif
