#ifndef LIGGGHTS_MEMBRANE_GUARD_MESSAGES_H
#define LIGGGHTS_MEMBRANE_GUARD_MESSAGES_H
// The wording of the stability errors and warnings that depends on numbers
// only (no LIGGGHTS), without the style's prefix: the messages of fix
// stability/guard. The limits they quote are those of common/stability_limits.h, so a
// change there changes every message. Steps and atom IDs are LIGGGHTS' bigint
// and tagint.

#include <string>

#include "stability_checks.h"

namespace stability {

// (the time-step warning: common/stability_limits.h)

// What to change, closing the errors of an unstable run: the time step only
// when dt / sqrt(m_min/k_n) = `time_step_ratio` is above TIME_STEP_SAFE; all
// three when the ratio is unknown (0: no linear stiffness table).
std::string unstable_hint(double time_step_ratio);

// `count` atoms have a non-finite x, v or f, the one named atom `first` (its
// `kind`, AtomScan::first_kind; None: not said). `at_start`: found at the setup
// of a run, before it made a step: the input gave it, not an instability.
std::string nonfinite_error(long count, long long step, int first, double time_step_ratio,
                            NonFinite kind = NonFinite::None, bool at_start = false);

// `count` atoms of the group have a radius or mass that is not a finite number
// > 0, the one named atom `tag` with that `radius` and (has_mass: atoms have a
// per-atom mass) `mass`: a fault of the input.
std::string size_error(long count, long long step, int tag, double radius, double mass,
                       bool has_mass);

// Atom `tag` moved `fraction` of its radius in one step, above the 'move' limit
// (`verdict` is judge_step_fraction(fraction, limit), not Within).
std::string step_error(int tag, double fraction, long long step, double limit, StepVerdict verdict,
                       double time_step_ratio);

// `lost` atoms of the group have gone since the start of the run.
std::string lost_error(long long lost, long long step, double time_step_ratio);

// Atoms `tag_a` and `tag_b` overlap by `fraction` of the smaller radius;
// `vector_entry` is the fix's output f_ID[k] that holds the current value.
std::string overlap_warning(int tag_a, int tag_b, double fraction, long long step, double limit,
                            int vector_entry);

// The inertial number `inertial` of strain rate, D50, density (per unit thickness
// in 2D, per volume in 3D: `dimension`) and pressure is above `limit`;
// `vector_entry` as for overlap_warning.
std::string inertial_warning(double inertial, double limit, long long step, double strain_rate,
                             double d50, double density, int dimension, double pressure,
                             int vector_entry);

// What is wrong when R and P are valid but I overflows (InertialStatus::Overflow).
std::string inertial_overflow(long long step, double strain_rate, double pressure);

} // namespace stability

#endif
