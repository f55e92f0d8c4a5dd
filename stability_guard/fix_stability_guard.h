#ifdef FIX_CLASS

// clang-format off
FixStyle(stability/guard,FixStabilityGuard)
// clang-format on

#else

#ifndef LIGGGHTS_MEMBRANE_FIX_STABILITY_GUARD_H
#define LIGGGHTS_MEMBRANE_FIX_STABILITY_GUARD_H

#include <string>

#include "fix.h"
#include "scalar_input.h"

namespace LAMMPS_NS {

// fix stability/guard: watches a granular run (2D or 3D) every N steps and stops it
// with an error that says what to change once it has gone unstable (non-finite
// values, a particle moving a large fraction of its radius per step, lost atoms);
// warns once each when the time step, the overlaps or the inertial number
// leave their safe range. See doc/fix_stability_guard.md. The measures and
// decisions are in stability_checks.h, the wording in stability_messages.h (no
// LIGGGHTS); this class gathers the atoms and contacts, reduces over the ranks
// and raises or prints what those return.
class FixStabilityGuard : public Fix {
 public:
  FixStabilityGuard(class LAMMPS *, int, char **);
  int setmask();
  void init();
  void setup(int);
  void end_of_step();
  double compute_vector(int);
  void write_restart(FILE *);
  void restart(char *);

  // global vector layout (1-based in input scripts: f_ID[k]); values of the last check
  enum VectorIndex {
    STEP_FRACTION = 0,
    OVERLAP,
    TIME_STEP_RATIO,
    INERTIAL,
    LOST,
    WARNINGS,
    VECTOR_SIZE
  };

 private:
  const std::string prefix; // of every message: "Fix stability/guard (id g): "
  double move_limit;        // error: a particle moves more than this x its radius in one step
  double overlap_limit;     // warning: overlap / smaller radius
  double time_step_limit;   // warning: dt / sqrt(m_min / k_n)
  double inertial_limit;    // warning: inertial number
  bool check_inertial;
  ScalarInput rate_in, pressure_in;

  double d50, density; // of the group, for the inertial number
  bigint natoms0;      // group atoms at setup
  int maxtag0 = 0;     // their largest tag (later ones were inserted during the run)
  double values[VECTOR_SIZE];
  bool warned_overlap, warned_inertial;
  double warned_dt = 0.0; // the time step last warned about
  int warnings;

  // each check returns its measure; the ones that stop the run raise the error
  // at_start: the checks of the setup of a run (what they find, the input gave)
  void run_checks(bool inertial, bool at_start);
  double check_atoms(bool at_start);
  bigint check_lost_atoms();
  double check_overlaps();
  double check_inertial_number();
  [[noreturn]] void bad_inertial_value(const ScalarInput &in, double value, const char *must);
  bigint count_group_atoms();
  void warn(const std::string &text);
};

} // namespace LAMMPS_NS

#endif
#endif
