#include "member_halo_plan.h"

#include <algorithm>
#include <map>
#include <stdexcept>
#include <string>

namespace membrane {

MemberCells::MemberCells(std::size_t members, const std::vector<int> &cells, int stride)
  : stride_(stride), cells_(cells), start_(members + 1, 0)
{
  if (stride <= 0 || cells.size() % stride != 0)
    throw std::invalid_argument("cells of " + std::to_string(cells.size()) +
                                " indices in cells of " + std::to_string(stride));
  for (int m : cells)
    if (m < 0 || static_cast<std::size_t>(m) >= members)
      throw std::invalid_argument("a cell has member " + std::to_string(m) + " of " +
                                  std::to_string(members));
  const std::size_t n = this->cells();
  // each cell once per member, in ascending cell order
  for (std::size_t c = 0; c < n; ++c)
    for (int j = 0; j < stride; ++j) {
      const int m = cells_[c * stride + j];
      bool first = true;
      for (int i = 0; i < j; ++i) first = first && cells_[c * stride + i] != m;
      if (first) ++start_[m + 1];
    }
  for (std::size_t m = 0; m < members; ++m) start_[m + 1] += start_[m];
  on_.resize(start_[members]);
  std::vector<int> fill(start_.begin(), start_.end() - 1);
  for (std::size_t c = 0; c < n; ++c)
    for (int j = 0; j < stride; ++j) {
      const int m = cells_[c * stride + j];
      bool first = true;
      for (int i = 0; i < j; ++i) first = first && cells_[c * stride + i] != m;
      if (first) on_[fill[m]++] = static_cast<int>(c);
    }
}

unsigned MemberCells::next_stamp() const
{
  const std::size_t size = std::max(members(), cells());
  if (mark_.size() != size || stamp_ == ~0u) {
    mark_.assign(size, 0);
    stamp_ = 0;
  }
  return ++stamp_;
}

std::vector<int> MemberCells::within(const std::vector<int> &seeds, int rings) const
{
  const unsigned stamp = next_stamp();
  std::vector<int> out;
  for (int m : seeds)
    if (mark_[m] != stamp) {
      mark_[m] = stamp;
      out.push_back(m);
    }
  std::size_t ring_start = 0;
  for (int ring = 0; ring < rings; ++ring) {
    const std::size_t ring_end = out.size();
    for (std::size_t k = ring_start; k < ring_end; ++k)
      for (const int *c = cells_begin(out[k]); c != cells_end(out[k]); ++c)
        for (int j = 0; j < stride_; ++j) {
          const int m = cells_[*c * stride_ + j];
          if (mark_[m] == stamp) continue;
          mark_[m] = stamp;
          out.push_back(m);
        }
    ring_start = ring_end;
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<int> MemberCells::cells_on(const std::vector<int> &members) const
{
  const unsigned stamp = next_stamp();
  std::vector<int> out;
  for (int m : members)
    for (const int *c = cells_begin(m); c != cells_end(m); ++c)
      if (mark_[*c] != stamp) {
        mark_[*c] = stamp;
        out.push_back(*c);
      }
  std::sort(out.begin(), out.end());
  return out;
}

double MemberCells::memory_usage() const
{
  return static_cast<double>((cells_.capacity() + start_.capacity() + on_.capacity()) *
                                 sizeof(int) +
                             mark_.capacity() * sizeof(unsigned));
}

double memory_usage(const HaloPlan &plan)
{
  double bytes = 0.0;
  for (const std::vector<int> *v : {&plan.owned, &plan.needed, &plan.missing, &plan.to,
                                    &plan.from, &plan.own_slot})
    bytes += v->capacity() * sizeof(int);
  for (const auto *lists : {&plan.send, &plan.send_slot, &plan.recv, &plan.recv_slot})
    for (const std::vector<int> &v : *lists) bytes += v.capacity() * sizeof(int);
  return bytes;
}

HaloPlan plan_halo(const MemberCells &cells, const std::vector<int> &owner, int me, int rings)
{
  if (owner.size() != cells.members())
    throw std::invalid_argument("an owner map of " + std::to_string(owner.size()) + " for " +
                                std::to_string(cells.members()) + " members");
  HaloPlan plan;
  for (std::size_t m = 0; m < owner.size(); ++m)
    if (owner[m] == me) plan.owned.push_back(static_cast<int>(m));
  plan.needed = cells.within(plan.owned, rings);
  const auto slot = [](const std::vector<int> &in, int m) {
    return static_cast<int>(std::lower_bound(in.begin(), in.end(), m) - in.begin());
  };
  for (int m : plan.owned) plan.own_slot.push_back(slot(plan.needed, m));
  // received: the needed members of other owners, by owner
  std::map<int, std::vector<int>> from;
  for (int m : plan.needed) {
    if (owner[m] < 0) plan.missing.push_back(m);
    else if (owner[m] != me) from[owner[m]].push_back(m);
  }
  for (auto &r : from) {
    plan.from.push_back(r.first);
    std::vector<int> at;
    for (int m : r.second) at.push_back(slot(plan.needed, m));
    plan.recv.push_back(std::move(r.second));
    plan.recv_slot.push_back(std::move(at));
  }
  // sent: each owned member to the owners of the members within `rings` rings of it
  std::map<int, std::vector<int>> to;
  for (std::size_t k = 0; k < plan.owned.size(); ++k) {
    const int m = plan.owned[k];
    std::vector<int> ranks;
    for (int near : cells.within({m}, rings))
      if (owner[near] >= 0 && owner[near] != me) ranks.push_back(owner[near]);
    std::sort(ranks.begin(), ranks.end());
    ranks.erase(std::unique(ranks.begin(), ranks.end()), ranks.end());
    for (int r : ranks) to[r].push_back(static_cast<int>(k));
  }
  for (auto &r : to) {
    plan.to.push_back(r.first);
    std::vector<int> members;
    for (int k : r.second) members.push_back(plan.owned[k]);
    plan.send.push_back(std::move(members));
    plan.send_slot.push_back(std::move(r.second));
  }
  return plan;
}

} // namespace membrane
