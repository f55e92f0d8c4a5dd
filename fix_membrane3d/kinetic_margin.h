// Margins of the kinetic flood's certificates (kinetic_flood.h): whether the sign of a
// predicate of the regular triangulation cannot change while each of its points moves
// by less than a distance from where it is. No LIGGGHTS, no CGAL here.
//
// The bounds are those of flood_watch.cpp: the determinant's change is at most its
// first-order (cofactor) terms plus the Hadamard bound of the rest, and a round-off
// allowance of 1e-10 of the product of its rows' lengths, far above the error of
// evaluating it in doubles. A point's motion by e moves a difference of two points by
// at most 2 e.
#ifndef LIGGGHTS_MEMBRANE_KINETIC_MARGIN_H
#define LIGGGHTS_MEMBRANE_KINETIC_MARGIN_H

#include "exterior_flood.h"

#include <array>

namespace membrane3d {

// orientation(p0, p1, p2, p3) of the centres keeps its sign (false when it is zero).
bool orientation_margin(const std::array<const Sphere *, 4> &p, double delta);

// The power test of p[4] against the power sphere of p[0..3] (weights r^2) keeps its
// sign (false when it is zero).
bool power_margin(const std::array<const Sphere *, 5> &p, double delta);

// The largest of most, most / 2, ... (12 halvings) within which the orientation or the
// power test keeps its sign by the bounds of orientation_margin or power_margin, or 0.
double orientation_reach(const std::array<const Sphere *, 4> &p, double most);
double power_reach(const std::array<const Sphere *, 5> &p, double most);

// The perturbed power test (CGAL's side_of_oriented_power_sphere with perturb, as
// flood_watch.cpp's Predicates) of p[4] against p[0..3] whose determinant is zero by the
// images' symmetry (points of one `family` share x and y): its result keeps its value
// while the points' lexicographic order holds (each pair apart by more than 2 delta in
// the coordinate that orders it: z within a family, x across) and the orientation
// that decides it is zero by the symmetry too or keeps its sign.
bool perturbed_margin(const std::array<const Sphere *, 5> &p, const std::array<int, 5> &family,
                      double delta);

// Four points of which two pairs share a family (or three one): coplanar.
bool vertical_pairs(const std::array<int, 4> &family);

} // namespace membrane3d

#endif
