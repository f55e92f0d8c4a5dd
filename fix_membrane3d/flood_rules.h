// The rules of the flood of exterior_flood.h over a regular triangulation of the
// spheres, shared by the flood of a fresh triangulation (PowerFlood, exterior_flood.cpp)
// and the kinetic flood's kept one (kinetic::Exterior, kinetic_exterior.cpp): function
// templates over the triangulation, whose vertices' info is the sphere's index. Internal
// to the core; no LIGGGHTS here.
#ifndef LIGGGHTS_MEMBRANE_FLOOD_RULES_H
#define LIGGGHTS_MEMBRANE_FLOOD_RULES_H

#include "exterior_flood.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <array>
#include <utility>
#include <vector>

namespace membrane3d {

namespace flood_rules {

// Across a platen (an edge with a sealed sphere) the tolerance doubles: a sphere and
// its image are then linked when the sphere is within T of the platen.
template <class Vertex>
bool linked(Vertex a, Vertex b, const std::vector<Sphere> &spheres, const std::vector<bool> &sealed,
            double tolerance)
{
  const bool across = sealed[a->info()] || sealed[b->info()];
  const Sphere &p = spheres[a->info()], &q = spheres[b->info()];
  return (p.x - q.x).norm() - p.r - q.r <= (across ? 2 * tolerance : tolerance);
}

// The facet of c opposite its vertex k: a wall when its three edges are links.
template <class Triangulation, class Cell>
bool wall(const Triangulation &t, Cell c, int k, const std::vector<Sphere> &spheres,
          const std::vector<bool> &sealed, double tolerance)
{
  const auto a = c->vertex((k + 1) & 3), b = c->vertex((k + 2) & 3), d = c->vertex((k + 3) & 3);
  return !t.is_infinite(a) && !t.is_infinite(b) && !t.is_infinite(d) &&
         linked(a, b, spheres, sealed, tolerance) && linked(b, d, spheres, sealed, tolerance) &&
         linked(a, d, spheres, sealed, tolerance);
}

// Every finite vertex of c a sealed sphere.
template <class Triangulation, class Cell>
bool all_sealed(const Triangulation &t, Cell c, const std::vector<bool> &sealed)
{
  for (int k = 0; k < 4; ++k) {
    const auto v = c->vertex(k);
    if (!t.is_infinite(v) && !sealed[v->info()]) return false;
  }
  return true;
}

// A facet with the infinite vertex or only sealed spheres is no part of the membrane.
template <class Triangulation, class Cell>
bool ignored_facet(const Triangulation &t, Cell c, int k, const std::vector<bool> &sealed)
{
  bool any_unsealed = false;
  for (int j = 1; j < 4; ++j) {
    const auto v = c->vertex((k + j) & 3);
    if (t.is_infinite(v)) return true;
    any_unsealed = any_unsealed || !sealed[v->info()];
  }
  return !any_unsealed;
}

// The facet of the unflooded cell c opposite vertex k, counter-clockwise seen from
// the flooded side (the vertex k is on the negative side of its normal).
template <class Cell> std::array<int, 3> outward_facet(Cell c, int k)
{
  auto a = c->vertex((k + 1) & 3), b = c->vertex((k + 2) & 3);
  const auto d = c->vertex((k + 3) & 3), inner = c->vertex(k);
  if (CGAL::orientation(a->point().point(), b->point().point(), d->point().point(),
                        inner->point().point()) == CGAL::POSITIVE)
    std::swap(a, b);
  return {a->info(), b->info(), d->info()};
}

} // namespace flood_rules

} // namespace membrane3d

#endif
