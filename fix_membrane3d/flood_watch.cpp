#include "flood_watch.h"

#include "determinant_margin.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <utility>

namespace membrane3d {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

// The cells watched: the flooded ones and this many rings of cells around them (the
// buffer, and the ring that keeps the buffer's neighbours: flood_watch.h).
constexpr int kRings = 2;

// A side that the watch does not decide: counts as changed.
constexpr int kUndecided = 2;

// A bound on the floating-point error of the determinants below, relative to the
// product of their rows' lengths: far above it (4 x 4 products of doubles).
constexpr double kRoundOff = 1e-10;

K::Point_3 point(const Sphere &s)
{
  return K::Point_3(s.x.x(), s.x.y(), s.x.z());
}
K::Weighted_point_3 weighted(const Sphere &s)
{
  return K::Weighted_point_3(point(s), s.r * s.r);
}

// The predicates of the regular triangulation on indexed points, as CGAL's
// Regular_triangulation_3 decides them (side_of_power_sphere with its symbolic
// perturbation: Devillers and Teillaud, Perturbations for Delaunay and weighted
// Delaunay 3D triangulations, 2011), with the images' structural zeros known.
class Predicates {
 public:
  Predicates(const std::vector<Sphere> &x, const MirrorFamilies &m) : x_(x), m_(m) {}

  int orientation(int a, int b, int c, int d) const
  {
    if (vertical_pairs(a, b, c, d)) return 0;
    return CGAL::orientation(point(x_[a]), point(x_[b]), point(x_[c]), point(x_[d]));
  }

  // side_of_power_sphere(cell, p, perturb = true): -1 outside (no conflict), +1 inside
  int side(const std::array<int, 4> &v, int p) const
  {
    int i3 = -1;
    for (int k = 0; k < 4; ++k)
      if (v[k] < 0) i3 = k;
    if (i3 < 0) return perturbed_sphere(v[0], v[1], v[2], v[3], p);
    int i0, i1, i2;
    if (i3 % 2 == 1) {
      i0 = (i3 + 1) & 3;
      i1 = (i3 + 2) & 3;
      i2 = (i3 + 3) & 3;
    } else {
      i0 = (i3 + 2) & 3;
      i1 = (i3 + 1) & 3;
      i2 = (i3 + 3) & 3;
    }
    const int o = orientation(v[i0], v[i1], v[i2], p);
    if (o != 0) return o;
    return bounded_circle(v[i0], v[i1], v[i2], p);
  }

 private:
  const std::vector<Sphere> &x_;
  const MirrorFamilies &m_;

  bool same_line(int a, int b) const { return m_.family[a] == m_.family[b]; }
  // a and b mirror each other in the platen `plane`
  bool mirrors(int a, int b, int plane) const
  {
    return same_line(a, b) && ((m_.plane[a] == 0 && m_.plane[b] == plane) ||
                               (m_.plane[b] == 0 && m_.plane[a] == plane));
  }
  // four points on two vertical lines (or three on one): coplanar
  bool vertical_pairs(int a, int b, int c, int d) const
  {
    const int p[4] = {a, b, c, d};
    int pairs = 0;
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) pairs += same_line(p[i], p[j]);
    return pairs >= 2;
  }
  // p mirrors one of `cell` in a platen in which two others of it mirror each other
  template <std::size_t N> bool mirror_zero(const std::array<int, N> &cell, int p) const
  {
    for (int plane : {-1, 1})
      for (std::size_t i = 0; i < N; ++i)
        for (std::size_t j = i + 1; j < N; ++j) {
          if (!mirrors(cell[i], cell[j], plane)) continue;
          for (std::size_t k = 0; k < N; ++k)
            if (k != i && k != j && mirrors(cell[k], p, plane)) return true;
        }
    return false;
  }

