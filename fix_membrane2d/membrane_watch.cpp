#include <algorithm>
#include <cmath>
#include <numeric>

#include "membrane_chain.h"

namespace membrane {

namespace {

bool finite_disk(const Disk &d)
{
  return std::isfinite(d.x) && std::isfinite(d.y) && std::isfinite(d.r);
}

// start ahead of other in the candidate order of ChainFinder::find
bool ahead_of(const Disk &start, const Disk &other, Side side)
{
  if (start.x != other.x) return side == Side::Right ? start.x > other.x : start.x < other.x;
  return start.tag < other.tag;
}

} // namespace

void watch_detection(const std::vector<Disk> &band, const ChainResult &r, Platens platens,
                     double tol, double budget, DetectionWatch &out)
{
  out.budget = budget;
  out.always = true;
  out.pairs.clear();
  out.platen_contacts.clear();
  out.ahead.clear();
  out.disks.clear();
  // A search that needed a second start depends on the whole failed walk.
  if (!r.ok || r.failed_starts > 0 || !(budget > 0.0) || r.chain.empty()) return;
  const int n = static_cast<int>(band.size());
  double rmax = 0.0;
  for (const Disk &d : band) {
    if (!finite_disk(d)) return;
    rmax = std::max(rmax, d.r);
  }

  // Pairs with a disk the walk stood on, within budget of the link threshold: two
  // disks that close have centres less than 2 rmax + tol + budget apart in y.
  std::vector<char> &visited = out.visited_scratch;
  visited.assign(n, 0);
  for (int i : r.visited) visited[i] = 1;
  std::vector<int> &by_y = out.by_y_scratch;
  by_y.resize(n);
  std::iota(by_y.begin(), by_y.end(), 0);
  std::sort(by_y.begin(), by_y.end(), [&](int a, int b) { return band[a].y < band[b].y; });
  const double reach = 2.0 * rmax + tol + budget;
  for (int i : r.visited) {
    const Disk &a = band[i];
    auto k = std::lower_bound(by_y.begin(), by_y.end(), a.y - reach,
                              [&](int b, double y) { return band[b].y < y; });
    for (; k != by_y.end() && band[*k].y - a.y <= reach; ++k) {
      const int j = *k;
      if (j == i || (visited[j] && j < i)) continue; // a visited pair once
      const Disk &b = band[j];
      const double dx = b.x - a.x, dy = b.y - a.y;
      // |gap - tol| < budget with gap = dist - ra - rb: compare squares first,
      // most disks of the window are far from the threshold
      const double d2 = dx * dx + dy * dy, hi = a.r + b.r + tol + budget, lo = hi - 2.0 * budget;
      if (d2 >= hi * hi || (lo > 0.0 && d2 <= lo * lo)) continue;
      out.pairs.push_back(
          {i, j, link_from(band[i], band[j], tol), link_from(band[j], band[i], tol)});
    }
  }

  const Disk &start = band[r.chain.front()];
  for (int i = 0; i < n; ++i) {
    const Disk &d = band[i];
    const double bottom_gap = d.y - d.r - platens.lo, top_gap = platens.hi - (d.y + d.r);
    if (std::abs(bottom_gap - tol) < budget)
      out.platen_contacts.push_back({i, true, touches_bottom(d, platens, tol)});
    if (std::abs(top_gap - tol) < budget)
      out.platen_contacts.push_back({i, false, touches_top(d, platens, tol)});
    // Candidates (and disks that may become one) close to the start in x.
    if (i != r.chain.front() && bottom_gap - tol < budget && std::abs(d.x - start.x) < budget)
      out.ahead.push_back({r.chain.front(), i});
  }

  for (const auto &p : out.pairs) {
    out.disks.push_back(p.i);
    out.disks.push_back(p.j);
  }
  for (const auto &c : out.platen_contacts) out.disks.push_back(c.i);
  for (const auto &a : out.ahead) {
    out.disks.push_back(a.start);
    out.disks.push_back(a.other);
  }
  std::sort(out.disks.begin(), out.disks.end());
  out.disks.erase(std::unique(out.disks.begin(), out.disks.end()), out.disks.end());
  out.always = false;
}

bool watched_relation_changed(const DetectionWatch &watch, const std::vector<Disk> &now, Side side,
                              Platens platens, double tol)
{
  if (watch.always) return true;
  for (const auto &p : watch.pairs)
    if (link_from(now[p.i], now[p.j], tol) != p.ij || link_from(now[p.j], now[p.i], tol) != p.ji)
      return true;
  for (const auto &c : watch.platen_contacts) {
    const bool touching =
        c.bottom ? touches_bottom(now[c.i], platens, tol) : touches_top(now[c.i], platens, tol);
    if (touching != c.touching) return true;
  }
  for (const auto &a : watch.ahead)
    if (!ahead_of(now[a.start], now[a.other], side)) return true;
  return false;
}

} // namespace membrane
