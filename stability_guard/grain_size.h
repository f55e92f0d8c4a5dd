#ifndef LIGGGHTS_MEMBRANE_GRAIN_SIZE_H
#define LIGGGHTS_MEMBRANE_GRAIN_SIZE_H
// Grain-size statistics used for the membrane's default band width and gap
// tolerance (no LIGGGHTS).

#include <vector>

namespace stability {

// D50 by mass of disks of one density: the diameter below which half of the
// total disk area lies. Empty input -> 0.
double d50_by_area(std::vector<double> diameters);

} // namespace stability

#endif
