#include "surface_closure.h"

#include <cmath>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>

namespace membrane3d {

std::vector<std::vector<int>> boundary_loops(const Surface &surface) {
  check_facets(surface);
  std::set<std::pair<int, int>> edges;
  for (const auto &f : surface.facets)
    for (int k = 0; k < 3; ++k) edges.insert({f[k], f[(k + 1) % 3]});
  // a rim edge has no facet on its other side, i.e. no reversed twin
  std::map<int, int> next;
  for (const auto &[a, b] : edges)
    if (!edges.count({b, a}) && !next.emplace(a, b).second)
      throw std::invalid_argument("vertex " + std::to_string(a) + " starts two rim edges");
  std::vector<std::vector<int>> loops;
  while (!next.empty()) {
    std::vector<int> loop{next.begin()->first};
    for (int v = next.begin()->second; v != loop.front();) {
      loop.push_back(v);
      const auto it = next.find(v);
      if (it == next.end())  // cannot happen: every rim vertex ends one rim edge and starts one
        throw std::logic_error("rim through vertex " + std::to_string(v) + " does not close");
      v = it->second;
    }
    for (int v : loop) next.erase(v);
    loops.push_back(std::move(loop));
  }
  return loops;
}

Surface close_with_caps(const Surface &surface) {
  Surface closed = surface;
  for (const auto &loop : boundary_loops(surface)) {
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (int v : loop) centroid += surface.points[v];
    const int c = static_cast<int>(closed.points.size());
    closed.points.push_back(centroid / static_cast<double>(loop.size()));
    for (std::size_t k = 0; k < loop.size(); ++k)
      closed.facets.push_back({loop[(k + 1) % loop.size()], loop[k], c});
  }
  return closed;
}

double winding_number(const Surface &closed, const Eigen::Vector3d &x) {
  check_facets(closed);
  double omega = 0.0;
  for (const auto &f : closed.facets) {
    const Eigen::Vector3d a = closed.points[f[0]] - x, b = closed.points[f[1]] - x,
                          c = closed.points[f[2]] - x;
    const double la = a.norm(), lb = b.norm(), lc = c.norm();
    const double numerator = a.dot(b.cross(c));
    const double denominator = la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la;
    omega += 2.0 * std::atan2(numerator, denominator);
  }
  return omega / (4.0 * M_PI);
}

} // namespace membrane3d
