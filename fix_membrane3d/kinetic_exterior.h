// The flood of the kinetic flood (kinetic_flood.h) over its kept triangulation: that of
// exterior_flood.cpp line for line (flood()), and between two whole floods updated
// locally (update(), kinetic_reflood.cpp) around the cells the step's repair destroyed
// and made and the facets whose walls changed, to the same result. Internal to
// kinetic_flood.cpp.
//
// Why the local update is exact. exterior_flood's flood is two functions of the
// triangulation and the spheres: R, the cells connected to a cell at infinity (not all
// sealed) through facets that are not walls (no all-sealed cell), and among the other
// cells (dry) the groups connected through any facet, of which the largest (counted by
// cells with an unsealed sphere) is kept; the membrane and the sides follow from which
// cells are flooded. Kept between steps: for each reached cell the facet it was
// reached through (a tree rooted at infinity), for each dry cell its group, each
// group's count, the membrane's facets, and the links (the edges of the reached cells'
// facets) with their distance from the threshold.
// (1) Reached. A reached cell whose way to the root keeps all its cells and its facets
// still no walls is still reached. Its way is broken only under a destroyed cell or a
// facet that became a wall (found from the changed links: a link's status cannot change
// while its spheres' motions since it was read sum to less than its distance from the
// threshold); the cells below (the orphans: a walk down the tree) and the made cells
// are flooded again from the cells still reached (a breadth-first flood through facets
// that are not walls, evaluated at the present positions as the flood does), seeded by
// each of them next to a still reached cell through a facet that is not a wall, or at
// infinity, and by each dry cell across a facet that ceased to be a wall from a reached
// cell. A cell joined to the reached ones through a facet that is not a wall is so
// through a facet that is new (a made cell: seeded), or of an orphan (seeded), or that
// ceased to be a wall (seeded), or it would have been reached before: so the reached
// cells are R.
// (2) Dry groups. The dry cells removed (destroyed, or reached now) are joined with
// their dry neighbours into classes (union-find over the cells' serial numbers); the
// surviving dry neighbours of each class and the new dry cells (made, or orphans not
// reached) are seeds of breadth-first fragments, run in turns and merged where they
// meet, until no class has more than one fragment still growing and every growing
// fragment holds an old dry cell. A fragment that stopped growing is a whole group,
// counted. Any two surviving cells of an old group not in such a one are joined (their
// old way, its removed stretches replaced by the way around them between their class's
// seeds, all in the one growing fragment), so a growing fragment's group is the union
// of the old groups it touched (their counts less the cells removed and the cells in
// finished fragments) and its new cells; untouched groups keep their counts. The sample
// is the largest group: when it is not the continuation of the last one, or ties with
// another, the whole flood is run (counted). Cells that change groups are relabelled
// by walks over the groups that are not the sample (smaller than it).
// (3) The membrane (a set of facets) loses the facets of destroyed cells and of cells
// whose flooding changed, and gains those of the made and changed cells; the sides of
// the spheres of these cells, the touched and the hidden spheres are found again.
// Everything else is as the whole flood left it, so the result is exterior_flood's.
#ifndef LIGGGHTS_MEMBRANE_KINETIC_EXTERIOR_H
#define LIGGGHTS_MEMBRANE_KINETIC_EXTERIOR_H

#include "kinetic_triangulation.h"

#include <set>
#include <unordered_map>
#include <utility>
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
  void begin_step();
  // Before a cell of the triangulation is destroyed.
  void destroying(Cell c);
  // The flood cannot be kept this step (a new triangulation, a radius changed).
  void invalidate() { local_ = false; }
  bool local() const { return local_; }
  // After the step's changes, `touched` holding the spheres around which cells were
  // made (the holes' spheres, those inserted): the flood updated locally into `out`
  // (above), or false (then flood()).
  bool update(const std::vector<int> &touched, Boundary &out);

  // cells the local updates visited (re-flooded, grown, relabelled), summed
  long visited() const { return visited_; }

 private:
  struct Link {
    int a, b;
    double slack; // its status holds while its spheres' motions from anchor_ sum below
    bool linked;
  };
  using Tracked = std::pair<Cell, unsigned>; // a cell and its serial when met
  struct Fragment {
    std::vector<Cell> queue, cells;
    std::size_t head = 0;
    int parent, klass;
    bool old = false; // holds an old dry cell
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
  std::vector<long> size_;              // per group: cells with an unsealed sphere
  std::set<std::array<int, 3>> facets_; // the membrane, each from its lowest sphere
  std::vector<Link> links_;             // (an edge may come more than once)
  std::size_t links_recorded_ = 0;
  std::vector<Eigen::Vector3d> anchor_; // the spheres' centres at the last whole flood
  unsigned serial_ = 0;
  long step_ = 0, visited_ = 0;
  // this step's changes
  std::vector<Tracked> orphan_roots_, dry_next_;
  std::unordered_map<int, long> removed_; // per group: unsealed cells removed
  std::unordered_map<unsigned, unsigned> klass_;
  std::vector<Fragment> fragments_;

  bool finite(Vertex v) const { return !t_.is_infinite(v); }
  double threshold(int a, int b) const;
  bool wall(Cell c, int k) const;
  bool all_sealed(Cell c) const;
  bool ignored_facet(Cell c, int k) const;
  void flood_from_outside();
  void keep_largest_dry_group();
  std::array<int, 3> outward_facet(Cell c, int k) const;
  void erase_facet(Cell c, int k);
  std::vector<Side> sides() const;
  Side side_of(int sphere) const;
  void record_links();
  void add_links(Cell c);
  // kinetic_reflood.cpp
  bool alive(const Tracked &x) const;
  unsigned find(unsigned serial);
  void unite(unsigned a, unsigned b);
  std::vector<std::pair<int, int>> changed_links();
  void changed_facets(const std::vector<std::pair<int, int>> &edges, std::vector<Cell> &orphan,
                      std::vector<Cell> &recheck);
  void reach(Cell c, int through, std::vector<Cell> &front, std::vector<Cell> &reached);
  int fragment_root(int f);
  bool race_done();
  void relabel(const std::vector<Cell> &from, int label, std::vector<Cell> &changed);
};

} // namespace kinetic

} // namespace membrane3d

#endif
