#include "membrane_vtk.h"

#include <array>
#include <cstdio>
#include <cstdlib>

namespace membrane {

namespace {

// One DataArray; `value(k)` gives the components of point k (the first `ncomp`).
template <class Value>
void data_array(std::string &out, const char *type, const char *name, int ncomp, std::size_t n,
                Value value)
{
  out += "        <DataArray type=\"" + std::string(type) + "\" Name=\"" + name +
         "\" NumberOfComponents=\"" + std::to_string(ncomp) + "\" format=\"ascii\">\n         ";
  char buf[32];
  for (std::size_t k = 0; k < n; k++) {
    const std::array<double, 3> v = value(k);
    for (int c = 0; c < ncomp; c++) {
      std::snprintf(buf, sizeof(buf), " %.17g", v[c]); // every digit: ParaView gets the run's values
      out += buf;
    }
  }
  out += "\n        </DataArray>\n";
}

} // namespace

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
  std::string out = "<?xml version=\"1.0\"?>\n"
                    "<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
                    "  <PolyData>\n"
                    "    <Piece NumberOfPoints=\"" +
                    std::to_string(n) + "\" NumberOfVerts=\"" + std::to_string(verts.size()) +
                    "\" NumberOfLines=\"" + std::to_string(lines.size()) +
                    "\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n"
                    "      <PointData>\n";
  data_array(out, "Int32", "side", 1, n, [&](std::size_t k) {
    return std::array<double, 3>{static_cast<double>(points[k].side)};
  });
  data_array(out, "Float64", "tag", 1, n,
             [&](std::size_t k) { return std::array<double, 3>{points[k].tag}; });
  data_array(out, "Float64", "radius", 1, n,
             [&](std::size_t k) { return std::array<double, 3>{points[k].r}; });
  data_array(out, "Float64", "force", 3, n,
             [&](std::size_t k) { return std::array<double, 3>{points[k].fx, points[k].fy, 0.0}; });
  out += "      </PointData>\n      <Points>\n";
  data_array(out, "Float64", "Points", 3, n,
             [&](std::size_t k) { return std::array<double, 3>{points[k].x, points[k].y, 0.0}; });
  out += "      </Points>\n";
  // a cell block: connectivity (point indices) and offsets (end of each cell)
  auto cells = [&](const char *block, const std::vector<std::pair<std::size_t, std::size_t>> &c) {
    out += "      <" + std::string(block) +
           ">\n        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n         ";
    for (const auto &cell : c)
      for (std::size_t k = 0; k < cell.second; k++) out += " " + std::to_string(cell.first + k);
    out += "\n        </DataArray>\n        <DataArray type=\"Int64\" Name=\"offsets\" "
           "format=\"ascii\">\n         ";
    std::size_t end = 0;
    for (const auto &cell : c) out += " " + std::to_string(end += cell.second);
    out += "\n        </DataArray>\n      </" + std::string(block) + ">\n";
  };
  std::vector<std::pair<std::size_t, std::size_t>> vert_cells;
  for (std::size_t v : verts) vert_cells.push_back({v, 1});
  cells("Verts", vert_cells);
  cells("Lines", lines);
  out += "    </Piece>\n  </PolyData>\n</VTKFile>\n";
  return out;
}

std::string pvd_collection(const std::vector<std::pair<long long, std::string>> &frames)
{
  std::string out = "<?xml version=\"1.0\"?>\n"
                    "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
                    "  <Collection>\n";
  for (const auto &f : frames)
    out += "    <DataSet timestep=\"" + std::to_string(f.first) + "\" part=\"0\" file=\"" +
           f.second + "\"/>\n";
  out += "  </Collection>\n</VTKFile>\n";
  return out;
}

std::vector<std::pair<long long, std::string>> pvd_frames(const std::string &pvd)
{
  std::vector<std::pair<long long, std::string>> frames;
  const std::string step_key = "timestep=\"", file_key = "file=\"";
  for (std::size_t at = pvd.find("<DataSet "); at != std::string::npos;
       at = pvd.find("<DataSet ", at + 1)) {
    const std::size_t s = pvd.find(step_key, at), f = pvd.find(file_key, at);
    if (s == std::string::npos || f == std::string::npos) break;
    const std::size_t f_end = pvd.find('"', f + file_key.size());
    if (f_end == std::string::npos) break;
    frames.push_back({std::atoll(pvd.c_str() + s + step_key.size()),
                      pvd.substr(f + file_key.size(), f_end - f - file_key.size())});
  }
  return frames;
}

} // namespace membrane
