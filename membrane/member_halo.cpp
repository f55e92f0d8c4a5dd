#include "member_halo.h"

#include <mpi.h>

#include <algorithm>

#include "atom.h"
#include "comm.h"

#include "owned_atom.h"

using namespace LAMMPS_NS;

namespace {

constexpr int HALO_TAG = 3401;

// the local index of member `tag` when this rank owns it in the group, else -1
int owned_member(Atom *atom, AtomId tag, int groupbit)
{
  const int i = owned_index(atom, tag);
  return i >= 0 && atom->tag[i] == tag && (atom->mask[i] & groupbit) ? i : -1;
}

} // namespace

MemberHalo::MemberHalo(LAMMPS *lmp, int width, int rings)
  : lmp_(lmp), width_(width), rings_(rings)
{
}

void MemberHalo::set_members(const std::vector<AtomId> &tags, const std::vector<int> &cells,
                             int stride)
{
  tags_ = tags;
  cells_ = membrane::MemberCells(tags.size(), cells, stride);
  plan_ = membrane::HaloPlan();
  owned_atoms_.clear();
  stale_ = true;
}

MemberHalo::Step MemberHalo::refresh(int groupbit, const std::function<int(int)> &fault, int flag)
{
  Atom *atom = lmp_->atom;
  int mine[3] = {stale_ || lost_ ? 1 : 0, 0, flag};
  if (!mine[0])
    for (std::size_t k = 0; k < plan_.owned.size() && !mine[0]; k++) {
      owned_atoms_[k] = owned_member(atom, tags_[plan_.owned[k]], groupbit);
      mine[0] = owned_atoms_[k] < 0;
      mine[1] = mine[1] || (!mine[0] && fault(owned_atoms_[k]));
    }
  int any[3];
  MPI_Allreduce(mine, any, 3, MPI_INT, MPI_MAX, lmp_->world);
  if (any[0]) {
    // a new plan on every rank: the faults of the members owned now
    make_plan(groupbit);
    mine[1] = 0;
    for (int i : owned_atoms_) mine[1] = mine[1] || fault(i);
    MPI_Allreduce(&mine[1], &any[1], 1, MPI_INT, MPI_MAX, lmp_->world);
  }
  Step out;
  out.fault = any[1] != 0;
  out.flag = any[2];
  return out;
}

void MemberHalo::make_plan(int groupbit)
{
  Atom *atom = lmp_->atom;
  std::vector<int> owned;
  for (std::size_t m = 0; m < tags_.size(); m++)
    if (owned_member(atom, tags_[m], groupbit) >= 0) owned.push_back(static_cast<int>(m));
  int nprocs = 1, me = 0;
  MPI_Comm_size(lmp_->world, &nprocs);
  MPI_Comm_rank(lmp_->world, &me);
  int n = static_cast<int>(owned.size());
  std::vector<int> counts(nprocs), displs(nprocs, 0);
  MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, lmp_->world);
  for (int r = 1; r < nprocs; r++) displs[r] = displs[r - 1] + counts[r - 1];
  std::vector<int> all(displs.back() + counts.back());
  MPI_Allgatherv(owned.data(), n, MPI_INT, all.data(), counts.data(), displs.data(), MPI_INT,
                 lmp_->world);
  count(sizeof(int) * (static_cast<double>(nprocs) + all.size()));
  std::vector<int> owner(tags_.size(), -1);
  for (int r = 0; r < nprocs; r++)
    for (int k = displs[r]; k < displs[r] + counts[r]; k++) owner[all[k]] = r;
  present_ = all.size();
  plan_ = membrane::plan_halo(cells_, owner, me, rings_);
  owned_atoms_.clear();
  for (int m : plan_.owned) owned_atoms_.push_back(owned_member(atom, tags_[m], groupbit));
  lost_ = present_ < tags_.size();
  stale_ = false;
  plans_made += 1.0;
}

