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

// every auto: the watch's budget in D50 (fix membrane2d's is 0.01 D50): a certificate that no
// motion below it can flip is not evaluated again, and the membrane is found again when
// a watched sphere has moved that far (flood_watch.h). It decides how often the watch
// is built again, never the membrane (every auto gives the results of every 1).
constexpr double WATCH_BUDGET = 0.02;

// every auto's dense schedule (dense_detections.h): at least 14 of 20 watched steps
// detecting, then 2 000 steps without the watch. A detection that builds the watch
// costs twice one from the skin (58 against 26 ms on the 7 699-sphere bench, whose
// membrane changes at every step): so the window probes briefly and rarely, adding
// about 1 % there.
constexpr long long DENSE_WINDOW_3D = 20, DENSE_DETECTIONS_3D = 14, UNWATCHED_STEPS_3D = 2000;

// The skin's thickness in mean diameters (membrane3d_skin.h): on the triaxial sample
// of examples/triaxial (7 699 spheres) the gap of one diameter around the members
// keeps about half of the triangulation's points and shows the result
// (bench/membrane3d_cost.sh). Around members 1 or 10 steps old, 0.5 d never showed it
// (all spheres were triangulated), 0.75 d always did, 10 % faster than 1 d
// (bench/membrane3d_steps.sh): 1 d keeps a margin for a sheared, bulging membrane.
constexpr double SKIN_THICKNESS = 1.0;
// The depth of the outermost spheres that seed a run's first detection, in mean
// diameters (skin_flood.h): the outer layer. One diameter takes the second layer of a
// block too, and the links among them close its core off as a dry group of its own: the
// skin is refused (tests/unit/membrane3d/test_skin_flood.cpp).
constexpr double OUTERMOST_DEPTH = 0.5;

} // namespace membrane3d

#endif
