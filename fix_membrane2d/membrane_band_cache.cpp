#include "membrane_band_cache.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace membrane {

namespace {

constexpr double kHuge = std::numeric_limits<double>::max();

// How far in from the outer edge a disk may lie and still matter to slice s:
// a non-candidate must stay beyond it, strictly (left: x - r > it; right:
// x + r < it). Beyond the band (edge near s +- width) and beyond the slice's
// own extent, so that it neither joins the band nor bounds an edge.
double reach(const BandSlices &s, int slice, double width)
{
  const double extent = s.extents()[static_cast<std::size_t>(slice)];
  const double edge = s.edge_near_slice(slice);
  return s.side() == Side::Left ? std::max(extent, edge + width) : std::min(extent, edge - width);
}

double outer(const BandDisk &d, Side side)
{
  return side == Side::Left ? d.x - d.r : d.x + d.r;
}

} // namespace

void BandCandidates::build(const std::vector<BandDisk> &disks, const BandSlices *left,
                           const BandSlices *right, double width, double margin, double motion,
                           double ybox_lo, double ybox_hi)
{
  width_ = width;
  motion_ = motion;
  ylo_ = ybox_lo;
  strip_ = width > 0.0 ? width : 1.0;
  const double span = ybox_hi - ybox_lo;
  long n = span > 0.0 && std::isfinite(span) ? static_cast<long>(std::ceil(span / strip_)) : 1;
  n = std::clamp(n, 1L, 1000000L);
  inner_left_.assign(static_cast<std::size_t>(n), kHuge);
  inner_right_.assign(static_cast<std::size_t>(n), -kHuge);
  candidates_.clear();
  const BandSlices *sides[2] = {left, right};
  for (const BandDisk &d : disks) {
    bool candidate = false;
    for (const BandSlices *s : sides) {
      if (!s) continue;
      const double limit = reach(*s, s->slice_of(d.y), width);
      const double q = outer(d, s->side());
      candidate = candidate || (s->side() == Side::Left ? q <= limit + margin : q >= limit - margin);
    }
    if (candidate) {
      candidates_.push_back(d.index);
      continue;
    }
    const double f = std::floor((d.y - ylo_) / strip_);
    const std::size_t b = static_cast<std::size_t>(std::clamp(f, 0.0, static_cast<double>(n - 1)));
    inner_left_[b] = std::min(inner_left_[b], d.x - d.r);
    inner_right_[b] = std::max(inner_right_[b], d.x + d.r);
  }
  valid_ = true;
}

bool BandCandidates::still_covers(const BandSlices *left, const BandSlices *right) const
{
  if (!valid_) return false;
  const int n = static_cast<int>(inner_left_.size());
  for (const BandSlices *s : {left, right}) {
    if (!s) continue;
    const bool is_left = s->side() == Side::Left;
    for (int b = 0; b < n; ++b) {
      const double inner = is_left ? inner_left_[b] : inner_right_[b];
      if (std::fabs(inner) == kHuge) continue; // no other disk in this strip
      // where its disks can be now: within motion of the strip (the end
      // strips also hold the disks beyond the box range)
      const int first = b == 0 ? 0 : s->slice_of(ylo_ + b * strip_ - motion_);
      const int last = b == n - 1 ? s->count() - 1 : s->slice_of(ylo_ + (b + 1) * strip_ + motion_);
      for (int slice = first; slice <= last; ++slice) {
        const double limit = reach(*s, slice, width_);
        const double slack = 1e-9 * (std::fabs(limit) + width_);
        if (is_left ? !(inner - motion_ - slack > limit) : !(inner + motion_ + slack < limit))
          return false;
      }
    }
  }
  return true;
}

void BandCandidates::stamp(long long neighbour_builds, int nlocal, const bool active[2])
{
  neighbour_builds_ = neighbour_builds;
  nlocal_ = nlocal;
  active_[0] = active[0];
  active_[1] = active[1];
}

bool BandCandidates::usable(double width, const bool active[2], long long neighbour_builds,
                            int nlocal) const
{
  return valid_ && width_ == width && neighbour_builds_ == neighbour_builds && nlocal_ == nlocal &&
         active_[0] == active[0] && active_[1] == active[1];
}

bool BandCandidates::motion_bounded(int every, int delay, bool check, bool build_once)
{
  return every == 1 && delay == 0 && check && !build_once;
}

} // namespace membrane
