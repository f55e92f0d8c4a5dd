#include "distributed_skin.h"

#include "math_constants.h"
#include "number_text.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <unordered_map>

namespace membrane3d {

std::vector<char> near_seeds(const std::vector<Sphere> &mine, const std::vector<Sphere> &seeds,
                             double r_max, double thickness)
{
  if (!std::isfinite(thickness) || !std::isfinite(r_max))
    throw std::invalid_argument("skin thickness " + number_text(thickness) + ", largest radius " +
                                number_text(r_max) + ": must be finite");
  std::vector<char> near(mine.size(), 0);
  double seed_r = 0;
  for (const Sphere &s : seeds) seed_r = std::max(seed_r, s.r);
  // cubes no narrower than any reach: a sphere near a seed is in its cube or the next
  const double side = std::max(r_max + seed_r + thickness, 1e-300);
  const auto cube = [side](const Eigen::Vector3d &x, int d) {
    return static_cast<std::int64_t>(std::floor(x[d] / side));
  };
  const auto key = [](std::int64_t a, std::int64_t b, std::int64_t c) {
    return (a * 73856093) ^ (b * 19349663) ^ (c * 83492791);
  };
  std::unordered_multimap<std::int64_t, int> grid;
  grid.reserve(seeds.size());
  for (std::size_t k = 0; k < seeds.size(); ++k)
    grid.emplace(key(cube(seeds[k].x, 0), cube(seeds[k].x, 1), cube(seeds[k].x, 2)),
                 static_cast<int>(k));
  for (std::size_t i = 0; i < mine.size(); ++i) {
    const Eigen::Vector3d &x = mine[i].x;
    const std::int64_t a = cube(x, 0), b = cube(x, 1), c = cube(x, 2);
    for (std::int64_t da = -1; da <= 1 && !near[i]; ++da)
      for (std::int64_t db = -1; db <= 1 && !near[i]; ++db)
        for (std::int64_t dc = -1; dc <= 1 && !near[i]; ++dc) {
          const auto range = grid.equal_range(key(a + da, b + db, c + dc));
          for (auto it = range.first; it != range.second && !near[i]; ++it) {
            const Sphere &s = seeds[it->second];
            // the same test as spheres_near's (a colliding key only costs a test)
            if ((x - s.x).norm() - mine[i].r - s.r <= thickness) near[i] = 1;
          }
        }
  }
  return near;
}

OutermostBins::OutermostBins(const Eigen::Vector2d &axis_, double z_lo_, double z_hi,
                             double outer, double diameter_)
  : axis(axis_), z_lo(z_lo_), diameter(diameter_)
{
  if (!(diameter > 0) || !std::isfinite(diameter) || !std::isfinite(outer) ||
      !std::isfinite(z_hi - z_lo))
    throw std::invalid_argument("outermost spheres: diameter " + number_text(diameter) +
                                ", outer radius " + number_text(outer) + ", heights " +
                                number_text(z_lo) + " to " + number_text(z_hi));
  slabs = std::max(1L, static_cast<long>((z_hi - z_lo) / diameter) + 1);
  slabs = std::min(slabs, MOST_BINS / 8);
  sectors = std::clamp(static_cast<long>(math_constants::TWO_PI * outer / diameter), 8L, 1L << 16);
  sectors = std::max(8L, std::min(sectors, MOST_BINS / slabs));
}

std::size_t OutermostBins::bin(const Eigen::Vector3d &x) const
{
  const Eigen::Vector2d r = x.head<2>() - axis;
  const double turn = (std::atan2(r.y(), r.x()) + math_constants::PI) / math_constants::TWO_PI;
  const long sector = std::clamp(static_cast<long>(turn * sectors), 0L, sectors - 1);
  const long slab = std::clamp(static_cast<long>((x.z() - z_lo) / diameter), 0L, slabs - 1);
  return static_cast<std::size_t>(slab * sectors + sector);
}

SkinCounters SkinCounters::operator-(const SkinCounters &then) const
{
  SkinCounters d = *this;
  d.detections -= then.detections;
  d.rounds -= then.rounds;
  d.joined -= then.joined;
  d.doublings -= then.doublings;
  d.last_resorts -= then.last_resorts;
  d.bytes -= then.bytes;
  return d;
}

std::string skin_run_note(const SkinCounters &run)
{
  if (run.rounds <= 0 && run.last_resorts <= 0) return "";
  const auto count = [](double n, const char *one, const char *many) {
    return count_text(static_cast<std::size_t>(n), one, many);
  };
  std::string text = "of the run's " + count(run.detections, "detection", "detections") +
                     " from the skin, ";
  if (run.rounds > 0) {
    text += count(run.rounds, "certificate", "certificates") + " failed and " +
            (run.rounds > 1 ? "were" : "was") + " made again with the " +
            count(run.joined, "left-out sphere", "left-out spheres") +
            " that failed joining the skin";
    if (run.doublings > 0)
      text += " (its thickness doubled " + count(run.doublings, "time", "times") + ")";
  }
  if (run.last_resorts > 0)
    text += std::string(run.rounds > 0 ? "; " : "") +
            count(run.last_resorts, "detection", "detections") +
            " gathered all the group's spheres (the last resort)";
  return text;
}

} // namespace membrane3d
