#include "membrane_part.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace membrane3d {

membrane::MemberCells facet_cells(const MembraneTopology &topology)
{
  std::vector<int> cells;
  cells.reserve(3 * topology.facets.size());
  for (const auto &f : topology.facets)
    for (const MembraneVertex &v : f) cells.push_back(v.sphere);
  return {topology.side.size(), cells, 3};
}

namespace {

int slot_of(const std::vector<int> &needed, int m)
{
  const auto at = std::lower_bound(needed.begin(), needed.end(), m);
  if (at == needed.end() || *at != m)
    throw std::invalid_argument("member " + std::to_string(m) +
                                " of a part's facet is not among its spheres");
  return static_cast<int>(at - needed.begin());
}

// the facets `which` of the topology over the positions in needed (monotone: the
// edge cuts compare the same order)
MembraneTopology renumbered(const MembraneTopology &topology, const std::vector<int> &which,
                            const std::vector<int> &needed)
{
  MembraneTopology out;
  out.facets.reserve(which.size());
  for (int f : which) {
    auto facet = topology.facets[f];
    for (MembraneVertex &v : facet) v.sphere = slot_of(needed, v.sphere);
    out.facets.push_back(facet);
  }
  out.side.assign(needed.size(), Side::inside);
  for (std::size_t k = 0; k < needed.size(); ++k) out.side[k] = topology.side[needed[k]];
  return out;
}

} // namespace

MembranePart place_part(const MembraneTopology &topology, const membrane::MemberCells &cells,
                        const std::vector<int> &owned, const std::vector<int> &needed,
                        const std::vector<Sphere> &at, const Platens &platens, double p,
                        Vertices vertices)
{
  if (at.size() != needed.size())
    throw std::invalid_argument("a part of " + std::to_string(needed.size()) + " members with " +
                                std::to_string(at.size()) + " spheres");
  MembranePart part;
  std::vector<Eigen::Vector3d> vertex(at.size());
  for (std::size_t k = 0; k < at.size(); ++k) vertex[k] = at[k].x;
  const std::vector<int> near_facets = cells.cells_on(owned); // the facets on owned members
  const MembraneTopology near = renumbered(topology, near_facets, needed);
  if (vertices == Vertices::outer_faces) {
    // the offsets of the members one ring away: every facet on them
    std::vector<int> ring(owned);
    for (int f : near_facets)
      for (const MembraneVertex &v : topology.facets[f]) ring.push_back(v.sphere);
    std::sort(ring.begin(), ring.end());
    ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
    const std::vector<Eigen::Vector3d> o = outer_face_offsets_unchecked(
        renumbered(topology, cells.cells_on(ring), needed), at, platens);
    for (int m : ring) {
      const int k = slot_of(needed, m);
      vertex[k] += o[k];
    }
  }
  std::vector<int> origin;
  const LateralSurface placed = clip_membrane(near, vertex, platens, &origin);
  const std::vector<Eigen::Vector3d> load = membrane_loads(placed, needed.size(), p);

  std::array<double, PART_SUMS> &sum = part.sums;
  for (int m : owned) {
    const int k = slot_of(needed, m);
    part.load.push_back(load[k]);
    part.side.push_back(placed.side[k]);
    sum[ON_SURFACE] += placed.side[k] == Side::surface;
    sum[ESCAPED] += placed.side[k] == Side::outside;
    sum[NET_X] += load[k].x();
    sum[NET_Y] += load[k].y();
    sum[NET_Z] += load[k].z();
    sum[MAGNITUDE] += load[k].norm();
  }
  // own facets: the first vertex's sphere owned (lateral_volume, membrane_axis)
  const Surface &s = placed.surface;
  for (std::size_t t = 0; t < s.facets.size(); ++t) {
    const int first = topology.facets[near_facets[origin[t]]][0].sphere;
    if (!std::binary_search(owned.begin(), owned.end(), first)) continue;
    const auto &f = s.facets[t];
    const Eigen::Vector3d &a = s.points[f[0]], &b = s.points[f[1]], &c = s.points[f[2]];
    const Eigen::Vector3d area = facet_vector_area(a, b, c);
    const Eigen::Vector3d centroid = (a + b + c) / 3.0;
    sum[CLIPPED] += 1;
    sum[VOLUME_SUM] += centroid.x() * area.x() + centroid.y() * area.y();
    const double norm = area.norm();
    const Eigen::Vector2d weighted = norm * (a + b + c).head<2>() / 3;
    sum[AXIS_X] += weighted.x();
    sum[AXIS_Y] += weighted.y();
    sum[AREA] += norm;
    for (int j = 0; j < 3; ++j) {
      sum[REACHES_LO] += s.points[f[j]].z() == platens.lo;
      sum[REACHES_HI] += s.points[f[j]].z() == platens.hi;
    }
  }
  return part;
}

void add_part_escapes(MembranePart &part, const std::vector<int> &owned,
                      const std::vector<int> &needed, const std::vector<Sphere> &at,
                      const std::array<double, PART_SUMS> &whole, double p)
{
  if (!(whole[ESCAPED] > 0)) return;
  const Eigen::Vector2d axis = whole[AREA] > 0
                                   ? Eigen::Vector2d(Eigen::Vector2d(whole[AXIS_X], whole[AXIS_Y]) /
                                                     whole[AREA])
                                   : Eigen::Vector2d::Zero();
  for (std::size_t k = 0; k < owned.size(); ++k)
    if (part.side[k] == Side::outside)
      part.load[k] += escape_push(at[slot_of(needed, owned[k])], axis, p);
}

} // namespace membrane3d
