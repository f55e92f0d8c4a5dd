#include "kinetic_flood.h"

#include "kinetic_exterior.h"
#include "kinetic_triangulation.h"
#include "power_flood.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace membrane3d {

using kinetic::Cell;
using kinetic::Vertex;

namespace {

// The triangulation is made anew rather than repaired when the spheres to remove and
// insert again are more than this share of all: removing and inserting a sphere costs
// some 4 times its share of a triangulation.
constexpr double kRebuildShare = 4.0;

// exterior_boundary's own message for a flat sample
[[noreturn]] void flat(const std::vector<Sphere> &spheres, const std::vector<bool> &sealed)
{
  exterior_boundary(spheres, sealed, 0.0);
  throw FlatSample("the spheres enclose no volume for a membrane to wrap");
}

// exterior_flood.cpp's test of a flat sample, to throw what exterior_boundary throws
void check_not_flat(const std::vector<Sphere> &spheres, const std::vector<bool> &sealed)
{
  const FlatTest t = flat_test(spheres);
  if (t.eigenvalues[0] > t.limit) return;
  flat(spheres, sealed);
}

} // namespace

struct KineticFlood::Impl {
  std::vector<bool> sealed;
  double tolerance, budget;
  std::vector<Sphere> now, reference, held; // held: where the triangulation is regular
  std::vector<long> moved;                  // per sphere: the step it took a new reference
  std::vector<Vertex> vertex;               // per sphere, null when hidden
  kinetic::Triangulation t;
  KineticStats stats;
  kinetic::Certifier certifier{t, reference, now, budget, stats};
  MirrorFamilies mirrors;
  std::vector<int> root; // per family: its sphere (plane 0), or -1
  long step = 0;
  bool forgotten = false;
  Boundary boundary;
  kinetic::Exterior exterior{t, now, sealed, tolerance, vertex};
  std::vector<int> touched; // this step: the spheres around which cells were made

  Impl(const std::vector<bool> &s, double tol, double b) : sealed(s), tolerance(tol), budget(b) {}

  void hold(const std::vector<Sphere> &at)
  {
    for (const Vertex v : vertex)
      if (v != Vertex()) v->set_point(kinetic::weighted_point(at[v->info()]));
  }
  bool symmetric() const;
  std::vector<Vertex> vertices_of(std::vector<int> spheres) const;
  void map_vertices();
  void rebuild();
  bool kinetic_step();
  bool repair(std::vector<int> failed);
  bool insert(int sphere, Vertex hint);
  bool reveal_hidden();
};

// Whether every image is the exact mirror of its sphere, in one plane per platen.
bool KineticFlood::Impl::symmetric() const
{
  if (root.empty()) return false;
  std::array<double, 2> sum{};
  std::array<bool, 2> seen{false, false};
  for (std::size_t i = 0; i < now.size(); ++i) {
    const int plane = mirrors.plane[i];
    if (plane == 0) continue;
    const int r = root[mirrors.family[i]];
    if (r < 0) return false;
    const Sphere &a = now[i], &b = now[r];
    if (a.x.x() != b.x.x() || a.x.y() != b.x.y() || a.r != b.r) return false;
    const double s = a.x.z() + b.x.z();
    const int side = plane > 0;
    if (seen[side] && s != sum[side]) return false;
    sum[side] = s;
    seen[side] = true;
  }
  return true;
}

void KineticFlood::Impl::map_vertices()
{
  vertex.assign(now.size(), Vertex());
  t.infinite_vertex()->info() = -1;
  for (auto v = t.finite_vertices_begin(); v != t.finite_vertices_end(); ++v) vertex[v->info()] = v;
  stats.hidden = std::count(vertex.begin(), vertex.end(), Vertex());
}

void KineticFlood::Impl::rebuild()
{
  ++stats.rebuilds;
  exterior.invalidate();
  forgotten = false;
  t.clear();
  std::vector<std::pair<kinetic::K::Weighted_point_3, int>> points;
  points.reserve(now.size());
  for (std::size_t i = 0; i < now.size(); ++i)
    points.emplace_back(kinetic::weighted_point(now[i]), static_cast<int>(i));
  t.insert(points.begin(), points.end());
  if (t.dimension() < 3) flat(now, sealed);
  map_vertices();
  reference = now;
  held = now;
  certifier.set_symmetric(symmetric());
  std::vector<int> failed;
  // every certificate of the new triangulation holds (CGAL's): this finds their margins;
  // one not decided here (a collinear hull facet): triangulate anew each step
  if (!certifier.pass(++step, moved, failed) || !failed.empty()) forgotten = true;
  stats.tight = certifier.tight();
}

