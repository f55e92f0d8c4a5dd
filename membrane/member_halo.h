// The members' records each rank needs each step (fix membrane3d now, fix membrane2d
// later): after a detection every rank holds the membrane's topology (its members' IDs
// and cells, replicated); each step each rank gets the records (a few doubles each:
// position, radius) of the members within k rings of those it owns, from their owners,
// and nothing more (membrane/member_halo_plan.h).
//
// Complete: the owner map is made from every rank's owned members (an allgather of
// member indices, O(M), only when a rank's set changed). Each step each rank checks that
// it still owns, in the group, every member it owned (O(its share)); the flags are
// reduced, so all ranks refresh together. Ownership partitions the atoms: when no rank
// lost one of its members, no rank gained one either (a member owned by no rank, lost or
// gone from the group, keeps the map refreshed every step until the next detection, and
// is counted: present() < members(), the caller detects again). Atoms that migrate, a
// periodic image or a ghost play no part: members are found by ID among owned atoms
// only, and their owners send the positions they hold.
#ifndef LIGGGHTS_MEMBRANE_MEMBER_HALO_H
#define LIGGGHTS_MEMBRANE_MEMBER_HALO_H

#include <functional>
#include <utility>
#include <vector>

#include "atom_id.h"
#include "lammps.h"
#include "member_halo_plan.h"

class MemberHalo {
 public:
  // `width` doubles per member's record, `rings` around the owned members
  MemberHalo(LAMMPS_NS::LAMMPS *lmp, int width, int rings);

  // After a detection (or a restart): the members and their cells (member indices,
  // `stride` each). The plan is made at the next refresh (on every rank: collective).
  void set_members(const std::vector<AtomId> &tags, const std::vector<int> &cells, int stride);
  std::size_t members() const { return tags_.size(); }

  // This step (collective): which members this rank owns (in group `groupbit`), the plan
  // made anew when any rank's changed. `fault(i)` is nonzero for an owned atom i that
  // is unusable; `flag` is this rank's flag to reduce along. Returns the maximum over
  // ranks of the faults and of the flags.
  struct Step {
    bool fault = false;
    int flag = 0;
  };
  Step refresh(int groupbit, const std::function<int(int)> &fault, int flag = 0);
  // members owned by some rank (after refresh)
  std::size_t present() const { return present_; }
  const membrane::HaloPlan &plan() const { return plan_; }
  const membrane::MemberCells &cells() const { return cells_; }
  // the local index of each owned member (plan().owned's order)
  const std::vector<int> &owned_atoms() const { return owned_atoms_; }

  // The records of plan().needed (in its order), `pack(i, out)` filling those of owned
  // atom i: point to point with the ranks of the plan.
  void exchange(const std::function<void(int, double *)> &pack, std::vector<double> &records);
  // The owned member (index) of the largest distance(member, owned atom) over all ranks
  // (collective; the lowest index of a tie), and that distance (0 and member 0: none).
  std::pair<double, int> farthest(const std::function<double(int, int)> &distance) const;

  // Every member's record on rank 0 (in member order; empty elsewhere): output steps.
  void gather_on_root(const std::function<void(int, double *)> &pack,
                      std::vector<double> &records);

  double memory_usage() const
  {
    return static_cast<double>(tags_.capacity() * sizeof(AtomId) +
                               owned_atoms_.capacity() * sizeof(int)) +
           cells_.memory_usage() + membrane::memory_usage(plan_);
  }

  // where to add the bytes this rank receives (exchanges, owner maps, gathers; null:
  // nowhere), and the owner maps made
  double *received = nullptr;
  double plans_made = 0.0;

 private:
  LAMMPS_NS::LAMMPS *lmp_;
  int width_, rings_;
  std::vector<AtomId> tags_;
  membrane::MemberCells cells_;
  membrane::HaloPlan plan_;
  std::vector<int> owned_atoms_;
  std::size_t present_ = 0;
  bool stale_ = true; // no plan for these members yet
  bool lost_ = false; // the plan has a member no rank owned

  void make_plan(int groupbit);
  void count(double bytes) const
  {
    if (received) *received += bytes;
  }
};

#endif
