// fix membrane3d's keyword 'vtk N FILE': the membrane as a series of VTK frames for
// ParaView, FILE_<step>.vtp every N steps collected in FILE.pvd (vtk_series.h),
// written by rank 0, which holds the whole membrane.
#ifndef LIGGGHTS_MEMBRANE_MEMBRANE3D_FRAMES_H
#define LIGGGHTS_MEMBRANE_MEMBRANE3D_FRAMES_H

#include <initializer_list>
#include <string>
#include <vector>

#include "lateral_surface.h"
#include "pointers.h"
#include "vtk_series.h"

class StyleArgs;

class Membrane3dFrames : protected LAMMPS_NS::Pointers {
 public:
  explicit Membrane3dFrames(LAMMPS_NS::LAMMPS *lammps) : Pointers(lammps) {}
  // N and FILE after the keyword; FILE may not be one of the style's `keywords`
  void read(StyleArgs &args, const char *prefix, const char *usage,
            std::initializer_list<const char *> keywords);
  // the frame of this step, when one is due
  void write(const char *prefix, const membrane3d::LateralSurface &membrane,
             const std::vector<membrane3d::Sphere> &spheres, double pressure);
  std::string pvd() const { return series_.pvd(); } // "" without the keyword

 private:
  LAMMPS_NS::bigint every_ = 0; // 0: no frames
  vtk_series::Series series_;
};

#endif
