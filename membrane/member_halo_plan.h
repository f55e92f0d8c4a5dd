// Which members' records a rank needs each step and from whom (membrane/member_halo.h):
// the membrane's cells (facets in 3D, segments in 2D) over member indices, the members
// within k rings of a rank's own, and the send and receive lists of the exchange. No
// LIGGGHTS here: unit-tested in tests/unit/membrane_layer.
//
// A rank needs the members within `rings` rings of the members it owns (ring 1: the
// members sharing a cell with one; fix membrane3d: 2, the loads on a sphere depend on the
// facets around it, whose corners move along normals that depend on their own facets).
// Ring distance is symmetric, so rank s sends member m to rank r exactly when m is
// within `rings` rings of a member r owns: both ranks compute the same list from the same
// owner map and cells, in ascending member order, and no count is exchanged.
#ifndef LIGGGHTS_MEMBRANE_MEMBER_HALO_PLAN_H
#define LIGGGHTS_MEMBRANE_MEMBER_HALO_PLAN_H

#include <cstddef>
#include <vector>

namespace membrane {

class MemberCells {
 public:
  MemberCells() = default;
  // `cells`: `stride` member indices each, below `members` (a member may repeat in a cell:
  // a sphere and its image). Throws std::invalid_argument for an index out of range.
  MemberCells(std::size_t members, const std::vector<int> &cells, int stride);

  std::size_t members() const { return start_.empty() ? 0 : start_.size() - 1; }
  std::size_t cells() const { return stride_ ? cells_.size() / stride_ : 0; }
  int stride() const { return stride_; }
  const int *cell(std::size_t c) const { return &cells_[c * stride_]; }
  // the cells on member m, ascending, each once
  const int *cells_begin(int m) const { return &on_[start_[m]]; }
  const int *cells_end(int m) const { return &on_[start_[m + 1]]; }

  // The members within `rings` rings of `seeds` (ring 0: the seeds themselves), ascending.
  std::vector<int> within(const std::vector<int> &seeds, int rings) const;
  // The cells on any of `members`, ascending.
  std::vector<int> cells_on(const std::vector<int> &members) const;
  double memory_usage() const;

 private:
  int stride_ = 0;
  std::vector<int> cells_;
  std::vector<int> start_, on_; // member m's cells: on_[start_[m] .. start_[m + 1])
  mutable std::vector<unsigned> mark_; // scratch of within/cells_on (a stamp per call)
  mutable unsigned stamp_ = 0;
  unsigned next_stamp() const;
};

struct HaloPlan {
  std::vector<int> owned;  // the members this rank owns, ascending
  std::vector<int> needed; // within `rings` rings of them (owned included), ascending
  std::vector<int> missing; // needed members no rank owns (lost): never delivered
  // the exchange, by rank: member indices ascending, with their positions in owned
  // (sent) and needed (received)
  std::vector<int> to, from;
  std::vector<std::vector<int>> send, send_slot, recv, recv_slot;
  std::vector<int> own_slot; // the position in needed of each owned member
};

double memory_usage(const HaloPlan &plan);

// The plan of rank `me` from the owner of each member (-1: none).
HaloPlan plan_halo(const MemberCells &cells, const std::vector<int> &owner, int me, int rings);

} // namespace membrane

#endif