  int power5(int a, int b, int c, int d, int p) const
  {
    if (mirror_zero(std::array<int, 4>{a, b, c, d}, p)) return 0;
    return K().power_side_of_oriented_power_sphere_3_object()(
        weighted(x_[a]), weighted(x_[b]), weighted(x_[c]), weighted(x_[d]), weighted(x_[p]));
  }
  int power4(int a, int b, int c, int p) const
  {
    if (mirror_zero(std::array<int, 3>{a, b, c}, p)) return 0;
    return K().power_side_of_oriented_power_sphere_3_object()(weighted(x_[a]), weighted(x_[b]),
                                                              weighted(x_[c]), weighted(x_[p]));
  }
  int coplanar_orientation(int a, int b, int c) const
  {
    if (same_line(a, b) && same_line(b, c)) return 0;
    return K().coplanar_orientation_3_object()(point(x_[a]), point(x_[b]), point(x_[c]));
  }
  // the points sorted lexicographically (x, y, z), as CGAL's Perturbation_order
  template <std::size_t N> std::array<int, N> lexicographic(std::array<int, N> p) const
  {
    std::sort(p.begin(), p.end(), [this](int a, int b) {
      return CGAL::compare_xyz(point(x_[a]), point(x_[b])) == CGAL::SMALLER;
    });
    return p;
  }

  int perturbed_sphere(int p0, int p1, int p2, int p3, int p) const
  {
    const int os = power5(p0, p1, p2, p3, p);
    if (os != 0) return os;
    const auto order = lexicographic(std::array<int, 5>{p0, p1, p2, p3, p});
    for (int i = 4; i > 1; --i) {
      const int q = order[i];
      if (q == p) return -1;
      int o = 0;
      if (q == p3 && (o = orientation(p0, p1, p2, p)) != 0) return o;
      if (q == p2 && (o = orientation(p0, p1, p, p3)) != 0) return o;
      if (q == p1 && (o = orientation(p0, p, p2, p3)) != 0) return o;
      if (q == p0 && (o = orientation(p, p1, p2, p3)) != 0) return o;
    }
    return -1;
  }

  int perturbed_circle(int p0, int p1, int p2, int p) const
  {
    const int os = power4(p0, p1, p2, p);
    if (os != 0) return os;
    const auto order = lexicographic(std::array<int, 4>{p0, p1, p2, p});
    for (int i = 3; i > 1; --i) {
      const int q = order[i];
      if (q == p) return -1;
      int o = 0;
      if (q == p2 && (o = coplanar_orientation(p0, p1, p)) != 0) return o;
      if (q == p1 && (o = coplanar_orientation(p0, p, p2)) != 0) return o;
      if (q == p0 && (o = coplanar_orientation(p, p1, p2)) != 0) return o;
    }
    return -1;
  }

  // (a collinear hull facet, CGAL's power segment, is not followed: undecided)
  int bounded_circle(int p0, int p1, int p2, int p) const
  {
    const int o = coplanar_orientation(p0, p1, p2);
    if (o == 0) return kUndecided;
    return o > 0 ? perturbed_circle(p0, p1, p2, p) : perturbed_circle(p0, p2, p1, p);
  }
};

// Whether orientation(p0, p1, p2, p3) keeps its sign while each point moves by less
// than delta: with q_i = p_i - p_0 moving by e_i, |e_i| < 2 delta, the determinant
// changes by at most the first-order cofactor terms and the Hadamard bounds of the rest.
bool orientation_safe(const std::array<const Sphere *, 4> &p, double delta)
{
  const Eigen::Vector3d q1 = p[1]->x - p[0]->x, q2 = p[2]->x - p[0]->x, q3 = p[3]->x - p[0]->x;
  const double det = q1.dot(q2.cross(q3));
  const double e = 2 * delta, n1 = q1.norm(), n2 = q2.norm(), n3 = q3.norm();
  const double first = e * (q2.cross(q3).norm() + q3.cross(q1).norm() + q1.cross(q2).norm());
  const double rest = e * e * (n1 + n2 + n3) + e * e * e;
  return first + rest + kRoundOff * n1 * n2 * n3 < std::abs(det);
}

