#include "detection_watch.h"

#include <algorithm>
#include <cmath>

namespace membrane3d {

MembraneTopology detect_watched_membrane(const std::vector<Sphere> &spheres, const Platens &platens,
                                         double tolerance, double budget, DetectionWatch &watch)
{
  Mirrored m;
  FloodCells cells;
  MembraneTopology topology = detect_membrane(spheres, platens, tolerance, &m, &cells);
  watch = DetectionWatch();
  watch.flood = watch_flood(cells, m.spheres, m.sealed, {m.original, m.image}, tolerance, budget);
  watch.grid = m.grid;
  watch.platens = platens;
  watch.band = m.band;
  watch.budget = budget;
  // the spheres of the flood's points and of the membrane (its members are among
  // them: a sphere on a facet or outside is a vertex of a flooded cell, or hidden)
  std::vector<int> entry(spheres.size(), -1);
  for (int p : watch.flood.point) entry[m.original[p]] = 0;
  for (const auto &f : topology.facets)
    for (const MembraneVertex &v : f) entry[v.sphere] = 0;
  for (std::size_t i = 0; i < spheres.size(); ++i)
    if (topology.side[i] == Side::outside) entry[i] = 0;
  for (std::size_t i = 0; i < spheres.size(); ++i)
    if (entry[i] == 0) {
      entry[i] = static_cast<int>(watch.spheres.size());
      watch.spheres.push_back(static_cast<int>(i));
      watch.at_detection.push_back(spheres[i]);
      const double z = spheres[i].x.z();
      watch.imaged.push_back(
          {imaged_below(z, platens, watch.band), imaged_above(z, platens, watch.band)});
    }
  for (int p : watch.flood.point) watch.points.push_back({entry[m.original[p]], m.image[p]});
  return topology;
}

bool membrane_can_have_changed(const DetectionWatch &watch, const std::vector<Sphere> &now,
                               const Platens &platens)
{
  if (watch.flood.always || now.size() != watch.spheres.size()) return true;
  for (std::size_t k = 0; k < now.size(); ++k) {
    const double z = now[k].x.z();
    if (now[k].r != watch.at_detection[k].r ||
        imaged_below(z, platens, watch.band) != static_cast<bool>(watch.imaged[k][0]) ||
        imaged_above(z, platens, watch.band) != static_cast<bool>(watch.imaged[k][1]))
      return true;
  }
  const double grid = height_grid(platens, watch.band);
  if (grid != watch.grid) return true;
  const double moved_lo = std::abs(platens.lo - watch.platens.lo);
  const double moved_hi = std::abs(platens.hi - watch.platens.hi);
  std::vector<Sphere> points;
  points.reserve(watch.points.size());
  for (const MembraneVertex &p : watch.points) {
    const Sphere &s = now[p.sphere];
    // (plus the grid: the heights' rounding to it moves a point by up to half of it)
    double moved = (s.x - watch.at_detection[p.sphere].x).norm() + grid;
    if (p.image != 0) moved += 2 * (p.image < 0 ? moved_lo : moved_hi);
    if (!(moved < watch.budget)) return true;
    points.push_back({mirrored_position(s.x, p.image, platens, grid), s.r});
  }
  return watched_flood_changed(watch.flood, points);
}

} // namespace membrane3d
