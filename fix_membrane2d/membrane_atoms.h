#ifndef LIGGGHTS_MEMBRANE_MEMBRANE_ATOMS_H
#define LIGGGHTS_MEMBRANE_MEMBRANE_ATOMS_H

// What fix membrane2d does to the LIGGGHTS atoms: the membrane forces on the
// owned chain disks and escapees, and their per-atom flags. (The frictionless
// type the chain disks wear: membrane/frictionless_atoms.h.)

#include <vector>

#include "pointers.h"

#include "membrane_gather.h"
#include "membrane_state.h"

class MembraneAtoms : protected LAMMPS_NS::Pointers {
 public:
  explicit MembraneAtoms(LAMMPS_NS::LAMMPS *lammps) : Pointers(lammps) {}
  // The loads on the owned chain disks, and the escapees pushed back.
  void add_forces(const membrane::SideChain (&chains)[2], const membrane::SideData (&sides)[2],
                  const membrane::SideLoad (&loads)[2], double pressure, double thickness);
  // Per-atom flags (LEFT_CHAIN, RIGHT_CHAIN, ESCAPEE, else 0) of the owned atoms.
  enum Flag { NONE = 0, LEFT_CHAIN = 1, RIGHT_CHAIN = 2, ESCAPEE = 3 };
  void flags(const membrane::SideChain (&chains)[2], double *&flag, int &capacity);
};

#endif
