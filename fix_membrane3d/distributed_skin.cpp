#include "distributed_skin.h"

#include "math_constants.h"
#include "number_text.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace membrane3d {

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
