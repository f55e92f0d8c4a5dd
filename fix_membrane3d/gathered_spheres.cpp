#include "gathered_spheres.h"

#include <algorithm>

namespace membrane3d {

double mean_diameter(const GatheredSpheres &g)
{
  double diameter = 0.0;
  for (const auto &s : g.spheres) diameter += 2.0 * s.r;
  return g.spheres.empty() ? 0.0 : diameter / static_cast<double>(g.spheres.size());
}

int index_of(const GatheredSpheres &g, AtomId tag)
{
  const auto at = std::lower_bound(g.tags.begin(), g.tags.end(), tag);
  return at != g.tags.end() && *at == tag ? static_cast<int>(at - g.tags.begin()) : -1;
}

GatheredSpheres subset(const GatheredSpheres &g, const std::vector<int> &index)
{
  GatheredSpheres out;
  for (int k : index) {
    out.tags.push_back(g.tags[k]);
    out.spheres.push_back(g.spheres[k]);
    out.types.push_back(g.types[k]);
  }
  return out;
}

} // namespace membrane3d
