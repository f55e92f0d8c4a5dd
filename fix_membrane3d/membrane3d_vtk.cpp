#include "membrane3d_vtk.h"

#include "vtk_series.h"

#include <array>

namespace membrane3d {

std::string vtk_frame(const LateralSurface &membrane, const std::vector<Sphere> &spheres,
                      double p) {
  struct Point {
    Eigen::Vector3d x, load;
    double escaped, r;
  };
  std::vector<Point> points;
  const std::vector<Eigen::Vector3d> at_corner = pressure_forces(membrane.surface, p);
  for (std::size_t k = 0; k < membrane.surface.points.size(); ++k)
    points.push_back({membrane.surface.points[k], at_corner[k], 0.0, 0.0});
  std::vector<Eigen::Vector3d> push(spheres.size(), Eigen::Vector3d::Zero());
  add_escape_loads(membrane, spheres, p, push);
  std::vector<std::vector<long long>> verts, polys;
  for (std::size_t i = 0; i < spheres.size(); ++i)
    if (membrane.side.at(i) == Side::outside) {
      verts.push_back({static_cast<long long>(points.size())});
      points.push_back({spheres[i].x, push[i], 1.0, spheres[i].r});
    }
  for (const auto &f : membrane.surface.facets) polys.push_back({f[0], f[1], f[2]});

  const std::size_t n = points.size();
  std::string out = vtk_series::polydata_start(n, verts.size(), 0, polys.size());
  using vtk_series::data_array;
  auto vec = [](const Eigen::Vector3d &v) { return std::array<double, 3>{v.x(), v.y(), v.z()}; };
  data_array(out, "Int32", "escaped", 1, n,
             [&](std::size_t k) { return std::array<double, 3>{points[k].escaped}; });
  data_array(out, "Float64", "radius", 1, n,
             [&](std::size_t k) { return std::array<double, 3>{points[k].r}; });
  data_array(out, "Float64", "load", 3, n, [&](std::size_t k) { return vec(points[k].load); });
  vtk_series::points_block(out, n, [&](std::size_t k) { return vec(points[k].x); });
  vtk_series::cell_block(out, "Verts", verts);
  vtk_series::cell_block(out, "Polys", polys);
  vtk_series::polydata_end(out);
  return out;
}

} // namespace membrane3d
