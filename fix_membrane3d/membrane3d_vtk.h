// The membrane of fix membrane3d as a VTK PolyData frame for ParaView (keyword vtk;
// the series and its .pvd: common/vtk_series.h). No LIGGGHTS: unit-tested in
// tests/unit/membrane3d.
#ifndef LIGGGHTS_MEMBRANE_MEMBRANE3D_VTK_H
#define LIGGGHTS_MEMBRANE_MEMBRANE3D_VTK_H

#include "lateral_surface.h"

#include <string>
#include <vector>

namespace membrane3d {

// Points: the membrane's corners, then the escaped spheres' centres. Polys: the
// facets; Verts: the escaped spheres. Point data: escaped (1 at an escaped sphere),
// radius (0 at a corner), load (the membrane's load on the corner, the push on the
// escaped sphere, at pressure p).
std::string vtk_frame(const LateralSurface &membrane, const std::vector<Sphere> &spheres,
                      double p);

} // namespace membrane3d

#endif
