#include "membrane3d_skin.h"

#include <algorithm>

#include "skin_flood.h"

namespace {

// The skin's thickness in mean diameters: on the triaxial sample of examples/triaxial
// (7 699 spheres) the gap of one diameter around the members keeps about half of the
// triangulation's points and shows the result (bench/membrane3d_cost.sh). Around
// members 1 or 10 steps old, 0.5 d never showed it (all spheres were triangulated),
// 0.75 d always did, 10 % faster than 1 d (bench/membrane3d_steps.sh): 1 d keeps a
// margin for a sheared, bulging membrane.
const double SKIN_THICKNESS = 1.0;
// The depth of the outermost spheres that seed a run's first detection, in mean
// diameters (skin_flood.h): the outer layer. One diameter takes the second layer of a
// block too, and the links among them close its core off as a dry group of its own: the
// skin is refused (tests/unit/membrane3d/test_skin_flood.cpp).
const double OUTERMOST_DEPTH = 0.5;

} // namespace

membrane3d::MembraneTopology detect_near_members(const GatheredSpheres &all,
                                                 const std::vector<int> &member_tags,
                                                 const membrane3d::Platens &platens,
                                                 double tolerance)
{
  std::vector<int> seeds;
  for (int tag : member_tags) {
    const auto at = std::lower_bound(all.tags.begin(), all.tags.end(), tag);
    if (at != all.tags.end() && *at == tag)
      seeds.push_back(static_cast<int>(at - all.tags.begin()));
  }
  const double d = mean_diameter(all);
  // a run's first detection: no members yet, the skin of the outermost spheres (a skin
  // from all spheres on every rank would hold about 1.4 kB per sphere on each)
  if (seeds.empty()) seeds = membrane3d::outermost_spheres(all.spheres, d, OUTERMOST_DEPTH * d);
  return membrane3d::detect_membrane_near(all.spheres, platens, tolerance, seeds,
                                          SKIN_THICKNESS * d);
}
