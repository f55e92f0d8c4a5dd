#include "membrane_chain.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace membrane {

namespace {

// Angles only need ordering, so a "diamond angle" (piecewise rational, monotone
// in the true angle) replaces atan2: the walk calls it for every neighbour.
constexpr double kFullTurn = 4.0;

// Counter-clockwise angle of (x, y) from +x in (0, 4]; 4 stands for a full turn
// (the direction of the back edge itself).
double pseudo_angle(double x, double y)
{
  const double s = std::abs(x) + std::abs(y);
  if (!(s > 0.0)) return kFullTurn;
  double d;
  if (y >= 0.0)
    d = x >= 0.0 ? y / s : 1.0 - x / s;
  else
    d = x < 0.0 ? 2.0 - y / s : 3.0 + x / s;
  return d > 0.0 ? d : kFullTurn;
}

bool finite_disk(const Disk &d)
{
  return std::isfinite(d.x) && std::isfinite(d.y) && std::isfinite(d.r);
}

} // namespace

bool ChainFinder::linked(int i, int j) const
{
  int count = 0;
  const int *nb = neighbours(i, count);
  return std::find(nb, nb + count, j) != nb + count;
}

int ChainFinder::degree(int i) const
{
  int count = 0;
  neighbours(i, count);
  return count;
}

void ChainFinder::build_graph(const std::vector<Disk> &disks, double tol)
{
  // Only the cell list is built here: the walk needs the neighbours of the
  // few disks it visits (the chain and its excursions), not the whole band's
  // graph, so neighbours() finds them on first use.
  disks_ = &disks;
  tol_ = tol;
  const int n = static_cast<int>(disks.size());
  double xmin = std::numeric_limits<double>::max(), ymin = xmin, rmax = 0.0;
  for (const Disk &d : disks) {
    if (!finite_disk(d)) continue;
    xmin = std::min(xmin, d.x);
    ymin = std::min(ymin, d.y);
    rmax = std::max(rmax, d.r);
  }
  rmax_ = rmax;
  // Any linked pair is at most 2 rmax + tol apart, so the 3x3 block of cells
  // around a disk holds all its possible contacts.
  cell_ = 2.0 * rmax + std::max(tol, 0.0);
  if (!(cell_ > 0.0)) cell_ = 1.0;
  // Cells are hashed into ~2n buckets rather than laid out as a grid, so a
  // stray far-away disk costs nothing and the build stays O(n) for any layout.
  nbucket_ = 16;
  while (nbucket_ < 2 * static_cast<std::size_t>(n)) nbucket_ *= 2;
  const auto cell_index = [&](double v, double lo) {
    // Clamped so the conversion cannot overflow; disks that far apart are
    // never linked anyway.
    return static_cast<long long>(std::floor(std::min((v - lo) / cell_, 1e15)));
  };

  cell_x_.assign(n, 0);
  cell_y_.assign(n, 0);
  cell_of_.assign(n, -1);
  cell_start_.assign(nbucket_ + 1, 0);
  for (int i = 0; i < n; ++i) {
    const Disk &d = disks[i];
    if (!finite_disk(d)) continue;
    cell_x_[i] = cell_index(d.x, xmin);
    cell_y_[i] = cell_index(d.y, ymin);
    cell_of_[i] = bucket_of(cell_x_[i], cell_y_[i]);
    ++cell_start_[cell_of_[i] + 1];
  }
  for (std::size_t c = 0; c < nbucket_; ++c) cell_start_[c + 1] += cell_start_[c];
  next_slot_.assign(cell_start_.begin(), cell_start_.end() - 1);
  cell_items_.resize(n);
  for (int i = 0; i < n; ++i)
    if (cell_of_[i] >= 0) cell_items_[next_slot_[cell_of_[i]]++] = i;

  nb_start_.assign(n, -1);
  nb_count_.assign(n, 0);
  nb_pool_.clear();
}

int ChainFinder::bucket_of(long long cx, long long cy) const
{
  const auto ux = static_cast<unsigned long long>(cx), uy = static_cast<unsigned long long>(cy);
  return static_cast<int>(((ux * 0x9E3779B97F4A7C15ULL) ^ (uy * 0xC2B2AE3D27D4EB4FULL)) >> 20 &
                          (nbucket_ - 1));
}

