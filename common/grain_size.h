#ifndef LIGGGHTS_MEMBRANE_GRAIN_SIZE_H
#define LIGGGHTS_MEMBRANE_GRAIN_SIZE_H
// Grain-size statistics used for the membranes' default band width and gap
// tolerance and the inertial number (no LIGGGHTS).

#include <vector>

namespace grains {

// D50 by mass, the step definition (issue 33; the one place it is computed in C++):
// the smallest diameter d such that the grains with diameter <= d hold at least
// half of the mass, a grain of diameter d weighing d^dimension (one density;
// disks per unit thickness in 2D, spheres in 3D). Empty input -> 0.
double d50_by_mass(std::vector<double> diameters, int dimension);

} // namespace grains

#endif