// The same for the power test of p4 against the power sphere of p0..p3: the 4 x 4
// determinant of rows (q_i, (|q_i|^2 - w_i + w_4) / L), q_i = p_i - p_4, weights
// w = r^2 (the lifted column scaled by the longest |q_i| = L, a length like the others).
bool power_safe(const std::array<const Sphere *, 5> &p, double delta)
{
  Eigen::Matrix4d a;
  double L = 0;
  for (int i = 0; i < 4; ++i) L = std::max(L, (p[i]->x - p[4]->x).norm());
  if (!(L > 0)) return false;
  const double w4 = p[4]->r * p[4]->r;
  for (int i = 0; i < 4; ++i) {
    const Eigen::Vector3d q = p[i]->x - p[4]->x;
    a.row(i) << q.transpose(), (q.squaredNorm() - p[i]->r * p[i]->r + w4) / L;
  }
  const double det = a.determinant();
  const double e = 2 * delta;
  double first = 0;
  std::array<double, 4> row_norm, row_change;
  for (int i = 0; i < 4; ++i) {
    // cofactors of row i
    Eigen::Vector4d c;
    for (int j = 0; j < 4; ++j) {
      Eigen::Matrix3d minor;
      for (int r = 0, mr = 0; r < 4; ++r) {
        if (r == i) continue;
        for (int s = 0, ms = 0; s < 4; ++s) {
          if (s == j) continue;
          minor(mr, ms++) = a(r, s);
        }
        ++mr;
      }
      c(j) = ((i + j) % 2 ? -1.0 : 1.0) * minor.determinant();
    }
    const Eigen::Vector3d q = a.row(i).head<3>().transpose();
    // row i moves by (e_i, (2 q . e_i + |e_i|^2) / L)
    first += e * (c.head<3>() + (2 / L) * c(3) * q).norm() + e * e * std::abs(c(3)) / L;
    row_norm[i] = a.row(i).norm();
    row_change[i] = e * (1 + (2 * q.norm() + e) / L);
  }
  return determinant_margin(det, first, row_norm, row_change, kRoundOff);
}

class WatchBuilder {
 public:
  WatchBuilder(const FloodCells &cells, const std::vector<Sphere> &spheres,
               const std::vector<bool> &sealed, const MirrorFamilies &mirrors, double tolerance,
               double budget)
    : cells_(cells), spheres_(spheres), sealed_(sealed), mirrors_(mirrors),
      predicates_(spheres, mirrors), tolerance_(tolerance), budget_(budget),
      compact_(spheres.size(), -1)
  {
  }

  FloodWatch build()
  {
    const std::size_t n = cells_.vertex.size();
    // the flood's choice of the sample among dry groups could change with flips of
    // unwatched cells only if another group came near it in size
    if (n == 0 || cells_.kept_group <= 4 * cells_.other_group) return watch_;
    // the buffer, and the ring of cells around it (see flood_watch.h)
    std::vector<char> buffer(n, 0), oriented(n, 0);
    for (std::size_t c = 0; c < n; ++c)
      if (cells_.flooded[c]) buffer[c] = 1;
    for (int ring = 0; ring < kRings; ++ring) {
      std::vector<char> grown = buffer;
      for (std::size_t c = 0; c < n; ++c)
        if (buffer[c])
          for (int n_c : cells_.neighbour[c]) grown[n_c] = 1;
      buffer.swap(grown);
    }
    for (std::size_t c = 0; c < n; ++c) {
      if (!buffer[c]) continue;
      for (int v : cells_.vertex[c])
        if (v >= 0) mark(v);
      if (finite(c)) add_orientation(c, oriented);
      for (int k = 0; k < 4; ++k) {
        const int nb = cells_.neighbour[c][k];
        if (buffer[nb] && nb < static_cast<int>(c)) continue; // each facet once
        add_facet(static_cast<int>(c), nb, oriented);
      }
      if (cells_.flooded[c]) add_links(static_cast<int>(c));
    }
    for (std::size_t h = 0; h < cells_.hidden.size(); ++h)
      if (!add_hidden(cells_.hidden[h], cells_.hidden_cell[h])) return watch_;
    finish();
    watch_.always = false;
    return watch_;
  }