const int *ChainFinder::neighbours(int i, int &count) const
{
  if (nb_start_[i] < 0) {
    nb_start_[i] = static_cast<int>(nb_pool_.size());
    if (cell_of_[i] >= 0) {
      const std::vector<Disk> &disks = *disks_;
      const Disk &a = disks[i];
      for (long long cy = cell_y_[i] - 1; cy <= cell_y_[i] + 1; ++cy) {
        for (long long cx = cell_x_[i] - 1; cx <= cell_x_[i] + 1; ++cx) {
          const int c = bucket_of(cx, cy);
          for (int k = cell_start_[c]; k < cell_start_[c + 1]; ++k) {
            const int j = cell_items_[k];
            // The cell test keeps a disk from being found twice when two
            // neighbour cells share a bucket.
            if (j == i || cell_x_[j] != cx || cell_y_[j] != cy) continue;
            const Disk &b = disks[j];
            const double dx = b.x - a.x, dy = b.y - a.y, d2 = dx * dx + dy * dy;
            const double reach = a.r + b.r + tol_;
            // Cheap reject with a margin; link_from is the definition (it also
            // refuses coincident centres: no direction to walk along).
            if (reach < 0.0 || d2 > reach * reach * (1.0 + 1e-9)) continue;
            if (link_from(a, b, tol_)) nb_pool_.push_back(j);
          }
        }
      }
    }
    nb_count_[i] = static_cast<int>(nb_pool_.size()) - nb_start_[i];
  }
  count = nb_count_[i];
  return nb_pool_.data() + nb_start_[i];
}

int ChainFinder::next_neighbour(const std::vector<Disk> &disks, int cur, int prev, Side side) const
{
  const Disk &p = disks[cur];
  // The first disk has no predecessor: pretending it came from below makes the
  // first step the most outward one (east first on the Right).
  const double bx = prev < 0 ? 0.0 : disks[prev].x - p.x;
  const double by = prev < 0 ? -1.0 : disks[prev].y - p.y;
  int best = -1;
  double best_ang = 0.0;
  int count = 0;
  const int *nb = neighbours(cur, count);
  for (int k = 0; k < count; ++k) {
    const int j = nb[k];
    double ang;
    if (j == prev) {
      // Going back is the last resort (a dead end); set exactly so round-off
      // cannot rank it first.
      ang = kFullTurn;
    } else {
      const double vx = disks[j].x - p.x, vy = disks[j].y - p.y;
      double cr = bx * vy - by * vx;
      if (side == Side::Left) cr = -cr; // clockwise on the Left = mirror image
      ang = pseudo_angle(bx * vx + by * vy, cr);
    }
    if (best < 0 || ang < best_ang || (ang == best_ang && disks[j].tag < disks[best].tag)) {
      best = j;
      best_ang = ang;
    }
  }
  return best;
}

bool ChainFinder::walk(const std::vector<Disk> &disks, int start, Side side, Platens platens,
                       double tol)
{
  // Forget the state of a previous (failed) walk of this find().
  for (int i : walked_) {
    chain_pos_[i] = -1;
    pruned_[i] = 0;
  }
  walked_.clear();
  chain_.clear();

  chain_.push_back(start);
  chain_pos_[start] = 0;
  visited_[start] = 1;
  walked_.push_back(start);
  if (touches_top(disks[start], platens, tol)) return true;

  // The walk is a permutation of directed edges, so it can only fail to reach
  // the top by repeating its first edge; the step limit is a second fence.
  // Directed edges number at most n x (max degree); a disk touches at most ~2 pi /
  // (2 asin(rmin / (rmin + rmax))) others, far below 64 for any real grading.
  const long limit = 64L * static_cast<long>(disks.size()) + 1;
  int prev = -1, cur = start, first_from = -1, first_to = -1;
  for (long step = 0; step <= limit; ++step) {
    const int nxt = next_neighbour(disks, cur, prev, side);
    if (nxt < 0) return false;
    if (step == 0) {
      first_from = cur;
      first_to = nxt;
    } else if (cur == first_from && nxt == first_to) {
      return false;
    }
    prev = cur;
    cur = nxt;
    visited_[cur] = 1;
    const int pos = chain_pos_[cur];
    if (pos >= 0) {
      // Back at a chain disk: what was walked since hangs on by this disk only
      // and would own zero-length polyline segments.
      while (static_cast<int>(chain_.size()) > pos + 1) {
        const int b = chain_.back();
        chain_.pop_back();
        chain_pos_[b] = -1;
        pruned_[b] = 1;
      }
    } else {
      chain_pos_[cur] = static_cast<int>(chain_.size());
      chain_.push_back(cur);
      pruned_[cur] = 0;
      walked_.push_back(cur);
      if (touches_top(disks[cur], platens, tol)) return true;
    }
  }
  return false;
}

