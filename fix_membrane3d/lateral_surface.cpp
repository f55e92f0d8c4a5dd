#include "lateral_surface.h"
#include "math_constants.h"
#include "number_text.h"
#include "outer_face_offset.h"

#include "skin_flood.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>

namespace membrane3d {

namespace {

// A corner of a clipped facet: its position, its weights over the facet's three
// vertices, and for a cut on an edge a key shared by the facets on it (-1: none).
struct ClipPoint {
  Eigen::Vector3d x;
  std::array<double, 3> w;
  std::int64_t key;
  int vertex; // the facet vertex it is, -1 for a cut point
};

// At most five corners: a triangle clipped by two planes.
struct Polygon {
  std::array<ClipPoint, 5> corner;
  int n = 0;
  void add(const ClipPoint &q) { corner.at(n++) = q; }
};

// Facets given by their vertices' ids (shared between facets), positions and spheres.
class PlatenClip {
 public:
  PlatenClip(std::int64_t n_ids, const Platens &p)
    : n_ids_(n_ids), platens_(p), vertex_corner_(static_cast<std::size_t>(n_ids), -1)
  {
  }

  void add_facet(const std::array<int, 3> &f, const std::array<Eigen::Vector3d, 3> &x,
                 const std::array<int, 3> &sphere)
  {
    Polygon poly;
    for (int j = 0; j < 3; ++j) {
      std::array<double, 3> w{0, 0, 0};
      w[j] = 1;
      poly.add({x[j], w, -1, j});
    }
    // most facets lie between the platens (the clips would keep them as they are) or
    // wholly beyond one (they would drop them)
    const double z_lo = std::min({x[0].z(), x[1].z(), x[2].z()});
    const double z_hi = std::max({x[0].z(), x[1].z(), x[2].z()});
    if (z_hi < platens_.lo || z_lo > platens_.hi) return;
    if (z_lo < platens_.lo || z_hi > platens_.hi) {
      poly = clip(poly, f, platens_.lo, +1, 1);
      poly = clip(poly, f, platens_.hi, -1, 2);
      if (poly.n < 3) return;
    }
    std::array<int, 5> corner;
    for (int k = 0; k < poly.n; ++k) corner[k] = corner_index(poly.corner[k], f, sphere);
    for (int k = 1; k + 1 < poly.n; ++k)
      out_.surface.facets.push_back({corner[0], corner[k], corner[k + 1]});
  }

  LateralSurface result() && { return std::move(out_); }
  std::size_t facets() const { return out_.surface.facets.size(); }

 private:
  std::int64_t n_ids_;
  Platens platens_;
  LateralSurface out_;
  std::vector<int> vertex_corner_;                   // by vertex id, -1: none yet
  std::unordered_map<std::int64_t, int> cut_corner_; // by edge_key

  std::int64_t edge_key(int u, int v, int plane) const
  {
    return (static_cast<std::int64_t>(std::min(u, v)) * n_ids_ + std::max(u, v)) * 3 + plane;
  }

  // Sutherland-Hodgman against the half-space side * (z - level) >= 0. A cut on an edge
  // between two facet vertices is computed from its lower-numbered sphere, so that the
  // two facets on that edge get the same bits.
  Polygon clip(const Polygon &in, const std::array<int, 3> &f, double level, int side,
               int plane) const
  {
    Polygon out;
    for (int k = 0; k < in.n; ++k) {
      const ClipPoint &p = in.corner[k], &q = in.corner[(k + 1) % in.n];
      const bool p_in = side * (p.x.z() - level) >= 0, q_in = side * (q.x.z() - level) >= 0;
      if (p_in) out.add(p);
      if (p_in == q_in) continue;
      const bool both_vertices = p.vertex >= 0 && q.vertex >= 0;
      const bool swap = both_vertices && f[q.vertex] < f[p.vertex];
      const ClipPoint &a = swap ? q : p, &b = swap ? p : q;
      const double t = (level - a.x.z()) / (b.x.z() - a.x.z());
      ClipPoint cut{a.x + t * (b.x - a.x), {}, -1, -1};
      cut.x.z() = level;
      for (int j = 0; j < 3; ++j) cut.w[j] = (1 - t) * a.w[j] + t * b.w[j];
      if (both_vertices) cut.key = edge_key(f[p.vertex], f[q.vertex], plane);
      out.add(cut);
    }
    return out;
  }

