#include "exterior_flood.h"

#include "flood_rules.h"
#include "number_text.h"
#include "power_flood.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace membrane3d {

using power::Cell;
using power::Vertex;

void check_spheres(const std::vector<Sphere> &spheres)
{
  for (std::size_t i = 0; i < spheres.size(); ++i)
    if (!(spheres[i].r > 0) || !spheres[i].x.allFinite())
      throw std::invalid_argument("sphere " + std::to_string(i) + " has radius " +
                                  number_text(spheres[i].r) + " or a centre that is not finite");
}

void check_flood_input(const std::vector<Sphere> &spheres, const std::vector<bool> &sealed,
                       double tolerance)
{
  if (spheres.size() < 4)
    throw std::invalid_argument(count_text(spheres.size(), "sphere", "spheres") +
                                ": a surface needs at least four");
  if (sealed.size() != spheres.size())
    throw std::invalid_argument("sealed flags for " + std::to_string(sealed.size()) + " of " +
                                std::to_string(spheres.size()) + " spheres");
  if (!std::isfinite(tolerance) || tolerance < 0)
    throw std::invalid_argument("tolerance " + number_text(tolerance) +
                                ": must be a finite length >= 0");
  check_spheres(spheres);
}

namespace {

// Centres within this RMS distance of one plane, in mean radii, span no volume that a
// membrane could wrap (a one-sphere-thick wall jittered by 1e-3 d is 6e-4 r thick; a
// sample two spheres across is about r thick).
constexpr double kFlatRms = 0.1;

} // namespace

FlatTest flat_test(const std::vector<Sphere> &spheres)
{
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  double r = 0;
  for (const Sphere &s : spheres) {
    mean += s.x;
    r += s.r;
  }
  const double n = static_cast<double>(spheres.size());
  mean /= n;
  r /= n;
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const Sphere &s : spheres) covariance += (s.x - mean) * (s.x - mean).transpose() / n;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(covariance, Eigen::EigenvaluesOnly);
  return {eigen.eigenvalues(), kFlatRms * kFlatRms * r * r};
}

namespace {

// "in one plane" or "on one line" when the spheres' centres (with their images) lie
// within kFlatRms of one, else "".
std::string flatness(const std::vector<Sphere> &spheres)
{
  const FlatTest t = flat_test(spheres);
  if (t.eigenvalues[1] <= t.limit) return "on one line";
  if (t.eigenvalues[0] <= t.limit) return "in one plane";
  return "";
}

[[noreturn]] void flat_sample(const std::vector<Sphere> &spheres, const std::vector<bool> &sealed,
                              const std::string &where)
{
  const auto images = static_cast<std::size_t>(std::count(sealed.begin(), sealed.end(), true));
  throw FlatSample("the " + count_text(spheres.size() - images, "sphere", "spheres") +
                   (images > 0 ? " and their " + count_text(images, "image", "images") +
                                     " in the platens"
                               : std::string()) +
                   " lie " + where + ": they enclose no volume for a membrane to wrap");
}

} // namespace

PowerFlood::PowerFlood(const std::vector<Sphere> &spheres, const std::vector<bool> &sealed,
                       double tolerance)
  : spheres_(spheres), sealed_(sealed), tolerance_(tolerance)
{
  const std::string flat = flatness(spheres);
  if (!flat.empty()) flat_sample(spheres, sealed, flat);
  std::vector<std::pair<power::K::Weighted_point_3, int>> points;
  points.reserve(spheres.size());
  for (std::size_t i = 0; i < spheres.size(); ++i)
    points.emplace_back(power::weighted_point(spheres[i]), static_cast<int>(i));
  triangulation_.insert(points.begin(), points.end());
  if (triangulation_.dimension() < 3)
    flat_sample(spheres, sealed, triangulation_.dimension() < 2 ? "on one line" : "in one plane");
  for (auto c = triangulation_.all_cells_begin(); c != triangulation_.all_cells_end(); ++c) {
    c->info() = static_cast<int>(cells_.size());
    cells_.push_back(c);
  }
  flooded_.assign(cells_.size(), 0);
  flood_from_outside();
  keep_largest_dry_group();
}

Boundary PowerFlood::boundary(FloodCells *cells) const
{
  Boundary b;
  for (Cell c : cells_) {
    if (flooded_[c->info()]) continue;
    for (int k = 0; k < 4; ++k)
      if (flooded_[c->neighbor(k)->info()] && !ignored_facet(c, k))
        b.facets.push_back(flood_rules::outward_facet(c, k));
  }
  for (auto &f : b.facets) std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
  std::sort(b.facets.begin(), b.facets.end());
  b.side = sides(cells);
  if (cells) export_cells(*cells);
  return b;
}

