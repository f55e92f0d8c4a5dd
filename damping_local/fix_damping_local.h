#ifdef FIX_CLASS

// clang-format off
FixStyle(damping/local,FixDampingLocal)
// clang-format on

#else

#ifndef LIGGGHTS_MEMBRANE_FIX_DAMPING_LOCAL_H
#define LIGGGHTS_MEMBRANE_FIX_DAMPING_LOCAL_H

#include <set>
#include <string>

#include "fix.h"

namespace LAMMPS_NS {

// fix damping/local: PFC's local (non-viscous) damping (Itasca PFC manual;
// Momeni et al. 2024, eq. 5). In post_force, for each owned atom of the group
// and each component, the unbalanced force becomes F + F_d with
// F_d = -alpha |F| sign(v), and the torque T + T_d with T_d = -alpha |T| sign(omega).
// See doc/fix_damping_local.md.
//
// It damps the force as it stands when its post_force runs: LIGGGHTS calls
// post_force in the order the fixes were defined, so define this fix after
// every fix that adds forces (addforce, gravity, wall/gran, membrane2d, ...).
// The law is in local_damping.h, which fixes may follow it and the warning
// about the others in damping_order.h (no LIGGGHTS). The damping force of the
// step is kept per atom (an N x 3 array) for output, e.g. its moment about the
// sample centre: the bias it puts on a boundary stress; LIGGGHTS grows and
// moves it with the atoms (atom->add_callback), so output read between runs,
// after atoms were deleted or created, gives each atom its own value.
class FixDampingLocal : public Fix {
 public:
  FixDampingLocal(class LAMMPS *, int, char **);
  ~FixDampingLocal();
  int setmask();
  void init();
  void setup(int);
  void post_force(int);
  double memory_usage();
  // the per-atom damping force follows its atom (delete_atoms, sorting, migration)
  // and is 0 for an atom created since the last step
  void grow_arrays(int);
  void copy_arrays(int, int, int);
  void set_arrays(int);
  int pack_exchange(int, double *);
  int unpack_exchange(int, double *);

 private:
  const std::string prefix; // of every message: "Fix damping/local (id d): "
  double alpha;
  bool damp_torque;
  double **damping_force;             // F_d of the last step, owned atoms (0 outside the group)
  std::set<std::string> warned_order; // fixes warned about (once each) for their order
};

} // namespace LAMMPS_NS

#endif
#endif
