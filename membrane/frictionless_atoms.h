// The keyword 'frictionless T' of the membranes: the membrane particles wear atom
// type T (no friction with any type) while they are on the membrane, and their own
// type again when they leave it. Between runs and in restart files every particle
// carries its own type: a run, a write_data, an unfix or a restart read without the
// fix see the true sample. Ghost copies are switched too: a ghost's type is otherwise
// refreshed only when the neighbour list is rebuilt. The own types are known on every
// rank (gathered with the particles), so a particle that moved to another rank gets
// its own type back there.
#ifndef LIGGGHTS_MEMBRANE_FRICTIONLESS_ATOMS_H
#define LIGGGHTS_MEMBRANE_FRICTIONLESS_ATOMS_H

#include <map>
#include <vector>

#include "pointers.h"

#include "atom_id.h"

class FrictionlessAtoms : protected LAMMPS_NS::Pointers {
 public:
  explicit FrictionlessAtoms(LAMMPS_NS::LAMMPS *lammps) : Pointers(lammps) {}
  void set_type(int type) { type_ = type; } // 0: the particles keep their types
  int type() const { return type_; }

  // The membrane particles are now `tags` (ascending), whose current types are
  // `types`: those that left take their own type back, the others wear type T.
  void wear(const std::vector<AtomId> &tags, const std::vector<int> &types);
  // Every particle its own type (end of a run, unfix, a fresh detection).
  void restore();
  bool applied() const { return applied_; }

  // write_restart: the owned membrane particles take their own type before
  // LIGGGHTS packs them, and type T again once each is packed.
  void restore_for_restart();
  void packed(int i);

  double memory_usage() const;

 private:
  void set_all_copies(AtomId tag, int type);

  int type_ = 0;
  bool applied_ = false;
  std::map<AtomId, int> own_type_; // membrane particle -> its own type
  std::vector<char> restored_;     // local atoms restore_for_restart gave their own type
};

#endif