void ChainFinder::find(const std::vector<Disk> &disks, Side side, Platens platens, double tol,
                       ChainResult &out)
{
  out.ok = false;
  out.failure.clear();
  out.chain.clear();
  out.polyline.clear();
  out.escaped.clear();
  out.pruned = 0;
  out.failed_starts = 0;
  out.visited.clear();
  chain_.clear();
  walked_.clear();

  const int n = static_cast<int>(disks.size());
  if (!(platens.hi > platens.lo)) {
    out.failure = "top platen is not above the bottom platen";
    return;
  }
  if (!std::isfinite(tol)) {
    out.failure = "gap tolerance is not finite";
    return;
  }
  if (n == 0) {
    out.failure = "no particles in the band";
    return;
  }

  build_graph(disks, tol);
  chain_pos_.assign(n, -1);
  pruned_.assign(n, 0);
  visited_.assign(n, 0);

  candidates_.clear();
  for (int i = 0; i < n; ++i)
    if (finite_disk(disks[i]) && touches_bottom(disks[i], platens, tol)) candidates_.push_back(i);
  if (candidates_.empty()) {
    out.failure = "no band particle touches the bottom platen";
    return;
  }
  std::sort(candidates_.begin(), candidates_.end(), [&](int a, int b) {
    const Disk &da = disks[a], &db = disks[b];
    if (da.x != db.x) return side == Side::Right ? da.x > db.x : da.x < db.x;
    return da.tag < db.tag;
  });

  bool reached = false;
  for (int c : candidates_) {
    // A failed walk goes round the whole outer face of its cluster, which holds
    // every bottom-touching disk of that cluster: retrying them cannot succeed.
    if (visited_[c]) continue;
    if (walk(disks, c, side, platens, tol)) {
      reached = true;
      break;
    }
    ++out.failed_starts;
  }
  for (int i = 0; i < n; ++i)
    if (visited_[i]) out.visited.push_back(i);
  if (!reached) {
    out.failure = "no contact path from the bottom platen to the top platen (" +
                  std::to_string(out.failed_starts) + " start particle(s) tried, first tag " +
                  std::to_string(disks[candidates_.front()].tag) + ")";
    return;
  }

  out.ok = true;
  out.chain.assign(chain_.begin(), chain_.end());
  polyline_from_chain(disks, out.chain, platens, out.polyline);
  bin_segments(out.polyline, platens, 2.0 * rmax_ + std::max(tol, 0.0));
  for (int i = 0; i < n; ++i) {
    if (chain_pos_[i] >= 0) continue;
    const Disk &d = disks[i];
    if (pruned_[i]) {
      out.escaped.push_back(i);
      ++out.pruned;
    } else if (finite_disk(d) && d.y > platens.lo && d.y < platens.hi &&
               outside_binned(d.x, d.y, out.polyline, side)) {
      out.escaped.push_back(i);
    }
  }
}

void ChainFinder::bin_segments(const Polyline &pl, Platens platens, double bin_height)
{
  // Testing every band disk against every segment would be O(n x chain);
  // horizontal slabs make the escapee test O(n + chain).
  const std::size_t nseg = pl.empty() ? 0 : pl.size() - 1;
  bin_lo_ = platens.lo;
  const double span = platens.hi - platens.lo;
  double nb = bin_height > 0.0 ? std::ceil(span / bin_height) : 1.0;
  nb = std::clamp(nb, 1.0, 4.0 * static_cast<double>(nseg) + 16.0);
  nbin_ = static_cast<int>(nb);
  bin_h_ = span / nb;
  bin_start_.assign(nbin_ + 1, 0);
  bin_xmin_.assign(nbin_, std::numeric_limits<double>::max());
  bin_xmax_.assign(nbin_, std::numeric_limits<double>::lowest());
  for (int pass = 0; pass < 2; ++pass) {
    if (pass == 1) {
      for (int b = 0; b < nbin_; ++b) bin_start_[b + 1] += bin_start_[b];
      next_slot_.assign(bin_start_.begin(), bin_start_.end() - 1);
      bin_items_.resize(bin_start_[nbin_]);
    }
    for (std::size_t k = 0; k < nseg; ++k) {
      const int b0 = bin_of(std::min(pl[k].y(), pl[k + 1].y()));
      const int b1 = bin_of(std::max(pl[k].y(), pl[k + 1].y()));
      for (int b = b0; b <= b1; ++b) {
        if (pass == 0) {
          ++bin_start_[b + 1];
        } else {
          bin_items_[next_slot_[b]++] = static_cast<int>(k);
          bin_xmin_[b] = std::min({bin_xmin_[b], pl[k].x(), pl[k + 1].x()});
          bin_xmax_[b] = std::max({bin_xmax_[b], pl[k].x(), pl[k + 1].x()});
        }
      }
    }
  }
}