 private:
  const FloodCells &cells_;
  const std::vector<Sphere> &spheres_;
  const std::vector<bool> &sealed_;
  const MirrorFamilies &mirrors_;
  const Predicates predicates_;
  double tolerance_, budget_;
  std::vector<int> compact_; // per sphere: 0 when the watch needs it (then its entry)
  std::vector<std::pair<int, int>> edges_;
  FloodWatch watch_;

  bool finite(std::size_t c) const
  {
    const auto &v = cells_.vertex[c];
    return v[0] >= 0 && v[1] >= 0 && v[2] >= 0 && v[3] >= 0;
  }
  void mark(int sphere) { compact_[sphere] = 0; }

  void add_orientation(std::size_t c, std::vector<char> &oriented)
  {
    if (oriented[c]) return;
    oriented[c] = 1;
    const auto &v = cells_.vertex[c];
    ++watch_.certificates;
    if (orientation_safe({&spheres_[v[0]], &spheres_[v[1]], &spheres_[v[2]], &spheres_[v[3]]},
                         budget_))
      return;
    watch_orientation(v);
  }

  void watch_orientation(const std::array<int, 4> &v)
  {
    for (int s : v) mark(s);
    watch_.orientation.push_back(v);
    watch_.orientation_sign.push_back(
        static_cast<signed char>(predicates_.orientation(v[0], v[1], v[2], v[3])));
  }

  // The side of p towards cell v's power sphere: safe when its leading test (the power
  // test of a finite cell, the orientation towards an infinite cell's hull facet) keeps
  // its sign.
  void add_side(const std::array<int, 4> &v, int p)
  {
    ++watch_.certificates;
    std::array<const Sphere *, 4> finite_points{};
    int m = 0;
    for (int s : v)
      if (s >= 0) finite_points[m++] = &spheres_[s];
    const bool safe =
        m == 4 ? power_safe({finite_points[0], finite_points[1], finite_points[2], finite_points[3],
                             &spheres_[p]},
                            budget_)
               : orientation_safe(
                     {finite_points[0], finite_points[1], finite_points[2], &spheres_[p]}, budget_);
    if (safe) return;
    watch_side(v, p);
  }

  void watch_side(const std::array<int, 4> &v, int p)
  {
    for (int s : v)
      if (s >= 0) mark(s);
    mark(p);
    watch_.side_cell.push_back(v);
    watch_.side_point.push_back(p);
    watch_.side.push_back(static_cast<signed char>(predicates_.side(v, p)));
  }

  // The vertex of cell nb opposite its facet shared with cell c.
  int far_vertex(int c, int nb) const
  {
    for (int j = 0; j < 4; ++j)
      if (cells_.neighbour[nb][j] == c) return cells_.vertex[nb][j];
    return -1;
  }

  // The facet between cells c and nb is regular while the far vertex of one is
  // outside the power sphere of the other (for a finite cell and an infinite one: the
  // finite cell's far vertex inside the hull; the infinite vertex is no point).
  void add_facet(int c, int nb, std::vector<char> &oriented)
  {
    const int far_of_nb = far_vertex(c, nb), far_of_c = far_vertex(nb, c);
    if (far_of_nb >= 0)
      add_side(cells_.vertex[c], far_of_nb);
    else if (far_of_c >= 0)
      add_side(cells_.vertex[nb], far_of_c);
    if (finite(c) != finite(nb)) add_orientation(finite(c) ? c : nb, oriented);
  }

