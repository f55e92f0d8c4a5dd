#ifndef LIGGGHTS_MEMBRANE_GRAIN_SIZE_H
#define LIGGGHTS_MEMBRANE_GRAIN_SIZE_H
// Grain-size statistics used for the membrane's default band width and gap
// tolerance and the inertial number (no LIGGGHTS).

#include <vector>

namespace stability {

// D50 by mass of particles of one density: the diameter below which half of the
// total mass lies, the mass of a particle of diameter d going as d^dimension
// (disks per unit thickness in 2D, spheres in 3D). Empty input -> 0.
double d50_by_mass(std::vector<double> diameters, int dimension);

} // namespace stability

#endif
