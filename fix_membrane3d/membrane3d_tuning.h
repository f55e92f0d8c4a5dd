// The tuned numbers of fix membrane3d, defined here only (doc/fix_membrane3d.md;
// how each was found: bench/README.md).
#ifndef LIGGGHTS_MEMBRANE_MEMBRANE3D_TUNING_H
#define LIGGGHTS_MEMBRANE_MEMBRANE3D_TUNING_H

namespace membrane3d {

// The default tolerance in D50: the smallest at which the flood found no surface
// sphere more than two diameters inside the skin of the compressed triaxial sample
// (0.6), with a margin (bench/membrane3d_tolerance.cpp).
constexpr double DEFAULT_TOLERANCE = 0.7;
// The largest tolerance in D50: at 1 D50 the membrane already bridges the surface's
// hollows (1 377 membrane spheres against 1 661 at 0.6, V up 1.6 %).
constexpr double MOST_TOLERANCE = 2.0;

// The lateral net load of a closed membrane, relative to the sum of the loads' sizes:
// zero but for the round-off of summing them.
constexpr double CLOSURE_ROUND_OFF = 1e-9;

} // namespace membrane3d

#endif