void PowerFlood::export_cells(FloodCells &out) const
{
  out.vertex.resize(cells_.size());
  out.neighbour.resize(cells_.size());
  for (Cell c : cells_)
    for (int k = 0; k < 4; ++k) {
      const Vertex v = c->vertex(k);
      out.vertex[c->info()][k] = finite(v) ? v->info() : -1;
      out.neighbour[c->info()][k] = c->neighbor(k)->info();
    }
  out.flooded = flooded_;
  out.kept_group = kept_group_;
  out.other_group = other_group_;
}

// (the rules of flood_rules.h)
bool PowerFlood::wall(Cell c, int k) const
{
  return flood_rules::wall(triangulation_, c, k, spheres_, sealed_, tolerance_);
}

bool PowerFlood::all_sealed(Cell c) const
{
  return flood_rules::all_sealed(triangulation_, c, sealed_);
}

bool PowerFlood::ignored_facet(Cell c, int k) const
{
  return flood_rules::ignored_facet(triangulation_, c, k, sealed_);
}

void PowerFlood::flood_from_outside()
{
  std::vector<Cell> front;
  for (Cell c : cells_)
    if (triangulation_.is_infinite(c) && !all_sealed(c)) {
      flooded_[c->info()] = 1;
      front.push_back(c);
    }
  while (!front.empty()) {
    const Cell c = front.back();
    front.pop_back();
    for (int k = 0; k < 4; ++k) {
      const Cell n = c->neighbor(k);
      if (flooded_[n->info()] || all_sealed(n) || wall(c, k)) continue;
      flooded_[n->info()] = 1;
      front.push_back(n);
    }
  }
}

// Unflooded cells in groups joined by facets; all but the group with the most cells
// that hold an unsealed sphere are flooded (lowest group first among equals).
void PowerFlood::keep_largest_dry_group()
{
  std::vector<int> group(cells_.size(), -1);
  std::vector<long> size;
  for (Cell seed : cells_) {
    if (flooded_[seed->info()] || group[seed->info()] >= 0) continue;
    const int g = static_cast<int>(size.size());
    size.push_back(0);
    std::vector<Cell> front{seed};
    group[seed->info()] = g;
    while (!front.empty()) {
      const Cell c = front.back();
      front.pop_back();
      if (!all_sealed(c)) ++size[g];
      for (int k = 0; k < 4; ++k) {
        const Cell n = c->neighbor(k);
        if (flooded_[n->info()] || group[n->info()] >= 0) continue;
        group[n->info()] = g;
        front.push_back(n);
      }
    }
  }
  int keep = 0;
  for (std::size_t g = 1; g < size.size(); ++g)
    if (size[g] > size[keep]) keep = static_cast<int>(g);
  for (std::size_t g = 0; g < size.size(); ++g)
    if (static_cast<int>(g) == keep)
      kept_group_ = size[g];
    else
      other_group_ = std::max(other_group_, size[g]);
  for (std::size_t i = 0; i < cells_.size(); ++i)
    if (!flooded_[i] && group[i] != keep) flooded_[i] = 1;
}

// Per sphere: on the membrane when its cells are both flooded and not, outside when
// all are flooded. A sphere hidden by the power triangulation (inside the power balls
// of its neighbours) takes the side of the cell that contains its centre.
// With `cells`, the spheres that are no vertex and their cells go to it.
std::vector<Side> PowerFlood::sides(FloodCells *cells) const
{
  std::vector<char> wet(spheres_.size(), 0), dry(spheres_.size(), 0), seen(spheres_.size(), 0);
  for (Cell c : cells_)
    for (int k = 0; k < 4; ++k) {
      const Vertex v = c->vertex(k);
      if (!finite(v)) continue;
      seen[v->info()] = 1;
      (flooded_[c->info()] ? wet : dry)[v->info()] = 1;
    }
  std::vector<Side> side(spheres_.size(), Side::inside);
  for (std::size_t i = 0; i < spheres_.size(); ++i) {
    if (!seen[i]) {
      const Cell c = triangulation_.locate(power::weighted_point(spheres_[i]));
      side[i] = flooded_[c->info()] ? Side::outside : Side::inside;
      if (cells) {
        cells->hidden.push_back(static_cast<int>(i));
        cells->hidden_cell.push_back(c->info());
      }
    } else if (wet[i]) {
      side[i] = dry[i] ? Side::surface : Side::outside;
    }
  }
  return side;
}

Boundary exterior_boundary(const std::vector<Sphere> &spheres, const std::vector<bool> &sealed,
                           double tolerance, FloodCells *cells)
{
  check_flood_input(spheres, sealed, tolerance);
  if (cells) *cells = FloodCells();
  return PowerFlood(spheres, sealed, tolerance).boundary(cells);
}

} // namespace membrane3d
