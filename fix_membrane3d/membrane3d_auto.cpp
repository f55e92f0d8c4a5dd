#include "membrane3d_auto.h"

#include <mpi.h>

#include <algorithm>

#include "atom.h"

#include "membrane3d_skin.h"

using namespace LAMMPS_NS;

namespace {

// The watch's budget as a fraction of the mean diameter: a certificate that no motion
// below it can flip is not evaluated again (flood_watch.h).
const double WATCH_BUDGET = 0.02;

// The dense schedule (dense_detections.h): at least 14 of 20 watched steps detecting,
// then 2 000 steps without the watch. A detection that builds the watch costs twice
// one from the skin (58 against 26 ms on the 7 699-sphere bench, whose membrane changes
// at every step): so the window probes briefly and rarely, adding about 1 % there.
const long long DENSE_WINDOW_3D = 20, DENSE_DETECTIONS_3D = 14, UNWATCHED_STEPS_3D = 2000;

void group_signature(const GatheredSpheres &g, double out[3])
{
  out[0] = static_cast<double>(g.tags.size());
  out[1] = 0.0;
  out[2] = 0.0;
  for (std::size_t k = 0; k < g.tags.size(); ++k) {
    out[1] += g.tags[k];
    out[2] = std::max(out[2], g.spheres[k].r);
  }
}

} // namespace

Membrane3dAuto::Membrane3dAuto()
{
  dense.window = DENSE_WINDOW_3D;
  dense.dense = DENSE_DETECTIONS_3D;
  dense.unwatched_steps = UNWATCHED_STEPS_3D;
}

membrane3d::MembraneTopology Membrane3dAuto::detect(const GatheredSpheres &all,
                                                    const std::vector<int> &member_tags,
                                                    const membrane3d::Platens &at, double tolerance,
                                                    long long step)
{
  platens = at;
  if (dense.unwatched(step)) { // no watch, and none to build again after a restart
    built = false;
    sample = GatheredSpheres();
    return detect_near_members(all, member_tags, platens, tolerance);
  }
  sample = all;
  return build(tolerance);
}

// The watch of the sample's detection, its budget from the sample in ID order: the
// same on every rank, and after a restart.
membrane3d::MembraneTopology Membrane3dAuto::build(double tolerance)
{
  const double budget = WATCH_BUDGET * mean_diameter(sample);
  group_signature(sample, signature);
  built = true;
  return membrane3d::detect_watched_membrane(sample.spheres, platens, tolerance, budget, watch);
}

void Membrane3dAuto::set_members(const std::vector<int> &members)
{
  watched_tags.clear();
  member_entry.clear();
  if (!built) return; // detected without a watch
  for (int k : watch.spheres) watched_tags.push_back(sample.tags[k]);
  member_entry.clear();
  for (int k : members)
    member_entry.push_back(static_cast<int>(
        std::lower_bound(watch.spheres.begin(), watch.spheres.end(), k) - watch.spheres.begin()));
}

bool Membrane3dAuto::can_have_changed(LAMMPS *lmp, int groupbit, const membrane3d::Platens &now,
                                      double tolerance, long long step,
                                      GatheredSpheres &members)
{
  if (dense.unwatched(step)) return true;
  if (!built) {
    if (sample.tags.empty()) return true;
    // after a restart: the watch of the detection it carries (the same membrane)
    std::vector<int> index;
    membrane3d::members_only(build(tolerance), index);
    set_members(index);
  }
  // the group as at the detection: the same atoms (count and sum of IDs), the
  // largest radius (the image band) unchanged
  Atom *atom = lmp->atom;
  double sums[2] = {0.0, 0.0}, largest = 0.0;
  for (int i = 0; i < atom->nlocal; i++)
    if (atom->mask[i] & groupbit) {
      sums[0] += 1.0;
      sums[1] += static_cast<double>(atom->tag[i]);
      largest = std::max(largest, atom->radius[i]);
    }
  MPI_Allreduce(MPI_IN_PLACE, sums, 2, MPI_DOUBLE, MPI_SUM, lmp->world);
  MPI_Allreduce(MPI_IN_PLACE, &largest, 1, MPI_DOUBLE, MPI_MAX, lmp->world);
  if (sums[0] != signature[0] || sums[1] != signature[1] || largest != signature[2]) return true;

  gather_tags(lmp, groupbit, watched_tags, watched);
  const bool changed = watched.tags.size() != watched_tags.size() ||
                       membrane3d::membrane_can_have_changed(watch, watched.spheres, now);
  dense.count_watched(step, changed);
  if (changed) return true;
  members.tags.clear();
  members.spheres.clear();
  members.types.clear();
  for (int e : member_entry) {
    members.tags.push_back(watched.tags[e]);
    members.spheres.push_back(watched.spheres[e]);
    members.types.push_back(watched.types[e]);
  }
  return false;
}

void Membrane3dAuto::save(membrane3d::Membrane3dState &state) const
{
  state.sample_tags = sample.tags;
  state.sample = sample.spheres;
  state.sample_platens = platens;
  state.window_steps = static_cast<double>(dense.window_steps);
  state.window_detections = static_cast<double>(dense.window_detections);
  state.unwatched_until = static_cast<double>(dense.unwatched_until);
}

void Membrane3dAuto::restore(const membrane3d::Membrane3dState &state)
{
  built = false;
  sample.tags = state.sample_tags;
  sample.spheres = state.sample;
  sample.types.assign(sample.tags.size(), 0);
  platens = state.sample_platens;
  dense.window_steps = static_cast<long long>(state.window_steps);
  dense.window_detections = static_cast<long long>(state.window_detections);
  dense.unwatched_until = static_cast<long long>(state.unwatched_until);
}

double Membrane3dAuto::memory_usage() const
{
  return static_cast<double>((sample.spheres.capacity() + watched.spheres.capacity()) *
                                 sizeof(membrane3d::Sphere) +
                             watch.flood.side.capacity() * (sizeof(std::array<int, 4>) + 5));
}
