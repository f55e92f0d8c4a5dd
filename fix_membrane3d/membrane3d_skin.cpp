#include "membrane3d_skin.h"

#include "membrane3d_tuning.h"
#include "skin_flood.h"

namespace membrane3d {

MembraneTopology detect_near_members(const GatheredSpheres &all,
                                     const std::vector<AtomId> &member_tags, const Platens &platens,
                                     double tolerance)
{
  std::vector<int> seeds;
  for (AtomId tag : member_tags) {
    const int k = index_of(all, tag);
    if (k >= 0) seeds.push_back(k);
  }
  const double d = mean_diameter(all);
  // a run's first detection: no members yet, the skin of the outermost spheres (a skin
  // from all spheres on every rank would hold about 1.4 kB per sphere on each)
  if (seeds.empty()) seeds = outermost_spheres(all.spheres, d, OUTERMOST_DEPTH * d);
  return detect_membrane_near(all.spheres, platens, tolerance, seeds, SKIN_THICKNESS * d);
}

} // namespace membrane3d
