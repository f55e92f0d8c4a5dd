#include "kinetic_exterior.h"

#include <algorithm>
#include <cmath>

namespace membrane3d {

namespace kinetic {

namespace {

// The round-off allowance of a link's test (exterior_flood.cpp's expression), relative
// to the distance and the threshold: far above a few ulps.
constexpr double kLinkRoundOff = 1e-9;

// Where the flood has not been kept on the last two steps, the links are followed after
// one whole flood in this many.
constexpr int kRetry = 8;

} // namespace

// The flood of exterior_flood.cpp, line for line (PowerFlood), over the kept cells;
// each cell's state keeps whether it is reached from outside, flooded and its group.
void Exterior::flood(Boundary &boundary)
{
  cells_.clear();
  for (auto c = t_.all_cells_begin(); c != t_.all_cells_end(); ++c) {
    c->info().index = static_cast<int>(cells_.size());
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
  boundary.side = sides();
  // following the links costs about a whole flood's links: where the flood has not been
  // kept lately (the repairs cross the membrane), only every kRetry floods
  valid_ = misses_ < 2 || ++retry_ % kRetry == 0;
  if (valid_) record_links();
}

bool Exterior::linked(Vertex a, Vertex b) const
{
  const bool across = sealed_[a->info()] || sealed_[b->info()];
  const Sphere &p = now_[a->info()], &q = now_[b->info()];
  return (p.x - q.x).norm() - p.r - q.r <= (across ? 2 * tolerance_ : tolerance_);
}

bool Exterior::wall(Cell c, int k) const
{
  const Vertex a = c->vertex((k + 1) & 3), b = c->vertex((k + 2) & 3), d = c->vertex((k + 3) & 3);
  return finite(a) && finite(b) && finite(d) && linked(a, b) && linked(b, d) && linked(a, d);
}

bool Exterior::all_sealed(Cell c) const
{
  for (int k = 0; k < 4; ++k) {
    const Vertex v = c->vertex(k);
    if (finite(v) && !sealed_[v->info()]) return false;
  }
  return true;
}

bool Exterior::ignored_facet(Cell c, int k) const
{
  bool any_unsealed = false;
  for (int j = 1; j < 4; ++j) {
    const Vertex v = c->vertex((k + j) & 3);
    if (!finite(v)) return true;
    any_unsealed = any_unsealed || !sealed_[v->info()];
  }
  return !any_unsealed;
}

void Exterior::flood_from_outside()
{
  std::vector<Cell> front;
  for (Cell c : cells_)
    if (t_.is_infinite(c) && !all_sealed(c)) {
      flooded_[c->info().index] = 1;
      front.push_back(c);
    }
  while (!front.empty()) {
    const Cell c = front.back();
    front.pop_back();
    for (int k = 0; k < 4; ++k) {
      const Cell n = c->neighbor(k);
      if (flooded_[n->info().index] || all_sealed(n) || wall(c, k)) continue;
      flooded_[n->info().index] = 1;
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
  kept_size_ = size.empty() ? 0 : size[keep];
  other_size_ = 0;
  for (std::size_t g = 0; g < size.size(); ++g)
    if (static_cast<int>(g) != keep) other_size_ = std::max(other_size_, size[g]);
  for (Cell c : cells_) c->info().group = group[c->info().index];
}

std::array<int, 3> Exterior::outward_facet(Cell c, int k) const
{
  Vertex a = c->vertex((k + 1) & 3), b = c->vertex((k + 2) & 3);
  const Vertex d = c->vertex((k + 3) & 3), inner = c->vertex(k);
  if (CGAL::orientation(a->point().point(), b->point().point(), d->point().point(),
                        inner->point().point()) == CGAL::POSITIVE)
    std::swap(a, b);
  return {a->info(), b->info(), d->info()};
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

// The edges of the facets of the cells reached from outside: the links the flood reads.
void Exterior::record_links()
{
  links_.clear();
  for (Cell c : cells_) {
    if (c->info().wet != 1) continue;
    for (int k = 0; k < 4; ++k) {
      const Vertex v[3] = {c->vertex((k + 1) & 3), c->vertex((k + 2) & 3), c->vertex((k + 3) & 3)};
      for (int i = 0; i < 3; ++i) {
        const Vertex p = v[i], q = v[(i + 1) % 3];
        if (!finite(p) || !finite(q)) continue;
        const int a = std::min(p->info(), q->info()), b = std::max(p->info(), q->info());
        const Sphere &x = now_[a], &y = now_[b]; // (the anchor)
        const double distance = (x.x - y.x).norm(), gap = distance - x.r - y.r;
        const double t = threshold(a, b);
        links_.push_back({a, b, std::abs(gap - t) - kLinkRoundOff * (distance + t), gap <= t});
      }
    }
  }
  anchor_.resize(now_.size());
  for (std::size_t i = 0; i < now_.size(); ++i) anchor_[i] = now_[i].x;
}

// Whether every link the flood reads has its status of the last whole flood.
bool Exterior::links_hold() const
{
  std::vector<double> moved(now_.size());
  for (std::size_t i = 0; i < now_.size(); ++i) moved[i] = (now_[i].x - anchor_[i]).norm();
  for (const Link &l : links_) {
    if (moved[l.a] + moved[l.b] < l.slack) continue;
    const Sphere &p = now_[l.a], &q = now_[l.b];
    // the expression of the flood's test, to the last bit
    if (((p.x - q.x).norm() - p.r - q.r <= threshold(l.a, l.b)) != l.linked) return false;
  }
  return true;
}

void Exterior::destroying(Cell c)
{
  const CellState &s = c->info();
  if (!local_ || s.wet < 0) return; // made this step: not counted
  const int mode = s.wet == 1 ? 1 : s.group == kept_group_ ? 2 : 0;
  if (mode == 0 || (mode_ != 0 && mode != mode_)) {
    local_ = false;
    return;
  }
  mode_ = mode;
  if (mode == 2 && !all_sealed(c)) --kept_delta_;
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

// The cells made this step, marked (wet -2): around the touched spheres (every cell made
// by an insertion or removal is around the hole's or the inserted sphere's vertex).
std::vector<Cell> Exterior::made(const std::vector<int> &touched) const
{
  std::vector<Cell> out, around;
  for (int i : touched) {
    if (vertex_[i] == Vertex()) continue;
    around.clear();
    t_.incident_cells(vertex_[i], std::back_inserter(around));
    for (const Cell c : around)
      if (c->info().wet == -1) {
        c->info().wet = -2;
        out.push_back(c);
      }
  }
  return out;
}

// Dry: the made cells fill dry cells of the sample's group, reached from no cell.
bool Exterior::made_dry(const std::vector<Cell> &made)
{
  for (const Cell c : made) {
    if (t_.is_infinite(c) && !all_sealed(c)) return false; // a new way in
    for (int k = 0; k < 4; ++k) {
      const Cell n = c->neighbor(k);
      const CellState &m = n->info();
      if (m.wet == -2) continue;
      if (m.wet == 0 && m.group != kept_group_) return false; // (not so: checked)
      if (m.wet == 1 && !all_sealed(c) && !wall(n, n->index(c))) return false;
    }
    if (!all_sealed(c)) ++kept_delta_;
  }
  if (kept_size_ + kept_delta_ <= other_size_) return false;
  kept_size_ += kept_delta_;
  for (const Cell c : made) {
    c->info().wet = 0;
    c->info().group = kept_group_;
    c->info().flooded = false;
  }
  return true;
}

// Reached: the made cells fill reached cells; none is all sealed, none has a wall
// between two of them (so that a way through the destroyed cells goes through them),
// each is reached, none lets the flood into a dry cell.
bool Exterior::made_reached(const std::vector<Cell> &made)
{
  std::vector<Cell> front;
  for (const Cell c : made) {
    if (all_sealed(c)) return false;
    bool seed = t_.is_infinite(c);
    for (int k = 0; k < 4; ++k) {
      const Cell n = c->neighbor(k);
      const CellState &m = n->info();
      const bool w = wall(c, k);
      if (m.wet == -2 && w) return false;
      if (m.wet == 1 && !w) seed = true;
      if (m.wet == 0 && !w && !all_sealed(n)) return false;
    }
    if (seed) front.push_back(c);
  }
  for (const Cell c : front) c->info().wet = 1;
  while (!front.empty()) {
    const Cell c = front.back();
    front.pop_back();
    for (int k = 0; k < 4; ++k) {
      const Cell n = c->neighbor(k);
      if (n->info().wet != -2) continue;
      n->info().wet = 1;
      front.push_back(n);
    }
  }
  for (const Cell c : made)
    if (c->info().wet != 1) return false;
  for (const Cell c : made) {
    c->info().flooded = true;
    c->info().group = -1;
    add_links(c);
  }
  return true;
}

// The edges of a reached cell's facets, to the links the flood reads.
void Exterior::add_links(Cell c)
{
  for (int k = 0; k < 4; ++k) {
    const Vertex v[3] = {c->vertex((k + 1) & 3), c->vertex((k + 2) & 3), c->vertex((k + 3) & 3)};
    for (int i = 0; i < 3; ++i) {
      const Vertex p = v[i], q = v[(i + 1) % 3];
      if (!finite(p) || !finite(q)) continue;
      const int a = std::min(p->info(), q->info()), b = std::max(p->info(), q->info());
      // at the positions of the last whole flood, as the others
      const double distance = (anchor_[a] - anchor_[b]).norm();
      const double gap = distance - now_[a].r - now_[b].r, t = threshold(a, b);
      links_.push_back({a, b, std::abs(gap - t) - kLinkRoundOff * (distance + t), gap <= t});
    }
  }
}

bool Exterior::update(const std::vector<int> &touched, Boundary &out)
{
  if (!local_) {
    if (valid_) ++misses_;
    return false;
  }
  const std::vector<Cell> cells = made(touched);
  const bool kept = (mode_ == 1 ? made_reached(cells) : made_dry(cells)) && links_hold();
  misses_ = kept ? 0 : misses_ + 1;
  if (!kept) return false; // (the whole flood sets every cell's state)
  for (std::size_t i = 0; i < now_.size(); ++i)
    if (vertex_[i] == Vertex()) out.side[i] = side_of(static_cast<int>(i));
  for (int i : touched) out.side[i] = side_of(i);
  return true;
}

} // namespace kinetic

} // namespace membrane3d
