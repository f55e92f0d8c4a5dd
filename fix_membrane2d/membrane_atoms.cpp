#include "membrane_atoms.h"

#include <algorithm>

#include "atom.h"
#include "memory.h"

using membrane::SideChain;

void MembraneAtoms::add_forces(const SideChain (&chains)[2], const membrane::SideData (&sides)[2],
                               const membrane::SideLoad (&loads)[2], double pressure,
                               double thickness)
{
  double **f = atom->f;
  const int nlocal = atom->nlocal;
  for (int k = membrane::LEFT; k <= membrane::RIGHT; k++) {
    if (!chains[k].active) continue;
    const std::vector<membrane::Disk> &chain = sides[k].chain_disks;
    for (std::size_t c = 0; c < chain.size(); c++) {
      const int i = atom->map(chain[c].tag);
      if (i < 0 || i >= nlocal) continue;
      f[i][0] += loads[k].forces[c].x();
      f[i][1] += loads[k].forces[c].y();
    }
    for (AtomId tag : chains[k].escaped_tags) {
      const int i = atom->map(tag);
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
  auto mark = [&](AtomId tag, double value) {
    const int i = atom->map(tag);
    if (i >= 0 && i < nlocal) flag[i] = value;
  };
  for (int k = membrane::LEFT; k <= membrane::RIGHT; k++) {
    if (!chains[k].active) continue;
    for (AtomId tag : chains[k].chain_tags) mark(tag, k == membrane::LEFT ? LEFT_CHAIN : RIGHT_CHAIN);
    for (AtomId tag : chains[k].escaped_tags) mark(tag, ESCAPEE);
  }
}
