#ifndef LIGGGHTS_MEMBRANE_STABILITY_CHECKS_H
#define LIGGGHTS_MEMBRANE_STABILITY_CHECKS_H
// Numerical-stability measures of an explicit DEM step (no LIGGGHTS), shared by
// fix stability/guard and fix membrane2d. Each returns a dimensionless number
// whose safe range is stated where it is defined, and the decisions taken on
// them are made here too, so a style only gathers, reduces and reports.

#include <cstddef>

#include "stability_limits.h"

namespace stability {

// The limits and the contact time scale: common/stability_limits.h

// Inertial number I = |rate| d sqrt(rho / p) of a sheared granular sample
// (GDR MiDi 2004): quasi-static below 1e-3. p <= 0 -> +inf.
double inertial_number(double strain_rate, double diameter, double density, double pressure);

// Distance a particle moves in one step, as a fraction of its radius: |v| dt / r
// (in 2D vz is 0). A quasi-static test moves particles well below 1e-3 of their
// radius per step; several percent means the contacts are no longer resolved.
double step_fraction(double vx, double vy, double vz, double dt, double radius);

// Overlap of two particles as a fraction of the smaller radius: (ri + rj - |xi - xj|)
// / min(ri, rj); negative when they do not touch.
double overlap_fraction(double dx, double dy, double dz, double ri, double rj);

// One pass over the owned atoms of a group: the atoms whose radius (or mass) is
// not a finite number > 0 (a fault of the input: |v| dt / r means nothing for
// them), the atoms with a non-finite position, velocity or force, and the
// particle that moves the largest fraction of its radius per step. Arrays as
// LIGGGHTS keeps them (x[i][0..2] etc.); `in_group` masks the atoms to look at
// (mask[i] & groupbit); rmass may be null (no per-atom mass to check). The atom
// each count names is the one with the smallest tag (tag null: index), so that
// it does not depend on how the atoms are spread over ranks; of the non-finite
// ones an atom whose position or velocity is not finite is named before one
// whose force only is (a non-finite velocity makes the contact forces of its
// neighbours non-finite too: the cause is named, not its neighbours).
enum class NonFinite { None, Position, Velocity, Force };
struct AtomScan {
  long nonfinite = 0;                     // atoms with a non-finite x, v or f
  long first_nonfinite = -1;              // index of the one to name (see above), -1 if none
  NonFinite first_kind = NonFinite::None; // what of it is not finite (x before v before f)
  long bad_size = 0;                      // atoms whose radius or mass is not finite and > 0
  long first_bad_size = -1;               // index of the one to name, -1 if none
  double max_step_fraction = 0;           // max |v| dt / r over finite atoms of a valid size
  long argmax_step = -1; // its index (of equal ones the smallest tag), -1 if no atom
};

AtomScan scan_atoms(std::size_t n, const double *const *x, const double *const *v,
                    const double *const *f, const double *radius, const int *mask, int groupbit,
                    double dt, const double *rmass = nullptr, const int *tag = nullptr);

// What the largest |v| dt / r of a check means against the 'move' limit: within
// it; above it but below STEP_FRACTION_BLOWN_UP (a strict limit stops a run
// that need not be unstable); above both (the run has blown up).
enum class StepVerdict { Within, AboveLimit, BlownUp };
StepVerdict judge_step_fraction(double fraction, double limit);

// The largest particle-particle overlap (overlap_fraction) over a neighbour list as
// LIGGGHTS keeps it: ilist[0..inum), numneigh[i], firstneigh[i][..] (& neighmask
// gives the index), both atoms of a pair in the group. Touching pairs only: 0
// and no pair when no two particles of the group overlap.
struct OverlapScan {
  double max_fraction = 0;
  long i = -1, j = -1; // the pair (i from ilist), -1 if none
};

// With `tag`, of equal overlaps the pair with the smaller (lower tag, higher tag)
// is kept, so the pair named does not depend on the order of the lists (nor on the
// ranks: see fix stability/guard); without, the first found.
OverlapScan scan_overlaps(int inum, const int *ilist, const int *numneigh,
                          const int *const *firstneigh, int neighmask, const double *const *x,
                          const double *radius, const int *mask, int groupbit,
                          const int *tag = nullptr);

// The key of a pair of tags for choosing among equal overlaps: (lower << 32) | higher.
long long pair_key(int tag_a, int tag_b);

// Whether a measure that is warned about once is to be warned about now: it
// exceeds its limit and has not been warned about before.
bool warn_once_now(double value, double limit, bool warned_before);

// The inertial number of 'inertial R P' once R and P are known: R must be
// finite and >= 0, P finite and > 0, and I finite (a tiny P makes it overflow).
enum class InertialStatus { Ok, BadRate, BadPressure, Overflow };
struct InertialCheck {
  InertialStatus status;
  double value; // inertial_number(); 0 unless status is Ok
};
InertialCheck check_inertial_number(double strain_rate, double pressure, double diameter,
                                    double density);

} // namespace stability

#endif
