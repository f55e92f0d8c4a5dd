#include "frictionless_atoms.h"

#include "atom.h"

#include "owned_atom.h"

void FrictionlessAtoms::set_all_copies(AtomId tag, int type)
{
  if (tag > atom->map_tag_max) return;
  for (int i = atom->map(tag); i >= 0; i = atom->sametag[i]) atom->type[i] = type;
}

void FrictionlessAtoms::wear(const std::vector<AtomId> &tags, const std::vector<int> &types)
{
  if (type_ <= 0) return;
  std::map<AtomId, int> now;
  for (std::size_t k = 0; k < tags.size(); k++) {
    const auto known = own_type_.find(tags[k]);
    // a particle already on the membrane wears type T: its own type is the one kept
    now[tags[k]] = known != own_type_.end() ? known->second : types[k];
  }
  for (const auto &left : own_type_)
    if (!now.count(left.first)) set_all_copies(left.first, left.second);
  own_type_.swap(now);
  for (const auto &on : own_type_) set_all_copies(on.first, type_);
  applied_ = true;
}

void FrictionlessAtoms::restore()
{
  if (applied_)
    for (const auto &on : own_type_) set_all_copies(on.first, on.second);
  own_type_.clear(); // between runs a type may be set anew: gathered again at the next
  applied_ = false;
}

void FrictionlessAtoms::restore_for_restart()
{
  const int nlocal = atom->nlocal;
  restored_.assign(nlocal, 0);
  if (!applied_) return;
  for (const auto &on : own_type_) {
    const int i = owned_index(atom, on.first);
    if (i < 0 || atom->type[i] != type_) continue;
    atom->type[i] = on.second;
    restored_[i] = 1;
  }
  applied_ = false; // pre_force gives the type again to a particle the write skipped
}

void FrictionlessAtoms::packed(int i)
{
  if (i < static_cast<int>(restored_.size()) && restored_[i]) {
    atom->type[i] = type_;
    restored_[i] = 0;
  }
}

double FrictionlessAtoms::memory_usage() const
{
  // a map node: the pair and about four pointers of the tree
  return static_cast<double>(own_type_.size() * (sizeof(AtomId) + sizeof(int) + 32) +
                             restored_.capacity());
}
