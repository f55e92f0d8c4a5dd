#include "skin_flood.h"
#include "math_constants.h"

#include "number_text.h"
#include "power_flood.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <unordered_map>

namespace membrane3d {

namespace {

using power::Cell;

// A cell whose edge vectors span less than this fraction of their lengths' product is
// too flat for its power sphere in doubles: it is tested against every left-out sphere.
constexpr double kFlat = 1e-9;
// The widening of a power sphere's reach, relative to it and its centre's distance from
// the cell: above the round-off of the centre of any cell not flat (the condition of its
// linear system below 1 / kFlat gives an error below 1e-7 of that distance).
constexpr double kMargin = 1e-6;
// More flat cells than this: the skin is no gain, flood all the spheres.
constexpr int kMostFlatCells = 64;

// Spheres in a uniform grid of cubes, for the ones near a point.
class SphereGrid {
 public:
  SphereGrid(const std::vector<Sphere> &spheres, const std::vector<int> &members, double side)
    : spheres_(spheres)
  {
    if (members.empty()) return;
    Eigen::Vector3d lo = spheres[members[0]].x, hi = lo;
    for (int i : members) {
      lo = lo.cwiseMin(spheres[i].x);
      hi = hi.cwiseMax(spheres[i].x);
    }
    // no more cubes than about 8 per member: a far-flung sphere widens them
    const double volume = (hi - lo + Eigen::Vector3d::Constant(side)).prod();
    side_ = std::max(side, std::cbrt(volume / (8.0 * static_cast<double>(members.size()))));
    origin_ = lo;
    for (int d = 0; d < 3; ++d) dims_[d] = static_cast<int>((hi[d] - lo[d]) / side_) + 1;
    std::vector<int> cube(members.size());
    start_.assign(static_cast<std::size_t>(dims_[0]) * dims_[1] * dims_[2] + 1, 0);
    for (std::size_t k = 0; k < members.size(); ++k) {
      cube[k] = index(cube_of(spheres[members[k]].x, 0), cube_of(spheres[members[k]].x, 1),
                      cube_of(spheres[members[k]].x, 2));
      ++start_[cube[k] + 1];
    }
    for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
    sphere_.resize(members.size());
    std::vector<int> fill(start_.begin(), start_.end() - 1);
    for (std::size_t k = 0; k < members.size(); ++k) sphere_[fill[cube[k]]++] = members[k];
  }

  // the members, cube by cube (neighbours in space near each other in it)
  const std::vector<int> &in_cube_order() const { return sphere_; }

  // f(i) for each member whose centre is within `reach` of x
  template <class F> void for_each_within(const Eigen::Vector3d &x, double reach, F f) const
  {
    if (sphere_.empty()) return;
    int lo[3], hi[3];
    for (int d = 0; d < 3; ++d) {
      lo[d] = cube_of(x - Eigen::Vector3d::Constant(reach), d);
      hi[d] = cube_of(x + Eigen::Vector3d::Constant(reach), d);
    }
    for (int a = lo[0]; a <= hi[0]; ++a)
      for (int b = lo[1]; b <= hi[1]; ++b)
        for (int c = lo[2]; c <= hi[2]; ++c) {
          const int cube = index(a, b, c);
          for (int k = start_[cube]; k < start_[cube + 1]; ++k)
            if ((spheres_[sphere_[k]].x - x).squaredNorm() <= reach * reach) f(sphere_[k]);
        }
  }

 private:
  const std::vector<Sphere> &spheres_;
  Eigen::Vector3d origin_ = Eigen::Vector3d::Zero();
  double side_ = 1;
  int dims_[3] = {1, 1, 1};
  std::vector<int> start_, sphere_; // per cube its first entry of sphere_

  int cube_of(const Eigen::Vector3d &x, int d) const
  {
    const double c = std::floor((x[d] - origin_[d]) / side_);
    return static_cast<int>(std::clamp(c, 0.0, static_cast<double>(dims_[d] - 1)));
  }
  int index(int a, int b, int c) const { return (a * dims_[1] + b) * dims_[2] + c; }
};

// A finite cell's power sphere in doubles: a sphere of radius r_p is in conflict with
// the cell only if its centre is within `reach` of `centre` (with r_p <= r_max).
struct PowerReach {
  Eigen::Vector3d centre;
  double weight; // the power sphere's squared radius (negative: none)
  double margin;
  double reach; // for r_max
  bool flat;

