#include "membrane_atoms.h"

#include <algorithm>

#include "atom.h"
#include "memory.h"

using membrane::SideChain;

void MembraneAtoms::change_chain(const std::vector<long> &old_tags,
                                 const std::vector<long> &new_tags, const std::vector<int> &chain,
                                 const MembraneSideData &side)
{
  if (type_ <= 0) return;
  for (int idx : chain)
    if (side.band_type[idx] != type_) own_type_[side.band[idx].tag] = side.band_type[idx];
  switch_types(old_tags, new_tags);
}

void MembraneAtoms::apply(const SideChain (&chains)[2], const MembraneSideData (&sides)[2])
{
  applied_ = true;
  if (type_ <= 0) return;
  for (const MembraneSideData &s : sides)
    for (std::size_t c = 0; c < s.chain_disks.size(); c++)
      if (s.chain_types[c] != type_) own_type_.emplace(s.chain_disks[c].tag, s.chain_types[c]);
  for (const SideChain &s : chains) switch_types({}, s.chain_tags);
}

void MembraneAtoms::restore(const SideChain (&chains)[2])
{
  if (applied_ && type_ > 0)
    for (const SideChain &s : chains) switch_types(s.chain_tags, {});
  applied_ = false;
}

void MembraneAtoms::restore_for_restart(const SideChain (&chains)[2])
{
  const int nlocal = atom->nlocal;
  restored_.assign(nlocal, 0);
  if (applied_ && type_ > 0)
    for (const SideChain &s : chains)
      for (long tag : s.chain_tags) {
        const int i = atom->map(static_cast<int>(tag));
        const auto it = own_type_.find(tag);
        if (i < 0 || i >= nlocal || it == own_type_.end() || atom->type[i] != type_) continue;
        atom->type[i] = it->second;
        restored_[i] = 1;
      }
  applied_ = false; // pre_force switches the disks a region write skipped
}

void MembraneAtoms::packed(int i)
{
  if (i < static_cast<int>(restored_.size()) && restored_[i]) {
    atom->type[i] = type_;
    restored_[i] = 0;
  }
}

void MembraneAtoms::switch_types(const std::vector<long> &old_tags,
                                 const std::vector<long> &new_tags)
{
  if (type_ <= 0) return;
  for (const auto &change : membrane::type_changes(old_tags, new_tags, own_type_, type_))
    for (int i = atom->map(static_cast<int>(change.first)); i >= 0; i = atom->sametag[i])
      atom->type[i] = change.second;
}

void MembraneAtoms::add_forces(const SideChain (&chains)[2], const MembraneSideData (&sides)[2],
                               const membrane::SideLoad (&loads)[2], double pressure,
                               double thickness)
{
  double **f = atom->f;
  const int nlocal = atom->nlocal;
  for (int k = membrane::LEFT; k <= membrane::RIGHT; k++) {
    if (!chains[k].active) continue;
    const std::vector<membrane::Disk> &chain = sides[k].chain_disks;
    for (std::size_t c = 0; c < chain.size(); c++) {
      const int i = atom->map(static_cast<int>(chain[c].tag));
      if (i < 0 || i >= nlocal) continue;
      f[i][0] += loads[k].forces[c].x();
      f[i][1] += loads[k].forces[c].y();
    }
    for (long tag : chains[k].escaped_tags) {
      const int i = atom->map(static_cast<int>(tag));
      if (i < 0 || i >= nlocal) continue;
      const membrane::Disk d{tag, atom->x[i][0], atom->x[i][1], atom->radius[i]};
      const Eigen::Vector2d push = membrane::escapee_force(d, chains[k].side, pressure, thickness);
      f[i][0] += push.x();
      f[i][1] += push.y();
    }
  }
}

void MembraneAtoms::flags(const SideChain (&chains)[2], double *&flag, int &capacity)
{
  if (atom->nmax > capacity) {
    memory->destroy(flag);
    capacity = atom->nmax;
    memory->create(flag, capacity, "membrane2d:flag");
  }
  const int nlocal = atom->nlocal;
  std::fill(flag, flag + nlocal, 0.0);
  auto mark = [&](long tag, double value) {
    const int i = atom->map(static_cast<int>(tag));
    if (i >= 0 && i < nlocal) flag[i] = value;
  };
  for (int k = membrane::LEFT; k <= membrane::RIGHT; k++) {
    if (!chains[k].active) continue;
    for (long tag : chains[k].chain_tags) mark(tag, k == membrane::LEFT ? LEFT_CHAIN : RIGHT_CHAIN);
    for (long tag : chains[k].escaped_tags) mark(tag, ESCAPEE);
  }
}

double MembraneAtoms::memory_usage() const
{
  return own_type_.size() * (sizeof(long) + sizeof(int) + 32) + restored_.capacity();
}
