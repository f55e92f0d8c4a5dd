#ifndef LIGGGHTS_MEMBRANE_MEMBRANE_CHAIN_H
#define LIGGGHTS_MEMBRANE_MEMBRANE_CHAIN_H

// LIGGGHTS-free geometry of fix membrane2d (doc/fix_membrane2d.md):
// chain of outermost disks per side, its polyline, membrane forces, escapees,
// sample area / widths and the band selection. Lengths in m, pressure in Pa,
// thickness in m, forces in N. Kept free of LIGGGHTS so it can be tested exactly.

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "atom_id.h"
#include "platens.h"

namespace membrane {

enum class Side { Left, Right };

struct Disk {
  AtomId tag;
  double x, y, r;
};


using Polyline = std::vector<Eigen::Vector2d>;

struct ChainResult {
  bool ok = false;
  std::string failure;      // set when !ok: why no chain reaches the top platen
  std::vector<int> chain;   // indices into the input, bottom -> top
  Polyline polyline;        // chain.size() + 1 points, (x_first, ylo) ... (x_last, yhi)
  std::vector<int> escaped; // ascending indices; includes the pruned dead ends
  int pruned = 0;           // dead-end / hanging-cluster disks cut out of the walk
  int failed_starts = 0;    // start candidates whose walk could not reach the top
  std::vector<int> visited; // ascending indices of the disks the walk stood on (their
                            // neighbours are all it looked at)
};

// Finds the membrane chain of one side. Keeps its (hashed) cell list and graph buffers
// between calls, so after warm-up a call allocates nothing (when the caller
// also reuses its ChainResult).
//
// Walk: starts at the bottom-touching disk with the largest x (Right) / smallest
// x (Left), ties by lowest tag, with a virtual previous direction straight down;
// at each disk it takes the neighbour first counter-clockwise (Right) / clockwise
// (Left) from the direction back to the previous disk, i.e. it follows the outer
// face of the contact graph with the outside on its right (Right side). It stops
// at the first disk touching the top platen. Returning to a disk already in the
// chain truncates the chain to it (pruned disks become escapees).
// Failure: a start whose walk comes back to its first edge (its component never
// touches the top) is abandoned and the next candidate (next largest x on Right)
// not already visited by a failed walk is tried; if none succeeds, ok=false with
// a reason, chain/polyline empty, escaped empty: the caller must not apply
// membrane forces from such a result.
class ChainFinder {
 public:
  // tol: gap tolerance (m). Two disks are linked when dist - ri - rj <= tol; a
  // disk touches the bottom when y - r - ylo <= tol, the top when yhi - y - r <= tol.
  // Results depend only on the set of disks (not on their order), given unique tags.
  void find(const std::vector<Disk> &disks, Side side, Platens platens, double tol,
            ChainResult &out);
  ChainResult find(const std::vector<Disk> &disks, Side side, Platens platens, double tol);

  // Contact graph of the last find() (for diagnostics and tests).
  int degree(int i) const;
  bool linked(int i, int j) const;

 private:
  void build_graph(const std::vector<Disk> &disks, double tol);
  // Returns true when the top is reached; chain_ holds the result.
  bool walk(const std::vector<Disk> &disks, int start, Side side, Platens platens, double tol);
  int next_neighbour(const std::vector<Disk> &disks, int cur, int prev, Side side) const;
  void bin_segments(const Polyline &polyline, Platens platens, double bin_height);
  int bin_of(double y) const;
  bool outside_binned(double x, double y, const Polyline &polyline, Side side) const;

  std::vector<int> cell_start_, cell_items_, cell_of_; // cell_of_: hash bucket
  std::vector<long long> cell_x_, cell_y_;
  int bucket_of(long long cx, long long cy) const;
  // Neighbours (gap <= tol) of disk i, found on first use and cached until the
  // next find(): the walk visits a few hundred disks of a band of thousands.
  const int *neighbours(int i, int &count) const;

