// The flood of the kinetic flood (kinetic_flood.h) over its kept triangulation: that of
// exterior_flood.cpp line for line, and kept from step to step where it is shown the
// same. Internal to kinetic_flood.cpp.
//
// When the flood is kept (a). Let the step's changes of the triangulation destroy only cells
// that were dry (not reached from outside) and in the sample's dry group, and make cells
// none of which is at infinity (unless all sealed) or next to a reached cell across a
// facet that is not a wall (unless all sealed); and let no link read by the flood (the
// edges of the facets of reached cells) have changed. Then the reached cells are the
// same: they all remain, with the same facets and walls between them, and no new cell
// is reached. The dry cells cover the same space (the triangulation covers the hull),
// so their groups are the same regions: the new cells lie in the sample's, whose count
// changes by the new cells less the destroyed ones (it must stay above any other
// group's, else the flood is run again). The membrane's facets (between a flooded and a
// dry cell: facets of flooded cells, kept) and the sides of the spheres that remain
// vertices are the same; those of the spheres inserted, removed or hidden are found
// again. (b) Let them destroy only cells reached from outside, and make cells none of
// which is all sealed, with no wall between two of them, each reached (from a reached
// cell across a facet that is not a wall, or at infinity) and none letting the flood
// into a dry cell. Then a way of the flood through the destroyed cells goes through
// the made ones, which fill the same space: the reached cells are those kept and those
// made, the dry cells the same, and so the groups, the membrane's facets and the sides
// of the spheres that remain vertices with a cell reached before and after.
// A link's status is known unchanged while the motions of its two spheres since
// the last whole flood sum to less than its gap's distance from the threshold
// (beyond a round-off allowance), else its test is evaluated again, exactly as the
// flood evaluates it.
#ifndef LIGGGHTS_MEMBRANE_KINETIC_EXTERIOR_H
#define LIGGGHTS_MEMBRANE_KINETIC_EXTERIOR_H

#include "kinetic_triangulation.h"

#include <vector>

namespace membrane3d {

namespace kinetic {

class Exterior {
 public:
  Exterior(const Triangulation &t, const std::vector<Sphere> &now, const std::vector<bool> &sealed,
           double tolerance, const std::vector<Vertex> &vertex)
    : t_(t), now_(now), sealed_(sealed), tolerance_(tolerance), vertex_(vertex)
  {
  }

  // The whole flood (exterior_flood.cpp's) into `out`.
  void flood(Boundary &out);

  // A step begins: its changes are followed from here.
  void begin_step()
  {
    local_ = valid_;
    kept_delta_ = 0;
    mode_ = 0;
  }
  // Before a cell of the triangulation is destroyed.
  void destroying(Cell c);
  // The flood cannot be kept this step (a new triangulation, a radius changed).
  void invalidate() { local_ = false; }
  bool local() const { return local_; }
  // After the step's changes, `touched` holding the spheres around which cells were
  // made (the holes' spheres, those inserted): the flood kept and `out` updated when
  // that is shown the same (above), else false (then flood()).
  bool update(const std::vector<int> &touched, Boundary &out);

 private:
  struct Link {
    int a, b;
    double slack; // |gap - threshold| at the last whole flood
    bool linked;
  };

  const Triangulation &t_;
  const std::vector<Sphere> &now_;
  const std::vector<bool> &sealed_;
  double tolerance_;
  const std::vector<Vertex> &vertex_;
  std::vector<Cell> cells_; // by index, at the last whole flood
  std::vector<char> flooded_;
  bool valid_ = false, local_ = false;
  int kept_group_ = -1;
  long kept_size_ = 0, other_size_ = 0, kept_delta_ = 0;
  int mode_ = 0; // what the step destroyed: 1 reached cells, 2 dry cells of the sample
  int misses_ = 0, retry_ = 0;          // steps since the flood was last kept; floods since
  std::vector<Link> links_;             // (an edge may come more than once)
  std::vector<Eigen::Vector3d> anchor_; // the spheres' centres at the last whole flood

  bool finite(Vertex v) const { return !t_.is_infinite(v); }
  double gap(int a, int b) const;
  double threshold(int a, int b) const;
  bool linked(Vertex a, Vertex b) const;
  bool wall(Cell c, int k) const;
  bool all_sealed(Cell c) const;
  bool ignored_facet(Cell c, int k) const;
  void flood_from_outside();
  void keep_largest_dry_group();
  std::array<int, 3> outward_facet(Cell c, int k) const;
  std::vector<Side> sides() const;
  Side side_of(int sphere) const;
  void record_links();
  void add_links(Cell c);
  std::vector<Cell> made(const std::vector<int> &touched) const;
  bool made_dry(const std::vector<Cell> &made);
  bool made_reached(const std::vector<Cell> &made);
  bool links_hold() const;
};

} // namespace kinetic

} // namespace membrane3d

#endif
