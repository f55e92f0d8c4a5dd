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

PartLayout part_layout(const MembraneTopology &topology, const membrane::MemberCells &cells,
                       const std::vector<int> &owned, const std::vector<int> &needed,
                       Vertices vertices)
{
  PartLayout layout;
  layout.outer_faces = vertices == Vertices::outer_faces;
  const std::vector<int> near_facets = cells.cells_on(owned); // the facets on owned members
  layout.near = renumbered(topology, near_facets, needed);
  // the members one ring away: the offsets of their facets' corners need every facet on
  // them
  std::vector<int> ring(owned);
  for (int f : near_facets)
    for (const MembraneVertex &v : topology.facets[f]) ring.push_back(v.sphere);
  std::sort(ring.begin(), ring.end());
  ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
  for (int m : owned) layout.owned_slots.push_back(slot_of(needed, m));
  for (int f : near_facets)
    layout.counted.push_back(
        std::binary_search(owned.begin(), owned.end(), topology.facets[f][0].sphere));
  if (!layout.outer_faces) return layout;
  for (int m : ring) layout.ring_slots.push_back(slot_of(needed, m));
  layout.around = renumbered(topology, cells.cells_on(ring), needed);
  return layout;
}

MembranePart place_part(const PartLayout &layout, const std::vector<Sphere> &at,
                        const Platens &platens, double p, Vertices vertices)
{
  if (at.size() != layout.near.side.size())
    throw std::invalid_argument("a part of " + std::to_string(layout.near.side.size()) +
                                " members with " + std::to_string(at.size()) + " spheres");
  MembranePart part;
  std::vector<Eigen::Vector3d> vertex(at.size());
  for (std::size_t k = 0; k < at.size(); ++k) vertex[k] = at[k].x;
  if (vertices == Vertices::outer_faces) {
    if (!layout.outer_faces)
      throw std::invalid_argument("a part laid out for the centres placed on the outer faces");
    const std::vector<Eigen::Vector3d> o = outer_face_offsets_unchecked(layout.around, at, platens);
    for (int k : layout.ring_slots) vertex[k] += o[k];
  }
  std::vector<int> origin;
  const LateralSurface placed = clip_membrane(layout.near, vertex, platens, &origin);
  const std::vector<Eigen::Vector3d> load = membrane_loads(placed, at.size(), p);

  std::array<double, PART_SUMS> &sum = part.sums;
  part.load.reserve(layout.owned_slots.size());
  part.side.reserve(layout.owned_slots.size());
  for (int k : layout.owned_slots) {
    part.load.push_back(load[k]);
    part.side.push_back(placed.side[k]);
    sum[ON_SURFACE] += placed.side[k] == Side::surface;
    sum[ESCAPED] += placed.side[k] == Side::outside;
    sum[NET_X] += load[k].x();
    sum[NET_Y] += load[k].y();
    sum[NET_Z] += load[k].z();
    sum[MAGNITUDE] += load[k].norm();
  }
  // the facets counted here (lateral_volume, membrane_axis)
  const Surface &s = placed.surface;
  for (std::size_t t = 0; t < s.facets.size(); ++t) {
    if (!layout.counted[origin[t]]) continue;
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

MembranePart place_part(const MembraneTopology &topology, const membrane::MemberCells &cells,
                        const std::vector<int> &owned, const std::vector<int> &needed,
                        const std::vector<Sphere> &at, const Platens &platens, double p,
                        Vertices vertices)
{
  return place_part(part_layout(topology, cells, owned, needed, vertices), at, platens, p,
                    vertices);
}

void add_part_escapes(MembranePart &part, const PartLayout &layout, const std::vector<Sphere> &at,
                      const std::array<double, PART_SUMS> &whole, double p)
{
  if (!(whole[ESCAPED] > 0)) return;
  const Eigen::Vector2d axis = whole[AREA] > 0
                                   ? Eigen::Vector2d(Eigen::Vector2d(whole[AXIS_X], whole[AXIS_Y]) /
                                                     whole[AREA])
                                   : Eigen::Vector2d::Zero();
  for (std::size_t k = 0; k < layout.owned_slots.size(); ++k)
    if (part.side[k] == Side::outside)
      part.load[k] += escape_push(at[layout.owned_slots[k]], axis, p);
}

} // namespace membrane3d
