#include "membrane_vtk.h"

#include "vtk_series.h"

#include <array>
#include <cstdio>
#include <cstdlib>

namespace membrane {

using vtk_series::data_array;

std::string vtk_frame(const std::vector<VtkSide> &sides)
{
  // per point: x, y, side, tag, radius, fx, fy
  struct Point {
    double x, y;
    int side;
    double tag, r, fx, fy;
  };
  std::vector<Point> points;
  std::vector<std::pair<std::size_t, std::size_t>> lines; // first point, count
  std::vector<std::size_t> verts;
  for (const VtkSide &s : sides) {
    lines.push_back({points.size(), s.polyline->size()});
    for (const Eigen::Vector2d &p : *s.polyline)
      points.push_back({p.x(), p.y(), s.side, -1.0, 0.0, 0.0, 0.0});
    for (std::size_t c = 0; c < s.chain->size(); c++) {
      const Disk &d = (*s.chain)[c];
      verts.push_back(points.size());
      points.push_back({d.x, d.y, s.side, static_cast<double>(d.tag), d.r, (*s.forces)[c].x(),
                        (*s.forces)[c].y()});
    }
  }
  const std::size_t n = points.size();
  std::string out = vtk_series::polydata_start(n, verts.size(), lines.size(), 0);
  data_array(out, "Int32", "side", 1, n, [&](std::size_t k) {
    return std::array<double, 3>{static_cast<double>(points[k].side)};
  });
  data_array(out, "Float64", "tag", 1, n,
             [&](std::size_t k) { return std::array<double, 3>{points[k].tag}; });
  data_array(out, "Float64", "radius", 1, n,
             [&](std::size_t k) { return std::array<double, 3>{points[k].r}; });
  data_array(out, "Float64", "force", 3, n,
             [&](std::size_t k) { return std::array<double, 3>{points[k].fx, points[k].fy, 0.0}; });
  vtk_series::points_block(out, n, [&](std::size_t k) {
    return std::array<double, 3>{points[k].x, points[k].y, 0.0};
  });
  std::vector<std::vector<long long>> vert_cells, line_cells;
  for (std::size_t v : verts) vert_cells.push_back({static_cast<long long>(v)});
  for (const auto &line : lines) {
    line_cells.emplace_back();
    for (std::size_t k = 0; k < line.second; k++)
      line_cells.back().push_back(static_cast<long long>(line.first + k));
  }
  vtk_series::cell_block(out, "Verts", vert_cells);
  vtk_series::cell_block(out, "Lines", line_cells);
  vtk_series::polydata_end(out);
  return out;
}

std::string chains_vtk_frame(const SideChain (&chains)[2], const SideData (&sides)[2],
                             const SideLoad (&loads)[2])
{
  std::vector<VtkSide> shown;
  for (int k = LEFT; k <= RIGHT; k++)
    if (chains[k].active)
      shown.push_back({k == LEFT ? 1 : 2, &loads[k].polyline, &sides[k].chain_disks,
                       &loads[k].forces});
  return vtk_frame(shown);
}

} // namespace membrane