void MemberHalo::exchange(const std::function<void(int, double *)> &pack,
                          std::vector<double> &records)
{
  records.assign(plan_.needed.size() * width_, 0.0);
  std::vector<std::vector<double>> in(plan_.from.size()), out(plan_.to.size());
  std::vector<MPI_Request> requests;
  for (std::size_t k = 0; k < plan_.from.size(); k++) {
    in[k].resize(plan_.recv[k].size() * width_);
    requests.emplace_back();
    MPI_Irecv(in[k].data(), static_cast<int>(in[k].size()), MPI_DOUBLE, plan_.from[k], HALO_TAG,
              lmp_->world, &requests.back());
  }
  for (std::size_t k = 0; k < plan_.to.size(); k++) {
    out[k].resize(plan_.send[k].size() * width_);
    for (std::size_t j = 0; j < plan_.send_slot[k].size(); j++)
      pack(owned_atoms_[plan_.send_slot[k][j]], &out[k][j * width_]);
    requests.emplace_back();
    MPI_Isend(out[k].data(), static_cast<int>(out[k].size()), MPI_DOUBLE, plan_.to[k], HALO_TAG,
              lmp_->world, &requests.back());
  }
  for (std::size_t k = 0; k < plan_.owned.size(); k++)
    pack(owned_atoms_[k], &records[plan_.own_slot[k] * width_]);
  MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE);
  for (const std::vector<double> &v : in) count(sizeof(double) * static_cast<double>(v.size()));
  for (std::size_t k = 0; k < plan_.from.size(); k++)
    for (std::size_t j = 0; j < plan_.recv_slot[k].size(); j++)
      std::copy_n(&in[k][j * width_], width_, &records[plan_.recv_slot[k][j] * width_]);
}

std::pair<double, int> MemberHalo::farthest(const std::function<double(int, int)> &distance) const
{
  struct {
    double distance;
    int member;
  } most{0.0, 0};
  for (std::size_t k = 0; k < owned_atoms_.size(); k++) {
    const int m = plan_.owned[k];
    const double d = distance(m, owned_atoms_[k]);
    if (d > most.distance || (d == most.distance && m < most.member)) most = {d, m};
  }
  MPI_Allreduce(MPI_IN_PLACE, &most, 1, MPI_DOUBLE_INT, MPI_MAXLOC, lmp_->world);
  return {most.distance, most.member};
}

void MemberHalo::gather_on_root(const std::function<void(int, double *)> &pack,
                                std::vector<double> &records)
{
  const int stride = width_ + 1;
  std::vector<double> send(plan_.owned.size() * stride);
  for (std::size_t k = 0; k < plan_.owned.size(); k++) {
    send[k * stride] = plan_.owned[k];
    pack(owned_atoms_[k], &send[k * stride + 1]);
  }
  int nprocs = 1, me = 0;
  MPI_Comm_size(lmp_->world, &nprocs);
  MPI_Comm_rank(lmp_->world, &me);
  int n = static_cast<int>(send.size());
  std::vector<int> counts(nprocs), displs(nprocs, 0);
  MPI_Gather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, lmp_->world);
  for (int r = 1; r < nprocs; r++) displs[r] = displs[r - 1] + counts[r - 1];
  std::vector<double> all(me == 0 ? displs.back() + counts.back() : 0);
  MPI_Gatherv(send.data(), n, MPI_DOUBLE, all.data(), counts.data(), displs.data(), MPI_DOUBLE, 0,
              lmp_->world);
  if (me == 0) count(sizeof(double) * static_cast<double>(all.size() - send.size()));
  records.clear();
  if (me != 0) return;
  records.assign(tags_.size() * width_, 0.0);
  for (std::size_t k = 0; k + stride <= all.size(); k += stride)
    std::copy_n(&all[k + 1], width_, &records[static_cast<std::size_t>(all[k]) * width_]);
}