  int corner_index(const ClipPoint &q, const std::array<int, 3> &f,
                   const std::array<int, 3> &sphere)
  {
    int *known = nullptr;
    if (q.vertex >= 0) {
      known = &vertex_corner_[f[q.vertex]];
    } else if (q.key >= 0) {
      known = &cut_corner_.emplace(q.key, -1).first->second;
    }
    if (known && *known >= 0) return *known;
    Corner c{{-1, -1, -1}, {0, 0, 0}};
    for (int j = 0; j < 3; ++j) {
      if (q.w[j] == 0) continue;
      const int s = sphere[j];
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
    if (known) *known = index;
    return index;
  }
};

void check_platens(const std::vector<Sphere> &spheres, const Platens &p)
{
  if (spheres.size() < 4)
    throw std::invalid_argument(count_text(spheres.size(), "sphere", "spheres") +
                                ": a surface needs at least four");
  if (!(std::isfinite(p.lo) && std::isfinite(p.hi) && p.lo < p.hi))
    throw std::invalid_argument("platens at z = " + number_text(p.lo) + " and " +
                                number_text(p.hi) + ": the lower must be below the upper");
  for (std::size_t i = 0; i < spheres.size(); ++i)
    if (!(spheres[i].x.z() > p.lo && spheres[i].x.z() < p.hi))
      throw std::invalid_argument("sphere " + std::to_string(i) + " at z = " +
                                  number_text(spheres[i].x.z()) + " is not between the platens");
}

// The topology of the boundary of the spheres' flood with their images `m`.
// The checks and messages count the group's n_spheres, the sides are of the first
// n_skin (all of them but for a skin, whose left-out spheres are inside).
MembraneTopology topology_of(const Boundary &boundary, const Mirrored &m, std::size_t n_spheres,
                             double tolerance, std::size_t n_skin)
{
  if (boundary.facets.empty())
    throw std::runtime_error("no surface: no facet of links between the platens separates the " +
                             count_text(n_spheres, "sphere", "spheres") +
                             " from the outside (are they a packing? tolerance " +
                             number_text(tolerance) + ")");
  // a membrane that leaves most spheres outside wraps no sample: a shell one sphere
  // thick whose ends are open to the flood, spheres scattered beyond the tolerance
  const auto outside = static_cast<std::size_t>(
      std::count(boundary.side.begin(), boundary.side.begin() + n_skin, Side::outside));
  if (2 * outside > n_spheres)
    throw std::runtime_error("only " + std::to_string(n_spheres - outside) + " of the " +
                             count_text(n_spheres, "sphere", "spheres") +
                             " lie inside the membrane or on it (" + std::to_string(outside) +
                             " outside): the group is no packing between the platens (a shell "
                             "one sphere thick, open to the outside? tolerance " +
                             number_text(tolerance) + ")");
  MembraneTopology t;
  for (const auto &f : boundary.facets) {
    std::array<MembraneVertex, 3> facet;
    for (int j = 0; j < 3; ++j) facet[j] = {m.original[f[j]], m.image[f[j]]};
    t.facets.push_back(facet);
  }
  t.side.assign(boundary.side.begin(), boundary.side.begin() + n_skin);
  return t;
}

} // namespace

MembraneTopology detect_membrane(const std::vector<Sphere> &spheres, const Platens &platens,
                                 double tolerance, Mirrored *mirrored, FloodCells *cells)
{
  check_platens(spheres, platens);
  Mirrored own;
  Mirrored &m = mirrored ? *mirrored : own;
  m = mirror_in_platens(spheres, platens, tolerance);
  return topology_of(exterior_boundary(m.spheres, m.sealed, tolerance, cells), m, spheres.size(),
                     tolerance, spheres.size());
}

MembraneTopology detect_membrane_near(const std::vector<Sphere> &spheres, const Platens &platens,
                                      double tolerance, const std::vector<int> &seeds,
                                      double thickness, bool *from_skin)
{
  check_platens(spheres, platens);
  const Mirrored m = mirror_in_platens(spheres, platens, tolerance);
  const std::vector<char> near = spheres_near(spheres, seeds, thickness);
  std::vector<char> keep(m.spheres.size());
  for (std::size_t i = 0; i < keep.size(); ++i) keep[i] = near[m.original[i]];
  Boundary boundary;
  const bool skin = skin_boundary(m.spheres, m.sealed, tolerance, keep, boundary);
  if (!skin) boundary = exterior_boundary(m.spheres, m.sealed, tolerance);
  if (from_skin) *from_skin = skin;
  return topology_of(boundary, m, spheres.size(), tolerance, spheres.size());
}

MembraneTopology skin_topology(const Boundary &boundary, const Mirrored &m, std::size_t n_skin,
                               std::size_t n_group, double tolerance)
{
  return topology_of(boundary, m, n_group, tolerance, n_skin);
}

MembraneTopology members_only(const MembraneTopology &topology, std::vector<int> &members)
{
  std::vector<int> index(topology.side.size(), -1);
  for (const auto &f : topology.facets)
    for (const MembraneVertex &v : f) index.at(v.sphere) = 0;
  for (std::size_t i = 0; i < topology.side.size(); ++i)
    if (topology.side[i] == Side::outside) index[i] = 0;
  MembraneTopology out;
  members.clear();
  for (std::size_t i = 0; i < index.size(); ++i)
    if (index[i] == 0) {
      index[i] = static_cast<int>(members.size());
      members.push_back(static_cast<int>(i));
      out.side.push_back(topology.side[i]);
    }
  for (auto f : topology.facets) {
    for (MembraneVertex &v : f) v.sphere = index[v.sphere];
    out.facets.push_back(f);
  }
  return out;
}

namespace {

void check_placement(const MembraneTopology &topology, const std::vector<Sphere> &spheres,
                     const Platens &platens)
{
  check_platens(spheres, platens);
  if (topology.side.size() != spheres.size())
    throw std::invalid_argument("a topology of " + std::to_string(topology.side.size()) +
                                " spheres placed on " + std::to_string(spheres.size()));
  for (const auto &f : topology.facets)
    for (const MembraneVertex &v : f)
      if (v.sphere < 0 || v.sphere >= static_cast<int>(spheres.size()))
        throw std::invalid_argument("a facet has sphere " + std::to_string(v.sphere) + " of " +
                                    std::to_string(spheres.size()));
}

} // namespace

std::vector<Eigen::Vector3d> outer_face_offsets_unchecked(const MembraneTopology &topology,
                                                const std::vector<Sphere> &spheres,
                                                const Platens &platens)
{
  // the facet's vector area seen at the sphere of its vertex j (at an image: mirrored)
  const auto facet_area_at = [&](const std::array<MembraneVertex, 3> &f,
                                 std::array<Eigen::Vector3d, 3> &seen) {
    std::array<Eigen::Vector3d, 3> x;
    for (int j = 0; j < 3; ++j) x[j] = image_position(spheres[f[j].sphere].x, f[j].image, platens);
    const Eigen::Vector3d a = facet_vector_area(x[0], x[1], x[2]);
    for (int j = 0; j < 3; ++j) seen[j] = f[j].image != 0 ? Eigen::Vector3d(a.x(), a.y(), -a.z()) : a;
    return a.norm();
  };
  // Where the flood's boundary passes through a flat sliver (a face with a sphere dented
  // by round-off, mirrored at a platen) it folds: a facet lies on its neighbours facing
  // the other way. Its pressure cancels theirs, and it must not pull the vertex in
  // either: a facet facing against its sphere's net outward area is left out.
  std::vector<Eigen::Vector3d> net(spheres.size(), Eigen::Vector3d::Zero());
  std::array<Eigen::Vector3d, 3> seen;
  for (const auto &f : topology.facets) {
    facet_area_at(f, seen);
    for (int j = 0; j < 3; ++j) net[f[j].sphere] += seen[j];
  }
  std::vector<NormalSums> sums(spheres.size());
  for (const auto &f : topology.facets) {
    const double area = facet_area_at(f, seen);
    if (!(area > 0)) continue;
    for (int j = 0; j < 3; ++j)
      if (seen[j].dot(net[f[j].sphere]) > 0) sums[f[j].sphere].add(seen[j], area);
  }
  std::vector<Eigen::Vector3d> offset(spheres.size(), Eigen::Vector3d::Zero());
  for (std::size_t i = 0; i < spheres.size(); ++i) {
    if (sums[i].b.isZero(0)) continue;
    // at most 2 r from the centre (outer_face_offset.h)
    Eigen::Vector3d o = least_squares_offset(sums[i]) * spheres[i].r;
    // Never past a platen plane: the vertex's image would come inside, and the facets
    // of images only, beyond the platen, are not part of the membrane (it would open).
    const double z = spheres[i].x.z();
    o.z() = std::min(std::max(o.z(), platens.lo - z), platens.hi - z);
    offset[i] = o;
  }
  return offset;
}

std::vector<Eigen::Vector3d> outer_face_offsets(const MembraneTopology &topology,
                                                const std::vector<Sphere> &spheres,
                                                const Platens &platens)
{
  check_placement(topology, spheres, platens);
  return outer_face_offsets_unchecked(topology, spheres, platens);
}

LateralSurface place_membrane(const MembraneTopology &topology, const std::vector<Sphere> &spheres,
                              const Platens &platens, Vertices at)
{
  check_placement(topology, spheres, platens);
  std::vector<Eigen::Vector3d> vertex(spheres.size());
  for (std::size_t i = 0; i < spheres.size(); ++i) vertex[i] = spheres[i].x;
  if (at == Vertices::outer_faces) {
    const std::vector<Eigen::Vector3d> o = outer_face_offsets_unchecked(topology, spheres, platens);
    for (std::size_t i = 0; i < spheres.size(); ++i) vertex[i] += o[i];
  }
  return clip_membrane(topology, vertex, platens);
}

LateralSurface clip_membrane(const MembraneTopology &topology,
                             const std::vector<Eigen::Vector3d> &vertex, const Platens &platens,
                             std::vector<int> *origin)
{
  PlatenClip clip(3 * static_cast<std::int64_t>(vertex.size()), platens);
  if (origin) origin->clear();
  for (std::size_t k = 0; k < topology.facets.size(); ++k) {
    const auto &f = topology.facets[k];
    std::array<int, 3> id, sphere;
    std::array<Eigen::Vector3d, 3> x;
    for (int j = 0; j < 3; ++j) {
      sphere[j] = f[j].sphere;
      id[j] = 3 * sphere[j] + f[j].image + 1;
      x[j] = image_position(vertex[sphere[j]], f[j].image, platens);
    }
    clip.add_facet(id, x, sphere);
    if (origin) origin->resize(clip.facets(), static_cast<int>(k));
  }
  LateralSurface out = std::move(clip).result();
  out.side = topology.side;
  for (Side &s : out.side)
    if (s == Side::surface) s = Side::inside; // set again below from the loads
  for (const Corner &c : out.corners)
    for (int j = 0; j < 3; ++j)
      if (c.sphere[j] >= 0 && c.weight[j] > 0) out.side[c.sphere[j]] = Side::surface;
  return out;
}

LateralSurface lateral_surface(const std::vector<Sphere> &spheres, const Platens &platens,
                               double tolerance, Vertices at)
{
  return place_membrane(detect_membrane(spheres, platens, tolerance), spheres, platens, at);
}

std::vector<Eigen::Vector3d> membrane_loads(const LateralSurface &membrane, std::size_t n_spheres,
                                            double p)
{
  const std::vector<Eigen::Vector3d> at_corner = pressure_forces(membrane.surface, p);
  std::vector<Eigen::Vector3d> load(n_spheres, Eigen::Vector3d::Zero());
  for (std::size_t k = 0; k < at_corner.size(); ++k) {
    const Corner &c = membrane.corners[k];
    for (int j = 0; j < 3; ++j)
      if (c.sphere[j] >= 0) load.at(c.sphere[j]) += c.weight[j] * at_corner[k];
  }
  return load;
}

Eigen::Vector2d membrane_axis(const LateralSurface &membrane)
{
  const Surface &s = membrane.surface;
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  double area = 0;
  for (const auto &f : s.facets) {
    const double a = facet_vector_area(s.points[f[0]], s.points[f[1]], s.points[f[2]]).norm();
    sum += a * (s.points[f[0]] + s.points[f[1]] + s.points[f[2]]).head<2>() / 3;
    area += a;
  }
  return area > 0 ? Eigen::Vector2d(sum / area) : Eigen::Vector2d::Zero();
}

void add_escape_loads(const LateralSurface &membrane, const std::vector<Sphere> &spheres, double p,
                      std::vector<Eigen::Vector3d> &load)
{
  if (std::find(membrane.side.begin(), membrane.side.end(), Side::outside) == membrane.side.end())
    return; // no escapee: no axis needed
  const Eigen::Vector2d axis = membrane_axis(membrane);
  for (std::size_t i = 0; i < spheres.size(); ++i)
    if (membrane.side.at(i) == Side::outside) load.at(i) += escape_push(spheres[i], axis, p);
}

Eigen::Vector3d escape_push(const Sphere &sphere, const Eigen::Vector2d &axis, double p)
{
  const Eigen::Vector2d inwards = axis - sphere.x.head<2>();
  const double distance = inwards.norm();
  if (distance == 0) return Eigen::Vector3d::Zero();
  const double push = p * math_constants::PI * sphere.r * sphere.r / distance;
  return Eigen::Vector3d(push * inwards.x(), push * inwards.y(), 0);
}

} // namespace membrane3d
