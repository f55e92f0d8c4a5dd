#include "membrane3d_distributed.h"

#include <mpi.h>

#include <algorithm>
#include <cmath>

#include "allgather.h"
#include "membrane3d_tuning.h"
#include "skin_flood.h"

namespace membrane3d {

namespace {

// This rank's atoms of the group.
struct Own {
  std::vector<int> index;
  std::vector<Sphere> spheres;
  std::vector<AtomId> tags;
};

// Seeds of a run's first detection: the outermost spheres (skin_flood.h), collectively.
void outermost(const Membrane3dGather &gather, const Membrane3dGather::Totals &totals,
               const Own &own, GatheredSpheres &seeds)
{
  MPI_Comm world = gather.lmp->world;
  const double d = totals.mean_diameter();
  const Eigen::Vector2d axis(totals.x_sum / totals.atoms, totals.y_sum / totals.atoms);
  double outer = 0;
  for (const Sphere &s : own.spheres) outer = std::max(outer, (s.x.head<2>() - axis).norm() + s.r);
  MPI_Allreduce(MPI_IN_PLACE, &outer, 1, MPI_DOUBLE, MPI_MAX, world);
  const OutermostBins bins(axis, totals.z_lo, totals.z_hi, outer, d);
  std::vector<double> farthest(bins.count(), -HUGE_VAL);
  std::vector<std::size_t> bin(own.spheres.size());
  for (std::size_t k = 0; k < own.spheres.size(); ++k) {
    bin[k] = bins.bin(own.spheres[k].x);
    farthest[bin[k]] = std::max(farthest[bin[k]], bins.reach(own.spheres[k]));
  }
  MPI_Allreduce(MPI_IN_PLACE, farthest.data(), static_cast<int>(farthest.size()), MPI_DOUBLE,
                MPI_MAX, world);
  std::vector<int> picked;
  for (std::size_t k = 0; k < own.spheres.size(); ++k)
    if (bins.reach(own.spheres[k]) >= farthest[bin[k]] - OUTERMOST_DEPTH * d)
      picked.push_back(own.index[k]);
  gather.some(picked, seeds);
}

// The IDs of every rank's `mine`, ascending, once each.
std::vector<AtomId> gather_ids(MPI_Comm world, const std::vector<AtomId> &mine, double *bytes)
{
  std::vector<double> send(mine.begin(), mine.end()), all;
  std::vector<int> counts, displs;
  const double received = allgather_doubles(world, send, all, counts, displs);
  if (bytes) *bytes += received;
  std::vector<AtomId> ids(all.begin(), all.end());
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  return ids;
}

bool holds(const std::vector<AtomId> &sorted, AtomId tag)
{
  return std::binary_search(sorted.begin(), sorted.end(), tag);
}

// a and b (each sorted by ID, no ID in both) in one, sorted by ID
void merge(const GatheredSpheres &a, const GatheredSpheres &b, GatheredSpheres &out)
{
  out = GatheredSpheres();
  std::size_t i = 0, j = 0;
  while (i < a.tags.size() || j < b.tags.size()) {
    const bool from_a = j == b.tags.size() || (i < a.tags.size() && a.tags[i] < b.tags[j]);
    const GatheredSpheres &g = from_a ? a : b;
    const std::size_t k = from_a ? i++ : j++;
    out.tags.push_back(g.tags[k]);
    out.spheres.push_back(g.spheres[k]);
    out.types.push_back(g.types[k]);
  }
}

} // namespace

MembraneTopology detect_distributed(const Membrane3dGather &gather,
                                    const std::vector<AtomId> &member_tags, double tolerance,
                                    const Membrane3dGather::Totals &totals, GatheredSpheres &skin,
                                    SkinCounters &counters)
{
  const double bytes_before = counters.bytes;
  Membrane3dGather counted = gather;
  counted.received = &counters.bytes; // the caller adds last_bytes to its own count
  MPI_Comm world = gather.lmp->world;
  const auto n_group = static_cast<std::size_t>(totals.atoms);
  const double d = totals.mean_diameter();
  const double band = image_band(totals.r_max, tolerance);
  Own own;
  gather.own(own.index, own.spheres, own.tags);

  GatheredSpheres seeds;
  counted.tags(member_tags, seeds);
  if (seeds.tags.empty()) outermost(counted, totals, own, seeds);

  double thickness = SKIN_THICKNESS * d;
  std::vector<AtomId> joined; // ascending
  counters.detections += 1;
  for (int round = 0; round < MOST_ROUNDS; ++round) {
    if (round > 0 && round % ROUNDS_PER_THICKNESS == 0) {
      thickness *= 2;
      counters.doublings += 1;
    }
    const std::vector<char> near = near_seeds(own.spheres, seeds.spheres, thickness);
    // the seeds are in the skin (each at a gap -2 r from itself): every rank has them
    std::vector<int> kept;
    std::vector<Sphere> left;
    std::vector<AtomId> left_tags;
    for (std::size_t k = 0; k < own.spheres.size(); ++k) {
      if (holds(seeds.tags, own.tags[k])) continue;
      if (near[k] || holds(joined, own.tags[k])) {
        kept.push_back(own.index[k]);
      } else {
        left.push_back(own.spheres[k]);
        left_tags.push_back(own.tags[k]);
      }
    }
    GatheredSpheres rest;
    counted.some(kept, rest);
    merge(seeds, rest, skin);
    counters.last_skin = static_cast<double>(skin.tags.size());
    const Mirrored m = mirror_in_band(skin.spheres, gather.platens, band);
    if (skin.tags.size() == n_group) { // nothing left out: the flood of all of them
      counters.last_bytes = counters.bytes - bytes_before;
      return skin_topology(exterior_boundary(m.spheres, m.sealed, tolerance), m, n_group,
                           n_group, tolerance);
    }
    const SkinShell shell(m.spheres, m.sealed, tolerance);
    if (!shell.usable()) break;
    const Mirrored l = mirror_in_band(left, gather.platens, band);
    std::vector<AtomId> failed;
    for (int k : shell.failing(l.spheres, l.sealed)) failed.push_back(left_tags[l.original[k]]);
    const std::vector<AtomId> all_failed = gather_ids(world, failed, &counters.bytes);
    if (all_failed.empty()) {
      counters.last_bytes = counters.bytes - bytes_before;
      return skin_topology(shell.boundary(), m, skin.tags.size(), n_group, tolerance);
    }
    counters.rounds += 1;
    counters.joined += static_cast<double>(all_failed.size());
    std::vector<AtomId> both;
    std::set_union(joined.begin(), joined.end(), all_failed.begin(), all_failed.end(),
                   std::back_inserter(both));
    joined.swap(both);
  }
  // the last resort: every sphere, as before the skin
  counters.last_resorts += 1;
  counted.group(skin);
  counters.last_skin = static_cast<double>(skin.tags.size());
  counters.last_bytes = counters.bytes - bytes_before;
  return detect_membrane(skin.spheres, gather.platens, tolerance);
}

} // namespace membrane3d
