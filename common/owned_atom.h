#ifndef LIGGGHTS_MEMBRANE_OWNED_ATOM_H
#define LIGGGHTS_MEMBRANE_OWNED_ATOM_H

#include "atom.h"

#include "atom_id.h"

// The local index of the atom with ID `tag` when this rank owns it, else -1: an ID
// the map was not set up for (an atom deleted, or created since), a ghost, an atom
// lost. LIGGGHTS keeps the map of owned atoms current between neighbour-list builds.
inline int owned_index(LAMMPS_NS::Atom *atom, AtomId tag)
{
  if (tag <= 0 || tag > atom->map_tag_max) return -1;
  const int i = atom->map(tag);
  return i >= 0 && i < atom->nlocal ? i : -1;
}

#endif
