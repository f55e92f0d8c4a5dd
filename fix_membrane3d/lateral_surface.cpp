#include "lateral_surface.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <unordered_map>

namespace membrane3d {

namespace {

// The spheres and their images in the platens; image k stands for sphere original[k].
struct Mirrored {
  std::vector<Sphere> spheres;
  std::vector<bool> image;
  std::vector<int> original;
};

Mirrored mirror_in_platens(const std::vector<Sphere> &spheres, const Platens &platens,
                           double tolerance) {
  double r_max = 0;
  for (const Sphere &s : spheres) r_max = std::max(r_max, s.r);
  const double band = 3 * (2 * r_max + tolerance);
  Mirrored m{spheres, std::vector<bool>(spheres.size(), false), {}};
  for (std::size_t i = 0; i < spheres.size(); ++i) m.original.push_back(static_cast<int>(i));
  auto add_image = [&m](const Sphere &s, int i, double plane) {
    Sphere image = s;
    image.x.z() = 2 * plane - s.x.z();
    m.spheres.push_back(image);
    m.image.push_back(true);
    m.original.push_back(i);
  };
  for (std::size_t i = 0; i < spheres.size(); ++i) {
    const Sphere &s = spheres[i];
    if (s.x.z() - platens.lo < band) add_image(s, static_cast<int>(i), platens.lo);
    if (platens.hi - s.x.z() < band) add_image(s, static_cast<int>(i), platens.hi);
  }
  return m;
}

// A corner of a clipped facet: its position, its weights over the facet's three
// vertices, and a key shared by every facet that has the same corner (-1: none).
struct ClipPoint {
  Eigen::Vector3d x;
  std::array<double, 3> w;
  std::int64_t key;
  int vertex;  // the facet vertex it is, -1 for a cut point
};

class PlatenClip {
public:
  PlatenClip(const Mirrored &m, const Platens &p) : m_(m), platens_(p) {}

  void add_facet(const std::array<int, 3> &f) {
    std::vector<ClipPoint> poly;
    for (int j = 0; j < 3; ++j) {
      std::array<double, 3> w{0, 0, 0};
      w[j] = 1;
      poly.push_back({m_.spheres[f[j]].x, w, f[j], j});
    }
    poly = clip(poly, f, platens_.lo, +1, 1);
    poly = clip(poly, f, platens_.hi, -1, 2);
    if (poly.size() < 3) return;
    std::vector<int> corner;
    for (const ClipPoint &q : poly) corner.push_back(corner_index(q, f));
    for (std::size_t k = 1; k + 1 < corner.size(); ++k)
      out_.surface.facets.push_back({corner[0], corner[k], corner[k + 1]});
  }

  LateralSurface result() && { return std::move(out_); }

private:
  const Mirrored &m_;
  Platens platens_;
  LateralSurface out_;
  std::unordered_map<std::int64_t, int> by_key_;

  std::int64_t edge_key(int u, int v, int plane) const {
    const std::int64_t n = static_cast<std::int64_t>(m_.spheres.size());
    return (static_cast<std::int64_t>(std::min(u, v)) * n + std::max(u, v)) * 3 + plane;
  }

  // Sutherland-Hodgman against the half-space side * (z - level) >= 0. A cut on an edge
  // between two facet vertices is computed from its lower-numbered sphere, so that the
  // two facets on that edge get the same bits.
  std::vector<ClipPoint> clip(const std::vector<ClipPoint> &in, const std::array<int, 3> &f,
                              double level, int side, int plane) const {
    std::vector<ClipPoint> out;
    for (std::size_t k = 0; k < in.size(); ++k) {
      const ClipPoint &p = in[k], &q = in[(k + 1) % in.size()];
      const bool p_in = side * (p.x.z() - level) >= 0, q_in = side * (q.x.z() - level) >= 0;
      if (p_in) out.push_back(p);
      if (p_in == q_in) continue;
      const bool both_vertices = p.vertex >= 0 && q.vertex >= 0;
      const bool swap = both_vertices && f[q.vertex] < f[p.vertex];
      const ClipPoint &a = swap ? q : p, &b = swap ? p : q;
      const double t = (level - a.x.z()) / (b.x.z() - a.x.z());
      ClipPoint cut{a.x + t * (b.x - a.x), {}, -1, -1};
      cut.x.z() = level;
      for (int j = 0; j < 3; ++j) cut.w[j] = (1 - t) * a.w[j] + t * b.w[j];
      if (both_vertices) cut.key = edge_key(f[p.vertex], f[q.vertex], plane);
      out.push_back(cut);
    }
    return out;
  }

