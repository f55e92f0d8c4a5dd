// What fix membrane3d's keyword 'frictionless T' does to the atoms: the membrane
// spheres wear type T (no friction) while they are on the membrane, and their own
// type again when they leave it. Between runs and in restart files every sphere
// carries its own type: a run, a write_data, an unfix or a restart read without
// this fix see the true sample. Ghost copies are switched too: a ghost's type is
// otherwise refreshed only when the neighbour list is rebuilt. The own types are
// known on every rank (gathered with the spheres), so a sphere that moved to
// another rank gets its own type back there.
#ifndef LIGGGHTS_MEMBRANE_MEMBRANE3D_TYPES_H
#define LIGGGHTS_MEMBRANE_MEMBRANE3D_TYPES_H

#include <map>
#include <vector>

#include "pointers.h"

class Membrane3dTypes : protected LAMMPS_NS::Pointers {
 public:
  explicit Membrane3dTypes(LAMMPS_NS::LAMMPS *lammps) : Pointers(lammps) {}
  void set_type(int type) { type_ = type; } // 0: the spheres keep their types
  int type() const { return type_; }

  // The membrane spheres are now `tags` (ascending), whose current types are `types`:
  // those that left take their own type back, the others wear the frictionless type.
  void change(const std::vector<int> &tags, const std::vector<int> &types);
  // Every sphere its own type (end of a run, unfix, a fresh detection).
  void restore();
  bool applied() const { return applied_; }

  // write_restart: the owned membrane spheres take their own type before LIGGGHTS
  // packs them, and the frictionless one again once each is packed.
  void restore_for_restart();
  void packed(int i);

 private:
  void set_all_copies(int tag, int type);

  int type_ = 0;
  bool applied_ = false;
  std::map<int, int> own_type_; // membrane sphere tag -> its own type
  std::vector<char> restored_;  // local atoms restore_for_restart gave their own type
};

#endif
