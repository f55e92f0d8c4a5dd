#ifndef LIGGGHTS_MEMBRANE_MEMBRANE_ATOMS_H
#define LIGGGHTS_MEMBRANE_MEMBRANE_ATOMS_H

// What fix membrane2d does to the LIGGGHTS atoms: the membrane forces on the
// owned chain disks and escapees, their per-atom flags, and the frictionless
// type the chain disks wear while it runs.
// Between runs and in restart files every disk carries its own type: a run,
// a write_data, an unfix or a restart read without this fix see the true
// sample. Ghost copies are switched too: a ghost's type is otherwise
// refreshed only when the neighbour list is rebuilt.

#include <map>
#include <vector>

#include "pointers.h"

#include "membrane_gather.h"
#include "membrane_state.h"

class MembraneAtoms : protected LAMMPS_NS::Pointers {
 public:
  explicit MembraneAtoms(LAMMPS_NS::LAMMPS *lammps) : Pointers(lammps) {}
  void set_frictionless_type(int type) { type_ = type; } // 0: chain disks keep their type

  // Disks that leave the chain take their own type back, disks of the new one
  // the frictionless type; `side.band_type` holds the types of `chain` (band
  // indices) as every rank saw them when they joined.
  void change_chain(const std::vector<long> &old_tags, const std::vector<long> &new_tags,
                    const std::vector<int> &chain, const MembraneSideData &side);
  // The chain disks take the frictionless type (start of a run, after a restart).
  void apply(const membrane::SideChain (&chains)[2], const MembraneSideData (&sides)[2]);
  // Every disk its own type (end of a run, unfix).
  void restore(const membrane::SideChain (&chains)[2]);
  bool applied() const { return applied_; }
  void forget() { own_type_.clear(); }

  // write_restart: the owned chain disks take their own type before LIGGGHTS
  // packs them, and the frictionless one again once each is packed.
  void restore_for_restart(const membrane::SideChain (&chains)[2]);
  void packed(int i);

  // The loads on the owned chain disks, and the escapees pushed back.
  void add_forces(const membrane::SideChain (&chains)[2], const MembraneSideData (&sides)[2],
                  const membrane::SideLoad (&loads)[2], double pressure, double thickness);
  // Per-atom flags (LEFT_CHAIN, RIGHT_CHAIN, ESCAPEE, else 0) of the owned atoms.
  enum Flag { NONE = 0, LEFT_CHAIN = 1, RIGHT_CHAIN = 2, ESCAPEE = 3 };
  void flags(const membrane::SideChain (&chains)[2], double *&flag, int &capacity);

  double memory_usage() const;

 private:
  void switch_types(const std::vector<long> &old_tags, const std::vector<long> &new_tags);

  int type_ = 0;
  bool applied_ = false;
  std::map<long, int> own_type_; // chain disk tag -> its own (not frictionless) type
  std::vector<char> restored_;   // local atoms restore_for_restart gave their own type
};

#endif
