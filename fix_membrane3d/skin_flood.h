// The flood of exterior_flood.h found from a skin of the spheres: the same boundary and
// sides as from all of them, at the cost of the skin (fix membrane3d detects from the
// spheres near its last membrane). No LIGGGHTS here: unit-tested in tests/unit/membrane3d.
//
// Why the result is the same. The flood reads the triangulation only in the flooded
// cells and the dry cells next to them. Triangulate the kept spheres only: inserting a
// left-out sphere then replaces exactly the cells in conflict with it (whose power
// sphere it enters), and whether a cell is in conflict with a sphere depends on the two
// alone. So when no left-out sphere is in conflict with a flooded cell or a dry cell next
// to one, the triangulation of all spheres has those cells too, with the same walls, and
// floods the same cells: the same boundary, oriented by the same dry cells. Besides:
// - every left-out sphere lies strictly inside a dry cell (so the hull is the same, and
//   none is hidden in a flooded cell: each left-out sphere is inside);
// - the sample's dry group keeps its place as the largest: its cells next to the flood
//   (which stay) outnumber the cells of any other group (a flooded pocket, which stays).
// The conflict and location tests are CGAL's exact predicates (a tie counts as a
// conflict); the left-out spheres a cell is tested against are those within its power
// sphere computed in doubles, widened by a margin far above its round-off, or all of
// them for a cell too flat for that bound. Any failed test: false, and the caller floods
// all the spheres.
#ifndef LIGGGHTS_MEMBRANE_SKIN_FLOOD_H
#define LIGGGHTS_MEMBRANE_SKIN_FLOOD_H

#include "exterior_flood.h"

#include <vector>

namespace membrane3d {

// The spheres with a gap of at most `thickness` to one of the `seeds` (indices), the seeds
// among them. Throws std::invalid_argument for a radius not positive, a centre or the
// thickness not finite, std::out_of_range for a seed not a sphere's index.
std::vector<char> spheres_near(const std::vector<Sphere> &spheres, const std::vector<int> &seeds,
                               double thickness);

// Seeds for a detection with no last membrane to start from (a run's first): the
// outermost spheres around the sample's axis (through the centroid of the centres, along
// z). Around the axis the sample is cut into sectors about `diameter` wide at its
// outer radius and slabs `diameter` high; in each, the spheres whose outer face is
// within `depth` of the outermost's. Any seeds are safe (skin_boundary shows the result
// or all spheres are triangulated); these find a sample that is not hollow.
std::vector<int> outermost_spheres(const std::vector<Sphere> &spheres, double diameter,
                                   double depth);

// exterior_boundary(spheres, sealed, tolerance) from the spheres with `keep` set, into
// `out`, when that is shown to be the same (above); false, with `out` untouched, when
// not. Throws what exterior_boundary throws, and std::invalid_argument for `keep` not
// one flag per sphere.
bool skin_boundary(const std::vector<Sphere> &spheres, const std::vector<bool> &sealed,
                   double tolerance, const std::vector<char> &keep, Boundary &out);

} // namespace membrane3d

#endif
