// The outer boundary of a packing of spheres (fix membrane3d): which facets of the
// packing the membrane lies on, and which spheres are inside, on it or outside. No
// LIGGGHTS here: unit-tested in tests/unit/membrane3d.
//
// Construction. The spheres' centres are triangulated by the regular (power)
// triangulation with weights r^2, so that small spheres between large ones keep their
// own facets (CGAL's Regular_triangulation_3, exact predicates: the combinatorics is
// exact for the given doubles and does not depend on the input order). Two spheres are
// linked when their gap |x_i - x_j| - r_i - r_j is at most the tolerance T; a facet
// whose three edges are links is a wall. The exterior is flooded from the unbounded
// cells through every facet that is not a wall. The membrane is the walls between a
// flooded cell and one that is not, oriented towards the flood.
//
// Why this is robust: whatever the geometry, the boundary of a set of cells is a closed
// surface, so the membrane can leak (if T leaves a window of the skin open) but never
// be torn, pinched into nonsense or crash; a sphere is on the membrane exactly when its
// cells are both flooded and not, so no sphere whose cells are all unflooded (an
// interior sphere, or one in a closed internal void) ever gets pressure.
//
// Sealed spheres (the platen images of lateral_surface.h) are never a way in: a cell
// all of whose spheres are sealed is not flooded, so the flood reaches the packing only
// from the sides; an edge with a sealed sphere is a link up to a gap of 2 T, so that a
// sphere within T of a platen is linked to its image, as to the platen itself. Of the unflooded cells only the largest connected group (by cells with an
// unsealed sphere) is the sample: the spheres of any other group (a linked cluster that
// has left the sample) are outside.
#ifndef LIGGGHTS_MEMBRANE_EXTERIOR_FLOOD_H
#define LIGGGHTS_MEMBRANE_EXTERIOR_FLOOD_H

#include <Eigen/Core>

#include <array>
#include <stdexcept>
#include <vector>

namespace membrane3d {

struct Sphere {
  Eigen::Vector3d x;
  double r;
};

enum class Side : char { inside, surface, outside };

struct Boundary {
  std::vector<std::array<int, 3>> facets;  // sphere indices, counter-clockwise from outside
  std::vector<Side> side;                  // per sphere
};

// The flooded triangulation itself, for what the boundary depends on (flood_watch.h):
// cells by index, vertex -1 the infinite one, neighbour k opposite vertex k.
struct FloodCells {
  std::vector<std::array<int, 4>> vertex;
  std::vector<std::array<int, 4>> neighbour;
  std::vector<char> flooded;
  std::vector<int> hidden, hidden_cell; // spheres that are no vertex, and the cell holding each
  long kept_group = 0, other_group = 0; // cells (with an unsealed sphere) of the sample's dry
                                        // group and of the largest other one
};

// The spheres and their platen images span no volume: their centres lie in one plane
// or on one line, or within 0.1 mean radii (RMS) of one (a one-sphere-thick wall, a
// single column, one layer), so no closed surface encloses them (or only slivers).
struct FlatSample : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

// Throws FlatSample for spheres that span no volume, std::invalid_argument for fewer
// than four spheres, a radius that is not
// positive or a tolerance that is negative or not finite, naming the value. The
// facets come in a canonical order (each starting at its lowest sphere, sorted), so
// that the same boundary is the same list whatever the triangulation's history.
// With `cells`, also the triangulation and its flood.
Boundary exterior_boundary(const std::vector<Sphere> &spheres, const std::vector<bool> &sealed,
                           double tolerance, FloodCells *cells = nullptr);

} // namespace membrane3d

#endif
