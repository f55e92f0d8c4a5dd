#include "surface_loads.h"
#include "math_constants.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace membrane3d {

void check_facets(const Surface &surface) {
  const long n = static_cast<long>(surface.points.size());
  for (std::size_t f = 0; f < surface.facets.size(); ++f)
    for (int v : surface.facets[f])
      if (v < 0 || v >= n)
        throw std::out_of_range("facet " + std::to_string(f) + " has vertex " + std::to_string(v) +
                                " of " + std::to_string(n) + " points");
}

namespace {

// N_f and the three corners of facet f.
struct FacetGeometry {
  const Eigen::Vector3d &a, &b, &c;
  Eigen::Vector3d area;
};

FacetGeometry facet(const Surface &s, const std::array<int, 3> &f) {
  const Eigen::Vector3d &a = s.points[f[0]], &b = s.points[f[1]], &c = s.points[f[2]];
  return {a, b, c, facet_vector_area(a, b, c)};
}

} // namespace

Eigen::Vector3d vector_area(const Surface &surface) {
  check_facets(surface);
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const auto &f : surface.facets) sum += facet(surface, f).area;
  return sum;
}

std::vector<Eigen::Vector3d> pressure_forces(const Surface &surface, double p) {
  check_facets(surface);
  std::vector<Eigen::Vector3d> force(surface.points.size(), Eigen::Vector3d::Zero());
  for (const auto &f : surface.facets) {
    const Eigen::Vector3d share = -p / 3.0 * facet(surface, f).area;
    for (int v : f) force[v] += share;
  }
  return force;
}

double enclosed_volume(const Surface &surface) {
  check_facets(surface);
  double sum = 0.0;
  for (const auto &f : surface.facets) {
    const FacetGeometry g = facet(surface, f);
    sum += g.a.dot(g.b.cross(g.c));
  }
  return sum / 6.0;
}

double lateral_volume(const Surface &surface) {
  check_facets(surface);
  double sum = 0.0;
  for (const auto &f : surface.facets) {
    const FacetGeometry g = facet(surface, f);
    const Eigen::Vector3d centroid = (g.a + g.b + g.c) / 3.0;
    sum += centroid.x() * g.area.x() + centroid.y() * g.area.y();
  }
  return sum / 2.0;
}

double equivalent_radius(double volume, double height) {
  return std::sqrt(volume / (math_constants::PI * height));
}

} // namespace membrane3d
