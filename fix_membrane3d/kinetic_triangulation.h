// The kept regular triangulation of the kinetic flood (kinetic_flood.h): CGAL's
// Regular_triangulation_3 of the spheres (weights r^2), its cells carrying the state of
// their certificates, kept regular from step to step. Internal to kinetic_flood.cpp.
#ifndef LIGGGHTS_MEMBRANE_KINETIC_TRIANGULATION_H
#define LIGGGHTS_MEMBRANE_KINETIC_TRIANGULATION_H

#include "flood_watch.h"
#include "kinetic_flood.h"
#include "power_flood.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Regular_triangulation_3.h>
#include <CGAL/Regular_triangulation_cell_base_3.h>
#include <CGAL/Regular_triangulation_vertex_base_3.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <array>
#include <utility>
#include <vector>

namespace membrane3d {

namespace kinetic {

// Per cell: its index (for the flood), a serial number (0: new), the serial numbers of
// its neighbours when its certificates were last decided, which of them have no margin
// (bits 0-3: the facets it owns, bit 4: its orientation), which facets have theirs by
// the images' symmetry, and the step they were last evaluated at.
struct CellState {
  int index = -1;
  unsigned id = 0;   // given when the cell is first met (by itself or a neighbour)
  bool seen = false; // its certificates decided once
  std::array<unsigned, 4> neighbour_id{};
  unsigned char tight = 0, mirror = 0;
  bool listed = false; // in the certifier's list of cells to evaluate each step
  int anchor = -1;     // its entry of the certifier's anchors, or -1
  // the flood (kinetic_exterior.h): reached from outside (-1: made since the last
  // flood), flooded, its dry group
  signed char wet = -1;
  bool flooded = false;
  int group = -1;
  // the flood's own (kinetic_reflood.cpp): a serial number (0: made since), the facet
  // through which it was reached (4: from outside), the re-flood's fragment and its step
  unsigned serial = 0;
  signed char parent = -1;
  int fragment = -1;
  long stamp = -1;
  long evaluated = -1;
};

// the kernel, vertices (info: the sphere's index) and weights of power_flood.h
using power::K;
using power::Vb;
using power::weighted_point;
using Rcb = CGAL::Regular_triangulation_cell_base_3<K, CGAL::Triangulation_cell_base_3<K>,
                                                    CGAL::Discard_hidden_points>;
using Cb = CGAL::Triangulation_cell_base_with_info_3<CellState, K, Rcb>;
using Tds = CGAL::Triangulation_data_structure_3<Vb, Cb>;
using Triangulation = CGAL::Regular_triangulation_3<K, Tds>;
using Cell = Triangulation::Cell_handle;
using Vertex = Triangulation::Vertex_handle;

// The certificates of a triangulation whose points have moved (kinetic_flood.h):
// evaluated at the points the triangulation holds, margins from the references.
class Certifier {
 public:
  Certifier(Triangulation &t, const std::vector<Sphere> &reference, const std::vector<Sphere> &now,
            double budget, KineticStats &stats)
    : t_(t), reference_(reference), now_(now), budget_(budget), stats_(stats)
  {
  }

  // The certificates of a cell at `step`: all of a new cell's, a changed facet's, those
  // with a point in `moved` (marked with `step`) and those without a margin (once a
  // step). The spheres of failed certificates go to `failed`, five entries each (-1:
  // none); false when one is
  // undecided (triangulate anew). A cell with a certificate without a margin is listed.
  bool visit(Cell c, long step, const std::vector<long> &moved, std::vector<int> &failed);
  // every cell (a new triangulation)
  bool pass(long step, const std::vector<long> &moved, std::vector<int> &failed);
  // the listed cells
  bool visit_tight(long step, const std::vector<long> &moved, std::vector<int> &failed);
  // the cells around the vertices and their neighbours (all the cells made by an
  // insertion or removal are around the vertices of its hole; the cells whose
  // neighbour changed are their neighbours; a moved point's certificates are there)
  bool visit_around(const std::vector<Vertex> &vertices, long step, const std::vector<long> &moved,
                    std::vector<int> &failed);
  // the list without the cells gone or with margins again
  void compact();

  long tight() const { return tight_; }

  // The points' families (flood_watch.h: a sphere and its images), and whether the
  // images are at present exact mirrors of their spheres (x, y, r the same, one platen
  // height for each side): then the tests zero by the symmetry stay zero.
  void set_mirrors(const MirrorFamilies *mirrors) { mirrors_ = mirrors; }
  void set_symmetric(bool symmetric) { symmetric_ = symmetric; }

 private:
  // A listed cell's points when its certificates without a margin were last evaluated
  // (its vertices, then its neighbours' far vertices; -1: none), and the motion from
  // there within which they keep their signs.
  struct Anchor {
    std::array<int, 8> point{};
    std::array<Eigen::Vector3d, 8> x;
    double reach = 0;
  };

  Triangulation &t_;
  const std::vector<Sphere> &reference_, &now_;
  std::vector<Anchor> anchors_;
  double budget_;
  KineticStats &stats_;
  unsigned next_id_ = 0;
  long tight_ = 0;
  const MirrorFamilies *mirrors_ = nullptr;
  bool symmetric_ = false;
  std::vector<std::pair<Cell, unsigned>> listed_; // (cell, its id)

  // 1: holds, 0: fails, -1: undecided; *margin: whether it holds with a margin,
  // *by_mirror: whether that margin needs the symmetry
  int orientation(Cell c, bool *margin);
  int facet(Cell c, int k, bool *margin, bool *by_mirror);
  bool mirror_zero(const std::array<int, 4> &cell, int p) const;
  bool margin_of(Cell c, int k, const std::vector<Sphere> &at, double delta, bool *by_mirror) const;
  double reach_of(Cell c, int k, double most) const;
  double reach(Cell c) const;
  void anchor(Cell c);
  bool within_reach(Cell c) const;
  static void add_points(Cell c, int far, std::vector<int> &failed);
};

} // namespace kinetic

} // namespace membrane3d

#endif
