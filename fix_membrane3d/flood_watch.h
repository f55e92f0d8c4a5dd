// What the flood of exterior_flood.h depends on, so that it is found again only when
// it can have changed (fix membrane3d, every auto). No LIGGGHTS here: unit-tested in
// tests/unit/membrane3d.
//
// The boundary is a function of the flooded cells. The flood reads the triangulation
// and the links only in the flooded cells and the dry cells next to them (the buffer):
// a change of the triangulation among dry cells alone (a flip of dry cells) leaves
// the flooded set as it is, for the flood enters a cell only through a facet of a
// flooded one. The triangulation holds in the buffer while every certificate of its
// cells holds: the orientation of each cell, the power test of each facet (the
// neighbour's far vertex outside the cell's power sphere) and the convexity of the
// hull between two infinite cells; the flood holds while the links on the facets of
// the flooded cells hold; a sphere that is no vertex stays so, in its cell, while its
// own power test and orientations hold. The certificates of a buffer cell are tests
// against its neighbours' far vertices; a flip just beyond the buffer would give it
// another neighbour, whose far vertex it is not tested against, so the ring of cells
// around the buffer is watched too (every facet of it). What is left unwatched is a
// chain of two flips beyond that ring followed by a point entering a buffer cell's
// power sphere: argued away by the power spheres' nesting (on the far side of a
// regular facet a cell's power sphere lies inside its neighbour's), not proven; the
// tests compare with fresh detections (tests/unit/membrane3d, tests/scripts,
// tests/examples).
//
// A certificate whose sign cannot change while no point moves by `budget` (bounded
// from its cofactors, with the remainder by Hadamard's inequality) is not evaluated
// again: the caller detects anew when a buffer point has moved that far. The others
// are evaluated every step as the triangulation decides them: CGAL's exact
// predicates and, where a test is zero, its symbolic perturbation (by the points'
// lexicographic order). Tests that are zero by the images' symmetry (a cell with a
// sphere and its image has its power sphere centred in the platen plane, so the image
// of any of its other vertices lies on it; a sphere's images stand on one vertical
// line with it) are known to be zero and not evaluated; any other zero (a lattice's
// cospherical spheres) is found by the exact predicate and decided by the same
// perturbation. A cell's orientation of zero, or a collinear hull facet (CGAL's
// power segment, not followed here), counts as changed.
#ifndef LIGGGHTS_MEMBRANE_FLOOD_WATCH_H
#define LIGGGHTS_MEMBRANE_FLOOD_WATCH_H

#include "exterior_flood.h"

#include <array>
#include <vector>

namespace membrane3d {

// The points of a flood that share x and y: a sphere and its images. `family` is the
// sphere, `plane` 0 for the sphere, -1 / +1 for its image in the lower / upper platen.
struct MirrorFamilies {
  std::vector<int> family, plane;
};

struct FloodWatch {
  bool always = true;     // the flood depends on more than is watched: find it every step
  std::vector<int> point; // the points (indices of the flood's spheres) it depends on, ascending
  MirrorFamilies mirrors; // per entry of `point`
  // the watched certificates over entries of `point`, and their values at the flood:
  // the side of a point towards a cell's power sphere (-1 in a vertex for the
  // infinite one; CGAL's side_of_power_sphere), the orientations of cells
  std::vector<std::array<int, 4>> side_cell;
  std::vector<int> side_point;
  std::vector<signed char> side;
  std::vector<std::array<int, 4>> orientation;
  std::vector<signed char> orientation_sign;
  std::vector<std::array<int, 2>> link;
  std::vector<double> link_threshold;
  std::vector<char> linked;
  long certificates = 0; // all of them, watched or not (bench)
};

// The watch of a flood of `spheres` (its cells from exterior_boundary): certificates
// safe for any motion of every point by less than `budget` are left out.
FloodWatch watch_flood(const FloodCells &cells, const std::vector<Sphere> &spheres,
                       const std::vector<bool> &sealed, const MirrorFamilies &mirrors,
                       double tolerance, double budget);

// Whether a watched certificate has changed, `now` holding the watch's points (in
// the order of watch.point) at their present positions.
bool watched_flood_changed(const FloodWatch &watch, const std::vector<Sphere> &now);

} // namespace membrane3d

#endif
