// The kinetic flood (fix_membrane3d/kinetic_flood.h) on a real moving sample: for
// consecutive snapshots of a dump "id radius x y z" (sorted by id, the same atoms in
// each), the spheres with their platen images (the images of the first snapshot's
// imaged spheres, on the height grid, kept for all: a fixed set of points), advanced
// step by step against exterior_boundary from scratch on the same points: the time of
// each, whether they are identical (facets and sides, to the last bit), and per step
// the certificates evaluated, failed and the spheres moved by the repair. Times are
// CPU times of this process (the split between triangulation and flood: wall time).
//   membrane3d_kinetic DUMP ZLO ZHI TOLERANCE_IN_MEAN_DIAMETERS [BUDGET_IN_MEAN_DIAMETERS...]
// (several budgets: one run each)
#include "dump_snapshots.h"
#include "kinetic_flood.h"
#include "platen_images.h"

#include <algorithm>
#include <ctime>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

namespace {

using membrane3d::Sphere;

using bench::Snapshot;

// The points of the flood: the spheres now and the images of `mirrored`'s entries.
std::vector<Sphere> points(const membrane3d::Mirrored &mirrored, const std::vector<Sphere> &now,
                           const membrane3d::Platens &platens)
{
  std::vector<Sphere> p(mirrored.original.size());
  for (std::size_t k = 0; k < p.size(); ++k) {
    const Sphere &s = now[mirrored.original[k]];
    p[k] = {membrane3d::mirrored_position(s.x, mirrored.image[k], platens, mirrored.grid), s.r};
  }
  return p;
}

double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

// CPU time of this process (the machine is shared: wall time is not the work's)
double cpu_seconds()
{
  return static_cast<double>(std::clock()) / CLOCKS_PER_SEC;
}

} // namespace

int main(int argc, char **argv)
{
  if (argc < 5) {
    std::cerr << "usage: membrane3d_kinetic DUMP ZLO ZHI TOLERANCE_IN_MEAN_DIAMETERS "
                 "[BUDGET_IN_MEAN_DIAMETERS...]\n";
    return 2;
  }
  const membrane3d::Platens platens{std::atof(argv[2]), std::atof(argv[3])};
  std::vector<Snapshot> snapshots;
  if (!bench::read_snapshots(argv[1], snapshots)) return 1;
  double diameters = 0;
  for (const Sphere &s : snapshots[0].spheres) diameters += 2 * s.r;
  const double d = diameters / static_cast<double>(snapshots[0].spheres.size());
  const double tolerance = std::atof(argv[4]) * d;
  const membrane3d::Mirrored mirrored =
      membrane3d::mirror_in_platens(snapshots[0].spheres, platens, tolerance);
  std::vector<std::vector<Sphere>> frames;
  for (const Snapshot &s : snapshots) frames.push_back(points(mirrored, s.spheres, platens));
  std::printf("%zu snapshots of %zu spheres and %zu images, tolerance %.4g m\n", snapshots.size(),
              snapshots[0].spheres.size(), mirrored.original.size() - snapshots[0].spheres.size(),
              tolerance);

  // exterior_boundary from scratch: the reference and its time
  std::vector<membrane3d::Boundary> fresh;
  std::vector<double> fresh_ms;
  for (const auto &f : frames) {
    const double start = cpu_seconds();
    fresh.push_back(membrane3d::exterior_boundary(f, mirrored.sealed, tolerance));
    fresh_ms.push_back(1e3 * (cpu_seconds() - start));
  }
  int changed = 0;
  for (std::size_t k = 1; k < fresh.size(); ++k)
    changed += fresh[k].facets != fresh[k - 1].facets || fresh[k].side != fresh[k - 1].side;
  std::printf("fresh exterior_boundary: median %.3f ms; the boundary changed on %d of %zu steps\n",
              median(fresh_ms), changed, frames.size() - 1);

  std::vector<double> budgets;
  for (int a = 5; a < argc; ++a) budgets.push_back(std::atof(argv[a]));
  if (budgets.empty()) budgets = {0.01, 0.03, 0.1};
  std::printf(
      "mirrors,budget_d,steps,identical,advance_ms_median,advance_ms_mean,triangulation_ms_mean,"
      "repair_ms_mean,flood_ms_mean,ratio_to_fresh,evaluated_per_step,failed_per_step,removed_per_"
      "step,"
      "max_removed,rereferenced_per_step,tight,hidden,rebuilds,floods_kept\n");
  for (const bool with_mirrors : {false, true})
    for (double b : budgets) {
      const membrane3d::MirrorFamilies families{mirrored.original, mirrored.image};
      membrane3d::KineticFlood flood(frames[0], mirrored.sealed, tolerance, b * d,
                                     with_mirrors ? &families : nullptr);
      const membrane3d::KineticStats first = flood.stats();
      std::vector<double> ms;
      int identical = 0;
      long max_removed = 0;
      for (std::size_t k = 1; k < frames.size(); ++k) {
        const long removed = flood.stats().removed;
        const double start = cpu_seconds();
        flood.advance(frames[k]);
        ms.push_back(1e3 * (cpu_seconds() - start));
        max_removed = std::max(max_removed, flood.stats().removed - removed);
        identical +=
            flood.boundary().facets == fresh[k].facets && flood.boundary().side == fresh[k].side;
      }
      const membrane3d::KineticStats &s = flood.stats();
      const double steps = static_cast<double>(frames.size() - 1);
      double mean = 0;
      for (double m : ms) mean += m / steps;
      std::printf(
          "%d,%g,%zu,%d,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,%.0f,%.1f,%.1f,%ld,%.1f,%ld,%ld,%ld,%ld\n",
          with_mirrors, b, frames.size() - 1, identical, median(ms), mean,
          1e3 * (s.triangulation_seconds - first.triangulation_seconds) / steps,
          1e3 * (s.repair_seconds - first.repair_seconds) / steps,
          1e3 * (s.flood_seconds - first.flood_seconds) / steps, median(ms) / median(fresh_ms),
          static_cast<double>(s.evaluated - first.evaluated) / steps,
          static_cast<double>(s.failed - first.failed) / steps,
          static_cast<double>(s.removed - first.removed) / steps, max_removed,
          static_cast<double>(s.rereferenced - first.rereferenced) / steps, s.tight, s.hidden,
          s.rebuilds - first.rebuilds, s.floods_kept - first.floods_kept);
    }
  return 0;
}