// Inserts a sphere at its present position; false when CGAL did what is not followed
// here (the sphere on another's centre).
bool KineticFlood::Impl::insert(int i, Vertex hint)
{
  const std::size_t before = t.number_of_vertices();
  const auto p = kinetic::weighted_point(now[i]);
  kinetic::Triangulation::Locate_type lt;
  int li, lj;
  const Cell c = t.locate(p, lt, li, lj, hint == Vertex() ? Cell() : hint->cell());
  if (lt == kinetic::Triangulation::VERTEX) return false; // on another's centre
  if (exterior.local()) {                                 // the cells the insertion destroys
    std::vector<Cell> conflict;
    t.find_conflicts(p, c, CGAL::Emptyset_iterator(), std::back_inserter(conflict));
    for (const Cell x : conflict) exterior.destroying(x);
  }
  const Vertex v = t.insert(p, lt, c, li, lj);
  if (v == Vertex()) { // hidden
    vertex[i] = Vertex();
    return true;
  }
  touched.push_back(i);
  if (t.number_of_vertices() != before + 1) {
    v->info() = i;
    map_vertices(); // it hid others
    return true;
  }
  v->info() = i;
  vertex[i] = v;
  return true;
}

// Of each failed certificate, the sphere that has moved most since the last step is
// removed (each failed certificate held at the last step's positions, so one has
// moved), then inserted at its present position; the cells made by the removals are
// certified at the present positions, and their failures repaired alike.
bool KineticFlood::Impl::repair(std::vector<int> failed)
{
  std::vector<int> out; // removed, to insert again
  while (!failed.empty()) {
    std::vector<int> pick;
    for (std::size_t g = 0; g + 5 <= failed.size(); g += 5) {
      int best = -1;
      double most = 0;
      for (std::size_t j = g; j < g + 5; ++j) {
        const int i = failed[j];
        if (i < 0 || vertex[i] == Vertex()) continue;
        const double d = (now[i].x - held[i].x).squaredNorm() + (now[i].r != held[i].r);
        if (d > most) most = d, best = i;
      }
      if (best < 0) return false; // not so: not followed here
      pick.push_back(best);
    }
    std::sort(pick.begin(), pick.end());
    pick.erase(std::unique(pick.begin(), pick.end()), pick.end());
    failed.swap(pick);
    // most of the points: cheaper to triangulate anew
    if (kRebuildShare * static_cast<double>(out.size() + failed.size()) > now.size()) return false;
    hold(held);            // where the triangulation is regular: CGAL may remove there
    std::vector<int> hole; // the spheres around the removed ones
    std::vector<Vertex> adjacent;
    for (int i : failed) {
      if (vertex[i] == Vertex()) continue;
      adjacent.clear();
      t.adjacent_vertices(vertex[i], std::back_inserter(adjacent));
      for (const Vertex v : adjacent)
        if (!t.is_infinite(v)) hole.push_back(v->info());
      if (exterior.local()) {
        std::vector<Cell> star;
        t.incident_cells(vertex[i], std::back_inserter(star));
        for (const Cell c : star) exterior.destroying(c);
      }
      t.remove(vertex[i]);
      vertex[i] = Vertex();
      out.push_back(i);
    }
    stats.removed += static_cast<long>(failed.size());
    hold(now);
    failed.clear();
    // the cells the removals made, at the present positions
    touched.insert(touched.end(), hole.begin(), hole.end());
    if (!certifier.visit_around(vertices_of(hole), step, moved, failed)) return false;
  }
  int last = -1; // the last sphere inserted: its vertex (if it is still one) the hint
  for (int i : out) {
    if (!insert(i, last >= 0 ? vertex[last] : Vertex())) return false;
    if (vertex[i] != Vertex()) last = i;
  }
  std::vector<int> check;
  // the inserted spheres' cells: regular by CGAL; their margins
  if (!certifier.visit_around(vertices_of(out), step, moved, check)) return false;
  return check.empty();
}

// The vertices of these spheres that are vertices, once each.
std::vector<Vertex> KineticFlood::Impl::vertices_of(std::vector<int> spheres) const
{
  std::sort(spheres.begin(), spheres.end());
  spheres.erase(std::unique(spheres.begin(), spheres.end()), spheres.end());
  std::vector<Vertex> out;
  for (int i : spheres)
    if (vertex[i] != Vertex()) out.push_back(vertex[i]);
  return out;
}

