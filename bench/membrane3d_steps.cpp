// How much of fix membrane3d's surface changes from one step to the next on a real
// run: what a kinetic repair of the triangulation (flips where it changed) would have
// to redo each step, against the detection from scratch that every auto does now.
// For consecutive snapshots of a dump "id radius x y z" (sorted by id, the same atoms
// in each), the membrane of each (all spheres, detect_membrane) against the first
// snapshot's and the one before it: facets and membrane spheres gained or lost, and
// the cells of the triangulation the flood reads (flooded cells and the dry cells next
// to them) that are new. Then the detection from the skin (detect_membrane_near, as
// fix membrane3d does it) of each snapshot around the members of the one 1 or 10 steps
// before, for skins of 0.5, 0.75 and 1 mean diameter: how often the skin holds (else
// all spheres are triangulated) and its time; and a run's first detection, from the
// skin of the outermost spheres.
//   membrane3d_steps DUMP ZLO ZHI TOLERANCE_IN_MEAN_DIAMETERS
#include "dump_snapshots.h"
#include "lateral_surface.h"
#include "skin_flood.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace {

using Vertex = std::pair<int, int>; // (sphere, image)
using FacetKey = std::array<Vertex, 3>;
using CellKey = std::array<Vertex, 4>;

using bench::Snapshot;

struct Found {
  std::set<FacetKey> facets;
  std::set<int> members;
  std::vector<int> seeds; // on the membrane or escaped: fix membrane3d's members
  std::set<CellKey> read_cells; // flooded, and dry next to the flood
  double ms = 0;
};

Found detect(const Snapshot &s, const membrane3d::Platens &platens, double tolerance)
{
  Found out;
  membrane3d::Mirrored mirrored;
  membrane3d::FloodCells cells;
  const auto start = std::chrono::steady_clock::now();
  const membrane3d::MembraneTopology t =
      membrane3d::detect_membrane(s.spheres, platens, tolerance, &mirrored, &cells);
  out.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  for (const auto &f : t.facets) {
    FacetKey key;
    for (int j = 0; j < 3; ++j) key[j] = {f[j].sphere, f[j].image};
    std::sort(key.begin(), key.end());
    out.facets.insert(key);
  }
  for (std::size_t k = 0; k < t.side.size(); ++k) {
    if (t.side[k] == membrane3d::Side::surface) out.members.insert(static_cast<int>(k));
    if (t.side[k] != membrane3d::Side::inside) out.seeds.push_back(static_cast<int>(k));
  }
  const auto vertex = [&](int v) -> Vertex {
    return v < 0 ? Vertex{-1, 0} : Vertex{mirrored.original[v], mirrored.image[v]};
  };
  for (std::size_t c = 0; c < cells.vertex.size(); ++c) {
    bool read = cells.flooded[c] != 0;
    for (int j = 0; j < 4 && !read; ++j) {
      const int n = cells.neighbour[c][j];
      read = n >= 0 && cells.flooded[n] != 0;
    }
    if (!read) continue;
    CellKey key;
    for (int j = 0; j < 4; ++j) key[j] = vertex(cells.vertex[c][j]);
    std::sort(key.begin(), key.end());
    out.read_cells.insert(key);
  }
  return out;
}

template <class T> std::size_t missing(const std::set<T> &from, const std::set<T> &in)
{
  std::size_t n = 0;
  for (const T &x : from) n += in.count(x) == 0;
  return n;
}

} // namespace

int main(int argc, char **argv)
{
  if (argc != 5) {
    std::cerr << "usage: membrane3d_steps DUMP ZLO ZHI TOLERANCE_IN_MEAN_DIAMETERS\n";
    return 2;
  }
  const membrane3d::Platens platens{std::atof(argv[2]), std::atof(argv[3])};
  std::vector<Snapshot> snapshots;
  if (!bench::read_snapshots(argv[1], snapshots)) return 1;
  double diameters = 0;
  for (const auto &s : snapshots[0].spheres) diameters += 2 * s.r;
  const double tolerance = std::atof(argv[4]) * diameters / snapshots[0].spheres.size();
  std::printf("%zu snapshots of %zu spheres, tolerance %.4g m\n", snapshots.size(),
              snapshots[0].spheres.size(), tolerance);
  std::printf("step,facets,facets_new_since_last,facets_new_since_first,members,"
              "members_new_since_last,read_cells,read_cells_new_since_last,detection_ms\n");
  Found first, last;
  std::vector<Found> found;
  for (std::size_t k = 0; k < snapshots.size(); ++k) {
    const Found now = detect(snapshots[k], platens, tolerance);
    found.push_back(now);
    if (k == 0) first = now;
    std::printf("%ld,%zu,%zu,%zu,%zu,%zu,%zu,%zu,%.1f\n", snapshots[k].step, now.facets.size(),
                k ? missing(now.facets, last.facets) : 0, missing(now.facets, first.facets),
                now.members.size(), k ? missing(now.members, last.members) : 0,
                now.read_cells.size(), k ? missing(now.read_cells, last.read_cells) : 0, now.ms);
    last = now;
  }
  const double d = diameters / snapshots[0].spheres.size();
  std::printf("skin_diameters,steps_old,detections,held,mean_ms\n");
  for (double skin : {0.5, 0.75, 1.0})
    for (std::size_t old : {1, 10}) {
      int held = 0, n = 0;
      double ms = 0;
      for (std::size_t k = old; k < snapshots.size(); ++k, ++n) {
        bool from_skin = false;
        const auto start = std::chrono::steady_clock::now();
        membrane3d::detect_membrane_near(snapshots[k].spheres, platens, tolerance,
                                         found[k - old].seeds, skin * d, &from_skin);
        ms += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                  .count();
        held += from_skin;
      }
      std::printf("%.2f,%zu,%d,%d,%.1f\n", skin, old, n, held, ms / n);
    }
  // a run's first detection: no members yet, the skin of the outermost spheres
  const std::vector<int> seeds = membrane3d::outermost_spheres(snapshots[0].spheres, d, 0.5 * d);
  bool from_skin = false;
  const auto start = std::chrono::steady_clock::now();
  membrane3d::detect_membrane_near(snapshots[0].spheres, platens, tolerance, seeds, d, &from_skin);
  std::printf("first detection from the %zu outermost spheres: %s, %.1f ms\n", seeds.size(),
              from_skin ? "held" : "all spheres triangulated",
              std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                  .count());
  return 0;
}