  // whether a sphere of radius r at x can be in conflict with the cell
  bool may_reach(const Eigen::Vector3d &x, double r) const
  {
    const double d = std::sqrt(std::max(weight, 0.0) + r * r) + margin;
    return (x - centre).squaredNorm() <= d * d;
  }
};

PowerReach power_reach(Cell c, double r_max)
{
  // centre x_0 + y with 2 e_i . y = |e_i|^2 - w_i + w_0 (e_i = x_i - x_0, w = r^2)
  const auto x = [c](int k) {
    const auto &p = c->vertex(k)->point().point();
    return Eigen::Vector3d(p.x(), p.y(), p.z());
  };
  const auto w = [c](int k) { return c->vertex(k)->point().weight(); };
  const Eigen::Vector3d x0 = x(0), e1 = x(1) - x0, e2 = x(2) - x0, e3 = x(3) - x0;
  const double b1 = 0.5 * (e1.squaredNorm() - w(1) + w(0)),
               b2 = 0.5 * (e2.squaredNorm() - w(2) + w(0)),
               b3 = 0.5 * (e3.squaredNorm() - w(3) + w(0));
  const Eigen::Vector3d c23 = e2.cross(e3), c31 = e3.cross(e1), c12 = e1.cross(e2);
  const double det = e1.dot(c23);
  PowerReach out{x0, 0.0, 0.0, 0.0, !(std::abs(det) >= kFlat * e1.norm() * e2.norm() * e3.norm())};
  if (out.flat) return out;
  const Eigen::Vector3d y = (b1 * c23 + b2 * c31 + b3 * c12) / det;
  out.centre = x0 + y;
  out.weight = y.squaredNorm() - w(0);
  const double reach = std::sqrt(std::max(out.weight, 0.0) + r_max * r_max);
  out.margin = kMargin * (reach + y.norm());
  out.reach = reach + out.margin;
  return out;
}

// An image left out beyond the skin's hull, seen from the located infinite cell c:
// inserted, it replaces the hull facets it sees and the cells in conflict with it.
// They change nothing the flood reads when the facets it sees are neither flooded nor
// next to a flooded cell (its cells in conflict that are finite are tested with the
// others) and are all sealed, so that the hull's new cells are all sealed too.
bool hidden_beyond_hull(const PowerFlood &flood, Cell c, const power::K::Weighted_point_3 &p)
{
  const power::Triangulation &t = flood.triangulation();
  std::vector<Cell> front{c}, seen{c};
  const auto visible = [&](Cell h) {
    const int inf = h->index(t.infinite_vertex());
    // the facet's vertices in the order that makes its inner side negative
    const auto &a = h->vertex((inf + 1) & 3)->point(), &b = h->vertex((inf + 2) & 3)->point(),
               &d = h->vertex((inf + 3) & 3)->point();
    return (inf % 2 == 1 ? CGAL::orientation(a.point(), b.point(), d.point(), p.point())
                         : CGAL::orientation(b.point(), a.point(), d.point(), p.point()));
  };
  while (!front.empty()) {
    const Cell h = front.back();
    front.pop_back();
    if (flood.flooded(h) || !flood.all_sealed(h)) return false;
    for (int k = 0; k < 4; ++k)
      if (flood.flooded(h->neighbor(k))) return false;
    for (int k = 0; k < 4; ++k) {
      const Cell n = h->neighbor(k);
      if (!t.is_infinite(n) || std::find(seen.begin(), seen.end(), n) != seen.end()) continue;
      const CGAL::Orientation o = visible(n);
      if (o == CGAL::ZERO) return false; // on a hull facet's plane: not followed here
      if (o == CGAL::NEGATIVE) continue;
      seen.push_back(n);
      front.push_back(n);
    }
  }
  return true;
}

} // namespace

std::vector<char> spheres_near(const std::vector<Sphere> &spheres, const std::vector<int> &seeds,
                               double thickness)
{
  std::vector<char> near(spheres.size(), 0);
  check_spheres(spheres);
  double r_max = 0;
  for (const Sphere &s : spheres) r_max = std::max(r_max, s.r);
  if (!std::isfinite(thickness))
    throw std::invalid_argument("skin thickness " + number_text(thickness) +
                                ": must be finite");
  std::vector<int> all(spheres.size());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int>(i);
  const SphereGrid grid(spheres, all, 2 * r_max + thickness);
  for (int s : seeds) {
    const Sphere &seed = spheres.at(s);
    near[s] = 1;
    grid.for_each_within(seed.x, seed.r + r_max + thickness, [&](int i) {
      if ((spheres[i].x - seed.x).norm() - spheres[i].r - seed.r <= thickness) near[i] = 1;
    });
  }
  return near;
}

struct SkinShell::Impl {
  std::vector<Sphere> skin;
  std::vector<bool> sealed;
  std::unique_ptr<PowerFlood> flood; // none: not usable
  std::vector<Cell> shell_cells;     // the finite ones
};

SkinShell::SkinShell(std::vector<Sphere> skin, std::vector<bool> sealed, double tolerance)
  : impl_(std::make_unique<Impl>())
{
  Impl &m = *impl_;
  m.skin = std::move(skin);
  m.sealed = std::move(sealed);
  if (m.skin.size() < 4) return;
  check_flood_input(m.skin, m.sealed, tolerance);
  try {
    m.flood = std::make_unique<PowerFlood>(m.skin, m.sealed, tolerance);
  } catch (const FlatSample &) {
    return; // a flat skin says nothing of the whole
  }
  const PowerFlood &flood = *m.flood;
  const power::Triangulation &t = flood.triangulation();
  // the dry cells next to flooded ones (the sample's group's shell)
  long shell = 0;
  int flat_cells = 0;
  for (Cell c : flood.cells()) {
    if (flood.flooded(c)) continue;
    bool near = false;
    for (int k = 0; k < 4 && !near; ++k) near = flood.flooded(c->neighbor(k));
    if (!near) continue;
    if (!flood.all_sealed(c)) ++shell;
    if (t.is_infinite(c)) continue;
    m.shell_cells.push_back(c);
    flat_cells += power_reach(c, 0.0).flat;
  }
  if (shell <= flood.other_group() || flat_cells > kMostFlatCells) {
    m.shell_cells.clear();
    m.flood.reset();
  }
}

SkinShell::~SkinShell() = default;

bool SkinShell::usable() const
{
  return impl_->flood != nullptr;
}

std::vector<int> SkinShell::failing(const std::vector<Sphere> &left,
                                    const std::vector<bool> &sealed, bool first_only) const
{
  check_spheres(left);
  if (sealed.size() != left.size())
    throw std::invalid_argument("sealed flags for " + std::to_string(sealed.size()) + " of " +
                                std::to_string(left.size()) + " spheres");
  std::vector<int> out;
  if (!usable()) {
    for (std::size_t i = 0; i < left.size() && !(first_only && !out.empty()); ++i)
      out.push_back(static_cast<int>(i));
    return out;
  }
  if (left.empty()) return out;
  const PowerFlood &flood = *impl_->flood;
  const power::Triangulation &t = flood.triangulation();
  std::vector<char> failed(left.size(), 0);
  double r_max = 0;
  for (const Sphere &s : left) r_max = std::max(r_max, s.r);
  std::vector<int> all(left.size());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int>(i);
  const SphereGrid grid(left, all, 2 * r_max);
  Cell hint;
  for (int i : grid.in_cube_order()) {
    power::Triangulation::Locate_type type;
    int li = 0, lj = 0;
    const power::K::Weighted_point_3 p = power::weighted_point(left[i]);
    const Cell c = t.locate(p, type, li, lj, hint);
    hint = c;
    if (type == power::Triangulation::CELL && !flood.flooded(c)) continue;
    if (type == power::Triangulation::OUTSIDE_CONVEX_HULL && sealed[i] &&
        hidden_beyond_hull(flood, c, p))
      continue;
    if (first_only) return {i};
    failed[i] = 1;
  }
  for (Cell c : impl_->shell_cells) {
    const auto test = [&](int i) {
      if (failed[i] ||
          t.side_of_power_sphere(c, power::weighted_point(left[i])) == CGAL::ON_UNBOUNDED_SIDE)
        return false;
      failed[i] = 1;
      return true;
    };
    const PowerReach p = power_reach(c, r_max);
    if (p.flat) {
      for (int i : all)
        if (test(i) && first_only) return {i};
    } else {
      bool found = false;
      grid.for_each_within(p.centre, p.reach, [&](int i) {
        if (!found && p.may_reach(left[i].x, left[i].r)) found = test(i) && first_only;
      });
      if (found)
        for (int i : all)
          if (failed[i]) return {i};
    }
  }
  for (std::size_t i = 0; i < left.size(); ++i)
    if (failed[i]) out.push_back(static_cast<int>(i));
  return out;
}

Boundary SkinShell::boundary() const
{
  if (!usable()) throw std::logic_error("the boundary of a skin that shows nothing");
  return impl_->flood->boundary(nullptr);
}

std::vector<char> near_seeds(const std::vector<Sphere> &mine, const std::vector<Sphere> &seeds,
                             double thickness)
{
  if (!std::isfinite(thickness))
    throw std::invalid_argument("skin thickness " + number_text(thickness) +
                                ": must be finite");
  std::vector<char> near(mine.size(), 0);
  if (seeds.empty()) return near;
  double seed_r = 0;
  for (const Sphere &s : seeds) seed_r = std::max(seed_r, s.r);
  std::vector<int> all(seeds.size());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int>(i);
  const SphereGrid grid(seeds, all, std::max(2 * seed_r + thickness, 1e-9 * seed_r));
  Eigen::Vector3d lo = seeds[0].x, hi = lo;
  for (const Sphere &s : seeds) {
    lo = lo.cwiseMin(s.x);
    hi = hi.cwiseMax(s.x);
  }
  for (std::size_t i = 0; i < mine.size(); ++i) {
    const Sphere &m = mine[i];
    const double reach = m.r + seed_r + thickness;
    const Eigen::Vector3d x = m.x;
    if ((x.array() < lo.array() - reach).any() || (x.array() > hi.array() + reach).any()) continue;
    grid.for_each_within(x, reach, [&](int k) {
      if (!near[i] && (seeds[k].x - x).norm() - m.r - seeds[k].r <= thickness) near[i] = 1;
    });
  }
  return near;
}

bool skin_boundary(const std::vector<Sphere> &spheres, const std::vector<bool> &sealed,
                   double tolerance, const std::vector<char> &keep, Boundary &out)
{
  check_flood_input(spheres, sealed, tolerance);
  if (keep.size() != spheres.size())
    throw std::invalid_argument("skin flags for " + std::to_string(keep.size()) + " of " +
                                std::to_string(spheres.size()) + " spheres");
  std::vector<Sphere> skin, left;
  std::vector<bool> skin_sealed, left_sealed;
  std::vector<int> skin_index;
  for (std::size_t i = 0; i < spheres.size(); ++i) {
    if (!keep[i]) {
      left.push_back(spheres[i]);
      left_sealed.push_back(sealed[i]);
      continue;
    }
    skin.push_back(spheres[i]);
    skin_sealed.push_back(sealed[i]);
    skin_index.push_back(static_cast<int>(i));
  }
  if (left.empty() || skin.size() < 4) return false;
  const SkinShell shell(std::move(skin), std::move(skin_sealed), tolerance);
  if (!shell.usable() || !shell.failing(left, left_sealed, true).empty()) return false;

  // the skin's boundary in the spheres' numbering (ascending with it: the facets keep
  // their order); every left-out sphere is inside
  Boundary b = shell.boundary();
  for (auto &f : b.facets)
    for (int &v : f) v = skin_index[v];
  out.facets = std::move(b.facets);
  out.side.assign(spheres.size(), Side::inside);
  for (std::size_t k = 0; k < skin_index.size(); ++k) out.side[skin_index[k]] = b.side[k];
  return true;
}

std::vector<int> outermost_spheres(const std::vector<Sphere> &spheres, double diameter,
                                   double depth)
{
  if (spheres.empty() || !(diameter > 0) || !std::isfinite(diameter)) return {};
  Eigen::Vector2d axis = Eigen::Vector2d::Zero();
  double z_lo = spheres[0].x.z(), outer = 0;
  for (const Sphere &s : spheres) {
    axis += s.x.head<2>() / static_cast<double>(spheres.size());
    z_lo = std::min(z_lo, s.x.z());
  }
  std::vector<double> reach(spheres.size()); // of each outer face from the axis
  for (std::size_t i = 0; i < spheres.size(); ++i) {
    reach[i] = (spheres[i].x.head<2>() - axis).norm() + spheres[i].r;
    outer = std::max(outer, reach[i]);
  }
  const long sectors = std::clamp(static_cast<long>(math_constants::TWO_PI * outer / diameter), 8L, 1L << 16);
  std::vector<long> bin(spheres.size());
  std::unordered_map<long, double> farthest;
  for (std::size_t i = 0; i < spheres.size(); ++i) {
    const Eigen::Vector2d r = spheres[i].x.head<2>() - axis;
    const double turn = (std::atan2(r.y(), r.x()) + math_constants::PI) / (math_constants::TWO_PI); // 0 .. 1
    const long sector = std::min(static_cast<long>(turn * sectors), sectors - 1);
    bin[i] = static_cast<long>((spheres[i].x.z() - z_lo) / diameter) * sectors + sector;
    double &most = farthest.emplace(bin[i], reach[i]).first->second;
    most = std::max(most, reach[i]);
  }
  std::vector<int> seeds;
  for (std::size_t i = 0; i < spheres.size(); ++i)
    if (reach[i] >= farthest[bin[i]] - depth) seeds.push_back(static_cast<int>(i));
  return seeds;
}

} // namespace membrane3d