  int corner_index(const ClipPoint &q, const std::array<int, 3> &f) {
    const std::int64_t key = q.vertex >= 0 ? edge_key(f[q.vertex], f[q.vertex], 0) : q.key;
    if (key >= 0) {
      const auto found = by_key_.find(key);
      if (found != by_key_.end()) return found->second;
    }
    Corner c{{-1, -1, -1}, {0, 0, 0}};
    for (int j = 0; j < 3; ++j) {
      if (q.w[j] == 0) continue;
      const int s = m_.original[f[j]];
      int slot = 0;
      while (c.sphere[slot] >= 0 && c.sphere[slot] != s) ++slot;
      c.sphere[slot] = s;
      c.weight[slot] += q.w[j];
    }
    const int index = static_cast<int>(out_.corners.size());
    out_.corners.push_back(c);
    out_.surface.points.push_back(q.x);
    out_.reaches_lo = out_.reaches_lo || q.x.z() == platens_.lo;
    out_.reaches_hi = out_.reaches_hi || q.x.z() == platens_.hi;
    if (key >= 0) by_key_.emplace(key, index);
    return index;
  }
};

void check_platens(const std::vector<Sphere> &spheres, const Platens &p) {
  if (spheres.size() < 4)
    throw std::invalid_argument(std::to_string(spheres.size()) +
                                " spheres: a surface needs at least four");
  if (!(std::isfinite(p.lo) && std::isfinite(p.hi) && p.lo < p.hi))
    throw std::invalid_argument("platens at z = " + std::to_string(p.lo) + " and " +
                                std::to_string(p.hi) + ": the lower must be below the upper");
  for (std::size_t i = 0; i < spheres.size(); ++i)
    if (!(spheres[i].x.z() > p.lo && spheres[i].x.z() < p.hi))
      throw std::invalid_argument("sphere " + std::to_string(i) + " at z = " +
                                  std::to_string(spheres[i].x.z()) +
                                  " is not between the platens");
}

} // namespace

LateralSurface lateral_surface(const std::vector<Sphere> &spheres, const Platens &platens,
                               double tolerance) {
  check_platens(spheres, platens);
  const Mirrored m = mirror_in_platens(spheres, platens, tolerance);
  const Boundary boundary = exterior_boundary(m.spheres, m.image, tolerance);
  PlatenClip clip(m, platens);
  for (const auto &f : boundary.facets) clip.add_facet(f);
  LateralSurface out = std::move(clip).result();
  out.side.assign(boundary.side.begin(), boundary.side.begin() + spheres.size());
  for (Side &s : out.side)
    if (s == Side::surface) s = Side::inside;  // set again below from the loads
  for (const Corner &c : out.corners)
    for (int j = 0; j < 3; ++j)
      if (c.sphere[j] >= 0 && c.weight[j] > 0) out.side[c.sphere[j]] = Side::surface;
  if (out.surface.facets.empty())
    throw std::runtime_error("no surface: no facet of links between the platens separates the " +
                             std::to_string(spheres.size()) +
                             " spheres from the outside (are they a packing? tolerance " +
                             std::to_string(tolerance) + ")");
  return out;
}

std::vector<Eigen::Vector3d> membrane_loads(const LateralSurface &membrane,
                                            std::size_t n_spheres, double p) {
  const std::vector<Eigen::Vector3d> at_corner = pressure_forces(membrane.surface, p);
  std::vector<Eigen::Vector3d> load(n_spheres, Eigen::Vector3d::Zero());
  for (std::size_t k = 0; k < at_corner.size(); ++k) {
    const Corner &c = membrane.corners[k];
    for (int j = 0; j < 3; ++j)
      if (c.sphere[j] >= 0) load.at(c.sphere[j]) += c.weight[j] * at_corner[k];
  }
  return load;
}

} // namespace membrane3d