// A left-out sphere stays out while it conflicts with no cell: CGAL's insert decides.
bool KineticFlood::Impl::reveal_hidden()
{
  std::vector<int> revealed;
  for (std::size_t i = 0; i < now.size(); ++i) {
    if (vertex[i] != Vertex()) continue;
    if (!insert(static_cast<int>(i), Vertex())) return false;
    if (vertex[i] != Vertex()) revealed.push_back(static_cast<int>(i));
  }
  if (!revealed.empty()) {
    std::vector<int> check;
    if (!certifier.visit_around(vertices_of(revealed), step, moved, check) || !check.empty())
      return false;
  }
  stats.hidden = std::count(vertex.begin(), vertex.end(), Vertex());
  return true;
}

bool KineticFlood::Impl::kinetic_step()
{
  ++step;
  const double reach = budget * budget;
  std::vector<Vertex> around; // of the points that take a new reference
  for (std::size_t i = 0; i < now.size(); ++i)
    if (now[i].r != reference[i].r || (now[i].x - reference[i].x).squaredNorm() >= reach) {
      if (now[i].r != reference[i].r) exterior.invalidate(); // the links' allowances
      reference[i] = now[i];
      moved[i] = step;
      ++stats.rereferenced;
      if (vertex[i] != Vertex()) around.push_back(vertex[i]);
    }
  hold(now);
  certifier.set_symmetric(symmetric());
  std::vector<int> failed;
  if (!certifier.visit_tight(step, moved, failed) ||
      !certifier.visit_around(around, step, moved, failed))
    return false;
  if (!failed.empty()) {
    const auto start = std::chrono::steady_clock::now();
    const bool repaired = repair(std::move(failed));
    stats.repair_seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!repaired) return false;
  }
  if (!reveal_hidden()) return false;
  certifier.compact();
  stats.tight = certifier.tight();
  held = now;
  return true;
}

KineticFlood::KineticFlood(const std::vector<Sphere> &spheres, const std::vector<bool> &sealed,
                           double tolerance, double budget, const MirrorFamilies *mirrors)
{
  check_flood_input(spheres, sealed, tolerance);
  if (!std::isfinite(budget) || !(budget > 0))
    throw std::invalid_argument("kinetic flood budget " + std::to_string(budget) +
                                ": must be a finite length > 0");
  check_not_flat(spheres, sealed);
  impl_ = std::make_unique<Impl>(sealed, tolerance, budget);
  impl_->now = spheres;
  impl_->moved.assign(spheres.size(), -1);
  if (mirrors) {
    if (mirrors->family.size() != spheres.size() || mirrors->plane.size() != spheres.size())
      throw std::invalid_argument("kinetic flood: mirror families for " +
                                  std::to_string(mirrors->family.size()) + " of " +
                                  std::to_string(spheres.size()) + " spheres");
    impl_->mirrors = *mirrors;
    int families = 0;
    for (int f : mirrors->family) {
      if (f < 0) throw std::invalid_argument("kinetic flood: a negative mirror family");
      families = std::max(families, f + 1);
    }
    impl_->root.assign(static_cast<std::size_t>(families), -1);
    for (std::size_t i = 0; i < spheres.size(); ++i)
      if (mirrors->plane[i] == 0) impl_->root[mirrors->family[i]] = static_cast<int>(i);
    impl_->certifier.set_mirrors(&impl_->mirrors);
  }
  impl_->rebuild();
  impl_->exterior.flood(impl_->boundary);
}

KineticFlood::~KineticFlood() = default;

void KineticFlood::advance(const std::vector<Sphere> &now)
{
  Impl &m = *impl_;
  if (now.size() != m.now.size())
    throw std::invalid_argument("kinetic flood: " + std::to_string(now.size()) +
                                " spheres where it has " + std::to_string(m.now.size()));
  check_flood_input(now, m.sealed, m.tolerance);
  check_not_flat(now, m.sealed);
  m.now = now;
  ++m.stats.steps;
  const auto start = std::chrono::steady_clock::now();
  m.exterior.begin_step();
  m.touched.clear();
  if (m.forgotten || !m.kinetic_step()) m.rebuild();
  const auto kept = std::chrono::steady_clock::now();
  if (m.exterior.update(m.touched, m.boundary))
    ++m.stats.floods_kept;
  else
    m.exterior.flood(m.boundary);
  m.stats.flood_visited = m.exterior.visited();
  m.stats.triangulation_seconds += std::chrono::duration<double>(kept - start).count();
  m.stats.flood_seconds +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - kept).count();
}

const Boundary &KineticFlood::boundary() const
{
  return impl_->boundary;
}

const KineticStats &KineticFlood::stats() const
{
  return impl_->stats;
}

void KineticFlood::forget()
{
  impl_->forgotten = true;
}

} // namespace membrane3d
