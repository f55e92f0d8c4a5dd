// The side bands of a detection without a pass over every disk of a rank.
//
// A detection needs the disks within the band width of the outer edge of each
// side (BandSlices). Finding them by looking at every disk costs O(N/P) per
// detection, and in a large sample under load `every auto` detects at most
// steps. BandCandidates keeps, after such a full pass, the disks within the
// band width plus a margin of the edges (the candidates) and, per fixed
// horizontal strip of the box, the outermost extent of all the others. While
// no disk has moved more than `motion` since (the caller knows that bound:
// LIGGGHTS rebuilds its neighbour lists before any atom moves half a skin),
// the next detections look at the candidates only and check with the strips,
// in O(strips), that none of the others can be in a band or bound an edge:
// then the bands are exactly those of a full pass. When the check fails the
// caller makes a full pass again. No LIGGGHTS.
#ifndef LIGGGHTS_MEMBRANE_MEMBRANE_BAND_CACHE_H
#define LIGGGHTS_MEMBRANE_MEMBRANE_BAND_CACHE_H

#include <vector>

#include "membrane_chain.h"

namespace membrane {

// One disk as the cache sees it: its index in the caller's arrays.
struct BandDisk {
  int index;
  double x, y, r;
};

class BandCandidates {
 public:
  // After a full pass: `disks` are all the rank's disks of the group, `left` /
  // `right` the finished slices of the active sides (nullptr: inactive, e.g.
  // both the same slicing of the platens), `width` the band width, `margin`
  // how much further in candidates reach, `motion` the largest displacement
  // allowed before the cache is stale, [ybox_lo, ybox_hi] the range of y the
  // strips cover (the box: a disk outside falls into the end strips).
  void build(const std::vector<BandDisk> &disks, const BandSlices *left, const BandSlices *right,
             double width, double margin, double motion, double ybox_lo, double ybox_hi);
  void clear() { valid_ = false; }
  // After build: the key of the rank's atoms the candidates index (LIGGGHTS'
  // neighbour list builds so far, the local atom count) and the active sides.
  void stamp(long long neighbour_builds, int nlocal, const bool active[2]);
  // Whether the candidates may serve a detection with bands of `width` on the
  // `active` sides while the key is this: no atom changed rank or index since.
  bool usable(double width, const bool active[2], long long neighbour_builds, int nlocal) const;
  // LIGGGHTS rebuilds its neighbour lists (and only then moves atoms between
  // ranks or reorders them) before any atom has moved half a skin from where
  // it was at the last build when it checks every step (neigh_modify every 1
  // delay 0 check yes): between two builds no disk moves more than a skin.
  // Without that bound (these settings) every detection is a full pass.
  static bool motion_bounded(int every, int delay, bool check, bool build_once);
  const std::vector<int> &candidates() const { return candidates_; }

  // Given the finished slices of this detection (their extents computed from
  // the candidates, merged over the ranks): true when no other disk of this
  // rank, anywhere within `motion` of where it was at the build, can be in a
  // band (within width of the edge near its slice) or be more outward than
  // the candidates of its slice. Strictly, with a slack for rounding.
  bool still_covers(const BandSlices *left, const BandSlices *right) const;

 private:
  bool valid_ = false;
  long long neighbour_builds_ = -1;
  int nlocal_ = -1;
  bool active_[2] = {false, false};
  double width_ = 0.0, motion_ = 0.0;
  double ylo_ = 0.0, strip_ = 1.0;
  std::vector<int> candidates_;
  // per strip, over the non-candidates: the smallest x - r, the largest x + r
  std::vector<double> inner_left_, inner_right_;
};

} // namespace membrane

#endif
