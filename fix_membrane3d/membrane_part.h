// The membrane placed by parts (fix membrane3d on several ranks): each rank places the
// facets on the members it owns, from the present positions of the members within two
// rings of them (membrane/member_halo_plan.h), and gets the loads of its own members and
// its share of the global sums; the sums of all parts are the whole membrane's. No
// LIGGGHTS here: unit-tested in tests/unit/membrane3d.
//
// Exact: a member's load is the sum over the clipped corners on it (created in facet
// order) of its weight times the sum of the consistent loads of the clipped facets on
// that corner (in facet order). Every facet on a corner on member i is a facet on i, so
// the part holding every facet on i, in the topology's order, sums the same terms in the
// same order as place_membrane and membrane_loads: the same bits. The corners of those
// facets lie on members one ring away, whose outer-face offsets are sums over the facets
// on them (in order): hence every facet on a member within one ring, and positions within
// two. A facet's own measures (clipped area, volume, centroid) are those of its clip
// alone; each facet is counted by the part that owns its first vertex's sphere, so the
// parts' sums add up to the whole's (in another order: round-off).
#ifndef LIGGGHTS_MEMBRANE_MEMBRANE_PART_H
#define LIGGGHTS_MEMBRANE_MEMBRANE_PART_H

#include <array>
#include <vector>

#include "lateral_surface.h"
#include "member_halo_plan.h"

namespace membrane3d {

// A part's share of the global sums (added over the parts, then used as the whole's).
enum PartSum {
  ON_SURFACE,  // own members carrying a load
  ESCAPED,     // own members outside
  CLIPPED,     // clipped facets of own facets
  NET_X,       // the membrane loads of own members (no escape push)
  NET_Y,
  NET_Z,
  MAGNITUDE,   // sum of their norms
  VOLUME_SUM,  // lateral_volume's sum (twice the volume) over own clipped facets
  AXIS_X,      // membrane_axis' sums: area times centroid, area
  AXIS_Y,
  AREA,
  REACHES_LO,  // clipped corners of own facets in a platen's plane
  REACHES_HI,
  PART_SUMS
};

// The facets on member m of `cells` are the topology's (cells = its facets' spheres).
membrane::MemberCells facet_cells(const MembraneTopology &topology);

struct MembranePart {
  std::vector<Eigen::Vector3d> load; // per owned member: the membrane's
  std::vector<Side> side;            // per owned member
  std::array<double, PART_SUMS> sums{};
};

// What a part places, over the positions of `needed` (slots): made once per topology
// and owners, used every step.
struct PartLayout {
  MembraneTopology near;       // the facets on owned members, in order
  MembraneTopology around;     // the facets on the members one ring away, in order
  std::vector<int> ring_slots; // those members (whose outer-face offsets are exact)
  std::vector<int> owned_slots;
  std::vector<char> counted;   // per facet of near: its first vertex's sphere owned
  bool outer_faces = true;     // around and ring_slots made (else centres only)
};

// The layout of the members `owned` (ascending) with the spheres of the members `needed`
// (ascending; a superset of those within two rings of owned, one ring with
// for a layout of Vertices::centres only). Throws std::invalid_argument for a facet on
// an owned member whose sphere is not in `needed`.
PartLayout part_layout(const MembraneTopology &topology, const membrane::MemberCells &cells,
                       const std::vector<int> &owned, const std::vector<int> &needed,
                       Vertices vertices = Vertices::outer_faces);

// The part placed on the spheres `at` of the layout's needed members (outer faces: a
// layout of outer faces, else std::invalid_argument).
MembranePart place_part(const PartLayout &layout, const std::vector<Sphere> &at,
                        const Platens &platens, double p, Vertices vertices);

// part_layout and place_part at once.
MembranePart place_part(const MembraneTopology &topology, const membrane::MemberCells &cells,
                        const std::vector<int> &owned, const std::vector<int> &needed,
                        const std::vector<Sphere> &at, const Platens &platens, double p,
                        Vertices vertices);

// The escape pushes of the part's escaped members towards the axis of the whole (from the
// summed AXIS_X, AXIS_Y, AREA), added to part.load.
void add_part_escapes(MembranePart &part, const PartLayout &layout, const std::vector<Sphere> &at,
                      const std::array<double, PART_SUMS> &whole, double p);

} // namespace membrane3d

#endif
