// The flood of exterior_flood.h over CGAL's regular triangulation of the spheres: the
// triangulation, which cells are flooded, and the boundary read from them. Internal
// to the core (exterior_flood.cpp, skin_flood.cpp); no LIGGGHTS here.
#ifndef LIGGGHTS_MEMBRANE_POWER_FLOOD_H
#define LIGGGHTS_MEMBRANE_POWER_FLOOD_H

#include "exterior_flood.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Regular_triangulation_3.h>
#include <CGAL/Regular_triangulation_cell_base_3.h>
#include <CGAL/Regular_triangulation_vertex_base_3.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <array>
#include <vector>

namespace membrane3d {

namespace power {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb =
    CGAL::Triangulation_vertex_base_with_info_3<int, K,
                                                CGAL::Regular_triangulation_vertex_base_3<K>>;
using Cb =
    CGAL::Triangulation_cell_base_with_info_3<int, K, CGAL::Regular_triangulation_cell_base_3<K>>;
using Tds = CGAL::Triangulation_data_structure_3<Vb, Cb>;
using Triangulation = CGAL::Regular_triangulation_3<K, Tds>;
using Cell = Triangulation::Cell_handle;
using Vertex = Triangulation::Vertex_handle;

inline K::Weighted_point_3 weighted_point(const Sphere &s)
{
  return K::Weighted_point_3(K::Point_3(s.x.x(), s.x.y(), s.x.z()), s.r * s.r);
}

} // namespace power

// Each sphere's radius positive and centre finite, else std::invalid_argument naming
// the sphere (the flood's and the skin's check).
void check_spheres(const std::vector<Sphere> &spheres);

// exterior_boundary's test of a flat sample: the eigenvalues (ascending) of the
// covariance of the spheres' centres (with their images) and the square of 0.1 mean
// radii; the centres lie within that RMS distance of one plane when the first is at
// most the limit, of one line when the second is.
struct FlatTest {
  Eigen::Vector3d eigenvalues;
  double limit;
};
FlatTest flat_test(const std::vector<Sphere> &spheres);

// exterior_boundary's checks of its arguments (std::invalid_argument).
void check_flood_input(const std::vector<Sphere> &spheres, const std::vector<bool> &sealed,
                       double tolerance);

// The spheres triangulated and flooded (the flood of exterior_flood.h). The spheres and
// sealed flags are held by reference: they must outlive it.
class PowerFlood {
 public:
  PowerFlood(const std::vector<Sphere> &spheres, const std::vector<bool> &sealed, double tolerance);

  // With `cells`, also the triangulation, its flood and the hidden spheres.
  Boundary boundary(FloodCells *cells) const;

  const power::Triangulation &triangulation() const { return triangulation_; }
  const std::vector<power::Cell> &cells() const { return cells_; } // by cell info
  bool flooded(power::Cell c) const { return flooded_[c->info()] != 0; }
  bool all_sealed(power::Cell c) const;
  long other_group() const { return other_group_; }

 private:
  const std::vector<Sphere> &spheres_;
  const std::vector<bool> &sealed_;
  double tolerance_;
  power::Triangulation triangulation_;
  std::vector<power::Cell> cells_; // by cell info
  std::vector<char> flooded_;      // by cell info
  long kept_group_ = 0, other_group_ = 0;

  bool finite(power::Vertex v) const { return !triangulation_.is_infinite(v); }
  bool wall(power::Cell c, int k) const;
  bool ignored_facet(power::Cell c, int k) const;
  void flood_from_outside();
  void keep_largest_dry_group();
  std::vector<Side> sides(FloodCells *cells) const;
  void export_cells(FloodCells &out) const;
};

} // namespace membrane3d

#endif
