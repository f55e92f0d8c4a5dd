// Closing the lateral surface of a triaxial sample at its platens, and telling inside
// from outside: an independent check, for the membrane3d tests, of the volume
// lateral_volume gives and of the spheres the flood finds inside and outside.
//
// The lateral surface (surface_loads.h: facets counter-clockwise from outside) is open
// at its rims. Each rim is closed by a cap: a fan of facets from the rim's centroid,
// oriented so that the closed surface still faces outwards. The volume and the
// pressure forces of the closed surface are those of the sample between flat platens
// when the rims lie in the platen planes; the winding number of the closed surface
// tells a sphere inside the sample (1) from an escaped one (0).
#ifndef LIGGGHTS_MEMBRANE_SURFACE_CLOSURE_H
#define LIGGGHTS_MEMBRANE_SURFACE_CLOSURE_H

#include "surface_loads.h"

#include <vector>

namespace membrane3d {

// The rims: the loops of edges that belong to one facet only, each as its vertices in
// the order of the facets' own edges. Throws std::invalid_argument when a vertex
// starts two rim edges (the surface is pinched there: no single rim through it).
std::vector<std::vector<int>> boundary_loops(const Surface &surface);

// The surface with one cap per rim: the rim's centroid appended to the points, one
// facet per rim edge (b, a, centroid) for the rim edge a -> b.
Surface close_with_caps(const Surface &surface);

// The winding number of a closed surface about x: the sum of the facets' signed solid
// angles (van Oosterom & Strackee 1983) over 4 pi; 1 inside, 0 outside, for x not on
// the surface.
double winding_number(const Surface &closed, const Eigen::Vector3d &x);

} // namespace membrane3d

#endif