  const std::vector<Disk> *disks_ = nullptr;
  double tol_ = 0.0, cell_ = 1.0;
  std::size_t nbucket_ = 16;
  mutable std::vector<int> nb_start_, nb_count_, nb_pool_;
  std::vector<int> next_slot_; // counting sort: the next free slot of each cell / slab
  std::vector<int> candidates_;
  std::vector<int> chain_pos_; // position in the current chain or -1
  std::vector<char> pruned_, visited_;
  std::vector<int> chain_, walked_; // walked_: disks ever pushed in the current walk
  double rmax_ = 0.0;
  // Polyline segments by horizontal slab, for the escapee parity test.
  std::vector<int> bin_start_, bin_items_;
  std::vector<double> bin_xmin_, bin_xmax_; // x range of each slab's segments
  double bin_lo_ = 0.0, bin_h_ = 1.0;
  int nbin_ = 1;
};

// The relations a chain search depends on, as the search tests them: a
// directed link a -> b (a's neighbour list holds b), and disks touching the
// platens. Exposed so that the detection watch (below) uses the very same
// floating-point expressions.
inline bool link_from(const Disk &a, const Disk &b, double tol)
{
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double dist = std::sqrt(dx * dx + dy * dy);
  return dist > 0.0 && dist - a.r - b.r <= tol;
}
inline bool touches_bottom(const Disk &d, Platens p, double tol)
{
  return d.y - d.r - p.lo <= tol;
}
inline bool touches_top(const Disk &d, Platens p, double tol)
{
  return p.hi - (d.y + d.r) <= tol;
}

// When may a detection be skipped? A ChainFinder result depends only on (i) the
// links from the disks the walk stood on (r.visited: the walk looks at nothing
// else, so with these unchanged it takes the same path), (ii) which disks touch
// each platen, (iii) the x order of the start candidates ahead of the start
// disk; the walk's angular choices and
// the escapee test cannot change while these hold (two neighbours of a disk
// cannot swap their angular order, nor a disk cross a chain segment, without
// overlapping a chain disk, which is a new link). Relations within `budget`
// of their threshold at the detection are watched exactly every step; every
// other one needs a relative displacement of at least `budget` to flip, which
// the caller bounds by the largest displacement of a band disk (and of the
// platens) since the detection. Disks entering the band are not watched: the
// band reaches 4 D50 inside the outermost disks and the walk stays at the edge.
struct DetectionWatch {
  struct Pair {
    int i, j;
    bool ij, ji;
  }; // link_from(i, j), link_from(j, i)
  struct PlatenContact {
    int i;
    bool bottom, touching;
  };
  struct Ahead {
    int start, other;
  }; // start stays ahead of other in x
  double budget = 0.0;
  bool always = true; // the result cannot be watched: detect every step
  std::vector<Pair> pairs;
  std::vector<PlatenContact> platen_contacts;
  std::vector<Ahead> ahead;
  std::vector<int> disks;            // every band index the relations refer to, ascending
  std::vector<char> visited_scratch; // kept so that a detection allocates nothing
  std::vector<int> by_y_scratch;
};

// Records the watch of a successful result `r` of ChainFinder::find on `band`.
void watch_detection(const std::vector<Disk> &band, const ChainResult &r, Platens platens,
                     double tol, double budget, DetectionWatch &out);

// True when a watched relation differs at the positions in `now` (indexed like
// the band; only the entries of watch.disks are read) and platens `platens`.
bool watched_relation_changed(const DetectionWatch &watch, const std::vector<Disk> &now, Side side,
                              Platens platens, double tol);

// P_0 = (x_first, ylo), P_k = contact point of chain disks k-1 and k (0-based),
// P_n = (x_last, yhi). Used after find() and on steps where a kept chain is
// re-evaluated at current positions. Empty chain -> empty polyline.
void polyline_from_chain(const std::vector<Disk> &disks, const std::vector<int> &chain,
                         Platens platens, Polyline &out);
Polyline polyline_from_chain(const std::vector<Disk> &disks, const std::vector<int> &chain,
                             Platens platens);

// One force per chain disk (disk k owns segment P_k -> P_{k+1}), pointing inward:
// Right F = p t (-dy, dx), Left F = p t (dy, -dx). Their sum is exactly (to
// round-off) p t (-Dy, Dx) on the Right and p t (Dy, -Dx) on the Left with
// D = polyline.back() - polyline.front().
void chain_forces(const Polyline &polyline, Side side, double pressure, double thickness,
                  std::vector<Eigen::Vector2d> &out);
std::vector<Eigen::Vector2d> chain_forces(const Polyline &polyline, Side side, double pressure,
                                          double thickness);

// p t 2r horizontally inward (-x on Right, +x on Left).
Eigen::Vector2d escapee_force(const Disk &d, Side side, double pressure, double thickness);

// Parity of a horizontal ray cast outward (+x Right, -x Left) from p against the
// side's polyline: true when p is outside the sample. Meaningful for
// polyline.front().y < p.y < polyline.back().y.
bool outside_polyline(const Eigen::Vector2d &p, const Polyline &polyline, Side side);

// Area of the polygon left polyline (bottom->top) + right polyline (top->bottom),
// closed along the platens. Oriented so a normal sample is positive; a negative
// value means the two sides cross.
double sample_area(const Polyline &left, const Polyline &right);
// Area between one side's polyline and a straight opposite boundary x = x_wall
// (for a sample with a membrane on one side only); positive for a normal sample.
double side_area(const Polyline &polyline, Side side, double x_wall);
// x_right(y) - x_left(y) using the outermost crossing of each polyline with the
// horizontal line at y (max x on the right, min x on the left). NaN when a
// polyline does not cross y. Mean width = sample_area / (yhi - ylo).
double width_at(double y, const Polyline &left, const Polyline &right);
// Outermost x where the polyline crosses the horizontal line at y, NaN if none.
double outermost_x_at(double y, const Polyline &polyline, Side side);

// Band selection on local particles, so the band follows the current edge.
// Usage per step: reset(); add() each local disk; MPI_Allreduce(extents().data(),
// n, MPI_DOUBLE, side == Right ? MPI_MAX : MPI_MIN); then contains() per local disk.
// Empty slices hold lowest() (Right) / max() (Left) so the reduction needs no
// special case.
class BandSlices {
 public:
  // Slices of height h from ylo up to yhi (at least one). h > 0.
  void reset(Side side, Platens platens, double h);
  void add(double x, double y, double r);
  std::vector<double> &extents() { return extent_; }
  const std::vector<double> &extents() const { return extent_; }
  // clamped to [0, n-1]; inline with the two below: they run for every local
  // disk at every detection
  int slice_of(double y) const
  {
    const double f = std::floor((y - ylo_) * inv_h_);
    const double last = static_cast<double>(extent_.size()) - 1.0;
    if (!(f > 0.0)) return 0; // also NaN
    return static_cast<int>(std::min(f, last));
  }
  // Optional, after the reduction: tabulates outer_edge_near per slice, so that
  // contains() costs one lookup per disk.
  void finish();
  // Outermost extent of the slice of y and its two neighbours.
  double outer_edge_near(double y) const;
  // The same for a slice index (after finish(): a lookup), and the slice count.
  double edge_near_slice(int slice) const { return edge_of_slice(slice); }
  int count() const { return static_cast<int>(extent_.size()); }
  Side side() const { return side_; }
  // True when the disk reaches to within `width` of outer_edge_near(y), i.e.
  // x + r >= edge - width (Right), x - r <= edge + width (Left).
  bool contains(double x, double y, double r, double width) const;
  // The same with the slice of y already known (slice_of is the same for both
  // sides of one sample, so a caller computes it once per disk).
  void add_in_slice(int slice, double x, double r)
  {
    double &e = extent_[static_cast<std::size_t>(slice)];
    e = side_ == Side::Right ? std::max(e, x + r) : std::min(e, x - r);
  }
  bool contains_in_slice(int slice, double x, double r, double width) const
  {
    // The disk itself bounds the edge, so an empty neighbourhood never rejects it.
    const double e = edge_of_slice(slice);
    if (side_ == Side::Right) return x + r >= std::max(e, x + r) - width;
    return x - r <= std::min(e, x - r) + width;
  }

 private:
  double edge_of_slice(int slice) const
  {
    if (near_.size() == extent_.size()) return near_[static_cast<std::size_t>(slice)];
    return outer_edge_near(ylo_ + (slice + 0.5) * h_);
  }

  Side side_ = Side::Right;
  double ylo_ = 0.0, h_ = 1.0, inv_h_ = 1.0;
  std::vector<double> extent_;
  std::vector<double> near_; // outer edge of each slice and its neighbours, after finish()
};

} // namespace membrane

#endif
