#include "kinetic_triangulation.h"

#include "kinetic_margin.h"

#include <algorithm>

namespace membrane3d {

namespace kinetic {

namespace {

constexpr unsigned char kOrientation = 16;

} // namespace

// A failed certificate's points, five entries (-1: none): its cell's, the far vertex.
void Certifier::add_points(Cell c, int far, std::vector<int> &failed)
{
  for (int k = 0; k < 4; ++k) failed.push_back(c->vertex(k)->info());
  failed.push_back(far);
}

// A finite cell is positively oriented.
// Whether certificate k of c (0-3: the facet opposite vertex k, as facet() tests it;
// 4: the orientation) keeps its sign while its points stay within delta of `at`.
bool Certifier::margin_of(Cell c, int k, const std::vector<Sphere> &at, double delta,
                          bool *by_mirror) const
{
  *by_mirror = false;
  std::array<const Sphere *, 4> finite{};
  int m = 0;
  for (int j = 0; j < 4; ++j)
    if (!t_.is_infinite(c->vertex(j))) finite[m++] = &at[c->vertex(j)->info()];
  if (k == 4) return orientation_margin({finite[0], finite[1], finite[2], finite[3]}, delta);
  const Cell n = c->neighbor(k);
  const Vertex far = n->vertex(n->index(c));
  const Sphere &p = at[far->info()];
  if (t_.is_infinite(c)) return orientation_margin({finite[0], finite[1], finite[2], &p}, delta);
  if (mirrors_ && symmetric_) {
    const std::array<int, 4> v{c->vertex(0)->info(), c->vertex(1)->info(), c->vertex(2)->info(),
                               c->vertex(3)->info()};
    *by_mirror = mirror_zero(v, far->info());
    const auto &f = mirrors_->family;
    if (*by_mirror)
      return perturbed_margin({finite[0], finite[1], finite[2], finite[3], &p},
                              {f[v[0]], f[v[1]], f[v[2]], f[v[3]], f[far->info()]}, delta);
  }
  return power_margin({finite[0], finite[1], finite[2], finite[3], &p}, delta);
}

// The motion from the present positions within which certificate k of c keeps its sign
// (margin_of's bounds at the present positions): at most `most`, within a factor of 2
// of the bounds' best (kinetic_margin.h), or 0.
double Certifier::reach_of(Cell c, int k, double most) const
{
  std::array<const Sphere *, 4> finite{};
  int m = 0;
  for (int j = 0; j < 4; ++j)
    if (!t_.is_infinite(c->vertex(j))) finite[m++] = &now_[c->vertex(j)->info()];
  if (k == 4) return orientation_reach({finite[0], finite[1], finite[2], finite[3]}, most);
  const Cell n = c->neighbor(k);
  const Vertex far = n->vertex(n->index(c));
  const Sphere &p = now_[far->info()];
  if (t_.is_infinite(c)) return orientation_reach({finite[0], finite[1], finite[2], &p}, most);
  if (mirrors_ && symmetric_) {
    const std::array<int, 4> v{c->vertex(0)->info(), c->vertex(1)->info(), c->vertex(2)->info(),
                               c->vertex(3)->info()};
    if (mirror_zero(v, far->info())) { // the perturbed test: its tiers
      bool by_mirror = false;
      for (double r = most; r >= most / 64; r /= 8)
        if (margin_of(c, k, now_, r, &by_mirror)) return r;
      return 0;
    }
  }
  return power_reach({finite[0], finite[1], finite[2], finite[3], &p}, most);
}

// The motion from the present positions within which the cell's certificates without
// a margin keep their signs (the least of their reaches, at most budget / 2), or 0.
double Certifier::reach(Cell c) const
{
  double r = budget_ / 2;
  const unsigned char tight = c->info().tight;
  for (int k = 0; k < 5 && r > 0; ++k)
    if ((tight >> k) & 1) r = std::min(r, reach_of(c, k, r));
  return r;
}

// The present positions of the cell's points and of its neighbours' far vertices.
void Certifier::anchor(Cell c)
{
  CellState &s = c->info();
  if (s.anchor < 0) {
    s.anchor = static_cast<int>(anchors_.size());
    anchors_.emplace_back();
  }
  Anchor &a = anchors_[s.anchor];
  for (int j = 0; j < 4; ++j) {
    const Vertex v = c->vertex(j);
    a.point[j] = t_.is_infinite(v) ? -1 : v->info();
    const Cell n = c->neighbor(j);
    const Vertex far = n->vertex(n->index(c));
    a.point[4 + j] = t_.is_infinite(far) ? -1 : far->info();
  }
  for (int j = 0; j < 8; ++j)
    if (a.point[j] >= 0) a.x[j] = now_[a.point[j]].x;
  a.reach = symmetric_ || !mirrors_ ? reach(c) : 0.0;
}

// Whether the cell's points are all still within its reach of its anchor.
bool Certifier::within_reach(Cell c) const
{
  const int slot = c->info().anchor;
  if (slot < 0) return false;
  const Anchor &a = anchors_[slot];
  if (!(a.reach > 0) || (mirrors_ && !symmetric_)) return false;
  const double r2 = a.reach * a.reach;
  for (int j = 0; j < 8; ++j)
    if (a.point[j] >= 0 && (now_[a.point[j]].x - a.x[j]).squaredNorm() >= r2) return false;
  return true;
}

int Certifier::orientation(Cell c, bool *margin)
{
  ++stats_.evaluated;
  const auto o = CGAL::orientation(c->vertex(0)->point().point(), c->vertex(1)->point().point(),
                                   c->vertex(2)->point().point(), c->vertex(3)->point().point());
  if (o != CGAL::POSITIVE) return 0;
  if (margin) {
    ++stats_.classified;
    bool by_mirror = false;
    *margin = margin_of(c, 4, reference_, budget_, &by_mirror);
  }
  return 1;
}

// The facet of c opposite vertex k is locally regular: the far vertex of the neighbour
// outside c's power sphere (CGAL's side_of_power_sphere with its perturbation; for two
// cells at infinity, on the inner side of c's hull facet or, coplanar, outside its
// power circle). Between a finite cell and one at infinity: the finite cell's
// orientation, not here.
// p mirrors one of `cell` in a platen in which two others of it mirror each other: the
// power test is zero (flood_watch.cpp).
bool Certifier::mirror_zero(const std::array<int, 4> &cell, int p) const
{
  const auto &f = mirrors_->family, &z = mirrors_->plane;
  auto mirrors = [&f, &z](int a, int b, int plane) {
    return f[a] == f[b] && ((z[a] == 0 && z[b] == plane) || (z[b] == 0 && z[a] == plane));
  };
  for (int plane : {-1, 1})
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) {
        if (!mirrors(cell[i], cell[j], plane)) continue;
        for (int k = 0; k < 4; ++k)
          if (k != i && k != j && mirrors(cell[k], p, plane)) return true;
      }
  return false;
}

int Certifier::facet(Cell c, int k, bool *margin, bool *by_mirror)
{
  const Cell n = c->neighbor(k);
  const Vertex far = n->vertex(n->index(c));
  const bool c_infinite = t_.is_infinite(c);
  if (t_.is_infinite(far) || c_infinite != t_.is_infinite(n)) return 1;
  ++stats_.evaluated;
  if (c_infinite) {
    // a collinear hull facet (CGAL's power segment) is in no regular triangulation: the
    // finite cell on it is flat
    int i3 = c->index(t_.infinite_vertex());
    const auto &a = c->vertex((i3 + 1) & 3)->point(), &b = c->vertex((i3 + 2) & 3)->point(),
               &d = c->vertex((i3 + 3) & 3)->point();
    if (CGAL::orientation(a.point(), b.point(), d.point(), far->point().point()) ==
            CGAL::COPLANAR &&
        CGAL::coplanar_orientation(a.point(), b.point(), d.point()) == CGAL::COLLINEAR)
      return 0;
  } else if (CGAL::orientation(c->vertex(0)->point().point(), c->vertex(1)->point().point(),
                               c->vertex(2)->point().point(),
                               c->vertex(3)->point().point()) != CGAL::POSITIVE) {
    return 0; // a flat cell has no power sphere
  }
  if (t_.side_of_power_sphere(c, far->point(), true) != CGAL::ON_UNBOUNDED_SIDE) return 0;
  if (margin) {
    ++stats_.classified;
    *margin = margin_of(c, k, reference_, budget_, by_mirror);
  }
  return 1;
}

bool Certifier::pass(long step, const std::vector<long> &moved, std::vector<int> &failed)
{
  listed_.clear();
  anchors_.clear();
  for (auto c = t_.all_cells_begin(); c != t_.all_cells_end(); ++c) {
    c->info().listed = false;
    c->info().anchor = -1;
    if (!visit(c, step, moved, failed)) return false;
  }
  tight_ = static_cast<long>(listed_.size());
  return true;
}

bool Certifier::visit_tight(long step, const std::vector<long> &moved, std::vector<int> &failed)
{
  // a listed cell within its reach has nothing to evaluate here: its moved points'
  // certificates and its changed facets are visited around them (visit_around)
  for (std::size_t k = 0; k < listed_.size(); ++k) // (visit may add to it)
    if (t_.tds().cells().is_used(listed_[k].first) &&
        listed_[k].first->info().id == listed_[k].second &&
        (listed_[k].first->info().mirror != 0 || !within_reach(listed_[k].first)) &&
        !visit(listed_[k].first, step, moved, failed))
      return false;
  return true;
}

bool Certifier::visit_around(const std::vector<Vertex> &vertices, long step,
                             const std::vector<long> &moved, std::vector<int> &failed)
{
  std::vector<Cell> around;
  for (const Vertex v : vertices) {
    around.clear();
    t_.incident_cells(v, std::back_inserter(around));
    for (const Cell c : around) {
      if (!visit(c, step, moved, failed)) return false;
      for (int k = 0; k < 4; ++k)
        if (!visit(c->neighbor(k), step, moved, failed)) return false;
    }
  }
  return true;
}

void Certifier::compact()
{
  std::vector<Anchor> anchors;
  std::size_t kept = 0;
  for (auto &entry : listed_) {
    const bool alive =
        t_.tds().cells().is_used(entry.first) && entry.first->info().id == entry.second;
    if (!alive) continue;
    CellState &s = entry.first->info();
    if (s.tight == 0 && s.mirror == 0) {
      s.listed = false;
      s.anchor = -1;
      continue;
    }
    if (s.anchor >= 0) {
      anchors.push_back(anchors_[s.anchor]);
      s.anchor = static_cast<int>(anchors.size()) - 1;
    }
    listed_[kept++] = entry;
  }
  listed_.resize(kept);
  anchors_.swap(anchors);
  tight_ = static_cast<long>(kept);
}

bool Certifier::visit(Cell c, long step, const std::vector<long> &moved, std::vector<int> &failed)
{
  {
    CellState &s = c->info();
    const bool fresh = !s.seen; // (its id may come from a neighbour's visit)
    if (s.id == 0) s.id = ++next_id_;
    s.seen = true;
    // not yet evaluated at this step, and (for the certificates without a margin) its
    // points not within the reach of their last evaluation
    const bool again = s.evaluated != step;
    const bool tight_again = again && !within_reach(c);
    bool evaluated = false;
    bool moved_cell = false;
    for (int j = 0; j < 4; ++j) {
      const int v = c->vertex(j)->info();
      if (v >= 0 && moved[v] == step && !t_.is_infinite(c->vertex(j))) moved_cell = true;
    }
    const bool finite = !t_.is_infinite(c);
    if (finite && (fresh || (again && moved_cell) || (tight_again && (s.tight & kOrientation)))) {
      evaluated = true;
      bool margin = false;
      const bool decide = fresh || moved_cell;
      if (orientation(c, decide ? &margin : nullptr) != 1) {
        ++stats_.failed;
        add_points(c, -1, failed);
      }
      if (decide) s.tight = margin ? (s.tight & ~kOrientation) : (s.tight | kOrientation);
    }
    for (int k = 0; k < 4; ++k) {
      Cell n = c->neighbor(k);
      if (n->info().id == 0) n->info().id = ++next_id_;
      const unsigned nid = n->info().id;
      const bool changed = fresh || s.neighbour_id[k] != nid;
      s.neighbour_id[k] = nid;
      const unsigned char bit = static_cast<unsigned char>(1u << k);
      if (s.id > nid) { // the neighbour owns the facet
        s.tight &= static_cast<unsigned char>(~bit);
        s.mirror &= static_cast<unsigned char>(~bit);
        continue;
      }
      const Vertex far = n->vertex(n->index(c));
      const bool moved_far = !t_.is_infinite(far) && moved[far->info()] == step;
      const bool decide = changed || (again && (moved_cell || moved_far));
      if (!decide && !(again && (s.mirror & bit) && !symmetric_) &&
          !(tight_again && (s.tight & bit)))
        continue;
      evaluated = true;
      bool margin = false, by_mirror = false;
      const int holds = facet(c, k, decide ? &margin : nullptr, &by_mirror);
      if (holds < 0) return false;
      if (holds == 0) {
        ++stats_.failed;
        add_points(c, t_.is_infinite(far) ? -1 : far->info(), failed);
      }
      if (decide) {
        s.tight = margin ? (s.tight & static_cast<unsigned char>(~bit)) : (s.tight | bit);
        s.mirror =
            margin && by_mirror ? (s.mirror | bit) : (s.mirror & static_cast<unsigned char>(~bit));
      }
    }
    s.evaluated = step;
    if (s.tight != 0 && (evaluated || s.anchor < 0)) anchor(c);
    if ((s.tight != 0 || s.mirror != 0) && !s.listed) {
      s.listed = true;
      listed_.emplace_back(c, s.id);
    }
  }
  return true;
}

} // namespace kinetic

} // namespace membrane3d
