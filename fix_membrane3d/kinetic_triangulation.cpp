#include "kinetic_triangulation.h"

#include "kinetic_margin.h"

namespace membrane3d {

namespace kinetic {

namespace {

constexpr unsigned char kOrientation = 16;

} // namespace

void Certifier::add_points(Cell c, std::vector<int> &failed)
{
  for (int k = 0; k < 4; ++k)
    if (c->vertex(k)->info() >= 0) failed.push_back(c->vertex(k)->info());
}

// A finite cell is positively oriented.
int Certifier::orientation(Cell c, bool *margin)
{
  ++stats_.evaluated;
  const auto o = CGAL::orientation(c->vertex(0)->point().point(), c->vertex(1)->point().point(),
                                   c->vertex(2)->point().point(), c->vertex(3)->point().point());
  if (o != CGAL::POSITIVE) return 0;
  if (margin) {
    ++stats_.classified;
    *margin =
        orientation_margin({&reference_[c->vertex(0)->info()], &reference_[c->vertex(1)->info()],
                            &reference_[c->vertex(2)->info()], &reference_[c->vertex(3)->info()]},
                           budget_);
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
  std::array<const Sphere *, 4> finite{};
  int m = 0;
  for (int j = 0; j < 4; ++j)
    if (!t_.is_infinite(c->vertex(j))) finite[m++] = &reference_[c->vertex(j)->info()];
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
    const Sphere &p = reference_[far->info()];
    *by_mirror = false;
    if (c_infinite) {
      *margin = orientation_margin({finite[0], finite[1], finite[2], &p}, budget_);
    } else if (mirrors_ && symmetric_) {
      const std::array<int, 4> v{c->vertex(0)->info(), c->vertex(1)->info(), c->vertex(2)->info(),
                                 c->vertex(3)->info()};
      *by_mirror = mirror_zero(v, far->info());
      const auto &f = mirrors_->family;
      *margin =
          *by_mirror
              ? perturbed_margin({finite[0], finite[1], finite[2], finite[3], &p},
                                 {f[v[0]], f[v[1]], f[v[2]], f[v[3]], f[far->info()]}, budget_)
              : power_margin({finite[0], finite[1], finite[2], finite[3], &p}, budget_);
    } else {
      *margin = power_margin({finite[0], finite[1], finite[2], finite[3], &p}, budget_);
    }
  }
  return 1;
}

bool Certifier::pass(long step, const std::vector<long> &moved, std::vector<int> &failed)
{
  listed_.clear();
  for (auto c = t_.all_cells_begin(); c != t_.all_cells_end(); ++c) {
    c->info().listed = false;
    if (!visit(c, step, moved, failed)) return false;
  }
  tight_ = static_cast<long>(listed_.size());
  return true;
}

bool Certifier::visit_tight(long step, const std::vector<long> &moved, std::vector<int> &failed)
{
  for (std::size_t k = 0; k < listed_.size(); ++k) // (visit may add to it)
    if (t_.tds().cells().is_used(listed_[k].first) &&
        listed_[k].first->info().id == listed_[k].second &&
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
  std::size_t kept = 0;
  for (auto &entry : listed_) {
    const bool alive =
        t_.tds().cells().is_used(entry.first) && entry.first->info().id == entry.second;
    if (!alive) continue;
    CellState &s = entry.first->info();
    if (s.tight == 0 && s.mirror == 0) {
      s.listed = false;
      continue;
    }
    listed_[kept++] = entry;
  }
  listed_.resize(kept);
  tight_ = static_cast<long>(kept);
}

bool Certifier::visit(Cell c, long step, const std::vector<long> &moved, std::vector<int> &failed)
{
  {
    CellState &s = c->info();
    const bool fresh = s.id == 0;
    if (fresh) s.id = ++next_id_;
    const bool again = s.evaluated != step; // not yet evaluated at this step
    bool moved_cell = false;
    for (int j = 0; j < 4; ++j) {
      const int v = c->vertex(j)->info();
      if (v >= 0 && moved[v] == step && !t_.is_infinite(c->vertex(j))) moved_cell = true;
    }
    const bool finite = !t_.is_infinite(c);
    if (finite && (fresh || (again && (moved_cell || (s.tight & kOrientation))))) {
      bool margin = false;
      const bool decide = fresh || moved_cell;
      if (orientation(c, decide ? &margin : nullptr) != 1) {
        ++stats_.failed;
        add_points(c, failed);
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
      const bool unsafe = (s.tight & bit) || (!symmetric_ && (s.mirror & bit));
      if (!decide && !(again && unsafe)) continue;
      bool margin = false, by_mirror = false;
      const int holds = facet(c, k, decide ? &margin : nullptr, &by_mirror);
      if (holds < 0) return false;
      if (holds == 0) {
        ++stats_.failed;
        add_points(c, failed);
        if (!t_.is_infinite(far)) failed.push_back(far->info());
      }
      if (decide) {
        s.tight = margin ? (s.tight & static_cast<unsigned char>(~bit)) : (s.tight | bit);
        s.mirror =
            margin && by_mirror ? (s.mirror | bit) : (s.mirror & static_cast<unsigned char>(~bit));
      }
    }
    s.evaluated = step;
    if ((s.tight != 0 || s.mirror != 0) && !s.listed) {
      s.listed = true;
      listed_.emplace_back(c, s.id);
    }
  }
  return true;
}

} // namespace kinetic

} // namespace membrane3d