  // The links on the facets of a flooded cell: the walls the flood could not pass.
  void add_links(int c)
  {
    const auto &v = cells_.vertex[c];
    for (int k = 0; k < 4; ++k) {
      const int a = v[(k + 1) & 3], b = v[(k + 2) & 3], d = v[(k + 3) & 3];
      if (a < 0 || b < 0 || d < 0) continue;
      for (auto e : {std::minmax(a, b), std::minmax(b, d), std::minmax(a, d)}) edges_.push_back(e);
    }
  }

  // A sphere that is no vertex: it stays so while its side towards its cell holds,
  // and in that cell while its orientations towards the cell's facets hold.
  bool add_hidden(int h, int c)
  {
    if (!finite(c)) return false;
    const auto &v = cells_.vertex[c];
    mark(h);
    watch_side(v, h);
    for (int k = 0; k < 4; ++k) {
      std::array<int, 4> u = v;
      u[k] = h;
      watch_orientation(u);
    }
    watch_.certificates += 5;
    return true;
  }

  void finish()
  {
    std::sort(edges_.begin(), edges_.end());
    edges_.erase(std::unique(edges_.begin(), edges_.end()), edges_.end());
    for (const auto &[a, b] : edges_) {
      ++watch_.certificates;
      const Sphere &p = spheres_[a], &q = spheres_[b];
      const double threshold = sealed_[a] || sealed_[b] ? 2 * tolerance_ : tolerance_;
      const double distance = (p.x - q.x).norm(), gap = distance - p.r - q.r;
      // the gap changes by less than 2 budget
      if (std::abs(gap - threshold) > 2 * budget_ + kRoundOff * (distance + threshold)) continue;
      mark(a);
      mark(b);
      watch_.link.push_back({a, b});
      watch_.link_threshold.push_back(threshold);
      watch_.linked.push_back(gap <= threshold);
    }
    for (std::size_t s = 0; s < compact_.size(); ++s)
      if (compact_[s] == 0) {
        compact_[s] = static_cast<int>(watch_.point.size());
        watch_.point.push_back(static_cast<int>(s));
        watch_.mirrors.family.push_back(mirrors_.family[s]);
        watch_.mirrors.plane.push_back(mirrors_.plane[s]);
      }
    for (auto &v : watch_.side_cell)
      for (int &s : v)
        if (s >= 0) s = compact_[s];
    for (int &s : watch_.side_point) s = compact_[s];
    for (auto &v : watch_.orientation)
      for (int &s : v) s = compact_[s];
    for (auto &v : watch_.link)
      for (int &s : v) s = compact_[s];
  }
};

} // namespace

FloodWatch watch_flood(const FloodCells &cells, const std::vector<Sphere> &spheres,
                       const std::vector<bool> &sealed, const MirrorFamilies &mirrors,
                       double tolerance, double budget)
{
  return WatchBuilder(cells, spheres, sealed, mirrors, tolerance, budget).build();
}

bool watched_flood_changed(const FloodWatch &watch, const std::vector<Sphere> &now)
{
  if (watch.always) return true;
  for (std::size_t k = 0; k < watch.link.size(); ++k) {
    const Sphere &p = now[watch.link[k][0]], &q = now[watch.link[k][1]];
    // the expression of the flood's test (exterior_flood.cpp), to the last bit
    const bool linked = (p.x - q.x).norm() - p.r - q.r <= watch.link_threshold[k];
    if (linked != static_cast<bool>(watch.linked[k])) return true;
  }
  const Predicates predicates(now, watch.mirrors);
  for (std::size_t k = 0; k < watch.orientation.size(); ++k) {
    const auto &v = watch.orientation[k];
    const int s = predicates.orientation(v[0], v[1], v[2], v[3]);
    if (s == 0 || s != watch.orientation_sign[k]) return true;
  }
  for (std::size_t k = 0; k < watch.side.size(); ++k) {
    const int s = predicates.side(watch.side_cell[k], watch.side_point[k]);
    if (s == kUndecided || s != watch.side[k]) return true;
  }
  return false;
}

} // namespace membrane3d
