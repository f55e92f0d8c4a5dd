#include <algorithm>
#include <cmath>
#include <limits>

#include "membrane_chain.h"

namespace membrane {

namespace {

// Identity of the MPI reduction of each side (MAX on the Right, MIN on the Left).
double empty_extent(Side side)
{
  return side == Side::Right ? std::numeric_limits<double>::lowest()
                             : std::numeric_limits<double>::max();
}

} // namespace

void BandSlices::reset(Side side, Platens platens, double h)
{
  side_ = side;
  ylo_ = platens.lo;
  const double span = platens.hi - platens.lo;
  h_ = (h > 0.0 && std::isfinite(h)) ? h : std::max(span, 1.0);
  inv_h_ = 1.0 / h_;
  long n = (span > 0.0 && std::isfinite(span)) ? static_cast<long>(std::ceil(span / h_)) : 1;
  n = std::clamp(n, 1L, 1000000L);
  extent_.assign(static_cast<std::size_t>(n), empty_extent(side));
  near_.clear();
}

void BandSlices::finish()
{
  const int n = static_cast<int>(extent_.size());
  near_.assign(extent_.size(), empty_extent(side_));
  for (int i = 0; i < n; ++i)
    for (int k = std::max(0, i - 1); k <= std::min(n - 1, i + 1); ++k)
      near_[i] =
          side_ == Side::Right ? std::max(near_[i], extent_[k]) : std::min(near_[i], extent_[k]);
}

void BandSlices::add(double x, double y, double r)
{
  if (extent_.empty()) return;
  add_in_slice(slice_of(y), x, r);
}

double BandSlices::outer_edge_near(double y) const
{
  if (extent_.empty()) return empty_extent(side_);
  const int i = slice_of(y);
  if (near_.size() == extent_.size()) return near_[i];
  const int last = static_cast<int>(extent_.size()) - 1;
  double e = empty_extent(side_);
  for (int k = std::max(0, i - 1); k <= std::min(last, i + 1); ++k)
    e = side_ == Side::Right ? std::max(e, extent_[k]) : std::min(e, extent_[k]);
  return e;
}

bool BandSlices::contains(double x, double y, double r, double width) const
{
  return contains_in_slice(slice_of(y), x, r, width);
}

} // namespace membrane
