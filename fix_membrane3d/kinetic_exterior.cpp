#include "kinetic_exterior.h"

#include "flood_rules.h"

#include <algorithm>
#include <cmath>

namespace membrane3d {

namespace kinetic {

namespace {

// The round-off allowance of a link's test (exterior_flood.cpp's expression), relative
// to the distance and the threshold: far above a few ulps.
constexpr double kLinkRoundOff = 1e-9;


} // namespace

// The flood of exterior_flood.cpp, line for line (PowerFlood), over the kept cells;
// each cell's state keeps whether it is reached from outside, flooded and its group.
void Exterior::flood(Boundary &boundary)
{
  cells_.clear();
  for (auto c = t_.all_cells_begin(); c != t_.all_cells_end(); ++c) {
    c->info().index = static_cast<int>(cells_.size());
    c->info().serial = ++serial_;
    c->info().parent = -1;
    cells_.push_back(c);
  }
  flooded_.assign(cells_.size(), 0);
  flood_from_outside();
  for (Cell c : cells_) c->info().wet = flooded_[c->info().index];
  keep_largest_dry_group();
  for (Cell c : cells_) c->info().flooded = flooded_[c->info().index] != 0;
  boundary.facets.clear();
  for (Cell c : cells_) {
    if (flooded_[c->info().index]) continue;
    for (int k = 0; k < 4; ++k)
      if (flooded_[c->neighbor(k)->info().index] && !ignored_facet(c, k))
        boundary.facets.push_back(outward_facet(c, k));
  }
  for (auto &f : boundary.facets)
    std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
  std::sort(boundary.facets.begin(), boundary.facets.end());
  facets_ = std::set<std::array<int, 3>>(boundary.facets.begin(), boundary.facets.end());
  boundary.side = sides();
  valid_ = true;
  record_links();
}

// (the rules of flood_rules.h, at the present positions)
bool Exterior::wall(Cell c, int k) const
{
  return flood_rules::wall(t_, c, k, now_, sealed_, tolerance_);
}

bool Exterior::all_sealed(Cell c) const
{
  return flood_rules::all_sealed(t_, c, sealed_);
}

bool Exterior::ignored_facet(Cell c, int k) const
{
  return flood_rules::ignored_facet(t_, c, k, sealed_);
}

// (breadth first: a cell's way to the outside is short, so a change near the membrane
// cuts few ways; the reached cells are the same in any order)
void Exterior::flood_from_outside()
{
  std::vector<Cell> front;
  for (Cell c : cells_)
    if (t_.is_infinite(c) && !all_sealed(c)) {
      flooded_[c->info().index] = 1;
      c->info().parent = 4;
      front.push_back(c);
    }
  for (std::size_t head = 0; head < front.size(); ++head) {
    const Cell c = front[head];
    for (int k = 0; k < 4; ++k) {
      const Cell n = c->neighbor(k);
      if (flooded_[n->info().index] || all_sealed(n) || wall(c, k)) continue;
      flooded_[n->info().index] = 1;
      n->info().parent = static_cast<signed char>(n->index(c));
      front.push_back(n);
    }
  }
}

void Exterior::keep_largest_dry_group()
{
  std::vector<int> group(cells_.size(), -1);
  std::vector<long> size;
  for (Cell seed : cells_) {
    if (flooded_[seed->info().index] || group[seed->info().index] >= 0) continue;
    const int g = static_cast<int>(size.size());
    size.push_back(0);
    std::vector<Cell> front{seed};
    group[seed->info().index] = g;
    while (!front.empty()) {
      const Cell c = front.back();
      front.pop_back();
      if (!all_sealed(c)) ++size[g];
      for (int k = 0; k < 4; ++k) {
        const Cell n = c->neighbor(k);
        if (flooded_[n->info().index] || group[n->info().index] >= 0) continue;
        group[n->info().index] = g;
        front.push_back(n);
      }
    }
  }
  int keep = 0;
  for (std::size_t g = 1; g < size.size(); ++g)
    if (size[g] > size[keep]) keep = static_cast<int>(g);
  for (std::size_t i = 0; i < cells_.size(); ++i)
    if (!flooded_[i] && group[i] != keep) flooded_[i] = 1;
  kept_group_ = keep;
  size_ = size;
  for (Cell c : cells_) c->info().group = group[c->info().index];
}

std::array<int, 3> Exterior::outward_facet(Cell c, int k) const
{
  return flood_rules::outward_facet(c, k);
}

std::vector<Side> Exterior::sides() const
{
  std::vector<char> wet(now_.size(), 0), dry(now_.size(), 0);
  for (Cell c : cells_)
    for (int k = 0; k < 4; ++k) {
      const Vertex v = c->vertex(k);
      if (!finite(v)) continue;
      (flooded_[c->info().index] ? wet : dry)[v->info()] = 1;
    }
  std::vector<Side> side(now_.size(), Side::inside);
  for (std::size_t i = 0; i < now_.size(); ++i) {
    if (vertex_[i] == Vertex()) {
      const Cell c = t_.locate(weighted_point(now_[i]));
      side[i] = flooded_[c->info().index] ? Side::outside : Side::inside;
    } else if (wet[i]) {
      side[i] = dry[i] ? Side::surface : Side::outside;
    }
  }
  return side;
}

double Exterior::threshold(int a, int b) const
{
  return sealed_[a] || sealed_[b] ? 2 * tolerance_ : tolerance_;
}

// The edges of the facets of the cells reached from outside: the links the flood reads,
// anchored at the present positions (add_links with no motion from the anchor: its
// subtracted motion is +0, which leaves the slack as it is to the bit).
void Exterior::record_links()
{
  links_.clear();
  anchor_.resize(now_.size());
  for (std::size_t i = 0; i < now_.size(); ++i) anchor_[i] = now_[i].x;
  for (Cell c : cells_)
    if (c->info().wet == 1) add_links(c);
  links_recorded_ = links_.size();
}

void Exterior::begin_step()
{
  local_ = valid_;
  ++step_;
  orphan_roots_.clear();
  dry_next_.clear();
  removed_.clear();
  klass_.clear();
}

// The facet of c opposite k out of the membrane, in either orientation.
void Exterior::erase_facet(Cell c, int k)
{
  if (ignored_facet(c, k)) return;
  std::array<int, 3> f{c->vertex((k + 1) & 3)->info(), c->vertex((k + 2) & 3)->info(),
                       c->vertex((k + 3) & 3)->info()};
  for (int turn = 0; turn < 2; ++turn) {
    std::array<int, 3> g = f;
    std::rotate(g.begin(), std::min_element(g.begin(), g.end()), g.end());
    facets_.erase(g);
    std::swap(f[0], f[1]);
  }
}

// What the whole flood's state loses with the cell: its membrane facets, the way of the
// cells reached through it, a dry cell of its group (its dry neighbours: seeds).
void Exterior::destroying(Cell c)
{
  const CellState &s = c->info();
  if (!local_ || s.wet < 0 || s.serial == 0) return; // made this step: not counted
  for (int k = 0; k < 4; ++k) {
    const Cell n = c->neighbor(k);
    const CellState &m = n->info();
    if (m.wet < 0 || m.serial == 0) continue;
    if (m.flooded != s.flooded) erase_facet(c, k);
    if (s.wet == 1 && m.wet == 1 && m.parent >= 0 && m.parent < 4 && n->neighbor(m.parent) == c)
      orphan_roots_.emplace_back(n, m.serial);
    if (s.wet == 0 && m.wet == 0) {
      unite(s.serial, m.serial);
      dry_next_.emplace_back(n, m.serial);
    }
  }
  if (s.wet == 0 && !all_sealed(c)) ++removed_[s.group];
}

Side Exterior::side_of(int i) const
{
  if (vertex_[i] == Vertex())
    return t_.locate(weighted_point(now_[i]))->info().flooded ? Side::outside : Side::inside;
  std::vector<Cell> around;
  t_.incident_cells(vertex_[i], std::back_inserter(around));
  bool wet = false, dry = false;
  for (const Cell c : around) (c->info().flooded ? wet : dry) = true;
  return wet ? (dry ? Side::surface : Side::outside) : Side::inside;
}

// The edges of a reached cell's facets, to the links the flood reads, their status at
// the present positions: it holds while the motions from anchor_ sum below the slack
// (the present distance from the threshold less the motions from anchor_ so far).
void Exterior::add_links(Cell c)
{
  for (int k = 0; k < 4; ++k) {
    const Vertex v[3] = {c->vertex((k + 1) & 3), c->vertex((k + 2) & 3), c->vertex((k + 3) & 3)};
    for (int i = 0; i < 3; ++i) {
      const Vertex p = v[i], q = v[(i + 1) % 3];
      if (!finite(p) || !finite(q)) continue;
      const int a = std::min(p->info(), q->info()), b = std::max(p->info(), q->info());
      const Sphere &x = now_[a], &y = now_[b];
      const double distance = (x.x - y.x).norm(), gap = distance - x.r - y.r, t = threshold(a, b);
      const double moved = (x.x - anchor_[a]).norm() + (y.x - anchor_[b]).norm();
      links_.push_back(
          {a, b, std::abs(gap - t) - kLinkRoundOff * (distance + t) - moved, gap <= t});
    }
  }
}

} // namespace kinetic

} // namespace membrane3d