int ChainFinder::bin_of(double y) const
{
  // Monotone in y, so a segment's bins always include those of any y it spans.
  const double f = std::floor((y - bin_lo_) / bin_h_);
  if (!(f > 0.0)) return 0;
  return static_cast<int>(std::min(f, static_cast<double>(nbin_ - 1)));
}

bool ChainFinder::outside_binned(double x, double y, const Polyline &pl, Side side) const
{
  const int b = bin_of(y);
  // The polyline runs from ylo to yhi, so it crosses every height between an
  // odd number of times: a disk inward of all of this slab's segments is inside.
  if (bin_start_[b + 1] > bin_start_[b] &&
      (side == Side::Right ? x < bin_xmin_[b] : x > bin_xmax_[b]))
    return false;
  int crossings = 0;
  for (int k = bin_start_[b]; k < bin_start_[b + 1]; ++k) {
    const Eigen::Vector2d &a = pl[bin_items_[k]];
    const Eigen::Vector2d &c = pl[bin_items_[k] + 1];
    if ((a.y() > y) == (c.y() > y)) continue;
    const double xc = a.x() + (y - a.y()) * (c.x() - a.x()) / (c.y() - a.y());
    if (side == Side::Right ? xc > x : xc < x) ++crossings;
  }
  return crossings % 2 == 0;
}

ChainResult ChainFinder::find(const std::vector<Disk> &disks, Side side, Platens platens,
                              double tol)
{
  ChainResult r;
  find(disks, side, platens, tol, r);
  return r;
}

void polyline_from_chain(const std::vector<Disk> &disks, const std::vector<int> &chain,
                         Platens platens, Polyline &out)
{
  out.clear();
  if (chain.empty()) return;
  out.emplace_back(disks[chain.front()].x, platens.lo);
  for (std::size_t k = 0; k + 1 < chain.size(); ++k) {
    const Disk &a = disks[chain[k]];
    const Disk &b = disks[chain[k + 1]];
    const double rs = a.r + b.r;
    // Equal split for zero radii keeps the point defined.
    const double f = rs > 0.0 ? a.r / rs : 0.5;
    out.emplace_back(a.x + f * (b.x - a.x), a.y + f * (b.y - a.y));
  }
  out.emplace_back(disks[chain.back()].x, platens.hi);
}

Polyline polyline_from_chain(const std::vector<Disk> &disks, const std::vector<int> &chain,
                             Platens platens)
{
  Polyline p;
  polyline_from_chain(disks, chain, platens, p);
  return p;
}

void chain_forces(const Polyline &polyline, Side side, double pressure, double thickness,
                  std::vector<Eigen::Vector2d> &out)
{
  out.clear();
  const double pt = pressure * thickness;
  for (std::size_t k = 0; k + 1 < polyline.size(); ++k) {
    const Eigen::Vector2d d = polyline[k + 1] - polyline[k];
    if (side == Side::Right)
      out.emplace_back(-pt * d.y(), pt * d.x());
    else
      out.emplace_back(pt * d.y(), -pt * d.x());
  }
}

std::vector<Eigen::Vector2d> chain_forces(const Polyline &polyline, Side side, double pressure,
                                          double thickness)
{
  std::vector<Eigen::Vector2d> f;
  chain_forces(polyline, side, pressure, thickness, f);
  return f;
}

Eigen::Vector2d escapee_force(const Disk &d, Side side, double pressure, double thickness)
{
  const double mag = pressure * thickness * 2.0 * d.r;
  return Eigen::Vector2d(side == Side::Right ? -mag : mag, 0.0);
}

bool outside_polyline(const Eigen::Vector2d &p, const Polyline &polyline, Side side)
{
  int crossings = 0;
  for (std::size_t k = 0; k + 1 < polyline.size(); ++k) {
    const Eigen::Vector2d &a = polyline[k];
    const Eigen::Vector2d &b = polyline[k + 1];
    // Half-open in y so a ray through a vertex counts it exactly once.
    if ((a.y() > p.y()) == (b.y() > p.y())) continue;
    const double x = a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
    if (side == Side::Right ? x > p.x() : x < p.x()) ++crossings;
  }
  return crossings % 2 == 0;
}

} // namespace membrane
