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

#include <memory>
#include <vector>

namespace membrane3d {

// The spheres with a gap of at most `thickness` to one of the `seeds` (indices), the seeds
// among them. Throws std::invalid_argument for a radius not positive, a centre or the
// thickness not finite, std::out_of_range for a seed not a sphere's index.
std::vector<char> spheres_near(const std::vector<Sphere> &spheres, const std::vector<int> &seeds,
                               double thickness);

// Which of `mine` have a gap of at most `thickness` to one of the `seeds` (the test of
// spheres_near, for spheres and seeds given apart: a rank's own spheres, the seeds
// gathered from all). Throws std::invalid_argument for a thickness not finite.
std::vector<char> near_seeds(const std::vector<Sphere> &mine, const std::vector<Sphere> &seeds,
                             double thickness);

// Seeds for a detection with no last membrane to start from (a run's first): the
// outermost spheres around the sample's axis (through the centroid of the centres, along
// z). Around the axis the sample is cut into sectors about `diameter` wide at its
// outer radius and slabs `diameter` high; in each, the spheres whose outer face is
// within `depth` of the outermost's. Any seeds are safe (skin_boundary shows the result
// or all spheres are triangulated); these find a sample that is not hollow.
std::vector<int> outermost_spheres(const std::vector<Sphere> &spheres, double diameter,
                                   double depth);

// The certificate in two parts, so that the left-out spheres can be tested where they
// are (fix membrane3d: each rank its own, membrane3d_distributed.h). (a) SkinShell: the
// skin's flood and its shell (the dry cells next to flooded ones), built alike wherever
// the same skin is given. (b) failing(): which of a set of left-out spheres the skin
// does not show hidden. Each sphere's tests read the skin alone (its location; its
// conflicts with the shell cells, their candidates found from the set's own largest
// radius), so the spheres failing in a set are those failing in its parts together,
// and the skin holds for the whole exactly when no part has one failing.
class SkinShell {
 public:
  // The skin (copied; images sealed). Not usable (nothing shown) for fewer than four
  // spheres, a flat skin, a shell no larger than another dry group (the sample's group
  // might not stay the largest), or more than a bound of flat shell cells.
  SkinShell(std::vector<Sphere> skin, std::vector<bool> sealed, double tolerance);
  ~SkinShell();
  SkinShell(const SkinShell &) = delete;
  SkinShell &operator=(const SkinShell &) = delete;

  bool usable() const;
  // The entries of `left` (left-out spheres, their images sealed) that could change the
  // flood: located in a flooded cell, on a face, edge or vertex, beyond the hull where
  // they would change it, or in conflict with a shell cell. Ascending; with
  // `first_only`, at most one (the verdict only). All of them when not usable. Throws
  // std::invalid_argument for a radius not positive, a centre not finite or `sealed`
  // not one flag per sphere.
  std::vector<int> failing(const std::vector<Sphere> &left, const std::vector<bool> &sealed,
                           bool first_only = false) const;
  // The skin's boundary, in its numbering (usable only).
  Boundary boundary() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// exterior_boundary(spheres, sealed, tolerance) from the spheres with `keep` set, into
// `out`, when that is shown to be the same (above); false, with `out` untouched, when
// not. Throws what exterior_boundary throws, and std::invalid_argument for `keep` not
// one flag per sphere.
bool skin_boundary(const std::vector<Sphere> &spheres, const std::vector<bool> &sealed,
                   double tolerance, const std::vector<char> &keep, Boundary &out);

} // namespace membrane3d

#endif
