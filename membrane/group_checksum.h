// Whether a group's atoms changed between two runs of a membrane (fix membrane2d,
// fix membrane3d): a sum over the group of a hash of each atom's ID, type, position
// and radius. The sum does not depend on the order or on the ranks holding the atoms;
// delete_atoms (which renumbers the IDs), create_atoms, set or displace_atoms between
// two runs change it, so that a membrane kept by atom ID is found anew.
#ifndef LIGGGHTS_MEMBRANE_GROUP_CHECKSUM_H
#define LIGGGHTS_MEMBRANE_GROUP_CHECKSUM_H

#include <mpi.h>

#include <cstdint>
#include <cstring>

#include "atom.h"
#include "lammps.h"

// One atom's hash: its ID, type, radius and `dims` coordinates of x.
inline std::uint64_t atom_checksum(long tag, int type, const double *x, int dims, double r)
{
  auto mix = [](std::uint64_t h) { // splitmix64 finaliser
    h += 0x9e3779b97f4a7c15ull;
    h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ull;
    h = (h ^ (h >> 27)) * 0x94d049bb133111ebull;
    return h ^ (h >> 31);
  };
  auto bits = [](double v) {
    std::uint64_t b;
    std::memcpy(&b, &v, sizeof b);
    return b;
  };
  std::uint64_t h = mix(static_cast<std::uint64_t>(tag));
  h = mix(h ^ static_cast<std::uint64_t>(type));
  for (int d = 0; d < dims; d++) h = mix(h ^ bits(x[d]));
  return mix(h ^ bits(r));
}

// The group's sum on every rank (collective).
inline std::uint64_t group_checksum(LAMMPS_NS::LAMMPS *lmp, int groupbit, int dims)
{
  const LAMMPS_NS::Atom *atom = lmp->atom;
  std::uint64_t sum = 0, total = 0;
  for (int i = 0; i < atom->nlocal; i++)
    if (atom->mask[i] & groupbit)
      sum += atom_checksum(atom->tag[i], atom->type[i], atom->x[i], dims, atom->radius[i]);
  MPI_Allreduce(&sum, &total, 1, MPI_UINT64_T, MPI_SUM, lmp->world);
  return total;
}

#endif
