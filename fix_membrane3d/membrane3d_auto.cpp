#include "membrane3d_auto.h"

#include <algorithm>

#include "membrane3d_skin.h"
#include "membrane3d_tuning.h"

namespace membrane3d {

void GroupSignature::add(AtomId tag, double r)
{
  atoms += 1.0;
  id_sum += static_cast<double>(tag);
  largest = std::max(largest, r);
}

Membrane3dAuto::Membrane3dAuto()
{
  dense.window = DENSE_WINDOW_3D;
  dense.dense = DENSE_DETECTIONS_3D;
  dense.unwatched_steps = UNWATCHED_STEPS_3D;
}

MembraneTopology Membrane3dAuto::detect(const GatheredSpheres &all,
                                        const std::vector<AtomId> &member_tags, const Platens &at,
                                        double tolerance, double d50, long long step)
{
  if (dense.unwatched(step)) {
    unwatched(at);
    return detect_near_members(all, member_tags, platens, tolerance);
  }
  platens = at;
  sample = all;
  return build(tolerance, d50);
}

// no watch, and none to build again after a restart
void Membrane3dAuto::unwatched(const Platens &at)
{
  platens = at;
  built = false;
  sample = GatheredSpheres();
}

// The watch of the sample's detection, its budget from the group's D50 (the same on
// every rank).
MembraneTopology Membrane3dAuto::build(double tolerance, double d50)
{
  signature = GroupSignature();
  for (std::size_t k = 0; k < sample.tags.size(); ++k)
    signature.add(sample.tags[k], sample.spheres[k].r);
  built = true;
  return detect_watched_membrane(sample.spheres, platens, tolerance, WATCH_BUDGET * d50, watch);
}

void Membrane3dAuto::set_members(const std::vector<int> &members)
{
  watched_tags.clear();
  member_entry.clear();
  if (!built) return; // detected without a watch
  for (int k : watch.spheres) watched_tags.push_back(sample.tags[k]);
  for (int k : members)
    member_entry.push_back(static_cast<int>(
        std::lower_bound(watch.spheres.begin(), watch.spheres.end(), k) - watch.spheres.begin()));
}

bool Membrane3dAuto::can_have_changed(const Group &group, const Platens &now, double tolerance,
                                      double d50, long long step, GatheredSpheres &members)
{
  if (dense.unwatched(step)) return true;
  if (!built) {
    if (sample.tags.empty()) return true;
    // after a restart: the watch of the detection it carries (the same membrane)
    std::vector<int> index;
    members_only(build(tolerance, d50), index);
    set_members(index);
  }
  if (!(group.signature() == signature)) return true;

  group.gather(watched_tags, watched);
  const bool changed = watched.tags.size() != watched_tags.size() ||
                       membrane_can_have_changed(watch, watched.spheres, now);
  dense.count_watched(step, changed);
  if (changed) return true;
  members = subset(watched, member_entry);
  return false;
}

void Membrane3dAuto::save(Membrane3dState &state) const
{
  state.sample_tags = sample.tags;
  state.sample = sample.spheres;
  state.sample_platens = platens;
  state.window_steps = static_cast<double>(dense.window_steps);
  state.window_detections = static_cast<double>(dense.window_detections);
  state.unwatched_until = static_cast<double>(dense.unwatched_until);
}

void Membrane3dAuto::restore(const Membrane3dState &state)
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
                                 sizeof(Sphere) +
                             watch.flood.side.capacity() * (sizeof(std::array<int, 4>) + 5));
}

} // namespace membrane3d
