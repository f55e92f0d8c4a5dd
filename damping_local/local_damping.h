// Local (non-viscous) damping as in PFC (Itasca PFC manual, "local damping";
// Momeni et al. 2024, eq. 5). No LIGGGHTS here: unit-tested in tests/unit/damping.
//
// For each component k of an unbalanced force (or torque) F and the matching
// velocity (or angular velocity) v:
//
//   F_d,k = -alpha * |F_k| * sign(v_k),   sign(0) = 0,
//
// so the damping force always opposes the motion, its size is a fraction alpha
// of the unbalanced force, and a component that does not move is not damped.
#ifndef LIGGGHTS_MEMBRANE_LOCAL_DAMPING_H
#define LIGGGHTS_MEMBRANE_LOCAL_DAMPING_H

#include <cstddef>

namespace damping {

// sign(v): +1, -1, or 0 for v == 0 (and for NaN).
double sign(double v);

// The damping force of one component: -alpha |f| sign(v).
double local_damping_component(double f, double v, double alpha);

// fd[k] = -alpha |f[k]| sign(v[k]) for k < n.
void local_damping_force(const double *f, const double *v, std::size_t n, double alpha, double *fd);

// f[k] += -alpha |f[k]| sign(v[k]) for k < n: the damped force, in place.
void apply_local_damping(double *f, const double *v, std::size_t n, double alpha);

} // namespace damping

#endif
